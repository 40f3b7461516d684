//! The sizing optimum against brute-force searches written inside the tests,
//! with the pressure angle computed from first principles (instant centre of
//! cam and follower) rather than by the crate.

use tmm_cams::CamError;
use tmm_cams::design::{CamTask, FollowerSpec};
use tmm_cams::mechanism::{Mechanism, Rotation};
use tmm_cams::program::{PhaseKind, Program};
use tmm_cams::sizing;
use tmm_cams::spec::{self, Limits};

const SEED: &str = "rise 108 const-accel(u=1/3); dwell 15; return 108 const-accel(u=1/3); dwell 129";

fn program(h: f64, phases: &str) -> Program {
    Program::new(h, spec::parse_phases(phases).unwrap()).unwrap()
}

/// (s, ds/dφ, tan of the allowed angle) at `n` points of every moving phase.
fn samples(p: &Program, lim: Limits, n: usize) -> Vec<(f64, f64, f64)> {
    let mut out = Vec::new();
    for (k, ph) in p.phases().iter().enumerate() {
        let t = match ph.kind {
            PhaseKind::Rise => lim.rise.tan(),
            PhaseKind::Return => lim.ret.tan(),
            PhaseKind::Dwell => continue,
        };
        let breaks = ph.law.as_ref().map(|l| l.breaks()).unwrap_or_default();
        for x in (0..=n).map(|i| i as f64 / n as f64).chain(breaks) {
            let m = p.eval_in(k, ph.angle * x);
            out.push((m.s, m.v, t));
        }
    }
    out
}

/// For a translating follower with offset e, the cam centre lies s₀ below the
/// lowest roller centre; the instant centre of cam and follower is on the
/// line through O perpendicular to the axis at σ·ds/dφ from O, and the
/// contact normal joins it to the roller centre: tan ϑ = |σ·s′ − e|/(s₀ + s).
/// The least admissible s₀ for one e is the largest of |σs′ − e|/t − s.
fn least_s0(smp: &[(f64, f64, f64)], sigma: f64, e: f64) -> f64 {
    smp.iter()
        .map(|&(s, v, t)| (sigma * v - e).abs() / t - s)
        .fold(f64::NEG_INFINITY, f64::max)
}

#[test]
fn translating_roller_optimum_beats_a_grid_of_offsets() {
    let p = program(0.013, SEED);
    for (lim, sigma) in [
        (spec::parse_limits("rise 75, return 60", true).unwrap(), 1.0),
        (spec::parse_limits("30", false).unwrap(), -1.0),
    ] {
        let (e, s0) = sizing::translating_roller(&p, sigma, lim, None).unwrap();
        let r0 = e.hypot(s0);
        let smp = samples(&p, lim, 4000);
        // brute force: e on a 5 µm grid over ±40 mm, s₀ the least admissible for each
        // then a 5 nm grid around the best
        let mut best = (f64::INFINITY, 0.0);
        for i in -8000..=8000 {
            let eg = i as f64 * 5e-6;
            let r = eg.hypot(least_s0(&smp, sigma, eg));
            if r < best.0 {
                best = (r, eg);
            }
        }
        let c = best.1;
        for i in -1000..=1000 {
            let eg = c + i as f64 * 5e-9;
            let r = eg.hypot(least_s0(&smp, sigma, eg));
            if r < best.0 {
                best = (r, eg);
            }
        }
        assert!((r0 - best.0).abs() < 1e-8, "solver r0 {r0} vs grid {}", best.0);
        assert!((e - best.1).abs() < 1e-7, "solver e {e} vs grid {}", best.1);
        // the solver's centre is admissible at every sample
        assert!(least_s0(&smp, sigma, e) <= s0 + 1e-12);
    }
}

#[test]
fn translating_roller_for_a_given_offset() {
    let p = program(0.02, "rise 120 sine; dwell 30; return 90 poly345; dwell 120");
    let lim = spec::parse_limits("rise 30, return 40", false).unwrap();
    let smp = samples(&p, lim, 20000);
    for e in [0.0, 0.004, -0.006] {
        let (e2, s0) = sizing::translating_roller(&p, 1.0, lim, Some(e)).unwrap();
        assert_eq!(e, e2);
        let brute = least_s0(&smp, 1.0, e);
        assert!((s0 - brute).abs() < 1e-7, "e = {e}: {s0} vs {brute}");
    }
}

