//! Reading a gear task: the `[gear]` section of a task file or the options of
//! `tmm gear pair` / `tmm gear contour`, both turned into one [`Job`], with
//! errors that name the field (or option), its place and what would be valid.

use std::ops::Range;

use serde::Deserialize;
use tmm_gears::choose::Criterion;
use tmm_gears::{BasicRack, GearError, Kind, Limits, PairSpec};
use tmm_geom::units::{self, Dim};

use crate::task::{Qty, RawQty};
use crate::{Error, TaskSource};

/// The task file as the gear section sees it.
#[derive(Debug, Deserialize)]
pub struct GearFile {
    /// The `[gear]` section, if any.
    pub gear: Option<toml::Spanned<GearSection>>,
}

/// The `[gear]` section.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GearSection {
    /// Pinion tooth number.
    pub z1: toml::Spanned<i64>,
    /// Wheel (or ring) tooth number.
    pub z2: toml::Spanned<i64>,
    /// Module, e.g. `"5 mm"`.
    pub module: Qty,
    /// Pinion shift coefficient.
    pub x1: Option<Qty>,
    /// Wheel shift coefficient.
    pub x2: Option<Qty>,
    /// Required centre distance instead of the shifts.
    pub aw: Option<Qty>,
    /// `equal-sliding`, `max-contact-ratio` or `balanced`.
    pub criterion: Option<toml::Spanned<String>>,
    /// Profile angle of the basic rack (default 20°).
    pub alpha: Option<Qty>,
    /// ha* (default 1).
    pub ha: Option<Qty>,
    /// c* (default 0.25).
    pub c: Option<Qty>,
    /// hl* (default 2).
    pub hl: Option<Qty>,
    /// `true` for an internal pair (wheel 2 a ring).
    pub internal: Option<toml::Spanned<bool>>,
    /// Least tip thickness as a fraction of m (default 0.25).
    pub sa_min: Option<Qty>,
    /// Least contact ratio (default 1.2).
    pub eps_min: Option<Qty>,
}

/// The inputs as written, from either source.
#[derive(Debug, Clone, Default)]
pub struct Raw {
    /// z1.
    pub z1: Option<i64>,
    /// z2.
    pub z2: Option<i64>,
    /// Module.
    pub module: Option<RawQty>,
    /// x1.
    pub x1: Option<RawQty>,
    /// x2.
    pub x2: Option<RawQty>,
    /// Centre distance.
    pub aw: Option<RawQty>,
    /// Criterion name.
    pub criterion: Option<String>,
    /// α.
    pub alpha: Option<RawQty>,
    /// ha*.
    pub ha: Option<RawQty>,
    /// c*.
    pub c: Option<RawQty>,
    /// hl*.
    pub hl: Option<RawQty>,
    /// Internal pair.
    pub internal: bool,
    /// sa_min / m.
    pub sa_min: Option<RawQty>,
    /// εmin.
    pub eps_min: Option<RawQty>,
}

/// A field of the gear task, for locating errors.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Field {
    /// The section or command as a whole.
    Section,
    /// `z1`.
    Z1,
    /// `z2`.
    Z2,
    /// `module`.
    Module,
    /// `x1`.
    X1,
    /// `x2`.
    X2,
    /// `aw`.
    Aw,
    /// `criterion`.
    Criterion,
    /// `alpha`.
    Alpha,
    /// `ha`.
    Ha,
    /// `c`.
    C,
    /// `hl`.
    Hl,
    /// `internal`.
    Internal,
    /// `sa_min`.
    SaMin,
    /// `eps_min`.
    EpsMin,
}

const FIELDS: usize = 15;

impl Field {
    fn index(self) -> usize {
        self as usize
    }

