//! Generated profiles against the involute's closed form, and the fillet against
//! the mating tooth's path (simulated meshing of the pair at aw).

use std::f64::consts::PI;

use tmm_gears::generate::{Part, generate};
use tmm_gears::{BasicRack, Pair, PairSpec};

fn inv(a: f64) -> f64 {
    a.tan() - a
}

/// ψ(r) = s/d + inv α − inv α_r (half-thickness angle of an involute tooth,
/// GOST 16532-70 t.4 for the tip, any radius alike).
fn psi_involute(z: u32, m: f64, x: f64, r: f64) -> f64 {
    let al = 20f64.to_radians();
    let d = z as f64 * m;
    let s = (PI / 2.0 + 2.0 * x * al.tan()) * m;
    let rb = d / 2.0 * al.cos();
    s / d + inv(al) - inv((rb / r).acos())
}

#[test]
fn involute_points_lie_on_the_involute() {
    for &(z, x) in &[(15u32, 0.2), (20, 0.85), (30, -0.3), (12, 0.5), (60, 0.0)] {
        let m = 0.005;
        let ra = (z as f64 / 2.0 + 1.0 + x) * m;
        let t = generate(z, m, x, &BasicRack::default(), ra, 80).unwrap();
        // form circle: the boundary point of the generated involute, ρl = r sin α − (hl* − ha* − x) m / sin α
        let al = 20f64.to_radians();
        let r = z as f64 * m / 2.0;
        let rb = r * al.cos();
        let rho_l = r * al.sin() - (1.0 - x) * m / al.sin();
        let r_form = (rb * rb + rho_l.max(0.0).powi(2)).sqrt();
        let mut n = 0;
        for q in t.half.iter().filter(|q| q.part == Part::Involute || q.part == Part::Tip) {
            assert!(q.r >= r_form - 1e-12 * m, "z {z}: involute point below the form circle");
            let dist = q.r * (q.psi - psi_involute(z, m, x, q.r)).abs();
            assert!(dist < 1e-9 * m, "z {z} x {x}: {dist}");
            n += 1;
        }
        assert!(n > 20);
        // the tip corner is on the tip circle
        assert!((t.half.last().unwrap().r - ra).abs() < 1e-12);
    }
}

/// An undercut tooth (z = 10, x = 0 < xmin = 0.415): the involute starts above
/// the form circle of the rack formula, and the profile is thinner than the
/// involute just above the base circle (the undercut), as generation cuts it.
#[test]
fn undercut_appears() {
    let (z, m, x) = (10u32, 0.01, 0.0);
    let ra = (z as f64 / 2.0 + 1.0) * m;
    let t = generate(z, m, x, &BasicRack::default(), ra, 120).unwrap();
    let al = 20f64.to_radians();
    let rb = z as f64 * m / 2.0 * al.cos();
    // some fillet point just above the base circle is thinner than the involute would be there
    let thinner = t
        .half
        .iter()
        .filter(|q| q.part == Part::Fillet && q.r > rb * 1.0005 && q.r < rb * 1.02)
        .any(|q| q.psi < psi_involute(z, m, x, q.r) - 1e-6);
    assert!(thinner, "no undercut found");
    // without undercut (x = xmin + 0.05) no fillet point is thinner than the involute
    let x2 = 1.0 - z as f64 * al.sin().powi(2) / 2.0 + 0.05;
    let t2 = generate(z, m, x2, &BasicRack::default(), ra + x2 * m, 120).unwrap();
    assert!(
        !t2.half
            .iter()
            .filter(|q| q.part == Part::Fillet && q.r > rb)
            .any(|q| q.psi < psi_involute(z, m, x2, q.r) - 1e-9)
    );
}

/// Mesh the pair at aw and follow wheel 2's tip corners in wheel 1's frame: they
/// never enter wheel 1's tooth (its fillet included), and likewise the other way.
#[test]
fn fillet_clear_of_mating_tip_path() {
    for &(z1, z2, x1, x2) in &[(15u32, 20u32, 0.2, 0.85), (17, 40, 0.0, 0.0), (12, 30, 0.4, 0.1)] {
        let m = 0.005;
        let p = Pair::new(&PairSpec::external(z1, z2, m, x1, x2)).unwrap();
        let rack = BasicRack::default();
        let t1 = generate(z1, m, x1, &rack, p.w1.da / 2.0, 100).unwrap();
        let t2 = generate(z2, m, x2, &rack, p.w2.da / 2.0, 100).unwrap();
        clear(&t1, &t2, z1, z2, p.aw);
        clear(&t2, &t1, z2, z1, p.aw);
    }
}

/// Half-thickness angle of tooth `t` at radius r, by interpolation on its half
/// profile (largest where the profile doubles back).
fn psi_at(t: &tmm_gears::generate::ToothProfile, r: f64) -> Option<f64> {
    let mut best: Option<f64> = None;
    for w in t.half.windows(2) {
        let (a, b) = (w[0], w[1]);
        if (a.r - r) * (b.r - r) <= 0.0 && a.r != b.r {
            let v = a.psi + (b.psi - a.psi) * (r - a.r) / (b.r - a.r);
            best = Some(best.map_or(v, |o: f64| o.max(v)));
        }
    }
    best
}

fn clear(ta: &tmm_gears::generate::ToothProfile, tb: &tmm_gears::generate::ToothProfile, za: u32, zb: u32, aw: f64) {
    // Wheel a at the origin with a tooth SPACE centred on +y at φa = 0; wheel b
    // at (0, aw) with a TOOTH centred on −y (zero backlash, symmetric).
    let tip_b = tb.half.last().unwrap();
    let tau_a = 2.0 * PI / za as f64;
    for k in -400..=400 {
        let phi_a = k as f64 * 1e-3 * 2.0 * PI / za as f64 * 3.0;
        let phi_b = -phi_a * za as f64 / zb as f64;
        for side in [-1.0, 1.0] {
            // tip corner of b in b's frame (tooth centred on −y), turned by phi_b about O2
            let ang = -PI / 2.0 + side * tip_b.psi + phi_b;
            let (px, py) = (tip_b.r * ang.cos(), aw + tip_b.r * ang.sin());
            // into a's frame (turn by −φa)
            let (s, c) = (-phi_a).sin_cos();
            let (qx, qy) = (c * px - s * py, s * px + c * py);
            let rr = (qx * qx + qy * qy).sqrt();
            if rr > ta.ra || rr < ta.rf {
                continue;
            }
            // angle from the nearest tooth centre of a (teeth centred at π/2 ± τ/2 + kτ)
            let th = qx.atan2(qy); // from +y toward +x
            let rel = (th - tau_a / 2.0).rem_euclid(tau_a);
            let from_centre = rel.min(tau_a - rel);
            let psi = psi_at(ta, rr).unwrap();
            assert!(
                from_centre >= psi - 1e-6,
                "tip of the mate enters the tooth: r {rr}, {from_centre} < {psi}"
            );
        }
    }
}
