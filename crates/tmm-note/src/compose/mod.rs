//! Composing the explanatory note from a run of the course project
//! (формирование пояснительной записки по результатам расчёта).
//!
//! [`compose`] turns a [`Run`] of `tmm-report` (the combined JSON report, SI,
//! and every drawing of the run) into a [`Note`]: the title page from
//! `[project]`, the technical assignment (the task's data as tables), then
//! one section per part of the course project the task has, in the course's
//! order — metric synthesis, structure and kinematics, kinetostatics,
//! dynamics and the flywheel, the gear pair, the planetary train, the cam.
//! Each section has the statement (assumptions, given data, method, what is
//! sought), the formulas used, the figures (the run's own SVG drawings), the
//! results as tables and the conclusions with the numbers; then the list of
//! sources and the appendices with the 12-position tables.
//!
//! Every word comes from `lang/body/{ru,uk,en}.toml` ([`Words`]); every
//! number is read from the report and printed with [`DIGITS`] significant
//! digits (angles in degrees) by [`crate::number::format_number`].

mod appendix;
mod assignment;
mod cam;
mod context;
mod cylinder;
mod dynamics;
mod forces;
mod frame_parts;
mod gear;
mod group_equations;
mod linkage;
mod order;
mod planetary;
mod references;
mod stroke;
mod structure;
mod synthesis;
mod words;

pub use context::DIGITS;
pub use words::Words;

use tmm_report::TaskSource;
use tmm_report::project::Language;
use tmm_report::run::Run;

use crate::error::NoteError;
use crate::model::{Lang, Note, ProjectInfo};
use context::Ctx;
use frame_parts::Part;

/// The note's language for a run's language.
///
/// ```
/// use tmm_report::project::Language;
/// assert_eq!(tmm_note::compose::lang_of(Language::Uk), tmm_note::Lang::Uk);
/// ```
pub fn lang_of(l: Language) -> Lang {
    match l {
        Language::Ru => Lang::Ru,
        Language::Uk => Lang::Uk,
        Language::En => Lang::En,
    }
}

/// A section's composer: its part of the note, if the run has it.
type SectionBuilder = fn(&Ctx) -> Result<Option<crate::model::Section>, NoteError>;

/// Composes the note of `run` (computed from `task`) in the run's language.
///
/// ```no_run
/// use tmm_report::{TaskSource, run::{run_task, DEFAULT_TASK}};
/// let task = TaskSource::new("t.toml", DEFAULT_TASK);
/// let run = run_task(&task).unwrap();
/// let note = tmm_note::compose::compose(&run, &task).unwrap();
/// assert!(note.sections.len() >= 5);
/// let pdf = tmm_note::typeset(&note).unwrap();
/// assert!(pdf.starts_with(b"%PDF"));
/// ```
///
/// # Errors
/// [`NoteError::MissingValue`] if the report lacks a value the note prints,
/// [`NoteError::Translation`] if a words file lacks a key, a formatting error
/// for a non-finite number.
pub fn compose(run: &Run, task: &TaskSource) -> Result<Note, NoteError> {
    let lang = lang_of(run.project.lang);
    let words = Words::load(lang)?;
    let task_table: toml::Table = toml::from_str(&task.text).unwrap_or_default();
    // the drawings again, made for the note's page (the run's are the sheets')
    let figures = tmm_report::run::note_figures(task, Some(run.project.lang)).map_err(|e| NoteError::Figures { message: e.to_string() })?;
    let cx = Ctx {
        lang,
        words: &words,
        report: &run.report,
        docs: &run.docs,
        figures: &figures,
        task: &task_table,
    };
    let p = &run.project;
    let designation = if p.designation.is_empty() {
        String::new()
    } else {
        format!("{} {}", p.designation, words.get("doc_code")?)
    };
    let project = ProjectInfo {
        university: p.university.clone(),
        department: p.department.clone(),
        student: p.student.clone(),
        group: p.group.clone(),
        teacher: p.teacher.clone(),
        variant: p.variant.clone(),
        city: p.city.clone(),
        year: p.year.clone(),
        // no empty «» on the title page: a task without a title is named
        // by the course's topic, as the introduction names it
        title: if p.title.trim().is_empty() {
            words.get("intro_default_topic")?.to_string()
        } else {
            p.title.clone()
        },
        designation,
    };
    let mut sections = Vec::new();
    // each builder with the name of its part (the introduction names the
    // aims of the parts the note has, and of no other)
    let builders: [(Part, SectionBuilder); 9] = [
        (Part::Synthesis, synthesis::section),
        (Part::Linkage, linkage::section),
        (Part::Forces, forces::section),
        (Part::Dynamics, dynamics::section),
        (Part::Stroke, stroke::section),
        (Part::Gear, gear::section),
        (Part::Planetary, planetary::section),
        (Part::Cam, cam::section),
        (Part::Cylinder, cylinder::section),
    ];
    let mut parts = Vec::new();
    for (part, b) in builders {
        if let Some(s) = b(&cx)? {
            sections.push(s);
            parts.push(part);
        }
    }
    references::add(&cx, &mut sections)?;
    // The dynamics' six diagrams (each about a third of a page) stay after
    // its two tables (of nine and four rows, kept whole): moved before them,
    // they left the lower third of two pages empty, for the tables did not
    // fit under two diagrams and no text came between; after them, the
    // conclusions' paragraphs flow under the diagrams (GOST 2.105-95, 4.3.1).
    for (s, part) in sections.iter_mut().zip(&parts) {
        if *part != Part::Dynamics {
            order::figures_early(std::slice::from_mut(s));
        }
    }
    references::join_figure_runs(lang, &mut sections);
    let mut sources = Vec::new();
    for i in 1.. {
        match words.get(&format!("source_{i}")) {
            Ok(s) => sources.push(s.to_string()),
            Err(_) => break,
        }
    }
    Ok(Note {
        lang,
        frame: p.frame,
        assignment: assignment::blocks(&cx)?,
        introduction: frame_parts::introduction(&cx, &project.title, &sections, &parts)?,
        conclusion: frame_parts::conclusion(&cx, &sections)?,
        project,
        sections,
        sources,
        appendices: appendix::appendices(&cx)?,
    })
}
