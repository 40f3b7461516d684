//! Random extreme but well-formed input thrown at the public entry points:
//! Ok with finite numbers or a typed error, never a panic, NaN or infinity.

use proptest::prelude::*;
use tmm_cams::design::{CamDesign, CamTask, FollowerSpec};
use tmm_cams::law::{Law, LawKind};
use tmm_cams::mechanism::Rotation;
use tmm_cams::program::Program;
use tmm_cams::spec;

/// Mostly sensible values, often absurd ones.
fn mostly(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    prop_oneof![3 => lo..hi, 1 => wild()]
}

fn wild() -> impl Strategy<Value = f64> {
    prop_oneof![
        (-300i32..300).prop_map(|e| 10f64.powi(e)),
        (-300i32..300).prop_map(|e| -(10f64.powi(e))),
        0.001f64..0.2,
        Just(0.0),
        Just(f64::MAX),
        Just(f64::NAN),
        Just(f64::INFINITY),
    ]
}

const LAWS: [&str; 6] = [
    "const-accel(u=1/3)",
    "cosine",
    "sine",
    "const-velocity",
    "poly4567",
    "table(1, 0, -1)",
];

fn finite(d: &CamDesign) -> bool {
    [d.r0, d.rb, d.roller, d.pressure_max_rise, d.pressure_max_return, d.rho_min]
        .iter()
        .all(|v| v.is_finite())
        && d.profile
            .pitch
            .iter()
            .chain(&d.profile.working)
            .all(|p| p.x.is_finite() && p.y.is_finite())
        && d.profile.curvature.iter().chain(&d.profile.pressure).all(|v| v.is_finite())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]
    #[test]
    fn designs_are_finite_or_errors(
        h in mostly(0.001, 0.05), omega in mostly(1.0, 1e3), a1 in 10.0f64..200.0, a2 in 10.0f64..140.0,
        l1 in 0usize..6, l2 in 0usize..6, kind in 0usize..4,
        x in mostly(-0.02, 0.02), y in mostly(0.05, 0.3), r0 in mostly(0.02, 0.2), lim in 1.0f64..89.0,
    ) {
        let rest = 360.0 - a1 - a2;
        prop_assume!(rest > 1.0);
        let text = format!("rise {a1} {}; return {a2} {}; dwell {rest}", LAWS[l1], LAWS[l2]);
        let Ok(program) = Program::new(h, spec::parse_phases(&text).unwrap()) else { return Ok(()) };
        for m in program.diagram(64) {
            prop_assert!(m.1.s.is_finite() && m.1.v.is_finite() && m.1.a.is_finite() && m.1.j.is_finite());
        }
        prop_assert!(program.jumps().iter().all(|j| j.before.is_finite() && j.after.is_finite()));
        let follower = match kind {
            0 => FollowerSpec::TranslatingRoller { offset: Some(x).filter(|v| v.abs() < 1.0), roller: Some(y.abs()).filter(|v| *v < 1.0) },
            1 => FollowerSpec::TranslatingFlat { offset: x },
            2 => FollowerSpec::OscillatingRoller { arm: x, pivot: Some(y), roller: None },
            _ => FollowerSpec::OscillatingFlat { pivot: y },
        };
        let task = CamTask {
            program,
            follower,
            rotation: Rotation::Cw,
            limits: spec::Limits { rise: lim.to_radians(), ret: lim.to_radians() },
            min_curvature: None,
            face_margin: 0.005,
            omega,
            points: 64,
        };
        if kind != 2 {
            if let Ok(d) = task.solve() {
                prop_assert!(finite(&d), "{task:?}");
            }
        }
        if let Ok(d) = task.solve_with_r0(r0) {
            prop_assert!(finite(&d), "given r0 {r0}: {task:?}");
        }
    }

    #[test]
    fn texts_and_tables_never_panic(s in "\\PC{0,40}", v in proptest::collection::vec(wild(), 0..6)) {
        let _ = spec::parse_phases(&s);
        let _ = spec::parse_limits(&s, false);
        let _ = spec::parse_law(&s);
        if let Ok(l) = Law::new(LawKind::Table(v)) {
            for i in 0..=16 {
                let y = l.eval(i as f64 / 16.0);
                prop_assert!(y.iter().all(|v| v.is_finite()));
            }
        }
    }
}
