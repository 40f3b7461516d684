//! The `[synthesis]` section of a task file and the options of `tmm synth`,
//! read into a [`Request`] of the core (задача синтеза). Both come as named
//! fields (`k = 1.28` in the file, `--k 1.28` on the command line), so one
//! reader serves both and every error names the field where the user wrote
//! it: `task.toml:4:7: synthesis.swing: …` or `--swing: …`.
//!
//! ```toml
//! [synthesis]
//! kind = "crank-rocker"
//! k = 1.28
//! swing = "60 deg"
//! rocker = "245 mm"
//! crank = "100 mm"          # or frame = "350 mm", frame_angle = "90 deg", optimum = true
//! speed = "900 rpm"         # the input speed of the generated [linkage]
//! direction = "ccw"
//! ```

use std::cell::RefCell;
use std::collections::{BTreeMap, BTreeSet};
use std::ops::Range;

use serde::Deserialize;
use tmm_geom::Vec2;
use tmm_geom::units::{self, Dim};
use tmm_linkage::synthesis::crank_rocker::{CrankRockerRequest, RockerCondition};
use tmm_linkage::synthesis::crank_slider::{CrankSliderRequest, SliderCondition, TwoPositionsRequest};
use tmm_linkage::synthesis::cylinder::{CylinderRequest, PressureAt};
use tmm_linkage::synthesis::function_gen::FunctionRequest;
use tmm_linkage::synthesis::knee_bell_crank::BellKneeRequest;
use tmm_linkage::synthesis::knee_press::{KneePivot, KneeRequest};
use tmm_linkage::synthesis::pivot::PivotCondition;
use tmm_linkage::synthesis::rocker_extremes::{Abscissa, ExtremesRequest};
use tmm_linkage::synthesis::shaper::ShaperRequest;
use tmm_linkage::synthesis::six_bar::{InversionRequest, PressureRequest};
use tmm_linkage::synthesis::slotted::{Coupler, Lever, SlottedRequest};
use tmm_linkage::synthesis::three_positions::ThreePositionsRequest;
use tmm_linkage::synthesis::{Drive, Limits, Request, Rotation};

use crate::{Error, TaskSource};

/// The kinds of `[synthesis]` / `tmm synth KIND`, with what each solves.
pub const KINDS: &[(&str, &str)] = &[
    ("crank-slider", "crank-slider by the stroke and K (seed 000 § 1.2)"),
    (
        "crank-slider-positions",
        "crank-slider by two crank positions and the travel (seed 000 § 1.2.2)",
    ),
    ("crank-rocker", "crank-rocker four-bar by K, rocker and swing (seed 002 ex. 1)"),
    (
        "function-generation",
        "four-bar through given crank and rocker positions (Freudenstein)",
    ),
    ("slotted-lever", "slotted-lever shaper (seed 002 ex. 3)"),
    ("knee-press", "crank-knee press (seed 002 ex. 2)"),
    ("six-bar-inversion", "six-bar by kinematic inversion (seed 002 ex. 4)"),
    ("six-bar-pressure", "six-bar by the pressure angle (seed 003)"),
    (
        "rocker-extremes",
        "crank-rocker by the rocker's extreme positions, its pivot D given (textbook П1.2)",
    ),
    (
        "rocker-extremes-k",
        "crank-rocker by the rocker's extreme positions and K, the abscissa of D found (textbook П1.3)",
    ),
    (
        "three-positions",
        "four-bar through three positions, the rocker's pivot D and length given (textbook П1.4)",
    ),
    (
        "knee-press-bell-crank",
        "crank-knee press with a bell-crank rocker B–C–D (seed 002 ex. 2 read literally)",
    ),
    (
        "oscillating-cylinder",
        "lever driven by an oscillating cylinder by its stroke and a pressure angle (textbook П1.5)",
    ),
    (
        "shaper",
        "shaper: crank, coupler, rocker C–B–D and the ram driven through a slider in its slot, by H, K, λ, l_BC and l_OC (textbook П3)",
    ),
];

/// A field's value as written (a number, a text with a unit, a flag, a list).
#[derive(Debug, Clone, Deserialize, PartialEq)]
#[serde(untagged)]
pub enum RawField {
    /// `true` / `false`.
    Flag(bool),
    /// A plain number: SI, degrees for an angle.
    Num(f64),
    /// A number with a unit, or a word.
    Text(String),
    /// A list (positions, coordinates).
    List(Vec<RawField>),
}

/// Where a field was written.
#[derive(Debug, Clone, PartialEq)]
pub enum Place {
    /// In the task file, at this span.
    File(Range<usize>),
    /// On the command line.
    Option,
}

