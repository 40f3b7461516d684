//! The generated profiles checked by geometry applied to their points: the
//! curvature by the parametric-curve formula with finite differences, the
//! pressure angle from the contact normal against the follower's direction
//! of motion, the roller offset distance, the flat face's tangency.

use tmm_cams::design::{CamDesign, CamTask, FollowerSpec};
use tmm_cams::mechanism::{Mechanism, Rotation};
use tmm_cams::program::Program;
use tmm_cams::spec;
use tmm_geom::Vec2;

const N: usize = 7200;

fn task(phases: &str, h: f64, follower: FollowerSpec, rot: Rotation, limits: &str) -> CamTask {
    CamTask {
        program: Program::new(h, spec::parse_phases(phases).unwrap()).unwrap(),
        follower,
        rotation: rot,
        limits: spec::parse_limits(limits, false).unwrap(),
        min_curvature: None,
        face_margin: 0.005,
        omega: 10.0,
        points: N,
    }
}

fn designs() -> Vec<(CamTask, CamDesign)> {
    let smooth = "rise 120 poly345; dwell 40; return 100 sine; dwell 100";
    let tasks = vec![
        task(
            smooth,
            0.02,
            FollowerSpec::TranslatingRoller {
                offset: None,
                roller: None,
            },
            Rotation::Ccw,
            "rise 25, return 35",
        ),
        task(
            smooth,
            0.02,
            FollowerSpec::TranslatingRoller {
                offset: Some(-0.004),
                roller: Some(0.0),
            },
            Rotation::Cw,
            "30",
        ),
        task(smooth, 0.02, FollowerSpec::TranslatingFlat { offset: 0.003 }, Rotation::Ccw, "30"),
        task(
            smooth,
            0.3,
            FollowerSpec::OscillatingRoller {
                arm: 0.09,
                pivot: None,
                roller: None,
            },
            Rotation::Ccw,
            "35",
        ),
        task(
            smooth,
            0.3,
            FollowerSpec::OscillatingRoller {
                arm: 0.09,
                pivot: None,
                roller: Some(0.004),
            },
            Rotation::Cw,
            "35",
        ),
        task(smooth, 0.25, FollowerSpec::OscillatingFlat { pivot: 0.12 }, Rotation::Ccw, "30"),
    ];
    tasks
        .into_iter()
        .map(|t| {
            let d = t.solve().unwrap();
            (t, d)
        })
        .collect()
}

/// Indices whose neighbours are all inside one smooth piece of the cycle
/// (away from phase joints, where curvature may jump).
fn smooth_index(t: &CamTask, i: usize) -> bool {
    let p = &t.program;
    let phi = std::f64::consts::TAU * i as f64 / N as f64;
    let margin = 3.0 * std::f64::consts::TAU / N as f64;
    (0..p.phases().len()).all(|k| {
        let a = p.start(k);
        (phi - a).abs() > margin && (phi - a - std::f64::consts::TAU).abs() > margin && phi > margin
    })
}

#[test]
fn curvature_matches_the_parametric_formula_on_the_points() {
    for (t, d) in designs() {
        let w = &d.profile.working;
        let sigma = t.rotation.sign();
        let mut checked = 0;
        for i in 1..N - 1 {
            if !smooth_index(&t, i) {
                continue;
            }
            // κ = (x′y″ − y′x″)/|X′|³ with central differences in the index
            let (a, b, c) = (w[i - 1], w[i], w[i + 1]);
            let d1 = (c - a) * 0.5;
            let d2 = c - b * 2.0 + a;
            let k = (d1.x * d2.y - d1.y * d2.x) / d1.hypot().powi(3);
            // the cam-frame curve runs clockwise for a counter-clockwise cam
            let k = -sigma * k;
            let kc = d.profile.curvature[i];
            assert!(
                (k - kc).abs() < 2e-3 * kc.abs().max(1.0 / d.r0),
                "{} at {i}: {k} vs {kc}",
                t.follower.name()
            );
            checked += 1;
        }
        assert!(checked > N / 2);
    }
}

/// The frame direction of the follower's rise motion at the pitch point `b` (frame).
fn rise_direction(m: &Mechanism, b: Vec2) -> Vec2 {
    match *m {
        Mechanism::TranslatingRoller { .. } | Mechanism::TranslatingFlat { .. } => Vec2::new(0.0, 1.0),
        Mechanism::OscillatingRoller { pivot, kappa, .. } => {
            let u = b - pivot;
            Vec2::new(-u.y, u.x) * (kappa / u.hypot())
        }
        Mechanism::OscillatingFlat { a, .. } => {
            let u = b - Vec2::new(a, 0.0);
            Vec2::new(-u.y, u.x) * (1.0 / u.hypot())
        }
    }
}

fn rot(v: Vec2, a: f64) -> Vec2 {
    Vec2::new(a.cos() * v.x - a.sin() * v.y, a.sin() * v.x + a.cos() * v.y)
}

