//! The user's own text in a task file (текст пользователя): names of links,
//! joints, points, sliders and groups, titles, the `[project]` fields and
//! every other string or key. It reaches the tables, the drawings (SVG, DXF),
//! the sheets and the note as written, so it is checked once, before any
//! section reads the file:
//!
//! - a name or title is at most [`MAX_TEXT_CHARS`] characters (a title block's
//!   field holds far less; a longer one is nonsense and costs the typesetter
//!   minutes and gigabytes);
//! - no control character (U+0000–U+001F, U+007F–U+009F) and no Unicode
//!   noncharacter (U+FDD0–U+FDEF, U+xFFFE, U+xFFFF): XML 1.0 forbids most of
//!   them and none has a meaning in a one-line field. The few long texts
//!   ([`LONG_TEXT_FIELDS`], a cam's phases) may hold tabs and line breaks.
//!
//! Each refusal names the field by its path in the file and points at it.
//! [`excused`] lists the user's strings that contain a word the output guard
//! looks for (`inf`, `NaN`, `Infinity`), so [`crate::output::check_finite`]
//! can tell them from a non-finite number.

use std::ops::Range;

use toml::de::{DeTable, DeValue};

use crate::{Error, TaskSource};

/// The longest name, title or other one-line text accepted, in characters.
pub const MAX_TEXT_CHARS: usize = 300;

/// The fields whose text is not a name but a description that may be long
/// and span lines (dotted paths, array indices left out).
pub const LONG_TEXT_FIELDS: &[&str] = &["cam.phases"];

/// Why a character is refused in a field, if it is.
///
/// ```
/// use tmm_report::user_text::refused_char;
/// assert!(refused_char('\u{1}', false));
/// assert!(refused_char('\t', false) && !refused_char('\t', true));
/// assert!(refused_char('\u{85}', true) && refused_char('\u{fffe}', true));
/// assert!(!refused_char('Ж', false) && !refused_char('∞', false));
/// ```
pub fn refused_char(c: char, multiline: bool) -> bool {
    let u = c as u32;
    if multiline && matches!(c, '\t' | '\n' | '\r') {
        return false;
    }
    u < 0x20 || (0x7f..=0x9f).contains(&u) || (0xfdd0..=0xfdef).contains(&u) || (u & 0xfffe) == 0xfffe
}

/// Check every key and string of the task's text (see the module's header).
/// A file that is not TOML passes here: the section's own reading reports it.
///
/// ```
/// use tmm_report::{TaskSource, user_text::check};
/// assert!(check(&TaskSource::new("t.toml", "title = \"Infinity gear\"\n")).is_ok());
/// let e = check(&TaskSource::new("t.toml", "[project]\nstudent = \"A\\u0001B\"\n")).unwrap_err();
/// assert!(e.to_string().starts_with("t.toml:2:11: project.student: control characters are not allowed"), "{e}");
/// let long = format!("[[linkage.links]]\nname = \"{}\"\n", "Ж".repeat(301));
/// let e = check(&TaskSource::new("t.toml", long)).unwrap_err();
/// assert!(e.to_string().starts_with("t.toml:2:8: linkage.links[1].name: the text is 301 characters long"), "{e}");
/// ```
pub fn check(task: &TaskSource) -> Result<(), Error> {
    let Ok(doc) = DeTable::parse(&task.text) else { return Ok(()) };
    let mut first: Option<Error> = None;
    walk_table(doc.get_ref(), "", &mut |path, text, span, is_key| {
        if first.is_none() {
            first = judge(task, path, text, span, is_key).err();
        }
    });
    first.map_or(Ok(()), Err)
}

/// The user's keys and strings that hold a word the output guard looks for
/// (`inf`, `NaN`, `Infinity` standing as a word), each as written and as
/// escaped for XML: the text [`crate::output::check_finite`] lets pass.
///
/// ```
/// use tmm_report::{TaskSource, user_text::excused};
/// let t = TaskSource::new("t.toml", "title = \"Infinity & gear\"\n[x]\ninf = \"information\"\n");
/// assert_eq!(excused(&t), ["Infinity & gear", "Infinity &amp; gear", "inf"]);
/// ```
pub fn excused(task: &TaskSource) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let Ok(doc) = DeTable::parse(&task.text) else { return out };
    walk_table(doc.get_ref(), "", &mut |_, text, _, _| {
        if crate::output::find_nonfinite_word(text).is_some() {
            for t in [text.to_string(), crate::svg::escape(text)] {
                if !out.contains(&t) {
                    out.push(t);
                }
            }
        }
    });
    out
}

fn judge(task: &TaskSource, path: &str, text: &str, span: Range<usize>, is_key: bool) -> Result<(), Error> {
    let long = !is_key && LONG_TEXT_FIELDS.contains(&strip_indices(path).as_str());
    if let Some((i, c)) = text.chars().enumerate().find(|&(_, c)| refused_char(c, long)) {
        return Err(Error::at(
            task,
            span,
            path,
            format!("control characters are not allowed (U+{:04X} at character {})", c as u32, i + 1),
        )
        .with_help(if long {
            "write the text with printable characters, tabs and line breaks only"
        } else {
            "write a name or title on one line with printable characters only (no tabs, line breaks or control codes)"
        }));
    }
    let n = text.chars().count();
    if !long && n > MAX_TEXT_CHARS {
        return Err(Error::at(
            task,
            span,
            path,
            format!("the text is {n} characters long; names and titles are limited to {MAX_TEXT_CHARS} characters"),
        )
        .with_help(format!("shorten it to at most {MAX_TEXT_CHARS} characters")));
    }
    Ok(())
}

/// `linkage.links[2].name` → `linkage.links.name`.
fn strip_indices(path: &str) -> String {
    let mut s = String::with_capacity(path.len());
    let mut skip = false;
    for c in path.chars() {
        match c {
            '[' => skip = true,
            ']' => skip = false,
            _ if !skip => s.push(c),
            _ => {}
        }
    }
    s
}

type Visit<'f> = dyn FnMut(&str, &str, Range<usize>, bool) + 'f;

fn walk_table(t: &DeTable<'_>, path: &str, f: &mut Visit<'_>) {
    for (k, v) in t {
        let p = if path.is_empty() {
            k.get_ref().to_string()
        } else {
            format!("{path}.{}", k.get_ref())
        };
        f(&p, k.get_ref(), k.span(), true);
        walk_value(v.get_ref(), v.span(), &p, f);
    }
}

fn walk_value(v: &DeValue<'_>, span: Range<usize>, path: &str, f: &mut Visit<'_>) {
    match v {
        DeValue::String(s) => f(path, s, span, false),
        DeValue::Table(t) => walk_table(t, path, f),
        DeValue::Array(a) => {
            for (i, item) in a.iter().enumerate() {
                walk_value(item.get_ref(), item.span(), &format!("{path}[{}]", i + 1), f);
            }
        }
        _ => {}
    }
}
