//! Reading the `[dynamics]` section of a task file into the core's
//! [`DynamicsSpec`]: the coefficient of speed fluctuation δ (коэффициент
//! неравномерности хода), the driving moment (constant or an induction
//! motor through a gear ratio), constant inertias on the crank and motor
//! shafts, and the flywheel's place, material and shape. The nominal crank
//! speed is the `[linkage]` input speed; the loads are those of `[forces]`.
//!
//! ```toml
//! [dynamics]
//! delta = 0.02                    # 0 < δ < 1
//! driving = "constant"            # or "motor" (needs [dynamics.motor]), or "engine"
//! [dynamics.motor]
//! synchronous_speed = "1500 rpm"
//! nominal_speed = "1420 rpm"
//! nominal_torque = "40 N m"
//! ratio = 1.6                     # ω_motor / ω_crank
//! [dynamics.inertia]
//! crank_shaft = "0.05 kg m^2"     # besides the crank itself
//! motor_shaft = "0.01 kg m^2"     # rotor, gearbox reduced to the motor shaft
//! [dynamics.flywheel]
//! place = "crank"                 # or "motor"
//! density = "7850 kg/m^3"
//! shape = "disc"                  # or "rim" (with thickness_ratio)
//! width_ratio = 0.2               # b/D
//! ```

use std::collections::BTreeMap;
use std::ops::Range;

use serde::Deserialize;
use tmm_geom::units::Dim;
use tmm_linkage::dynamics::{DrivingMoment, DynamicsSpec, FlywheelPlace, FlywheelShape, FlywheelSpec, Motor, STEEL_DENSITY};
use tmm_linkage::forces::stroke::Working;

use crate::task::{Qty, RawQty, qty};
use crate::{Error, TaskSource};

type S<T> = toml::Spanned<T>;

