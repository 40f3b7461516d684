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
        Error::Input(Box::new(InputError {
            message: tidy(&format!("{}:{line}:{col}: {field}: {message}", task.name)),
            src: Some(NamedSource::new(task.name.clone(), task.text.clone())),
            span: Some(SourceSpan::from(span.start..span.end.max(span.start))),
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