/// Pressure angle of an oscillating roller follower from the instant centre:
/// with the pivot A at the origin, cam centre O, ratio q = ω_follower/ω_cam,
/// the instant centre is I = O/(1 − q) on the line OA; the normal is B–I and
/// the roller centre moves along d (perpendicular to the arm).
fn osc_pressure(o: (f64, f64), arm: f64, kappa: f64, sigma: f64, s: f64, v: f64) -> Option<f64> {
    let psi = kappa * s;
    let (ux, uy) = (psi.cos(), psi.sin());
    let (bx, by) = (arm * ux, arm * uy);
    let (dx, dy) = (-uy * kappa, ux * kappa);
    // the cam must lie behind the roller with respect to the rise
    if (bx - o.0) * dx + (by - o.1) * dy <= 0.0 {
        return None;
    }
    let q = sigma * kappa * v;
    let (ix, iy) = (o.0 / (1.0 - q), o.1 / (1.0 - q));
    let (nx, ny) = (bx - ix, by - iy);
    Some(((nx * dx + ny * dy).abs() / nx.hypot(ny)).min(1.0).acos())
}

fn osc_feasible(p: &Program, lim: Limits, o: (f64, f64), arm: f64, kappa: f64, sigma: f64, n: usize) -> bool {
    for (k, ph) in p.phases().iter().enumerate() {
        let t = match ph.kind {
            PhaseKind::Rise => lim.rise,
            PhaseKind::Return => lim.ret,
            PhaseKind::Dwell => continue,
        };
        for i in 0..=n {
            let m = p.eval_in(k, ph.angle * i as f64 / n as f64);
            match osc_pressure(o, arm, kappa, sigma, m.s, m.v) {
                Some(th) if th <= t => {}
                _ => return false,
            }
        }
    }
    true
}

#[test]
fn oscillating_roller_optimum_beats_a_grid_of_centres() {
    let p = program(20f64.to_radians(), "rise 120 sine; dwell 30; return 120 cosine; dwell 90");
    let lim = spec::parse_limits("rise 30, return 35", false).unwrap();
    let arm = 0.1;
    let sigma = 1.0;
    let m = sizing::oscillating_roller(&p, sigma, lim, arm, None, tmm_cams::design::OSC_SAMPLES).unwrap();
    let Mechanism::OscillatingRoller { pivot, kappa, .. } = m else {
        panic!()
    };
    let o = (-pivot.x, -pivot.y);
    let r0 = (o.0 - arm).hypot(o.1);
    // brute force over both senses of the swing: a 0.5 mm grid over ±100 mm,
    // then two finer grids around the best point (the region is a narrow wedge)
    let mut best = (f64::INFINITY, (0.0, 0.0), 0.0);
    for kg in [1.0, -1.0] {
        for i in -200..=200 {
            for j in -200..=200 {
                let og = (arm + i as f64 * 5e-4, j as f64 * 5e-4);
                let r = (og.0 - arm).hypot(og.1);
                if r < best.0 && osc_feasible(&p, lim, og, arm, kg, sigma, 200) {
                    best = (r, og, kg);
                }
            }
        }
    }
    for step in [5e-5, 5e-6] {
        let (c, kg) = (best.1, best.2);
        for i in -60..=60 {
            for j in -60..=60 {
                let og = (c.0 + i as f64 * step, c.1 + j as f64 * step);
                let r = (og.0 - arm).hypot(og.1);
                if r < best.0 && osc_feasible(&p, lim, og, arm, kg, sigma, 200) {
                    best = (r, og, kg);
                }
            }
        }
    }
    assert!(best.0.is_finite());
    assert_eq!(kappa, best.2, "the sense of the swing");
    assert!((r0 - best.0).abs() < 5e-5, "solver r0 {r0} vs grid {}", best.0);
    // the solver's centre keeps the limits to within the sampling of the cones
    let slack = Limits {
        rise: lim.rise + 1e-4,
        ret: lim.ret + 1e-4,
    };
    assert!(osc_feasible(&p, slack, o, arm, kappa, sigma, 5000));
}

