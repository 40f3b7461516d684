//! Internal pairs: the trimming (radial assembly) condition against a brute
//! force that moves the pinion's real tooth outlines along the line of centres
//! into mesh, at every phase of the mesh, and looks for overlapping teeth.

use std::f64::consts::PI;

use tmm_gears::{Kind, Limits, Pair, PairSpec};

fn inv(a: f64) -> f64 {
    a.tan() - a
}

/// Angular distance of `th` from the nearest of the centres `c0 + k·tau`.
fn off(th: f64, c0: f64, tau: f64) -> f64 {
    let r = (th - c0).rem_euclid(tau);
    r.min(tau - r)
}

/// Does any pinion tooth overlap a ring tooth while the pinion moves from
/// O1 = (0, aw − travel) to O1 = (0, aw) without turning, at some phase of the
/// mesh? O2 at the origin; at phase φ the pinion is turned by φ and the ring
/// by φ·z1/z2 (both CCW) from the placement where a pinion tooth and a ring
/// space are centred on +y. Both outlines are the involutes in closed form.
fn trims(p: &Pair, phases: usize, steps: usize) -> bool {
    let (z1, z2) = (p.spec.z1 as f64, p.spec.z2 as f64);
    let al = p.spec.rack.alpha;
    let (ra1, rb1, rf1) = (p.w1.da / 2.0, p.w1.db / 2.0, p.w1.df / 2.0);
    let (ra2, rb2, rf2) = (p.w2.da / 2.0, p.w2.db / 2.0, p.w2.df / 2.0);
    // half-thickness angles: pinion tooth (shrinks outward), ring tooth (grows outward)
    let psi1 = |r: f64| p.w1.s / p.w1.d + inv(al) - inv((rb1 / r.max(rb1)).min(1.0).acos());
    let psi2 = |r: f64| p.w2.s / p.w2.d - inv(al) + inv((rb2 / r).min(1.0).acos());
    let (t1, t2) = (2.0 * PI / z1, 2.0 * PI / z2);
    // outlines relative to a tooth centred on angle 0: (r, angle offset)
    let n = 24;
    let mut pin = Vec::new();
    let r_lo1 = rb1.max(rf1);
    for i in 0..=n {
        let r = r_lo1 + (ra1 - r_lo1) * i as f64 / n as f64;
        pin.push((r, psi1(r)));
        pin.push((r, -psi1(r)));
    }
    for i in 0..=n {
        pin.push((ra1, psi1(ra1) * (2.0 * i as f64 / n as f64 - 1.0)));
    }
    let mut ring = Vec::new();
    for i in 0..=n {
        let r = ra2 + (rf2 - ra2) * i as f64 / n as f64;
        ring.push((r, psi2(r)));
        ring.push((r, -psi2(r)));
    }
    for i in 0..=n {
        ring.push((ra2, psi2(ra2) * (2.0 * i as f64 / n as f64 - 1.0)));
    }
    let tol = 1e-9 * p.spec.m;
    let travel = 3.0 * p.spec.m;
    for ip in 0..phases {
        let phi1 = t1 * ip as f64 / phases as f64;
        let phi2 = phi1 * z1 / z2;
        let c1 = PI / 2.0 + phi1; // a pinion tooth centre
        let c2 = PI / 2.0 + phi2 + t2 / 2.0; // a ring tooth centre
        for is in 0..steps {
            // stop short of the final position, where the flanks touch along the line of action
            let yo = p.aw - travel * (1.0 - is as f64 / steps as f64);
            // pinion outline points inside ring teeth
            for k in 0..p.spec.z1 {
                let ck = c1 + t1 * k as f64;
                // only the teeth facing the mesh can reach the ring's tips
                if (ck - PI / 2.0).sin().abs() > 0.9 || (ck - PI / 2.0).cos() < 0.0 {
                    continue;
                }
                for &(r, a) in &pin {
                    let (x, y) = (r * (ck + a).cos(), yo + r * (ck + a).sin());
                    let rr = x.hypot(y);
                    if rr <= ra2 + tol {
                        continue;
                    }
                    if rr >= rf2 || off(y.atan2(x), c2, t2) * rr < psi2(rr) * rr - tol {
                        return true;
                    }
                }
            }
            // ring outline points inside pinion teeth
            for k in 0..p.spec.z2 {
                let ck = c2 + t2 * k as f64;
                if (ck - PI / 2.0).sin().abs() > 0.9 || (ck - PI / 2.0).cos() < 0.0 {
                    continue;
                }
                for &(r, a) in &ring {
                    let (x, y) = (r * (ck + a).cos(), r * (ck + a).sin() - yo);
                    let rr = x.hypot(y);
                    if rr >= ra1 - tol {
                        continue;
                    }
                    if rr <= rf1 || off(y.atan2(x), c1, t1) * rr < psi1(rr) * rr - tol {
                        return true;
                    }
                }
            }
        }
    }
    false
}

fn internal(z1: u32, z2: u32, m: f64, x1: f64, x2: f64) -> PairSpec {
    PairSpec {
        kind: Kind::Internal,
        ..PairSpec::external(z1, z2, m, x1, x2)
    }
}

/// The pair of the hardening list: 30/36, m = 1 mm, x = 0/0.5 passes every
/// other check but the pinion cannot be moved into mesh radially.
#[test]
fn thirty_thirty_six_trims() {
    let p = Pair::new(&internal(30, 36, 0.001, 0.0, 0.5)).unwrap();
    assert!(trims(&p, 60, 120), "the brute force finds the teeth overlapping");
    let t = p.trimming.unwrap();
    assert!(t < 0.0, "margin {t}");
    let c = p.checks(&Limits::default());
    let failed: Vec<_> = c.as_slice().iter().filter(|c| !c.pass).map(|c| c.kind.key()).collect();
    assert_eq!(failed, vec!["trimming".to_string()]);
}

#[test]
fn trimming_matches_brute_force() {
    let (mut agree, mut trimmed) = (0, 0);
    for &(z1, x1, x2) in &[(30u32, 0.0, 0.5), (20, 0.0, 0.0), (24, 0.2, 0.6), (40, 0.0, 0.3)] {
        for dz in [5u32, 6, 8, 10, 14, 30] {
            let Ok(p) = Pair::compute(&internal(z1, z1 + dz, 0.002, x1, x2)) else {
                continue;
            };
            let margin = p.trimming.unwrap();
            if margin.abs() < 0.05 {
                continue; // too close to call with a sampled brute force
            }
            let t = trims(&p, 30, 40);
            assert_eq!(t, margin < 0.0, "z {z1}/{} x {x1}/{x2}: margin {margin}, brute force {t}", z1 + dz);
            agree += 1;
            trimmed += usize::from(t);
        }
    }
    eprintln!("{agree} pairs, {trimmed} trimmed");
    assert!(agree >= 12, "{agree}");
    assert!(trimmed >= 3 && agree - trimmed >= 3, "{trimmed} of {agree}");
}
