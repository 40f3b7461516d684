//! Function generation, the slotted lever, the knee press and the six-bars
//! against references derived in the test: forward closed forms of random
//! mechanisms synthesised back, the dead positions found by the linkage core
//! compared with the construction's extreme positions, and every failure a
//! typed error.

use crate::common;

use std::f64::consts::PI;

use common::Rng;
use tmm_geom::Vec2;
use tmm_linkage::synthesis::function_gen::{self, FunctionRequest};
use tmm_linkage::synthesis::knee_press::{self, KneePivot, KneeRequest};
use tmm_linkage::synthesis::pivot::PivotCondition;
use tmm_linkage::synthesis::six_bar::{self, InversionRequest, PressureRequest};
use tmm_linkage::synthesis::slotted::{self, Coupler, Lever, SlottedRequest};
use tmm_linkage::synthesis::{Drive, Limits, Stroke, Synthesis, SynthesisError};

fn at(s: &Synthesis, i: usize, name: &str) -> Vec2 {
    s.check.dead_positions[i].iter().find(|(n, _)| n == name).unwrap().1
}

fn linear(s: &Synthesis) -> f64 {
    match s.check.stroke.unwrap() {
        Stroke::Linear(h) => h,
        Stroke::Angular(_) => panic!("angular"),
    }
}

/// The rocker angle of a four-bar O(0,0)–A–B–C(d,0) on one circuit.
fn psi(a: f64, b: f64, c: f64, d: f64, phi: f64) -> f64 {
    let v = Vec2::new(a * phi.cos() - d, a * phi.sin());
    let r = v.hypot();
    v.atan2() + ((c * c + r * r - b * b) / (2.0 * c * r)).acos()
}

#[test]
fn function_generation_recovers_random_four_bars() {
    let mut rng = Rng(0x5eed_0003);
    let mut n = 0;
    while n < 1000 {
        let (a, b, c, d) = (
            0.05 + 0.2 * rng.uniform(),
            0.3 + rng.uniform(),
            0.3 + rng.uniform(),
            0.3 + rng.uniform(),
        );
        let mut s = [a, b, c, d];
        s.sort_by(f64::total_cmp);
        if s[0] != a || s[0] + s[3] >= s[1] + s[2] {
            continue;
        }
        let count = if n % 2 == 0 { 3 } else { 6 };
        let start = rng.sym(PI);
        let step = (25.0 + 20.0 * rng.uniform()).to_radians();
        let positions: Vec<(f64, f64)> = (0..count)
            .map(|k| start + step * k as f64)
            .map(|p| (p, psi(a, b, c, d, p)))
            .collect();
        let syn = function_gen::synthesize(&FunctionRequest {
            positions,
            frame: d,
            omega: 1.0,
            limits: Limits::default(),
        })
        .unwrap_or_else(|e| panic!("{n}: {e}"));
        for (name, want) in [("OA", a), ("AB", b), ("BC", c)] {
            let got = syn.length(name).unwrap();
            assert!((got - want).abs() < 1e-6 * want, "{n} {name}: {got} vs {want}");
        }
        assert!(syn.free_parameter.as_ref().unwrap().value < 1e-8);
        assert!(syn.check.crank_turns_fully);
        n += 1;
    }
}

#[test]
fn function_generation_rejects_too_few_and_repeated_positions() {
    let r = FunctionRequest {
        positions: vec![(0.1, 0.2), (0.3, 0.4)],
        frame: 1.0,
        omega: 1.0,
        limits: Limits::default(),
    };
    assert!(matches!(function_gen::synthesize(&r), Err(SynthesisError::Input { .. })));
    let r = FunctionRequest {
        positions: vec![(0.1, 0.2), (0.1, 0.2), (0.1, 0.2)],
        frame: 1.0,
        omega: 1.0,
        limits: Limits::default(),
    };
    assert!(matches!(function_gen::synthesize(&r), Err(SynthesisError::Infeasible { .. })));
}

