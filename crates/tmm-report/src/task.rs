//! Task files (TOML): the source text, quantities with units, and the
//! conversion of parse errors into located [`Error`]s.
//!
//! Each area (`linkage`, `forces`, `gear`, `planetary`, `cam`) reads its own
//! section from the whole text with its own `serde` structs, so byte spans
//! point into the file the user wrote.

use std::ops::Range;

use serde::Deserialize;
use tmm_geom::units::{self, Dim};

use crate::Error;

/// A task file's name (for messages) and text.
#[derive(Debug, Clone)]
pub struct TaskSource {
    /// The name shown in messages, e.g. `examples/seed-001-fourbar.toml`.
    pub name: String,
    /// The whole TOML text.
    pub text: String,
    /// The language of the drawings' words (the `[project]` language, or
    /// the one asked for on the command line); Russian unless set.
    pub lang: crate::project::Language,
    /// The sheet format the drawings are made for (`[project] sheet`).
    pub sheet: crate::project::SheetFormat,
}

/// The top-level sections a task file may have.
pub const SECTIONS: &[&str] = &[
    "title",
    "project",
    "synthesis",
    "linkage",
    "forces",
    "dynamics",
    "gear",
    "planetary",
    "cam",
    "cylinder",
];

impl TaskSource {
    /// A task from its name and text.
    pub fn new(name: impl Into<String>, text: impl Into<String>) -> Self {
        TaskSource {
            name: name.into(),
            text: text.into(),
            lang: crate::project::Language::default(),
            sheet: crate::project::SheetFormat::default(),
        }
    }

    /// The same task with the drawings' words in `lang`.
    pub fn with_lang(mut self, lang: crate::project::Language) -> Self {
        self.lang = lang;
        self
    }

    /// The same task with the drawings made for `sheet`.
    pub fn with_sheet(mut self, sheet: crate::project::SheetFormat) -> Self {
        self.sheet = sheet;
        self
    }

    /// 1-based line and column of a byte offset; the column counts
    /// characters, so it is right on lines with Cyrillic text.
    ///
    /// ```
    /// let t = tmm_report::TaskSource::new("t.toml", "a = 1\nbb = 2\n");
    /// assert_eq!(t.line_col(8), (2, 3));
    /// let t = tmm_report::TaskSource::new("t.toml", "title = \"Кривошип\" x");
    /// assert_eq!(t.line_col(t.text.find('x').unwrap()), (1, 20));
    /// ```
    pub fn line_col(&self, offset: usize) -> (usize, usize) {
        let mut off = offset.min(self.text.len());
        while !self.text.is_char_boundary(off) {
            off -= 1;
        }
        let before = &self.text[..off];
        let line = before.matches('\n').count() + 1;
        let start = before.rfind('\n').map_or(0, |p| p + 1);
        let col = before[start..].chars().count() + 1;
        (line, col)
    }

    /// Deserialize the whole file into `T` (an area's view of the file),
    /// turning a TOML or schema error into a located [`Error`]. The user's
    /// names and texts are checked first ([`crate::user_text::check`]:
    /// length and control characters), so no section reads one that is
    /// refused.
    pub fn parse<T: for<'de> Deserialize<'de>>(&self, section: &str) -> Result<T, Error> {
        crate::user_text::check(self)?;
        toml::from_str::<T>(&self.text).map_err(|e| self.toml_error(section, &e))
    }

    /// A `toml` error as a located input error.
    pub fn toml_error(&self, section: &str, e: &toml::de::Error) -> Error {
        let msg = plain_message(e.message().trim());
        match e.span() {
            Some(span) => Error::at(self, span, section, msg),
            // the parser's nesting limit comes without a place: point at the
            // line nested deepest (dotted keys and headers, brackets, braces)
            None if msg.contains("recursion limit") => {
                let span = self.deepest_line();
                Error::at(
                    self,
                    span,
                    section,
                    "tables or arrays nested too deep for the reader (its recursion limit); a task file nests them a few levels at most",
                )
            }
            None => Error::input(&format!("{}: {section}", self.name), msg),
        }
    }

