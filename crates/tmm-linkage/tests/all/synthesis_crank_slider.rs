//! Crank-slider synthesis against independent references: random mechanisms
//! analysed forward by the linkage core (their K and stroke measured over the
//! cycle), then synthesised back from those numbers — the lengths must come
//! back; closed forms derived in the test; seed 000's formulas; infeasible
//! requests give typed errors with the nearest feasible value.

use crate::common;

use common::Rng;
use tmm_geom::Vec2;
use tmm_linkage::cycle::{Cycle, Working};
use tmm_linkage::synthesis::crank_slider::*;
use tmm_linkage::synthesis::{Drive, Limits, Rotation, SynthesisError};
use tmm_linkage::{AssemblyHint, HintKind, InputDef, LinkDef, Mechanism, MechanismDef, SliderDef};

/// A crank-slider built here (guide at y = −e, slider to the right, ccw).
fn forward(l1: f64, l2: f64, e: f64) -> (f64, f64) {
    let def = MechanismDef {
        fixed: vec![("O".into(), Vec2::ZERO)],
        links: vec![
            LinkDef::bar("1", "O", "A", l1),
            LinkDef::bar("2", "A", "B", l2),
            LinkDef::block("3", "B"),
        ],
        sliders: vec![SliderDef {
            slider: "3".into(),
            point: "B".into(),
            guide_link: "frame".into(),
            through: Vec2::new(0.0, -e),
            angle: 0.0,
            angle_on_slider: 0.0,
        }],
        input: Some(InputDef {
            link: "1".into(),
            pivot: "O".into(),
            pin: "A".into(),
            omega: 1.0,
            epsilon: 0.0,
        }),
        hints: vec![AssemblyHint {
            point: "B".into(),
            kind: HintKind::Near(Vec2::new(l1 + l2, 0.0)),
        }],
        ..Default::default()
    };
    let m = Mechanism::new(&def).unwrap();
    let c = Cycle::new(&m, Working::Slower).unwrap();
    (c.stroke, c.kv)
}

fn req(h: f64, k: f64, c: SliderCondition) -> CrankSliderRequest {
    CrankSliderRequest {
        stroke: h,
        k,
        condition: c,
        drive: Drive::default(),
        limits: Limits::default(),
    }
}

/// The largest pressure angle on the working (slower) and return strokes of
/// the crank-slider of [`forward`], by brute force over 20 000 crank angles:
/// A = l1(cos φ, sin φ), B on y = −e, sin ϑ = |y_A + e|/l2; the dead
/// positions where x_B is largest and smallest, with their angles exactly
/// (crank and coupler collinear: sin ϑ = e/(l2 ± l1)); the working stroke
/// the one the counter-clockwise crank takes longer over.
fn pressure_brute(l1: f64, l2: f64, e: f64) -> (f64, f64) {
    let n = 20_000;
    let at = |p: f64| {
        let (ya, xa) = (l1 * p.sin(), l1 * p.cos());
        (xa + (l2 * l2 - (ya + e).powi(2)).sqrt(), ((ya + e).abs() / l2).asin())
    };
    let phis: Vec<f64> = (0..n).map(|i| std::f64::consts::TAU * i as f64 / n as f64).collect();
    let xs: Vec<(f64, f64)> = phis.iter().map(|&p| at(p)).collect();
    let imax = (0..n).max_by(|&a, &b| xs[a].0.total_cmp(&xs[b].0)).unwrap();
    let imin = (0..n).min_by(|&a, &b| xs[a].0.total_cmp(&xs[b].0)).unwrap();
    // counter-clockwise from the innermost to the outermost: x_B increases
    let out_len = (imax + n - imin) % n;
    // the samples next to a dead position may lie a little past it: the ends
    // of each stroke are the exact dead-position values instead
    let ends = (e / (l2 + l1)).asin().max((e / (l2 - l1)).asin());
    let span = |from: usize, len: usize| (2..len.saturating_sub(1)).map(|j| xs[(from + j) % n].1).fold(ends, f64::max);
    let (outward, inward) = (span(imin, out_len), span(imax, n - out_len));
    if out_len >= n - out_len {
        (outward, inward)
    } else {
        (inward, outward)
    }
}