#[test]
fn oscillating_roller_with_a_given_pivot_distance() {
    let p = program(15f64.to_radians(), "rise 90 poly345; dwell 90; return 90 poly345; dwell 90");
    let lim = spec::parse_limits("35", false).unwrap();
    let (arm, a) = (0.08, 0.1);
    let m = sizing::oscillating_roller(&p, -1.0, lim, arm, Some(a), tmm_cams::design::OSC_SAMPLES).unwrap();
    let Mechanism::OscillatingRoller { pivot, kappa, .. } = m else {
        panic!()
    };
    assert!((pivot.hypot() - a).abs() < 1e-12);
    let o = (-pivot.x, -pivot.y);
    let r0 = (o.0 - arm).hypot(o.1);
    // brute force along the circle |O| = a
    let mut best = f64::INFINITY;
    for kg in [1.0, -1.0] {
        for i in 0..20000 {
            let t = std::f64::consts::TAU * i as f64 / 20000.0;
            let og = (a * t.cos(), a * t.sin());
            let r = (og.0 - arm).hypot(og.1);
            if r < best && osc_feasible(&p, lim, og, arm, kg, -1.0, 200) {
                best = r;
            }
        }
    }
    let _ = kappa;
    assert!((r0 - best).abs() < 5e-5, "{r0} vs {best}");
}

#[test]
fn flat_face_meets_geronimus_with_equality() {
    let p = program(0.013, SEED);
    let rho = 0.01;
    let r0 = sizing::translating_flat(&p, rho);
    // r₀ + s + s″ ≥ ρ everywhere, with equality somewhere (both sides of each joint)
    let mut least = f64::INFINITY;
    for (k, ph) in p.phases().iter().enumerate() {
        for i in 0..=20000 {
            let m = p.eval_in(k, ph.angle * i as f64 / 20000.0);
            least = least.min(r0 + m.s + m.a);
        }
    }
    assert!(least >= rho - 1e-12 && least - rho < 2e-6, "{least}");
    // closed form: s + s″ is least where s″ is most negative — just after the
    // rise's switch (y = u, y″ = −2/(1−u)), or just before the return's switch
    // (s = h·(1 − u), s″ = −h·(2/u)/β²)
    let (h, b, u) = (0.013, 108f64.to_radians(), 1.0 / 3.0);
    let after_switch = h * u - h * 2.0 / (1.0 - u) / (b * b);
    let at_top = h - h * 2.0 / (1.0 - u) / (b * b);
    let return_switch = h * (1.0 - u) - h * 2.0 / u / (b * b);
    assert!((r0 - (rho - after_switch.min(at_top).min(return_switch))).abs() < 1e-12);
}

#[test]
fn bad_inputs_are_refused() {
    assert!(matches!(
        Program::new(0.01, spec::parse_phases("rise 100 sine; return 100 sine; dwell 100").unwrap()),
        Err(CamError::PhaseSum { .. })
    ));
    assert!(matches!(
        Program::new(0.0, spec::parse_phases("rise 180 sine; return 180 sine").unwrap()),
        Err(CamError::Stroke(_))
    ));
    assert!(matches!(
        Program::new(-1.0, spec::parse_phases("rise 180 sine; return 180 sine").unwrap()),
        Err(CamError::Stroke(_))
    ));
    assert!(matches!(spec::parse_limits("90", false), Err(CamError::PressureLimit { .. })));
    assert!(matches!(
        spec::parse_limits("rise 0, return 30", true),
        Err(CamError::PressureLimit { .. })
    ));
    assert!(matches!(
        spec::parse_phases("rise 180 bogus; return 180 sine"),
        Err(CamError::UnknownLaw { .. })
    ));
    assert!(matches!(
        Program::new(0.01, spec::parse_phases("return 180 sine; rise 180 sine").unwrap()),
        Err(CamError::Sequence(_))
    ));
    // a roller larger than the pitch curve's curvature
    let task = CamTask {
        program: program(0.013, SEED),
        follower: FollowerSpec::TranslatingRoller {
            offset: None,
            roller: Some(0.05),
        },
        rotation: Rotation::Ccw,
        limits: spec::parse_limits("30", false).unwrap(),
        min_curvature: None,
        face_margin: 0.005,
        omega: 1.0,
        points: 360,
    };
    assert!(matches!(task.solve(), Err(CamError::RollerTooLarge { .. })));
}
