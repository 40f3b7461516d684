//! `tmm note [FILE] [--lang ru|uk|en] [--out DIR]`: the explanatory note
//! (пояснительная записка) of a task file as `DIR/note.pdf`; also the
//! typesetting shared with `tmm run` (the note and the sheets' PDFs).

use std::path::PathBuf;

use tmm_report::output::Documents;
use tmm_report::project::Language;
use tmm_report::run::{DEFAULT_TASK, DEFAULT_TASK_NAME, Run, run_task_in};
use tmm_report::{Error, TaskSource};

use super::common::{print, read_task, write_into, written};

/// The note of a task file as PDF.
#[derive(clap::Args)]
pub struct Args {
    /// The task file (TOML); without it, the embedded default course project
    pub file: Option<PathBuf>,
    /// The language of the note (default: the task's [project] lang, else ru)
    #[arg(long, value_parser = ["ru", "uk", "en"])]
    pub lang: Option<String>,
    /// The folder note.pdf is written into (an existing note.pdf that tmm did not write is never replaced)
    #[arg(short, long, default_value = ".")]
    pub out: PathBuf,
}

/// The language of a `--lang` value (clap has already checked it).
pub fn language(code: Option<&str>) -> Option<Language> {
    code.and_then(Language::from_code)
}

/// The task of a command line: the file, or the embedded default.
pub fn task_of(file: Option<&PathBuf>) -> Result<TaskSource, Error> {
    match file {
        Some(p) => read_task(p),
        None => Ok(TaskSource::new(DEFAULT_TASK_NAME, DEFAULT_TASK)),
    }
}

/// One progress line on standard error (a closed stderr is ignored).
pub fn progress(line: &str) {
    use std::io::Write;
    let _ = writeln!(std::io::stderr().lock(), "tmm: {line}");
}

/// A typesetting failure: the note or a sheet could not be produced
/// (exit code 1, as a failed write: the input was accepted).
fn typeset_error(e: &tmm_note::documents::DocumentError) -> Error {
    Error::Io(e.to_string())
}

/// One line on standard error when the PDFs are made without the GOST
/// lettering font, saying how to install it ([`tmm_note::fonts`]).
fn gost_font_notice() {
    if tmm_note::fonts::gost_font().is_none() {
        progress(tmm_note::fonts::INSTALL_HINT);
    }
}

/// The note of `run` as PDF bytes.
pub fn note_pdf(run: &Run, task: &TaskSource) -> Result<Vec<u8>, Error> {
    gost_font_notice();
    tmm_note::documents::note_pdf(run, task).map_err(|e| typeset_error(&e))
}

/// The PDF documents of a run (`note.pdf`, `sheets/sheet-N.pdf`; see
/// [`tmm_note::documents::pdf_documents`]), with a progress line per stage.
pub fn pdf_documents(run: &Run, task: &TaskSource) -> Result<Documents, Error> {
    use tmm_note::documents::Stage;
    gost_font_notice();
    tmm_note::documents::pdf_documents(run, task, |stage| match stage {
        Stage::Note => progress("typesetting the note"),
        Stage::Sheets(n) => progress(&format!("typesetting {n} sheet(s)")),
    })
    .map_err(|e| typeset_error(&e))
}

/// Run the command.
pub fn run(a: &Args) -> Result<(), Error> {
    let task = task_of(a.file.as_ref())?;
    progress("computing");
    let run = run_task_in(&task, language(a.lang.as_deref()))?;
    progress("typesetting the note");
    let pdf = note_pdf(&run, &task)?;
    progress("writing");
    let mut docs = Documents::new();
    docs.add_bytes("note.pdf", pdf)?;
    let files = write_into(&a.out, &docs, "--out")?;
    print(&written(&files))
}