#[test]
fn random_mechanisms_come_back_from_their_stroke_and_k() {
    let mut rng = Rng(0x5eed_0001);
    for i in 0..1000 {
        let l1 = 0.02 + 0.2 * rng.uniform();
        let lam = 1.5 + 5.0 * rng.uniform();
        let e = (lam - 1.0) * l1 * 0.9 * rng.uniform() + 1e-3 * l1;
        let (h, k) = forward(l1, lam * l1, e);
        let cond = match i % 4 {
            0 => SliderCondition::Lambda(lam),
            1 => SliderCondition::Offset(e),
            2 => SliderCondition::MaxPressure(((l1 + e) / (lam * l1)).asin()),
            _ => SliderCondition::Optimum,
        };
        // every other request (and every optimum) adds the limits the
        // original mechanism meets, a little above its own angles
        let (pw, pr) = pressure_brute(l1, lam * l1, e);
        let limits = if i % 2 == 1 {
            Limits {
                pressure_working: Some(pw + 1e-4 + 0.05 * rng.uniform()),
                pressure_return: Some(pr + 1e-4 + 0.05 * rng.uniform()),
                transmission_min: None,
            }
        } else {
            Limits::default()
        };
        let s = synthesize(&CrankSliderRequest { limits, ..req(h, k, cond) }).unwrap_or_else(|err| panic!("{i}: {err}"));
        let (a, b, ee) = (s.length("OA").unwrap(), s.length("AB").unwrap(), s.length("e").unwrap());
        let sol_ok = (a - l1).abs() < 1e-8 * l1 && (b - lam * l1).abs() < 1e-8 * l1 && (ee - e).abs() < 1e-8 * l1;
        match i % 4 {
            0 | 1 => assert!(sol_ok, "{i}: {a} {b} {ee} vs {l1} {} {e}", lam * l1),
            2 => {
                // two offsets give this pressure angle: either is right if K, H, ϑ hold
                let (_, r) = s.check.pressure_angle_max;
                assert!((r - ((l1 + e) / (lam * l1)).asin()).abs() < 1e-9, "{i}");
            }
            _ => {}
        }
        // the result analysed afresh by the linkage core from its lengths
        // (a mechanism built here, not the synthesis's description)
        let (h2, k2) = forward(a, b, ee);
        assert!(
            (k2 - k).abs() < 1e-9 * k && (h2 - h).abs() < 1e-9 * h.max(1.0),
            "{i}: K {k2} vs {k}, H {h2} vs {h}"
        );
        // and its pressure angles by brute force meet the limits
        let (w2, r2) = pressure_brute(a, b, ee);
        if let (Some(lw), Some(lr)) = (limits.pressure_working, limits.pressure_return) {
            assert!(w2 <= lw + 1e-7 && r2 <= lr + 1e-7, "{i}: {w2} > {lw} or {r2} > {lr}");
        }
        assert!(
            (w2 - s.check.pressure_angle_max.0).abs() < 1e-7,
            "{i}: ϑw {w2} vs {:?}",
            s.check.pressure_angle_max
        );
        assert!((r2 - s.check.pressure_angle_max.1).abs() < 1e-7, "{i}");
    }
}

#[test]
fn pressure_angles_match_seed_000_formula() {
    // ϑmax = arcsin((l1 + e)/l2) at φ1 = 90° or 270° (seed 000 § 1.2.3)
    let s = synthesize(&req(0.3, 1.2, SliderCondition::Lambda(3.5))).unwrap();
    let (l1, l2, e) = (s.length("OA").unwrap(), s.length("AB").unwrap(), s.length("e").unwrap());
    let (w, r) = s.check.pressure_angle_max;
    assert!((w.max(r) - ((l1 + e) / l2).asin()).abs() < 1e-9);
    // working stroke: the larger of arcsin(|l1 − e|/l2) and the folded dead position's arcsin(e/(l2 − l1))
    let wexp = ((l1 - e).abs() / l2).asin().max((e / (l2 - l1)).asin());
    assert!((w - wexp).abs() < 1e-9, "{} {}", w.to_degrees(), wexp.to_degrees());
}

#[test]
fn axial_by_mean_speed_is_seed_000_formula() {
    // l1 = v_mean/(4·n1), l2 = λ2·l1, H = 2·l1, K = 1
    let s = by_mean_speed(1.8, 12.0, 1.0, SliderCondition::Lambda(4.2), Drive::default(), Limits::default()).unwrap();
    let l1 = 1.8 / 48.0;
    assert!((s.length("OA").unwrap() - l1).abs() < 1e-14);
    assert!((s.length("AB").unwrap() - 4.2 * l1).abs() < 1e-14);
    assert!(s.length("e").unwrap() == 0.0);
    assert!((s.check.k.unwrap() - 1.0).abs() < 1e-9);
}

