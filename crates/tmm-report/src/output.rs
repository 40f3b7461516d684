//! What a section of a task produces, held in memory: the tables, the JSON
//! document and the files (drawings, CSV, DXF, JSON) as named documents.
//!
//! Nothing here touches a file system. The command line writes the documents
//! (all or none), the browser page shows them and the note typesets them: the
//! same bytes everywhere. Every text document passes one check for
//! non-finite numbers ([`check_finite_in`]) before it is handed out, so a NaN
//! or an infinity becomes an error instead of a wrong drawing or table; the
//! user's own text (a title "Infinity gear", a link named `inf`) is told
//! apart from a number and passes as written.

use crate::Error;
use crate::picture::Picture;

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

/// The documents of a run or a section, in the order they were made, with
/// the user's text that the non-finite check lets pass ([`check_finite_in`]).
#[derive(Debug, Clone, Default)]
pub struct Documents {
    docs: Vec<Document>,
    excused: std::sync::Arc<Vec<String>>,
    /// The drawings among the documents, by path: what the sheets place.
    pictures: Vec<(String, std::sync::Arc<Picture>)>,
}

/// What [`Documents::add_text`] takes: a text, or a drawing ([`Picture`]),
/// whose SVG text is the document and whose elements are kept beside it
/// for the sheets.
pub trait IntoText {
    /// The text and, for a drawing, the drawing.
    fn into_text(self) -> (String, Option<Picture>);
}

impl IntoText for String {
    fn into_text(self) -> (String, Option<Picture>) {
        (self, None)
    }
}

impl IntoText for &str {
    fn into_text(self) -> (String, Option<Picture>) {
        (self.to_string(), None)
    }
}

impl IntoText for &String {
    fn into_text(self) -> (String, Option<Picture>) {
        (self.clone(), None)
    }
}

impl IntoText for Picture {
    fn into_text(self) -> (String, Option<Picture>) {
        (self.svg().to_string(), Some(self))
    }
}

impl Documents {
    /// No documents yet, and no user text: every `NaN`, `inf` or `Infinity`
    /// word in a document is refused.
    pub fn new() -> Self {
        Self::default()
    }

    /// No documents yet, for a task: its own text ([`crate::user_text::excused`])
    /// passes the non-finite check as written.
    ///
    /// ```
    /// use tmm_report::{TaskSource, output::Documents};
    /// let t = TaskSource::new("t.toml", "title = \"Infinity gear\"\n");
    /// let mut d = Documents::for_task(&t);
    /// assert!(d.add_text("a.txt", "Infinity gear: u = 6").is_ok());
    /// assert!(d.add_text("b.txt", "Infinity gear: u = inf").is_err());
    /// assert!(Documents::new().add_text("a.txt", "Infinity gear").is_err());
    /// ```
    pub fn for_task(task: &crate::TaskSource) -> Self {
        Documents {
            docs: Vec::new(),
            excused: std::sync::Arc::new(crate::user_text::excused(task)),
            pictures: Vec::new(),
        }
    }

    /// No documents yet, with the same user text as `other`.
    pub fn like(other: &Documents) -> Self {
        Documents {
            docs: Vec::new(),
            excused: other.excused.clone(),
            pictures: Vec::new(),
        }
    }

    /// The user's text that passes the non-finite check.
    pub fn excused(&self) -> &[String] {
        &self.excused
    }

    /// Add a text document at `path` after checking it for non-finite
    /// numbers ([`check_finite_in`]).
    pub fn add_text(&mut self, path: impl Into<String>, text: impl IntoText) -> Result<(), Error> {
        let (text, pic) = text.into_text();
        let d = Document::text(path, text);
        check_finite_in(&d, &self.excused)?;
        if let Some(p) = pic {
            self.pictures.push((d.path.clone(), std::sync::Arc::new(p)));
        }
        self.docs.push(d);
        Ok(())
    }

