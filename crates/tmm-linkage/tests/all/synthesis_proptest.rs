//! No input makes synthesis panic or return a number that is not finite:
//! arbitrary values (negative, zero, huge, NaN, infinite) for every field of
//! every kind give either a result whose numbers are all finite or a typed
//! error.

use proptest::prelude::*;
use tmm_geom::Vec2;
use tmm_linkage::synthesis::crank_rocker::{CrankRockerRequest, RockerCondition};
use tmm_linkage::synthesis::crank_slider::{CrankSliderRequest, SliderCondition, TwoPositionsRequest};
use tmm_linkage::synthesis::function_gen::FunctionRequest;
use tmm_linkage::synthesis::knee_press::{KneePivot, KneeRequest};
use tmm_linkage::synthesis::pivot::PivotCondition;
use tmm_linkage::synthesis::six_bar::{InversionRequest, PressureRequest};
use tmm_linkage::synthesis::slotted::{Coupler, Lever, SlottedRequest};
use tmm_linkage::synthesis::{Drive, Limits, Request, Synthesis, synthesize};

/// Mostly plausible values, sometimes wild ones.
fn num() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => 0.01f64..2.0,
        1 => -2.0f64..0.0,
        1 => Just(0.0),
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
        1 => Just(1e300),
        1 => Just(1e-300),
    ]
}

fn k() -> impl Strategy<Value = f64> {
    prop_oneof![8 => 1.0f64..3.5, 1 => Just(f64::NAN), 1 => -1.0f64..1.0]
}

fn finite(s: &Synthesis) -> bool {
    let mut xs: Vec<f64> = vec![s.k, s.theta];
    xs.extend(s.lengths.iter().map(|(_, v)| *v));
    xs.extend(s.frame.iter().flat_map(|(_, p)| [p.x, p.y]));
    xs.extend([
        s.check.pressure_angle_max.0,
        s.check.pressure_angle_max.1,
        s.check.transmission_angle_min,
    ]);
    xs.extend(s.check.k);
    xs.extend(s.check.dead_positions.iter().flatten().flat_map(|(_, p)| [p.x, p.y]));
    xs.extend(s.def.links.iter().flat_map(|l| l.points.iter().flat_map(|(_, p)| [p.x, p.y])));
    xs.extend([s.construction.pivot.x, s.construction.pivot.y]);
    if let Some(l) = s.construction.locus {
        xs.extend([l.center.x, l.center.y, l.radius, l.arc_start, l.arc_sweep]);
    }
    xs.iter().all(|x| x.is_finite())
}

fn run(r: Request) -> Result<(), TestCaseError> {
    if let Ok(s) = synthesize(&r) {
        prop_assert!(finite(&s), "{r:?} gave {s:?}");
    }
    Ok(())
}

fn limits(p: f64) -> Limits {
    Limits {
        pressure_working: Some(p),
        pressure_return: None,
        transmission_min: None,
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, .. ProptestConfig::default() })]

    #[test]
    fn crank_slider(h in num(), kk in k(), x in num(), c in 0usize..4, p in num()) {
        let condition = match c {
            0 => SliderCondition::Lambda(x * 5.0),
            1 => SliderCondition::Offset(x),
            2 => SliderCondition::MaxPressure(x),
            _ => SliderCondition::Optimum,
        };
        run(Request::CrankSlider(CrankSliderRequest { stroke: h, k: kk, condition, drive: Drive::default(), limits: limits(p) }))?;
    }

    #[test]
    fn two_positions(l in num(), le in num(), a in num(), b in num(), t in num()) {
        run(Request::TwoPositions(TwoPositionsRequest {
            lambda: 5.0 * l, lambda_e: le - 1.0, phi_start: 4.0 * a, phi_end: 4.0 * b, travel: t - 1.0, drive: Drive::default(), limits: Limits::default(),
        }))?;
    }

    #[test]
    fn crank_rocker(kk in k(), rocker in num(), swing in num(), x in num(), c in 0usize..4, p in num()) {
        let condition = match c {
            0 => RockerCondition::Crank(x),
            1 => RockerCondition::Frame(x),
            2 => RockerCondition::FrameAngle(3.0 * x),
            _ => RockerCondition::Optimum,
        };
        run(Request::CrankRocker(CrankRockerRequest { k: kk, rocker, swing, condition, drive: Drive::default(), limits: limits(p) }))?;
    }

    #[test]
    fn function_generation(ps in proptest::collection::vec((num(), num()), 0..7), frame in num()) {
        let positions = ps.into_iter().map(|(a, b)| (3.0 * a, 3.0 * b)).collect();
        run(Request::Function(FunctionRequest { positions, frame, omega: 1.0, limits: Limits::default() }))?;
    }

    #[test]
    fn slotted(h in num(), kk in k(), loe in num(), q in num(), osc in any::<bool>()) {
        run(Request::Slotted(SlottedRequest {
            stroke: h, k: kk, pivots: loe, coupler: Coupler::Ratio(3.0 * q),
            lever: if osc { Lever::Oscillating } else { Lever::Rotating }, drive: Drive::default(), limits: Limits::default(),
        }))?;
    }

    #[test]
    fn knee(h in num(), kk in k(), l in num(), lf in num(), d in num(), x in num(), c in 0usize..4) {
        let pivot = match c { 0 => KneePivot::Horizontal(x), 1 => KneePivot::Crank(x), 2 => KneePivot::Frame(x), _ => KneePivot::Optimum };
        run(Request::Knee(KneeRequest { stroke: 0.2 * h, k: kk, rocker: l, link: lf, delta: 0.5 * d, pivot, drive: Drive::default(), limits: Limits::default() }))?;
    }

    #[test]
    fn six_bar_inversion(kk in k(), t in num(), g in num(), s in num(), c in num(), sw in num(), lv in num(), a in num()) {
        run(Request::SixBarInversion(InversionRequest {
            k: kk, travel: t, guide: -g, start: s, coupler: c, swing: 2.0 * sw - 1.0, lever: lv,
            pivot: PivotCondition::OnLine { point: Vec2::new(0.0, a), dir: Vec2::new(1.0, 0.0) },
            drive: Drive::default(), limits: Limits::default(),
        }))?;
    }

    #[test]
    fn six_bar_pressure(kk in k(), sw in num(), b in num(), c in num(), g in num(), p in num(), opt in any::<bool>()) {
        run(Request::SixBarPressure(PressureRequest {
            k: kk, swing: sw, arm_b: b, arm_c: c, arm_angle: std::f64::consts::PI, guide: -g, max_pressure: p,
            pivot: if opt { PivotCondition::Optimum } else { PivotCondition::ExtremePressure(p) },
            drive: Drive::default(), limits: Limits::default(),
        }))?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, .. ProptestConfig::default() })]

    /// Sweeps over any range of any name: typed errors or finite rows.
    #[test]
    fn sweeps(name in prop_oneof![Just("lambda"), Just("offset"), Just("k"), Just("stroke"), Just("nonsense")],
              from in num(), to in num(), n in 0usize..4) {
        let base = Request::CrankSlider(CrankSliderRequest {
            stroke: 0.3, k: 1.2, condition: SliderCondition::Lambda(3.5), drive: Drive::default(), limits: Limits::default(),
        });
        if let Ok(rows) = tmm_linkage::synthesis::sweep::sweep(&base, name, 4.0 * from, 4.0 * to, n) {
            for v in rows {
                if let Ok(row) = v.outcome {
                    prop_assert!(row.size.is_finite() && row.lengths.iter().all(|(_, x)| x.is_finite()));
                }
            }
        }
    }
}