#[test]
fn two_positions_reproduce_seed_000_system() {
    // independent: x_C = l1 cos φ1 + l2 cos φ2 with sin φ2 = (e − l1 sin φ1)/l2
    let (lam, le, p0, p1, hc) = (3.8, 0.4, 200f64.to_radians(), 330f64.to_radians(), -0.12);
    let s = by_two_positions(&TwoPositionsRequest {
        lambda: lam,
        lambda_e: le,
        phi_start: p0,
        phi_end: p1,
        travel: hc,
        drive: Drive::default(),
        limits: Limits::default(),
    })
    .unwrap();
    let (l1, l2, e) = (s.length("OA").unwrap(), s.length("AB").unwrap(), s.length("e").unwrap());
    let xc = |p: f64| l1 * p.cos() + (l2 * l2 - (e - l1 * p.sin()).powi(2)).sqrt();
    assert!((xc(p0) - xc(p1) - hc).abs() < 1e-12);
    assert!((l2 / l1 - lam).abs() < 1e-12 && (e / l1 - le).abs() < 1e-12);
}

#[test]
fn clockwise_mirrors_the_guide_and_keeps_k() {
    let mut r = req(0.25, 1.4, SliderCondition::Offset(0.05));
    r.drive.rotation = Rotation::Cw;
    let s = synthesize(&r).unwrap();
    assert!(s.def.sliders[0].through.y > 0.0);
    assert!((s.check.k.unwrap() - 1.4).abs() < 1e-9);
}

#[test]
fn infeasible_requests_name_the_condition_and_the_nearest_value() {
    // e beyond H·cot θ
    let th = std::f64::consts::PI * 0.4 / 2.4;
    let emax = 0.3 / th.tan();
    match synthesize(&req(0.3, 1.4, SliderCondition::Offset(2.0 * emax))) {
        Err(SynthesisError::Infeasible {
            field, nearest: Some(n), ..
        }) => {
            assert_eq!(field, "offset");
            assert!((n - emax).abs() < 1e-6 * emax);
        }
        other => panic!("{other:?}"),
    }
    // λ2 beyond cot²(θ/2)
    let top = (0.5 * th).tan().powi(-2);
    match synthesize(&req(0.3, 1.4, SliderCondition::Lambda(top + 1.0))) {
        Err(SynthesisError::Infeasible {
            field, nearest: Some(n), ..
        }) => {
            assert_eq!(field, "lambda");
            assert!((n - top).abs() < 1e-6 * top);
        }
        other => panic!("{other:?}"),
    }
    // a pressure angle below the smallest possible: the nearest is that smallest, and it is feasible
    match synthesize(&req(0.3, 1.6, SliderCondition::MaxPressure(5f64.to_radians()))) {
        Err(SynthesisError::Infeasible {
            field, nearest: Some(n), ..
        }) => {
            assert_eq!(field, "max_pressure");
            let ok = synthesize(&req(0.3, 1.6, SliderCondition::MaxPressure(n + 1e-9))).unwrap();
            assert!((ok.check.pressure_angle_max.1 - n).abs() < 1e-6);
            // and it is the optimum's value
            let opt = synthesize(&req(0.3, 1.6, SliderCondition::Optimum)).unwrap();
            assert!((opt.check.pressure_angle_max.1 - n).abs() < 1e-6);
        }
        other => panic!("{other:?}"),
    }
    // K ≥ 3
    assert!(matches!(
        synthesize(&req(0.3, 3.5, SliderCondition::Optimum)),
        Err(SynthesisError::Infeasible { .. })
    ));
    // limits that cannot hold
    let mut r = req(0.3, 1.6, SliderCondition::Lambda(3.0));
    r.limits.pressure_return = Some(10f64.to_radians());
    assert!(matches!(synthesize(&r), Err(SynthesisError::Infeasible { .. })));
}

#[test]
fn random_two_position_requests_recover_the_crank() {
    // forward: x_C(φ) = l1 cos φ + √(l2² − (e − l1 sin φ)²) (the branch x_C > x_A)
    let mut rng = Rng(0x5eed_0008);
    let mut n = 0;
    while n < 1000 {
        let l1 = 0.02 + 0.3 * rng.uniform();
        let lam = 1.6 + 4.0 * rng.uniform();
        let le = rng.sym(0.9 * (lam - 1.0));
        let (p0, p1) = (rng.sym(std::f64::consts::PI), rng.sym(std::f64::consts::PI));
        let (l2, e) = (lam * l1, le * l1);
        let x = |p: f64| l1 * p.cos() + (l2 * l2 - (e - l1 * p.sin()).powi(2)).sqrt();
        let travel = x(p0) - x(p1);
        if travel.abs() < 1e-3 * l1 {
            continue;
        }
        let s = by_two_positions(&TwoPositionsRequest {
            lambda: lam,
            lambda_e: le,
            phi_start: p0,
            phi_end: p1,
            travel,
            drive: Drive::default(),
            limits: Limits::default(),
        })
        .unwrap_or_else(|err| panic!("{n}: {err}"));
        assert!((s.length("OA").unwrap() - l1).abs() < 1e-9 * l1, "{n}");
        assert!((s.length("e").unwrap() - e).abs() < 1e-9 * l1, "{n}");
        n += 1;
    }
}
