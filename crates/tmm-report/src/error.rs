//! The one error type at the edge: bad input (exit code 2) or a failed write
//! (exit code 1), rendered with the place in the task file.
//!
//! Every message names the field (`linkage.links.BC.length`), where it is in
//! the file (`task.toml:12:9`) and what would be valid; numbers in it keep at
//! most 12 digits ([`crate::message_numbers`]).

use std::ops::Range;

use miette::{Diagnostic, NamedSource, SourceSpan};

use crate::message_numbers::tidy;
use crate::task::TaskSource;

/// A bad-input error: the message, the task file and the place in it.
#[derive(Debug, thiserror::Error, Diagnostic)]
#[error("{message}")]
#[diagnostic(code(tmm::input))]
pub struct InputError {
    /// The full message, starting with the field and its place.
    pub message: String,
    /// The task file, when the error is in one.
    #[source_code]
    pub src: Option<NamedSource<String>>,
    /// The offending value in the file.
    #[label("here")]
    pub span: Option<SourceSpan>,
    /// What would be valid.
    #[help]
    pub help: Option<String>,
}

/// What went wrong, for the user. Boxed, so that `Result<T, Error>` stays
/// small on every happy path.
#[derive(Debug, thiserror::Error, Diagnostic)]
pub enum Error {
    /// The input is wrong: a task-file field, a command-line value, or a
    /// mechanism that cannot work as described. Exit code 2.
    #[error(transparent)]
    #[diagnostic(transparent)]
    Input(Box<InputError>),
    /// Writing an output failed. Exit code 1.
    #[error("{0}")]
    #[diagnostic(code(tmm::io))]
    Io(String),
}

impl Error {
    /// A bad-input error about `field` (a dotted path such as
    /// `linkage.links.BC.length`, or a command-line option such as `--z1`).
    ///
    /// ```
    /// let e = tmm_report::Error::input("--z1", "must be at least 5").with_help("give --z1 17");
    /// assert_eq!(e.exit_code(), 2);
    /// assert!(e.to_string().contains("--z1"));
    /// ```
    pub fn input(field: &str, message: impl std::fmt::Display) -> Self {
        Error::Input(Box::new(InputError {
            message: tidy(&format!("{field}: {message}")),
            src: None,
            span: None,
            help: None,
        }))
    }

    /// A bad-input error located in a task file: the message starts with
    /// `file:line:column: field:`.
    pub fn at(task: &TaskSource, span: Range<usize>, field: &str, message: impl std::fmt::Display) -> Self {
        let (line, col) = task.line_col(span.start);
        let shown = screen_width(&task.text, span);
        Error::Input(Box::new(InputError {
            message: tidy(&format!("{}:{line}:{col}: {field}: {message}", task.name)),
            src: Some(NamedSource::new(task.name.clone(), shown.0)),
            span: Some(SourceSpan::from(shown.1.start..shown.1.end.max(shown.1.start))),
            help: None,
        }))
    }

    /// Add what would be valid.
    pub fn with_help(mut self, text: impl Into<String>) -> Self {
        if let Error::Input(e) = &mut self {
            e.help = Some(tidy(&text.into()));
        }
        self
    }

    /// A failed write of `path`.
    pub fn io(path: &std::path::Path, e: impl std::fmt::Display) -> Self {
        Error::Io(format!("cannot write {}: {e}", path.display()))
    }

    /// The process exit code: 2 for bad input, 1 for a failed write.
    pub fn exit_code(&self) -> i32 {
        match self {
            Error::Input(_) => 2,
            Error::Io(_) => 1,
        }
    }
}

/// The longest line of a task file shown under a message, in bytes: a
/// longer line is cut there and ends in `…`.
pub const MAX_SHOWN_LINE: usize = 200;

/// The task file as shown under a message: every line longer than
/// [`MAX_SHOWN_LINE`] cut (the lines keep their numbers), and the span moved
/// into the shortened text (to the cut when it lay beyond it).
///
/// ```
/// let text = format!("a = 1\nbogus = \"{}\"\n", "y".repeat(50_000));
/// let (shown, span) = tmm_report::error::screen_width(&text, 6..50_000);
/// assert!(shown.len() < 300 && shown.lines().count() == 2);
/// assert_eq!(&shown[span.start..span.start + 5], "bogus");
/// assert!(span.end <= shown.len());
/// ```
pub fn screen_width(text: &str, span: Range<usize>) -> (String, Range<usize>) {
    if text.split('\n').all(|l| l.len() <= MAX_SHOWN_LINE) {
        return (text.to_string(), span);
    }
    let mut out = String::with_capacity(text.len().min(1 << 16));
    let (mut start, mut end) = (None, None);
    let mut at = 0;
    for line in text.split_inclusive('\n') {
        let body = line.strip_suffix('\n').unwrap_or(line);
        let mut cut = body.len().min(MAX_SHOWN_LINE);
        while !body.is_char_boundary(cut) {
            cut -= 1;
        }
        let here = out.len();
        for (pos, slot) in [(span.start, &mut start), (span.end, &mut end)] {
            if slot.is_none() && pos >= at && pos <= at + body.len() {
                *slot = Some(here + (pos - at).min(cut));
            }
        }
        out.push_str(&body[..cut]);
        if cut < body.len() {
            out.push('…');
        }
        if line.len() > body.len() {
            out.push('\n');
        }
        at += line.len();
    }
    let start = start.unwrap_or(out.len());
    (out, start..end.unwrap_or(start).max(start))
}
