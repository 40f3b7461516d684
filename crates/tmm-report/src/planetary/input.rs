//! The inputs of a planetary search, read from a `[planetary]` task section
//! or from command-line options, and errors that point back at where each
//! value came from.

use std::collections::{BTreeMap, BTreeSet};
use std::ops::Range;

use serde::Deserialize;
use tmm_geom::units::Dim;
use tmm_planetary::{MeshEfficiency, Request, Scheme};

use crate::task::{Qty, qty};
use crate::{Error, TaskSource};

/// Everything a planetary run needs, in SI.
#[derive(Debug, Clone, PartialEq)]
pub struct Params {
    /// The search request (scheme, ratio, planets, limits).
    pub request: Request,
    /// Module of row I, m (default 1 mm): scales the dimensions and the picture.
    pub module: f64,
    /// Angular velocity of wheel 1, rad/s (default 1 rad/s): scales the picture.
    pub omega1: f64,
    /// Mesh efficiencies (0.99 external, 0.995 internal by default).
    pub efficiency: MeshEfficiency,
    /// How many candidates the table and the JSON list (default 10).
    pub top: usize,
}

impl Params {
    /// Defaults around a request.
    pub fn new(request: Request) -> Params {
        Params {
            request,
            module: 1e-3,
            omega1: 1.0,
            efficiency: MeshEfficiency::default(),
            top: 10,
        }
    }
}

/// Where the values came from, to name them in errors: a task file (with the
/// byte span of each field given there) and/or command-line options.
#[derive(Debug, Clone, Default)]
pub struct Origin {
    task: Option<TaskSource>,
    section: Range<usize>,
    spans: BTreeMap<&'static str, Range<usize>>,
    cli: BTreeSet<&'static str>,
}

/// The command-line option of a request field.
pub fn option_name(field: &str) -> &'static str {
    match field {
        "scheme" => "--scheme",
        "ratio" => "--ratio",
        "planets" => "--planets",
        "tolerance" => "--tolerance",
        "zmin" => "--zmin",
        "zmax" => "--zmax",
        "ring_zmin" => "--ring-zmin",
        "min_difference" => "--min-difference",
        "addendum" => "--addendum",
        "module" => "--module",
        "omega1" => "--omega1",
        "efficiency_external" => "--eta-external",
        "efficiency_internal" => "--eta-internal",
        "top" => "--top",
        _ => "--ratio",
    }
}

impl Origin {
    /// Values from the command line only.
    pub fn cli() -> Origin {
        Origin::default()
    }

    /// Mark a field as given on the command line (it overrides the file).
    pub fn set_cli(&mut self, field: &'static str) {
        self.spans.remove(field);
        self.cli.insert(field);
    }

    /// An input error about `field`: located in the task file when the field
    /// came from there, else naming the command-line option.
    pub fn error(&self, field: &str, message: impl std::fmt::Display, help: impl Into<String>) -> Error {
        let key = format!("planetary.{field}");
        let e = match (&self.task, self.spans.get(field)) {
            (Some(t), Some(span)) => Error::at(t, span.clone(), &key, message),
            (Some(t), None) if !self.cli.contains(field) => Error::at(t, self.section.clone(), &key, message),
            _ => Error::input(option_name(field), message),
        };
        e.with_help(help)
    }
}

/// The whole task file as the planetary section sees it.
#[derive(Deserialize)]
struct File {
    planetary: Option<toml::Spanned<Section>>,
}

/// The `[planetary]` section.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Section {
    scheme: toml::Spanned<String>,
    ratio: Qty,
    planets: toml::Spanned<i64>,
    tolerance: Option<Qty>,
    zmin: Option<toml::Spanned<i64>>,
    zmax: Option<toml::Spanned<i64>>,
    ring_zmin: Option<toml::Spanned<i64>>,
    min_difference: Option<toml::Spanned<i64>>,
    addendum: Option<toml::Spanned<f64>>,
    two_modules: Option<bool>,
    module: Option<Qty>,
    omega1: Option<Qty>,
    efficiency_external: Option<toml::Spanned<f64>>,
    efficiency_internal: Option<toml::Spanned<f64>>,
    top: Option<toml::Spanned<i64>>,
}

/// The scheme of a name, or an error listing the four.
pub fn scheme_named(name: &str) -> Result<Scheme, String> {
    Scheme::from_name(name.trim()).ok_or_else(|| format!("unknown scheme `{name}`"))
}

/// The help text listing the schemes.
pub const SCHEMES_HELP: &str = "schemes: sun-planet-ring (1–2 external, 2–3 internal), ext-int (double planet, 1–2 external, 2′–3 internal), ext-ext (two external meshes), int-int (two internal meshes)";

/// A whole number for a count field, as `u32`.
pub fn whole(origin: &Origin, field: &str, v: i64, help: &str) -> Result<u32, Error> {
    u32::try_from(v).map_err(|_| origin.error(field, format!("{v} is not a valid count"), help))
}

