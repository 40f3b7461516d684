//! Reading `[cylinder]`: the lever driven by an oscillating cylinder with
//! the piston's travel s as the coordinate (the textbook's П5), with located
//! errors.
//!
//! ```toml
//! [cylinder]
//! h_min = "50 mm"            # D to the piston at s = 0
//! h_max = "300 mm"           # … at the end, s_max = h_max − h_min
//! rod = "390 mm"             # l_шт, the piston C to the rod's end B
//! # the П1.5 synthesis (variant 1): the lever's turn, a pressure angle, Y_D
//! swing = "60 deg"
//! pressure_end = "50 deg"    # or pressure_start
//! frame_y = "0.05 m"
//! # … or the geometry given: frame = ["0.6 m", "0.05 m"], lever_length = "0.3 m",
//! # start_angle = "90 deg" (the lever's angle at s = 0, near)
//! rod_center = "195 mm"      # l_CS2, C to S2 (default rod/2)
//! switch = "0.18 m"          # s_c, where the control force starts to change
//! at = "0.15 m"              # the kinetostatics' position
//! points = 200               # intervals of the travel in the tables
//! gravity = "9.81 m/s^2"
//! [cylinder.load]            # the load at K on the lever
//! mass = "100 kg"
//! arm = "0.2 m"              # l_AK
//! angle = "150 deg"          # α, clockwise from AB
//! [cylinder.lever]           # link 1, centre of mass at A
//! mass = "10 kg"
//! inertia = "1 kg m^2"
//! [cylinder.piston]          # link 2, piston and rod, centre of mass S2
//! [cylinder.body]            # link 3, the cylinder, centre of mass at D
//! ```

use std::collections::BTreeMap;
use std::ops::Range;

use serde::Deserialize;
use tmm_geom::Vec2;
use tmm_geom::units::Dim;
use tmm_linkage::dynamics::DynamicsError;
use tmm_linkage::linear::{CylinderDrive, CylinderMasses};
use tmm_linkage::synthesis::SynthesisError;
use tmm_linkage::synthesis::cylinder::{CylinderRequest, PressureAt, synthesize};
use tmm_linkage::synthesis::result::Synthesis;

use crate::task::{Qty, qty};
use crate::{Error, TaskSource};

type S<T> = toml::Spanned<T>;

