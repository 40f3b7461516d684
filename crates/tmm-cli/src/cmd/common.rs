//! Helpers shared by the subcommands: reading a task file, printing JSON.

use std::path::Path;

use tmm_report::{Error, TaskSource};

/// Read a task file; a missing or unreadable file is bad input (exit code 2).
pub fn read_task(path: &Path) -> Result<TaskSource, Error> {
    let text =
        std::fs::read_to_string(path).map_err(|e| Error::input(&path.display().to_string(), format!("cannot read the task file: {e}")))?;
    Ok(TaskSource::new(path.display().to_string(), text))
}

/// Print one JSON document on stdout.
pub fn print_json(v: &serde_json::Value) -> Result<(), Error> {
    let s = serde_json::to_string_pretty(v).map_err(|e| Error::Io(e.to_string()))?;
    println!("{s}");
    Ok(())
}
