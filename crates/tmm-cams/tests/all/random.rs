//! Random cycles: every design keeps its limits, at least one limit is
//! reached (the cam cannot be smaller), r₀ is the nearest pitch point, and
//! nothing panics or turns non-finite.

use proptest::prelude::*;
use tmm_cams::design::{CamTask, FollowerSpec};
use tmm_cams::mechanism::Rotation;
use tmm_cams::program::Program;
use tmm_cams::spec::{self, Limits};

const LAWS: [&str; 9] = [
    "const-accel(u=1/3)",
    "const-accel(u=0.6)",
    "cosine",
    "sine",
    "linear-decreasing",
    "trapezoid",
    "mod-trapezoid",
    "mod-sine",
    "poly345",
];

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    #[test]
    fn translating_roller_designs_are_tight(
        rise in 40.0f64..170.0, top in 0.0f64..60.0, ret in 40.0f64..150.0,
        l1 in 0usize..9, l2 in 0usize..9,
        lim_r in 12.0f64..45.0, lim_t in 12.0f64..50.0,
        h in 0.002f64..0.05, ccw in any::<bool>(),
    ) {
        let bottom = 360.0 - rise - top - ret;
        prop_assume!(bottom > 1.0);
        let phases = if top > 1.0 {
            format!("rise {rise} {}; dwell {top}; return {ret} {}; dwell {bottom}", LAWS[l1], LAWS[l2])
        } else {
            format!("rise {rise} {}; return {ret} {}; dwell {}", LAWS[l1], LAWS[l2], bottom + top)
        };
        let task = CamTask {
            program: Program::new(h, spec::parse_phases(&phases).unwrap()).unwrap(),
            follower: FollowerSpec::TranslatingRoller { offset: None, roller: None },
            rotation: if ccw { Rotation::Ccw } else { Rotation::Cw },
            limits: Limits { rise: lim_r.to_radians(), ret: lim_t.to_radians() },
            min_curvature: None,
            face_margin: 0.005,
            omega: 1.0,
            points: 720,
        };
        let d = task.solve().unwrap();
        let (er, et) = (d.pressure_max_rise - task.limits.rise, d.pressure_max_return - task.limits.ret);
        prop_assert!(er <= 1e-9 && et <= 1e-9, "limits exceeded: {er} {et}");
        prop_assert!(er.max(et) > -1e-7, "no limit is reached: {er} {et}");
        let nearest = d.profile.pitch.iter().map(|p| p.hypot()).fold(f64::INFINITY, f64::min);
        prop_assert!((nearest - d.r0).abs() < 1e-9 * (1.0 + d.r0));
        prop_assert!(d.roller > 0.0 && d.roller <= 0.4 * d.r0 + 1e-15);
        prop_assert!(d.profile.curvature.iter().all(|k| k.is_finite()));
    }
}