/// The named fields of one request, with the place of each.
#[derive(Debug, Clone)]
pub struct Fields {
    /// The task file the fields come from (`None`: the command line).
    pub src: Option<TaskSource>,
    /// Span of the whole section in the file.
    pub section: Range<usize>,
    /// The fields by key (`max_pressure`).
    pub map: BTreeMap<String, (RawField, Place)>,
    used: RefCell<BTreeSet<String>>,
}

#[derive(Deserialize)]
struct File {
    synthesis: Option<toml::Spanned<BTreeMap<String, toml::Spanned<RawField>>>>,
}

impl Fields {
    /// Fields given on the command line, by key (`max_pressure`, not `--max-pressure`).
    pub fn options(map: impl IntoIterator<Item = (String, RawField)>) -> Self {
        Fields {
            src: None,
            section: 0..0,
            map: map.into_iter().map(|(k, v)| (k, (v, Place::Option))).collect(),
            used: RefCell::new(BTreeSet::new()),
        }
    }

    /// The `[synthesis]` section of a task file; `None` when there is none.
    pub fn section(task: &TaskSource) -> Result<Option<Self>, Error> {
        let f: File = task.parse("synthesis")?;
        let Some(sec) = f.synthesis else { return Ok(None) };
        let section = sec.span();
        Ok(Some(Fields {
            src: Some(task.clone()),
            section,
            map: sec
                .into_inner()
                .into_iter()
                .map(|(k, v)| {
                    let span = v.span();
                    (k, (v.into_inner(), Place::File(span)))
                })
                .collect(),
            used: RefCell::new(BTreeSet::new()),
        }))
    }

    /// How the user names a key: `synthesis.max_pressure` or `--max-pressure`
    /// (the kind, a subcommand on the command line: `tmm synth KIND`).
    pub fn label(&self, key: &str) -> String {
        match (&self.src, self.map.get("kind")) {
            (Some(_), _) => format!("synthesis.{key}"),
            (None, Some((RawField::Text(k), _))) if key == "kind" => format!("tmm synth {k}"),
            (None, _) => format!("--{}", key.replace('_', "-")),
        }
    }

    /// An input error about `key`, located where it was written.
    pub fn error(&self, key: &str, message: impl std::fmt::Display) -> Error {
        let label = self.label(key);
        match (&self.src, self.map.get(key)) {
            (Some(src), Some((_, Place::File(span)))) => Error::at(src, span.clone(), &label, message),
            (Some(src), _) => Error::at(src, self.section.clone(), &label, message),
            (None, _) => Error::input(&label, message),
        }
    }

    fn get(&self, key: &str) -> Option<&RawField> {
        let v = self.map.get(key).map(|(v, _)| v);
        if v.is_some() {
            self.used.borrow_mut().insert(key.to_string());
        }
        v
    }

    /// Whether the key was given.
    pub fn has(&self, key: &str) -> bool {
        self.map.contains_key(key)
    }

    /// A quantity of dimension `dim`, SI.
    pub fn qty(&self, key: &str, dim: Dim) -> Result<Option<f64>, Error> {
        match self.get(key) {
            None => Ok(None),
            Some(v) => self.convert(key, v, dim).map(Some),
        }
    }

    fn convert(&self, key: &str, v: &RawField, dim: Dim) -> Result<f64, Error> {
        let r = match v {
            RawField::Num(x) => units::from_number(*x, dim),
            RawField::Text(s) => units::parse(s, dim),
            _ => {
                return Err(self
                    .error(
                        key,
                        format!("expected {} {} (a number or a text with a unit)", dim.article(), dim_word(dim)),
                    )
                    .with_help(example(dim)));
            }
        };
        let x = r.map_err(|e| self.error(key, e))?;
        if dim == Dim::Length {
            self.within_size(key, x)?;
        }
        Ok(x)
    }

    /// A given length within the linkage's range, |x| ≤ 1e4 m
    /// ([`tmm_linkage::limits::MAX_LENGTH`]): the synthesised mechanism is
    /// analysed by the linkage core, which refuses larger coordinates, so a
    /// huge request is named here rather than as an internal coordinate of
    /// the result. The stroke and the travel, which set the mechanism's size,
    /// are at least [`MIN_SIZE`].
    fn within_size(&self, key: &str, x: f64) -> Result<(), Error> {
        let max = tmm_linkage::limits::MAX_LENGTH;
        let sized = matches!(key, "stroke" | "travel");
        if x.abs() <= max && (!sized || x.abs() >= MIN_SIZE) {
            return Ok(());
        }
        let range = if sized { "1e-6 m … 1e4 m" } else { "−1e4 m … 1e4 m" };
        Err(self
            .error(
                key,
                format!("{} m is outside the accepted range {range}", tmm_linkage::synthesis::error::show(x)),
            )
            .with_help("a lever mechanism from a micrometre to 10 km; give the value with its unit, e.g. \"300 mm\""))
    }

