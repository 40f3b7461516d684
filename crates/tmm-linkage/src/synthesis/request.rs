//! Any synthesis request (задача синтеза) as one value, so that a caller (the
//! task file, the command line, a sweep) can hold, change and solve it
//! without knowing its kind; and the names of the numbers a sweep may vary.

use super::crank_rocker::{CrankRockerRequest, RockerCondition};
use super::crank_slider::{CrankSliderRequest, SliderCondition, TwoPositionsRequest};
use super::cylinder::{self, CylinderRequest, PressureAt};
use super::error::SynthesisError;
use super::function_gen::FunctionRequest;
use super::knee_bell_crank::{self, BellKneeRequest};
use super::knee_press::{KneePivot, KneeRequest};
use super::pivot::PivotCondition;
use super::result::Synthesis;
use super::rocker_extremes::{self, Abscissa, ExtremesRequest};
use super::shaper::{self, ShaperRequest};
use super::six_bar::{InversionRequest, PressureRequest};
use super::slotted::{Coupler, SlottedRequest};
use super::three_positions::{self, ThreePositionsRequest};
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
    /// Crank-rocker by the rocker's extreme positions with D given, or with
    /// K given and X_D unknown (textbook П1.2, П1.3).
    RockerExtremes(ExtremesRequest),
    /// Four-bar through three positions with D and the rocker given
    /// (textbook П1.4).
    ThreePositions(ThreePositionsRequest),
    /// Lever with an oscillating cylinder (textbook П1.5).
    Cylinder(CylinderRequest),
    /// Crank-knee press with a bell-crank rocker (seed 002 ex. 2 read
    /// literally).
    KneeBellCrank(BellKneeRequest),
    /// The textbook's П3 shaper.
    Shaper(ShaperRequest),
}

/// Solve a request (each kind checks its result over the cycle). When no
/// mechanism meets it, the error's nearest feasible value is one that has
/// been solved and checked with everything else unchanged, differs from the
/// value asked for, and is rounded to few significant digits (in degrees for
/// an angle) towards the feasible side ([`nearest_feasible`]).
///
/// ```
/// use tmm_linkage::synthesis::{Request, SynthesisError, Drive, synthesize};
/// use tmm_linkage::synthesis::crank_slider::{CrankSliderRequest, SliderCondition};
/// // K = 3 is beyond every crank-slider; with λ2 = 3.5 the largest K is
/// // that of θ = 2·arctan(1/√3.5) (docs/synthesis.md § 3)
/// let r = Request::CrankSlider(CrankSliderRequest { stroke: 0.3, k: 3.0,
///     condition: SliderCondition::Lambda(3.5), drive: Drive::default(), limits: Default::default() });
/// let Err(SynthesisError::Infeasible { field, nearest: Some(k), .. }) = synthesize(&r) else { panic!() };
/// let th = 2.0 * (1.0 / 3.5f64.sqrt()).atan();
/// let k_max = (std::f64::consts::PI + th) / (std::f64::consts::PI - th);
/// assert_eq!(field, "k");
/// // (just below the bound the pressure angle reaches 90° and the check refuses)
/// assert!(k < k_max && k > k_max - 2e-3);
/// assert!(synthesize(&r.with_param("k", k).unwrap()).is_ok());
/// ```
pub fn synthesize(r: &Request) -> Result<Synthesis, SynthesisError> {
    match solve(r) {
        Err(SynthesisError::Infeasible { field, condition, nearest }) => {
            let nearest = nearest_feasible(r, &field, nearest);
            Err(SynthesisError::Infeasible { field, condition, nearest })
        }
        other => other,
    }
}

