//! The explanatory note (пояснительная записка) of the TMM course project,
//! typeset to PDF.
//!
//! The caller builds a [`Note`] — the project's data, the technical
//! assignment, numbered [`Section`]s of [`Block`]s (paragraphs, formulas,
//! tables, SVG figures, lists), the sources and the appendices — and
//! [`typeset`] turns it into a PDF with the `typst` compiler linked into the
//! binary: no external program runs, the fonts are embedded.
//!
//! The layout follows GOST 2.105 (text documents) and GOST 2.104 (the frame
//! and the title block forms 2 and 2a, drawn to the standard's dimensions
//! when [`Note::frame`] is set); see `docs/note.md`. Every fixed word comes
//! from the translation files `lang/{ru,uk,en}.toml` ([`Translation`]).
//!
//! ```no_run
//! use tmm_note::{Block, Lang, Note, Section, Text, typeset};
//! let mut note = Note { lang: Lang::Uk, ..Note::default() };
//! note.project.student = "Іваненко І. І.".into();
//! let mut s = Section::new("Структурний аналіз механізму");
//! s.blocks.push(Block::Paragraph(Text::plain("Механізм має один ступінь вільності.")));
//! note.sections.push(s);
//! let pdf = typeset(&note).unwrap();
//! assert!(pdf.starts_with(b"%PDF"));
//! ```

pub mod calc;
pub mod compose;
pub mod documents;
pub mod error;
pub mod escape;
pub mod fonts;
pub mod markup;
pub mod model;
pub mod notation;
pub mod number;
pub mod numbering;
pub mod sheet;
pub mod translation;
pub mod world;

pub use compose::compose;
pub use error::NoteError;
pub use model::{Block, Cell, Lang, Note, ProjectInfo, Section, Span, Text};
pub use sheet::sheet_pdf;
pub use translation::Translation;

use typst::WorldExt;
use typst::diag::{Severity, SourceDiagnostic};
use typst::layout::{Frame, FrameItem};
use typst_layout::PagedDocument;

use crate::world::NoteWorld;

/// A typeset note: the PDF and what the compiler warned about.
#[derive(Debug, Clone, PartialEq)]
pub struct Typeset {
    /// The PDF file's bytes.
    pub pdf: Vec<u8>,
    /// The count of pages.
    pub pages: usize,
    /// Warnings: typst's own (each with its file and line) and every
    /// character no embedded font has a glyph for. A correct note has none.
    pub warnings: Vec<String>,
}

/// Typesets `note` to PDF bytes.
///
/// Warnings (see [`Typeset::warnings`]) do not stop the PDF; use
/// [`typeset_with_warnings`] to see them.
///
/// # Errors
/// A [`NoteError`] for a malformed note (bad label, unknown reference,
/// non-finite number, ragged table …), or [`NoteError::Typst`] if a formula
/// or an SVG figure cannot be read.
pub fn typeset(note: &Note) -> Result<Vec<u8>, NoteError> {
    typeset_with_warnings(note).map(|t| t.pdf)
}

/// Typesets `note` and returns the PDF with the warnings.
///
/// # Errors
/// As [`typeset`].
pub fn typeset_with_warnings(note: &Note) -> Result<Typeset, NoteError> {
    let tr = Translation::load(note.lang)?;
    let generated = markup::generate(note, &tr)?;
    let world = NoteWorld::new(generated.main, generated.figures)?;
    let result = typst::compile::<PagedDocument>(&world);
    // Drop memoized results unused for 10 compilations, so a long-lived
    // process typesetting many notes does not grow without bound.
    typst::comemo::evict(10);
    let mut warnings: Vec<String> = result.warnings.iter().map(|d| describe(&world, d)).collect();
    let document = result.output.map_err(|errors| NoteError::Typst {
        messages: errors.iter().map(|d| describe(&world, d)).collect(),
    })?;
    warnings.extend(missing_glyphs(&document));
    let pdf = typst_pdf::pdf(&document, &typst_pdf::PdfOptions::default()).map_err(|errors| NoteError::Pdf {
        messages: errors.iter().map(|d| describe(&world, d)).collect(),
    })?;
    Ok(Typeset {
        pdf,
        pages: document.pages().len(),
        warnings,
    })
}

/// A diagnostic as one line: `warning: /main.typ:12: message (hint: …)`.
fn describe(world: &NoteWorld, d: &SourceDiagnostic) -> String {
    let kind = match d.severity {
        Severity::Error => "error",
        Severity::Warning => "warning",
    };
    let place = world.describe(d.span.id(), world.range(d.span));
    let mut s = format!("{kind}: {place}: {}", d.message);
    for hint in &d.hints {
        s.push_str(" (hint: ");
        s.push_str(&hint.v);
        s.push(')');
    }
    s
}

/// The characters typeset with no glyph (the font's `.notdef`, id 0), one
/// warning each: typst itself does not warn about them.
fn missing_glyphs(document: &PagedDocument) -> Vec<String> {
    fn walk(frame: &Frame, missing: &mut Vec<char>) {
        for (_, item) in frame.items() {
            match item {
                FrameItem::Group(g) => walk(&g.frame, missing),
                FrameItem::Text(t) => {
                    for g in t.glyphs.iter().filter(|g| g.id == 0) {
                        for c in t.text.get(g.range()).unwrap_or("").chars() {
                            if !missing.contains(&c) {
                                missing.push(c);
                            }
                        }
                    }
                }
                _ => {}
            }
        }
    }
    let mut missing = Vec::new();
    for page in document.pages() {
        walk(&page.frame, &mut missing);
    }
    missing
        .into_iter()
        .map(|c| format!("warning: no embedded font has the character {c:?} (U+{:04X})", u32::from(c)))
        .collect()
}
