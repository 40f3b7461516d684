//! Reading `[dynamics]` with `motion = "single-stroke"`: the unsteady
//! single stroke of a machine driven by an induction motor by Kloss's
//! formula through a reducer (the textbook's П4 press), into the core's
//! [`StrokeSpec`] (docs/dynamics.md, "The unsteady single stroke").
//!
//! ```toml
//! [dynamics]
//! motion = "single-stroke"        # the default "steady" is the flywheel design
//! points = 360                    # intervals of the tables over the cycle
//! [dynamics.motor]                # Kloss: M = 2·M_K·S·S_K/(S² + S_K²)
//! synchronous_speed = "16.7 rev/s"
//! breakdown_speed = "12.3 rev/s"  # the critical speed, where the torque is largest
//! breakdown_torque = "5.24e3 N m"
//! ratio = 18.6                    # reducer: n_motor / n_crank
//! [dynamics.inertia]
//! crank_shaft = "140e3 kg m^2"    # I_I: flywheel, gear, clutch reduced to the crank
//! [dynamics.stroke]
//! start_speed = "synchronous"     # or a crank speed, "5 rad/s"
//! constant_torque = "breakdown"   # the second model's motor torque, or "5 kN m"
//! time_constant = "0 s"           # τ of the dynamic characteristic τ·Ṁ + M = M_st
//! design_angle = "120 deg"        # the design position, cycle angle
//! ```

use std::collections::BTreeMap;
use std::ops::Range;

use serde::Deserialize;
use tmm_geom::units::Dim;
use tmm_linkage::dynamics::{KlossMotor, StrokeSpec};
use tmm_linkage::forces::stroke::Working;

use crate::task::{Qty, RawQty, qty};
use crate::{Error, TaskSource};

type S<T> = toml::Spanned<T>;

/// The value of `motion` that selects the single stroke.
pub const SINGLE_STROKE: &str = "single-stroke";

