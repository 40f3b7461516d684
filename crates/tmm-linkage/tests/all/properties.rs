//! Property tests of the solvers on random mechanisms: every pair closes,
//! distances between points of one link stay rigid, velocities are central
//! finite differences of positions and accelerations of velocities, and the
//! force polygon of every group and of the crank closes.

use crate::common;

use common::v;
use proptest::prelude::*;
use tmm_linkage::forces::{Kinetostatics, Loads};
use tmm_linkage::mechanism::Pair;
use tmm_linkage::state::{conj, rot};
use tmm_linkage::{InputDef, LinkDef, Mechanism, MechanismDef, SliderDef};

/// Check closure, rigidity and finite differences at φ when the position
/// solves (nothing to check when it does not, e.g. at a random dead centre).
fn check(m: &Mechanism, phi: f64) -> Result<(), TestCaseError> {
    let (mut s0, mut sm, mut sp) = (m.solution(), m.solution(), m.solution());
    let h = 1e-6;
    if m.solve(phi, &mut s0).is_err() || m.solve(phi - h, &mut sm).is_err() || m.solve(phi + h, &mut sp).is_err() {
        return Ok(());
    }
    let size = m
        .pairs
        .iter()
        .map(|p| match *p {
            Pair::R { la, lb, .. } => la.hypot().max(lb.hypot()),
            Pair::P { q, .. } => q.hypot(),
        })
        .fold(m.crank.radius, f64::max);
    for p in &m.pairs {
        match *p {
            Pair::R { a, b, la, lb, .. } => {
                let d = s0.links[a].pos(la) - s0.links[b].pos(lb);
                prop_assert!(d.hypot() < 1e-11 * size, "joint open by {}", d.hypot());
            }
            Pair::P {
                slider,
                guide,
                ps,
                q,
                d,
                rel,
                ..
            } => {
                let g = &s0.links[guide];
                let n = rot(g.u, tmm_geom::perp(d));
                let off = (s0.links[slider].pos(ps) - g.pos(q)).dot(n);
                prop_assert!(off.abs() < 1e-11 * size, "slider off its guide by {off}");
                let turn = rot(s0.links[slider].u, conj(rot(g.u, rel)));
                prop_assert!(turn.y.abs() < 1e-12 && turn.x > 0.0);
            }
        }
    }
    for (i, pi) in m.points.iter().enumerate() {
        for (j, pj) in m.points.iter().enumerate().skip(i + 1) {
            if pi.link == pj.link {
                let d = (s0.points[i].p - s0.points[j].p).hypot();
                let d0 = (pi.local - pj.local).hypot();
                prop_assert!((d - d0).abs() < 1e-11 * size);
            }
        }
    }
    let w = m.crank.omega;
    // the FD error grows near a dead centre: compare with the amplification
    for i in 0..m.points.len() {
        let v_fd = (sp.points[i].p - sm.points[i].p) * (w / (2.0 * h));
        let a_fd = (sp.points[i].v - sm.points[i].v) * (w / (2.0 * h));
        let (v, a) = (s0.points[i].v, s0.points[i].a);
        let vs = v.hypot().max(w.abs() * size * 1e-3);
        let as_ = a.hypot().max(w * w * size * 1e-3);
        prop_assert!((v - v_fd).hypot() <= 1e-5 * vs, "{}: v {v:?} vs {v_fd:?}", m.points[i].name);
        prop_assert!((a - a_fd).hypot() <= 1e-4 * as_, "{}: a {a:?} vs {a_fd:?}", m.points[i].name);
    }
    Ok(())
}

fn input(omega: f64) -> Option<InputDef> {
    Some(InputDef {
        link: "1".into(),
        pivot: "O".into(),
        pin: "A".into(),
        omega,
        epsilon: 0.0,
    })
}

fn four_bar(r: f64, b: f64, c: f64, d: f64, omega: f64) -> Option<Mechanism> {
    Mechanism::new(&MechanismDef {
        fixed: vec![("O".into(), v(0.0, 0.0)), ("D".into(), v(d, 0.0))],
        links: vec![
            LinkDef::bar("1", "O", "A", r),
            LinkDef::bar("2", "A", "C", b),
            LinkDef::bar("3", "D", "C", c),
        ],
        input: input(omega),
        ..Default::default()
    })
    .ok()
}

