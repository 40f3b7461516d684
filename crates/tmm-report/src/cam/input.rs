//! Reading a cam task: the `[cam]` section of a task file or the options of
//! `tmm cam`, both turned into one [`tmm_cams::design::CamTask`], with errors
//! that name the field (or option), its place and what would be valid.

use std::ops::Range;

use serde::Deserialize;
use tmm_cams::CamError;
use tmm_cams::design::{CamTask, FollowerSpec};
use tmm_cams::law::LAW_NAMES;
use tmm_cams::mechanism::Rotation;
use tmm_cams::program::Program;
use tmm_cams::spec::{self, Limits};
use tmm_geom::units::{self, Dim};

use crate::task::{Qty, RawQty};
use crate::{Error, TaskSource};

/// The task file as the cam section sees it (other sections are ignored here).
#[derive(Debug, Deserialize)]
pub struct CamFile {
    /// The `[cam]` section, if any.
    pub cam: Option<toml::Spanned<CamSection>>,
}

/// The `[cam]` section.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CamSection {
    /// `translating-roller`, `translating-flat`, `oscillating-roller`, `oscillating-flat`.
    pub follower: toml::Spanned<String>,
    /// Stroke h: a length, or an angle for an oscillating follower; may be
    /// left out when every rise and return in `phases` carries its own.
    pub stroke: Option<Qty>,
    /// Phase list, e.g. `"rise 108 const-accel(u=1/3); dwell 15; return 108 const-accel(u=1/3); dwell 129"`.
    pub phases: toml::Spanned<String>,
    /// Allowed pressure angles: `"rise 15, return 30"` or one value.
    pub max_pressure: Option<Qty>,
    /// Allowed transmission angles γ = 90° − ϑ: `"rise 75, return 60"`.
    pub min_transmission: Option<Qty>,
    /// Cam speed |ω| (default 1 rad/s).
    pub omega: Option<Qty>,
    /// Offset e of a translating follower, or `"auto"` (default).
    pub offset: Option<Qty>,
    /// Roller radius (default: the course's rule).
    pub roller: Option<Qty>,
    /// Smallest radius of curvature of the working profile.
    pub min_curvature: Option<Qty>,
    /// `ccw` (default) or `cw`.
    pub rotation: Option<toml::Spanned<String>>,
    /// Arm length of an oscillating follower.
    pub arm: Option<Qty>,
    /// Pivot distance of an oscillating follower.
    pub pivot: Option<Qty>,
    /// Margin added to the flat face's contact extremes (default 5 mm).
    pub face_margin: Option<Qty>,
    /// Profile points over one turn (default 720).
    pub points: Option<toml::Spanned<i64>>,
    /// A given base (prime) circle radius r0: analyse this cam instead of
    /// sizing the smallest one.
    pub r0: Option<Qty>,
    /// Also give the textbook's constructions beside the design (the tangent
    /// methods of a translating follower, the level lines of an oscillating
    /// one, the roller rules; appendix П6).
    pub book_methods: Option<toml::Spanned<bool>>,
}

/// The inputs of a cam task as written, from either source.
#[derive(Debug, Clone, Default)]
pub struct Raw {
    /// Follower kind.
    pub follower: Option<String>,
    /// Stroke.
    pub stroke: Option<RawQty>,
    /// Phase list.
    pub phases: Option<String>,
    /// Pressure limits.
    pub max_pressure: Option<RawQty>,
    /// Transmission limits.
    pub min_transmission: Option<RawQty>,
    /// Cam speed.
    pub omega: Option<RawQty>,
    /// Offset or `auto`.
    pub offset: Option<RawQty>,
    /// Roller radius.
    pub roller: Option<RawQty>,
    /// Smallest radius of curvature.
    pub min_curvature: Option<RawQty>,
    /// `ccw` / `cw`.
    pub rotation: Option<String>,
    /// Arm length.
    pub arm: Option<RawQty>,
    /// Pivot distance.
    pub pivot: Option<RawQty>,
    /// Face margin.
    pub face_margin: Option<RawQty>,
    /// Profile points.
    pub points: Option<i64>,
    /// A given base circle radius (analyse instead of size).
    pub r0: Option<RawQty>,
    /// The textbook's constructions beside the design.
    pub book_methods: bool,
}

