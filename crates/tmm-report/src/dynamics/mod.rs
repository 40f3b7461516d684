//! The `[dynamics]` section: the dynamics of the machine (динамика
//! машинного агрегата) for the `[linkage]` mechanism under the loads of
//! `[forces]` — the reduced inertia and moments, the flywheel for the
//! coefficient of speed fluctuation δ by Mertsalov's method, by Wittenbauer's
//! energy–mass diagram and exactly, its size, the true ω₁(φ), ε₁(φ) and,
//! with a motor, the run-up — as tables, one JSON document and SVG
//! diagrams; with `motion = "single-stroke"` the unsteady single stroke
//! ([`stroke`]). The computation is `tmm_linkage::dynamics` (docs/dynamics.md).

#[doc(hidden)]
pub mod draw;
#[doc(hidden)]
pub mod json;
pub mod stroke;
#[doc(hidden)]
pub mod stroke_json;
pub mod stroke_task;
mod stroke_text;
pub mod task;
mod text;

use tmm_linkage::dynamics::{Dynamics, DynamicsError};

use crate::forces::{self, ForcesTask};
use crate::linkage::{self, Loaded};
use crate::output::{Documents, SectionOutput};
use crate::{Error, TaskSource};

pub use task::DynamicsTask;

/// Turn a core dynamics error into a located input error.
pub fn locate(src: &TaskSource, l: &Loaded, ft: &ForcesTask, dt: &DynamicsTask, e: &DynamicsError) -> Error {
    match e {
        DynamicsError::Spec { field, message } => Error::at(src, dt.span_of(field), field, message).with_help(task::help_for(field)),
        DynamicsError::Force(fe) => forces::locate(src, l, ft, fe),
        DynamicsError::Kinematics(k) => linkage::locate(src, &l.task, k),
        DynamicsError::NoResistance { .. } => Error::at(src, ft.section.clone(), "forces", e.to_string())
            .with_help("add the useful resistance: [[forces.resistance]] link = \"3\", moment = \"380 N m\""),
        other => Error::at(src, dt.section.clone(), "dynamics", other.to_string()),
    }
}

/// Read the `[linkage]`, `[forces]` and `[dynamics]` sections; `None` when
/// there is no `[dynamics]`. A `[dynamics]` without `[forces]` is an error:
/// the loads are those of `[forces]`.
pub fn load(src: &TaskSource) -> Result<Option<(Loaded, ForcesTask, DynamicsTask)>, Error> {
    let Some(span) = task::section_span(src)? else { return Ok(None) };
    let Some((l, ft)) = forces::load(src)? else {
        return Err(Error::at(
            src,
            span,
            "dynamics",
            "the dynamics needs the loads of a [forces] section (masses, moments of inertia, the useful resistance), and the task has none",
        )
        .with_help("add [forces] with the masses and the resistance, e.g. mass_per_length = \"10 kg/m\" and [[forces.resistance]] link = \"3\", moment = \"380 N m\" (see examples/seed-001-fourbar.toml)"));
    };
    let dt = task::read(src, forces::working(l.task.working))?.ok_or_else(|| Error::input(&src.name, "no [dynamics] section"))?;
    Ok(Some((l, ft, dt)))
}

/// Compute the dynamics of the machine.
pub fn analyse(src: &TaskSource, l: &Loaded, ft: &ForcesTask, dt: &DynamicsTask) -> Result<Dynamics, Error> {
    crate::linkage::require_full_turn(src, l, "dynamics")?;
    Dynamics::compute(&l.mech, &ft.loads, &dt.spec).map_err(|e| locate(src, l, ft, dt, &e))
}

/// Run the `[dynamics]` section of a task: documents under `dynamics/`.
pub fn run_section(task: &TaskSource) -> Result<Option<SectionOutput>, Error> {
    if stroke_task::is_single_stroke(task)? {
        return stroke::run_section(task).map(Some);
    }
    let Some((l, ft, dt)) = load(task)? else { return Ok(None) };
    let d = analyse(task, &l, &ft, &dt)?;
    let mut docs = Documents::for_task(task);
    draw::draw_all(&d, "dynamics/", task.lang, task.sheet, &mut docs)?;
    let json = json::document(&l, &d);
    docs.add_json("dynamics/dynamics.json", &json)?;
    let text = text::report(&l, &d);
    docs.add_text("dynamics/dynamics.txt", text.clone())?;
    Ok(Some(SectionOutput {
        section: "dynamics",
        text,
        json,
        docs,
    }))
}

/// [`run_section`] in two stages: the tables and the JSON now, the
/// drawings when [`crate::run::Staged::drawings`] is called (the same
/// documents as [`run_section`]'s).
pub fn run_staged(task: &TaskSource) -> Result<Option<crate::run::Staged>, Error> {
    if stroke_task::is_single_stroke(task)? {
        return stroke::run_staged(task).map(Some);
    }
    let Some((l, ft, dt)) = load(task)? else { return Ok(None) };
    let d = analyse(task, &l, &ft, &dt)?;
    let (lang, sheet) = (task.lang, task.sheet);
    let mut docs = Documents::for_task(task);
    let json = json::document(&l, &d);
    docs.add_json("dynamics/dynamics.json", &json)?;
    let text = text::report(&l, &d);
    docs.add_text("dynamics/dynamics.txt", text.clone())?;
    Ok(Some(crate::run::Staged {
        output: SectionOutput {
            section: "dynamics",
            text,
            json,
            docs,
        },
        draw: Box::new(move || {
            let mut docs = Documents::new();
            draw::draw_all(&d, "dynamics/", lang, sheet, &mut docs)?;
            Ok(docs)
        }),
    }))
}

/// The human report.
pub fn text_report(l: &Loaded, d: &Dynamics) -> String {
    text::report(l, d)
}

/// The JSON document.
pub fn json_document(l: &Loaded, d: &Dynamics) -> serde_json::Value {
    json::document(l, d)
}

/// The diagrams, as documents named by file name only (`moments.svg`, …),
/// with the words of `lang` and sized for a sheet of `sheet`.
pub fn drawings(d: &Dynamics, lang: crate::project::Language, sheet: crate::project::SheetFormat) -> Result<Documents, Error> {
    let mut docs = Documents::new();
    draw::draw_all(d, "", lang, sheet, &mut docs)?;
    Ok(docs)
}