#[test]
fn slotted_levers_give_k_and_stroke_by_the_closed_forms() {
    let mut rng = Rng(0x5eed_0004);
    for i in 0..1000 {
        let h = 0.1 + rng.uniform();
        let k = 1.05 + 1.4 * rng.uniform();
        let loe = h * (0.02 + 0.3 * rng.uniform());
        let lever = if i % 2 == 0 { Lever::Rotating } else { Lever::Oscillating };
        let q = 1.5 + 3.0 * rng.uniform();
        let s = slotted::synthesize(&SlottedRequest {
            stroke: h,
            k,
            pivots: loe,
            coupler: Coupler::Ratio(q),
            lever,
            drive: Drive::default(),
            limits: Limits::default(),
        })
        .unwrap_or_else(|e| panic!("{i}: {e}"));
        let r = s.length("OA").unwrap();
        let lec = s.length("EC").unwrap();
        // the crank turns by π − θ between the two dead positions:
        // rotating lever: crank pin on the perpendicular to OE through E, 2·acos(l_OE/r);
        // oscillating lever: slot tangent to the crank circle, 2·acos(r/l_OE)
        let fast = match lever {
            Lever::Rotating => 2.0 * (loe / r).acos(),
            Lever::Oscillating => 2.0 * (r / loe).acos(),
        };
        let k_test = (2.0 * PI - fast) / fast;
        assert!((k_test - k).abs() < 1e-9, "{i}: {k_test} vs {k}");
        assert!((s.check.k.unwrap() - k).abs() < 1e-9);
        // the ram's travel from the lever's extreme angles
        let lcd = s.length("CD").unwrap();
        let yg = s.def.sliders[1].through.y;
        let dx = |beta: f64| lec * beta.cos() + (lcd * lcd - (yg - lec * beta.sin()).powi(2)).sqrt();
        let h_test = match lever {
            Lever::Rotating => dx(0.0) - dx(PI),
            Lever::Oscillating => {
                let half = (r / loe).asin();
                dx(PI / 2.0 - half) - dx(PI / 2.0 + half)
            }
        };
        assert!((h_test - h).abs() < 1e-9 * h, "{i}: {h_test} vs {h}");
        assert!((linear(&s) - h).abs() < 1e-9 * h);
    }
    // K = 1 has no slotted lever
    let r = SlottedRequest {
        stroke: 0.4,
        k: 1.0,
        pivots: 0.05,
        coupler: Coupler::Ratio(3.0),
        lever: Lever::Rotating,
        drive: Drive::default(),
        limits: Limits::default(),
    };
    assert!(matches!(slotted::synthesize(&r), Err(SynthesisError::Infeasible { .. })));
}

#[test]
fn knee_presses_reach_the_stroke_at_the_knee_angles() {
    let mut rng = Rng(0x5eed_0005);
    for i in 0..1000 {
        let l = 0.1 + 0.4 * rng.uniform();
        let lf = if i % 2 == 0 { l } else { l * (1.0 + 0.5 * rng.uniform()) };
        let delta = (2.0 + 15.0 * rng.uniform()).to_radians();
        let depth = |b: f64| l * b.cos() + (lf * lf - (l * b.sin()).powi(2)).sqrt();
        let h = (depth(delta) - depth(PI / 2.0)) * (0.1 + 0.7 * rng.uniform());
        let k = 1.0 + 0.5 * rng.uniform();
        let s = knee_press::synthesize(&KneeRequest {
            stroke: h,
            k,
            rocker: l,
            link: lf,
            delta,
            pivot: KneePivot::Optimum,
            drive: Drive::default(),
            limits: Limits::default(),
        })
        .unwrap_or_else(|e| panic!("{i}: {e}"));
        assert!((s.check.k.unwrap() - k).abs() < 1e-9);
        // the dead positions found by the core: the lower one at the knee angle δ
        let fs = [at(&s, 0, "F"), at(&s, 1, "F")];
        let bs = [at(&s, 0, "B"), at(&s, 1, "B")];
        let low = if fs[0].y < fs[1].y { 0 } else { 1 };
        // the working (slower) stroke, which starts at the first dead
        // position, is the pressing one: it starts with the slide at the top
        assert_eq!(low, 1, "{i}: the working stroke lifts the slide");
        assert!((bs[low].x.atan2(-bs[low].y) - delta).abs() < 1e-7, "{i}");
        assert!(((fs[0].y - fs[1].y).abs() - h).abs() < 1e-9 * h.max(1.0));
        if lf == l {
            // closed form: cos β″ = cos δ − H/(2l)
            let b2 = (delta.cos() - h / (2.0 * l)).acos();
            assert!((bs[1 - low].x.atan2(-bs[1 - low].y) - b2).abs() < 1e-7, "{i}");
        }
    }
}

