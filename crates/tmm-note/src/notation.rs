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
/// // a Greek letter standing alone is a symbol in every language
/// assert_eq!(notation("угол θ,"), format!("угол {O}θ{C},"));
/// assert_eq!(notation("A_c(2π)"), format!("{O}A_c{C}(2{O}π{C})"));
/// ```
pub fn notation(text: &str) -> String {
    notation_with(text, false)
}

/// [`notation`], and with `lone_latin` a Latin letter standing alone
/// (`m`, `W`, `c*`, not the Roman numerals `I`, `V`, `X`) marked as a
/// symbol too (a letter with a star, `c*`, in every language): in a Russian or Ukrainian text a lone Latin letter is always
/// one (`модуль m`, `точки B`), so it is set in italics as in the formulas;
/// in English it may be a word (`a`, `I`) or a unit (`m`, `s`) and stays
/// text. `ΔT` and `Δy` (Δ before one letter) are symbols in every language.
///
/// ```
/// use tmm_note::notation::{notation_with, MATH_OPEN as O, MATH_CLOSE as C};
/// assert_eq!(notation_with("модуль m, мм", true), format!("модуль {O}m{C}, мм"));
/// assert_eq!(notation_with("c* —", true), format!("{O}c^*{C} —"));
/// assert_eq!(notation_with("класс I(0,1)", true), "класс I(0,1)");
/// assert_eq!(notation_with("a module m", false), "a module m");
/// // a letter with a star is a symbol in every language
/// assert_eq!(notation_with("clearance c*", false), format!("clearance {O}c^*{C}"));
/// // and a letter set equal to a value (`W = 1`, `D = 426.9 mm`)
/// assert_eq!(notation_with("freedom W = 1", false), format!("freedom {O}W{C} = 1"));
/// assert_eq!(notation_with("a = b", false), "a = b");
/// assert_eq!(notation_with("ΔT —", false), format!("{O}Δ T{C} —"));
/// // `$…$` marks its letters as symbols in every language, a squared one too
/// assert_eq!(notation_with("per metre $q$,", false), format!("per metre {O}q{C},"));
/// assert_eq!(notation_with("$k·l²$", false), format!("{O}k{C}·{O}l{C}²"));
/// assert_eq!(notation_with("5 $ only", false), "5 $ only");
/// ```
pub fn notation_with(text: &str, lone_latin: bool) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < chars.len() {
        // `$q$`: the words mark a symbol themselves (a lone Latin letter of
        // an English label, `$k·m·l²$`): every letter between is one
        if chars[i] == '$'
            && let Some(end) = chars[i + 1..].iter().position(|c| *c == '$')
        {
            let inner: String = chars[i + 1..i + 1 + end].iter().collect();
            out.push_str(&notation_with(&inner, true));
            i += end + 2;
            continue;
        }
        // a token starts at a letter that follows a non-letter
        let starts = is_base(chars[i]) && (i == 0 || !is_base(chars[i - 1]) && !chars[i - 1].is_alphanumeric())
            // a Greek letter after a number: 2π as in the formulas' 2𝜋
            || is_greek(chars[i]) && i > 0 && chars[i - 1].is_ascii_digit();
        if starts
            && let Some((math, len)) = derivative(&chars[i..])
                .or_else(|| token(&chars[i..]))
                .or_else(|| lone(&chars[i..], lone_latin))
        {
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

/// A line of the symbols under a formula ("где θ — угол перекрытия, °;
/// K_v — …", "where θ is …; K_v the …"): every symbol it explains — the
/// head of each entry, before " — " (or the English " is ", " are ",
/// " the " …) — is marked as math whatever the language, so a lone `m` or
/// `W` is set as in the formula; the explanations as [`notation_with`].
///
/// ```
/// use tmm_note::notation::{where_line, MATH_OPEN as O, MATH_CLOSE as C};
/// assert_eq!(
///     where_line("where W is the mobility; n the number of links", false),
///     format!("where {O}W{C} is the mobility; {O}n{C} the number of links")
/// );
/// assert_eq!(where_line("где v_B, v_C — скорости", true), format!("где {O}v_B{C}, {O}v_C{C} — скорости"));
/// ```
pub fn where_line(text: &str, lone_latin: bool) -> String {
    let Some((prefix, rest)) = text.split_once(' ') else {
        return notation_with(text, lone_latin);
    };
    let entries: Vec<String> = rest
        .split("; ")
        .map(|entry| {
            let end = WHERE_VERBS.iter().filter_map(|v| entry.find(v)).min().unwrap_or(0);
            format!("{}{}", notation_with(&entry[..end], true), notation_with(&entry[end..], lone_latin))
        })
        .collect();
    format!("{prefix} {}", entries.join("; "))
}

/// What ends the symbols of a where-line's entry.
const WHERE_VERBS: [&str; 7] = [" — ", " is ", " are ", " the ", " as ", " its ", " their "];

/// A derivative written flat at the start of `s`, `ds/dφ` or `d²s/dφ²`
/// (a letter over a Greek letter), as the formulas set it: an upright d,
/// the letters in italics, a slash.
///
/// ```
/// use tmm_note::notation::{notation, MATH_OPEN as O, MATH_CLOSE as C};
/// assert_eq!(notation("max |ds/dφ|"), format!("max |{O}dif s\\/dif φ{C}|"));
/// assert_eq!(notation("d²s/dφ², мм"), format!("{O}dif^2 s\\/dif φ^2{C}, мм"));
/// ```
fn derivative(s: &[char]) -> Option<(String, usize)> {
    let mut i = 0;
    let at = |k: usize| s.get(k).copied();
    if at(i)? != 'd' {
        return None;
    }
    i += 1;
    let square = at(i) == Some('²');
    if square {
        i += 1;
    }
    let top = at(i).filter(char::is_ascii_alphabetic)?;
    i += 1;
    if at(i) != Some('/') || at(i + 1) != Some('d') {
        return None;
    }
    i += 2;
    let bottom = at(i).filter(|c| is_greek(*c))?;
    i += 1;
    if square {
        if at(i) != Some('²') {
            return None;
        }
        i += 1;
    }
    if at(i).is_some_and(|c| c.is_alphanumeric() || matches!(c, '_' | '^')) {
        return None;
    }
    Some(if square {
        (format!("dif^2 {top}\\/dif {bottom}^2"), i)
    } else {
        (format!("dif {top}\\/dif {bottom}"), i)
    })
}

/// A symbol of one letter at the start of `s` standing alone: a Greek
/// letter (`θ`, `ϑ`), `Δ` with one letter (`ΔT`), with `lone_latin` a
/// Latin letter other than a Roman numeral; a `*` after it is a
/// superscript (`c*`). Without `lone_latin` (English, where `a` and `I`
/// are words) a Latin letter other than `a`, `A`, `I` followed by ` = `
/// is a symbol too (`W = 1`, `D = 426.9 mm`), set as in the formulas.
fn lone(s: &[char], lone_latin: bool) -> Option<(String, usize)> {
    // a square or a cube after the letter (`l²`) leaves it alone
    let free = |k: usize| {
        s.get(k)
            .is_none_or(|c| matches!(c, '²' | '³') || !c.is_alphanumeric() && !matches!(c, '_' | '^'))
    };
    let c = *s.first()?;
    let equated = !matches!(c, 'a' | 'A' | 'I') && matches!(s.get(1), Some(' ' | '\u{a0}')) && matches!(s.get(2), Some('=' | '≈'));
    let lone_latin = lone_latin || equated;
    let (math, len) = if c == 'Δ' && s.get(1).is_some_and(|d| d.is_ascii_alphabetic() || is_greek(*d)) && free(2) {
        (format!("Δ {}", s[1]), 2)
    } else if free(1)
        && (is_greek(c) && c != 'Δ' || c.is_ascii_alphabetic() && (lone_latin && !matches!(c, 'I' | 'V' | 'X') || s.get(1) == Some(&'*')))
    {
        (c.to_string(), 1)
    } else {
        return None;
    };
    if s.get(len) == Some(&'*') {
        return Some((format!("{math}^*"), len + 1));
    }
    Some((math, len))
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
            // a subscript in quotes is upright as written: I_"M" (Mertsalov's)
            if s.get(start) == Some(&'"')
                && let Some(len) = s[start + 1..].iter().position(|c| *c == '"')
                && len > 0
            {
                let end = start + 1 + len;
                math.push(mark);
                math.extend(&s[start..=end]);
                i = end + 1;
                continue;
            }
            // a script in parentheses keeps them: u_13^(H) (Willis's ratio)
            if s.get(start) == Some(&'(')
                && let Some(len) = s[start + 1..].iter().position(|c| *c == ')')
                && len > 0
                && s[start + 1..start + 1 + len].iter().all(|c| c.is_alphanumeric())
            {
                let end = start + 1 + len;
                let inner: String = s[start + 1..end].iter().collect();
                math.push(mark);
                math.push_str(&format!("(({}))", spaced(&inner)));
                i = end + 1;
                continue;
            }
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
    ('\u{0391}'..='\u{03C9}').contains(&c) || matches!(c, 'ϑ' | 'ϕ' | 'ϵ')
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
        assert_eq!(m("I_\"M\""), "I_\"M\"");
        assert_eq!(m("u_13^(H)"), "u_(13)^((H))");
        // a number with a power, words without a mark, a lone underscore stay text
        assert_eq!(notation("10^5 a _ b"), "10^5 a _ b");
        let r = runs(&notation("по K_v и l_AB."));
        assert_eq!(r.len(), 5, "{r:?}");
        assert_eq!(r[4], (false, ".".to_string()));
    }
}