    /// A required quantity.
    pub fn need(&self, key: &str, dim: Dim) -> Result<f64, Error> {
        self.qty(key, dim)?.ok_or_else(|| {
            self.error(key, format!("missing: this kind needs the {}", dim_word(dim)))
                .with_help(format!("give {} {}", self.assign(key), example(dim)))
        })
    }

    fn assign(&self, key: &str) -> String {
        match self.src {
            Some(_) => format!("{key} ="),
            None => self.label(key),
        }
    }

    /// A flag (`optimum = true`, `--optimum`).
    pub fn flag(&self, key: &str) -> Result<bool, Error> {
        match self.get(key) {
            None => Ok(false),
            Some(RawField::Flag(b)) => Ok(*b),
            Some(_) => Err(self.error(key, "expected true or false")),
        }
    }

    /// A word (`lever = "rotating"`).
    pub fn word(&self, key: &str, allowed: &[&str]) -> Result<Option<String>, Error> {
        match self.get(key) {
            None => Ok(None),
            Some(RawField::Text(t)) if allowed.contains(&t.to_lowercase().as_str()) => Ok(Some(t.to_lowercase())),
            Some(_) => Err(self.error(key, format!("expected one of: {}", allowed.join(", ")))),
        }
    }

    /// Exactly one of `keys` (none allowed when `optional`): its key.
    pub fn one_of<'k>(&self, keys: &[&'k str], optional: bool) -> Result<Option<&'k str>, Error> {
        let given: Vec<&'k str> = keys.iter().copied().filter(|k| self.has(k)).collect();
        match given.len() {
            0 if optional => Ok(None),
            0 => Err(self.error(keys[0], format!("give one of: {}", self.list(keys)))),
            1 => Ok(Some(given[0])),
            _ => Err(self.error(
                given[1],
                format!("give only one of: {} (found {})", self.list(keys), self.list(&given)),
            )),
        }
    }

    fn list(&self, keys: &[&str]) -> String {
        keys.iter().map(|k| self.label(k)).collect::<Vec<_>>().join(", ")
    }

    /// A pair of lengths `[x, y]` (`"0 m, 0.2 m"` on the command line).
    pub fn point(&self, key: &str) -> Result<Option<Vec2>, Error> {
        let Some(v) = self.get(key) else { return Ok(None) };
        let items = self.items(key, v)?;
        if items.len() != 2 {
            return Err(self
                .error(key, "expected two coordinates [x, y]")
                .with_help("e.g. [\"0 m\", \"0.2 m\"]"));
        }
        Ok(Some(Vec2::new(
            self.convert(key, &items[0], Dim::Length)?,
            self.convert(key, &items[1], Dim::Length)?,
        )))
    }

    /// A list: a TOML array, or a command-line text split at commas.
    fn items(&self, key: &str, v: &RawField) -> Result<Vec<RawField>, Error> {
        match v {
            RawField::List(l) => Ok(l.clone()),
            RawField::Text(t) => Ok(t.split(',').map(|s| RawField::Text(s.trim().to_string())).collect()),
            _ => Err(self.error(key, "expected a list")),
        }
    }

    /// Pairs of angles `[[φ, ψ], …]` (`--position "30 deg, 75 deg"`, repeated).
    pub fn angle_pairs(&self, key: &str) -> Result<Vec<(f64, f64)>, Error> {
        let Some(v) = self.get(key) else { return Ok(Vec::new()) };
        let rows = match v {
            RawField::List(l) => l.clone(),
            other => vec![other.clone()],
        };
        rows.iter()
            .map(|r| {
                let it = self.items(key, r)?;
                if it.len() != 2 {
                    return Err(self
                        .error(key, "each position is a pair [crank angle, rocker angle]")
                        .with_help("e.g. [\"30 deg\", \"75 deg\"]"));
                }
                Ok((self.convert(key, &it[0], Dim::Angle)?, self.convert(key, &it[1], Dim::Angle)?))
            })
            .collect()
    }

    /// Refuse any field this kind did not read.
    pub fn finish(&self, kind: &str) -> Result<(), Error> {
        let used = self.used.borrow();
        if let Some(k) = self.map.keys().find(|k| !used.contains(*k)) {
            let known: Vec<String> = used.iter().filter(|u| *u != "kind").map(|u| self.label(u)).collect();
            return Err(self.error(k, format!("not a field of a {kind} synthesis")).with_help(format!(
                "this request used: {}; docs/synthesis.md lists the fields of every kind",
                known.join(", ")
            )));
        }
        Ok(())
    }
}