/// Solve a request as its kind does, the nearest value of an infeasible
/// request as the kind's own search gives it (not verified).
pub fn solve(r: &Request) -> Result<Synthesis, SynthesisError> {
    match r {
        Request::CrankSlider(q) => crank_slider::synthesize(q),
        Request::TwoPositions(q) => crank_slider::by_two_positions(q),
        Request::CrankRocker(q) => crank_rocker::synthesize(q),
        Request::Function(q) => function_gen::synthesize(q),
        Request::Slotted(q) => slotted::synthesize(q),
        Request::Knee(q) => knee_press::synthesize(q),
        Request::SixBarInversion(q) => six_bar::by_inversion(q),
        Request::SixBarPressure(q) => six_bar::by_pressure(q),
        Request::RockerExtremes(q) => rocker_extremes::synthesize(q),
        Request::ThreePositions(q) => three_positions::synthesize(q),
        Request::Cylinder(q) => cylinder::synthesize(q),
        Request::KneeBellCrank(q) => knee_bell_crank::synthesize(q),
        Request::Shaper(q) => shaper::synthesize(q),
    }
}

/// `x` rounded to `digits` significant digits, up (towards +∞) or down.
fn round_sig(x: f64, digits: i32, up: bool) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let e = x.abs().log10().floor() as i32;
    let scale = 10f64.powi(digits - 1 - e);
    let y = x * scale;
    // a value that is already round stays (y may carry a rounding error of
    // its own in the last bit)
    let near = y.round();
    let r = if (y - near).abs() <= 1e-9 * near.abs().max(1.0) {
        near
    } else if up {
        y.ceil()
    } else {
        y.floor()
    };
    r / scale
}

/// Whether the number `name` of a request is an angle (rounded in degrees).
fn is_angle(r: &Request, name: &str) -> bool {
    match name {
        "swing" | "frame_angle" | "max_pressure" | "delta" | "phi_start" | "phi_end" | "arm_angle" | "extreme_pressure"
        | "pivot_max_pressure" | "pressure_working" | "pressure_return" | "transmission_min" => true,
        "gamma_start" | "gamma_end" | "gamma1" | "gamma2" | "gamma3" | "phi12" | "phi13" | "pressure_start" | "pressure_end" => true,
        "pivot" => matches!(
            r,
            Request::SixBarInversion(InversionRequest {
                pivot: PivotCondition::MaxPressure(_) | PivotCondition::ExtremePressure(_),
                ..
            }) | Request::SixBarPressure(PressureRequest {
                pivot: PivotCondition::MaxPressure(_) | PivotCondition::ExtremePressure(_),
                ..
            })
        ),
        _ => false,
    }
}

/// The nearest feasible value of the number an infeasibility error names:
/// starting from the kind's own estimate `raw`, rounded away from the value
/// asked for to 4, 3, 2, then 5…12 significant digits, the first that
/// differs from the request and for which the request, solved again with
/// that value and everything else unchanged, passes its whole check. When no
/// rounding of the estimate works: for K, a bisection between the request
/// and a feasible K found below it; for any other number, a walk on from
/// the estimate away from the request in doubling steps (1e-4 of its size
/// first) to a value that works, a bisection back to the edge, then the same
/// rounding. `None` when no such value is found.
pub fn nearest_feasible(r: &Request, field: &str, raw: Option<f64>) -> Option<f64> {
    let name = r.param_name(field)?;
    let asked = r.value(name)?;
    let works = |v: f64| v != asked && r.with_param(name, v).is_ok_and(|q| solve(&q).is_ok());
    let angle = is_angle(r, name);
    let (to_user, from_user) = if angle {
        (f64::to_degrees as fn(f64) -> f64, f64::to_radians as fn(f64) -> f64)
    } else {
        ((|x| x) as fn(f64) -> f64, (|x| x) as fn(f64) -> f64)
    };
    let polish = |raw: f64| -> Option<f64> {
        if !raw.is_finite() || raw == asked {
            return None;
        }
        let up = raw > asked;
        for digits in [4, 3, 2, 5, 6, 7, 8, 9, 10, 11, 12] {
            let v = from_user(round_sig(to_user(raw), digits, up));
            if works(v) {
                return Some(v);
            }
        }
        works(raw).then_some(raw)
    };
    if let Some(v) = raw.and_then(polish) {
        return Some(v);
    }
    if name == "k" {
        if !(asked.is_finite() && asked > 1.0) {
            return None;
        }
        // K: a feasible value below the request, then bisection towards it
        // on t = (K − 1)/(K + 1) = θ/π, which stays in [0, 1) for any K
        let k_of = |t: f64| (1.0 + t) / (1.0 - t);
        let t_asked = (asked - 1.0) / (asked + 1.0);
        let lo = [0.5, 0.25, 0.125, 0.0625, 0.03125, 0.0]
            .into_iter()
            .map(|f| f * t_asked)
            .find(|&t| works(k_of(t)))?;
        let t = bisect(lo, t_asked, |t| works(k_of(t)));
        return polish(k_of(t)).or(Some(k_of(t)));
    }
    // the estimate is not a bound that works (the kind's estimate ignores a
    // condition checked later): walk on from it, away from the request, in
    // doubling steps to the first value that works, then bisect back
    let raw = raw.filter(|x| x.is_finite() && *x != asked)?;
    let dir = (raw - asked).signum();
    let scale = raw.abs().max(asked.abs()).max(f64::MIN_POSITIVE);
    let mut fail = raw;
    for j in 0..24 {
        let v = raw + dir * scale * 1e-4 * 2f64.powi(j);
        if works(v) {
            let v = bisect(v, fail, works);
            return polish(v).or(Some(v));
        }
        fail = v;
    }
    None
}