    /// The key in the task file.
    pub fn key(self) -> &'static str {
        match self {
            Field::Section => "gear",
            Field::Z1 => "z1",
            Field::Z2 => "z2",
            Field::Module => "module",
            Field::X1 => "x1",
            Field::X2 => "x2",
            Field::Aw => "aw",
            Field::Criterion => "criterion",
            Field::Alpha => "alpha",
            Field::Ha => "ha",
            Field::C => "c",
            Field::Hl => "hl",
            Field::Internal => "internal",
            Field::SaMin => "sa_min",
            Field::EpsMin => "eps_min",
        }
    }

    /// The command-line option.
    pub fn option(self) -> String {
        match self {
            Field::Section => "tmm gear".into(),
            Field::SaMin => "--sa-min".into(),
            Field::EpsMin => "--eps-min".into(),
            f => format!("--{}", f.key()),
        }
    }
}

/// Where the inputs came from, to locate errors.
pub enum Origin<'a> {
    /// Command-line options.
    Cli,
    /// A task file with the spans of the fields it has.
    Task {
        /// The file.
        task: &'a TaskSource,
        /// Span of each field (by [`Field`] index).
        spans: Box<[Option<Range<usize>>; FIELDS]>,
    },
}

impl Origin<'_> {
    /// A bad-input error about a field.
    pub fn err(&self, f: Field, msg: impl std::fmt::Display) -> Error {
        match self {
            Origin::Cli => Error::input(&f.option(), msg),
            Origin::Task { task, spans } => {
                let span = spans[f.index()]
                    .clone()
                    .or_else(|| spans[Field::Section.index()].clone())
                    .unwrap_or(0..0);
                Error::at(task, span, &format!("gear.{}", f.key()), msg)
            }
        }
    }
}

/// How the shifts are given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Mode {
    /// x1, x2 given.
    Shifts,
    /// A centre distance given: find the sum, then split it.
    CentreDistance(f64),
    /// Neither: choose both.
    Choose,
}

/// A validated gear job.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Job {
    /// The pair (x1, x2 are placeholders unless `mode` is [`Mode::Shifts`]).
    pub spec: PairSpec,
    /// How the shifts are given.
    pub mode: Mode,
    /// The criterion named by the user.
    pub criterion: Option<Criterion>,
    /// Check limits.
    pub limits: Limits,
}

impl Raw {
    /// Read the `[gear]` section of a task file; `None` when it has none.
    pub fn from_task(task: &TaskSource) -> Result<Option<(Raw, Origin<'_>)>, Error> {
        let file: GearFile = task.parse("gear")?;
        let Some(sec) = file.gear else { return Ok(None) };
        let section_span = sec.span();
        let s = sec.into_inner();
        let mut spans: Box<[Option<Range<usize>>; FIELDS]> = Box::new(std::array::from_fn(|_| None));
        spans[Field::Section.index()] = Some(section_span);
        let mut put = |f: Field, sp: Option<Range<usize>>| spans[f.index()] = sp;
        put(Field::Z1, Some(s.z1.span()));
        put(Field::Z2, Some(s.z2.span()));
        put(Field::Module, Some(s.module.span()));
        let q = |x: &Option<Qty>| x.as_ref().map(|v| v.span());
        put(Field::X1, q(&s.x1));
        put(Field::X2, q(&s.x2));
        put(Field::Aw, q(&s.aw));
        put(Field::Criterion, s.criterion.as_ref().map(|v| v.span()));
        put(Field::Alpha, q(&s.alpha));
        put(Field::Ha, q(&s.ha));
        put(Field::C, q(&s.c));
        put(Field::Hl, q(&s.hl));
        put(Field::Internal, s.internal.as_ref().map(|v| v.span()));
        put(Field::SaMin, q(&s.sa_min));
        put(Field::EpsMin, q(&s.eps_min));
        let v = |x: Option<Qty>| x.map(|q| q.into_inner());
        let raw = Raw {
            z1: Some(*s.z1.get_ref()),
            z2: Some(*s.z2.get_ref()),
            module: Some(s.module.into_inner()),
            x1: v(s.x1),
            x2: v(s.x2),
            aw: v(s.aw),
            criterion: s.criterion.map(|c| c.into_inner()),
            alpha: v(s.alpha),
            ha: v(s.ha),
            c: v(s.c),
            hl: v(s.hl),
            internal: s.internal.is_some_and(|b| *b.get_ref()),
            sa_min: v(s.sa_min),
            eps_min: v(s.eps_min),
        };
        Ok(Some((raw, Origin::Task { task, spans })))
    }

