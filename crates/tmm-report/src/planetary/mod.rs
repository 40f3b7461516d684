//! The `[planetary]` section of a task file and `tmm planetary`: reading the
//! inputs, running the tooth-number search, and its outputs (tables, JSON,
//! the SVG sheet with the scheme, the velocity picture and the
//! angular-velocity diagram).
//!
//! | file | what |
//! | --- | --- |
//! | [`input`] | the section, the command-line values, located errors |
//! | [`analysis`] | the core run: search, efficiency, picture |
//! | [`text`] | human tables |
//! | [`json`] | the JSON document |
//! | [`drawing`] | the SVG sheet |

// The edge's one error type (`crate::Error`, with the task source for
// located messages) is large by design; `run_section` must return it.

pub mod analysis;
pub mod drawing;
pub mod input;
pub mod json;
pub mod text;

use crate::output::Documents;
use crate::{Error, SectionOutput, TaskSource};

pub use analysis::{Analysis, analyse};
pub use input::{Origin, Params};

/// Run the `[planetary]` section of a task: documents under `planetary/`.
/// Returns `None` when the task has no such section.
pub fn run_section(task: &TaskSource) -> Result<Option<SectionOutput>, Error> {
    let Some((params, origin)) = input::from_task(task)? else {
        return Ok(None);
    };
    let a = analyse(&params, &origin)?;
    let mut docs = Documents::for_task(task);
    let sheet = drawing::sheet(&a, task.lang, task.sheet);
    let text = text::report(&a);
    let json = json::document(&a);
    docs.add_text("planetary/planetary.svg", sheet.svg)?;
    docs.add_json("planetary/planetary.json", &json)?;
    docs.add_text("planetary/planetary.txt", text.clone())?;
    Ok(Some(SectionOutput {
        section: "planetary",
        text,
        json,
        docs,
    }))
}