/// Bisection between `good` (where `ok` holds) and `bad` (where it does
/// not): the last value where it holds.
fn bisect(mut good: f64, mut bad: f64, ok: impl Fn(f64) -> bool) -> f64 {
    for _ in 0..52 {
        let mid = 0.5 * (good + bad);
        if mid == good || mid == bad {
            break;
        }
        if ok(mid) {
            good = mid;
        } else {
            bad = mid;
        }
    }
    good
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

/// The number a six-bar's pivot condition of this name holds, or the
/// condition with that number.
fn pivot_named<'a>(p: &'a mut PivotCondition, name: &str, set: Option<f64>) -> Option<Option<&'a mut f64>> {
    let make: fn(f64) -> PivotCondition = match name {
        "crank" => PivotCondition::CrankLength,
        "frame" => PivotCondition::FrameDistance,
        "pivot_max_pressure" => PivotCondition::MaxPressure,
        "extreme_pressure" => PivotCondition::ExtremePressure,
        _ => return None,
    };
    if let Some(v) = set {
        *p = make(v);
        return Some(None);
    }
    let active = matches!(
        (name, &*p),
        ("crank", PivotCondition::CrankLength(_))
            | ("frame", PivotCondition::FrameDistance(_))
            | ("pivot_max_pressure", PivotCondition::MaxPressure(_))
            | ("extreme_pressure", PivotCondition::ExtremePressure(_))
    );
    Some(if active { pivot_value(p) } else { None })
}

