//! A shaper's loads on a crank-slider whose kinematics is written here in
//! closed form: a cutting force by travel with its overrun window and its
//! arm l_p (П3, Chernaya & Timofeev 2019), friction, the rotor reduced by
//! its speed and the flywheel on a shaft of another speed. The references:
//! the slider's travel x(φ) = r·cos φ + √(l² − r² sin² φ), its analogue by
//! central differences, Simpson's rule between the force's jumps (located
//! by bisection here), the slider's moment equation for the arm.

use std::f64::consts::PI;

use tmm_geom::{Vec2, cross};
use tmm_linkage::dynamics::{Dynamics, DynamicsSpec, FlywheelPlace};
use tmm_linkage::forces::stroke::Working;
use tmm_linkage::forces::{Curve, Interpolation, Kinetostatics, Loads, SliderLoad, SliderLoadKind, TravelScale};
use tmm_linkage::{AssemblyHint, HintKind, InputDef, LinkDef, Mechanism, MechanismDef, SliderDef};

const R: f64 = 0.1;
const L: f64 = 0.4;
const W: f64 = 5.0;
const M3: f64 = 20.0;
const ARM: f64 = 0.09;
const WINDOW: (f64, f64) = (0.05, 0.95);

/// The slider's x at crank angle φ (ccw from the outer dead centre at φ = 0).
fn x(phi: f64) -> f64 {
    R * phi.cos() + (L * L - (R * phi.sin()).powi(2)).sqrt()
}

/// The cutting force's magnitude by travel s from the outer dead centre:
/// 400 N → 800 N → 600 N, linear, as П3's table.
fn table(s: f64) -> f64 {
    let h = 2.0 * R;
    if s <= 0.35 * h {
        400.0 + 400.0 * s / (0.35 * h)
    } else {
        800.0 - 200.0 * (s - 0.35 * h) / (0.65 * h)
    }
}

fn shaper(arm: f64) -> (Mechanism, Loads) {
    let def = MechanismDef {
        fixed: vec![("O".into(), Vec2::ZERO)],
        links: vec![
            LinkDef::bar("1", "O", "A", R),
            LinkDef::bar("2", "A", "B", L),
            LinkDef::block("3", "B"),
        ],
        sliders: vec![SliderDef {
            slider: "3".into(),
            point: "B".into(),
            guide_link: "frame".into(),
            through: Vec2::ZERO,
            angle: 0.0,
            angle_on_slider: 0.0,
        }],
        input: Some(InputDef {
            link: "1".into(),
            pivot: "O".into(),
            pin: "A".into(),
            omega: W,
            epsilon: 0.0,
        }),
        hints: vec![AssemblyHint {
            point: "B".into(),
            kind: HintKind::Near(Vec2::new(0.5, 0.0)),
        }],
        ..Default::default()
    };
    let m = Mechanism::new(&def).unwrap();
    let mut loads = Loads::new(&m);
    let s3 = m.link("3").unwrap();
    loads.links[s3].mass = M3;
    let pts: Vec<(f64, f64)> = (0..=20).map(|k| k as f64 * 0.01).map(|s| (s, table(s))).collect();
    loads.sliders.push(SliderLoad {
        link: s3,
        kind: SliderLoadKind::StrokeForce {
            table: Curve::new(&pts, Interpolation::Linear, "t").unwrap(),
            travel: TravelScale::Metres,
            // the working stroke: x decreasing, from the outer dead centre (φ = 0 … π)
            working: Working::Decreasing,
            window: WINDOW,
            arm,
        },
    });
    loads.sliders.push(SliderLoad {
        link: s3,
        kind: SliderLoadKind::Friction { force: 50.0 },
    });
    (m, loads)
}

