//! Random extreme but well-formed input thrown at the public entry points:
//! every call returns Ok with finite numbers or a typed error, never a panic,
//! NaN or infinity.

use proptest::prelude::*;
use tmm_gears::centre::shift_sum_for_aw;
use tmm_gears::choose::{Criterion, choose};
use tmm_gears::contour::{ContourOptions, blocking_contour};
use tmm_gears::generate::generate;
use tmm_gears::spec::{lone_tip_thickness, smallest_cuttable, xmin};
use tmm_gears::{BasicRack, Kind, Limits, Pair, PairSpec};

/// Magnitudes from the tiny to the absurd, both signs, and the special values.
fn wild() -> impl Strategy<Value = f64> {
    prop_oneof![
        (-300i32..300).prop_map(|e| 10f64.powi(e)),
        (-300i32..300).prop_map(|e| -(10f64.powi(e))),
        -5.0f64..5.0,
        Just(0.0),
        Just(f64::MAX),
        Just(f64::MIN_POSITIVE),
        Just(f64::NAN),
        Just(f64::INFINITY),
    ]
}

fn teeth() -> impl Strategy<Value = u32> {
    prop_oneof![0u32..300, Just(u32::MAX), 1000u32..100_000]
}

fn finite_pair(p: &Pair) -> bool {
    let w = |w: &tmm_gears::Wheel| {
        [w.d, w.db, w.dw, w.da, w.df, w.h, w.s, w.sa, w.alpha_a, w.rho_a, w.rho_p, w.rho_l]
            .iter()
            .all(|v| v.is_finite())
    };
    [
        p.a,
        p.alpha_w,
        p.aw,
        p.y,
        p.dy,
        p.g,
        p.s_start,
        p.s_end,
        p.eps_alpha,
        p.eps_alpha_gost,
    ]
    .iter()
    .all(|v| v.is_finite())
        && w(&p.w1)
        && w(&p.w2)
        && p.checks(&Limits::default())
            .as_slice()
            .iter()
            .all(|c| c.value.is_finite() && c.limit.is_finite())
        && p.sliding_table(9).iter().all(|q| q.theta1.is_finite() && q.theta2.is_finite())
        && p.theta1_max().is_none_or(f64::is_finite)
        && p.theta2_max().is_none_or(f64::is_finite)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]
    #[test]
    fn pair_is_finite_or_an_error(
        z1 in teeth(), z2 in teeth(), m in wild(), x1 in wild(), x2 in wild(),
        alpha in wild(), ha in wild(), internal in any::<bool>(),
    ) {
        let rack = BasicRack { alpha, ha, ..BasicRack::default() };
        let spec = PairSpec {
            rack: if alpha.is_nan() { BasicRack::default() } else { rack },
            kind: if internal { Kind::Internal } else { Kind::External },
            ..PairSpec::external(z1, z2, m, x1, x2)
        };
        if let Ok(p) = Pair::new(&spec) {
            prop_assert!(finite_pair(&p), "{spec:?}");
        }
        // `compute` is for the contour's inner loop: its caller validated the
        // spec apart from the shifts, which may be anything
        let valid_but_shifts = PairSpec { x1: 0.0, x2: 0.0, ..spec }.validate().is_ok();
        if valid_but_shifts && let Ok(p) = Pair::compute(&spec) {
            prop_assert!(finite_pair(&p), "compute {spec:?}");
        }
        if let Ok(xs) = shift_sum_for_aw(z1, z2, m, x1.abs(), &spec.rack, spec.kind) {
            prop_assert!(xs.is_finite());
        }
        let r = BasicRack::default();
        prop_assert!(xmin(z1, &r).is_finite());
        if let Some(s) = lone_tip_thickness(z1, x1, &r) {
            prop_assert!(s.is_finite());
        }
        if let Ok(f) = spec.rack.fit_fillet() {
            prop_assert!(f.rho_f.is_finite() && f.rack.hl.is_finite());
            prop_assert!(smallest_cuttable(&f.rack) >= 1);
        }
    }

    #[test]
    fn generated_teeth_are_finite_or_an_error(z in teeth(), m in wild(), x in wild(), ra in wild(), alpha in 5.5f64..44.0) {
        let rack = BasicRack { alpha: alpha.to_radians(), ..BasicRack::default() };
        if let Ok(t) = generate(z, m, x, &rack, ra, 16) {
            prop_assert!(t.half.iter().all(|p| p.r.is_finite() && p.psi.is_finite()));
            prop_assert!(t.fillet_radius.is_finite());
        }
        let ring = tmm_gears::generate::ring_profile(z, m, x, &rack, ra, ra * 1.1, ra * 1.05, 16);
        prop_assert!(ring.half.iter().all(|p| p.r.is_finite() && p.psi.is_finite()));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]
    #[test]
    fn contour_and_choice_are_finite_or_an_error(
        z1 in prop_oneof![8u32..60, Just(u32::MAX)], z2 in prop_oneof![8u32..120, Just(u32::MAX)],
        m in prop_oneof![Just(1e160), Just(0.002), Just(1e-9)], internal in any::<bool>(), crit in 0usize..3,
    ) {
        let spec = PairSpec {
            kind: if internal { Kind::Internal } else { Kind::External },
            ..PairSpec::external(z1, z2, m, 0.0, 0.0)
        };
        let opts = ContourOptions { n: 12, ..ContourOptions::default() };
        if let Ok(c) = blocking_contour(&spec, &opts) {
            for l in &c.lines {
                prop_assert!(l.polylines.iter().flatten().all(|&(a, b)| a.is_finite() && b.is_finite()));
            }
        }
        let crit = [Criterion::EqualSliding, Criterion::MaxContactRatio, Criterion::Balanced][crit];
        if let Ok(ch) = choose(&spec, crit, None, &Limits::default()) {
            prop_assert!(finite_pair(&ch.pair));
        }
    }
}

/// The shift sum for a centre distance refuses a basic rack out of range:
/// found by the property above (α = −1e38 gave NaN).
#[test]
fn shift_sum_for_aw_refuses_what_has_no_finite_sum() {
    let bad = BasicRack {
        alpha: -1e38,
        ..BasicRack::default()
    };
    assert!(shift_sum_for_aw(1000, u32::MAX, 0.1, 0.0, &bad, Kind::External).is_err());
    let r = BasicRack::default();
    // an ordinary request still has its closed form: aw = a gives x1 + x2 = 0
    let a = 0.5 * 50.0 * 0.005;
    let xs = shift_sum_for_aw(20, 30, 0.005, a, &r, Kind::External).unwrap();
    assert!(xs.abs() < 1e-12, "{xs}");
}