fn crank_slider(r: f64, l: f64, e: f64, angle: f64, omega: f64) -> Option<Mechanism> {
    Mechanism::new(&MechanismDef {
        fixed: vec![("O".into(), v(0.0, 0.0))],
        links: vec![
            LinkDef::bar("1", "O", "A", r),
            LinkDef::bar("2", "A", "B", l),
            LinkDef::block("3", "B"),
        ],
        sliders: vec![SliderDef {
            slider: "3".into(),
            point: "B".into(),
            guide_link: "frame".into(),
            through: v(-e * angle.sin(), e * angle.cos()),
            angle,
            angle_on_slider: 0.0,
        }],
        input: input(omega),
        ..Default::default()
    })
    .ok()
}

fn slotted(r: f64, h: f64, omega: f64) -> Option<Mechanism> {
    Mechanism::new(&MechanismDef {
        fixed: vec![("O".into(), v(0.0, 0.0)), ("C".into(), v(0.0, -h))],
        links: vec![
            LinkDef::bar("1", "O", "A", r),
            LinkDef::block("2", "A"),
            LinkDef::bar("3", "C", "K", 2.0 * (r + h)),
        ],
        sliders: vec![SliderDef {
            slider: "2".into(),
            point: "A".into(),
            guide_link: "3".into(),
            through: v(0.0, 0.0),
            angle: 0.0,
            angle_on_slider: 0.0,
        }],
        input: input(omega),
        ..Default::default()
    })
    .ok()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, .. ProptestConfig::default() })]

    #[test]
    fn four_bars(r in 0.02f64..0.2, b in 0.2f64..1.0, c in 0.2f64..1.0, d in 0.2f64..1.0,
                 omega in prop_oneof![-50.0f64..-0.5, 0.5f64..50.0], phi in 0.0f64..std::f64::consts::TAU,
                 k in prop_oneof![Just(1e-3), Just(1.0), Just(1e3)]) {
        if let Some(m) = four_bar(r * k, b * k, c * k, d * k, omega) {
            check(&m, phi)?;
        }
    }

    #[test]
    fn crank_sliders(r in 0.02f64..0.2, l in 0.2f64..1.0, e in -0.15f64..0.15, angle in -3.0f64..3.0,
                     omega in prop_oneof![-50.0f64..-0.5, 0.5f64..50.0], phi in 0.0f64..std::f64::consts::TAU) {
        if let Some(m) = crank_slider(r, l, e, angle, omega) {
            check(&m, phi)?;
        }
    }

    #[test]
    fn slotted_links(r in 0.02f64..0.3, h in 0.05f64..0.5, omega in prop_oneof![-50.0f64..-0.5, 0.5f64..50.0],
                     phi in 0.0f64..std::f64::consts::TAU) {
        if let Some(m) = slotted(r, h, omega) {
            check(&m, phi)?;
        }
    }

    /// Every force polygon closes under random loads at a random position.
    #[test]
    fn force_polygons_close(seed in 1u64..u64::MAX, phi in 0.0f64..std::f64::consts::TAU, which in 0usize..4) {
        let m = match which {
            0 => common::seed001(),
            1 => common::seed003(),
            2 => common::seed004(),
            _ => common::triad(),
        };
        let mut rng = common::Rng(seed);
        let mut loads = Loads::new(&m);
        for l in 1..m.link_names.len() {
            loads.links[l].mass = 0.5 + 10.0 * rng.uniform();
            loads.links[l].inertia = 0.01 + 0.1 * rng.uniform();
            loads.links[l].moment = rng.sym(50.0);
        }
        let mut k = Kinetostatics::new(&m, loads).unwrap();
        let (mut s, mut f) = (m.solution(), k.result());
        if k.solve_at(phi, &mut s, &mut f).is_ok() {
            for p in f.polygons(&m) {
                prop_assert!(p.closure().hypot() <= 1e-9 * p.largest(), "{:?}", p.closure());
            }
        }
    }
}
