//! A slider on a fixed guide as the input of a linkage, against references
//! derived here: the inverted crank-slider (the slider drives the crank),
//! whose crank angle follows from the slider's s by the cosine rule and
//! whose ω and ε from differentiating it; a six-bar driven by a slider,
//! whose velocities are the finite differences of its positions and whose
//! accelerations those of its velocities; the structure (class I input of
//! the slider and the frame, W = 1, no passive freedom); and the
//! description's errors naming their field.

use tmm_geom::Vec2;
use tmm_linkage::{AssemblyHint, FRAME, HintKind, LinkDef, LinkageError, Mechanism, MechanismDef, SliderDef, SliderInputDef};

const R: f64 = 0.1;
const L: f64 = 0.3;

/// The slider B on the x-axis through O drives the crank OA (r = 0.1 m)
/// through the rod AB (l = 0.3 m); A above the axis.
fn inverted_crank_slider(v: f64, a: f64) -> MechanismDef {
    MechanismDef {
        fixed: vec![("O".into(), Vec2::ZERO)],
        links: vec![
            LinkDef::bar("1", "O", "A", R),
            LinkDef::bar("2", "A", "B", L),
            LinkDef::block("3", "B"),
        ],
        sliders: vec![SliderDef {
            slider: "3".into(),
            point: "B".into(),
            guide_link: FRAME.into(),
            through: Vec2::ZERO,
            angle: 0.0,
            angle_on_slider: 0.0,
        }],
        slider_input: Some(SliderInputDef {
            link: "3".into(),
            speed: v,
            acceleration: a,
        }),
        hints: vec![AssemblyHint {
            point: "A".into(),
            kind: HintKind::Near(Vec2::new(0.0, R)),
        }],
        assembly_angle: 0.3,
        ..Default::default()
    }
}

/// φ(s), φ′(s), φ″(s) of the crank, derived here: the triangle OAB gives
/// l² = r² + s² − 2rs·cos φ, so cos φ = g(s) = s/(2r) + (r² − l²)/(2rs)
/// with A above the axis (0 < φ < π); −sin φ·φ′ = g′ and
/// −cos φ·φ′² − sin φ·φ″ = g″, g′ = 1/(2r) − (r² − l²)/(2rs²),
/// g″ = (r² − l²)/(rs³).
fn crank_closed_form(s: f64) -> (f64, f64, f64) {
    let g = s / (2.0 * R) + (R * R - L * L) / (2.0 * R * s);
    let g1 = 1.0 / (2.0 * R) - (R * R - L * L) / (2.0 * R * s * s);
    let g2 = (R * R - L * L) / (R * s * s * s);
    let phi = g.acos();
    let (sn, cs) = phi.sin_cos();
    let p1 = -g1 / sn;
    let p2 = -(g2 + cs * p1 * p1) / sn;
    (phi, p1, p2)
}

#[test]
fn inverted_crank_slider_matches_the_cosine_rule() {
    for (v, a) in [(0.5, 0.0), (-0.8, 3.0)] {
        let m = Mechanism::new(&inverted_crank_slider(v, a)).unwrap();
        // the input mechanism of class I is the slider with the frame
        assert_eq!(m.structure.formula, "I(0,3) → II(1,2)");
        assert_eq!((m.structure.dof, m.structure.dof_rank, m.structure.passive), (1, 1, 0));
        let crank = m.link("1").unwrap();
        let mut sol = m.solution();
        let mut worst = (0.0f64, 0.0f64, 0.0f64);
        // the dead centres are at s = l − r = 0.2 and l + r = 0.4
        for k in 0..=50 {
            let s = 0.21 + 0.18 * k as f64 / 50.0;
            m.solve(s, &mut sol).unwrap();
            let (phi, p1, p2) = crank_closed_form(s);
            let st = &sol.links[crank];
            // ω = φ′·v, ε = φ″·v² + φ′·a (the chain rule)
            let omega = p1 * v;
            let eps = p2 * v * v + p1 * a;
            worst.0 = worst.0.max(tmm_geom::angle::diff(phi, st.angle()).abs());
            worst.1 = worst.1.max((st.omega - omega).abs() / omega.abs().max(1.0));
            worst.2 = worst.2.max((st.eps - eps).abs() / eps.abs().max(1.0));
            // the slider itself: at s, moving at v, not turning
            let b = sol.points[m.point("B").unwrap()];
            assert!((b.p - Vec2::new(s, 0.0)).hypot() < 1e-14);
            assert!((b.v - Vec2::new(v, 0.0)).hypot() < 1e-14 && (b.a - Vec2::new(a, 0.0)).hypot() < 1e-12);
        }
        assert!(worst.0 < 1e-12 && worst.1 < 1e-10 && worst.2 < 1e-9, "{worst:?}");
    }
}

