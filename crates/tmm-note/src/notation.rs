//! The course's notation in the note's own words (обозначения): `K_v`,
//! `l_OA`, `M_ур`, `R^τ`, `h_a*` written plainly in the words files are set
//! as math — subscripts, superscripts, Greek — as the course writes them.
//!
//! [`notation`] turns every such token of a words text into a math run
//! between [`MATH_OPEN`] and [`MATH_CLOSE`] (two characters of Unicode's
//! private-use area, which no words file or task holds); the markup writer
//! ([`crate::markup`]) sets a run between them as typst math and everything
//! else as a string literal, as before. The caller's own strings (names of
//! links and points, the project's fields, a task's labels) never pass
//! through [`notation`] and stay literal; [`strip`] removes the two markers
//! from them so they can never open a math run.
//!
//! The rules (the course's textbooks, e.g. Артоболевский 1988): a token is a
//! base of letters (`K`, `ΔE`, `ω`) followed by `_sub` and/or `^sup` and an
//! optional `*`. A one-character subscript is set as is (a Cyrillic one
//! upright); an upper-case Latin pair of point names (`OA`) as the two
//! letters in italics; a mixed one (`1H`) as its characters; a word (`max`,
//! `ур`, `II`) upright.

/// Opens a math run in a words text.
pub const MATH_OPEN: char = '\u{E000}';
/// Closes a math run in a words text.
pub const MATH_CLOSE: char = '\u{E001}';

/// The words text with its notation tokens marked as math runs.
///
/// ```
/// use tmm_note::notation::{notation, MATH_OPEN as O, MATH_CLOSE as C};
/// assert_eq!(notation("K_v = 1"), format!("{O}K_v{C} = 1"));
/// assert_eq!(notation("l_OA,"), format!("{O}l_(O A){C},"));
/// assert_eq!(notation("M_ур"), format!("{O}M_\"ур\"{C}"));
/// assert_eq!(notation("(ΔT_max —"), format!("({O}Δ T_\"max\"{C} —"));
/// assert_eq!(notation("h_a*"), format!("{O}h_a^*{C}"));
/// assert_eq!(notation("R^τ, Н"), format!("{O}R^τ{C}, Н"));
/// assert_eq!(notation("a plain_text"), "a plain_text");
/// assert_eq!(notation("no notation"), "no notation");
/// ```
pub fn notation(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < chars.len() {
        // a token starts at a letter that follows a non-letter
        let starts = is_base(chars[i]) && (i == 0 || !is_base(chars[i - 1]) && !chars[i - 1].is_alphanumeric());
        if starts && let Some((math, len)) = token(&chars[i..]) {
            out.push(MATH_OPEN);
            out.push_str(&math);
            out.push(MATH_CLOSE);
            i += len;
            continue;
        }
        out.push(chars[i]);
        i += 1;
    }
    out
}

/// A caller's string with the math markers removed.
///
/// ```
/// assert_eq!(tmm_note::notation::strip("a\u{E000}b\u{E001}"), "ab");
/// ```
pub fn strip(s: &str) -> String {
    s.chars().filter(|c| *c != MATH_OPEN && *c != MATH_CLOSE).collect()
}

/// Whether `s` holds a math run.
pub fn has_math(s: &str) -> bool {
    s.contains(MATH_OPEN)
}

/// The runs of a marked text: (is math, text).
pub fn runs(s: &str) -> Vec<(bool, String)> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let mut math = false;
    for c in s.chars() {
        match c {
            MATH_OPEN if !math => {
                if !cur.is_empty() {
                    out.push((false, std::mem::take(&mut cur)));
                }
                math = true;
            }
            MATH_CLOSE if math => {
                out.push((true, std::mem::take(&mut cur)));
                math = false;
            }
            _ => cur.push(c),
        }
    }
    if !cur.is_empty() {
        out.push((math, cur));
    }
    out
}

fn is_base(c: char) -> bool {
    c.is_alphabetic() || c == 'Δ'
}

fn is_sub(c: char) -> bool {
    c.is_alphanumeric()
}

/// The math of a notation token at the start of `s` and its length in
/// characters, or `None` if `s` does not start with one.
fn token(s: &[char]) -> Option<(String, usize)> {
    let mut i = 0;
    while i < s.len() && is_base(s[i]) {
        i += 1;
    }
    let base_len = i;
    if base_len == 0 || base_len > 3 || i >= s.len() || !matches!(s[i], '_' | '^') {
        return None;
    }
    let base: String = s[..base_len].iter().map(|c| c.to_string()).collect::<Vec<_>>().join(" ");
    let mut math = base;
    for mark in ['_', '^'] {
        if i < s.len() && s[i] == mark {
            let start = i + 1;
            let mut j = start;
            while j < s.len() && is_sub(s[j]) {
                j += 1;
            }
            if j == start {
                return None;
            }
            let part: String = s[start..j].iter().collect();
            math.push(mark);
            math.push_str(&script(&part));
            i = j;
        }
    }
    if i < s.len() && s[i] == '*' {
        math.push_str("^*");
        i += 1;
    }
    Some((math, i))
}

/// A subscript or superscript as typst math.
fn script(p: &str) -> String {
    let n = p.chars().count();
    let ascii_upper = p.chars().all(|c| c.is_ascii_uppercase());
    let roman = p.chars().all(|c| matches!(c, 'I' | 'V' | 'X'));
    if n == 1 {
        let c = p.chars().next().unwrap_or(' ');
        if c.is_ascii_alphanumeric() || is_greek(c) {
            p.to_string()
        } else {
            format!("\"{p}\"")
        }
    } else if p.chars().all(|c| c.is_ascii_digit()) {
        format!("({p})")
    } else if (ascii_upper && !roman)
        // a point with the running index: v_Si, J_Si
        || (n == 2 && p.starts_with(|c: char| c.is_ascii_uppercase()) && p.ends_with('i'))
        // a number with a letter: u_1H, α_a1
        || (p.chars().any(|c| c.is_ascii_digit()) && p.chars().all(|c| c.is_ascii_alphanumeric()))
        || p.chars().all(is_greek)
    {
        // letters apart, each in italics
        format!("({})", spaced(p))
    } else {
        format!("\"{p}\"")
    }
}

fn spaced(p: &str) -> String {
    p.chars().map(|c| c.to_string()).collect::<Vec<_>>().join(" ")
}

fn is_greek(c: char) -> bool {
    ('\u{0391}'..='\u{03C9}').contains(&c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_issues_tokens() {
        let m = |s: &str| {
            let r = runs(&notation(s));
            assert_eq!(r.len(), 1, "{s}: {r:?}");
            assert!(r[0].0, "{s}");
            r[0].1.clone()
        };
        assert_eq!(m("I_мах"), "I_\"мах\"");
        assert_eq!(m("u_1H"), "u_(1 H)");
        assert_eq!(m("I_II"), "I_\"II\"");
        assert_eq!(m("ω_m"), "ω_m");
        assert_eq!(m("t_ц"), "t_\"ц\"");
        assert_eq!(m("R^n"), "R^n");
        assert_eq!(m("J_S"), "J_S");
        assert_eq!(m("v_Si"), "v_(S i)");
        assert_eq!(m("M_Zh"), "M_\"Zh\"");
        assert_eq!(m("u_13^H"), "u_(13)^H");
        // a number with a power, words without a mark, a lone underscore stay text
        assert_eq!(notation("10^5 a _ b"), "10^5 a _ b");
        let r = runs(&notation("по K_v и l_AB."));
        assert_eq!(r.len(), 5, "{r:?}");
        assert_eq!(r[4], (false, ".".to_string()));
    }
}
