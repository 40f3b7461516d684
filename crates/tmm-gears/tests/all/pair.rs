//! Pair geometry against independent references: seed 001 (MADI, variant 17,
//! sheet 2) recomputed from GOST 16532-70 inside the test, the centre-distance
//! identities, and the contact ratio two ways.

use std::f64::consts::PI;

use tmm_gears::{BasicRack, Kind, Limits, Pair, PairSpec};

fn inv(a: f64) -> f64 {
    a.tan() - a
}

/// Inverse involute by plain bisection (independent of the crate's Newton).
fn inv_inv(v: f64) -> f64 {
    let (mut lo, mut hi) = (0.0f64, 1.5f64);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if inv(mid) < v { lo = mid } else { hi = mid }
    }
    0.5 * (lo + hi)
}

#[test]
fn seed_001_sheet_2_recomputed() {
    // Seed 001: z1 = 15, z2 = 20, m = 5 mm, x1 = 0.2, x2 = 0.85, α = 20°, ha* = 1, c* = 0.25, hl* = 2.
    let (z1, z2, m, x1, x2) = (15.0, 20.0, 5.0, 0.2, 0.85);
    let al = 20f64.to_radians();
    let p = Pair::new(&PairSpec::external(15, 20, 0.005, 0.2, 0.85)).unwrap();
    let mm = |v: f64| v * 1000.0;
    // a = 87.5 mm (the text prints 85.5 by a typo and computes with 87.5).
    let a = (z1 + z2) * m / 2.0;
    assert_eq!(a, 87.5);
    assert!((mm(p.a) - a).abs() < 1e-12);
    let inv_aw = inv(al) + 2.0 * (x1 + x2) * al.tan() / (z1 + z2);
    assert!((p.inv_alpha_w - inv_aw).abs() < 1e-15);
    // The seed prints inv αw = 0.036742012 (0.0367426 exactly: rounded tg α).
    assert!((inv_aw - 0.036742012).abs() < 1e-6);
    let aw_angle = inv_inv(inv_aw);
    assert!((p.alpha_w - aw_angle).abs() < 1e-12, "inverse involute to 1e-12");
    // The seed: αw = 26.654°, aw = 91.99949 mm (graphical rounding in the 5th digit).
    assert!((p.alpha_w.to_degrees() - 26.654).abs() < 5e-3);
    let aw = a * al.cos() / aw_angle.cos();
    assert!((mm(p.aw) - aw).abs() < 1e-9);
    assert!((aw - 91.9995).abs() < 2e-3);
    let y = (aw - a) / m;
    let dy = x1 + x2 - y;
    assert!((p.y - y).abs() < 1e-9 && (p.dy - dy).abs() < 1e-9);
    let (d1, d2) = (z1 * m, z2 * m);
    let da1 = d1 + 2.0 * (1.0 + x1 - dy) * m;
    let da2 = d2 + 2.0 * (1.0 + x2 - dy) * m;
    let df1 = d1 - 2.0 * (1.25 - x1) * m;
    let df2 = d2 - 2.0 * (1.25 - x2) * m;
    assert!((mm(p.w1.da) - da1).abs() < 1e-9 && (mm(p.w2.da) - da2).abs() < 1e-9);
    assert!((mm(p.w1.df) - 64.5).abs() < 1e-9 && (mm(p.w2.df) - 96.0).abs() < 1e-9);
    assert!((df1 - 64.5).abs() < 1e-12 && (df2 - 96.0).abs() < 1e-12);
    // Seed: da1 = 85.499, da2 = 116.999 mm.
    assert!((da1 - 85.499).abs() < 2e-3 && (da2 - 116.999).abs() < 2e-3);
    // dw1 = 2 aw / (u + 1) with the exact ratio (the seed rounds u to 1.333).
    assert!((mm(p.w1.dw) - 2.0 * aw / (z2 / z1 + 1.0)).abs() < 1e-9);
    assert!((mm(p.w2.dw) - 2.0 * aw * (z2 / z1) / (z2 / z1 + 1.0)).abs() < 1e-9);
    // s = (π/2 + 2 x tg α) m; seed: 8.584 and 10.948 mm with π ≈ 3.14.
    let s1 = (PI / 2.0 + 2.0 * x1 * al.tan()) * m;
    let s2 = (PI / 2.0 + 2.0 * x2 * al.tan()) * m;
    assert!((mm(p.w1.s) - s1).abs() < 1e-9 && (mm(p.w2.s) - s2).abs() < 1e-9);
    // Tip: αa, sa.
    let (db1, db2) = (d1 * al.cos(), d2 * al.cos());
    let aa1 = (db1 / da1).acos();
    let aa2 = (db2 / da2).acos();
    assert!((aa1.to_degrees() - 34.48).abs() < 0.01, "seed: 34.4825°");
    let sa1 = da1 * (s1 / d1 + inv(al) - inv(aa1));
    let sa2 = da2 * (s2 / d2 + inv(al) - inv(aa2));
    assert!((mm(p.w1.sa) - sa1).abs() < 1e-9 && (mm(p.w2.sa) - sa2).abs() < 1e-9);
    // ρp and ρl (seed §III.7, §IV.2).
    let (rb1, rb2) = (db1 / 2.0, db2 / 2.0);
    let rp1 = aw * aw_angle.sin() - rb2 * aa2.tan();
    let rp2 = aw * aw_angle.sin() - rb1 * aa1.tan();
    assert!((mm(p.w1.rho_p) - rp1).abs() < 1e-9 && (mm(p.w2.rho_p) - rp2).abs() < 1e-9);
    assert!((rp1 - 6.419).abs() < 0.01 && (rp2 - 17.068).abs() < 0.01);
    let rl1 = d1 / 2.0 * al.sin() - (2.0 - 1.0 - x1) * m / al.sin();
    let rl2 = d2 / 2.0 * al.sin() - (2.0 - 1.0 - x2) * m / al.sin();
    assert!((mm(p.w1.rho_l) - rl1).abs() < 1e-9 && (mm(p.w2.rho_l) - rl2).abs() < 1e-9);
    // The seed prints 1.32853 and 15.17197: it evaluated d·sin α / 2 as d·sin(α/2)
    // (0.17365 = sin 10°). Recomputed: 1.1306 and 14.908 mm.
    assert!((rl1 - 1.1306).abs() < 1e-3 && (rl2 - 14.908).abs() < 1e-3);
    // εα ≈ 1.205, not 3.72 (the seed's typo).
    let eps = (z1 * aa1.tan() + z2 * aa2.tan() - (z1 + z2) * aw_angle.tan()) / (2.0 * PI);
    assert!((p.eps_alpha - eps).abs() < 1e-12);
    assert!((eps - 1.205).abs() < 0.003, "{eps}");
    // xmin (seed §IV.1): 0.1227 and −0.1698.
    assert!((p.w1.xmin.unwrap() - (1.0 - z1 * al.sin().powi(2) / 2.0)).abs() < 1e-12);
    assert!((p.w1.xmin.unwrap() - 0.12267).abs() < 1e-4 && (p.w2.xmin.unwrap() + 0.16978).abs() < 1e-4);
    assert!(p.checks(&Limits::default()).all_pass());
}

