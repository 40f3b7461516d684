//! Internal pairs: the tip-interference condition against a brute-force
//! simulation of the mesh (the pinion's tip corners followed through a whole
//! pitch in the ring's frame, tested against the ring's teeth).

use std::f64::consts::PI;

use tmm_gears::{Kind, Pair, PairSpec};

fn inv(a: f64) -> f64 {
    a.tan() - a
}

/// Does a pinion tip corner enter a ring tooth anywhere in one pitch of rotation?
/// Placement: zero backlash, a ring tooth on +y of O2 filling the pinion's
/// space on +y of O1; O1 = O2 + (0, aw); both turn the same way, φ2 = φ1 z1/z2.
fn tips_collide(p: &Pair) -> bool {
    let (z1, z2) = (p.spec.z1 as f64, p.spec.z2 as f64);
    let al = p.spec.rack.alpha;
    let (ra1, ra2, rf2) = (p.w1.da / 2.0, p.w2.da / 2.0, p.w2.df / 2.0);
    let rb2 = p.w2.db / 2.0;
    let psi_a1 = p.w1.sa / (2.0 * ra1);
    // half-thickness angle of a ring tooth at radius r (it grows outward)
    let psi2 = |r: f64| p.w2.s / p.w2.d - inv(al) + inv((rb2 / r).min(1.0).acos());
    let (t1, t2) = (2.0 * PI / z1, 2.0 * PI / z2);
    let steps = 4000;
    for i in 0..steps {
        let phi1 = t1 * i as f64 / steps as f64;
        let phi2 = phi1 * z1 / z2;
        for k in 0..p.spec.z1 {
            for side in [-1.0, 1.0] {
                let th = PI / 2.0 + t1 / 2.0 + t1 * k as f64 + side * psi_a1 + phi1;
                let (x, y) = (ra1 * th.cos(), p.aw + ra1 * th.sin());
                // into the ring's frame
                let (s, c) = (-phi2).sin_cos();
                let (qx, qy) = (c * x - s * y, s * x + c * y);
                let r = (qx * qx + qy * qy).sqrt();
                if r <= ra2 || r >= rf2 {
                    continue;
                }
                let rel = (qy.atan2(qx) - PI / 2.0).rem_euclid(t2);
                let d = rel.min(t2 - rel);
                if d < psi2(r) - 1e-9 {
                    return true;
                }
            }
        }
    }
    false
}

#[test]
fn tip_interference_matches_simulation() {
    // Around the threshold of z2 − z1 for several pinions and shifts.
    let (mut agree, mut collisions) = (0, 0);
    for &(z1, x1, x2) in &[(30u32, 0.0, 0.0), (20, 0.0, 0.3), (40, 0.2, 0.2), (25, 0.3, 0.6)] {
        for dz in 4..16u32 {
            let spec = PairSpec {
                kind: Kind::Internal,
                ..PairSpec::external(z1, z1 + dz, 0.002, x1, x2)
            };
            let Ok(p) = Pair::compute(&spec) else { continue };
            let margin = p.tip_interference.unwrap();
            if margin.abs() < 0.02 {
                continue; // too close to call with a sampled simulation
            }
            let collide = tips_collide(&p);
            assert_eq!(
                collide,
                margin < 0.0,
                "z1 {z1} z2 {} x {x1}/{x2}: margin {margin}, simulated collision {collide}",
                z1 + dz
            );
            agree += 1;
            collisions += usize::from(collide);
        }
    }
    assert!(agree >= 10, "{agree}");
    // both verdicts were exercised
    assert!(collisions >= 3 && agree - collisions >= 3, "{collisions} of {agree}");
}

#[test]
fn internal_errors() {
    // a ring with fewer teeth than the pinion, and tips that interfere
    let spec = |z1, z2| PairSpec {
        kind: Kind::Internal,
        ..PairSpec::external(z1, z2, 0.002, 0.0, 0.0)
    };
    assert!(Pair::new(&spec(30, 20)).is_err());
    assert!(Pair::new(&spec(30, 36)).is_err());
    assert!(Pair::new(&spec(30, 60)).is_ok());
}
