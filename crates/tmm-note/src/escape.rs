//! Safe passage of the caller's strings into the generated typst source.
//!
//! User text never enters typst *markup*, where `#`, `*`, `_`, `$`, `@`, `<`,
//! `=` … have meaning: it is written as a typst *string literal*
//! (`#"…"` in markup, `"…"` in code), which typst displays verbatim. Inside a
//! string literal only the backslash, the double quote and control characters
//! need escapes (typst reference, "str": `\\ \" \n \r \t \u{…}`).

use crate::error::NoteError;

/// A typst string literal holding `s` verbatim.
///
/// ```
/// use tmm_note::escape::string_literal;
/// assert_eq!(string_literal(r#"a "b" \c"#), r#""a \"b\" \\c""#);
/// assert_eq!(string_literal("#*_$@<"), "\"#*_$@<\"");
/// assert_eq!(string_literal("x\ny"), "\"x\\ny\"");
/// ```
pub fn string_literal(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '\\' => out.push_str("\\\\"),
            '"' => out.push_str("\\\""),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if c.is_control() => out.push_str(&format!("\\u{{{:x}}}", u32::from(c))),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// Checks a label: ASCII letters, digits, `_`, `-`, `.`, `:`, starting with a
/// letter (a subset of what typst's `<label>` syntax accepts).
///
/// ```
/// use tmm_note::escape::check_label;
/// assert!(check_label("eq:velocity-1").is_ok());
/// assert!(check_label("1eq").is_err());
/// assert!(check_label("a b").is_err());
/// ```
///
/// # Errors
/// [`NoteError::InvalidLabel`].
pub fn check_label(label: &str) -> Result<(), NoteError> {
    let mut chars = label.chars();
    let first_ok = chars.next().is_some_and(|c| c.is_ascii_alphabetic());
    if first_ok && chars.all(|c| c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '.' | ':')) {
        Ok(())
    } else {
        Err(NoteError::InvalidLabel { label: label.to_owned() })
    }
}

/// Checks that typst math has no unescaped `$`, which would end the formula
/// and let the rest be read as markup.
///
/// ```
/// use tmm_note::escape::check_math;
/// assert!(check_math("omega_1 = 2 pi n / 60").is_ok());
/// assert!(check_math(r"\$ 5").is_ok());
/// assert!(check_math("a $ #b").is_err());
/// ```
///
/// # Errors
/// [`NoteError::MathDelimiter`].
pub fn check_math(math: &str) -> Result<(), NoteError> {
    let mut escaped = false;
    for c in math.chars() {
        match c {
            '\\' => escaped = !escaped,
            '$' if !escaped => return Err(NoteError::MathDelimiter { math: math.to_owned() }),
            _ => escaped = false,
        }
    }
    Ok(())
}