/// The slot of a number of a request, or `None` when the request has no
/// such number or its condition is another one. With `set`, a name that
/// selects an extra condition switches to it with that value (and gives no
/// slot). `Err(())`: not a name of this kind.
fn slot<'a>(r: &'a mut Request, name: &str, set: Option<f64>) -> Result<Option<&'a mut f64>, ()> {
    if matches!(name, "pressure_working" | "pressure_return" | "transmission_min") {
        let limits = match r {
            Request::CrankSlider(q) => &mut q.limits,
            Request::TwoPositions(q) => &mut q.limits,
            Request::CrankRocker(q) => &mut q.limits,
            Request::Function(q) => &mut q.limits,
            Request::Slotted(q) => &mut q.limits,
            Request::Knee(q) => &mut q.limits,
            Request::SixBarInversion(q) => &mut q.limits,
            Request::SixBarPressure(q) => &mut q.limits,
            Request::RockerExtremes(q) => &mut q.limits,
            Request::ThreePositions(q) => &mut q.limits,
            Request::Cylinder(q) => &mut q.limits,
            Request::KneeBellCrank(q) => &mut q.limits,
            Request::Shaper(q) => &mut q.limits,
        };
        let l = match name {
            "pressure_working" => &mut limits.pressure_working,
            "pressure_return" => &mut limits.pressure_return,
            _ => &mut limits.transmission_min,
        };
        if let Some(v) = set {
            *l = Some(v);
        }
        return Ok(l.as_mut());
    }
    // a condition's number: switch to it, or its value when it is the one
    macro_rules! cond {
        ($c:expr, $variant:path) => {{
            if let Some(v) = set {
                $c = $variant(v);
                return Ok(None);
            }
            match &mut $c {
                $variant(x) => Some(x),
                _ => None,
            }
        }};
    }
    Ok(match r {
        Request::CrankSlider(q) => match name {
            "stroke" => Some(&mut q.stroke),
            "k" => Some(&mut q.k),
            "lambda" => cond!(q.condition, SliderCondition::Lambda),
            "offset" => cond!(q.condition, SliderCondition::Offset),
            "max_pressure" => cond!(q.condition, SliderCondition::MaxPressure),
            _ => return Err(()),
        },
        Request::TwoPositions(q) => match name {
            "lambda" => Some(&mut q.lambda),
            "lambda_e" => Some(&mut q.lambda_e),
            "phi_start" => Some(&mut q.phi_start),
            "phi_end" => Some(&mut q.phi_end),
            "travel" => Some(&mut q.travel),
            _ => return Err(()),
        },
        Request::CrankRocker(q) => match name {
            "k" => Some(&mut q.k),
            "rocker" => Some(&mut q.rocker),
            "swing" => Some(&mut q.swing),
            "crank" => cond!(q.condition, RockerCondition::Crank),
            "frame" => cond!(q.condition, RockerCondition::Frame),
            "frame_angle" => cond!(q.condition, RockerCondition::FrameAngle),
            _ => return Err(()),
        },
        Request::Function(q) => match name {
            "frame" => Some(&mut q.frame),
            _ => return Err(()),
        },
        Request::Slotted(q) => match name {
            "stroke" => Some(&mut q.stroke),
            "k" => Some(&mut q.k),
            "pivots" => Some(&mut q.pivots),
            "coupler" => match &mut q.coupler {
                Coupler::Ratio(x) | Coupler::Length(x) => Some(x),
            },
            _ => return Err(()),
        },
        Request::Knee(q) => match name {
            "stroke" => Some(&mut q.stroke),
            "k" => Some(&mut q.k),
            "rocker" => Some(&mut q.rocker),
            "link" => Some(&mut q.link),
            "delta" => Some(&mut q.delta),
            "horizontal" => cond!(q.pivot, KneePivot::Horizontal),
            "crank" => cond!(q.pivot, KneePivot::Crank),
            "frame" => cond!(q.pivot, KneePivot::Frame),
            "pivot" => match &mut q.pivot {
                KneePivot::Horizontal(x) | KneePivot::Crank(x) | KneePivot::Frame(x) => Some(x),
                KneePivot::Optimum => None,
            },
            _ => return Err(()),
        },
        Request::SixBarInversion(q) => match name {
            "k" => Some(&mut q.k),
            "travel" => Some(&mut q.travel),
            "guide" => Some(&mut q.guide),
            "start" => Some(&mut q.start),
            "coupler" => Some(&mut q.coupler),
            "swing" => Some(&mut q.swing),
            "lever" => Some(&mut q.lever),
            "pivot" => pivot_value(&mut q.pivot),
            n => pivot_named(&mut q.pivot, n, set).ok_or(())?,
        },
        Request::SixBarPressure(q) => match name {
            "k" => Some(&mut q.k),
            "swing" => Some(&mut q.swing),
            "arm_b" => Some(&mut q.arm_b),
            "arm_c" => Some(&mut q.arm_c),
            "guide" => Some(&mut q.guide),
            "max_pressure" => Some(&mut q.max_pressure),
            "pivot" => pivot_value(&mut q.pivot),
            n => pivot_named(&mut q.pivot, n, set).ok_or(())?,
        },
        Request::RockerExtremes(q) => match name {
            "frame_x" => match &mut q.abscissa {
                Abscissa::Given(x) => Some(x),
                Abscissa::ByK(_) => None,
            },
            "k" => match &mut q.abscissa {
                Abscissa::ByK(k) => Some(k),
                Abscissa::Given(_) => None,
            },
            "frame_y" => Some(&mut q.frame_y),
            "rocker" => Some(&mut q.rocker),
            "gamma_start" => Some(&mut q.gamma_start),
            "gamma_end" => Some(&mut q.gamma_end),
            _ => return Err(()),
        },
        Request::ThreePositions(q) => match name {
            "frame_x" => Some(&mut q.frame.x),
            "frame_y" => Some(&mut q.frame.y),
            "rocker" => Some(&mut q.rocker),
            "gamma1" => Some(&mut q.gammas[0]),
            "gamma2" => Some(&mut q.gammas[1]),
            "gamma3" => Some(&mut q.gammas[2]),
            "phi12" => Some(&mut q.crank_turns[0]),
            "phi13" => Some(&mut q.crank_turns[1]),
            _ => return Err(()),
        },
        Request::Cylinder(q) => match name {
            "h_min" => Some(&mut q.h_min),
            "h_max" => Some(&mut q.h_max),
            "rod" => Some(&mut q.rod),
            "swing" => Some(&mut q.swing),
            "pressure_start" => match &mut q.pressure {
                PressureAt::Start(t) => Some(t),
                PressureAt::End(_) => None,
            },
            "pressure_end" => match &mut q.pressure {
                PressureAt::End(t) => Some(t),
                PressureAt::Start(_) => None,
            },
            "frame_y" => q.frame_y.as_mut(),
            _ => return Err(()),
        },
        Request::KneeBellCrank(q) => match name {
            "stroke" => Some(&mut q.stroke),
            "k" => Some(&mut q.k),
            "knee" => Some(&mut q.knee),
            "link" => Some(&mut q.link),
            "arm" => Some(&mut q.arm),
            "chord" => Some(&mut q.chord),
            "delta" => Some(&mut q.delta),
            "horizontal" => cond!(q.pivot, KneePivot::Horizontal),
            "crank" => cond!(q.pivot, KneePivot::Crank),
            "frame" => cond!(q.pivot, KneePivot::Frame),
            "pivot" => match &mut q.pivot {
                KneePivot::Horizontal(x) | KneePivot::Crank(x) | KneePivot::Frame(x) => Some(x),
                KneePivot::Optimum => None,
            },
            _ => return Err(()),
        },
        Request::Shaper(q) => match name {
            "stroke" => Some(&mut q.stroke),
            "k" => Some(&mut q.k),
            "rocker" => Some(&mut q.rocker),
            "lambda" => Some(&mut q.lambda),
            "frame" => Some(&mut q.frame),
            "ram_center" => Some(&mut q.ram_center),
            _ => return Err(()),
        },
    })
}