#[test]
fn pressure_angle_recomputed_from_the_profile() {
    for (t, d) in designs() {
        if d.mechanism.is_flat() {
            continue;
        }
        let sigma = t.rotation.sign();
        let p = &d.profile.pitch;
        for i in (1..N - 1).step_by(7) {
            if !smooth_index(&t, i) {
                continue;
            }
            let phi = d.profile.phi[i];
            // tangent of the pitch curve in the cam frame, normal ⟂ to it, both turned back into the frame
            let tan = rot(p[i + 1] - p[i - 1], sigma * phi);
            let normal = Vec2::new(-tan.y, tan.x) * (1.0 / tan.hypot());
            let b = rot(p[i], sigma * phi);
            let dir = rise_direction(&d.mechanism, b);
            let th = normal.dot(dir).abs().min(1.0).acos();
            assert!(
                (th - d.profile.pressure[i]).abs() < 1e-5,
                "{} at φ = {:.2}°: {th} vs {}",
                t.follower.name(),
                phi.to_degrees(),
                d.profile.pressure[i]
            );
        }
    }
}

#[test]
fn pressure_extremes_respect_the_limits() {
    for (t, d) in designs() {
        if d.mechanism.is_flat() {
            continue;
        }
        assert!(d.pressure_max_rise <= t.limits.rise + 1e-4, "{}", t.follower.name());
        assert!(d.pressure_max_return <= t.limits.ret + 1e-4, "{}", t.follower.name());
        // the exact extremes bound every dense sample of their phases
        for (i, &phi) in d.profile.phi.iter().enumerate() {
            let k = t.program.phase_at(phi);
            let bound = match t.program.phases()[k].kind {
                tmm_cams::program::PhaseKind::Rise => d.pressure_max_rise,
                tmm_cams::program::PhaseKind::Return => d.pressure_max_return,
                tmm_cams::program::PhaseKind::Dwell => continue,
            };
            assert!(d.profile.pressure[i] <= bound + 1e-12, "{} at {i}", t.follower.name());
        }
    }
}

#[test]
fn radii_and_the_roller_offset() {
    for (t, d) in designs() {
        let prof = &d.profile;
        let min_pitch = prof.pitch.iter().map(|p| p.hypot()).fold(f64::INFINITY, f64::min);
        assert!(
            (min_pitch - d.r0).abs() < 1e-9,
            "{}: r0 {} vs nearest pitch point {min_pitch}",
            t.follower.name(),
            d.r0
        );
        let min_work = prof.working.iter().map(|p| p.hypot()).fold(f64::INFINITY, f64::min);
        assert!((min_work - d.rb).abs() < 1e-6, "{}: rb {} vs {min_work}", t.follower.name(), d.rb);
        if !d.mechanism.is_flat() {
            // every working point is one roller radius from the pitch point and no closer to the pitch curve
            for (i, w) in prof.working.iter().enumerate().step_by(13) {
                assert!(((*w - prof.pitch[i]).hypot() - d.roller).abs() < 1e-12);
                let nearest = prof.pitch.iter().map(|p| (*p - *w).hypot()).fold(f64::INFINITY, f64::min);
                assert!(nearest > d.roller - 1e-6, "the working profile is undercut at {i}");
            }
            // the course's rule
            assert!(
                d.roller <= 0.4 * d.r0 + 1e-15
                    || t.follower
                        != FollowerSpec::TranslatingRoller {
                            offset: None,
                            roller: None
                        }
            );
        }
    }
}

#[test]
fn flat_face_touches_its_line_tangentially() {
    for (t, d) in designs() {
        if !d.mechanism.is_flat() {
            continue;
        }
        let sigma = t.rotation.sign();
        for i in (1..N - 1).step_by(11) {
            if !smooth_index(&t, i) {
                continue;
            }
            let phi = d.profile.phi[i];
            let m = d.profile.motion[i];
            let c = rot(d.profile.working[i], sigma * phi);
            let tan = rot(d.profile.working[i + 1] - d.profile.working[i - 1], sigma * phi);
            let (n, p) = match d.mechanism {
                Mechanism::TranslatingFlat { r0, .. } => (Vec2::new(0.0, 1.0), r0 + m.s),
                Mechanism::OscillatingFlat { a, delta0 } => {
                    let dl = delta0 + m.s;
                    (Vec2::new(dl.sin(), -dl.cos()), a * dl.sin())
                }
                _ => unreachable!(),
            };
            assert!((n.dot(c) - p).abs() < 1e-12, "contact off the face at {i}");
            assert!(n.dot(tan).abs() < 1e-3 * tan.hypot(), "profile not tangent to the face at {i}");
        }
        // Geronimus for the translating face: ρ = r0 + s + s″ ≥ ρmin = 10 mm
        if let Mechanism::TranslatingFlat { r0, .. } = d.mechanism {
            for (i, m) in d.profile.motion.iter().enumerate() {
                assert!((1.0 / d.profile.curvature[i] - (r0 + m.s + m.a)).abs() < 1e-9);
            }
            assert!((d.rho_min - 0.010).abs() < 1e-9);
        }
    }
}