#[derive(Deserialize)]
struct File {
    dynamics: Option<S<Sec>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Sec {
    motion: S<String>,
    points: Option<S<i64>>,
    driving: Option<S<String>>,
    motor: Option<S<MotorSec>>,
    inertia: Option<S<InertiaSec>>,
    stroke: Option<S<StrokeSec>>,
    delta: Option<Qty>,
    flywheel: Option<S<toml::Value>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct MotorSec {
    synchronous_speed: Qty,
    breakdown_speed: Option<Qty>,
    breakdown_torque: Option<Qty>,
    ratio: Option<Qty>,
    nominal_speed: Option<Qty>,
    nominal_torque: Option<Qty>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct InertiaSec {
    crank_shaft: Option<Qty>,
    motor_shaft: Option<Qty>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct StrokeSec {
    start_speed: Option<Qty>,
    constant_torque: Option<Qty>,
    time_constant: Option<Qty>,
    design_angle: Option<Qty>,
}

/// `[dynamics]` with `motion = "single-stroke"`, read and checked.
#[derive(Debug, Clone)]
pub struct StrokeTask {
    /// The specification for the core.
    pub spec: StrokeSpec,
    /// Spans of the fields by their full name.
    pub spans: BTreeMap<String, Range<usize>>,
    /// Span of the whole section.
    pub section: Range<usize>,
}

impl StrokeTask {
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

/// What would be valid for each field.
pub fn help_for(field: &str) -> &'static str {
    match field {
        "dynamics.motion" => {
            "motion = \"steady\" (the flywheel for δ, the default) or \"single-stroke\" (one cycle from a given speed, driven by a motor by Kloss's formula)"
        }
        "dynamics.points" => "points = 360 (intervals of the tables over the cycle, 12 … 36 000)",
        "dynamics.motor"
        | "dynamics.motor.synchronous_speed"
        | "dynamics.motor.breakdown_speed"
        | "dynamics.motor.breakdown_torque"
        | "dynamics.motor.ratio" => {
            "[dynamics.motor] synchronous_speed = \"16.7 rev/s\", breakdown_speed = \"12.3 rev/s\" (the critical speed, below the synchronous), breakdown_torque = \"5.24e3 N m\" (the largest torque), ratio = 18.6 (n_motor/n_crank)"
        }
        "dynamics.inertia" | "dynamics.inertia.crank_shaft" => {
            "[dynamics.inertia] crank_shaft = \"140e3 kg m^2\" (the constant inertia reduced to the crank: flywheel, gear, clutch; 0 … 1e12)"
        }
        "dynamics.stroke.start_speed" => {
            "start_speed = \"synchronous\" (the motor's synchronous speed seen at the crank, the default) or a crank speed such as \"5 rad/s\""
        }
        "dynamics.stroke.constant_torque" => {
            "constant_torque = \"breakdown\" (the motor's breakdown torque M_K, the default) or a torque on the motor shaft such as \"5 kN m\""
        }
        "dynamics.stroke.time_constant" => {
            "time_constant = \"0.02 s\" (τ of the dynamic characteristic τ·dM/dt + M = M_st; 0, the default, is the static characteristic; else 0.001 … 10 s)"
        }
        "dynamics.stroke.design_angle" => "design_angle = \"120 deg\" (the design position, a cycle angle from 0° to 360°)",
        "dynamics" => {
            "a larger constant inertia ([dynamics.inertia] crank_shaft), a motor of larger breakdown torque, a higher start speed or smaller loads carry the machine through the cycle"
        }
        _ => "see \"The unsteady single stroke\" in docs/dynamics.md",
    }
}

/// `true` when `[dynamics]` asks for the single stroke.
pub fn is_single_stroke(task: &TaskSource) -> Result<bool, Error> {
    #[derive(Deserialize)]
    struct Probe {
        dynamics: Option<toml::Table>,
    }
    let p: Probe = task.parse("dynamics")?;
    Ok(p.dynamics
        .and_then(|d| d.get("motion").and_then(|m| m.as_str().map(|s| s == SINGLE_STROKE)))
        .unwrap_or(false))
}

/// Read the section, with the working stroke of `[linkage]` (where the
/// cycle starts).
pub fn read(task: &TaskSource, working: Working) -> Result<StrokeTask, Error> {
    let f: File = task.parse("dynamics")?;
    let sec = f.dynamics.ok_or_else(|| Error::input(&task.name, "no [dynamics] section"))?;
    let section = sec.span();
    let sec = sec.into_inner();
    let mut spans = BTreeMap::new();
    spans.insert("dynamics.motion".to_string(), sec.motion.span());
    let refuse = |span: Range<usize>, field: &str, msg: &str| Err(Error::at(task, span, field, msg.to_string()).with_help(help_for(field)));
    if let Some(d) = &sec.delta {
        return refuse(
            d.span(),
            "dynamics.delta",
            "a single stroke has no steady cycle, so no coefficient of speed fluctuation δ: remove delta (or say motion = \"steady\" for the flywheel design)",
        );
    }
    if let Some(fw) = &sec.flywheel {
        return refuse(
            fw.span(),
            "dynamics.flywheel",
            "a single stroke sizes no flywheel: give its inertia with the constant inertia on the crank shaft, [dynamics.inertia] crank_shaft",
        );
    }
    if let Some(d) = &sec.driving
        && d.get_ref() != "motor"
    {
        return refuse(
            d.span(),
            "dynamics.driving",
            "a single stroke is driven by the motor of [dynamics.motor] (the constant-moment model is computed beside it): say driving = \"motor\" or leave it out",
        );
    }
    let Some(mo) = &sec.motor else {
        return refuse(
            section,
            "dynamics.motor",
            "a single stroke needs the motor: a [dynamics.motor] table with synchronous_speed, breakdown_speed, breakdown_torque and ratio",
        );
    };
    spans.insert("dynamics.motor".to_string(), mo.span());
    let mr = mo.get_ref();
    for (name, q) in [("nominal_speed", &mr.nominal_speed), ("nominal_torque", &mr.nominal_torque)] {
        if let Some(q) = q {
            let field = format!("dynamics.motor.{name}");
            return refuse(
                q.span(),
                &field,
                "the single stroke's motor is given by Kloss's formula: its breakdown_speed and breakdown_torque, not the nominal point of the linear characteristic",
            );
        }
    }
    let get = |name: &str, q: &Qty, dim: Dim, spans: &mut BTreeMap<String, Range<usize>>| -> Result<f64, Error> {
        let field = format!("dynamics.{name}");
        spans.insert(field.clone(), q.span());
        qty(task, &field, q, dim).map_err(|e| e.with_help(help_for(&field)))
    };
    let need = |q: &Option<Qty>, name: &str| -> Result<Qty, Error> {
        q.clone().ok_or_else(|| {
            let field = format!("dynamics.motor.{name}");
            Error::at(task, mo.span(), &field, format!("the motor's {name} is missing")).with_help(help_for(&field))
        })
    };
    let motor = KlossMotor {
        synchronous_speed: get("motor.synchronous_speed", &mr.synchronous_speed, Dim::AngularVelocity, &mut spans)?,
        breakdown_speed: get(
            "motor.breakdown_speed",
            &need(&mr.breakdown_speed, "breakdown_speed")?,
            Dim::AngularVelocity,
            &mut spans,
        )?,
        breakdown_torque: get(
            "motor.breakdown_torque",
            &need(&mr.breakdown_torque, "breakdown_torque")?,
            Dim::Moment,
            &mut spans,
        )?,
        ratio: match &mr.ratio {
            Some(q) => get("motor.ratio", q, Dim::Ratio, &mut spans)?,
            None => 1.0,
        },
    };
    let mut inertia = 0.0;
    if let Some(i) = &sec.inertia {
        spans.insert("dynamics.inertia".to_string(), i.span());
        if let Some(q) = &i.get_ref().motor_shaft {
            return refuse(
                q.span(),
                "dynamics.inertia.motor_shaft",
                "give the single stroke's constant inertia reduced to the crank, in crank_shaft (the rotor's J·u² included)",
            );
        }
        if let Some(q) = &i.get_ref().crank_shaft {
            inertia = get("inertia.crank_shaft", q, Dim::Inertia, &mut spans)?;
        }
    }
    let mut spec = StrokeSpec::new(motor, inertia);
    spec.working = working;
    if let Some(p) = &sec.points {
        spans.insert("dynamics.points".to_string(), p.span());
        let v = *p.get_ref();
        if !(12..=tmm_linkage::dynamics::single_stroke::MAX_STROKE_POINTS as i64).contains(&v) {
            return refuse(
                p.span(),
                "dynamics.points",
                &format!("the stroke's tables need 12 to 36 000 intervals over the cycle, not {v}"),
            );
        }
        spec.points = v as usize;
    }
    if let Some(st) = &sec.stroke {
        spans.insert("dynamics.stroke".to_string(), st.span());
        let s = st.get_ref();
        let word = |q: &Qty, w: &str| matches!(q.get_ref(), RawQty::Text(t) if t.trim() == w);
        if let Some(q) = &s.start_speed {
            if word(q, "synchronous") {
                spans.insert("dynamics.stroke.start_speed".to_string(), q.span());
            } else {
                spec.start_speed = get("stroke.start_speed", q, Dim::AngularVelocity, &mut spans)?;
            }
        }
        if let Some(q) = &s.constant_torque {
            if word(q, "breakdown") {
                spans.insert("dynamics.stroke.constant_torque".to_string(), q.span());
            } else {
                spec.constant_torque = get("stroke.constant_torque", q, Dim::Moment, &mut spans)?;
            }
        }
        if let Some(q) = &s.time_constant {
            spec.time_constant = get("stroke.time_constant", q, Dim::Time, &mut spans)?;
        }
        if let Some(q) = &s.design_angle {
            spec.design_angle = Some(get("stroke.design_angle", q, Dim::Angle, &mut spans)?);
        }
    }
    let t = StrokeTask { spec, spans, section };
    if let Err(tmm_linkage::dynamics::DynamicsError::Spec { field, message }) = t.spec.check() {
        return Err(Error::at(task, t.span_of(&field), &field, message).with_help(help_for(&field)));
    }
    Ok(t)
}
