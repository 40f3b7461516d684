//! Crank-rocker synthesis against closed forms derived in the test: random
//! Grashof crank-rockers give K and the swing from their dead positions
//! (crank and coupler collinear, law of cosines); synthesised back from those
//! numbers with each extra condition, the result must reproduce K and the
//! swing (checked by the linkage core) and, since the original four-bar is one
//! of the pivots meeting the condition, have a smallest transmission angle no
//! worse than the original's (cos μ = (b² + c² − (d ∓ a)²)/(2bc)).

use crate::common;

use std::f64::consts::PI;

use common::Rng;
use tmm_linkage::Mechanism;
use tmm_linkage::cycle::{Cycle, Working};
use tmm_linkage::synthesis::crank_rocker::*;
use tmm_linkage::synthesis::{Drive, Limits, Rotation, SynthesisError};

/// A random Grashof crank-rocker (a shortest): (a, b, c, d).
fn random_bar(rng: &mut Rng) -> (f64, f64, f64, f64) {
    loop {
        let (b, c, d) = (0.2 + rng.uniform(), 0.2 + rng.uniform(), 0.2 + rng.uniform());
        let mut s = [b, c, d];
        s.sort_by(f64::total_cmp);
        let top = s[0].min(s[0] + s[1] - s[2]);
        if top > 0.02 {
            let a = top * (0.1 + 0.85 * rng.uniform());
            return (a, b, c, d);
        }
    }
}

/// Closed forms: (K, swing, frame angle δ from O→D to the swing's bisector,
/// smallest transmission angle).
fn closed_form(a: f64, b: f64, c: f64, d: f64) -> (f64, f64, f64, f64) {
    let ang = |r: f64| ((r * r + d * d - c * c) / (2.0 * r * d)).acos();
    let (ae, af) = (ang(a + b), ang(b - a));
    let theta = (ae - af).abs();
    let ce = (ae.cos() * (a + b), ae.sin() * (a + b));
    let cf = (af.cos() * (b - a), af.sin() * (b - a));
    let be = (ce.1).atan2(ce.0 - d);
    let bf = (cf.1).atan2(cf.0 - d);
    let swing = (be - bf).abs();
    let bis = 0.5 * (be + bf);
    let mu = |x: f64| ((b * b + c * c - x * x) / (2.0 * b * c)).acos();
    let gmin = mu(d - a).min(PI - mu(d + a));
    ((PI + theta) / (PI - theta), swing, bis, gmin)
}

#[test]
fn random_crank_rockers_come_back() {
    let mut rng = Rng(0x5eed_0002);
    for i in 0..1000 {
        let (a, b, c, d) = random_bar(&mut rng);
        let (k, swing, delta, gmin) = closed_form(a, b, c, d);
        let condition = match i % 4 {
            0 => RockerCondition::Crank(a),
            1 => RockerCondition::Frame(d),
            2 => RockerCondition::FrameAngle(delta),
            _ => RockerCondition::Optimum,
        };
        let drive = Drive {
            rotation: if i % 2 == 0 { Rotation::Ccw } else { Rotation::Cw },
            omega: 1.0,
        };
        // every other pair of requests adds a transmission-angle limit the
        // original meets (a little below its own)
        let limits = if i % 4 >= 2 {
            Limits {
                transmission_min: Some(gmin - 1e-4 - 0.05 * rng.uniform()),
                ..Limits::default()
            }
        } else {
            Limits::default()
        };
        let s = synthesize(&CrankRockerRequest {
            k,
            rocker: c,
            swing,
            condition,
            drive,
            limits,
        })
        .unwrap_or_else(|e| panic!("{i}: a {a} b {b} c {c} d {d}: {e}"));
        assert!((s.check.k.unwrap() - k).abs() < 1e-9, "{i}");
        assert!((s.length("BC").unwrap() - c).abs() < 1e-12);
        match condition {
            RockerCondition::Crank(x) => assert!((s.length("OA").unwrap() - x).abs() < 1e-9 * x),
            RockerCondition::Frame(x) => assert!((s.length("OC").unwrap() - x).abs() < 1e-9 * x),
            _ => {}
        }
        // the result analysed afresh from its lengths by the closed forms:
        // K and the swing to 1e-9, the transmission angle against the limit
        let (a2, b2, d2) = (s.length("OA").unwrap(), s.length("AB").unwrap(), s.length("OC").unwrap());
        let (k2, swing2, _, g2) = closed_form(a2, b2, c, d2);
        assert!((k2 - k).abs() < 1e-9 * k, "{i}: K {k2} vs {k}");
        assert!((swing2 - swing).abs() < 1e-9, "{i}: swing {swing2} vs {swing}");
        assert!(
            (g2 - s.check.transmission_angle_min).abs() < 1e-9,
            "{i}: γmin {g2} vs {}",
            s.check.transmission_angle_min
        );
        if let Some(l) = limits.transmission_min {
            assert!(g2 >= l - 1e-9, "{i}: γmin {g2} below the limit {l}");
        }
        assert!(
            s.check.transmission_angle_min >= gmin - 1e-7,
            "{i}: γmin {} < original {}",
            s.check.transmission_angle_min.to_degrees(),
            gmin.to_degrees()
        );
        if i % 50 == 0 {
            // a fresh analysis of the description
            let m = Mechanism::new(&s.def).unwrap();
            let cy = Cycle::new(&m, Working::Slower).unwrap();
            assert!((cy.kv - k).abs() < 1e-9 && (cy.stroke - swing).abs() < 1e-9);
        }
    }
}