/// A field of the cam task, for locating errors.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Field {
    /// The section (or the command) as a whole.
    Section,
    /// `follower`.
    Follower,
    /// `stroke`.
    Stroke,
    /// `phases`.
    Phases,
    /// `max_pressure`.
    MaxPressure,
    /// `min_transmission`.
    MinTransmission,
    /// `omega`.
    Omega,
    /// `offset`.
    Offset,
    /// `roller`.
    Roller,
    /// `min_curvature`.
    MinCurvature,
    /// `rotation`.
    Rotation,
    /// `arm`.
    Arm,
    /// `pivot`.
    Pivot,
    /// `face_margin`.
    FaceMargin,
    /// `points`.
    Points,
    /// `r0`.
    R0,
    /// `book_methods`.
    BookMethods,
}

impl Field {
    /// The task-file key.
    pub fn key(self) -> &'static str {
        match self {
            Field::Section => "cam",
            Field::Follower => "cam.follower",
            Field::Stroke => "cam.stroke",
            Field::Phases => "cam.phases",
            Field::MaxPressure => "cam.max_pressure",
            Field::MinTransmission => "cam.min_transmission",
            Field::Omega => "cam.omega",
            Field::Offset => "cam.offset",
            Field::Roller => "cam.roller",
            Field::MinCurvature => "cam.min_curvature",
            Field::Rotation => "cam.rotation",
            Field::Arm => "cam.arm",
            Field::Pivot => "cam.pivot",
            Field::FaceMargin => "cam.face_margin",
            Field::Points => "cam.points",
            Field::R0 => "cam.r0",
            Field::BookMethods => "cam.book_methods",
        }
    }
    /// The command-line option.
    pub fn option(self) -> &'static str {
        match self {
            Field::Section => "tmm cam",
            Field::Follower => "--follower",
            Field::Stroke => "--stroke",
            Field::Phases => "--phases",
            Field::MaxPressure => "--max-pressure",
            Field::MinTransmission => "--min-transmission",
            Field::Omega => "--omega",
            Field::Offset => "--offset",
            Field::Roller => "--roller",
            Field::MinCurvature => "--min-curvature",
            Field::Rotation => "--rotation",
            Field::Arm => "--arm",
            Field::Pivot => "--pivot",
            Field::FaceMargin => "--face-margin",
            Field::Points => "--points",
            Field::R0 => "--r0",
            Field::BookMethods => "--book-methods",
        }
    }
}

/// Makes a located error for a field.
pub type Locate<'a> = dyn Fn(Field, String) -> Error + 'a;

/// The follower kinds, for messages.
pub const FOLLOWERS: &str = "translating-roller, translating-flat, oscillating-roller, oscillating-flat";

impl CamSection {
    /// The same inputs as a [`Raw`].
    pub fn raw(&self) -> Raw {
        let q = |x: &Option<Qty>| x.as_ref().map(|v| v.get_ref().clone());
        Raw {
            follower: Some(self.follower.get_ref().clone()),
            stroke: q(&self.stroke),
            phases: Some(self.phases.get_ref().clone()),
            max_pressure: q(&self.max_pressure),
            min_transmission: q(&self.min_transmission),
            omega: q(&self.omega),
            offset: q(&self.offset),
            roller: q(&self.roller),
            min_curvature: q(&self.min_curvature),
            rotation: self.rotation.as_ref().map(|r| r.get_ref().clone()),
            arm: q(&self.arm),
            pivot: q(&self.pivot),
            face_margin: q(&self.face_margin),
            points: self.points.as_ref().map(|p| *p.get_ref()),
            r0: q(&self.r0),
            book_methods: self.book_methods.as_ref().is_some_and(|b| *b.get_ref()),
        }
    }