/// aw = rw1 + rw2 = r1 + r2 + y·m = ra1 + rf2 + c*·m = rf1 + ra2 + c*·m (seed 001 §II).
#[test]
fn centre_distance_identities() {
    for &(z1, z2, x1, x2) in &[
        (15u32, 20u32, 0.2, 0.85),
        (12, 40, 0.5, 0.3),
        (17, 17, 0.0, 0.0),
        (25, 60, -0.2, 0.1),
        (10, 31, 0.6, 0.9),
    ] {
        let m = 0.004;
        let p = Pair::new(&PairSpec::external(z1, z2, m, x1, x2)).unwrap();
        let tol = 1e-12;
        assert!((p.aw - (p.w1.dw + p.w2.dw) / 2.0).abs() < tol);
        assert!((p.aw - (p.w1.d / 2.0 + p.w2.d / 2.0 + p.y * m)).abs() < tol);
        assert!((p.aw - (p.w1.da / 2.0 + p.w2.df / 2.0 + 0.25 * m)).abs() < tol);
        assert!((p.aw - (p.w1.df / 2.0 + p.w2.da / 2.0 + 0.25 * m)).abs() < tol);
        // h = (2 ha* + c* − Δy) m for both wheels.
        assert!((p.w1.h - (2.25 - p.dy) * m).abs() < tol && (p.w2.h - (2.25 - p.dy) * m).abs() < tol);
        // Δy ≥ 0 for a non-negative shift sum (GOST 16532-70 t.1, note).
        if x1 + x2 >= 0.0 {
            assert!(p.dy >= -1e-9, "{}", p.dy);
        }
    }
}