fn dim_word(d: Dim) -> &'static str {
    match d {
        Dim::Length => "length",
        Dim::Angle => "angle",
        Dim::AngularVelocity => "angular velocity",
        Dim::Velocity => "velocity",
        _ => "number",
    }
}

fn example(d: Dim) -> &'static str {
    match d {
        Dim::Length => "e.g. \"245 mm\"",
        Dim::Angle => "e.g. \"60 deg\"",
        Dim::AngularVelocity => "e.g. \"900 rpm\"",
        Dim::Velocity => "e.g. \"1.5 m/s\"",
        _ => "e.g. 1.28",
    }
}

/// A sweep of one number: `PARAM=FROM..TO:N`.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepSpec {
    /// The core's name of the number.
    pub param: String,
    /// First value, SI.
    pub from: f64,
    /// Last value, SI.
    pub to: f64,
    /// Number of values.
    pub n: usize,
}

/// A request read from its fields.
#[derive(Debug, Clone)]
pub struct Spec {
    /// The kind (`crank-rocker`).
    pub kind: &'static str,
    /// The core's request.
    pub request: Request,
    /// Extra given data not in the request (the mean speed), SI.
    pub extra_given: Vec<(String, f64)>,
    /// The key that holds the free parameter's condition, when one was given.
    pub condition_key: Option<&'static str>,
    /// The sweep, when asked for.
    pub sweep: Option<SweepSpec>,
    /// |ω1|, rad/s, for the generated `[linkage]`.
    pub speed: f64,
    /// Whether the speed was given.
    pub speed_given: bool,
    /// The design position (`design_position`): the angle of the crank
    /// from the start of the working stroke at which the generated
    /// `[linkage]` sets `at` (the plans and the kinetostatics), rad.
    pub design_position: Option<f64>,
}

/// The dimension of a core field or sweep parameter of a request.
pub fn param_dim(r: &Request, name: &str) -> Dim {
    match name {
        "k" | "lambda" | "lambda_e" => Dim::Ratio,
        "swing" | "frame_angle" | "max_pressure" | "delta" | "phi_start" | "phi_end" | "arm_angle" | "extreme_pressure"
        | "pivot_max_pressure" | "pivot_angle" | "pressure_working" | "pressure_return" | "transmission_min" => Dim::Angle,
        "gamma_start" | "gamma_end" | "gamma1" | "gamma2" | "gamma3" | "phi12" | "phi13" | "pressure_start" | "pressure_end" => Dim::Angle,
        "speed" => Dim::AngularVelocity,
        "mean_speed" | "cutting_speed" => Dim::Velocity,
        "design_position" => Dim::Angle,
        "coupler" => match r {
            Request::Slotted(q) if matches!(q.coupler, Coupler::Ratio(_)) => Dim::Ratio,
            _ => Dim::Length,
        },
        "pivot" => match r {
            Request::SixBarInversion(InversionRequest { pivot, .. }) | Request::SixBarPressure(PressureRequest { pivot, .. })
                if matches!(pivot, PivotCondition::MaxPressure(_) | PivotCondition::ExtremePressure(_)) =>
            {
                Dim::Angle
            }
            _ => Dim::Length,
        },
        _ => Dim::Length,
    }
}

/// The most variants of a sweep: each is a whole synthesis (10 000 of the
/// slowest kind, the six-bar with `--optimum`, take about 3.5 s).
pub const MAX_SWEEP: usize = 10_000;

/// Read a sweep spec `PARAM=FROM..TO:N` for the request; errors name `label`
/// (`--sweep` or `synthesis.sweep`) and the valid parameter names.
pub fn parse_sweep(r: &Request, text: &str) -> Result<SweepSpec, String> {
    let names = r.params().join(", ");
    let bad = |why: &str| format!("{why} in `{text}`; the form is PARAM=FROM..TO:N with PARAM one of: {names}");
    let (param, rest) = text.split_once('=').ok_or_else(|| bad("no `=`"))?;
    let param = param.trim();
    if !r.params().contains(&param) {
        return Err(bad(&format!("`{param}` is not a parameter of this kind")));
    }
    let (range, n) = rest.rsplit_once(':').ok_or_else(|| bad("no `:N`"))?;
    let (from, to) = range.split_once("..").ok_or_else(|| bad("no `..` between FROM and TO"))?;
    let n: usize = n.trim().parse().map_err(|_| bad("N is not a whole number"))?;
    if !(1..=MAX_SWEEP).contains(&n) {
        return Err(bad(&format!("N must be from 1 to {MAX_SWEEP}")));
    }
    let dim = param_dim(r, param);
    let val = |t: &str| units::parse(t.trim(), dim).map_err(|e| bad(&e.to_string()));
    Ok(SweepSpec {
        param: param.to_string(),
        from: val(from)?,
        to: val(to)?,
        n,
    })
}

