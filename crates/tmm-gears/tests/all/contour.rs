//! Blocking contour: sampled points of each boundary satisfy that boundary's
//! defining equation, computed here from the pair's formulas; the chosen points
//! pass every check and meet their criterion.

use std::f64::consts::PI;

use tmm_gears::choose::{Criterion, choose, din_split};
use tmm_gears::contour::{Boundary, ContourOptions, blocking_contour};
use tmm_gears::{Limits, Pair, PairSpec};

fn inv(a: f64) -> f64 {
    a.tan() - a
}

/// The quantities of an external pair on the default rack, written out here
/// (GOST 16532-70 t.1–4) independently of the crate.
struct Q {
    x1: f64,
    x2: f64,
    xmin1: f64,
    xmin2: f64,
    rho_p1: f64,
    rho_p2: f64,
    rho_l1: f64,
    rho_l2: f64,
    sa1: f64,
    sa2: f64,
    eps: f64,
    th1: f64,
    th2: f64,
}

fn q(z1: f64, z2: f64, x1: f64, x2: f64) -> Q {
    let m = 1.0;
    let al = 20f64.to_radians();
    let inv_aw = inv(al) + 2.0 * (x1 + x2) * al.tan() / (z1 + z2);
    let (mut lo, mut hi) = (0.0f64, 1.5f64);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if inv(mid) < inv_aw { lo = mid } else { hi = mid }
    }
    let aw_a = 0.5 * (lo + hi);
    let a = (z1 + z2) / 2.0;
    let aw = a * al.cos() / aw_a.cos();
    let dy = x1 + x2 - (aw - a);
    let ra1 = z1 / 2.0 + 1.0 + x1 - dy;
    let ra2 = z2 / 2.0 + 1.0 + x2 - dy;
    let (rb1, rb2) = (z1 / 2.0 * al.cos(), z2 / 2.0 * al.cos());
    let (aa1, aa2) = ((rb1 / ra1).acos(), (rb2 / ra2).acos());
    let g = aw * aw_a.sin();
    let rho_p1 = g - rb2 * aa2.tan();
    let rho_p2 = g - rb1 * aa1.tan();
    let u = z2 / z1;
    let rho_l1 = z1 / 2.0 * al.sin() - (1.0 - x1) * m / al.sin();
    let rho_l2 = z2 / 2.0 * al.sin() - (1.0 - x2) * m / al.sin();
    // The real active line: the involutes exist only beyond N1, N2 and their form points.
    let (sa_, sb_) = (rho_p1.max(rho_l1).max(0.0), (rb1 * aa1.tan()).min(g - rho_l2.max(0.0)));
    Q {
        x1,
        x2,
        xmin1: 1.0 - z1 * al.sin().powi(2) / 2.0,
        xmin2: 1.0 - z2 * al.sin().powi(2) / 2.0,
        rho_p1,
        rho_p2,
        rho_l1,
        rho_l2,
        sa1: 2.0 * ra1 * ((PI / 2.0 + 2.0 * x1 * al.tan()) / z1 + inv(al) - inv(aa1)),
        sa2: 2.0 * ra2 * ((PI / 2.0 + 2.0 * x2 * al.tan()) / z2 + inv(al) - inv(aa2)),
        // the length of the real active line over the base pitch π m cos α
        eps: (sb_ - sa_) / (PI * m * al.cos()),
        th1: (g - sa_) / (u * sa_) - 1.0,
        th2: u * sb_ / (g - sb_) - 1.0,
    }
}

