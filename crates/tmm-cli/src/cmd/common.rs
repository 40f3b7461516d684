//! Helpers shared by the subcommands: reading a task file, printing JSON and
//! text, writing the requested files and saying what was written.

use std::path::{Path, PathBuf};

use tmm_report::output::{Document, Documents, check_finite_in, to_json_text};
use tmm_report::{Error, TaskSource};

use crate::write::{self, Existing};

/// The largest task file read, in bytes (4 MiB; the largest example is a
/// few KB): a larger file, an endless device or a pipe that keeps writing is
/// refused after reading one byte more.
pub const MAX_TASK_BYTES: u64 = 4 << 20;

/// Read a task file; a missing, unreadable or too large file is bad input
/// (exit code 2).
pub fn read_task(path: &Path) -> Result<TaskSource, Error> {
    use std::io::Read;
    let name = path.display().to_string();
    let unreadable = |e: std::io::Error| Error::input(&name, format!("cannot read the task file: {e}"));
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_TASK_BYTES + 1).read_to_end(&mut bytes))
        .map_err(unreadable)?;
    if bytes.len() as u64 > MAX_TASK_BYTES {
        return Err(Error::input(
            &name,
            format!("the task file is larger than {MAX_TASK_BYTES} bytes (4 MiB), the most tmm reads; a task file is a few KB of TOML"),
        ));
    }
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

/// Write the drawings of a subcommand's `--svg DIR` into `dir`: a new or
/// tmm-made folder is replaced as a whole, an empty one written into; into
/// any other folder the files are added one by one, deleting nothing and
/// refusing to replace a file tmm did not write.
pub fn write_dir(dir: &Path, docs: &Documents) -> Result<Vec<PathBuf>, Error> {
    write::write_folder(dir, docs, Existing::AddFiles, "--svg")
}

/// Write documents into the folder `dir` given as `option` (`tmm note
/// --out DIR`), as [`write_dir`] does.
pub fn write_into(dir: &Path, docs: &Documents, option: &str) -> Result<Vec<PathBuf>, Error> {
    write::write_folder(dir, docs, Existing::AddFiles, option)
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