fn drive(f: &Fields) -> Result<(Drive, bool), Error> {
    let rotation = match f.word("direction", &["ccw", "cw", "counter-clockwise", "clockwise"])?.as_deref() {
        Some("cw" | "clockwise") => Rotation::Cw,
        _ => Rotation::Ccw,
    };
    let speed = f.qty("speed", Dim::AngularVelocity)?;
    if let Some(w) = speed {
        if w <= 0.0 {
            return Err(f.error("speed", "the input speed must be > 0 (the direction is `direction`)"));
        }
    }
    Ok((
        Drive {
            rotation,
            omega: speed.unwrap_or(1.0),
        },
        speed.is_some(),
    ))
}

fn limits(f: &Fields) -> Result<Limits, Error> {
    Ok(Limits {
        pressure_working: f.qty("pressure_working", Dim::Angle)?,
        pressure_return: f.qty("pressure_return", Dim::Angle)?,
        transmission_min: f.qty("transmission_min", Dim::Angle)?,
    })
}

/// The fields that fix a six-bar's crank pivot by a number.
/// The smallest stroke or travel a synthesis accepts, m (1 µm): the
/// synthesised lengths scale with it, and below about 1e-9 m the analysis of
/// the result loses the mechanism's joints in its absolute round-off.
pub const MIN_SIZE: f64 = 1e-6;

const SIX_BAR_PIVOTS: [&str; 4] = ["crank", "frame", "pivot_max_pressure", "extreme_pressure"];

/// The crank pivot condition of a six-bar.
fn pivot_condition(f: &Fields) -> Result<(PivotCondition, Option<&'static str>), Error> {
    let k = f.one_of(
        &[
            "crank",
            "frame",
            "pivot_max_pressure",
            "extreme_pressure",
            "pivot_through",
            "optimum",
        ],
        true,
    )?;
    let c = match k {
        Some("crank") => PivotCondition::CrankLength(f.need("crank", Dim::Length)?),
        Some("frame") => PivotCondition::FrameDistance(f.need("frame", Dim::Length)?),
        Some("pivot_max_pressure") => PivotCondition::MaxPressure(f.need("pivot_max_pressure", Dim::Angle)?),
        Some("extreme_pressure") => PivotCondition::ExtremePressure(f.need("extreme_pressure", Dim::Angle)?),
        Some("pivot_through") => {
            let p = f.point("pivot_through")?.unwrap_or_default();
            let a = f.qty("pivot_angle", Dim::Angle)?.unwrap_or(0.0);
            PivotCondition::OnLine {
                point: p,
                dir: Vec2::new(a.cos(), a.sin()),
            }
        }
        _ => {
            f.flag("optimum")?;
            PivotCondition::Optimum
        }
    };
    Ok((c, k))
}