    /// Where a field is in the file (the section's span when it is absent).
    pub fn span(&self, f: Field, section: Range<usize>) -> Range<usize> {
        let q = |x: &Option<Qty>| x.as_ref().map(|v| v.span());
        let s = match f {
            Field::Section => None,
            Field::Follower => Some(self.follower.span()),
            Field::Stroke => q(&self.stroke),
            Field::Phases => Some(self.phases.span()),
            Field::MaxPressure => q(&self.max_pressure),
            Field::MinTransmission => q(&self.min_transmission),
            Field::Omega => q(&self.omega),
            Field::Offset => q(&self.offset),
            Field::Roller => q(&self.roller),
            Field::MinCurvature => q(&self.min_curvature),
            Field::Rotation => self.rotation.as_ref().map(|r| r.span()),
            Field::Arm => q(&self.arm),
            Field::Pivot => q(&self.pivot),
            Field::FaceMargin => q(&self.face_margin),
            Field::Points => self.points.as_ref().map(|p| p.span()),
            Field::R0 => q(&self.r0),
            Field::BookMethods => self.book_methods.as_ref().map(|b| b.span()),
        };
        s.unwrap_or(section)
    }
}

/// Read the `[cam]` section of a task file: `None` when there is none.
pub fn read_section(task: &TaskSource) -> Result<Option<(CamSection, Range<usize>)>, Error> {
    let f: CamFile = task.parse("cam")?;
    Ok(f.cam.map(|s| {
        let span = s.span();
        (s.into_inner(), span)
    }))
}

/// Located errors for a task-file section.
pub fn file_locator<'a>(task: &'a TaskSource, sec: &'a CamSection, span: Range<usize>) -> impl Fn(Field, String) -> Error + 'a {
    move |f: Field, msg: String| Error::at(task, sec.span(f, span.clone()), f.key(), msg)
}

/// Errors naming a command-line option.
pub fn cli_locator(f: Field, msg: String) -> Error {
    Error::input(f.option(), msg)
}

fn quantity(raw: &Option<RawQty>, dim: Dim, f: Field, loc: &Locate<'_>) -> Result<Option<f64>, Error> {
    match raw {
        None => Ok(None),
        Some(RawQty::Num(x)) => units::from_number(*x, dim).map(Some).map_err(|e| loc(f, e.to_string())),
        Some(RawQty::Text(t)) => units::parse(t, dim).map(Some).map_err(|e| loc(f, e.to_string())),
    }
}

/// A length of the cam mechanism (the stroke, offset, roller, arm, pivot
/// distance), m: |x| ≤ [`tmm_linkage::limits::MAX_LENGTH`], the linkage's
/// limit, for the same reason — every tolerance is relative to the size, and
/// beyond it squares of lengths and the curvature 1/ρ leave the range of
/// doubles (a stroke of 1e12 m gives a curvature that underflows to 0).
fn within_size(x: f64, f: Field, loc: &Locate<'_>) -> Result<(), Error> {
    let max = tmm_linkage::limits::MAX_LENGTH;
    if x.abs() <= max {
        return Ok(());
    }
    Err(loc(f, format!("{x:e} m is outside the accepted range −1e4 m … 1e4 m"))
        .with_help("a cam mechanism up to 10 km across; give the value with its unit, e.g. \"13 mm\""))
}