#[derive(Deserialize)]
struct File {
    dynamics: Option<S<DynamicsSec>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct DynamicsSec {
    motion: Option<S<String>>,
    delta: Option<Qty>,
    points: Option<S<i64>>,
    driving: Option<S<String>>,
    motor: Option<S<MotorSec>>,
    inertia: Option<S<InertiaSec>>,
    flywheel: Option<S<FlywheelSec>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct MotorSec {
    synchronous_speed: Qty,
    nominal_speed: Qty,
    nominal_torque: Qty,
    ratio: Option<Qty>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct InertiaSec {
    crank_shaft: Option<Qty>,
    motor_shaft: Option<Qty>,
    motor_speed: Option<Qty>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FlywheelSec {
    place: Option<S<String>>,
    density: Option<Qty>,
    shape: Option<S<String>>,
    width_ratio: Option<Qty>,
    thickness_ratio: Option<Qty>,
    inner_ratio: Option<Qty>,
    speed_ratio: Option<Qty>,
}

/// The `[dynamics]` section, read and checked field by field.
#[derive(Debug, Clone)]
pub struct DynamicsTask {
    /// The specification for the core.
    pub spec: DynamicsSpec,
    /// Spans of the fields by their full name (`dynamics.delta`,
    /// `dynamics.motor.synchronous_speed`), to locate the core's errors.
    pub spans: BTreeMap<String, Range<usize>>,
    /// Span of the whole section.
    pub section: Range<usize>,
}

impl DynamicsTask {
    /// The span of a field, else of its nearest enclosing table, else of the
    /// section.
    pub fn span_of(&self, field: &str) -> Range<usize> {
        let mut f = field;
        loop {
            if let Some(s) = self.spans.get(f) {
                return s.clone();
            }
            match f.rsplit_once('.') {
                Some((head, _)) => f = head,
                None => return self.section.clone(),
            }
        }
    }
}

/// What would be valid for each field, for the help line of an error.
pub fn help_for(field: &str) -> &'static str {
    match field {
        "dynamics.delta" => "delta = 0.02 (0 < δ < 1; typically 0.01…0.1: 0.02–0.05 for presses and pumps, 0.01–0.02 for machine tools)",
        "dynamics.points" => "points = 3600 (intervals of the crank angle over the cycle, at least 360, a multiple of 12)",
        "dynamics.driving" => {
            "driving = \"constant\" (the course's constant driving moment, the default), \"motor\" (with [dynamics.motor]) or \"engine\" (the gas forces of [forces] drive; the resistance is a constant moment)"
        }
        "dynamics.motor"
        | "dynamics.motor.synchronous_speed"
        | "dynamics.motor.nominal_speed"
        | "dynamics.motor.nominal_torque"
        | "dynamics.motor.ratio" => {
            "[dynamics.motor] synchronous_speed = \"1500 rpm\", nominal_speed = \"1420 rpm\" (below the synchronous), nominal_torque = \"40 N m\", ratio = 1.6 (ω_motor/ω_crank: about nominal_speed / the crank's speed, so that the motor under the machine's mean moment turns the crank at its [linkage] speed)"
        }
        "dynamics.inertia" | "dynamics.inertia.crank_shaft" | "dynamics.inertia.motor_shaft" | "dynamics.inertia.motor_speed" => {
            "[dynamics.inertia] crank_shaft = \"0.05 kg m^2\", motor_shaft = \"0.01 kg m^2\" (0 to 1e12 kg·m²; the motor shaft's needs a motor or motor_speed = \"950 rpm\", the rotor's speed with a constant driving moment, > 0)"
        }
        "dynamics.flywheel.place" => {
            "place = \"crank\" (the default), \"motor\" (needs a motor or inertia.motor_speed) or \"shaft\" (with speed_ratio = ω_shaft/ω_crank)"
        }
        "dynamics.flywheel.speed_ratio" => {
            "speed_ratio = 1.8333 (ω_shaft/ω_crank of the flywheel's shaft, 1e-6 … 1e6; only with place = \"shaft\")"
        }
        "dynamics.flywheel.inner_ratio" => {
            "inner_ratio = 0.8 (a rim's inner diameter over its outer, D₁/D₂, 0.001 … 0.998; only with shape = \"rim\", instead of thickness_ratio)"
        }
        "dynamics.flywheel.density" => {
            "density = \"7850 kg/m^3\" (steel, the default; cast iron 7200) — kg/m^3, g/cm^3 or t/m^3, a plain number is kg/m³; 10 … 100 000 kg/m³"
        }
        "dynamics.flywheel.shape" => "shape = \"disc\" (the default) or \"rim\" (with thickness_ratio = h/D in (0, 0.5))",
        "dynamics.flywheel.width_ratio" => "width_ratio = 0.2 (b/D, 0.001 … 10)",
        "dynamics.flywheel.thickness_ratio" => {
            "thickness_ratio = 0.1 (the rim's radial thickness h/D, 0.001 … 0.4999; only with shape = \"rim\")"
        }
        _ => "see the \"Task file\" part of docs/dynamics.md",
    }
}

/// `true` when the task file has a `[dynamics]` section.
pub fn present(task: &TaskSource) -> Result<bool, Error> {
    #[derive(Deserialize)]
    struct Probe {
        dynamics: Option<S<toml::Value>>,
    }
    let p: Probe = task.parse("dynamics")?;
    Ok(p.dynamics.is_some())
}

/// The span of the `[dynamics]` section, if any.
pub fn section_span(task: &TaskSource) -> Result<Option<Range<usize>>, Error> {
    #[derive(Deserialize)]
    struct Probe {
        dynamics: Option<S<toml::Value>>,
    }
    let p: Probe = task.parse("dynamics")?;
    Ok(p.dynamics.map(|d| d.span()))
}

/// A material density in kg/m³: a plain number, or a string with
/// `kg/m^3` (`kg/m³`, `kg/m3`), `g/cm^3` or `t/m^3`.
fn density(task: &TaskSource, field: &str, q: &Qty) -> Result<f64, Error> {
    let bad = |m: String| Error::at(task, q.span(), field, m).with_help(help_for(field));
    match q.get_ref() {
        RawQty::Num(x) => Ok(*x),
        RawQty::Text(s) => {
            let s = s.trim();
            let split = s
                .find(|c: char| !(c.is_ascii_digit() || matches!(c, '.' | '-' | '+' | 'e' | 'E')))
                .unwrap_or(s.len());
            let (n, u) = s.split_at(split);
            let v: f64 = n.trim().parse().map_err(|_| bad(format!("`{s}` is not a density")))?;
            let u: String = u.chars().filter(|c| !c.is_whitespace()).collect();
            let k = match u.as_str() {
                "" | "kg/m^3" | "kg/m³" | "kg/m3" | "kg·m^-3" => 1.0,
                "g/cm^3" | "g/cm³" | "g/cm3" | "t/m^3" | "t/m³" | "t/m3" => 1000.0,
                other => return Err(bad(format!("unknown unit of density `{other}`"))),
            };
            Ok(v * k)
        }
    }
}

/// Read the `[dynamics]` section (`None` when the file has none), with the
/// working stroke of `[linkage]`. Every field's value is checked here, each
/// error located in the file; the motor against the crank's speed is
/// checked with the mechanism (`Dynamics::compute`, located by
/// [`DynamicsTask::span_of`]).
pub fn read(task: &TaskSource, working: Working) -> Result<Option<DynamicsTask>, Error> {
    // the motion first: the single stroke (`motion = "single-stroke"`) has
    // keys of its own and is read by stroke_task
    #[derive(Deserialize)]
    struct Probe {
        dynamics: Option<ProbeSec>,
    }
    #[derive(Deserialize)]
    struct ProbeSec {
        motion: Option<S<String>>,
    }
    let p: Probe = task.parse("dynamics")?;
    if let Some(m) = p.dynamics.and_then(|d| d.motion)
        && m.get_ref() != "steady"
    {
        let msg = if m.get_ref() == super::stroke_task::SINGLE_STROKE {
            "a single stroke has no steady cycle: the kinetostatics cannot take its crank motion from it (say crank_motion = \"constant\" in [forces])".to_string()
        } else {
            format!("unknown motion `{}`", m.get_ref())
        };
        return Err(Error::at(task, m.span(), "dynamics.motion", msg).with_help(super::stroke_task::help_for("dynamics.motion")));
    }
    let f: File = task.parse("dynamics")?;
    let Some(sec) = f.dynamics else { return Ok(None) };
    let section = sec.span();
    let sec = sec.into_inner();
    let mut spans = BTreeMap::new();
    // `motion = "steady"` (the probe above refused every other value)
    if let Some(m) = &sec.motion {
        spans.insert("dynamics.motion".to_string(), m.span());
    }
    let delta_q = sec.delta.as_ref().ok_or_else(|| {
        Error::at(
            task,
            section.clone(),
            "dynamics.delta",
            "the coefficient of speed fluctuation δ is missing",
        )
        .with_help(help_for("dynamics.delta"))
    })?;
    spans.insert("dynamics.delta".to_string(), delta_q.span());
    let delta = qty(task, "dynamics.delta", delta_q, Dim::Ratio)?;
    let mut spec = DynamicsSpec::new(delta);
    spec.working = working;
    if let Some(p) = &sec.points {
        spans.insert("dynamics.points".to_string(), p.span());
        let v = *p.get_ref();
        if !(360..=tmm_linkage::dynamics::spec::MAX_POINTS as i64).contains(&v) || v % 12 != 0 {
            return Err(Error::at(
                task,
                p.span(),
                "dynamics.points",
                format!(
                    "the cycle needs 360…{} intervals (0.01° apart at most), a multiple of 12; not {v}",
                    tmm_linkage::dynamics::spec::MAX_POINTS
                ),
            )
            .with_help(help_for("dynamics.points")));
        }
        spec.points = v as usize;
    }
    if let Some(m) = &sec.motor {
        spans.insert("dynamics.motor".to_string(), m.span());
        let mr = m.get_ref();
        let mut get = |name: &str, q: &Qty, dim: Dim| -> Result<f64, Error> {
            let field = format!("dynamics.motor.{name}");
            spans.insert(field.clone(), q.span());
            qty(task, &field, q, dim).map_err(|e| e.with_help(help_for(&field)))
        };
        let motor = Motor {
            synchronous_speed: get("synchronous_speed", &mr.synchronous_speed, Dim::AngularVelocity)?,
            nominal_speed: get("nominal_speed", &mr.nominal_speed, Dim::AngularVelocity)?,
            nominal_torque: get("nominal_torque", &mr.nominal_torque, Dim::Moment)?,
            ratio: match &mr.ratio {
                Some(q) => get("ratio", q, Dim::Ratio)?,
                None => 1.0,
            },
        };
        spec.driving = DrivingMoment::Motor(motor);
    }
    match sec.driving.as_ref().map(|d| (d.get_ref().as_str(), d.span())) {
        None => {}
        Some(("motor", sp)) => {
            spans.insert("dynamics.driving".to_string(), sp.clone());
            if sec.motor.is_none() {
                return Err(Error::at(
                    task,
                    sp,
                    "dynamics.driving",
                    "driving = \"motor\" needs a [dynamics.motor] table (synchronous_speed, nominal_speed, nominal_torque, ratio)",
                )
                .with_help(help_for("dynamics.motor")));
            }
        }
        Some(("constant", sp)) => {
            spans.insert("dynamics.driving".to_string(), sp.clone());
            if let Some(m) = &sec.motor {
                return Err(Error::at(
                    task,
                    m.span(),
                    "dynamics.motor",
                    "a motor is given but driving = \"constant\"; say driving = \"motor\" or remove [dynamics.motor]",
                )
                .with_help(help_for("dynamics.driving")));
            }
        }
        Some(("engine", sp)) => {
            spans.insert("dynamics.driving".to_string(), sp.clone());
            if let Some(m) = &sec.motor {
                return Err(Error::at(
                    task,
                    m.span(),
                    "dynamics.motor",
                    "an engine drives itself (its gas forces are the driving loads); remove [dynamics.motor] or say driving = \"motor\"",
                )
                .with_help(help_for("dynamics.driving")));
            }
            spec.driving = DrivingMoment::Engine;
        }
        Some((other, sp)) => {
            return Err(Error::at(task, sp, "dynamics.driving", format!("unknown driving moment `{other}`"))
                .with_help(help_for("dynamics.driving")));
        }
    }
    if let Some(i) = &sec.inertia {
        spans.insert("dynamics.inertia".to_string(), i.span());
        let ir = i.get_ref();
        for (name, q, slot) in [
            ("crank_shaft", &ir.crank_shaft, &mut spec.inertia_crank_shaft),
            ("motor_shaft", &ir.motor_shaft, &mut spec.inertia_motor_shaft),
        ] {
            if let Some(q) = q {
                let field = format!("dynamics.inertia.{name}");
                spans.insert(field.clone(), q.span());
                *slot = qty(task, &field, q, Dim::Inertia).map_err(|e| e.with_help(help_for(&field)))?;
            }
        }
        if let Some(q) = &ir.motor_speed {
            let field = "dynamics.inertia.motor_speed";
            spans.insert(field.to_string(), q.span());
            if spec.motor().is_some() {
                return Err(Error::at(
                    task,
                    q.span(),
                    field,
                    "the motor's speed ratio is [dynamics.motor] ratio; motor_speed is for a drive of constant moment",
                )
                .with_help(help_for(field)));
            }
            spec.motor_speed = Some(qty(task, field, q, Dim::AngularVelocity).map_err(|e| e.with_help(help_for(field)))?);
        }
    }
    if let Some(fw) = &sec.flywheel {
        spans.insert("dynamics.flywheel".to_string(), fw.span());
        let fr = fw.get_ref();
        let mut fs = FlywheelSpec::default();
        if let Some(p) = &fr.place {
            spans.insert("dynamics.flywheel.place".to_string(), p.span());
            fs.place = match p.get_ref().as_str() {
                "crank" => FlywheelPlace::Crank,
                "motor" => FlywheelPlace::Motor,
                "shaft" => FlywheelPlace::Shaft,
                other => {
                    return Err(
                        Error::at(task, p.span(), "dynamics.flywheel.place", format!("unknown place `{other}`"))
                            .with_help(help_for("dynamics.flywheel.place")),
                    );
                }
            };
        }
        fs.density = match &fr.density {
            Some(q) => {
                spans.insert("dynamics.flywheel.density".to_string(), q.span());
                density(task, "dynamics.flywheel.density", q)?
            }
            None => STEEL_DENSITY,
        };
        let mut ratio = |name: &str, q: &Option<Qty>, default: f64| -> Result<f64, Error> {
            match q {
                Some(q) => {
                    let field = format!("dynamics.flywheel.{name}");
                    spans.insert(field.clone(), q.span());
                    qty(task, &field, q, Dim::Ratio).map_err(|e| e.with_help(help_for(&field)))
                }
                None => Ok(default),
            }
        };
        let width_ratio = ratio("width_ratio", &fr.width_ratio, 0.2)?;
        let mut thickness_ratio = ratio("thickness_ratio", &fr.thickness_ratio, 0.0)?;
        let inner_ratio = ratio("inner_ratio", &fr.inner_ratio, 0.0)?;
        fs.speed_ratio = ratio("speed_ratio", &fr.speed_ratio, 1.0)?;
        match (&fr.speed_ratio, fs.place) {
            (Some(q), p) if p != FlywheelPlace::Shaft => {
                return Err(Error::at(
                    task,
                    q.span(),
                    "dynamics.flywheel.speed_ratio",
                    "a speed ratio needs place = \"shaft\" (the crank's ratio is 1, the motor's comes from the motor)",
                )
                .with_help(help_for("dynamics.flywheel.speed_ratio")));
            }
            (None, FlywheelPlace::Shaft) => {
                return Err(Error::at(
                    task,
                    fr.place.as_ref().map_or(fw.span(), |p| p.span()),
                    "dynamics.flywheel.speed_ratio",
                    "a flywheel on another shaft needs that shaft's speed ratio ω_shaft/ω_crank",
                )
                .with_help(help_for("dynamics.flywheel.speed_ratio")));
            }
            _ => {}
        }
        if let Some(q) = &fr.inner_ratio {
            // a rim of outer diameter D₂ and inner D₁ = r·D₂: h = (D₂ − D₁)/2 = (1 − r)/2·D₂
            if fr.thickness_ratio.is_some() {
                return Err(Error::at(
                    task,
                    q.span(),
                    "dynamics.flywheel.inner_ratio",
                    "give the rim's inner_ratio (D₁/D₂) or its thickness_ratio (h/D), not both",
                )
                .with_help(help_for("dynamics.flywheel.inner_ratio")));
            }
            if !(1e-3..=0.998).contains(&inner_ratio) {
                return Err(Error::at(
                    task,
                    q.span(),
                    "dynamics.flywheel.inner_ratio",
                    format!("{inner_ratio:e} is outside the accepted range 0.001 … 0.998 (D₁ < D₂)"),
                )
                .with_help(help_for("dynamics.flywheel.inner_ratio")));
            }
            thickness_ratio = 0.5 * (1.0 - inner_ratio);
        }
        // the sizes go as (I/(ρ·ratio))^(1/5): a ratio or density near zero
        // gives a flywheel of infinite size, so each is held to a range that
        // covers every real flywheel (a thin ring to a drum; cork to tungsten)
        let within = |name: &str, span: Option<std::ops::Range<usize>>, v: f64, lo: f64, hi: f64, range: &str| match span {
            Some(span) if !(lo..=hi).contains(&v) => {
                let field = format!("dynamics.flywheel.{name}");
                Err(Error::at(task, span, &field, format!("{v:e} is outside the accepted range {range}")).with_help(help_for(&field)))
            }
            _ => Ok(()),
        };
        within(
            "width_ratio",
            fr.width_ratio.as_ref().map(|q| q.span()),
            width_ratio,
            1e-3,
            10.0,
            "0.001 … 10",
        )?;
        within(
            "thickness_ratio",
            fr.thickness_ratio.as_ref().map(|q| q.span()),
            thickness_ratio,
            1e-3,
            0.4999,
            "0.001 … 0.4999 (below 0.5: the rim is thinner than its radius)",
        )?;
        within(
            "density",
            fr.density.as_ref().map(|q| q.span()),
            fs.density,
            10.0,
            1e5,
            "10 … 100 000 kg/m³",
        )?;
        let shape = fr.shape.as_ref().map_or("disc", |s| s.get_ref().as_str());
        let shape_span = fr.shape.as_ref().map_or(fw.span(), |s| s.span());
        spans.insert("dynamics.flywheel.shape".to_string(), shape_span.clone());
        fs.shape = match shape {
            "disc" => {
                if let Some(t) = fr.thickness_ratio.as_ref().or(fr.inner_ratio.as_ref()) {
                    return Err(Error::at(
                        task,
                        t.span(),
                        "dynamics.flywheel.thickness_ratio",
                        "a disc has no rim thickness; say shape = \"rim\" or remove thickness_ratio and inner_ratio",
                    )
                    .with_help(help_for("dynamics.flywheel.shape")));
                }
                FlywheelShape::Disc { width_ratio }
            }
            "rim" => {
                if fr.thickness_ratio.is_none() && fr.inner_ratio.is_none() {
                    return Err(Error::at(
                        task,
                        shape_span,
                        "dynamics.flywheel.thickness_ratio",
                        "a rim needs its radial thickness h/D",
                    )
                    .with_help(help_for("dynamics.flywheel.thickness_ratio")));
                }
                FlywheelShape::Rim {
                    width_ratio,
                    thickness_ratio,
                }
            }
            other => {
                return Err(
                    Error::at(task, shape_span, "dynamics.flywheel.shape", format!("unknown shape `{other}`"))
                        .with_help(help_for("dynamics.flywheel.shape")),
                );
            }
        };
        spec.flywheel = fs;
    }
    let dt = DynamicsTask { spec, spans, section };
    // every field on its own, located
    if let Err(tmm_linkage::dynamics::DynamicsError::Spec { field, message }) = dt.spec.check() {
        return Err(Error::at(task, dt.span_of(&field), &field, message).with_help(help_for(&field)));
    }
    Ok(Some(dt))
}
