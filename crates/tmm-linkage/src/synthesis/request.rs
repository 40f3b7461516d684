//! Any synthesis request (задача синтеза) as one value, so that a caller (the
//! task file, the command line, a sweep) can hold, change and solve it
//! without knowing its kind; and the names of the numbers a sweep may vary.

use super::crank_rocker::{CrankRockerRequest, RockerCondition};
use super::crank_slider::{CrankSliderRequest, SliderCondition, TwoPositionsRequest};
use super::error::SynthesisError;
use super::function_gen::FunctionRequest;
use super::knee_press::{KneePivot, KneeRequest};
use super::pivot::PivotCondition;
use super::result::Synthesis;
use super::six_bar::{InversionRequest, PressureRequest};
use super::slotted::{Coupler, SlottedRequest};
use super::{crank_rocker, crank_slider, function_gen, knee_press, six_bar, slotted};

/// A synthesis request of any kind.
#[derive(Debug, Clone, PartialEq)]
pub enum Request {
    /// Crank-slider by H and K.
    CrankSlider(CrankSliderRequest),
    /// Crank-slider by two crank positions and the travel between them.
    TwoPositions(TwoPositionsRequest),
    /// Crank-rocker by K, rocker and swing.
    CrankRocker(CrankRockerRequest),
    /// Function generation by positions.
    Function(FunctionRequest),
    /// Slotted-lever shaper.
    Slotted(SlottedRequest),
    /// Crank-knee press.
    Knee(KneeRequest),
    /// Six-bar by kinematic inversion.
    SixBarInversion(InversionRequest),
    /// Six-bar by the pressure angle.
    SixBarPressure(PressureRequest),
}

/// Solve a request (each kind checks its result over the cycle).
pub fn synthesize(r: &Request) -> Result<Synthesis, SynthesisError> {
    match r {
        Request::CrankSlider(q) => crank_slider::synthesize(q),
        Request::TwoPositions(q) => crank_slider::by_two_positions(q),
        Request::CrankRocker(q) => crank_rocker::synthesize(q),
        Request::Function(q) => function_gen::synthesize(q),
        Request::Slotted(q) => slotted::synthesize(q),
        Request::Knee(q) => knee_press::synthesize(q),
        Request::SixBarInversion(q) => six_bar::by_inversion(q),
        Request::SixBarPressure(q) => six_bar::by_pressure(q),
    }
}

fn pivot_value(p: &mut PivotCondition) -> Option<&mut f64> {
    match p {
        PivotCondition::CrankLength(x)
        | PivotCondition::FrameDistance(x)
        | PivotCondition::MaxPressure(x)
        | PivotCondition::ExtremePressure(x) => Some(x),
        PivotCondition::OnLine { .. } | PivotCondition::Optimum => None,
    }
}