fn limits_of(raw: &RawQty, transmission: bool, f: Field, loc: &Locate<'_>) -> Result<Limits, Error> {
    let r = match raw {
        RawQty::Num(x) => spec::parse_limits(&format!("{x}"), transmission),
        RawQty::Text(t) => spec::parse_limits(t, transmission),
    };
    r.map_err(|e| {
        let what = if transmission { "transmission" } else { "pressure" };
        let msg = match e {
            CamError::PressureLimit { phase, deg } if transmission => {
                format!(
                    "the allowed transmission angle on the {phase} must lie strictly between 0° and 90°, got {:.3}°",
                    90.0 - deg
                )
            }
            e => e.to_string(),
        };
        let example = if transmission { "rise 75, return 60" } else { "rise 15, return 30" };
        loc(f, msg).with_help(format!(
            "write the allowed {what} angles as \"{example}\" or one value for both, in degrees below 90"
        ))
    })
}

/// The given base circle radius r0 (`r0`), when the cam is to be analysed
/// rather than sized.
pub fn given_r0(raw: &Raw, loc: &Locate<'_>) -> Result<Option<f64>, Error> {
    let r0 = quantity(&raw.r0, Dim::Length, Field::R0, loc)?;
    if let Some(r) = r0 {
        if !(r.is_finite() && r > 0.0 && r <= 10.0) {
            return Err(loc(Field::R0, format!("the base circle radius must lie in (0, 10 m], got {r} m"))
                .with_help("a length such as \"40 mm\" or \"2 in\""));
        }
    }
    Ok(r0)
}

