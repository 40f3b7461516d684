//! Variants (варианты синтеза): one number of a request swept over
//! FROM..TO in N steps, each variant solved and checked, so that a student
//! can justify the choice by the table of feasible variants — the lengths,
//! K achieved, the worst pressure angle and the overall size — and see why
//! the others fail.

use super::error::SynthesisError;
use super::request::{Request, solve};

/// One row of the table of a feasible variant.
#[derive(Debug, Clone, PartialEq)]
pub struct VariantRow {
    /// The lengths, m, by name.
    pub lengths: Vec<(String, f64)>,
    /// K found over the cycle (the analysis, not the formula).
    pub k: Option<f64>,
    /// The largest pressure angle on the working and return strokes, rad.
    pub pressure_angle_max: (f64, f64),
    /// The smallest transmission angle, rad.
    pub transmission_angle_min: f64,
    /// The overall size (the diagonal of the box of all points at both dead
    /// positions), m.
    pub size: f64,
}

/// A variant: the swept value and its row or why it fails.
#[derive(Debug, Clone, PartialEq)]
pub struct Variant {
    /// The value of the swept number.
    pub value: f64,
    /// The row, or the error of that value.
    pub outcome: Result<VariantRow, SynthesisError>,
}

fn without_nearest(e: SynthesisError) -> SynthesisError {
    match e {
        SynthesisError::Infeasible { field, condition, .. } => SynthesisError::Infeasible {
            field,
            condition,
            nearest: None,
        },
        other => other,
    }
}

/// Sweep `param` over `from..=to` in `n` values (n ≥ 1; n = 1 gives `from`).
/// A name of an extra condition switches every variant to that condition.
///
/// ```
/// use tmm_linkage::synthesis::{request::Request, sweep::sweep, crank_slider::*, Drive};
/// let base = Request::CrankSlider(CrankSliderRequest { stroke: 0.3, k: 1.2,
///     condition: SliderCondition::Lambda(3.5), drive: Drive::default(), limits: Default::default() });
/// let t = sweep(&base, "lambda", 2.0, 6.0, 5).unwrap();
/// assert_eq!(t.len(), 5);
/// assert!(t.iter().all(|v| (v.outcome.as_ref().unwrap().k.unwrap() - 1.2).abs() < 1e-9));
/// ```
pub fn sweep(base: &Request, param: &str, from: f64, to: f64, n: usize) -> Result<Vec<Variant>, SynthesisError> {
    if !(from.is_finite() && to.is_finite()) {
        return Err(SynthesisError::input("sweep.range", "FROM and TO must be finite numbers"));
    }
    if n == 0 || n > 1_000_000 {
        return Err(SynthesisError::input("sweep.steps", "N must be between 1 and 1 000 000"));
    }
    base.with_param(param, from)?;
    Ok((0..n)
        .map(|i| {
            let value = if n == 1 {
                from
            } else {
                from + (to - from) * i as f64 / (n - 1) as f64
            };
            // an infeasible variant names the condition that fails; the
            // nearest feasible value of one variant is not searched for (the
            // table itself shows where the feasible values are)
            let outcome = base
                .with_param(param, value)
                .and_then(|r| solve(&r))
                .map_err(without_nearest)
                .map(|s| VariantRow {
                    size: s.overall_size(),
                    lengths: s.lengths,
                    k: s.check.k,
                    pressure_angle_max: s.check.pressure_angle_max,
                    transmission_angle_min: s.check.transmission_angle_min,
                });
            Variant { value, outcome }
        })
        .collect())
}
