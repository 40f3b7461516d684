//! `tmm run`: every section of a task file, in the order of the course
//! project, into one output folder (`./tmm-out/` by default).

use std::path::Path;

use crate::output::write_file;
use crate::{Error, SectionOutput, TaskSource, cam, forces, gear, linkage, planetary};

/// The embedded default course project (`tmm run` with no file).
pub const DEFAULT_TASK: &str = include_str!("../tasks/default.toml");

/// The name shown for the embedded default task in messages.
pub const DEFAULT_TASK_NAME: &str = "<embedded default task>";

type Runner = fn(&TaskSource, &Path) -> Result<Option<SectionOutput>, Error>;

/// The sections in the order of the course project.
const RUNNERS: &[Runner] = &[
    linkage::run_section,
    forces::run_section,
    gear::run_section,
    planetary::run_section,
    cam::run_section,
];

/// Run every section the task has; write `report.json` (all sections' JSON
/// under their names, `"units": "SI"`) and each section's files under `out`.
pub fn run_task(task: &TaskSource, out: &Path) -> Result<Vec<SectionOutput>, Error> {
    let table = task.check_sections()?;
    if !table.keys().any(|k| k != "title") {
        return Err(Error::input(&task.name, "the task file has no section to run")
            .with_help(format!("add one of {}", crate::task::SECTIONS[1..].join(", "))));
    }
    let mut outs = Vec::new();
    for run in RUNNERS {
        if let Some(o) = run(task, out)? {
            outs.push(o);
        }
    }
    let mut doc = serde_json::Map::new();
    doc.insert("units".into(), "SI".into());
    if let Some(toml::Value::String(t)) = table.get("title") {
        doc.insert("title".into(), t.clone().into());
    }
    for o in &outs {
        doc.insert(o.section.into(), o.json.clone());
    }
    let mut files = Vec::new();
    let text = serde_json::to_string_pretty(&serde_json::Value::Object(doc)).map_err(|e| Error::Io(e.to_string()))?;
    write_file(&out.join("report.json"), &text, &mut files)?;
    Ok(outs)
}
