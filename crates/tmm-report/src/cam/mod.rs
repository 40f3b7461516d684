//! The `[cam]` section of a task file and `tmm cam`: reading the task,
//! designing the cam with `tmm-cams`, and its outputs — tables, one JSON
//! document, SVG drawings, DXF and CSV of the working profile.
//!
//! | file | concept |
//! | --- | --- |
//! | [`input`] | the section / options → a `CamTask`, located errors |
//! | [`book`] | the textbook's constructions beside the design |
//! | [`text`] | human tables |
//! | [`json`] | the JSON document (SI, rad) |
//! | [`diagrams`] | SVG: the motion diagrams over the cam angle, at round μ |
//! | [`draw`] | SVG: diagrams, sizing diagram, the cam and follower |
//! | [`cad`] | DXF and CSV of the working profile |

// The shared `Error` carries the source text for located messages; it is
// large by design and returned only on the cold path.

pub mod book;
pub mod cad;
pub mod diagrams;
pub mod draw;
pub mod input;
pub mod json;
pub mod text;

use tmm_cams::design::{CamDesign, CamTask};

use crate::output::Documents;
use crate::project::{Language, SheetFormat};
use crate::{Error, SectionOutput, TaskSource};
use input::Locate;

/// Design the cam — the smallest one, or the one with the given base circle
/// radius `r0` — turning a core error into a located input error.
pub fn solve(task: &CamTask, r0: Option<f64>, loc: &Locate<'_>) -> Result<CamDesign, Error> {
    match r0 {
        Some(r) => task.solve_with_r0(r),
        None => task.solve(),
    }
    .map_err(|e| input::cam_error(e, loc))
}

/// The textbook's constructions (`book_methods`), located at that field
/// when they cannot be made; `None` when not asked for.
pub fn book_methods(
    task: &CamTask,
    d: &CamDesign,
    raw: &input::Raw,
    loc: &Locate<'_>,
) -> Result<Option<tmm_cams::textbook::BookMethods>, Error> {
    if !raw.book_methods {
        return Ok(None);
    }
    tmm_cams::textbook::compare(task, d).map(Some).map_err(|e| {
        loc(input::Field::BookMethods, e.to_string()).with_help(
            "the book's constructions take a roller or knife-edge follower and one rise and one return; remove book_methods otherwise",
        )
    })
}

/// The JSON document and the tables, with the textbook's constructions when given.
pub fn outputs(task: &CamTask, d: &CamDesign, b: Option<&tmm_cams::textbook::BookMethods>, step_deg: usize) -> (serde_json::Value, String) {
    let mut json = json::document(task, d);
    let mut text = text::tables(task, d, step_deg);
    if let Some(b) = b {
        if let Some(m) = json.as_object_mut() {
            m.insert("book".into(), book::json(task, d, b));
        }
        text.push_str(&book::text(task, b));
    }
    (json, text)
}

/// The SVG drawings, as documents whose paths start with `dir`
/// (`"cam/"` gives `cam/cam.svg`, …).
pub fn drawings(task: &CamTask, d: &CamDesign, dir: &str, docs: &mut Documents, lang: Language, sheet: SheetFormat) -> Result<(), Error> {
    docs.add_text(format!("{dir}cam.svg"), draw::cam(task, d, lang, sheet))?;
    docs.add_text(format!("{dir}cam-analogs.svg"), draw::analogs(task, lang, sheet))?;
    docs.add_text(format!("{dir}cam-motion.svg"), draw::motion(task, lang, sheet))?;
    docs.add_text(format!("{dir}cam-pressure.svg"), draw::pressure(task, d, lang, sheet))?;
    docs.add_text(format!("{dir}cam-sizing.svg"), draw::sizing_diagram(task, d, lang, sheet))?;
    Ok(())
}

/// The profile as DXF (millimetres, layers).
pub fn profile_dxf(d: &CamDesign) -> Result<Vec<u8>, Error> {
    cad::dxf(d).to_bytes()
}

/// The profile as CSV.
pub fn profile_csv(d: &CamDesign) -> Result<String, Error> {
    cad::csv(d)
}

/// Run the `[cam]` section of a task: documents under `cam/`.
/// Returns `None` when the task has no such section.
pub fn run_section(task: &TaskSource) -> Result<Option<SectionOutput>, Error> {
    let Some((sec, span)) = input::read_section(task)? else {
        return Ok(None);
    };
    let loc = input::file_locator(task, &sec, span);
    let raw = sec.raw();
    let cam = input::build(&raw, &loc)?;
    let d = solve(&cam, input::given_r0(&raw, &loc)?, &loc)?;
    let b = book_methods(&cam, &d, &raw, &loc)?;
    let mut docs = Documents::for_task(task);
    drawings(&cam, &d, "cam/", &mut docs, task.lang, task.sheet)?;
    docs.add_bytes("cam/cam-profile.dxf", profile_dxf(&d)?)?;
    docs.add_text("cam/cam-profile.csv", profile_csv(&d)?)?;
    let (json, text) = outputs(&cam, &d, b.as_ref(), 15);
    docs.add_json("cam/cam.json", &json)?;
    docs.add_text("cam/cam.txt", text.clone())?;
    Ok(Some(SectionOutput {
        section: "cam",
        text,
        json,
        docs,
    }))
}
