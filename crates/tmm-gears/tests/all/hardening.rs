//! Regression tests for defects of the pair calculation, each against a closed
//! form written out here or a brute force, never against the crate's output.

use std::f64::consts::PI;

use tmm_gears::checks::CheckKind;
use tmm_gears::generate::generate;
use tmm_gears::spec::check_module;
use tmm_gears::{BasicRack, GearError, Kind, Limits, Pair, PairSpec};

fn inv(a: f64) -> f64 {
    a.tan() - a
}

fn check(p: &Pair, kind: CheckKind) -> bool {
    p.checks(&Limits::default())
        .as_slice()
        .iter()
        .find(|c| c.kind == kind)
        .map(|c| c.pass)
        .unwrap()
}

/// z = 10/60, m = 1 mm, unshifted: the pinion is undercut (ρl1 < 0) and the
/// path of contact runs past N1 (ρp1 < 0). The old check ρl1 ≤ ρp1 passed
/// because both were negative; the involute ends at N1, so the limit is
/// max(ρl1, 0) and there is interference. εα counts the real line only.
#[test]
fn undercut_pinion_with_the_path_past_n1_interferes() {
    let p = Pair::new(&PairSpec::external(10, 60, 0.001, 0.0, 0.0)).unwrap();
    let al = 20f64.to_radians();
    let (m, z1, z2) = (1.0, 10.0, 60.0);
    // unshifted: aw = a, αw = α
    let aw = (z1 + z2) * m / 2.0;
    let g = aw * al.sin();
    let (rb1, rb2) = (z1 * m / 2.0 * al.cos(), z2 * m / 2.0 * al.cos());
    let (ra1, ra2) = (z1 * m / 2.0 + m, z2 * m / 2.0 + m);
    let rho_a1 = (ra1 * ra1 - rb1 * rb1).sqrt();
    let rho_a2 = (ra2 * ra2 - rb2 * rb2).sqrt();
    let rho_p1 = g - rho_a2;
    let rho_l1 = z1 * m / 2.0 * al.sin() - m / al.sin();
    let rho_l2 = z2 * m / 2.0 * al.sin() - m / al.sin();
    assert!(rho_p1 < 0.0 && rho_l1 < rho_p1, "the case of the report: {rho_l1} < {rho_p1} < 0");
    assert!(!check(&p, CheckKind::Interference(1)));
    // the real active line runs from N1 (s = 0) to the pinion's tip
    let s_end = rho_a1.min(g - rho_l2.max(0.0));
    let eps = (s_end - 0.0) / (PI * m * al.cos());
    assert!((p.eps_alpha - eps).abs() < 1e-12, "{} vs {eps}", p.eps_alpha);
    let gost = (z1 * (rho_a1 / rb1) + z2 * (rho_a2 / rb2) - (z1 + z2) * al.tan()) / (2.0 * PI);
    assert!((gost - 1.577).abs() < 1e-3 && (p.eps_alpha_gost - gost).abs() < 1e-12);
    assert!(p.eps_alpha < gost - 0.3);
    // ϑ1 = 1 − ρ2/(u ρ1) with ρ1 > 0 on the real line is below 1 and very negative near N1
    let t = p.sliding_table(21);
    assert!(t.iter().all(|q| q.s > 0.0 && q.theta1.is_finite() && q.theta2.is_finite()));
    assert!(t[0].theta1 < -10.0);
    assert!(p.theta1_max().is_none(), "the line reaches N1: ϑ1 is unbounded");
}