#[test]
fn knee_press_line_out_of_reach_names_the_nearest_line() {
    let r = KneeRequest {
        stroke: 0.09,
        k: 1.12,
        rocker: 0.22,
        link: 0.22,
        delta: 5f64.to_radians(),
        pivot: KneePivot::Horizontal(5.0),
        drive: Drive::default(),
        limits: Limits::default(),
    };
    match knee_press::synthesize(&r) {
        Err(SynthesisError::Infeasible {
            field, nearest: Some(x), ..
        }) => {
            assert_eq!(field, "pivot.horizontal");
            assert!(x < 5.0);
            assert!(
                knee_press::synthesize(&KneeRequest {
                    pivot: KneePivot::Horizontal(x * 0.999),
                    ..r
                })
                .is_ok()
            );
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn six_bars_by_inversion_put_the_slider_at_its_given_extremes() {
    let mut rng = Rng(0x5eed_0006);
    let mut ok = 0;
    for i in 0..1000 {
        // a forward rocker-slider: lever arm ρ at angle a0, swing γ, coupler, guide
        let rho = 0.2 + 0.3 * rng.uniform();
        let gamma = (30.0 + 50.0 * rng.uniform()).to_radians();
        let a0 = (-120.0 + 30.0 * rng.uniform()).to_radians();
        let yg = -(0.7 + 0.5 * rng.uniform()) * rho;
        let led = (0.9 + 0.8 * rng.uniform()) * rho;
        let d = |a: f64| Vec2::new(a.cos(), a.sin()) * rho;
        let e = |a: f64| {
            let p = d(a);
            Vec2::new(p.x + (led * led - (yg - p.y).powi(2)).sqrt(), yg)
        };
        let (e1, e2) = (e(a0), e(a0 + gamma));
        if !(e1.x.is_finite() && e2.x.is_finite()) {
            continue;
        }
        let r = InversionRequest {
            k: 1.0 + 0.4 * rng.uniform(),
            travel: e2.x - e1.x,
            guide: yg,
            start: e1.x,
            coupler: led,
            swing: gamma,
            lever: (0.5 + rng.uniform()) * rho,
            pivot: PivotCondition::Optimum,
            drive: Drive::default(),
            limits: Limits::default(),
        };
        match six_bar::by_inversion(&r) {
            Ok(s) => {
                ok += 1;
                assert!((s.check.k.unwrap() - r.k).abs() < 1e-9);
                // the core's dead positions of E are E′ and E″
                let es = [at(&s, 0, "E"), at(&s, 1, "E")];
                let hit = |p: Vec2| es.iter().any(|q| (*q - p).hypot() < 1e-8);
                assert!(hit(e1) && hit(e2), "{i}: {es:?} vs {e1:?} {e2:?}");
                // the lever turns by γ between them
                let ds = [at(&s, 0, "D"), at(&s, 1, "D")];
                let turn = tmm_geom::angle::wrap_pi(ds[1].atan2() - ds[0].atan2()).abs();
                assert!((turn - gamma).abs() < 1e-8, "{i}");
            }
            Err(SynthesisError::Infeasible { .. }) => {}
            Err(e) => panic!("{i}: {e}"),
        }
    }
    assert!(ok > 900, "{ok} of 1000 forward designs came back");
}

#[test]
fn six_bars_by_pressure_size_the_slider_coupler_by_the_closed_form() {
    let mut rng = Rng(0x5eed_0007);
    let mut ok = 0;
    for i in 0..4000 {
        let p = (30.0 + 20.0 * rng.uniform()).to_radians();
        let swing = (25.0 + 45.0 * rng.uniform()).to_radians();
        let (lb, lc) = (0.3 + 0.5 * rng.uniform(), 0.3 + 0.5 * rng.uniform());
        let guide = -lc * (0.1 + 0.6 * rng.uniform());
        let r = PressureRequest {
            k: 1.0 + 0.3 * rng.uniform(),
            swing,
            arm_b: lb,
            arm_c: lc,
            arm_angle: PI,
            guide,
            max_pressure: p,
            pivot: if i % 2 == 0 {
                PivotCondition::ExtremePressure(p)
            } else {
                PivotCondition::Optimum
            },
            drive: Drive::default(),
            limits: Limits::default(),
        };
        match six_bar::by_pressure(&r) {
            Ok(s) => {
                ok += 1;
                assert!((s.check.k.unwrap() - r.k).abs() < 1e-9);
                // C lowest with EC straight down (inside the symmetric swing):
                // its distance from the guide is l_EC + guide
                let want = (lc + guide) / p.sin();
                assert!((s.length("CD").unwrap() - want).abs() < 1e-12, "{i}");
            }
            // a random request may be infeasible (the guide too far for the
            // pressure angle): skipped; a failed cycle check is a defect
            Err(SynthesisError::Infeasible { .. }) => {}
            Err(e) => panic!("{i}: {e}"),
        }
        if ok == 1000 {
            break;
        }
    }
    assert_eq!(ok, 1000, "feasible requests among 4000");
}

#[test]
fn infeasible_requests_of_every_kind_name_the_field_and_the_nearest_value() {
    // slotted lever: a rotating lever's coupler must be longer than the arm EC
    let r = SlottedRequest {
        stroke: 0.4,
        k: 1.5,
        pivots: 0.05,
        coupler: Coupler::Ratio(0.8),
        lever: Lever::Rotating,
        drive: Drive::default(),
        limits: Limits::default(),
    };
    match slotted::synthesize(&r) {
        Err(SynthesisError::Infeasible {
            field, nearest: Some(n), ..
        }) => {
            assert_eq!(field, "coupler");
            assert!((n - 0.2).abs() < 1e-6, "{n}");
            assert!(
                slotted::synthesize(&SlottedRequest {
                    coupler: Coupler::Length(n * 1.01),
                    ..r
                })
                .is_ok()
            );
        }
        other => panic!("{other:?}"),
    }
    // knee press: a stroke beyond the knee's reach from δ (l = l_BF: 2l·cos δ)
    let r = KneeRequest {
        stroke: 0.5,
        k: 1.12,
        rocker: 0.22,
        link: 0.22,
        delta: 5f64.to_radians(),
        pivot: KneePivot::Optimum,
        drive: Drive::default(),
        limits: Limits::default(),
    };
    match knee_press::synthesize(&r) {
        Err(SynthesisError::Infeasible {
            field, nearest: Some(n), ..
        }) => {
            assert_eq!(field, "stroke");
            assert!((n - 0.44 * 5f64.to_radians().cos()).abs() < 1e-6, "{n}");
        }
        other => panic!("{other:?}"),
    }
    // six-bar by inversion: the coupler must reach both E′ and the inverted E″
    let r = InversionRequest {
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
    };
    match six_bar::by_inversion(&r) {
        Err(SynthesisError::Infeasible {
            field, nearest: Some(n), ..
        }) => {
            assert_eq!(field, "coupler");
            // half the distance from E′ to E″ turned by −γ about O3, computed here
            let (c, s) = ((-70f64).to_radians().cos(), (-70f64).to_radians().sin());
            let e2 = Vec2::new(0.54, -0.32);
            let e2i = Vec2::new(c * e2.x - s * e2.y, s * e2.x + c * e2.y);
            let half = 0.5 * (e2i - Vec2::new(0.18, -0.32)).hypot();
            assert!((n - half).abs() < 1e-5 * half, "{n} vs {half}");
        }
        other => panic!("{other:?}"),
    }
}

/// The acute angle between the lines of `a` and `b`, rad.
fn line_angle(a: Vec2, b: Vec2) -> f64 {
    ((a.x * b.x + a.y * b.y).abs() / (a.hypot() * b.hypot())).min(1.0).acos()
}

/// A kept design of case `i`: its working-stroke pressure angle `w`, found by
/// brute force, is within `limit`, and agrees with the design's own check.
#[track_caller]
fn kept_design_meets(i: usize, s: &Synthesis, w: f64, limit: f64) {
    assert!(w <= limit + 1e-9, "{i}: {}° over the limit {}°", w.to_degrees(), limit.to_degrees());
    assert!(
        (w - s.check.pressure_angle_max.0).abs() < 1e-6,
        "{i}: {w} vs {:?}",
        s.check.pressure_angle_max
    );
}

/// The largest of `angle` over the working stroke of a synthesised mechanism,
/// sampled at 20 001 crank angles: the working stroke is the longer crank
/// travel between the two dead positions the check found (K > 1).
fn working_stroke_max(s: &Synthesis, m: &tmm_linkage::Mechanism, angle: impl Fn(&tmm_linkage::mechanism::Solution) -> f64) -> f64 {
    let sg = m.crank.omega.signum();
    let (d0, d1) = (s.check.dead_phi[0], s.check.dead_phi[1]);
    let first = (sg * (d1 - d0)).rem_euclid(2.0 * PI);
    let (start, len) = if first > PI { (d0, first) } else { (d1, 2.0 * PI - first) };
    let mut sol = m.solution();
    let mut worst = 0.0f64;
    for k in 0..=20_000 {
        m.solve(start + sg * len * k as f64 / 20_000.0, &mut sol).unwrap();
        worst = worst.max(angle(&sol));
    }
    worst
}

/// The working stroke's largest pressure angle of a shaper's ram, by brute
/// force over 20 001 crank angles: the coupler CD pushes the ram D along its
/// guide, so ϑ is the angle between CD and the guide (the block slides in a
/// slot through the lever's pivot, where the force is normal to the slot and
/// so is the lever's velocity: ϑ = 0 there); over the working stroke, see [`working_stroke_max`].
fn shaper_working_pressure(s: &Synthesis) -> f64 {
    let m = tmm_linkage::Mechanism::new(&s.def).unwrap();
    let idx = |n: &str| m.points.iter().position(|p| p.name == n).unwrap();
    let (c, d) = (idx("C"), idx("D"));
    let guide = s.def.sliders.iter().find(|g| g.point == "D").unwrap().angle;
    let u = Vec2::new(guide.cos(), guide.sin());
    working_stroke_max(s, &m, |sol| line_angle(sol.points[d].p - sol.points[c].p, u))
}

/// A pressure limit on the working stroke holds on every shaper the synthesis
/// returns, and every refusal by that limit is right: the same request
/// without the limit gives a ram whose brute-force pressure angle exceeds it.
#[test]
fn shaper_pressure_limits_hold_by_brute_force() {
    let mut rng = Rng(0x5eed_0014);
    let (mut kept, mut refused) = (0, 0);
    for i in 0..300 {
        let h = 0.1 + rng.uniform();
        let k = 1.05 + 1.4 * rng.uniform();
        let loe = h * (0.02 + 0.3 * rng.uniform());
        let lever = if i % 2 == 0 { Lever::Rotating } else { Lever::Oscillating };
        let q = 1.5 + 3.0 * rng.uniform();
        let limit = (3.0 + 27.0 * rng.uniform()).to_radians();
        let request = |limits| SlottedRequest {
            stroke: h,
            k,
            pivots: loe,
            coupler: Coupler::Ratio(q),
            lever,
            drive: Drive::default(),
            limits,
        };
        let free = slotted::synthesize(&request(Limits::default())).unwrap_or_else(|e| panic!("{i}: {e}"));
        let worst = shaper_working_pressure(&free);
        let limited = Limits {
            pressure_working: Some(limit),
            ..Limits::default()
        };
        match slotted::synthesize(&request(limited)) {
            Ok(s) => {
                kept += 1;
                kept_design_meets(i, &s, shaper_working_pressure(&s), limit);
            }
            Err(SynthesisError::Infeasible { .. }) => {
                refused += 1;
                assert!(
                    worst > limit - 1e-6,
                    "{i}: refused, but the ram's ϑ is {}° ≤ {}°",
                    worst.to_degrees(),
                    limit.to_degrees()
                );
            }
            Err(e) => panic!("{i}: {e}"),
        }
    }
    // both outcomes occur
    assert!(kept > 30 && refused > 30, "{kept} kept, {refused} refused");
}

/// A knee press's largest pressure angle on the working stroke by brute
/// force over 20 001 crank angles, from the geometry alone: the coupler AB
/// pushes the rocker CB at B, which moves normal to CB; the link BF pushes
/// the ram F along its guide.
fn knee_working_pressure(s: &Synthesis) -> f64 {
    let m = tmm_linkage::Mechanism::new(&s.def).unwrap();
    let idx = |n: &str| m.points.iter().position(|p| p.name == n).unwrap();
    let (a, b, c, f) = (idx("A"), idx("B"), idx("C"), idx("F"));
    let guide = s.def.sliders.iter().find(|g| g.point == "F").unwrap().angle;
    let u = Vec2::new(guide.cos(), guide.sin());
    working_stroke_max(s, &m, |sol| {
        let p = |i: usize| sol.points[i].p;
        let cb = p(b) - p(c);
        line_angle(p(b) - p(a), Vec2::new(-cb.y, cb.x)).max(line_angle(p(f) - p(b), u))
    })
}

/// A working-stroke pressure limit holds, by the brute force above, on every
/// knee press the synthesis returns (the pivot chosen for the largest margin).
#[test]
fn knee_press_pressure_limits_hold_by_brute_force() {
    let mut rng = Rng(0x5eed_0015);
    let (mut kept, mut refused) = (0, 0);
    for i in 0..200 {
        let l = 0.1 + 0.4 * rng.uniform();
        let lf = if i % 2 == 0 { l } else { l * (1.0 + 0.5 * rng.uniform()) };
        let delta = (2.0 + 15.0 * rng.uniform()).to_radians();
        let depth = |b: f64| l * b.cos() + (lf * lf - (l * b.sin()).powi(2)).sqrt();
        let h = (depth(delta) - depth(PI / 2.0)) * (0.1 + 0.7 * rng.uniform());
        let k = 1.05 + 0.45 * rng.uniform();
        let limit = (20.0 + 40.0 * rng.uniform()).to_radians();
        let r = KneeRequest {
            stroke: h,
            k,
            rocker: l,
            link: lf,
            delta,
            pivot: KneePivot::Optimum,
            drive: Drive::default(),
            limits: Limits {
                pressure_working: Some(limit),
                ..Limits::default()
            },
        };
        match knee_press::synthesize(&r) {
            Ok(s) => {
                kept += 1;
                kept_design_meets(i, &s, knee_working_pressure(&s), limit);
            }
            Err(SynthesisError::Infeasible { .. }) => refused += 1,
            Err(e) => panic!("{i}: {e}"),
        }
    }
    assert!(kept > 20 && refused > 20, "{kept} kept, {refused} refused");
}

/// A six-bar's largest pressure angle on the working stroke by brute force
/// over 20 001 crank angles, from the geometry alone: the coupler AB pushes
/// the lever at B, which turns about its frame pivot; the slider's coupler
/// (link 4) pushes the slider along its guide.
fn six_bar_working_pressure(s: &Synthesis) -> f64 {
    let m = tmm_linkage::Mechanism::new(&s.def).unwrap();
    let idx = |n: &str| m.points.iter().position(|p| p.name == n).unwrap();
    let slider = &s.def.sliders[0];
    let to = slider.point.as_str();
    let link4 = s.def.links.iter().find(|l| l.name == "4").unwrap();
    let from = link4.points.iter().map(|(n, _)| n.as_str()).find(|n| *n != to).unwrap();
    let (a, b, o, f, t) = (idx("A"), idx("B"), idx(&s.def.fixed[1].0), idx(from), idx(to));
    let u = Vec2::new(slider.angle.cos(), slider.angle.sin());
    working_stroke_max(s, &m, |sol| {
        let p = |i: usize| sol.points[i].p;
        let ob = p(b) - p(o);
        line_angle(p(b) - p(a), Vec2::new(-ob.y, ob.x)).max(line_angle(p(t) - p(f), u))
    })
}

/// A working-stroke pressure limit holds, by the brute force above, on every
/// six-bar (by inversion and by pressure) the synthesis returns.
#[test]
fn six_bar_pressure_limits_hold_by_brute_force() {
    let mut rng = Rng(0x5eed_0016);
    let (mut kept, mut refused) = (0, 0);
    for i in 0..300 {
        let limit = (25.0 + 35.0 * rng.uniform()).to_radians();
        let limits = Limits {
            pressure_working: Some(limit),
            ..Limits::default()
        };
        let result = if i % 2 == 0 {
            let rho = 0.2 + 0.3 * rng.uniform();
            let gamma = (30.0 + 50.0 * rng.uniform()).to_radians();
            let a0 = (-120.0 + 30.0 * rng.uniform()).to_radians();
            let yg = -(0.7 + 0.5 * rng.uniform()) * rho;
            let led = (0.9 + 0.8 * rng.uniform()) * rho;
            let d = |a: f64| Vec2::new(a.cos(), a.sin()) * rho;
            let e = |a: f64| {
                let p = d(a);
                Vec2::new(p.x + (led * led - (yg - p.y).powi(2)).sqrt(), yg)
            };
            let (e1, e2) = (e(a0), e(a0 + gamma));
            if !(e1.x.is_finite() && e2.x.is_finite()) {
                continue;
            }
            six_bar::by_inversion(&InversionRequest {
                k: 1.05 + 0.35 * rng.uniform(),
                travel: e2.x - e1.x,
                guide: yg,
                start: e1.x,
                coupler: led,
                swing: gamma,
                lever: (0.5 + rng.uniform()) * rho,
                pivot: PivotCondition::Optimum,
                drive: Drive::default(),
                limits,
            })
        } else {
            let p = (30.0 + 20.0 * rng.uniform()).to_radians();
            let (lb, lc) = (0.3 + 0.5 * rng.uniform(), 0.3 + 0.5 * rng.uniform());
            six_bar::by_pressure(&PressureRequest {
                k: 1.05 + 0.25 * rng.uniform(),
                swing: (25.0 + 45.0 * rng.uniform()).to_radians(),
                arm_b: lb,
                arm_c: lc,
                arm_angle: PI,
                guide: -lc * (0.1 + 0.6 * rng.uniform()),
                max_pressure: p,
                pivot: PivotCondition::Optimum,
                drive: Drive::default(),
                limits,
            })
        };
        match result {
            Ok(s) => {
                kept += 1;
                kept_design_meets(i, &s, six_bar_working_pressure(&s), limit);
            }
            Err(SynthesisError::Infeasible { .. }) => refused += 1,
            Err(e) => panic!("{i}: {e}"),
        }
    }
    assert!(kept > 30 && refused > 10, "{kept} kept, {refused} refused");
}