#[test]
fn boundary_points_satisfy_their_equations() {
    for &(z1, z2) in &[(15u32, 20u32), (16, 20), (12, 35)] {
        let base = PairSpec::external(z1, z2, 0.001, 0.0, 0.0);
        let c = blocking_contour(
            &base,
            &ContourOptions {
                n: 61,
                ..Default::default()
            },
        )
        .unwrap();
        let mut checked = 0;
        for line in &c.lines {
            for pl in &line.polylines {
                for &(x1, x2) in pl.iter().step_by(3) {
                    let v = q(z1 as f64, z2 as f64, x1, x2);
                    let resid = match line.boundary {
                        Boundary::Undercut(1) => v.x1 - v.xmin1,
                        Boundary::Undercut(_) => v.x2 - v.xmin2,
                        Boundary::Interference(1) => v.rho_p1 - v.rho_l1.max(0.0),
                        Boundary::Interference(_) => v.rho_p2 - v.rho_l2.max(0.0),
                        Boundary::TipThickness(1, k) => v.sa1 - k,
                        Boundary::TipThickness(_, k) => v.sa2 - k,
                        Boundary::ContactRatio(e) => v.eps - e,
                        Boundary::EqualSliding => v.th1 - v.th2,
                        Boundary::TipInterference => 0.0,
                    };
                    assert!(
                        resid.abs() < 1e-8,
                        "{z1}/{z2} {:?} at ({x1}, {x2}): residual {resid}",
                        line.boundary
                    );
                    checked += 1;
                }
            }
        }
        assert!(checked > 100, "{checked}");
        // every blocking boundary of the contour was found
        for b in [
            Boundary::Undercut(1),
            Boundary::Interference(1),
            Boundary::TipThickness(1, 0.0),
            Boundary::ContactRatio(1.2),
            Boundary::EqualSliding,
        ] {
            assert!(
                c.lines.iter().any(|l| l.boundary == b && !l.polylines.is_empty()),
                "{z1}/{z2}: {b:?} missing"
            );
        }
    }
}

#[test]
fn chosen_points_meet_their_criteria() {
    let lim = Limits::default();
    let base = PairSpec::external(16, 20, 0.030, 0.0, 0.0);
    // equal sliding: ϑ1max = ϑ2max, every check passing
    let e = choose(&base, Criterion::EqualSliding, None, &lim).unwrap().pair;
    let v = q(16.0, 20.0, e.w1.x, e.w2.x);
    assert!((v.th1 - v.th2).abs() < 1e-6);
    assert!(e.checks(&lim).all_pass());
    // max contact ratio: no feasible point of a coarse grid beats it
    let mx = choose(&base, Criterion::MaxContactRatio, None, &lim).unwrap().pair;
    assert!(mx.checks(&lim).all_pass());
    for i in 0..40 {
        for j in 0..40 {
            let (x1, x2) = (-0.5 + 0.05 * i as f64, -0.8 + 0.05 * j as f64);
            if let Ok(p) = Pair::new(&PairSpec { x1, x2, ..base })
                && p.checks(&lim).all_pass()
            {
                assert!(
                    p.eps_alpha <= mx.eps_alpha + 1e-9,
                    "({x1}, {x2}) gives {} > {}",
                    p.eps_alpha,
                    mx.eps_alpha
                );
            }
        }
    }
    // balanced, with seed 003's rounded centre distance aw = 560 mm
    let xs = tmm_gears::centre::shift_sum_for_aw(16, 20, 0.030, 0.560, &base.rack, base.kind).unwrap();
    let b = choose(&base, Criterion::Balanced, Some(xs), &lim).unwrap().pair;
    assert!((b.aw - 0.560).abs() < 1e-12);
    assert!((b.w1.x - din_split(16, 20, xs)).abs() < 1e-12);
    assert!(b.checks(&lim).all_pass());
}

#[test]
fn seed_003_pair_recomputed() {
    // Seed 003 §14: z = 16/20, m = 30 mm, aw rounded to 560 mm; the text reads
    // x1 = 0.53, x2 = 0.30 off the 14/22 atlas and measures εα = 1.09.
    let m = 30.0;
    let a = (16.0 + 20.0) * m / 2.0;
    let al = 20f64.to_radians();
    let cos_aw = a * al.cos() / 560.0;
    assert!((cos_aw - 0.9061).abs() < 1e-4, "seed: cos αw = 0.9061");
    let xs = (inv(cos_aw.acos()) - inv(al)) * 36.0 / (2.0 * al.tan());
    let got = tmm_gears::centre::shift_sum_for_aw(16, 20, 0.030, 0.560, &Default::default(), Default::default()).unwrap();
    assert!((got - xs).abs() < 1e-12);
    // The seed's split sums to 0.53 + 0.30 = 0.83, which does not give its own
    // 560 mm: the sum for 560 mm is 0.750 (inv 25.02° − inv 20° = 0.01517).
    assert!((xs - 0.7498).abs() < 1e-3, "{xs}");
    // With x1 = 0.53 on that sum the contact ratio is above 1.09 (the seed's
    // value measured off its drawing) and above its own 1.2 limit.
    let v = q(16.0, 20.0, 0.53, xs - 0.53);
    assert!(v.eps > 1.2 && v.eps < 1.35, "{}", v.eps);
}
