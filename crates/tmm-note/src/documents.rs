//! The PDF documents of a run (документы в PDF): the explanatory note and
//! one PDF per drawing sheet, made in memory from a [`Run`] — the same
//! bytes whether the command line writes them or the browser page offers
//! them for download.

use tmm_report::TaskSource;
use tmm_report::output::Documents;
use tmm_report::run::Run;

use crate::NoteError;

/// A stage of [`pdf_documents`], for a caller that shows progress.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stage {
    /// The note is being composed and typeset.
    Note,
    /// The sheets (their count) are being typeset.
    Sheets(usize),
}

/// Why one of the PDFs could not be made: which document, and the
/// typesetter's error.
#[derive(Debug, Clone, PartialEq)]
pub struct DocumentError {
    /// `the note` or the sheet's path (`sheets/sheet-2.svg`).
    pub what: String,
    /// The typesetter's error.
    pub error: NoteError,
}

impl std::fmt::Display for DocumentError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "cannot typeset {}: {}", self.what, self.error)
    }
}

impl std::error::Error for DocumentError {}

/// The note of `run` (made from `task`) as PDF bytes.
///
/// # Errors
/// As [`crate::compose`] and [`crate::typeset`].
pub fn note_pdf(run: &Run, task: &TaskSource) -> Result<Vec<u8>, DocumentError> {
    let err = |error| DocumentError {
        what: "the note".into(),
        error,
    };
    let note = crate::compose(run, task).map_err(err)?;
    crate::typeset(&note).map_err(err)
}

/// The PDF documents of a run: `note.pdf` and `sheets/sheet-N.pdf` for
/// every `sheets/sheet-N.svg` of the run (each sheet's PDF is the page of
/// its SVG's size with the SVG on it, [`crate::sheet_pdf`]). `stage` is
/// called before each stage.
///
/// ```no_run
/// use tmm_report::{TaskSource, run::{run_task_in, DEFAULT_TASK}};
/// let task = TaskSource::new("t.toml", DEFAULT_TASK);
/// let run = run_task_in(&task, None).unwrap();
/// let docs = tmm_note::documents::pdf_documents(&run, &task, |_| {}).unwrap();
/// assert!(docs.get("note.pdf").unwrap().bytes.starts_with(b"%PDF"));
/// assert!(docs.get("sheets/sheet-1.pdf").is_some());
/// ```
///
/// # Errors
/// A [`DocumentError`] naming the document that could not be typeset.
pub fn pdf_documents(run: &Run, task: &TaskSource, mut stage: impl FnMut(Stage)) -> Result<Documents, DocumentError> {
    let mut docs = Documents::new();
    stage(Stage::Note);
    add(&mut docs, "note.pdf", note_pdf(run, task)?)?;
    let sheets: Vec<_> = run
        .docs
        .iter()
        .filter(|d| d.path.starts_with("sheets/") && d.path.ends_with(".svg"))
        .collect();
    if !sheets.is_empty() {
        stage(Stage::Sheets(sheets.len()));
    }
    for d in sheets {
        let err = |error| DocumentError {
            what: d.path.clone(),
            error,
        };
        let svg = d.as_text().ok_or_else(|| {
            err(NoteError::Figures {
                message: format!("{} is not text", d.path),
            })
        })?;
        let pdf = crate::sheet_pdf(svg).map_err(err)?;
        add(&mut docs, &format!("{}.pdf", d.path.trim_end_matches(".svg")), pdf)?;
    }
    Ok(docs)
}

/// Add one PDF to `docs` (a path the run's documents cannot refuse: a
/// refusal is reported as the document's error, never a panic).
fn add(docs: &mut Documents, path: &str, pdf: Vec<u8>) -> Result<(), DocumentError> {
    docs.add_bytes(path, pdf).map_err(|e| DocumentError {
        what: path.to_string(),
        error: NoteError::Figures { message: e.to_string() },
    })
}