/// Build the cam task from the inputs; every error is located by `loc`.
pub fn build(raw: &Raw, loc: &Locate<'_>) -> Result<CamTask, Error> {
    let follower_name = raw
        .follower
        .as_deref()
        .ok_or_else(|| loc(Field::Follower, "the follower kind is missing".into()).with_help(format!("one of {FOLLOWERS}")))?;
    // The kind first: every later field (the stroke's unit above all) is read
    // according to it, so a misspelt kind must be named, not a valid stroke.
    const KINDS: [&str; 6] = [
        "translating-roller",
        "knife-edge",
        "translating-knife",
        "translating-flat",
        "oscillating-roller",
        "oscillating-flat",
    ];
    if !KINDS.contains(&follower_name) {
        return Err(loc(Field::Follower, format!("`{follower_name}` is not a follower kind")).with_help(format!("one of {FOLLOWERS}")));
    }
    let oscillating = follower_name.starts_with("oscillating");
    let stroke_dim = if oscillating { Dim::Angle } else { Dim::Length };
    let stroke = match quantity(&raw.stroke, stroke_dim, Field::Stroke, loc) {
        Ok(s) => s,
        // an oscillating follower's stroke given as the arc its roller
        // centre travels (the textbook's П6.5: φ₂ = S/l_T): the angle h/l
        Err(e) if oscillating => match &raw.stroke {
            Some(RawQty::Text(t)) if units::parse(t, Dim::Length).is_ok() => {
                let arc = units::parse(t, Dim::Length).map_err(|e| loc(Field::Stroke, e.to_string()))?;
                let arm = quantity(&raw.arm, Dim::Length, Field::Arm, loc)?.ok_or_else(|| {
                    loc(
                        Field::Stroke,
                        format!("the stroke {t} is an arc length: the arm length is needed to turn it into the swing angle"),
                    )
                    .with_help("give arm = \"150 mm\", or the stroke as an angle such as \"20 deg\"")
                })?;
                if !(tmm_cams::positive(arc) && tmm_cams::positive(arm)) {
                    return Err(loc(Field::Stroke, format!("the arc {t} and the arm must be positive lengths"))
                        .with_help("e.g. stroke = \"80 mm\" with arm = \"150 mm\""));
                }
                Some(arc / arm)
            }
            _ => return Err(e),
        },
        Err(e) => return Err(e),
    };
    let phases_text = raw
        .phases
        .as_deref()
        .ok_or_else(|| loc(Field::Phases, "the phase list is missing".into()).with_help(PHASES_HELP))?;
    let phases = spec::parse_phases(phases_text).map_err(|e| cam_error(e, loc))?;
    let program = match stroke {
        Some(h) => Program::new(h, phases),
        None => Program::from_phases(phases),
    }
    .map_err(|e| cam_error(e, loc))?;
    if !oscillating {
        let f = if stroke.is_some() { Field::Stroke } else { Field::Phases };
        within_size(program.stroke(), f, loc)?;
    }
    let len = |r: &Option<RawQty>, f: Field| -> Result<Option<f64>, Error> {
        let x = quantity(r, Dim::Length, f, loc)?;
        if let Some(x) = x {
            within_size(x, f, loc)?;
        }
        Ok(x)
    };
    let offset = match &raw.offset {
        Some(RawQty::Text(t)) if t.trim().eq_ignore_ascii_case("auto") => None,
        r => len(r, Field::Offset)?,
    };
    let roller = len(&raw.roller, Field::Roller)?;
    let arm = len(&raw.arm, Field::Arm)?;
    let pivot = len(&raw.pivot, Field::Pivot)?;
    let min_curvature = len(&raw.min_curvature, Field::MinCurvature)?;
    let face_margin = len(&raw.face_margin, Field::FaceMargin)?.unwrap_or(0.005);
    let omega = quantity(&raw.omega, Dim::AngularVelocity, Field::Omega, loc)?.unwrap_or(1.0);
    if !tmm_cams::positive(omega) {
        return Err(loc(Field::Omega, format!("the cam speed must be positive, got {omega} rad/s"))
            .with_help("e.g. \"200 rad/s\" or \"1910 rpm\"; the sense of rotation is --rotation"));
    }
    let rotation = match raw.rotation.as_deref().map(|s| s.trim().to_ascii_lowercase()) {
        None => Rotation::Ccw,
        Some(s) if s == "ccw" || s == "counter-clockwise" || s == "counterclockwise" => Rotation::Ccw,
        Some(s) if s == "cw" || s == "clockwise" => Rotation::Cw,
        Some(s) => {
            return Err(
                loc(Field::Rotation, format!("`{s}` is not a sense of rotation")).with_help("ccw (counter-clockwise, the default) or cw")
            );
        }
    };
    let points = match raw.points {
        None => 720,
        Some(n) if (16..=100_000).contains(&n) => n as usize,
        Some(n) => return Err(loc(Field::Points, format!("{n} profile points")).with_help("between 16 and 100000 (0.0036° apart)")),
    };
    let not_for = |f: Field, present: bool| -> Result<(), Error> {
        if present {
            Err(loc(f, format!("does not apply to a {follower_name} follower")).with_help("remove it"))
        } else {
            Ok(())
        }
    };
    let need_arm = |f: Option<f64>, field: Field| {
        f.ok_or_else(|| {
            loc(field, format!("a {follower_name} follower needs it")).with_help(if field == Field::Arm {
                "the arm length, e.g. \"100 mm\""
            } else {
                "the pivot distance OA, e.g. \"120 mm\""
            })
        })
    };
    let follower = match follower_name {
        "translating-roller" | "knife-edge" | "translating-knife" => {
            not_for(Field::Arm, arm.is_some())?;
            not_for(Field::Pivot, pivot.is_some())?;
            let roller = if follower_name == "translating-roller" { roller } else { Some(0.0) };
            FollowerSpec::TranslatingRoller { offset, roller }
        }
        "translating-flat" => {
            not_for(Field::Roller, roller.is_some())?;
            not_for(Field::Arm, arm.is_some())?;
            not_for(Field::Pivot, pivot.is_some())?;
            FollowerSpec::TranslatingFlat {
                offset: offset.unwrap_or(0.0),
            }
        }
        "oscillating-roller" => {
            not_for(Field::Offset, offset.is_some())?;
            FollowerSpec::OscillatingRoller {
                arm: need_arm(arm, Field::Arm)?,
                pivot,
                roller,
            }
        }
        "oscillating-flat" => {
            not_for(Field::Offset, offset.is_some())?;
            not_for(Field::Roller, roller.is_some())?;
            not_for(Field::Arm, arm.is_some())?;
            FollowerSpec::OscillatingFlat {
                pivot: need_arm(pivot, Field::Pivot)?,
            }
        }
        other => return Err(loc(Field::Follower, format!("`{other}` is not a follower kind")).with_help(format!("one of {FOLLOWERS}"))),
    };
    let flat = matches!(
        follower,
        FollowerSpec::TranslatingFlat { .. } | FollowerSpec::OscillatingFlat { .. }
    );
    let limits = match (&raw.max_pressure, &raw.min_transmission) {
        (Some(_), Some(_)) => {
            return Err(loc(
                Field::MinTransmission,
                "give either the pressure limit or the transmission limit, not both".into(),
            )
            .with_help("γ = 90° − ϑ: they are the same limit"));
        }
        (Some(p), None) => limits_of(p, false, Field::MaxPressure, loc)?,
        (None, Some(t)) => limits_of(t, true, Field::MinTransmission, loc)?,
        // a flat face, or a given cam that is analysed, not sized: the
        // pressure angles are results; the limit only bounds them loosely
        (None, None) if flat || raw.r0.is_some() => Limits {
            rise: 89f64.to_radians(),
            ret: 89f64.to_radians(),
        },
        (None, None) => {
            return Err(loc(Field::MaxPressure, "a roller follower needs the allowed pressure angles".into())
                .with_help("e.g. max_pressure = \"rise 30, return 45\" (--max-pressure) or min_transmission = \"rise 75, return 60\" (--min-transmission)"));
        }
    };
    Ok(CamTask {
        program,
        follower,
        rotation,
        limits,
        min_curvature,
        face_margin,
        omega,
        points,
    })
}

