//! The errors of typesetting a note.

use thiserror::Error;

/// Why a note could not be typeset.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum NoteError {
    /// A number to print is NaN or infinite.
    #[error("a number in the note is {value}; only finite numbers can be printed")]
    NonFinite {
        /// The value as Rust prints it.
        value: String,
    },
    /// The count of significant digits is out of range.
    #[error("significant digits = {digits}; valid: 1 … 17")]
    Digits {
        /// The rejected count.
        digits: u8,
    },
    /// A label has characters typst labels cannot hold.
    #[error("label {label:?} is not valid; use ASCII letters, digits, '_', '-', '.' or ':', starting with a letter")]
    InvalidLabel {
        /// The rejected label.
        label: String,
    },
    /// Two blocks carry the same label.
    #[error("label {label:?} is given to two blocks; labels must be unique")]
    DuplicateLabel {
        /// The repeated label.
        label: String,
    },
    /// A reference names a label no block carries.
    #[error("reference to {label:?}, but no formula, figure or table has that label")]
    UnknownLabel {
        /// The missing label.
        label: String,
    },
    /// A citation's number is not in the list of sources.
    #[error("citation [{number}] but the list of sources has {count} entries (valid: 1 … {count})")]
    UnknownSource {
        /// The cited number.
        number: usize,
        /// The count of sources.
        count: usize,
    },
    /// A math string contains an unescaped `$`, which would end the formula.
    #[error("formula {math:?} contains an unescaped '$'; write the math without the $ delimiters")]
    MathDelimiter {
        /// The rejected math.
        math: String,
    },
    /// The drawings made for the note's page could not be made (the task
    /// was refused; the run of the same task would have been too).
    #[error("the note's figures: {message}")]
    Figures {
        /// The report's message.
        message: String,
    },
    /// A figure's width is not a positive finite number of millimetres.
    #[error("figure {caption:?}: width_mm = {width_mm}; valid: 1 … 1000 mm")]
    FigureWidth {
        /// The figure's caption.
        caption: String,
        /// The rejected width.
        width_mm: f64,
    },
    /// A table's row has another number of cells than the header, or the
    /// units do not match the columns.
    #[error("table {caption:?}: {what} has {found} cells, the header has {expected}")]
    TableShape {
        /// The table's caption.
        caption: String,
        /// Which part is wrong ("row 3", "units").
        what: String,
        /// The cells found.
        found: usize,
        /// The header's cells.
        expected: usize,
    },
    /// More appendices than the translation's appendix letters.
    #[error("{count} appendices, but the language has only {letters} appendix letters")]
    TooManyAppendices {
        /// The count of appendices.
        count: usize,
        /// The count of letters available.
        letters: usize,
    },
    /// A translation file is missing a key or has an unknown one.
    #[error("translation {lang}: {message}")]
    Translation {
        /// The language code.
        lang: &'static str,
        /// What is wrong.
        message: String,
    },
    /// The typst compiler reported errors (a defect of the template or a
    /// malformed formula or SVG given by the caller).
    #[error("typesetting failed: {}", messages.join("; "))]
    Typst {
        /// The diagnostics, each with its file and line.
        messages: Vec<String>,
    },
    /// The PDF export failed.
    #[error("PDF export failed: {}", messages.join("; "))]
    Pdf {
        /// The diagnostics.
        messages: Vec<String>,
    },
    /// The run's report lacks a value the note prints (a defect of the
    /// report, or a report of another version).
    #[error("the report has no value at {path}; the note cannot print it")]
    MissingValue {
        /// The JSON pointer of the value, e.g. `/gear/eps_alpha`.
        path: String,
    },
    /// An SVG sheet has no size the page can take.
    #[error("the sheet's SVG {what}; a sheet needs width and height in mm (1 … 5000)")]
    SheetSize {
        /// What is wrong.
        what: String,
    },
}
