//! What a section of a task produces, and the helpers that write it.

use std::path::{Path, PathBuf};

use crate::Error;

/// The result of running one section of a task (`linkage`, `gear`, …).
#[derive(Debug, Clone)]
pub struct SectionOutput {
    /// The section name (`linkage`, `forces`, `gear`, `planetary`, `cam`).
    pub section: &'static str,
    /// Human-readable tables.
    pub text: String,
    /// The section's JSON document (SI, angles in rad).
    pub json: serde_json::Value,
    /// Files written.
    pub files: Vec<PathBuf>,
}

/// Write a text file, creating its folder; remember the path.
pub fn write_file(path: &Path, contents: &str, files: &mut Vec<PathBuf>) -> Result<(), Error> {
    if let Some(dir) = path.parent() {
        if !dir.as_os_str().is_empty() {
            std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
        }
    }
    std::fs::write(path, contents).map_err(|e| Error::io(path, e))?;
    files.push(path.to_path_buf());
    Ok(())
}

/// Create an output folder.
pub fn ensure_dir(dir: &Path) -> Result<(), Error> {
    std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))
}

/// `true` when no number anywhere in the JSON value is non-finite. serde_json
/// turns NaN into `null`, so call this on the numbers before building the
/// value, or use [`num`].
pub fn num(x: f64) -> serde_json::Value {
    if x.is_finite() {
        serde_json::Value::from(x)
    } else {
        serde_json::Value::Null
    }
}