/// Read the request of `kind` from its fields.
pub fn spec(f: &Fields) -> Result<Spec, Error> {
    let kind_text = match f.get("kind") {
        Some(RawField::Text(t)) => t.clone(),
        _ => {
            return Err(f
                .error("kind", "missing or not a text: which mechanism to synthesise")
                .with_help(format!(
                    "kind = one of {}",
                    KINDS.iter().map(|k| k.0).collect::<Vec<_>>().join(", ")
                )));
        }
    };
    let Some(&(kind, _)) = KINDS.iter().find(|k| k.0 == kind_text) else {
        return Err(f
            .error("kind", format!("unknown kind `{kind_text}`"))
            .with_help(format!("one of {}", KINDS.iter().map(|k| k.0).collect::<Vec<_>>().join(", "))));
    };
    let (mut drive, mut speed_given) = drive(f)?;
    let limits = limits(f)?;
    let design_position = f.qty("design_position", Dim::Angle)?;
    if let Some(p) = design_position
        && !(0.0..std::f64::consts::TAU).contains(&p)
    {
        return Err(f
            .error("design_position", "the design position is an angle of the cycle from 0 to 360°")
            .with_help("the crank's angle from the start of the working stroke, e.g. \"90 deg\""));
    }
    let mut extra_given = Vec::new();
    let mut condition_key = None;
    // a swept extra condition needs not be given: the sweep sets it
    let swept: Option<String> = match f.map.get("sweep") {
        Some((RawField::Text(t), _)) => t.split_once('=').map(|(p, _)| p.trim().to_string()),
        _ => None,
    };
    let swept_of = |keys: &[&'static str]| -> Option<&'static str> {
        let p = swept.as_deref()?;
        keys.iter().copied().find(|k| *k == p && *k != "optimum")
    };
    let request = match kind {
        "crank-slider" => {
            let k = f.need("k", Dim::Ratio)?;
            let stroke = match f.one_of(&["stroke", "mean_speed"], false)? {
                Some("mean_speed") => {
                    let v = f.need("mean_speed", Dim::Velocity)?;
                    if !speed_given {
                        return Err(f
                            .error("mean_speed", "the stroke by the mean speed needs the crank speed")
                            .with_help(format!("give {} too (H = v_mean/(2 n1), seed 000 § 1.2.3)", f.label("speed"))));
                    }
                    let n1 = drive.omega / std::f64::consts::TAU;
                    extra_given.push(("v_mean".to_string(), v));
                    extra_given.push(("n1".to_string(), n1));
                    v / (2.0 * n1)
                }
                _ => f.need("stroke", Dim::Length)?,
            };
            let keys = ["lambda", "offset", "max_pressure", "optimum"];
            condition_key = f.one_of(&keys, swept_of(&keys).is_some())?;
            let condition = match condition_key {
                Some("lambda") => SliderCondition::Lambda(f.need("lambda", Dim::Ratio)?),
                Some("offset") => SliderCondition::Offset(f.need("offset", Dim::Length)?),
                Some("max_pressure") => SliderCondition::MaxPressure(f.need("max_pressure", Dim::Angle)?),
                None => {
                    // set below to the sweep's first value
                    condition_key = swept_of(&keys);
                    SliderCondition::Optimum
                }
                _ => {
                    f.flag("optimum")?;
                    SliderCondition::Optimum
                }
            };
            Request::CrankSlider(CrankSliderRequest {
                stroke,
                k,
                condition,
                drive,
                limits,
            })
        }
        "crank-slider-positions" => Request::TwoPositions(TwoPositionsRequest {
            lambda: f.need("lambda", Dim::Ratio)?,
            lambda_e: f.qty("lambda_e", Dim::Ratio)?.unwrap_or(0.0),
            phi_start: f.need("phi_start", Dim::Angle)?,
            phi_end: f.need("phi_end", Dim::Angle)?,
            travel: f.need("travel", Dim::Length)?,
            drive,
            limits,
        }),
        "crank-rocker" => {
            let k = f.need("k", Dim::Ratio)?;
            let swing = f.need("swing", Dim::Angle)?;
            let rocker = f.need("rocker", Dim::Length)?;
            let keys = ["crank", "frame", "frame_angle", "optimum"];
            condition_key = f.one_of(&keys, swept_of(&keys).is_some())?;
            let condition = match condition_key {
                Some("crank") => RockerCondition::Crank(f.need("crank", Dim::Length)?),
                Some("frame") => RockerCondition::Frame(f.need("frame", Dim::Length)?),
                Some("frame_angle") => RockerCondition::FrameAngle(f.need("frame_angle", Dim::Angle)?),
                None => {
                    condition_key = swept_of(&keys);
                    RockerCondition::Optimum
                }
                _ => {
                    f.flag("optimum")?;
                    RockerCondition::Optimum
                }
            };
            Request::CrankRocker(CrankRockerRequest {
                k,
                rocker,
                swing,
                condition,
                drive,
                limits,
            })
        }
        "function-generation" => {
            let positions = f.angle_pairs("positions")?;
            if positions.len() > tmm_linkage::synthesis::function_gen::MAX_POSITIONS {
                return Err(f.error(
                    "positions",
                    format!(
                        "{} positions given; at most {} are taken (each adds a row to every table and drawing)",
                        positions.len(),
                        tmm_linkage::synthesis::function_gen::MAX_POSITIONS
                    ),
                ));
            }
            if positions.len() < 3 {
                return Err(f
                    .error(
                        "positions",
                        format!("{} positions given; three or more are needed", positions.len()),
                    )
                    .with_help("positions = [[\"30 deg\", \"60 deg\"], [\"60 deg\", \"75 deg\"], [\"90 deg\", \"95 deg\"]]"));
            }
            Request::Function(FunctionRequest {
                positions,
                frame: f.need("frame", Dim::Length)?,
                omega: drive.signed_omega().map_err(|e| f.error("speed", e))?,
                limits,
            })
        }
        "slotted-lever" => {
            let stroke = f.need("stroke", Dim::Length)?;
            let k = f.need("k", Dim::Ratio)?;
            let pivots = f.need("pivots", Dim::Length)?;
            let coupler = match f.one_of(&["coupler", "coupler_ratio"], false)? {
                Some("coupler") => Coupler::Length(f.need("coupler", Dim::Length)?),
                _ => Coupler::Ratio(f.need("coupler_ratio", Dim::Ratio)?),
            };
            let lever = match f.word("lever", &["rotating", "oscillating"])?.as_deref() {
                Some("oscillating") => Lever::Oscillating,
                _ => Lever::Rotating,
            };
            Request::Slotted(SlottedRequest {
                stroke,
                k,
                pivots,
                coupler,
                lever,
                drive,
                limits,
            })
        }
        "knee-press" => {
            let stroke = f.need("stroke", Dim::Length)?;
            let k = f.need("k", Dim::Ratio)?;
            let rocker = f.need("rocker", Dim::Length)?;
            let link = f.need("link", Dim::Length)?;
            let delta = f.need("delta", Dim::Angle)?;
            let keys = ["horizontal", "crank", "frame", "optimum"];
            condition_key = f.one_of(&keys, swept_of(&keys).is_some())?;
            let pivot = match condition_key {
                Some("horizontal") => KneePivot::Horizontal(f.need("horizontal", Dim::Length)?),
                Some("crank") => KneePivot::Crank(f.need("crank", Dim::Length)?),
                Some("frame") => KneePivot::Frame(f.need("frame", Dim::Length)?),
                None => {
                    condition_key = swept_of(&keys);
                    KneePivot::Optimum
                }
                _ => {
                    f.flag("optimum")?;
                    KneePivot::Optimum
                }
            };
            Request::Knee(KneeRequest {
                stroke,
                k,
                rocker,
                link,
                delta,
                pivot,
                drive,
                limits,
            })
        }
        "six-bar-inversion" => {
            let (pivot, key) = pivot_condition(f)?;
            condition_key = key.or_else(|| swept_of(&SIX_BAR_PIVOTS));
            Request::SixBarInversion(InversionRequest {
                k: f.need("k", Dim::Ratio)?,
                travel: f.need("travel", Dim::Length)?,
                guide: f.need("guide", Dim::Length)?,
                start: f.need("start", Dim::Length)?,
                coupler: f.need("coupler", Dim::Length)?,
                swing: f.need("swing", Dim::Angle)?,
                lever: f.need("lever", Dim::Length)?,
                pivot,
                drive,
                limits,
            })
        }
        "knee-press-bell-crank" => {
            let stroke = f.need("stroke", Dim::Length)?;
            let k = f.need("k", Dim::Ratio)?;
            let knee = f.need("knee", Dim::Length)?;
            let link = f.need("link", Dim::Length)?;
            let arm = f.need("arm", Dim::Length)?;
            let chord = match f.one_of(&["chord", "arm_ratio"], false)? {
                Some("arm_ratio") => {
                    let q = f.need("arm_ratio", Dim::Ratio)?;
                    if q.is_nan() || q <= 0.0 {
                        return Err(f.error("arm_ratio", "l_CB / l_BD must be > 0"));
                    }
                    arm / q
                }
                _ => f.need("chord", Dim::Length)?,
            };
            let delta = f.need("delta", Dim::Angle)?;
            let keys = ["horizontal", "crank", "frame", "optimum"];
            condition_key = f.one_of(&keys, swept_of(&keys).is_some())?;
            let pivot = match condition_key {
                Some("horizontal") => KneePivot::Horizontal(f.need("horizontal", Dim::Length)?),
                Some("crank") => KneePivot::Crank(f.need("crank", Dim::Length)?),
                Some("frame") => KneePivot::Frame(f.need("frame", Dim::Length)?),
                None => {
                    condition_key = swept_of(&keys);
                    KneePivot::Optimum
                }
                _ => {
                    f.flag("optimum")?;
                    KneePivot::Optimum
                }
            };
            Request::KneeBellCrank(BellKneeRequest {
                stroke,
                k,
                knee,
                link,
                arm,
                chord,
                delta,
                pivot,
                drive,
                limits,
            })
        }
        "rocker-extremes" | "rocker-extremes-k" => Request::RockerExtremes(ExtremesRequest {
            abscissa: if kind == "rocker-extremes" {
                Abscissa::Given(f.need("frame_x", Dim::Length)?)
            } else {
                Abscissa::ByK(f.need("k", Dim::Ratio)?)
            },
            frame_y: f.need("frame_y", Dim::Length)?,
            rocker: f.need("rocker", Dim::Length)?,
            gamma_start: f.need("gamma_start", Dim::Angle)?,
            gamma_end: f.need("gamma_end", Dim::Angle)?,
            drive,
            limits,
        }),
        "three-positions" => Request::ThreePositions(ThreePositionsRequest {
            frame: Vec2::new(f.need("frame_x", Dim::Length)?, f.need("frame_y", Dim::Length)?),
            rocker: f.need("rocker", Dim::Length)?,
            gammas: [
                f.need("gamma1", Dim::Angle)?,
                f.need("gamma2", Dim::Angle)?,
                f.need("gamma3", Dim::Angle)?,
            ],
            crank_turns: [f.need("phi12", Dim::Angle)?, f.need("phi13", Dim::Angle)?],
            drive,
            limits,
        }),
        "oscillating-cylinder" => {
            let (h_min, h_max) = (f.need("h_min", Dim::Length)?, f.need("h_max", Dim::Length)?);
            let rod = f.need("rod", Dim::Length)?;
            let swing = f.need("swing", Dim::Angle)?;
            let pressure = match f.one_of(&["pressure_end", "pressure_start"], false)? {
                Some("pressure_start") => PressureAt::Start(f.need("pressure_start", Dim::Angle)?),
                _ => PressureAt::End(f.need("pressure_end", Dim::Angle)?),
            };
            Request::Cylinder(CylinderRequest {
                h_min,
                h_max,
                rod,
                swing,
                pressure,
                frame_y: f.qty("frame_y", Dim::Length)?,
                drive,
                limits,
            })
        }
        "shaper" => {
            let stroke = f.need("stroke", Dim::Length)?;
            let k = f.need("k", Dim::Ratio)?;
            // the book's nominal speed: the working stroke H takes H/V_рез,
            // so ω_cp = Δφ_PX·V_рез/H with Δφ_PX = 2πK/(K + 1) (textbook
            // П3, p. 130)
            if f.one_of(&["speed", "cutting_speed"], true)? == Some("cutting_speed") {
                let v = f.need("cutting_speed", Dim::Velocity)?;
                if v.is_nan() || v <= 0.0 {
                    return Err(f.error("cutting_speed", "the cutting speed must be > 0"));
                }
                if k.is_finite() && k >= 1.0 && stroke > 0.0 {
                    drive.omega = std::f64::consts::TAU * k / (k + 1.0) * v / stroke;
                    speed_given = true;
                    extra_given.push(("v_cut".to_string(), v));
                }
            }
            Request::Shaper(ShaperRequest {
                stroke,
                k,
                rocker: f.need("rocker", Dim::Length)?,
                lambda: f.need("lambda", Dim::Ratio)?,
                frame: f.need("frame", Dim::Length)?,
                ram_center: f.qty("ram_center", Dim::Length)?.unwrap_or(0.0),
                drive,
                limits,
            })
        }
        _ => {
            let (pivot, key) = pivot_condition(f)?;
            condition_key = key.or_else(|| swept_of(&SIX_BAR_PIVOTS));
            Request::SixBarPressure(PressureRequest {
                k: f.need("k", Dim::Ratio)?,
                swing: f.need("swing", Dim::Angle)?,
                arm_b: f.need("arm_b", Dim::Length)?,
                arm_c: f.need("arm_c", Dim::Length)?,
                arm_angle: f.qty("arm_angle", Dim::Angle)?.unwrap_or(std::f64::consts::PI),
                guide: f.need("guide", Dim::Length)?,
                max_pressure: f.need("max_pressure", Dim::Angle)?,
                pivot,
                drive,
                limits,
            })
        }
    };
    let sweep = match f.get("sweep") {
        None => None,
        Some(RawField::Text(t)) => Some(parse_sweep(&request, t).map_err(|m| f.error("sweep", m))?),
        Some(_) => return Err(f.error("sweep", "expected a text PARAM=FROM..TO:N")),
    };
    // a swept extra condition that was not given: the request (what `tmm
    // run` analyses) takes the sweep's first value
    let mut request = request;
    if let Some(sw) = &sweep
        && request.is_condition(&sw.param)
        && !f.has(&sw.param)
    {
        request = request.with_param(&sw.param, sw.from).map_err(|e| f.error("sweep", e))?;
    }
    f.finish(kind)?;
    Ok(Spec {
        kind,
        request,
        extra_given,
        condition_key,
        sweep,
        speed: drive.omega,
        speed_given,
        design_position,
    })
}
