//! What a section of a task produces, held in memory: the tables, the JSON
//! document and the files (drawings, CSV, DXF, JSON) as named documents.
//!
//! Nothing here touches a file system. The command line writes the documents
//! (all or none), the browser page shows them and the note typesets them: the
//! same bytes everywhere. Every text document passes one check for
//! non-finite numbers ([`check_finite`]) before it is handed out, so a NaN
//! or an infinity becomes an error instead of a wrong drawing or table.

use crate::Error;

/// One output file in memory: its path relative to the output folder
/// (`/`-separated, e.g. `linkage/positions.svg`) and its bytes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Document {
    /// Path relative to the output folder, `/`-separated.
    pub path: String,
    /// The file's contents.
    pub bytes: Vec<u8>,
}

impl Document {
    /// A text document.
    ///
    /// ```
    /// let d = tmm_report::output::Document::text("a/b.svg", "<svg/>");
    /// assert_eq!(d.path, "a/b.svg");
    /// assert_eq!(d.as_text(), Some("<svg/>"));
    /// ```
    pub fn text(path: impl Into<String>, text: impl Into<String>) -> Self {
        Document {
            path: path.into(),
            bytes: text.into().into_bytes(),
        }
    }

    /// The contents as text, when they are UTF-8.
    pub fn as_text(&self) -> Option<&str> {
        std::str::from_utf8(&self.bytes).ok()
    }

    /// The file name's extension (`svg`, `dxf`, `json`, …), lower case.
    pub fn extension(&self) -> String {
        self.path.rsplit_once('.').map(|(_, e)| e.to_ascii_lowercase()).unwrap_or_default()
    }
}

/// The documents of a run or a section, in the order they were made.
#[derive(Debug, Clone, Default)]
pub struct Documents {
    docs: Vec<Document>,
}

impl Documents {
    /// No documents yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// Add a text document at `path` after checking it for non-finite
    /// numbers ([`check_finite`]).
    pub fn add_text(&mut self, path: impl Into<String>, text: impl Into<String>) -> Result<(), Error> {
        let d = Document::text(path, text);
        check_finite(&d)?;
        self.docs.push(d);
        Ok(())
    }

    /// Add a JSON document, pretty-printed.
    pub fn add_json(&mut self, path: impl Into<String>, v: &serde_json::Value) -> Result<(), Error> {
        self.add_text(path, to_json_text(v))
    }

    /// Add a binary document (DXF is text too and goes through the check).
    pub fn add_bytes(&mut self, path: impl Into<String>, bytes: Vec<u8>) -> Result<(), Error> {
        let d = Document { path: path.into(), bytes };
        check_finite(&d)?;
        self.docs.push(d);
        Ok(())
    }

    /// Move every document of `other` in, after these.
    pub fn append(&mut self, other: Documents) {
        self.docs.extend(other.docs);
    }

    /// The documents.
    pub fn iter(&self) -> std::slice::Iter<'_, Document> {
        self.docs.iter()
    }

    /// How many documents.
    pub fn len(&self) -> usize {
        self.docs.len()
    }

    /// No documents.
    pub fn is_empty(&self) -> bool {
        self.docs.is_empty()
    }

    /// The document at `path`.
    pub fn get(&self, path: &str) -> Option<&Document> {
        self.docs.iter().find(|d| d.path == path)
    }

    /// Every document, by value.
    pub fn into_vec(self) -> Vec<Document> {
        self.docs
    }
}

impl<'a> IntoIterator for &'a Documents {
    type Item = &'a Document;
    type IntoIter = std::slice::Iter<'a, Document>;
    fn into_iter(self) -> Self::IntoIter {
        self.docs.iter()
    }
}

/// The result of running one section of a task (`linkage`, `gear`, …).
#[derive(Debug, Clone)]
pub struct SectionOutput {
    /// The section name (`linkage`, `forces`, `gear`, `planetary`, `cam`).
    pub section: &'static str,
    /// Human-readable tables.
    pub text: String,
    /// The section's JSON document (SI, angles in rad).
    pub json: serde_json::Value,
    /// The files, with paths relative to the output folder.
    pub docs: Documents,
}

/// The marker that [`num`] puts where a number is not finite; the check at
/// the write point turns it into an error.
const NONFINITE: &str = "NaN";

/// A JSON number; a non-finite value becomes the string `"NaN"`, which
/// [`check_finite`] refuses, so it never reaches a file silently as `null`.
pub fn num(x: f64) -> serde_json::Value {
    if x.is_finite() {
        serde_json::Value::from(x)
    } else {
        serde_json::Value::from(NONFINITE)
    }
}

/// Pretty JSON text of a value (the only serialiser tmm uses for output).
pub fn to_json_text(v: &serde_json::Value) -> String {
    // Serialising a `Value` cannot fail: its map keys are strings.
    serde_json::to_string_pretty(v).unwrap_or_default()
}

/// Refuse a document that carries a non-finite number: Rust prints NaN as
/// `NaN` and infinities as `inf`/`-inf`, and [`num`] marks them in JSON, so
/// one scan of the text for those words (not inside a longer word, so
/// `info` or `infeasible` pass) catches every table, drawing, CSV, DXF and
/// JSON document at the one place they are handed out.
///
/// ```
/// use tmm_report::output::{Document, check_finite};
/// assert!(check_finite(&Document::text("a.svg", "<line x1=\"1.5\"/> information")).is_ok());
/// assert!(check_finite(&Document::text("a.svg", "<line x1=\"NaN\"/>")).is_err());
/// assert!(check_finite(&Document::text("t.txt", "M = -inf N·m")).is_err());
/// ```
pub fn check_finite(d: &Document) -> Result<(), Error> {
    let Some(text) = d.as_text() else { return Ok(()) };
    if let Some(at) = find_nonfinite(text) {
        let line = text[..at].matches('\n').count() + 1;
        return Err(Error::input(
            &d.path,
            format!("a result is not a finite number (line {line} of this output); nothing was written"),
        )
        .with_help(
            "the input lies outside the range where the calculation is meaningful: check the magnitudes and units of the task's values",
        ));
    }
    Ok(())
}

/// Byte offset of the first `NaN`, `inf` or `Infinity` that stands as a word.
#[doc(hidden)]
pub fn find_nonfinite(text: &str) -> Option<usize> {
    let b = text.as_bytes();
    let is_word = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    for word in ["NaN", "inf", "Infinity"] {
        let mut from = 0;
        while let Some(i) = text[from..].find(word) {
            let s = from + i;
            let e = s + word.len();
            let before = s == 0 || !is_word(b[s - 1]);
            let after = e >= b.len() || !is_word(b[e]);
            if before && after {
                return Some(s);
            }
            from = e;
        }
    }
    None
}