#[derive(Deserialize)]
struct File {
    cylinder: Option<S<Sec>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Sec {
    h_min: Option<Qty>,
    h_max: Option<Qty>,
    rod: Option<Qty>,
    swing: Option<Qty>,
    pressure_end: Option<Qty>,
    pressure_start: Option<Qty>,
    frame_y: Option<Qty>,
    frame: Option<S<Vec<Qty>>>,
    lever: Option<S<LinkSec>>,
    lever_length: Option<Qty>,
    start_angle: Option<Qty>,
    rod_center: Option<Qty>,
    switch: Option<Qty>,
    at: Option<Qty>,
    points: Option<S<i64>>,
    gravity: Option<Qty>,
    load: Option<S<LoadSec>>,
    piston: Option<S<LinkSec>>,
    body: Option<S<LinkSec>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LoadSec {
    mass: Option<Qty>,
    arm: Option<Qty>,
    angle: Option<Qty>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LinkSec {
    mass: Option<Qty>,
    inertia: Option<Qty>,
}

/// `[cylinder]`, read and checked.
#[derive(Debug, Clone)]
pub struct CylinderTask {
    /// The mechanism.
    pub drive: CylinderDrive,
    /// Its masses.
    pub masses: CylinderMasses,
    /// The synthesis (П1.5), when the geometry was synthesised.
    pub synthesis: Option<Synthesis>,
    /// The lever's turn β over the travel, rad (from the positions).
    pub swing: f64,
    /// s_c, m.
    pub switch: f64,
    /// The kinetostatics' position s, m.
    pub at: f64,
    /// Intervals of the travel.
    pub points: usize,
    /// Spans of the fields by their full name.
    pub spans: BTreeMap<String, Range<usize>>,
    /// Span of the whole section.
    pub section: Range<usize>,
}

impl CylinderTask {
    /// The span of a field, else of its nearest enclosing table, else of the
    /// section.
    pub fn span_of(&self, field: &str) -> Range<usize> {
        span_in(&self.spans, &self.section, field)
    }

    /// A core error as a located one.
    pub fn located(&self, task: &TaskSource, e: DynamicsError) -> Error {
        match e {
            DynamicsError::Spec { field, message } => {
                let f = if field == "cylinder" { "cylinder.h_max".to_string() } else { field };
                Error::at(task, self.span_of(&f), &f, message).with_help(help_for(&f))
            }
            other => Error::at(task, self.section.clone(), "cylinder", other.to_string()),
        }
    }
}

fn span_in(spans: &BTreeMap<String, Range<usize>>, section: &Range<usize>, field: &str) -> Range<usize> {
    let mut f = field;
    loop {
        if let Some(s) = spans.get(f) {
            return s.clone();
        }
        match f.rsplit_once('.') {
            Some((head, _)) => f = head,
            None => return section.clone(),
        }
    }
}

/// What would be valid for each field.
pub fn help_for(field: &str) -> &'static str {
    match field {
        "cylinder.h_min" | "cylinder.h_max" => {
            "h_min = \"50 mm\", h_max = \"300 mm\": the piston's distance from the cylinder's pivot D at the start and the end of the travel (h_max > h_min > 0), within the reach of the lever: |AD − l_AB| < h + rod < AD + l_AB"
        }
        "cylinder.rod" => "rod = \"390 mm\": the piston rod l_шт from the piston C to the lever's pin B (> 0)",
        "cylinder.swing" => "swing = \"60 deg\": the lever's turn β over the travel, 0° … 180° (for the synthesis)",
        "cylinder.pressure_end" | "cylinder.pressure_start" => {
            "pressure_end = \"50 deg\" (θк at the end of the travel) or pressure_start (θн at its start), within ±90°"
        }
        "cylinder.frame_y" => "frame_y = \"0.05 m\": the ordinate Y_D of the cylinder's pivot (the synthesis' free turn about A)",
        "cylinder.frame" | "cylinder.lever_length" | "cylinder.start_angle" => {
            "either the П1.5 synthesis (swing, pressure_end or pressure_start, frame_y) or the geometry: frame = [\"0.6 m\", \"0.05 m\"] (D), lever_length = \"0.3 m\" (l_AB), start_angle = \"90 deg\" (the lever's angle at s = 0, near)"
        }
        "cylinder.rod_center" => "rod_center = \"195 mm\": l_CS2, from the piston C towards B (default: half the rod)",
        "cylinder.switch" => {
            "switch = \"0.18 m\": s_c, where the control force leaves its level F_H for the holding force F_K, 0 < s_c ≤ s_max; a later switch lifts a load the earlier one cannot"
        }
        "cylinder.at" => "at = \"0.15 m\": the travel s of the kinetostatics, 0 ≤ s ≤ s_max",
        "cylinder.points" => "points = 200 (intervals of the travel in the tables, 10 … 100 000)",
        "cylinder.gravity" => "gravity = \"9.81 m/s^2\" (along −Y; 0 … 1000)",
        "cylinder.load" | "cylinder.load.mass" | "cylinder.load.arm" | "cylinder.load.angle" => {
            "[cylinder.load] mass = \"100 kg\", arm = \"0.2 m\" (l_AK), angle = \"150 deg\" (α, clockwise from AB)"
        }
        _ if field.starts_with("cylinder.lever") || field.starts_with("cylinder.piston") || field.starts_with("cylinder.body") => {
            "[cylinder.lever], [cylinder.piston], [cylinder.body]: mass = \"10 kg\", inertia = \"1 kg m^2\" (about the centre of mass; ≥ 0)"
        }
        _ => "see \"A linear generalized coordinate\" in docs/dynamics.md",
    }
}

/// Read `[cylinder]`; `None` when the task has none.
pub fn read(task: &TaskSource) -> Result<Option<CylinderTask>, Error> {
    let f: File = task.parse("cylinder")?;
    let Some(sec) = f.cylinder else { return Ok(None) };
    let section = sec.span();
    let sec = sec.into_inner();
    let spans: std::cell::RefCell<BTreeMap<String, Range<usize>>> = Default::default();
    let get = |name: &str, q: &Qty, dim: Dim| -> Result<f64, Error> {
        let field = format!("cylinder.{name}");
        spans.borrow_mut().insert(field.clone(), q.span());
        qty(task, &field, q, dim).map_err(|e| e.with_help(help_for(&field)))
    };
    let need = |q: &Option<Qty>, name: &str| -> Result<Qty, Error> {
        q.clone().ok_or_else(|| {
            let field = format!("cylinder.{name}");
            Error::at(task, section.clone(), &field, format!("{name} is missing")).with_help(help_for(&field))
        })
    };
    let h_min = get("h_min", &need(&sec.h_min, "h_min")?, Dim::Length)?;
    let h_max = get("h_max", &need(&sec.h_max, "h_max")?, Dim::Length)?;
    let rod = get("rod", &need(&sec.rod, "rod")?, Dim::Length)?;
    let rod_center = match &sec.rod_center {
        Some(q) => get("rod_center", q, Dim::Length)?,
        None => 0.5 * rod,
    };
    let gravity = match &sec.gravity {
        Some(q) => get("gravity", q, Dim::Acceleration)?,
        None => 9.81,
    };
    let mut masses = CylinderMasses {
        gravity,
        ..Default::default()
    };
    let (mut arm, mut angle) = (0.0, 0.0);
    if let Some(l) = &sec.load {
        let lr = l.get_ref();
        if let Some(q) = &lr.mass {
            masses.load_mass = get("load.mass", q, Dim::Mass)?;
        }
        if let Some(q) = &lr.arm {
            arm = get("load.arm", q, Dim::Length)?;
        }
        if let Some(q) = &lr.angle {
            angle = get("load.angle", q, Dim::Angle)?;
        }
    }
    for (name, l) in [("lever", &sec.lever), ("piston", &sec.piston), ("body", &sec.body)] {
        if let Some(l) = l {
            let lr = l.get_ref();
            let (m, i) = (
                match &lr.mass {
                    Some(q) => get(&format!("{name}.mass"), q, Dim::Mass)?,
                    None => 0.0,
                },
                match &lr.inertia {
                    Some(q) => get(&format!("{name}.inertia"), q, Dim::Inertia)?,
                    None => 0.0,
                },
            );
            if name == "lever" {
                (masses.lever_mass, masses.lever_inertia) = (m, i);
            } else if name == "piston" {
                (masses.piston_mass, masses.piston_inertia) = (m, i);
            } else {
                (masses.cylinder_mass, masses.cylinder_inertia) = (m, i);
            }
        }
    }
    // the geometry: synthesised (П1.5) or given
    let synthesis_given = sec.swing.is_some() || sec.pressure_end.is_some() || sec.pressure_start.is_some();
    let (d, lever, start, syn) = if synthesis_given {
        for (name, given) in [
            ("frame", sec.frame.as_ref().map(|f| f.span())),
            ("lever_length", sec.lever_length.as_ref().map(|l| l.span())),
        ] {
            if let Some(span) = given {
                let field = format!("cylinder.{name}");
                return Err(Error::at(task, span, &field, "the geometry is synthesised from swing and the pressure angle here: give either the synthesis' fields or frame, lever_length and start_angle").with_help(help_for(&field)));
            }
        }
        let swing = get("swing", &need(&sec.swing, "swing")?, Dim::Angle)?;
        let pressure = match (&sec.pressure_end, &sec.pressure_start) {
            (Some(q), None) => PressureAt::End(get("pressure_end", q, Dim::Angle)?),
            (None, Some(q)) => PressureAt::Start(get("pressure_start", q, Dim::Angle)?),
            (Some(_), Some(q)) => {
                return Err(Error::at(
                    task,
                    q.span(),
                    "cylinder.pressure_start",
                    "give one pressure angle: pressure_end or pressure_start",
                )
                .with_help(help_for("cylinder.pressure_start")));
            }
            (None, None) => {
                return Err(Error::at(
                    task,
                    section.clone(),
                    "cylinder.pressure_end",
                    "the synthesis needs a pressure angle: pressure_end or pressure_start",
                )
                .with_help(help_for("cylinder.pressure_end")));
            }
        };
        let frame_y = match &sec.frame_y {
            Some(q) => Some(get("frame_y", q, Dim::Length)?),
            None => None,
        };
        let req = CylinderRequest {
            h_min,
            h_max,
            rod,
            swing,
            pressure,
            frame_y,
            drive: Default::default(),
            limits: Default::default(),
        };
        let s = synthesize(&req).map_err(|e| {
            let (field, msg) = match &e {
                SynthesisError::Input { field, message } => (format!("cylinder.{field}"), message.clone()),
                SynthesisError::Infeasible { field, .. } => (format!("cylinder.{field}"), e.to_string()),
                other => ("cylinder".to_string(), other.to_string()),
            };
            let msg = msg
                .strip_prefix(&format!("{}: ", field.trim_start_matches("cylinder.")))
                .map(str::to_string)
                .unwrap_or(msg);
            Error::at(task, span_in(&spans.borrow(), &section, &field), &field, msg).with_help(help_for(&field))
        })?;
        let d = s.frame.iter().find(|(n, _)| n == "D").map_or(Vec2::ZERO, |f| f.1);
        let lever = s.length("OB").unwrap_or(0.0);
        let start = s.angles.iter().find(|(n, _)| n == "phi1").map_or(0.0, |a| a.1);
        (d, lever, start, Some(s))
    } else {
        let fr = sec.frame.as_ref().ok_or_else(|| {
            Error::at(
                task,
                section.clone(),
                "cylinder.frame",
                "the mechanism needs its geometry: the П1.5 synthesis (swing, pressure_end, frame_y) or frame, lever_length and start_angle",
            )
            .with_help(help_for("cylinder.frame"))
        })?;
        if fr.get_ref().len() != 2 {
            return Err(Error::at(
                task,
                fr.span(),
                "cylinder.frame",
                "the cylinder's pivot D is two coordinates, [x, y]",
            )
            .with_help(help_for("cylinder.frame")));
        }
        spans.borrow_mut().insert("cylinder.frame".into(), fr.span());
        let x = qty(task, "cylinder.frame", &fr.get_ref()[0], Dim::Length)?;
        let y = qty(task, "cylinder.frame", &fr.get_ref()[1], Dim::Length)?;
        let lever = get("lever_length", &need(&sec.lever_length, "lever_length")?, Dim::Length)?;
        let start = get("start_angle", &need(&sec.start_angle, "start_angle")?, Dim::Angle)?;
        (Vec2::new(x, y), lever, start, None)
    };
    let switch = get("switch", &need(&sec.switch, "switch")?, Dim::Length)?;
    let at_q = sec.at.clone();
    let at = match &at_q {
        Some(q) => Some(get("at", q, Dim::Length)?),
        None => None,
    };
    let points = match &sec.points {
        Some(p) => {
            spans.borrow_mut().insert("cylinder.points".into(), p.span());
            let v = *p.get_ref();
            let (lo, hi) = tmm_linkage::linear::motion::POINTS_RANGE;
            if !(lo as i64..=hi as i64).contains(&v) {
                return Err(Error::at(
                    task,
                    p.span(),
                    "cylinder.points",
                    format!("the travel is cut into {lo} … {hi} intervals, not {v}"),
                )
                .with_help(help_for("cylinder.points")));
            }
            v as usize
        }
        None => 200,
    };
    let locate = |e: DynamicsError| match e {
        DynamicsError::Spec { field, message } => {
            let f = if field == "cylinder" { "cylinder.h_max".to_string() } else { field };
            Error::at(task, span_in(&spans.borrow(), &section, &f), &f, message).with_help(help_for(&f))
        }
        other => Error::at(task, section.clone(), "cylinder", other.to_string()),
    };
    for (f, v) in [("cylinder.rod_center", rod_center), ("cylinder.load.arm", arm)] {
        if !(v.is_finite() && v >= 0.0) {
            return Err(locate(DynamicsError::spec(f, "must be zero or a positive length")));
        }
    }
    if !(0.0..=1000.0).contains(&gravity) {
        return Err(locate(DynamicsError::spec("cylinder.gravity", "g must lie within 0 … 1000 m/s²")));
    }
    let drive = CylinderDrive::new(d, lever, h_min, h_max, rod, start)
        .map_err(locate)?
        .with_rod_center(rod_center)
        .with_load(arm, angle);
    masses.check().map_err(locate)?;
    let smax = drive.travel();
    let at = at.unwrap_or(0.5 * smax);
    if !(0.0..=smax).contains(&at) {
        return Err(locate(DynamicsError::spec(
            "cylinder.at",
            format!(
                "the kinetostatics' position must lie within the travel, 0 … {} m",
                tmm_linkage::dynamics::error::show(smax)
            ),
        )));
    }
    let mut st = tmm_linkage::linear::CylinderState::default();
    drive.solve(0.0, &mut st).map_err(locate)?;
    let p0 = st.phi1;
    drive.solve(smax, &mut st).map_err(locate)?;
    let swing = tmm_geom::angle::wrap_pi(st.phi1 - p0);
    Ok(Some(CylinderTask {
        drive,
        masses,
        synthesis: syn,
        swing,
        switch,
        at,
        points,
        spans: spans.into_inner(),
        section,
    }))
}
