//! `tmm run`: every section of a task file, in the order of the course
//! project, computed in memory. Every section is validated and computed
//! before anything is handed out, so a bad section leaves no partial run.

use crate::output::{Documents, to_json_text};
use crate::{Error, SectionOutput, TaskSource, cam, cylinder, dynamics, forces, gear, linkage, planetary, synthesis};

/// The embedded default course project (`tmm run` with no file).
pub const DEFAULT_TASK: &str = include_str!("../tasks/default.toml");

/// The name shown for the embedded default task in messages.
pub const DEFAULT_TASK_NAME: &str = "<embedded default task>";

type Runner = fn(&TaskSource) -> Result<Option<SectionOutput>, Error>;

/// The sections in the order of the course project.
const RUNNERS: &[Runner] = &[
    synthesis::run_section,
    linkage::run_section,
    forces::run_section,
    dynamics::run_section,
    gear::run_section,
    planetary::run_section,
    cam::run_section,
    cylinder::run_section,
];

/// Everything a run produces, in memory.
#[derive(Debug, Clone)]
pub struct Run {
    /// Each section's tables, JSON and documents, in course order.
    pub sections: Vec<SectionOutput>,
    /// The combined JSON report: `"units": "SI"` first, the task's title,
    /// then each section under its name.
    pub report: serde_json::Value,
    /// The `[project]` data (title page, title block, language, format).
    pub project: crate::project::Project,
    /// Every file of the run (`report.json` first, then each section's),
    /// paths relative to the output folder.
    pub docs: Documents,
}

/// Run every section the task has, in memory.
///
/// ```
/// use tmm_report::run::{run_task, DEFAULT_TASK};
/// let run = run_task(&tmm_report::TaskSource::new("t.toml", DEFAULT_TASK)).unwrap();
/// assert_eq!(run.report.as_object().unwrap().keys().next().unwrap(), "units");
/// assert!(run.docs.get("report.json").is_some());
/// assert!(run.docs.get("linkage/positions.svg").is_some());
/// ```
pub fn run_task(task: &TaskSource) -> Result<Run, Error> {
    run_task_in(task, None)
}

/// Run every section, with the drawings' words in `lang` (the `[project]`
/// language when `None`).
///
/// ```
/// use tmm_report::{TaskSource, project::Language, run::{run_task_in, DEFAULT_TASK}};
/// let run = run_task_in(&TaskSource::new("t.toml", DEFAULT_TASK), Some(Language::En)).unwrap();
/// assert_eq!(run.project.lang, Language::En);
/// ```
pub fn run_task_in(task: &TaskSource, lang: Option<crate::project::Language>) -> Result<Run, Error> {
    let prepared = prepare(task, lang)?;
    let mut sections = Vec::new();
    for run in RUNNERS {
        if let Some(o) = run(&prepared.task)? {
            sections.push(o);
        }
    }
    assemble(&prepared, sections)
}

/// A task made ready for its sections: the top-level tables as the user
/// wrote them, the `[project]` data, and the task as the sections read it
/// (language and sheet applied, a synthesised `[linkage]` written in).
#[derive(Debug, Clone)]
pub struct Prepared {
    /// The top-level tables of the text the user wrote.
    pub table: toml::Table,
    /// The `[project]` data (with the language asked for).
    pub project: crate::project::Project,
    /// The task as the sections read it.
    pub task: TaskSource,
}