/// Read the `[planetary]` section; `None` when the task has none.
pub fn from_task(task: &TaskSource) -> Result<Option<(Params, Origin)>, Error> {
    let file: File = task.parse("planetary")?;
    let Some(sec) = file.planetary else { return Ok(None) };
    let section = sec.span();
    let s = sec.into_inner();
    let mut o = Origin {
        task: Some(task.clone()),
        section,
        ..Origin::default()
    };
    let mut span = |f: &'static str, r: Range<usize>| {
        o.spans.insert(f, r);
    };
    span("scheme", s.scheme.span());
    span("ratio", s.ratio.span());
    span("planets", s.planets.span());
    for (f, v) in [
        ("zmin", &s.zmin),
        ("zmax", &s.zmax),
        ("ring_zmin", &s.ring_zmin),
        ("min_difference", &s.min_difference),
        ("top", &s.top),
    ] {
        if let Some(v) = v {
            span(f, v.span());
        }
    }
    for (f, v) in [("tolerance", &s.tolerance), ("module", &s.module), ("omega1", &s.omega1)] {
        if let Some(v) = v {
            span(f, v.span());
        }
    }
    for (f, v) in [
        ("addendum", &s.addendum),
        ("efficiency_external", &s.efficiency_external),
        ("efficiency_internal", &s.efficiency_internal),
    ] {
        if let Some(v) = v {
            span(f, v.span());
        }
    }
    let scheme = scheme_named(s.scheme.get_ref()).map_err(|m| o.error("scheme", m, SCHEMES_HELP))?;
    let ratio = qty(task, "planetary.ratio", &s.ratio, Dim::Ratio)?;
    let planets = whole(
        &o,
        "planets",
        *s.planets.get_ref(),
        "the number of planets k is 1 to 64 (usually 3)",
    )?;
    let mut request = Request::new(scheme, ratio, planets);
    if let Some(t) = &s.tolerance {
        request.tolerance = qty(task, "planetary.tolerance", t, Dim::Ratio)?;
    }
    let l = &mut request.limits;
    let count_help = "a whole number of teeth";
    for (f, v, slot) in [
        ("zmin", &s.zmin, &mut l.zmin),
        ("zmax", &s.zmax, &mut l.zmax),
        ("ring_zmin", &s.ring_zmin, &mut l.ring_zmin),
        ("min_difference", &s.min_difference, &mut l.min_difference),
    ] {
        if let Some(v) = v {
            *slot = whole(&o, f, *v.get_ref(), count_help)?;
        }
    }
    if let Some(a) = &s.addendum {
        l.addendum = *a.get_ref();
    }
    request.two_modules = s.two_modules.unwrap_or(false);
    let mut p = Params::new(request);
    if let Some(m) = &s.module {
        p.module = qty(task, "planetary.module", m, Dim::Length)?;
    }
    if let Some(w) = &s.omega1 {
        p.omega1 = qty(task, "planetary.omega1", w, Dim::AngularVelocity)?;
    }
    if let Some(e) = &s.efficiency_external {
        p.efficiency.external = *e.get_ref();
    }
    if let Some(e) = &s.efficiency_internal {
        p.efficiency.internal = *e.get_ref();
    }
    if let Some(t) = &s.top {
        p.top = whole(&o, "top", *t.get_ref(), "how many candidates to list, e.g. 10")? as usize;
    }
    Ok(Some((p, o)))
}

/// Check the values the core does not check (module, speed, efficiencies, top).
pub fn check_extra(p: &Params, o: &Origin) -> Result<(), Error> {
    if tmm_gears::spec::check_module(p.module).is_err() {
        let mm = p.module * 1e3;
        let hint = if (0.05..=100.0).contains(&p.module) {
            format!(" — did you mean {} mm? (a number without a unit is read in metres)", p.module)
        } else {
            String::new()
        };
        return Err(o.error(
            "module",
            format!("{mm} mm lies outside the GOST 9563-60 series' 0.05 mm … 100 mm{hint}"),
            "a module with its unit, e.g. \"2 mm\"",
        ));
    }
    // 1e5 rad/s (about a million rpm) is beyond any gear train
    if !p.omega1.is_finite() || p.omega1 == 0.0 || p.omega1.abs() > 1e5 {
        return Err(o.error(
            "omega1",
            format!("{} rad/s", p.omega1),
            "a non-zero angular velocity of wheel 1 up to 1e5 rad/s, e.g. \"1450 rpm\" or \"150 rad/s\"",
        ));
    }
    for (f, e) in [
        ("efficiency_external", p.efficiency.external),
        ("efficiency_internal", p.efficiency.internal),
    ] {
        if !e.is_finite() || e <= 0.0 || e > 1.0 {
            return Err(o.error(
                f,
                format!("{e} is not an efficiency"),
                "a mesh efficiency above 0 and at most 1 (0.99 external, 0.995 internal)",
            ));
        }
    }
    if p.top == 0 || p.top > 100_000 {
        return Err(o.error("top", format!("{}", p.top), "how many candidates to list: 1 to 100000"));
    }
    Ok(())
}