impl Request {
    /// The names a sweep may vary for this kind (SI values, angles in rad).
    /// A name of an extra condition (`lambda` of a crank-slider, `crank` of a
    /// crank-rocker, …) switches the request to that condition, so it needs
    /// not be the one given.
    pub fn params(&self) -> &'static [&'static str] {
        match self {
            Request::CrankSlider(_) => &["stroke", "k", "lambda", "offset", "max_pressure"],
            Request::TwoPositions(_) => &["lambda", "lambda_e", "phi_start", "phi_end", "travel"],
            Request::CrankRocker(_) => &["k", "rocker", "swing", "crank", "frame", "frame_angle"],
            Request::Function(_) => &["frame"],
            Request::Slotted(_) => &["stroke", "k", "pivots", "coupler"],
            Request::Knee(_) => &["stroke", "k", "rocker", "link", "delta", "horizontal", "crank", "frame", "pivot"],
            Request::SixBarInversion(_) => &[
                "k",
                "travel",
                "guide",
                "start",
                "coupler",
                "swing",
                "lever",
                "crank",
                "frame",
                "pivot_max_pressure",
                "extreme_pressure",
                "pivot",
            ],
            Request::SixBarPressure(_) => &[
                "k",
                "swing",
                "arm_b",
                "arm_c",
                "guide",
                "max_pressure",
                "crank",
                "frame",
                "pivot_max_pressure",
                "extreme_pressure",
                "pivot",
            ],
            Request::RockerExtremes(q) => match q.abscissa {
                Abscissa::Given(_) => &["frame_x", "frame_y", "rocker", "gamma_start", "gamma_end"],
                Abscissa::ByK(_) => &["k", "frame_y", "rocker", "gamma_start", "gamma_end"],
            },
            Request::ThreePositions(_) => &["frame_x", "frame_y", "rocker", "gamma1", "gamma2", "gamma3", "phi12", "phi13"],
            Request::Cylinder(q) => match (q.pressure, q.frame_y) {
                (PressureAt::Start(_), Some(_)) => &["h_min", "h_max", "rod", "swing", "pressure_start", "frame_y"],
                (PressureAt::Start(_), None) => &["h_min", "h_max", "rod", "swing", "pressure_start"],
                (PressureAt::End(_), Some(_)) => &["h_min", "h_max", "rod", "swing", "pressure_end", "frame_y"],
                (PressureAt::End(_), None) => &["h_min", "h_max", "rod", "swing", "pressure_end"],
            },
            Request::KneeBellCrank(_) => &[
                "stroke",
                "k",
                "knee",
                "link",
                "arm",
                "chord",
                "delta",
                "horizontal",
                "crank",
                "frame",
                "pivot",
            ],
            Request::Shaper(_) => &["stroke", "k", "rocker", "lambda", "frame", "ram_center"],
        }
    }

    /// Whether `name` selects an extra condition (setting it switches the
    /// request to that condition).
    pub fn is_condition(&self, name: &str) -> bool {
        matches!(
            (self, name),
            (Request::CrankSlider(_), "lambda" | "offset" | "max_pressure")
                | (Request::CrankRocker(_), "crank" | "frame" | "frame_angle")
                | (Request::Knee(_), "horizontal" | "crank" | "frame")
                | (Request::KneeBellCrank(_), "horizontal" | "crank" | "frame")
                | (
                    Request::SixBarInversion(_) | Request::SixBarPressure(_),
                    "crank" | "frame" | "pivot_max_pressure" | "extreme_pressure"
                )
        )
    }

    /// The value of the number `name` (a name of [`Request::params`] or a
    /// limit: `pressure_working`, `pressure_return`, `transmission_min`), SI;
    /// `None` when the request does not hold it (another condition, no limit).
    pub fn value(&self, name: &str) -> Option<f64> {
        let mut r = self.clone();
        slot(&mut r, name, None).ok().flatten().map(|x| *x)
    }

    /// The name of [`Request::value`] for a field an error of this request
    /// names (`limits.pressure_working` → `pressure_working`, a knee press's
    /// `pivot.horizontal` → `horizontal`).
    pub fn param_name<'a>(&self, field: &'a str) -> Option<&'a str> {
        let f = field.strip_prefix("limits.").unwrap_or(field);
        let f = match (self, f) {
            (Request::Knee(_), p) => p.strip_prefix("pivot.").unwrap_or(p),
            (Request::KneeBellCrank(_), p) => p.strip_prefix("pivot.").unwrap_or(p),
            (_, p) => p,
        };
        self.value(f).is_some().then_some(f)
    }

    /// The same request with the number `name` set to `value` (a name of
    /// [`Request::params`] or a limit). Setting the value of an extra
    /// condition switches to that condition.
    pub fn with_param(&self, name: &str, value: f64) -> Result<Request, SynthesisError> {
        let mut r = self.clone();
        match slot(&mut r, name, Some(value)) {
            Err(()) => Err(unknown(name, self)),
            Ok(Some(s)) => {
                *s = value;
                Ok(r)
            }
            Ok(None) if self.is_condition(name) || name.starts_with("pressure_") || name == "transmission_min" => Ok(r),
            Ok(None) => Err(no_value(name)),
        }
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