    /// [`Documents::picture`], shared.
    pub fn picture_shared(&self, path: &str) -> Option<std::sync::Arc<Picture>> {
        self.pictures.iter().find(|(p, _)| p == path).map(|(_, d)| d.clone())
    }

    /// The drawing a document at `path` was written from, if it is one.
    pub fn picture(&self, path: &str) -> Option<&Picture> {
        self.pictures.iter().find(|(p, _)| p == path).map(|(_, d)| d.as_ref())
    }

    /// Add a JSON document, pretty-printed.
    pub fn add_json(&mut self, path: impl Into<String>, v: &serde_json::Value) -> Result<(), Error> {
        self.add_text(path, to_json_text(v))
    }

    /// Add a binary document (DXF is text too and goes through the check).
    pub fn add_bytes(&mut self, path: impl Into<String>, bytes: Vec<u8>) -> Result<(), Error> {
        let d = Document { path: path.into(), bytes };
        check_finite_in(&d, &self.excused)?;
        self.docs.push(d);
        Ok(())
    }

    /// Copy the document `d` of `other` in, with the drawing it was written
    /// from (the sheets place drawings, not their SVG text).
    pub fn add_copy(&mut self, other: &Documents, d: &Document) {
        if let Some(p) = other.picture_shared(&d.path) {
            self.pictures.push((d.path.clone(), p));
        }
        self.docs.push(d.clone());
    }