impl Request {
    /// The names a sweep may vary for this kind (SI values, angles in rad).
    pub fn params(&self) -> &'static [&'static str] {
        match self {
            Request::CrankSlider(_) => &["stroke", "k", "lambda", "offset", "max_pressure"],
            Request::TwoPositions(_) => &["lambda", "lambda_e", "phi_start", "phi_end", "travel"],
            Request::CrankRocker(_) => &["k", "rocker", "swing", "crank", "frame", "frame_angle"],
            Request::Function(_) => &["frame"],
            Request::Slotted(_) => &["stroke", "k", "pivots", "coupler"],
            Request::Knee(_) => &["stroke", "k", "rocker", "link", "delta", "pivot"],
            Request::SixBarInversion(_) => &["k", "travel", "guide", "start", "coupler", "swing", "lever", "pivot"],
            Request::SixBarPressure(_) => &["k", "swing", "arm_b", "arm_c", "guide", "max_pressure", "pivot"],
        }
    }

    /// The same request with the number `name` set to `value`. Setting the
    /// value of an extra condition switches to that condition.
    pub fn with_param(&self, name: &str, value: f64) -> Result<Request, SynthesisError> {
        let mut r = self.clone();
        let slot: Option<&mut f64> = match &mut r {
            Request::CrankSlider(q) => match name {
                "stroke" => Some(&mut q.stroke),
                "k" => Some(&mut q.k),
                "lambda" => {
                    q.condition = SliderCondition::Lambda(value);
                    None
                }
                "offset" => {
                    q.condition = SliderCondition::Offset(value);
                    None
                }
                "max_pressure" => {
                    q.condition = SliderCondition::MaxPressure(value);
                    None
                }
                _ => return Err(unknown(name, self)),
            },
            Request::TwoPositions(q) => match name {
                "lambda" => Some(&mut q.lambda),
                "lambda_e" => Some(&mut q.lambda_e),
                "phi_start" => Some(&mut q.phi_start),
                "phi_end" => Some(&mut q.phi_end),
                "travel" => Some(&mut q.travel),
                _ => return Err(unknown(name, self)),
            },
            Request::CrankRocker(q) => match name {
                "k" => Some(&mut q.k),
                "rocker" => Some(&mut q.rocker),
                "swing" => Some(&mut q.swing),
                "crank" => {
                    q.condition = RockerCondition::Crank(value);
                    None
                }
                "frame" => {
                    q.condition = RockerCondition::Frame(value);
                    None
                }
                "frame_angle" => {
                    q.condition = RockerCondition::FrameAngle(value);
                    None
                }
                _ => return Err(unknown(name, self)),
            },
            Request::Function(q) => match name {
                "frame" => Some(&mut q.frame),
                _ => return Err(unknown(name, self)),
            },
            Request::Slotted(q) => match name {
                "stroke" => Some(&mut q.stroke),
                "k" => Some(&mut q.k),
                "pivots" => Some(&mut q.pivots),
                "coupler" => match &mut q.coupler {
                    Coupler::Ratio(x) | Coupler::Length(x) => Some(x),
                },
                _ => return Err(unknown(name, self)),
            },
            Request::Knee(q) => match name {
                "stroke" => Some(&mut q.stroke),
                "k" => Some(&mut q.k),
                "rocker" => Some(&mut q.rocker),
                "link" => Some(&mut q.link),
                "delta" => Some(&mut q.delta),
                "pivot" => match &mut q.pivot {
                    KneePivot::Horizontal(x) | KneePivot::Crank(x) | KneePivot::Frame(x) => Some(x),
                    KneePivot::Optimum => return Err(no_value(name)),
                },
                _ => return Err(unknown(name, self)),
            },
            Request::SixBarInversion(q) => match name {
                "k" => Some(&mut q.k),
                "travel" => Some(&mut q.travel),
                "guide" => Some(&mut q.guide),
                "start" => Some(&mut q.start),
                "coupler" => Some(&mut q.coupler),
                "swing" => Some(&mut q.swing),
                "lever" => Some(&mut q.lever),
                "pivot" => Some(pivot_value(&mut q.pivot).ok_or_else(|| no_value(name))?),
                _ => return Err(unknown(name, self)),
            },
            Request::SixBarPressure(q) => match name {
                "k" => Some(&mut q.k),
                "swing" => Some(&mut q.swing),
                "arm_b" => Some(&mut q.arm_b),
                "arm_c" => Some(&mut q.arm_c),
                "guide" => Some(&mut q.guide),
                "max_pressure" => Some(&mut q.max_pressure),
                "pivot" => Some(pivot_value(&mut q.pivot).ok_or_else(|| no_value(name))?),
                _ => return Err(unknown(name, self)),
            },
        };
        if let Some(s) = slot {
            *s = value;
        }
        Ok(r)
    }
}

fn unknown(name: &str, r: &Request) -> SynthesisError {
    SynthesisError::input(
        "sweep.param",
        format!("`{name}` is not a number of this problem; one of: {}", r.params().join(", ")),
    )
}

fn no_value(name: &str) -> SynthesisError {
    SynthesisError::input(
        "sweep.param",
        format!("`{name}`: the crank pivot's condition of this request has no number to vary"),
    )
}