/// The internal pair 16/24, m = 3 mm, x = 0/0.5: the involute-interference
/// condition z1/z2 ≥ 1 − tg αa2/tg αw (KHK, Gear Technical Reference,
/// internal gears) fails by −0.0014, and the check must say so.
#[test]
fn internal_16_24_involute_interference() {
    let spec = PairSpec {
        kind: Kind::Internal,
        ..PairSpec::external(16, 24, 0.003, 0.0, 0.5)
    };
    let p = Pair::compute(&spec).unwrap();
    let al = 20f64.to_radians();
    let (z1, z2, m, x2) = (16.0, 24.0, 3.0, 0.5);
    let inv_aw = inv(al) + 2.0 * (x2 - 0.0) * al.tan() / (z2 - z1);
    let (mut lo, mut hi) = (0.0f64, 1.5f64);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if inv(mid) < inv_aw { lo = mid } else { hi = mid }
    }
    let aw_angle = 0.5 * (lo + hi);
    let da2 = z2 * m - 2.0 * (1.0 - x2) * m;
    let aa2 = (z2 * m * al.cos() / da2).acos();
    let margin = z1 / z2 - 1.0 + aa2.tan() / aw_angle.tan();
    assert!((margin + 0.0014).abs() < 5e-5, "{margin}");
    assert!(!check(&p, CheckKind::Interference(1)));
    assert!(Pair::new(&spec).is_ok(), "a failed check, not a refusal");
}

/// z = 15/20, m = 5 mm, x1 = 5, x2 = 0.85: the tip shortening of the huge shift
/// sum leaves the tip below the circle where the rack's straight flank starts
/// the involute — the tooth is all fillet. The message names wheel 1 and tells
/// to lower the shift.
#[test]
fn tooth_with_no_involute_is_reported_for_its_wheel() {
    let e = Pair::new(&PairSpec::external(15, 20, 0.005, 5.0, 0.85)).unwrap_err();
    let GearError::TipInsideBase { wheel, da, db, form } = e else {
        panic!("{e:?}")
    };
    assert_eq!((wheel, form), (1, true));
    // form circle: ρl1 = r1 sin α − (hl* − ha* − x1) m / sin α, d = 2√(rb1² + ρl1²)
    let (al, m) = (20f64.to_radians(), 5.0);
    let rho_l1 = 37.5 * al.sin() - (1.0 - 5.0) * m / al.sin();
    let dl = 2.0 * (37.5 * al.cos()).hypot(rho_l1);
    assert!((db * 1e3 - dl).abs() < 1e-9, "{} vs {dl}", db * 1e3);
    assert!(da < db && (da * 1e3 - 115.04).abs() < 0.01);
    let msg = e.to_string();
    assert!(msg.starts_with("wheel 1:") && !msg.contains("wheel 0"), "{msg}");
    assert!(e.help().contains("lower x1"), "{}", e.help());
}

/// A module typed without its unit ("5" read as 5 m) is refused, naming the
/// range of GOST 9563-60 (0.05 … 100 mm) and suggesting millimetres.
#[test]
fn implausible_module_is_refused() {
    let e = Pair::new(&PairSpec::external(15, 20, 5.0, 0.0, 0.0)).unwrap_err();
    assert!(matches!(e, GearError::Module(m) if m == 5.0));
    assert!(e.to_string().contains("did you mean 5 mm"), "{e}");
    assert!(check_module(0.05e-3).is_ok() && check_module(0.1).is_ok());
    assert!(check_module(0.049e-3).is_err() && check_module(0.101).is_err());
    assert!(Pair::new(&PairSpec::external(15, 20, 1e160, 0.0, 0.0)).is_err());
}

/// α = 25° with hl* = 2 asks for a cutter fillet ρf* = 0.25/(1 − sin 25°) = 0.433
/// that does not fit on the cutter's tooth; the largest that fits is the
/// full-round tip, checked here by plain geometry.
#[test]
fn largest_fitting_fillet_on_a_25_degree_rack() {
    let al = 25f64.to_radians();
    let rack = BasicRack {
        alpha: al,
        ..BasicRack::default()
    };
    let fit = rack.fit_fillet().unwrap();
    assert!(fit.reduced);
    assert!((fit.rho_f_nominal - 0.25 / (1.0 - al.sin())).abs() < 1e-12);
    // Cutter tooth (m = 1) centred on ξ = 0, tip line η = −1.25, flank through
    // (π/4, 0) with direction (sin α, cos α)·(−1): a circle on the centreline
    // (0, −1.25 + ρ) tangent to the tip line and to the flank has
    // distance-to-flank = ρ.
    let rho = fit.rho_f;
    let (cx, cy) = (0.0, -1.25 + rho);
    // flank line: points (π/4 + η tg α, η); unit normal (cos α, −sin α)
    let dist = ((cx - PI / 4.0) * al.cos() - cy * al.sin()).abs();
    assert!((dist - rho).abs() < 1e-12, "{dist} vs {rho}");
    // the tangent point on the flank is where the straight part ends: depth hl* − ha*
    let foot_eta = cy - rho * al.sin(); // centre + ρ·(outward normal)
    assert!((-foot_eta - (fit.rack.hl - 1.0)).abs() < 1e-12);
    // and the teeth are generated with it
    let t = generate(20, 0.002, 0.0, &rack, 0.022, 40).unwrap();
    assert!(t.fillet_reduced && (t.fillet_radius - rho * 0.002).abs() < 1e-15);
    // a rack whose tooth is pointed before its tip line has no fillet at all
    let sharp = BasicRack {
        alpha: 40f64.to_radians(),
        ..BasicRack::default()
    };
    assert!(matches!(sharp.fit_fillet(), Err(GearError::Rack { param: "alpha", .. })));
}