/// The drawings of a run made for the explanatory note's page
/// ([`SheetFormat::A4`](crate::project::SheetFormat::A4)): each drawing
/// the note shows, built again for the note's text width at a standard
/// scale that fits, every letter and index raised to capitals of 2.5 mm
/// ([`crate::labels::MIN_EM`]), so the note prints it at its own size, its
/// "М 1:n" and μ are what the page shows and nothing is under GOST 2.304. Only the
/// drawings (SVG) are kept; the sheets are not laid out. Called by the note
/// when one is asked for, so a run without a note pays nothing for it.
///
/// ```
/// use tmm_report::{TaskSource, run::{note_figures, DEFAULT_TASK}};
/// let figs = note_figures(&TaskSource::new("t.toml", DEFAULT_TASK), None).unwrap();
/// let p = figs.picture("linkage/positions.svg").unwrap();
/// assert!(p.width <= tmm_report::paper::NOTE_WIDTH_MM && p.height <= tmm_report::paper::NOTE_HEIGHT_MM);
/// assert!(figs.get("sheets/sheet-1.svg").is_none() && figs.get("gear/mesh.dxf").is_none());
/// ```
pub fn note_figures(task: &TaskSource, lang: Option<crate::project::Language>) -> Result<Documents, Error> {
    let prepared = prepare(task, lang)?;
    let task = prepared.task.with_sheet(crate::project::SheetFormat::A4);
    let mut out = Documents::for_task(&task);
    // no capital under GOST 2.304's 2.5 mm in the faces that print the note
    crate::labels::with_lettering_floor(crate::labels::MIN_EM, || {
        for run in RUNNERS {
            if let Some(o) = run(&task)? {
                for d in o.docs.iter().filter(|d| d.path.ends_with(".svg")) {
                    // the name left out (the caption under the figure
                    // names it: GOST 2.105, one title per figure), the
                    // scale and parameters kept, then cut to its content:
                    // the page holds no empty paper
                    match o.docs.picture(&d.path) {
                        Some(p) => out.add_text(
                            d.path.clone(),
                            crate::crop::cropped(p.without_title(), crate::crop::MARGIN_MM, crate::crop::GAP_MM),
                        )?,
                        None => out.add_copy(&o.docs, d),
                    }
                }
            }
        }
        Ok::<(), Error>(())
    })?;
    Ok(out)
}

/// Check the task's sections, read `[project]` and write in the mechanism
/// a `[synthesis]` without `[linkage]` gives; the first step of
/// [`run_task_in`], for a caller that runs the sections one by one
/// ([`run_section`]) and puts them together with [`assemble`].
///
/// ```
/// use tmm_report::{TaskSource, run::{prepare, DEFAULT_TASK}};
/// let p = prepare(&TaskSource::new("t.toml", DEFAULT_TASK), None).unwrap();
/// assert!(p.table.contains_key("gear"));
/// ```
pub fn prepare(task: &TaskSource, lang: Option<crate::project::Language>) -> Result<Prepared, Error> {
    let table = task.check_sections()?;
    let mut project = crate::project::load(task)?;
    if let Some(l) = lang {
        project.lang = l;
    }
    let task = task.clone().with_lang(project.lang).with_sheet(project.sheet);
    if !table.keys().any(|k| k != "title" && k != "project") {
        return Err(task
            .missing("task file", "the task file has no section to run")
            .with_help(format!("add one of {}", crate::task::SECTIONS[2..].join(", "))));
    }
    // [synthesis] without [linkage]: the other sections see the synthesised one
    let task = synthesis::with_linkage(&task)?.into_owned();
    Ok(Prepared { table, project, task })
}

/// The sections in the order of the course project, each with the
/// top-level tables of the task it reads (besides the language and sheet,
/// which come from `[project]`): a section's output depends on these only.
pub const SECTION_TABLES: &[(&str, &[&str])] = &[
    ("synthesis", &["title", "project", "synthesis", "linkage"]),
    ("linkage", &["title", "project", "synthesis", "linkage"]),
    ("forces", &["title", "project", "synthesis", "linkage", "forces"]),
    ("dynamics", &["title", "project", "synthesis", "linkage", "forces", "dynamics"]),
    ("gear", &["title", "project", "gear"]),
    ("planetary", &["title", "project", "planetary"]),
    ("cam", &["title", "project", "cam"]),
    ("cylinder", &["title", "project", "cylinder"]),
];

