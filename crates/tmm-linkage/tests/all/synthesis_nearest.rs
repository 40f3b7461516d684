//! The nearest feasible value of an infeasible request: for every kind and
//! every condition that can fail, the value the error names is solved again
//! with the rest of the request unchanged and must pass the whole check by
//! the linkage core, differ from the value asked for, and lie on the
//! feasible side of the bound derived here (closed forms of
//! docs/synthesis.md §§ 2–5).

use crate::common;

use std::f64::consts::PI;

use common::Rng;
use tmm_linkage::synthesis::crank_rocker::{CrankRockerRequest, RockerCondition};
use tmm_linkage::synthesis::crank_slider::{CrankSliderRequest, SliderCondition};
use tmm_linkage::synthesis::knee_press::{KneePivot, KneeRequest};
use tmm_linkage::synthesis::pivot::PivotCondition;
use tmm_linkage::synthesis::six_bar::InversionRequest;
use tmm_linkage::synthesis::slotted::{Coupler, Lever, SlottedRequest};
use tmm_linkage::synthesis::{Drive, Limits, Request, SynthesisError, synthesize};

/// The request fails naming `field`; its nearest value works, differs from
/// the request and has at most `digits` significant digits in the user's
/// unit (degrees for an angle). Returns it.
fn nearest_works(r: &Request, field: &str, digits: usize) -> f64 {
    let (f, n) = match synthesize(r) {
        Err(SynthesisError::Infeasible { field, nearest, .. }) => (field, nearest),
        other => panic!("{r:?}: expected infeasible, got {other:?}"),
    };
    assert_eq!(f, field, "{r:?}");
    let n = n.unwrap_or_else(|| panic!("{r:?}: no nearest value"));
    let name = r.param_name(&f).unwrap();
    assert_ne!(Some(n), r.value(name), "{r:?}: the nearest value is the request");
    let s = synthesize(&r.with_param(name, n).unwrap());
    assert!(s.is_ok(), "{r:?}: nearest {n} fails: {s:?}");
    let user = if [
        "swing",
        "frame_angle",
        "max_pressure",
        "pressure_working",
        "pressure_return",
        "transmission_min",
    ]
    .contains(&name)
    {
        n.to_degrees()
    } else {
        n
    };
    let text = format!("{:.*e}", digits.saturating_sub(1), user);
    let back: f64 = text.parse().unwrap();
    assert!(
        (back - user).abs() <= 1e-12 * user.abs(),
        "{r:?}: {user} has more than {digits} significant digits"
    );
    n
}

fn slider(h: f64, k: f64, c: SliderCondition) -> Request {
    Request::CrankSlider(CrankSliderRequest {
        stroke: h,
        k,
        condition: c,
        drive: Drive::default(),
        limits: Limits::default(),
    })
}

fn rocker(k: f64, l3: f64, swing_deg: f64, c: RockerCondition) -> Request {
    Request::CrankRocker(CrankRockerRequest {
        k,
        rocker: l3,
        swing: swing_deg.to_radians(),
        condition: c,
        drive: Drive::default(),
        limits: Limits::default(),
    })
}

fn k_of(theta: f64) -> f64 {
    (PI + theta) / (PI - theta)
}

#[test]
fn crank_slider_k_beyond_three_gives_the_largest_k_of_its_condition() {
    // λ2 < cot²(θ/2): θ < 2·arctan(1/√λ2)
    for k in [3.0, 3.5, 100.0] {
        let n = nearest_works(&slider(0.3, k, SliderCondition::Lambda(3.5)), "k", 4);
        let kmax = k_of(2.0 * (1.0 / 3.5f64.sqrt()).atan());
        assert!(n < kmax && n > kmax - 2e-3, "{n} vs {kmax}");
        // e < H·cot θ: θ < arctan(H/e)
        let n = nearest_works(&slider(0.3, k, SliderCondition::Offset(0.05)), "k", 4);
        let kmax = k_of((0.3f64 / 0.05).atan());
        assert!(n < kmax && n > kmax - 2e-3, "{n} vs {kmax}");
        // any offset: θ < 90°, K < 3
        let n = nearest_works(&slider(0.3, k, SliderCondition::Optimum), "k", 4);
        assert!(n < 3.0 && n > 2.9, "{n}");
    }
}