    /// Move every document of `other` in, after these (they were checked
    /// when they were added to `other`).
    pub fn append(&mut self, other: Documents) {
        if self.excused.is_empty() {
            self.excused = other.excused;
        }
        self.docs.extend(other.docs);
        self.pictures.extend(other.pictures);
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

/// What a number that is not finite is printed as by tmm's formatting
/// helpers ([`num`], [`crate::svg::num`], [`crate::labels::num`]): a
/// control character (which no user text may hold, [`crate::user_text`])
/// before `NaN`, so [`check_finite_in`] refuses it wherever it stands, even
/// beside a user's name `NaN`.
pub const NONFINITE: &str = "\u{1}NaN";

/// [`NONFINITE`] as JSON writes it inside a string.
const NONFINITE_JSON: &str = "\\u0001NaN";

/// A JSON number; a non-finite value becomes the marker [`NONFINITE`], which
/// [`check_finite_in`] refuses, so it never reaches a file silently as `null`.
///
/// ```
/// use tmm_report::output::{num, to_json_text, Document, check_finite};
/// let j = to_json_text(&serde_json::json!({ "name": "NaN", "x": num(f64::NAN) }));
/// assert!(check_finite(&Document::text("a.json", j)).is_err());
/// ```
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

/// [`check_finite_in`] with no user text: every `NaN`, `inf` or `Infinity`
/// word is refused.
///
/// ```
/// use tmm_report::output::{Document, check_finite};
/// assert!(check_finite(&Document::text("a.svg", "<line x1=\"1.5\"/> information")).is_ok());
/// assert!(check_finite(&Document::text("a.svg", "<line x1=\"NaN\"/>")).is_err());
/// assert!(check_finite(&Document::text("t.txt", "M = -inf N·m")).is_err());
/// ```
pub fn check_finite(d: &Document) -> Result<(), Error> {
    check_finite_in(d, &[])
}

/// Refuse a document that carries a non-finite number. Two nets catch one:
/// tmm's formatting helpers print it as the marker [`NONFINITE`], refused
/// wherever it stands; and a number formatted elsewhere comes out as Rust
/// writes it, `NaN`, `inf` or `-inf`, so the text is scanned for those words
/// (and `Infinity`), not inside a longer word (`info`, `infeasible` pass).
/// A word that is part of the user's own text (`excused`, from
/// [`crate::user_text::excused`]: a title "Infinity gear", a link `inf`)
/// passes where it stands as the user wrote it, one space-separated piece
/// of that text at a time (a title block breaks a long title at spaces).
///
/// ```
/// use tmm_report::output::{Document, check_finite_in, NONFINITE};
/// let user = ["Planetary gear for -inf".to_string()];
/// let ok = "<text>Planetary gear for</text><text>-inf</text>";
/// assert!(check_finite_in(&Document::text("a.svg", ok), &user).is_ok());
/// assert!(check_finite_in(&Document::text("a.svg", "u = inf"), &user).is_err());
/// let marked = format!("<text>-inf</text><text>{NONFINITE}</text>");
/// assert!(check_finite_in(&Document::text("a.svg", marked), &user).is_err());
/// ```
pub fn check_finite_in(d: &Document, excused: &[String]) -> Result<(), Error> {
    let Some(text) = d.as_text() else { return Ok(()) };
    if let Some(at) = find_nonfinite_in(text, excused) {
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

/// Byte offset of the first non-finite number in `text`: the marker
/// [`NONFINITE`] (also as JSON escapes it), or a `NaN`, `inf` or `Infinity`
/// word that is not part of the user's text `excused`.
#[doc(hidden)]
pub fn find_nonfinite_in(text: &str, excused: &[String]) -> Option<usize> {
    // Both markers hold "NaN"; a text without any of the three words has
    // neither a marker nor a word, and `str::contains` reads it in wide
    // steps (most outputs are megabytes of numbers with none of them).
    if !["NaN", "inf", "Infinity"].iter().any(|w| text.contains(w)) {
        return None;
    }
    let marker = [NONFINITE, NONFINITE_JSON].iter().filter_map(|m| text.find(m)).min();
    let mut from = 0;
    let mut word = None;
    while let Some(i) = find_nonfinite_word(&text[from..]) {
        let s = from + i;
        if !excused.iter().any(|u| in_user_text(text, s, u)) {
            word = Some(s);
            break;
        }
        from = word_end(text, s);
    }
    match (marker, word) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    }
}

/// [`find_nonfinite_in`] with no user text.
#[doc(hidden)]
pub fn find_nonfinite(text: &str) -> Option<usize> {
    find_nonfinite_in(text, &[])
}

/// Whether the word at byte `s` of `text` stands inside a space-separated
/// piece of the user's text `u`, written out in full around it.
fn in_user_text(text: &str, s: usize, u: &str) -> bool {
    u.split_whitespace().any(|piece| {
        let mut from = 0;
        while let Some(i) = find_nonfinite_word(&piece[from..]) {
            let k = from + i;
            if let Some(start) = s.checked_sub(k)
                && text.is_char_boundary(start)
                && text[start..].starts_with(piece)
            {
                return true;
            }
            from = word_end(piece, k);
        }
        false
    })
}

/// The byte offset just past the word that starts at `s`.
fn word_end(text: &str, s: usize) -> usize {
    s + text[s..].bytes().take_while(|c| c.is_ascii_alphanumeric() || *c == b'_').count()
}

/// Byte offset of the first `NaN`, `inf` or `Infinity` that stands as a word.
///
/// One pass over the bytes: only a word's first byte (`N`, `i` or `I` after a
/// non-word byte) is tried against the three words, so a long output is read
/// once instead of once per word.
#[doc(hidden)]
pub fn find_nonfinite_word(text: &str) -> Option<usize> {
    let b = text.as_bytes();
    let is_word = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    let mut prev_is_word = false;
    for (s, &c) in b.iter().enumerate() {
        if !prev_is_word && matches!(c, b'N' | b'i' | b'I') {
            let word: &[u8] = match c {
                b'N' => b"NaN",
                b'i' => b"inf",
                _ => b"Infinity",
            };
            let e = s + word.len();
            if b[s..].starts_with(word) && (e >= b.len() || !is_word(b[e])) {
                return Some(s);
            }
        }
        prev_is_word = is_word(c);
    }
    None
}