/// φ in (lo, hi) where the travel x(0) − x(φ) (or its return) crosses s.
fn crossing(s: f64, mut lo: f64, mut hi: f64) -> f64 {
    let t = |p: f64| x(0.0) - x(p);
    let up = t(hi) > t(lo);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if (t(mid) < s) == up {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[test]
fn the_arm_is_a_couple_that_moves_the_guide_reaction_only() {
    let (m0, l0) = shaper(0.0);
    let (m1, l1) = shaper(ARM);
    let mut k0 = Kinetostatics::with_working(&m0, l0, Working::Decreasing).unwrap();
    let mut k1 = Kinetostatics::with_working(&m1, l1, Working::Decreasing).unwrap();
    let (mut s0, mut s1) = (m0.solution(), m1.solution());
    let (mut f0, mut f1) = (k0.result(), k1.result());
    let mut cutting = 0;
    for i in 1..72 {
        let phi = 2.0 * PI * i as f64 / 72.0;
        k0.solve_at(phi, &mut s0, &mut f0).unwrap();
        k1.solve_at(phi, &mut s1, &mut f1).unwrap();
        // a translating slider: the couple does no work
        assert!((f0.balancing_moment - f1.balancing_moment).abs() < 1e-9 * f0.balancing_moment.abs().max(1.0));
        let f = f1.slider_forces[0].x;
        let guide = |fs: &tmm_linkage::forces::ForceSolution| *fs.reactions.iter().find(|r| r.prismatic && r.from == 0).unwrap();
        let (g0, g1) = (guide(&f0), guide(&f1));
        assert!((g0.force - g1.force).hypot() < 1e-9 * g0.force.hypot().max(1.0));
        // the slider's moments about its point: the force's F·l_p is met by
        // the guide's reaction moved along the guide
        let dm = cross(g1.at - g0.at, g1.force);
        assert!(
            (dm + f * ARM).abs() < 1e-9 * (f * ARM).abs().max(1e-6),
            "at {phi}: {dm} vs {}",
            -f * ARM
        );
        if f != 0.0 {
            cutting += 1;
        }
    }
    assert!(cutting > 20);
}

#[test]
fn window_edges_and_the_work_over_the_cycle() {
    let (m, loads) = shaper(ARM);
    let k = Kinetostatics::with_working(&m, loads.clone(), Working::Decreasing).unwrap();
    let h = 2.0 * R;
    let on = crossing(WINDOW.0 * h, 0.0, PI);
    let off = crossing(WINDOW.1 * h, 0.0, PI);
    let edges = &k.sliders[0].edges;
    assert_eq!(edges.len(), 2);
    assert!((edges[0].rem_euclid(2.0 * PI) - on).abs() < 1e-9, "{} vs {on}", edges[0]);
    assert!((edges[1].rem_euclid(2.0 * PI) - off).abs() < 1e-9);
    // the reduced moment in closed form: (F_cut + F_fr)·dx/dφ, the work by
    // Simpson between the jumps, the table's kink and the dead positions
    let mc = |p: f64| {
        let d = 1e-6;
        let v = (x(p + d) - x(p - d)) / (2.0 * d);
        let s = x(0.0) - x(p);
        let cut = if p < PI && s >= WINDOW.0 * h && s <= WINDOW.1 * h {
            table(s)
        } else {
            0.0
        };
        // against the motion: the slider moves −x on the working stroke
        (cut - 50.0 * v.signum()) * v
    };
    // the table's kink at 0.35·H is a piece's end too
    let kink = crossing(0.35 * h, 0.0, PI);
    let mut a = 0.0;
    for w in [0.0, on, kink, off, PI, 2.0 * PI].windows(2) {
        let n = 2000;
        let step = (w[1] - w[0]) / n as f64;
        let f = |j: usize| mc((w[0] + j as f64 * step).clamp(w[0] + 1e-10, w[1] - 1e-10));
        let mut s = f(0) + f(n);
        for j in 1..n {
            s += if j % 2 == 1 { 4.0 } else { 2.0 } * f(j);
        }
        a += s * step / 3.0;
    }
    let mut spec = DynamicsSpec::new(0.05);
    spec.working = Working::Decreasing;
    spec.inertia_motor_shaft = 0.01;
    spec.motor_speed = Some(100.0);
    spec.flywheel.place = FlywheelPlace::Shaft;
    spec.flywheel.speed_ratio = 3.0;
    let d = Dynamics::compute(&m, &loads, &spec).unwrap();
    let md = d.cycle.driving_moment;
    assert!((md + a / (2.0 * PI)).abs() < 1e-8 * md.abs(), "{md} vs {}", -a / (2.0 * PI));
    // the rotor reduced by (ω_rot/ω_m)², the flywheel on its shaft ÷ i²
    assert!((d.inertia_given.motor_shaft - 0.01 * (100.0 / W).powi(2)).abs() < 1e-12);
    let need = d.motion.inertia_constant - d.inertia_given.total;
    assert!((d.flywheel_inertia_crank - need).abs() < 1e-9 * need);
    assert!((d.flywheel_inertia - need / 9.0).abs() < 1e-9 * need);
}