/// Run one section (a name of [`SECTION_TABLES`]) of a task made ready by
/// [`prepare`]; `None` when the task has no such section.
///
/// ```
/// use tmm_report::{TaskSource, run::{prepare, run_section, DEFAULT_TASK}};
/// let p = prepare(&TaskSource::new("t.toml", DEFAULT_TASK), None).unwrap();
/// let gear = run_section("gear", &p.task).unwrap().unwrap();
/// assert!(gear.docs.get("gear/contour.svg").is_some());
/// assert!(run_section("no such", &p.task).unwrap().is_none());
/// ```
pub fn run_section(name: &str, task: &TaskSource) -> Result<Option<SectionOutput>, Error> {
    match SECTION_TABLES.iter().position(|(n, _)| *n == name) {
        Some(i) => RUNNERS[i](task),
        None => Ok(None),
    }
}

/// A section's output in two stages: the tables and the JSON at once, the
/// drawings (the section's SVG, DXF and CSV files) only when asked — for
/// a caller that shows the numbers first and a drawing when it is looked
/// at. `output` and the documents of `draw` together are what
/// [`run_section`] gives.
pub struct Staged {
    /// The section's tables, JSON and the documents made without drawing.
    pub output: SectionOutput,
    /// Make the section's drawings.
    pub draw: Box<dyn Fn() -> Result<Documents, Error>>,
}

impl std::fmt::Debug for Staged {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Staged").field("output", &self.output).finish_non_exhaustive()
    }
}

impl Staged {
    /// The section's drawings (see [`Staged`]).
    pub fn drawings(&self) -> Result<Documents, Error> {
        (self.draw)()
    }
}

/// Run one section (a name of [`SECTION_TABLES`]) in two stages (see
/// [`Staged`]): `linkage`, `forces` and `dynamics` defer their drawings;
/// the other sections are computed whole and have no drawings left to make.
///
/// ```
/// use tmm_report::{TaskSource, run::{prepare, run_section, run_staged, DEFAULT_TASK}};
/// let p = prepare(&TaskSource::new("t.toml", DEFAULT_TASK), None).unwrap();
/// let s = run_staged("linkage", &p.task).unwrap().unwrap();
/// assert!(s.output.docs.get("linkage/positions.svg").is_none());
/// let drawn = s.drawings().unwrap();
/// let whole = run_section("linkage", &p.task).unwrap().unwrap();
/// assert_eq!(drawn.get("linkage/positions.svg").unwrap().bytes, whole.docs.get("linkage/positions.svg").unwrap().bytes);
/// ```
pub fn run_staged(name: &str, task: &TaskSource) -> Result<Option<Staged>, Error> {
    match name {
        "linkage" => linkage::run_staged(task),
        "forces" => forces::run_staged(task),
        "dynamics" => dynamics::run_staged(task),
        _ => Ok(run_section(name, task)?.map(|output| Staged {
            output,
            draw: Box::new(|| Ok(Documents::new())),
        })),
    }
}

/// Put the sections' outputs (in course order) together into a run: the
/// combined report and the files.
pub fn assemble(prepared: &Prepared, sections: Vec<SectionOutput>) -> Result<Run, Error> {
    let mut doc = serde_json::Map::new();
    doc.insert("units".into(), "SI".into());
    if let Some(toml::Value::String(t)) = prepared.table.get("title") {
        doc.insert("title".into(), t.clone().into());
    }
    for o in &sections {
        doc.insert(o.section.into(), o.json.clone());
    }
    let report = serde_json::Value::Object(doc);
    let mut docs = Documents::for_task(&prepared.task);
    docs.add_text("report.json", to_json_text(&report))?;
    for o in &sections {
        docs.append(o.docs.clone());
    }
    // the drawing sheets, made of the drawings above
    let sheets = crate::sheets::sheet_documents(&docs, &prepared.project)?;
    docs.append(sheets);
    Ok(Run {
        sections,
        report,
        project: prepared.project.clone(),
        docs,
    })
}