#[test]
fn crank_slider_bounds_of_lambda_offset_and_pressure() {
    let th = PI * 0.4 / 2.4;
    let top = (0.5 * th).tan().powi(-2);
    let n = nearest_works(&slider(0.3, 1.4, SliderCondition::Lambda(top + 1.0)), "lambda", 4);
    assert!(n < top && n > top * 0.999, "{n} vs {top}");
    let n = nearest_works(&slider(0.3, 1.4, SliderCondition::Lambda(0.5)), "lambda", 4);
    assert!(n > 1.0 && n < 1.01, "{n}");
    let emax = 0.3 / th.tan();
    let n = nearest_works(&slider(0.3, 1.4, SliderCondition::Offset(2.0 * emax)), "offset", 4);
    // right at the bound the return pressure angle reaches 90°: the core
    // refuses the last few tenths of a per cent, the rounding steps back
    assert!(n < emax && n > 0.995 * emax, "{n} vs {emax}");
    // ϑmax below the smallest possible (42.80° for H = 0.3 m, K = 1.2)
    let n = nearest_works(
        &slider(0.3, 1.2, SliderCondition::MaxPressure(40f64.to_radians())),
        "max_pressure",
        4,
    );
    assert!((n.to_degrees() - 42.8).abs() < 0.01, "{}", n.to_degrees());
    // a limit a fixed design cannot meet: the nearest limit is what it reaches
    let mut r = CrankSliderRequest {
        stroke: 0.3,
        k: 1.6,
        condition: SliderCondition::Lambda(3.0),
        drive: Drive::default(),
        limits: Limits::default(),
    };
    r.limits.pressure_return = Some(10f64.to_radians());
    let n = nearest_works(&Request::CrankSlider(r), "limits.pressure_return", 4);
    let s = synthesize(&slider(0.3, 1.6, SliderCondition::Lambda(3.0))).unwrap();
    let reached = s.check.pressure_angle_max.1;
    assert!(n >= reached && n < reached + 1e-3, "{n} vs {reached}");
}

#[test]
fn crank_rocker_k_too_large_and_conditions_out_of_reach() {
    // K = 3 and beyond with a small swing: the nearest K is below and works
    for (k, swing) in [(3.0, 30.0), (3.0, 60.0), (10.0, 30.0), (3.5, 10.0)] {
        let r = rocker(k, 0.245, swing, RockerCondition::Optimum);
        if let Err(SynthesisError::Infeasible { .. }) = synthesize(&r) {
            let n = nearest_works(&r, "k", 4);
            assert!(n < k, "{n}");
        }
    }
    // the crank is shorter than half the chord, h = l3·sin(ψ/2) = 0.1225 m
    let n = nearest_works(&rocker(1.28, 0.245, 60.0, RockerCondition::Crank(0.2)), "crank", 4);
    assert!(n < 0.1225 && n > 0.1, "{n}");
    // a frame too long or too short
    nearest_works(&rocker(1.28, 0.245, 60.0, RockerCondition::Frame(5.0)), "frame", 4);
    nearest_works(&rocker(1.28, 0.245, 60.0, RockerCondition::Frame(0.01)), "frame", 4);
    // a transmission angle above the best possible
    let best = synthesize(&rocker(1.2, 0.3, 45.0, RockerCondition::Optimum)).unwrap();
    let g = best.check.transmission_angle_min;
    let Request::CrankRocker(mut q) = rocker(1.2, 0.3, 45.0, RockerCondition::Optimum) else {
        unreachable!()
    };
    q.limits.transmission_min = Some(g + 0.05);
    let n = nearest_works(&Request::CrankRocker(q), "limits.transmission_min", 4);
    assert!(n <= g && n > g - 1e-3, "{n} vs {g}");
}