    /// Validate and convert to a [`Job`]. `need_module`: a contour needs none (default 1 mm).
    pub fn job(&self, o: &Origin<'_>, need_module: bool) -> Result<Job, Error> {
        let q = |raw: &Option<RawQty>, f: Field, dim: Dim| -> Result<Option<f64>, Error> {
            match raw {
                None => Ok(None),
                Some(RawQty::Num(x)) => units::from_number(*x, dim).map(Some).map_err(|e| o.err(f, e)),
                Some(RawQty::Text(s)) => units::parse(s, dim).map(Some).map_err(|e| o.err(f, e)),
            }
        };
        let z = |v: Option<i64>, f: Field| -> Result<u32, Error> {
            let v = v.ok_or_else(|| {
                o.err(f, "is required")
                    .with_help(format!("give the tooth number, e.g. {} 17", f.option()))
            })?;
            // the profile, contour and sliding computations grow with z: 2000
            // teeth (a 2 m wheel of module 1) keeps a run within seconds
            if !(1..=2000).contains(&v) {
                return Err(o
                    .err(f, format!("a tooth number must be a whole number from 8 to 2000, got {v}"))
                    .with_help("tooth numbers are positive integers, e.g. 17"));
            }
            Ok(v as u32)
        };
        let z1 = z(self.z1, Field::Z1)?;
        let z2 = z(self.z2, Field::Z2)?;
        let m = match q(&self.module, Field::Module, Dim::Length)? {
            Some(m) => m,
            None if !need_module => 0.001,
            None => {
                return Err(o
                    .err(Field::Module, "is required")
                    .with_help("give the module with a unit, e.g. --module \"5 mm\""));
            }
        };
        if !(m.is_finite() && m > 0.0) {
            return Err(o
                .err(Field::Module, format!("the module must be a positive length, got {m} m"))
                .with_help("e.g. \"5 mm\" (GOST 9563-60 series: 1, 1.25, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10 … mm)"));
        }
        let d = BasicRack::default();
        let rack = BasicRack {
            alpha: q(&self.alpha, Field::Alpha, Dim::Angle)?.unwrap_or(d.alpha),
            ha: q(&self.ha, Field::Ha, Dim::Ratio)?.unwrap_or(d.ha),
            c: q(&self.c, Field::C, Dim::Ratio)?.unwrap_or(d.c),
            hl: q(&self.hl, Field::Hl, Dim::Ratio)?.unwrap_or(d.hl),
        };
        let x1 = q(&self.x1, Field::X1, Dim::Ratio)?;
        let x2 = q(&self.x2, Field::X2, Dim::Ratio)?;
        let aw = q(&self.aw, Field::Aw, Dim::Length)?;
        let mode = match (x1, x2, aw) {
            (Some(_), Some(_), Some(_)) => {
                return Err(o
                    .err(Field::Aw, "give either the shifts x1, x2 or the centre distance aw, not both")
                    .with_help("drop aw, or drop x1 and x2"));
            }
            (Some(_), Some(_), None) => Mode::Shifts,
            (Some(_), None, _) => {
                return Err(o
                    .err(Field::X2, "x1 is given but x2 is not")
                    .with_help("give both shifts, or neither to have them chosen"));
            }
            (None, Some(_), _) => {
                return Err(o
                    .err(Field::X1, "x2 is given but x1 is not")
                    .with_help("give both shifts, or neither to have them chosen"));
            }
            (None, None, Some(a)) => Mode::CentreDistance(a),
            (None, None, None) => Mode::Choose,
        };
        let criterion = match &self.criterion {
            None => None,
            Some(s) => Some(Criterion::parse(s).ok_or_else(|| {
                o.err(Field::Criterion, format!("unknown criterion \"{s}\""))
                    .with_help("use equal-sliding, max-contact-ratio or balanced")
            })?),
        };
        let dl = Limits::default();
        let limits = Limits {
            sa_min: q(&self.sa_min, Field::SaMin, Dim::Ratio)?.unwrap_or(dl.sa_min),
            eps_min: q(&self.eps_min, Field::EpsMin, Dim::Ratio)?.unwrap_or(dl.eps_min),
        };
        if !(limits.sa_min.is_finite() && (0.0..=1.0).contains(&limits.sa_min)) {
            return Err(o
                .err(
                    Field::SaMin,
                    format!("must be a fraction of the module in [0, 1], got {}", limits.sa_min),
                )
                .with_help("GOST 16532-70: 0.3 for through-hardened, 0.4 for case-hardened teeth"));
        }
        if !(limits.eps_min.is_finite() && (1.0..=3.0).contains(&limits.eps_min)) {
            return Err(o
                .err(Field::EpsMin, format!("must lie in [1, 3], got {}", limits.eps_min))
                .with_help("GOST 16532-70 asks εα ≥ 1.2 for spur pairs"));
        }
        let spec = PairSpec {
            z1,
            z2,
            m,
            x1: x1.unwrap_or(0.0),
            x2: x2.unwrap_or(0.0),
            rack,
            kind: if self.internal { Kind::Internal } else { Kind::External },
        };
        spec.validate().map_err(|e| gear_error(o, &e))?;
        Ok(Job {
            spec,
            mode,
            criterion,
            limits,
        })
    }
}

