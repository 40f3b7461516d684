//! Helpers shared by the subcommands: reading a task file, printing JSON and
//! text, writing the requested files and saying what was written.

use std::path::{Path, PathBuf};

use tmm_report::output::{Document, Documents, check_finite_in, to_json_text};
use tmm_report::{Error, TaskSource};

use crate::write::{self, Existing};

/// Read a task file; a missing or unreadable file is bad input (exit code 2).
pub fn read_task(path: &Path) -> Result<TaskSource, Error> {
    let name = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|e| Error::input(&name, format!("cannot read the task file: {e}")))?;
    let text = tmm_report::task::text_of(&name, bytes)?;
    let task = TaskSource::new(name, text);
    let _ = EXCUSED.set(tmm_report::user_text::excused(&task));
    // the drawings speak the [project]'s language; a bad [project] is
    // reported by the section that reads it
    let p = tmm_report::project::load(&task).unwrap_or_default();
    Ok(task.with_lang(p.lang).with_sheet(p.sheet))
}

/// The user's text of the task this process read, which the non-finite
/// check of standard output lets pass (a link named `inf`); set once by
/// [`read_task`], since one `tmm` process reads one task.
static EXCUSED: std::sync::OnceLock<Vec<String>> = std::sync::OnceLock::new();

/// The user's text that the non-finite check of what is printed lets pass
/// (see [`tmm_report::output::check_finite_in`]).
pub fn excused() -> &'static [String] {
    EXCUSED.get().map_or(&[], Vec::as_slice)
}

/// A JSON document as the text printed on stdout, checked for non-finite
/// numbers before anything is written.
pub fn json_text(v: &serde_json::Value) -> Result<String, Error> {
    let mut s = to_json_text(v);
    s.push('\n');
    checked(s)
}

/// Text for stdout, checked for non-finite numbers before anything is written.
pub fn checked(text: String) -> Result<String, Error> {
    check_finite_in(&Document::text("standard output", text.as_str()), excused())?;
    Ok(text)
}

/// Print text on stdout (a closed pipe ends quietly).
pub fn print(text: &str) -> Result<(), Error> {
    write::print(text)
}

/// Write the drawings of a subcommand's `--svg DIR` into `dir`: a new, empty
/// or tmm-made folder is replaced as a whole; into any other folder the files
/// are added one by one, deleting nothing.
pub fn write_dir(dir: &Path, docs: &Documents) -> Result<Vec<PathBuf>, Error> {
    write::write_folder(dir, docs, Existing::AddFiles)
}

/// Write single files named on the command line (`--svg mesh.svg`), all or none.
pub fn write_named(files: &[(PathBuf, Vec<u8>)]) -> Result<Vec<PathBuf>, Error> {
    let refs: Vec<(PathBuf, &[u8])> = files.iter().map(|(p, b)| (p.clone(), b.as_slice())).collect();
    write::write_files(&refs)?;
    Ok(files.iter().map(|f| f.0.clone()).collect())
}

/// The one wording of "these files were written", for every subcommand.
pub fn written(files: &[PathBuf]) -> String {
    if files.is_empty() {
        return String::new();
    }
    let mut s = String::from("\nFiles written:\n");
    for f in files {
        s.push_str(&format!("  {}\n", f.display()));
    }
    s
}