    /// The byte range of the line nested deepest: the most dots, brackets
    /// and braces outside quotes (a rough depth, enough to point at it).
    fn deepest_line(&self) -> std::ops::Range<usize> {
        let mut best = (0usize, 0..0);
        let mut start = 0;
        for line in self.text.split_inclusive('\n') {
            let mut depth = 0;
            let mut quoted = false;
            for c in line.chars() {
                match c {
                    '"' | '\'' => quoted = !quoted,
                    '.' | '[' | '{' if !quoted => depth += 1,
                    _ => {}
                }
            }
            if depth > best.0 {
                best = (depth, start..start + line.trim_end().len());
            }
            start += line.len();
        }
        best.1
    }

    /// An error about a section the file lacks, located at the file's end,
    /// where the section would be added (`task.toml:41:1: linkage: …`).
    ///
    /// ```
    /// let t = tmm_report::TaskSource::new("t.toml", "title = \"x\"\n");
    /// let e = t.missing("linkage", "the file has no [linkage] section");
    /// assert!(e.to_string().starts_with("t.toml:2:1: linkage: the file has no [linkage] section"), "{e}");
    /// ```
    pub fn missing(&self, section: &str, message: impl std::fmt::Display) -> Error {
        let end = self.text.len();
        Error::at(self, end..end, section, message)
    }

    /// Check that every top-level key is a known section.
    pub fn check_sections(&self) -> Result<toml::Table, Error> {
        let doc: toml::Spanned<toml::Table> = self.parse("task file")?;
        let table = doc.into_inner();
        for key in table.keys() {
            if !SECTIONS.contains(&key.as_str()) {
                let pos = self.find_key(key).unwrap_or(0..0);
                return Err(
                    Error::at(self, pos, key, "unknown section").with_help(format!("a task file has the sections {}", SECTIONS.join(", ")))
                );
            }
        }
        Ok(table)
    }

    /// Where a top-level key is written: a `[key…]` header or `key =` at the
    /// start of a line, never inside a comment or a string.
    fn find_key(&self, key: &str) -> Option<Range<usize>> {
        let mut at = 0;
        for line in self.text.split_inclusive('\n') {
            let code = line.split('#').next().unwrap_or("");
            let lead = code.len() - code.trim_start().len();
            let rest = &code[lead..];
            let (skip, name) = match rest.strip_prefix("[[").or_else(|| rest.strip_prefix('[')) {
                Some(r) => (rest.len() - r.len(), r),
                None => (0, rest),
            };
            let name = name.trim_start_matches('"');
            if let Some(after) = name.strip_prefix(key) {
                let end = after.trim_start().chars().next();
                if matches!(end, Some('=' | ']' | '.' | '"')) {
                    let p = at + lead + skip + (rest.len() - skip - name.len());
                    return Some(p..p + key.len());
                }
            }
            at += line.len();
        }
        None
    }
}

/// A task file's bytes as text; a byte that is not UTF-8 is refused at its
/// place (`task.toml:28:12`, the column counting the characters before it),
/// from [`std::str::from_utf8`]'s offset of the first bad byte.
///
/// ```
/// let e = tmm_report::task::text_of("t.toml", b"a = 1\nb = \"1\xff\"\n".to_vec()).unwrap_err();
/// assert_eq!(e.exit_code(), 2);
/// assert!(e.to_string().starts_with("t.toml:2:7: "), "{e}");
/// assert_eq!(tmm_report::task::text_of("t.toml", b"a = 1".to_vec()).unwrap(), "a = 1");
/// ```
pub fn text_of(name: &str, bytes: Vec<u8>) -> Result<String, Error> {
    String::from_utf8(bytes).map_err(|e| {
        let err = e.utf8_error();
        let bytes = e.as_bytes();
        let at = err.valid_up_to();
        // the text up to the bad byte is valid: count its lines and characters
        let before = std::str::from_utf8(&bytes[..at]).unwrap_or_default();
        let line = before.matches('\n').count() + 1;
        let col = before[before.rfind('\n').map_or(0, |p| p + 1)..].chars().count() + 1;
        let bad: Vec<String> = bytes[at..(at + err.error_len().unwrap_or(bytes.len() - at)).min(bytes.len())]
            .iter()
            .take(4)
            .map(|b| format!("0x{b:02X}"))
            .collect();
        Error::input(
            &format!("{name}:{line}:{col}"),
            format!(
                "the task file is not UTF-8 text: the byte {} here is not a character",
                bad.join(" ")
            ),
        )
        .with_help("save the file as UTF-8 (any text editor can); tmm reads task files in UTF-8 only")
    })
}