/// εα two ways: GOST's tan formula and the length of the active line over pb;
/// a third, by brute force: the contact points swept while the pinion turns by
/// one base pitch angle, counted from a sampled line of action.
#[test]
fn contact_ratio_two_ways() {
    for &(z1, z2, x1, x2) in &[
        (15u32, 20u32, 0.2, 0.85),
        (20, 50, 0.0, 0.0),
        (13, 37, 0.4, 0.2),
        (30, 30, -0.3, 0.3),
    ] {
        let p = Pair::new(&PairSpec::external(z1, z2, 0.003, x1, x2)).unwrap();
        let r = BasicRack::default();
        let (rb1, rb2) = (p.w1.db / 2.0, p.w2.db / 2.0);
        let (ra1, ra2) = (p.w1.da / 2.0, p.w2.da / 2.0);
        // length of action from the tip circles: ga = √(ra1² − rb1²) + √(ra2² − rb2²) − aw sin αw
        let ga = (ra1 * ra1 - rb1 * rb1).sqrt() + (ra2 * ra2 - rb2 * rb2).sqrt() - p.aw * p.alpha_w.sin();
        let pb = PI * 0.003 * r.alpha.cos();
        assert!((p.eps_alpha - ga / pb).abs() < 1e-12);
        assert!((p.eps_alpha_by_length() - ga / pb).abs() < 1e-12);
    }
}

#[test]
fn internal_pair_basics() {
    let spec = PairSpec {
        kind: Kind::Internal,
        ..PairSpec::external(20, 60, 0.002, 0.0, 0.0)
    };
    let p = Pair::new(&spec).unwrap();
    // a = m (z2 − z1) / 2 and αw = α without shifts.
    assert!((p.aw - 0.040).abs() < 1e-15);
    assert!((p.alpha_w - 20f64.to_radians()).abs() < 1e-12);
    // rw2 − rw1 = aw, both tangent at the pole.
    assert!((p.w2.dw / 2.0 - p.w1.dw / 2.0 - p.aw).abs() < 1e-15);
    // εα by the length of the active line equals the tan formula.
    assert!((p.eps_alpha - p.eps_alpha_by_length()).abs() < 1e-12);
    assert!(p.eps_alpha > 1.5);
}

/// Bad data gives typed errors, never a panic or a non-finite result.
#[test]
fn bad_data_errors() {
    use tmm_gears::GearError;
    let e = |s: PairSpec| Pair::new(&s).unwrap_err();
    // z below the smallest that can be cut (8 for the 20° rack)
    assert!(matches!(
        e(PairSpec::external(7, 20, 0.002, 0.0, 0.0)),
        GearError::TooFewTeeth { wheel: 1, min: 8, .. }
    ));
    assert!(matches!(
        e(PairSpec::external(20, 5, 0.002, 0.0, 0.0)),
        GearError::TooFewTeeth { wheel: 2, .. }
    ));
    // m ≤ 0, non-finite
    assert!(matches!(e(PairSpec::external(20, 30, 0.0, 0.0, 0.0)), GearError::Module(_)));
    assert!(matches!(e(PairSpec::external(20, 30, -1.0, 0.0, 0.0)), GearError::Module(_)));
    assert!(matches!(
        e(PairSpec::external(20, 30, 0.002, f64::NAN, 0.0)),
        GearError::Shift { wheel: 1 }
    ));
    // da ≤ df: Δy of a huge shift sum eats the tooth; check the cause with the formulas
    let err = e(PairSpec::external(20, 20, 0.001, 5.0, 5.0));
    let GearError::TipBelowRoot { da, df, .. } = err else {
        panic!("{err:?}")
    };
    assert!(da <= df);
    // a centre distance no shift sum can reach: aw ≤ a cos α
    let r = BasicRack::default();
    let a = 0.0875;
    assert!(matches!(
        tmm_gears::centre::shift_sum_for_aw(15, 20, 0.005, a * r.alpha.cos(), &r, Kind::External),
        Err(GearError::CentreDistance { .. })
    ));
    assert!(tmm_gears::centre::shift_sum_for_aw(15, 20, 0.005, a * r.alpha.cos() * 1.0001, &r, Kind::External).is_ok());
    // a basic rack out of range names its parameter
    let bad_rack = PairSpec {
        rack: BasicRack { hl: 5.0, ..r },
        ..PairSpec::external(20, 30, 0.002, 0.0, 0.0)
    };
    assert!(matches!(e(bad_rack), GearError::Rack { param: "hl", .. }));
    // no panic over a wide sweep of shifts; every Ok pair is finite
    for i in -30..=30 {
        for j in -30..=30 {
            if let Ok(p) = Pair::new(&PairSpec::external(9, 40, 0.003, i as f64 * 0.1, j as f64 * 0.1)) {
                assert!(p.eps_alpha.is_finite() && p.w1.sa.is_finite() && p.w2.rho_p.is_finite());
            }
        }
    }
}
