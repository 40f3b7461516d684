//! The `[dynamics]` section with `motion = "single-stroke"`: the unsteady
//! single stroke of the `[linkage]` mechanism under the loads of
//! `[forces]`, driven by an induction motor by Kloss's formula, and beside
//! it the constant-moment model by the energy method — as tables, one JSON
//! document and SVG diagrams of ω, t and ε against φ. The computation is
//! `tmm_linkage::dynamics::SingleStroke` (docs/dynamics.md, "The unsteady
//! single stroke").

use tmm_linkage::dynamics::{DynamicsError, SingleStroke};

use super::stroke_task::{self, StrokeTask};
use crate::forces::{self, ForcesTask};
use crate::linkage::{self, Loaded};
use crate::output::{Documents, SectionOutput};
use crate::{Error, TaskSource};

/// Turn a core error into a located input error.
pub fn locate(src: &TaskSource, l: &Loaded, ft: &ForcesTask, st: &StrokeTask, e: &DynamicsError) -> Error {
    match e {
        DynamicsError::Spec { field, message } => Error::at(src, st.span_of(field), field, message).with_help(stroke_task::help_for(field)),
        DynamicsError::Force(fe) => forces::locate(src, l, ft, fe),
        DynamicsError::Kinematics(k) => linkage::locate(src, &l.task, k),
        other => Error::at(src, st.section.clone(), "dynamics", other.to_string()).with_help(stroke_task::help_for("dynamics")),
    }
}

/// Read `[linkage]`, `[forces]` and the single stroke's `[dynamics]`.
pub fn load(src: &TaskSource) -> Result<(Loaded, ForcesTask, StrokeTask), Error> {
    let span = super::task::section_span(src)?.unwrap_or(0..0);
    let Some((l, ft)) = forces::load(src)? else {
        return Err(Error::at(
            src,
            span,
            "dynamics",
            "the single stroke needs the loads of a [forces] section (masses, the force on the stroke, gravity), and the task has none",
        )
        .with_help("add [forces] with the masses and a [[forces.stroke_forces]] table (see examples/textbook/p4-press.toml)"));
    };
    let st = stroke_task::read(src, forces::working(l.task.working))?;
    Ok((l, ft, st))
}

/// Compute both models.
pub fn analyse(src: &TaskSource, l: &Loaded, ft: &ForcesTask, st: &StrokeTask) -> Result<SingleStroke, Error> {
    linkage::require_full_turn(src, l, "dynamics")?;
    SingleStroke::compute(&l.mech, &ft.loads, &st.spec).map_err(|e| locate(src, l, ft, st, &e))
}

/// The section in two stages: the tables and JSON now, the drawings later.
pub fn run_staged(task: &TaskSource) -> Result<crate::run::Staged, Error> {
    let (l, ft, st) = load(task)?;
    let s = analyse(task, &l, &ft, &st)?;
    let (lang, sheet) = (task.lang, task.sheet);
    let mut docs = Documents::for_task(task);
    let json = super::stroke_json::document(&l, &s);
    docs.add_json("dynamics/dynamics.json", &json)?;
    let text = super::stroke_text::report(&l, &s);
    docs.add_text("dynamics/dynamics.txt", text.clone())?;
    Ok(crate::run::Staged {
        output: SectionOutput {
            section: "dynamics",
            text,
            json,
            docs,
        },
        draw: Box::new(move || {
            let mut docs = Documents::new();
            super::draw::stroke::draw_all(&s, "dynamics/", lang, sheet, &mut docs)?;
            Ok(docs)
        }),
    })
}

/// The section at once (tables, JSON, drawings).
pub fn run_section(task: &TaskSource) -> Result<SectionOutput, Error> {
    let st = run_staged(task)?;
    let mut out = st.output;
    let drawn = (st.draw)()?;
    out.docs.append(drawn);
    Ok(out)
}

/// The human report.
pub fn text_report(l: &Loaded, s: &SingleStroke) -> String {
    super::stroke_text::report(l, s)
}

/// The JSON document.
pub fn json_document(l: &Loaded, s: &SingleStroke) -> serde_json::Value {
    super::stroke_json::document(l, s)
}

/// The diagrams, named by file name only.
pub fn drawings(s: &SingleStroke, lang: crate::project::Language, sheet: crate::project::SheetFormat) -> Result<Documents, Error> {
    let mut docs = Documents::new();
    super::draw::stroke::draw_all(s, "", lang, sheet, &mut docs)?;
    Ok(docs)
}