/// A `toml`/`serde` message in words for the user: no Rust type names.
///
/// ```
/// let m = tmm_report::task::plain_message("data did not match any variant of untagged enum RawQty");
/// assert!(m.contains("a number") && !m.contains("RawQty"));
/// ```
pub fn plain_message(msg: &str) -> String {
    if let Some(name) = msg.strip_prefix("data did not match any variant of untagged enum ") {
        return match name.trim() {
            "RawQty" => "expected a number or a quantity with its unit, e.g. \"120 mm\" or 0.12".into(),
            "HintSec" => {
                "expected an assembly hint: a text such as \"C below line A-D\" or a table { point = \"C\", near = [\"0.4 m\", \"0.3 m\"] }"
                    .into()
            }
            "Through" => "expected a point's name or its coordinates, e.g. \"O\" or [\"0 mm\", \"120 mm\"]".into(),
            _ => "this value has the wrong form; see the section's description in docs/".into(),
        };
    }
    let mut m = msg.replace("invalid type: ", "wrong kind of value: ");
    for (rust, words) in [
        ("expected f64", "expected a number"),
        ("expected usize", "expected a whole number"),
        ("expected u32", "expected a whole number"),
        ("expected u64", "expected a whole number"),
        ("expected i64", "expected a whole number"),
        ("expected a string", "expected a text in quotes"),
    ] {
        m = m.replace(rust, words);
    }
    m
}

/// A quantity as written in a task file: a plain number or a string with a unit.
#[derive(Debug, Clone, Deserialize, PartialEq)]
#[serde(untagged)]
pub enum RawQty {
    /// A number, SI (degrees for an angle).
    Num(f64),
    /// A string with a unit, e.g. `"120 mm"`.
    Text(String),
}

/// A quantity with its place in the file.
pub type Qty = toml::Spanned<RawQty>;

/// Convert a task-file quantity to SI, or say which field is malformed.
///
/// ```
/// use tmm_report::task::{qty, TaskSource, Qty};
/// use tmm_geom::units::Dim;
/// #[derive(serde::Deserialize)] struct F { l: Qty }
/// let t = TaskSource::new("t.toml", "l = \"120 mm\"\n");
/// let f: F = t.parse("l").unwrap();
/// assert!((qty(&t, "l", &f.l, Dim::Length).unwrap() - 0.12).abs() < 1e-15);
/// let bad = TaskSource::new("t.toml", "l = \"12 kg\"\n");
/// let f: F = bad.parse("l").unwrap();
/// let e = qty(&bad, "l", &f.l, Dim::Length).unwrap_err();
/// assert_eq!(e.exit_code(), 2);
/// assert!(e.to_string().starts_with("t.toml:1:5: l:"));
/// ```
pub fn qty(task: &TaskSource, field: &str, q: &Qty, dim: Dim) -> Result<f64, Error> {
    let r = match q.get_ref() {
        RawQty::Num(x) => units::from_number(*x, dim),
        RawQty::Text(s) => units::parse(s, dim),
    };
    r.map_err(|e| Error::at(task, q.span(), field, e))
}

/// Parse a command-line quantity (`--module "5 mm"`), naming the option on error.
///
/// ```
/// use tmm_geom::units::Dim;
/// assert!((tmm_report::task::arg_qty("--module", "5 mm", Dim::Length).unwrap() - 0.005).abs() < 1e-15);
/// assert_eq!(tmm_report::task::arg_qty("--module", "5 kg", Dim::Length).unwrap_err().exit_code(), 2);
/// ```
pub fn arg_qty(option: &str, text: &str, dim: Dim) -> Result<f64, Error> {
    units::parse(text, dim).map_err(|e| Error::input(option, e))
}