/// A ring's tip circle d2 − 2(ha* − x2)m is outside its base circle d2 cos α only
/// when z2 > 2(ha* − x2)/(1 − cos α) = 33.16 for x2 = 0: the advice names z2 ≥ 34
/// or a larger x2, not z2 − z1.
#[test]
fn small_ring_advice() {
    let al = 20f64.to_radians();
    let zlim = 2.0 / (1.0 - al.cos());
    for z2 in 28..40u32 {
        let spec = PairSpec {
            kind: Kind::Internal,
            ..PairSpec::external(18, z2, 0.002, 0.0, 0.0)
        };
        let r = Pair::compute(&spec);
        if (z2 as f64) < zlim {
            let Err(GearError::InternalAssembly(msg)) = r else {
                panic!("z2 = {z2}: {r:?}")
            };
            assert!(msg.contains("z2 ≥ 34") && msg.contains("x2 >"), "{msg}");
            assert!(!msg.contains("z2 − z1 ≥"), "{msg}");
        } else {
            assert!(r.is_ok(), "z2 = {z2}: {r:?}");
        }
    }
}

/// ϑ1max and ϑ2max are the largest magnitudes over the real active line
/// (brute force over 20 001 points), including a pair where ϑ1's largest
/// magnitude is at the end of the line, not at the pinion's lower point.
#[test]
fn sliding_extremes_by_brute_force() {
    let mut end_wins = 0;
    for &(z1, z2, x1, x2) in &[
        (20u32, 20u32, 1.0, -0.1),
        (15, 20, 0.2, 0.85),
        (17, 40, 0.3, 0.1),
        (25, 60, 0.0, 0.0),
    ] {
        let p = Pair::new(&PairSpec::external(z1, z2, 0.002, x1, x2)).unwrap();
        let (g, u) = (p.aw * p.alpha_w.sin(), z2 as f64 / z1 as f64);
        let (mut m1, mut m2) = (0.0f64, 0.0f64);
        let n = 20_000;
        for i in 0..=n {
            let s = p.s_start + (p.s_end - p.s_start) * i as f64 / n as f64;
            let rho2 = g - s;
            m1 = m1.max((1.0 - rho2 / (u * s)).abs());
            m2 = m2.max((1.0 - u * s / rho2).abs());
        }
        assert!((p.theta1_max().unwrap() - m1).abs() < 1e-9 * m1.max(1.0));
        assert!((p.theta2_max().unwrap() - m2).abs() < 1e-9 * m2.max(1.0));
        let at_start = (1.0 - (g - p.s_start) / (u * p.s_start)).abs();
        end_wins += usize::from(m1 > at_start + 1e-6);
    }
    assert!(end_wins >= 1);
}

/// The default least tip thickness is GOST 16532-70's 0.3·m for through-hardened
/// teeth (seed 001 §IV quotes 0.3m and 0.4m).
#[test]
fn default_tip_thickness_is_gost() {
    assert_eq!(Limits::default().sa_min, 0.3);
    assert_eq!(tmm_gears::checks::SA_MIN_CASE_HARDENED, 0.4);
}