#[test]
fn seed_002_data_as_the_issue_states_it() {
    // Kω = 1.28, ψ = 60°, rocker 0.245 m, crank 0.1 m: the crank must be
    // below h = l3·sin(ψ/2) = 0.1225 m, so 0.1 m is feasible
    let s = synthesize(&CrankRockerRequest {
        k: 1.28,
        rocker: 0.245,
        swing: 60f64.to_radians(),
        condition: RockerCondition::Crank(0.1),
        drive: Drive::default(),
        limits: Limits::default(),
    })
    .unwrap();
    assert!(
        (s.check
            .stroke
            .map(|x| match x {
                tmm_linkage::synthesis::Stroke::Angular(v) => v,
                _ => 0.0,
            })
            .unwrap()
            - 60f64.to_radians())
        .abs()
            < 1e-9
    );
}

#[test]
fn crank_longer_than_the_half_chord_is_infeasible_with_the_nearest_value() {
    // every pivot on the locus has l1 < h = l3·sin(ψ/2) (docs/synthesis.md § 2)
    let r = CrankRockerRequest {
        k: 1.28,
        rocker: 0.245,
        swing: 60f64.to_radians(),
        condition: RockerCondition::Crank(0.2),
        drive: Drive::default(),
        limits: Limits::default(),
    };
    match synthesize(&r) {
        Err(SynthesisError::Infeasible {
            field, nearest: Some(n), ..
        }) => {
            assert_eq!(field, "crank");
            assert!(n < 0.1225 && n > 0.1, "{n}");
            // the nearest value works
            let ok = synthesize(&CrankRockerRequest {
                condition: RockerCondition::Crank(n * (1.0 - 1e-6)),
                ..r
            });
            assert!(ok.is_ok(), "{ok:?}");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn limits_steer_the_optimum_and_impossible_limits_fail() {
    let base = CrankRockerRequest {
        k: 1.2,
        rocker: 0.3,
        swing: 45f64.to_radians(),
        condition: RockerCondition::Optimum,
        drive: Drive::default(),
        limits: Limits::default(),
    };
    let best = synthesize(&base).unwrap();
    let g = best.check.transmission_angle_min;
    // a limit the optimum meets is met
    let ok = synthesize(&CrankRockerRequest {
        limits: Limits {
            transmission_min: Some(g - 0.01),
            ..Limits::default()
        },
        ..base
    })
    .unwrap();
    assert!(ok.check.transmission_angle_min >= g - 0.01);
    // a limit above the best possible fails with that best as the nearest value
    match synthesize(&CrankRockerRequest {
        limits: Limits {
            transmission_min: Some(g + 0.05),
            ..Limits::default()
        },
        ..base
    }) {
        Err(SynthesisError::Infeasible {
            field, nearest: Some(n), ..
        }) => {
            assert_eq!(field, "limits.transmission_min");
            assert!((n - g).abs() < 1e-6, "{n}");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn k_too_large_for_the_swing_names_the_largest_feasible_k() {
    let r = CrankRockerRequest {
        k: 10.0,
        rocker: 0.245,
        swing: 30f64.to_radians(),
        condition: RockerCondition::Optimum,
        drive: Drive::default(),
        limits: Limits::default(),
    };
    match synthesize(&r) {
        Err(SynthesisError::Infeasible {
            field, nearest: Some(k), ..
        }) => {
            assert_eq!(field, "k");
            assert!(k > 1.0 && k < 10.0, "{k}");
            // just below it a crank-rocker exists, and it has the requested K and swing
            let s = synthesize(&CrankRockerRequest {
                k: 1.0 + (k - 1.0) * 0.99,
                ..r
            })
            .unwrap();
            assert!((s.check.k.unwrap() - (1.0 + (k - 1.0) * 0.99)).abs() < 1e-9);
            // just above it none does
            assert!(
                synthesize(&CrankRockerRequest {
                    k: 1.0 + (k - 1.0) * 1.01,
                    ..r
                })
                .is_err()
            );
        }
        other => panic!("{other:?}"),
    }
}
