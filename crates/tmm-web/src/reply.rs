//! The replies to the page as JSON text: a located error (message, help,
//! line, column) the editor can show at its line.

use serde_json::{Value, json};
use tmm_report::{Error, TaskSource};

/// A reply `{"ok": false, "error": {…}}` with an optional help and line.
///
/// ```
/// let r: serde_json::Value = serde_json::from_str(&tmm_web::reply::error_json("bad", Some("fix"), Some((3, 7)))).unwrap();
/// assert_eq!(r["ok"], false);
/// assert_eq!(r["error"]["line"], 3);
/// assert_eq!(r["error"]["column"], 7);
/// ```
pub fn error_json(message: &str, help: Option<&str>, at: Option<(usize, usize)>) -> String {
    error_value(message, help, at).to_string()
}

fn error_value(message: &str, help: Option<&str>, at: Option<(usize, usize)>) -> Value {
    json!({
        "ok": false,
        "error": {
            "message": message,
            "help": help,
            "line": at.map(|a| a.0),
            "column": at.map(|a| a.1),
        }
    })
}

/// The reply for an error of a run of `task`: the CLI's message and help,
/// and the line and column when the error is located in the text the user
/// typed (an error in a mechanism the synthesis wrote has no line there).
pub fn from_error(task: &TaskSource, e: &Error) -> Value {
    match e {
        Error::Input(i) => {
            let at = match (&i.src, i.span) {
                (Some(src), Some(span)) if src.inner() == &task.text => Some(task.line_col(span.offset())),
                _ => None,
            };
            error_value(&i.message, i.help.as_deref(), at)
        }
        Error::Io(m) => error_value(m, None, None),
    }
}