#[test]
fn slotted_knee_and_six_bar_bounds() {
    let r = Request::Slotted(SlottedRequest {
        stroke: 0.4,
        k: 1.5,
        pivots: 0.05,
        coupler: Coupler::Length(0.15),
        lever: Lever::Rotating,
        drive: Drive::default(),
        limits: Limits::default(),
    });
    // the rotating lever's coupler is longer than l_EC = H/2
    let n = nearest_works(&r, "coupler", 4);
    assert!(n > 0.2 && n < 0.2002, "{n}");
    let knee = KneeRequest {
        stroke: 0.5,
        k: 1.12,
        rocker: 0.22,
        link: 0.22,
        delta: 5f64.to_radians(),
        pivot: KneePivot::Optimum,
        drive: Drive::default(),
        limits: Limits::default(),
    };
    // l = l_BF: the stroke from δ up to 90° is 2l·cos δ
    let n = nearest_works(&Request::Knee(knee), "stroke", 4);
    let hmax = 0.44 * 5f64.to_radians().cos();
    assert!(n < hmax && n > hmax * 0.999, "{n} vs {hmax}");
    nearest_works(
        &Request::Knee(KneeRequest {
            stroke: 0.09,
            pivot: KneePivot::Horizontal(5.0),
            ..knee
        }),
        "pivot.horizontal",
        4,
    );
    let inv = Request::SixBarInversion(InversionRequest {
        k: 1.15,
        travel: 0.36,
        guide: -0.32,
        start: 0.18,
        coupler: 0.1,
        swing: 70f64.to_radians(),
        lever: 0.36,
        pivot: PivotCondition::Optimum,
        drive: Drive::default(),
        limits: Limits::default(),
    });
    nearest_works(&inv, "coupler", 4);
}

/// Random crank-slider and crank-rocker requests, many of them infeasible:
/// every nearest value given works and differs from the request.
#[test]
fn random_infeasible_requests_name_a_nearest_value_that_works() {
    let mut rng = Rng(0x5eed_0010);
    let mut checked = 0;
    for i in 0..300 {
        let k = 1.0 + 3.0 * rng.uniform();
        let r = if i % 2 == 0 {
            let c = match i % 8 {
                0 => SliderCondition::Lambda(0.5 + 8.0 * rng.uniform()),
                2 => SliderCondition::Offset(0.5 * rng.uniform()),
                4 => SliderCondition::MaxPressure((5.0 + 80.0 * rng.uniform()).to_radians()),
                _ => SliderCondition::Optimum,
            };
            slider(0.1 + rng.uniform(), k, c)
        } else {
            let c = match i % 8 {
                1 => RockerCondition::Crank(0.3 * rng.uniform()),
                3 => RockerCondition::Frame(1.5 * rng.uniform()),
                5 => RockerCondition::FrameAngle(rng.sym(PI)),
                _ => RockerCondition::Optimum,
            };
            rocker(k, 0.1 + rng.uniform(), 5.0 + 170.0 * rng.uniform(), c)
        };
        if let Err(SynthesisError::Infeasible {
            field, nearest: Some(n), ..
        }) = synthesize(&r)
        {
            let name = r.param_name(&field).unwrap_or_else(|| panic!("{r:?}: {field}"));
            assert_ne!(Some(n), r.value(name), "{r:?}");
            let s = synthesize(&r.with_param(name, n).unwrap());
            assert!(s.is_ok(), "{i}: {r:?}: nearest {field} = {n} fails: {s:?}");
            checked += 1;
        }
    }
    assert!(checked > 30, "{checked}");
}

/// A frame direction no valid pivot has: the nearest direction works, and
/// the directions between it and the one asked for all fail (so it is the
/// nearest, up to the rounding).
#[test]
fn crank_rocker_frame_angle_nearest_is_the_nearest_direction() {
    for want in [0.0f64, 10.0, 90.0, -90.0, 170.0] {
        let r = rocker(3.0, 0.245, 60.0, RockerCondition::FrameAngle(want.to_radians()));
        if synthesize(&r).is_ok() {
            continue;
        }
        let n = nearest_works(&r, "frame_angle", 4).to_degrees();
        // δ and δ + 180° are one frame line
        let d = (n - want + 90.0).rem_euclid(180.0) - 90.0;
        assert!(d.abs() <= 90.0, "{want}: {n}");
        for j in 1..20 {
            let between = want + d * j as f64 / 20.0;
            if (between - n).abs() < 0.02 {
                continue;
            }
            assert!(
                synthesize(&r.with_param("frame_angle", between.to_radians()).unwrap()).is_err(),
                "{want}: {between}° works but the nearest given is {n}°"
            );
        }
    }
}