/// A six-bar driven by a slider: slider B (on a guide at 20° through O)
/// drives the three-joint rocker D–C–E through the coupler BC; the rod EF
/// drives the output slider F on a horizontal guide (RRR then RRP).
fn six_bar(v: f64, a: f64) -> MechanismDef {
    let rocker = LinkDef {
        name: "3".into(),
        points: vec![
            ("D".into(), Vec2::ZERO),
            ("C".into(), Vec2::new(0.15, 0.0)),
            ("E".into(), Vec2::new(0.05, 0.12)),
        ],
        mass_center: Vec2::new(0.07, 0.04),
    };
    MechanismDef {
        fixed: vec![("O".into(), Vec2::ZERO), ("D".into(), Vec2::new(0.15, 0.2))],
        links: vec![
            LinkDef::block("1", "B"),
            LinkDef::bar("2", "B", "C", 0.25),
            rocker,
            LinkDef::bar("4", "E", "F", 0.3),
            LinkDef::block("5", "F"),
        ],
        sliders: vec![
            SliderDef {
                slider: "1".into(),
                point: "B".into(),
                guide_link: FRAME.into(),
                through: Vec2::ZERO,
                angle: 20f64.to_radians(),
                angle_on_slider: 0.0,
            },
            SliderDef {
                slider: "5".into(),
                point: "F".into(),
                guide_link: FRAME.into(),
                through: Vec2::new(0.0, 0.45),
                angle: 0.0,
                angle_on_slider: 0.0,
            },
        ],
        slider_input: Some(SliderInputDef {
            link: "1".into(),
            speed: v,
            acceleration: a,
        }),
        hints: vec![
            AssemblyHint {
                point: "C".into(),
                kind: HintKind::Below("B".into(), "D".into()),
            },
            AssemblyHint {
                point: "F".into(),
                kind: HintKind::Near(Vec2::new(0.49, 0.45)),
            },
        ],
        assembly_angle: 0.02,
        ..Default::default()
    }
}

#[test]
fn six_bar_velocities_and_accelerations_are_the_derivatives_of_its_motion() {
    let (v, a) = (0.7, -2.0);
    let m = Mechanism::new(&six_bar(v, a)).unwrap();
    assert_eq!(m.structure.formula, "I(0,1) → II(2,3) → II(4,5)");
    assert_eq!((m.structure.dof_rank, m.structure.passive), (1, 0));
    let (mut s0, mut sm, mut sp) = (m.solution(), m.solution(), m.solution());
    let h = 1e-5;
    let mut worst = (0.0f64, 0.0f64);
    for k in 0..=20 {
        let s = 0.02 + 0.1 * k as f64 / 20.0;
        m.solve(s, &mut s0).unwrap();
        m.solve(s - h, &mut sm).unwrap();
        m.solve(s + h, &mut sp).unwrap();
        for i in 0..m.points.len() {
            // dP/ds and d²P/ds² by central differences of the positions; the
            // time derivatives by the chain rule: v_P = P′·v, a_P = P″·v² + P′·a
            let d1 = (sp.points[i].p - sm.points[i].p) * (0.5 / h);
            let d2 = (sp.points[i].p - s0.points[i].p * 2.0 + sm.points[i].p) * (1.0 / (h * h));
            let vel = d1 * v;
            let acc = d2 * (v * v) + d1 * a;
            worst.0 = worst.0.max((s0.points[i].v - vel).hypot());
            worst.1 = worst.1.max((s0.points[i].a - acc).hypot());
        }
        for l in 1..m.link_names.len() {
            // ω = dθ/ds·v, from the angle's central difference
            let dth = tmm_geom::angle::diff(sm.links[l].angle(), sp.links[l].angle()) * (0.5 / h);
            worst.0 = worst.0.max((s0.links[l].omega - dth * v).abs() * 0.1);
            // ε = dω/dt: the velocities' difference (at constant a the
            // state at s ± h moves with the same v here, so dω/ds·v + ω/v·a)
            let dom = (sp.links[l].omega - sm.links[l].omega) * (0.5 / h);
            let eps = dom * v + s0.links[l].omega / v * a;
            worst.1 = worst.1.max((s0.links[l].eps - eps).abs() * 0.1);
        }
    }
    // velocities to 1e-8 m/s, accelerations to 1e-3 m/s² (h² and round-off/h²)
    assert!(worst.0 < 1e-8 && worst.1 < 1e-3, "{worst:?}");
}

#[test]
fn the_description_errors_name_their_field() {
    let field = |def: &MechanismDef| match Mechanism::new(def).unwrap_err() {
        LinkageError::Description { field, message } | LinkageError::Range { field, why: message, .. } => (field, message),
        e => panic!("{e}"),
    };
    // a link that slides on no guide
    let mut d = inverted_crank_slider(0.5, 0.0);
    d.slider_input.as_mut().unwrap().link = "2".into();
    let (f, m) = field(&d);
    assert!(f == "input.slider" && m.contains("slides on no guide"), "{f}: {m}");
    // a link that is not there
    d.slider_input.as_mut().unwrap().link = "9".into();
    assert_eq!(field(&d).0, "input.slider");
    // a slider whose guide moves
    let mut d = six_bar(0.5, 0.0);
    d.sliders[1].guide_link = "3".into();
    d.sliders[1].through = Vec2::ZERO;
    d.slider_input.as_mut().unwrap().link = "5".into();
    let (f, m) = field(&d);
    assert!(f == "input.slider" && m.contains("guide fixed to the frame"), "{f}: {m}");
    // a slider that does not move
    let d = inverted_crank_slider(0.0, 0.0);
    assert_eq!(field(&d).0, "input.speed");
    // a crank and a slider at once
    let mut d = inverted_crank_slider(0.5, 0.0);
    d.input = Some(tmm_linkage::InputDef::crank("1", "O", "A", 10.0));
    assert_eq!(field(&d).0, "input");
}

#[test]
fn a_position_past_the_dead_centre_names_its_travel() {
    let m = Mechanism::new(&inverted_crank_slider(0.5, 0.0)).unwrap();
    let mut sol = m.solution();
    let e = m.solve(0.45, &mut sol).unwrap_err();
    assert!(matches!(e, LinkageError::AssemblyAtTravel { .. }), "{e}");
    assert!(e.to_string().contains("s = 450.0000 mm"), "{e}");
    // the cycle of a crank's turn is refused for a slider input
    let e = tmm_linkage::cycle::Cycle::new(&m, Default::default()).unwrap_err();
    assert!(e.to_string().starts_with("input.slider:"), "{e}");
}