/// A core error as a located input error, naming the field it comes from.
pub fn gear_error(o: &Origin<'_>, e: &GearError) -> Error {
    let (f, help): (Field, String) = match e {
        GearError::TooFewTeeth { wheel, min, .. } => (
            if *wheel == 1 { Field::Z1 } else { Field::Z2 },
            format!("use at least {min} teeth (fewer cannot be cut by the rack without undercut or a pointed tip)"),
        ),
        GearError::Module(_) => (Field::Module, "give a positive module, e.g. \"5 mm\"".into()),
        GearError::Rack { param, .. } => (
            match *param {
                "ha" => Field::Ha,
                "c" => Field::C,
                "hl" => Field::Hl,
                _ => Field::Alpha,
            },
            "the default rack is α = 20°, ha* = 1, c* = 0.25, hl* = 2 (GOST 13755-81)".into(),
        ),
        GearError::Shift { wheel } => (
            if *wheel == 1 { Field::X1 } else { Field::X2 },
            "a shift is a plain number such as 0.3".into(),
        ),
        GearError::TipBelowRoot { wheel, .. } => (
            if *wheel == 2 { Field::X2 } else { Field::X1 },
            "raise the shifts or reduce their difference; see `tmm gear contour` for the allowed region".into(),
        ),
        GearError::TipInsideBase { wheel, .. } => (
            if *wheel == 2 { Field::X2 } else { Field::X1 },
            "raise the shift of that wheel".into(),
        ),
        GearError::ShiftSum { .. } => (Field::X1, "raise x1 + x2".into()),
        GearError::CentreDistance { min, .. } => (Field::Aw, format!("give aw above {:.4} mm", min * 1e3)),
        GearError::InternalAssembly(_) => (Field::Z2, "raise z2 − z1 (at least 8–10 for the 20° rack) or x2".into()),
        GearError::NoFeasibleSplit(_) => (
            Field::Criterion,
            "try another criterion, relax sa_min or eps_min, or change the tooth numbers".into(),
        ),
        GearError::NonFinite(_) => (Field::Section, "check the input values".into()),
    };
    o.err(f, e).with_help(help)
}