/// Help for the phase list.
pub const PHASES_HELP: &str = "phases separated by `;`, each KIND ANGLE [LAW] with KIND rise, dwell or return, starting at cam angle 0 and summing to 360°, e.g. \"rise 108 const-accel(u=1/3); dwell 15; return 108 const-accel(u=1/3); dwell 129\"";

/// A core error as a located input error with help.
pub fn cam_error(e: CamError, loc: &Locate<'_>) -> Error {
    let msg = e.to_string();
    match &e {
        CamError::Phase { .. } | CamError::Sequence(_) => loc(Field::Phases, msg).with_help(PHASES_HELP),
        CamError::UnknownLaw { .. } | CamError::LawParameter { .. } => {
            loc(Field::Phases, msg).with_help(format!("the laws are {LAW_NAMES}"))
        }
        CamError::PhaseSum { sum_deg } => {
            let gap = 360.0 - sum_deg;
            loc(Field::Phases, msg).with_help(if gap > 0.0 {
                format!("add {gap:.4}° somewhere, e.g. a final `dwell {gap:.4}`")
            } else {
                format!("remove {:.4}° from the phases", -gap)
            })
        }
        CamError::Stroke(_) => loc(Field::Stroke, msg)
            .with_help("a positive length such as \"13 mm\" (an angle such as \"20 deg\" for an oscillating follower)"),
        CamError::PressureLimit { .. } | CamError::Limits { .. } => loc(Field::MaxPressure, msg).with_help("e.g. \"rise 30, return 45\""),
        CamError::Dimension { field, .. } => {
            let f = match *field {
                "roller" => Field::Roller,
                "arm" => Field::Arm,
                "pivot" => Field::Pivot,
                "offset" => Field::Offset,
                "stroke" => Field::Stroke,
                "omega" => Field::Omega,
                "min-curvature" => Field::MinCurvature,
                "face-margin" => Field::FaceMargin,
                "points" => Field::Points,
                _ => Field::Section,
            };
            loc(f, msg)
        }
        CamError::RollerTooLarge { allowed_mm, .. } => loc(Field::Roller, msg).with_help(format!(
            "take a roller radius below {allowed_mm:.3} mm, or omit it to get the course's rule"
        )),
        CamError::Infeasible(_) => loc(Field::Section, msg),
    }
}
