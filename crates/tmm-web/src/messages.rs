//! The solver's and the task reader's messages in Russian and Ukrainian
//! (сообщения об ошибках на языке интерфейса): the page's screen never
//! mixes languages.
//!
//! The messages are made in English by the core crates and `tmm-report`
//! (the command line prints them so, whatever the task's language). The
//! page's word file `crates/tmm-web/lang/messages.toml` gives each English
//! wording, under a stable key, its Russian and Ukrainian wording; `{1}`,
//! `{2}`, … stand for the parts that vary (numbers, names, fields, a nested
//! message). A message is put into another language by [`translate`]:
//!
//! - a text without English prose ([`has_prose`]: numbers, symbols, field
//!   paths, units, the user's own names in quotes) stays as it is — the
//!   place `task.toml:12:9` and the field `linkage.links.BC.length` among
//!   them;
//! - a text that one English wording matches whole is that wording's
//!   translation, each varying part translated the same way;
//! - else a text joined of parts by `: `, `; `, ` — ` or `. ` is the parts'
//!   translations joined alike (a message is usually the place, the field,
//!   then what is wrong, then what would be valid).
//!
//! Numbers take a decimal comma ([`decimal_commas`]), except where the user
//! would copy them into the task file.
//!
//! When some part has no wording, the message has no translation: the page
//! then says so in the interface's language and keeps the English text out
//! of sight until asked (see `web/app.js`, `said`).

use std::collections::HashMap;
use std::sync::OnceLock;

use tmm_report::project::Language;

/// The word file of the messages, embedded at build time.
pub const MESSAGES_TOML: &str = include_str!("../lang/messages.toml");

/// One message: its key, its English wording cut at the varying parts, and
/// its Russian and Ukrainian wordings.
#[derive(Debug)]
pub struct Wording {
    /// The stable key (`messages.<key>` in the word file).
    pub key: String,
    /// The English wording: literal text and numbered holes.
    pub en: Vec<Piece>,
    /// The Russian wording, with `{n}` for the holes.
    pub ru: String,
    /// The Ukrainian wording, with `{n}` for the holes.
    pub uk: String,
}

/// A piece of an English wording.
#[derive(Debug, Clone, PartialEq)]
pub enum Piece {
    /// Text as written.
    Text(String),
    /// A varying part, `{n}`, translated in turn.
    Hole(usize),
    /// A varying part taken as it is, `{=n}`: the user's own names
    /// (`the links are 1, 2, abc`).
    Raw(usize),
}

/// Cut a wording at its holes `{1}`, `{2}`, ….
///
/// ```
/// use tmm_web::messages::{pieces, Piece};
/// assert_eq!(pieces("got {1} mm"), vec![Piece::Text("got ".into()), Piece::Hole(1), Piece::Text(" mm".into())]);
/// assert_eq!(pieces("links {=2}"), vec![Piece::Text("links ".into()), Piece::Raw(2)]);
/// ```
pub fn pieces(s: &str) -> Vec<Piece> {
    let mut out = Vec::new();
    let mut rest = s;
    while let Some(p) = rest.find('{') {
        let close = rest[p..].find('}').map(|c| p + c);
        let inner = close.map(|c| &rest[p + 1..c]).unwrap_or_default();
        let raw = inner.starts_with('=');
        let n = inner.trim_start_matches('=').parse::<usize>().ok().filter(|_| close.is_some());
        match (close, n) {
            (Some(c), Some(n)) => {
                if p > 0 {
                    out.push(Piece::Text(rest[..p].to_string()));
                }
                out.push(if raw { Piece::Raw(n) } else { Piece::Hole(n) });
                rest = &rest[c + 1..];
            }
            _ => {
                out.push(Piece::Text(rest[..=p].to_string()));
                rest = &rest[p + 1..];
            }
        }
    }
    if !rest.is_empty() {
        out.push(Piece::Text(rest.to_string()));
    }
    // glue neighbouring texts
    let mut glued: Vec<Piece> = Vec::with_capacity(out.len());
    for p in out {
        match (glued.last_mut(), p) {
            (Some(Piece::Text(a)), Piece::Text(b)) => a.push_str(&b),
            (_, p) => glued.push(p),
        }
    }
    glued
}

/// Every wording of the word file, read once.
///
/// # Panics
/// Never for the embedded file: its test reads it whole and checks each
/// wording's holes.
pub fn wordings() -> &'static [Wording] {
    static ALL: OnceLock<Vec<Wording>> = OnceLock::new();
    ALL.get_or_init(|| {
        let doc: toml::Table = MESSAGES_TOML.parse().expect("crates/tmm-web/lang/messages.toml is TOML");
        let Some(toml::Value::Table(m)) = doc.get("messages") else {
            return Vec::new();
        };
        let text = |t: &toml::Table, k: &str| t.get(k).and_then(|v| v.as_str()).unwrap_or_default().to_string();
        m.iter()
            .filter_map(|(key, v)| {
                let t = v.as_table()?;
                Some(Wording {
                    key: key.clone(),
                    en: pieces(&text(t, "en")),
                    ru: text(t, "ru"),
                    uk: text(t, "uk"),
                })
            })
            .collect()
    })
}

/// Units, function names and symbols written with Latin letters that are
/// not English words (they read the same in a Russian text).
const NOT_WORDS: &[&str] = &[
    "mm", "cm", "dm", "km", "in", "ft", "rad", "deg", "rpm", "min", "max", "kg", "kgf", "Pa", "kPa", "MPa", "bar", "inv", "cos", "sin",
    "tan", "atan", "arg", "mod", "exp", "ln", "lg", "sqrt", // the task file's one-word values
    "shaper",
];

/// English words of one or two letters, written in lower case (the rest of
/// that length are symbols: `A`, `OA`, `x1`, `mm`).
const SHORT_WORDS: &[&str] = &[
    "a", "an", "as", "at", "be", "by", "do", "go", "if", "in", "is", "it", "no", "of", "on", "or", "so", "to", "up", "we",
];

/// Whether `text` holds an English word outside symbols, units and the
/// user's own strings: the text in backticks, quotes (`"…"`, `«…»`) and
/// square brackets is the user's or the file's own, a token with a digit,
/// `.`, `_`, `/`, `=`, `-` or a letter outside ASCII is a symbol (a
/// hyphenated word is one of the task file's values, `crank-slider`,
/// `equal-sliding`: the wordings write no hyphenated English), a key before
/// ` = ` is the task file's own, a word of
/// capitals (`RRR`, `TOML`, `OA`) or with a capital inside (`kPa`, `Kv`) is
/// a symbol, and so are the units, function names and one-word values of
/// [`NOT_WORDS`] and the task file's section names (`tmm_report::task::SECTIONS`); `e.g.` and `i.e.` are English.
/// The browser test applies the same rule to the Russian and Ukrainian
/// screens.
///
/// ```
/// use tmm_web::messages::has_prose;
/// assert!(!has_prose("task.toml:12:9: linkage.links[0] (1).length: −5 mm, `BC`"));
/// assert!(!has_prose("длина звена BC должна быть положительной, а не -5 mm"));
/// assert!(has_prose("must be positive"));
/// assert!(has_prose("Zhukovsky's lever"));
/// assert!(!has_prose("inv αw = 0,012 (TOML, RRR, kPa)"));
/// assert!(!has_prose("задайте range = \"partial\""));
/// assert!(!has_prose("файлы *.txt и docs/web.md, точка A"));
/// ```
pub fn has_prose(text: &str) -> bool {
    let plain = strip_quoted(text);
    let toks: Vec<&str> = plain.split_whitespace().collect();
    toks.iter().enumerate().any(|(i, tok)| {
        // a key of the task file: `range = …`
        if toks.get(i + 1).is_some_and(|n| n.starts_with('=')) {
            return false;
        }
        // a file pattern or a path: `*.txt`, `.toml`, `docs/web.md`
        if tok.trim_start_matches(['(', '"', '«']).starts_with(['*', '.']) || tok.contains('/') {
            return false;
        }
        let tok = tok.trim_matches(|c: char| !c.is_alphanumeric());
        if tok == "e.g" || tok == "i.e" {
            return true;
        }
        // a command-line option
        if toks[i].trim_start_matches(['(', '"']).starts_with("--") {
            return false;
        }
        if tok.is_empty()
            || tok
                .chars()
                .any(|c| c.is_ascii_digit() || ".=_/<>+*·".contains(c) || (c.is_alphabetic() && !c.is_ascii()))
        {
            return false;
        }
        // a value of the task file: `crank-slider`, `equal-sliding`
        if tok.contains('-') {
            return false;
        }
        tok.split(['\'', '’']).any(is_word)
    })
}

/// Whether one run of ASCII letters is an English word (see [`has_prose`]).
fn is_word(w: &str) -> bool {
    if w.is_empty() || !w.chars().all(|c| c.is_ascii_alphabetic()) || NOT_WORDS.contains(&w) || tmm_report::task::SECTIONS.contains(&w) {
        return false;
    }
    let lower = w.to_ascii_lowercase();
    if w.len() <= 2 {
        // a capital alone or first is a point's or a link's name (`A`, `Of`)
        return SHORT_WORDS.contains(&lower.as_str()) && w.chars().all(|c| c.is_ascii_lowercase());
    }
    // capitals inside: a symbol or a unit
    w.chars().skip(1).all(|c| c.is_ascii_lowercase())
}

/// `text` without its parts in backticks, double quotes, guillemets and
/// square brackets.
fn strip_quoted(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut close: Option<char> = None;
    let mut depth = 0usize;
    for c in text.chars() {
        match close {
            Some(end) if c == end => {
                if end == ']' && depth > 1 {
                    depth -= 1;
                } else {
                    close = None;
                    depth = 0;
                }
                // the quoted part reads as one symbol glued to its neighbours
                out.push('0');
            }
            Some(']') if c == '[' => depth += 1,
            Some(_) => {}
            None => match c {
                '`' => close = Some('`'),
                '"' => close = Some('"'),
                '«' => close = Some('»'),
                '[' => {
                    close = Some(']');
                    depth = 1;
                }
                _ => out.push(c),
            },
        }
    }
    out
}

/// The separators a message's parts are joined by, tried in this order.
const JOINS: &[&str] = &[": ", "; ", " — ", ". ", ", "];

/// `text` (a message or its help, in English) in `lang`: `Some` with the
/// whole text translated, `None` when a part has no wording in the word
/// file (see the module's header). English is returned as it is.
///
/// ```
/// use tmm_report::project::Language;
/// use tmm_web::messages::translate;
/// let m = "task.toml:12:9: linkage.links.BC.length: must be positive";
/// let ru = translate(m, Language::Ru).unwrap();
/// assert!(ru.starts_with("task.toml:12:9: linkage.links.BC.length: "), "{ru}");
/// assert!(!tmm_web::messages::has_prose(&ru), "{ru}");
/// assert_eq!(translate(m, Language::En).as_deref(), Some(m));
/// assert_eq!(translate("a sentence nobody wrote down", Language::Uk), None);
/// ```
pub fn translate(text: &str, lang: Language) -> Option<String> {
    if lang == Language::En {
        return Some(text.to_string());
    }
    let mut memo = HashMap::new();
    let mut budget = 200_000usize;
    let out = Tr {
        lang,
        memo: &mut memo,
        budget: &mut budget,
    }
    .text(text, 0)?;
    Some(decimal_commas(&tmm_report::message_numbers::tidy(&out)))
}

/// `text` with the decimal point of each number written as a comma, as
/// Russian and Ukrainian write numbers (the page's other numbers do so too),
/// except where the user would copy it into the task file: after `= ` and
/// inside quotes or backticks (TOML and the unit reader take a point). A
/// number glued to a letter, digit, `_` or `.` before it (`x1.5`,
/// `task.toml`) or followed by a second point (`0.2.130`) is left alone.
///
/// ```
/// use tmm_web::messages::decimal_commas;
/// assert_eq!(decimal_commas("x1 = 0.2: сумма -1.0750 > 0.5 mm"), "x1 = 0.2: сумма -1,0750 > 0,5 mm");
/// assert_eq!(decimal_commas("t.toml:3:5: links.1.mass, \"0.5 mm\", `2.5`, 0.2.130"), "t.toml:3:5: links.1.mass, \"0.5 mm\", `2.5`, 0.2.130");
/// ```
pub fn decimal_commas(text: &str) -> String {
    let b = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let mut quote: Option<u8> = None;
    let mut i = 0;
    let mut done = 0;
    while i < b.len() {
        let c = b[i];
        match quote {
            Some(q) if c == q => quote = None,
            Some(_) => {}
            None if c == b'"' || c == b'`' => quote = Some(c),
            None if c.is_ascii_digit() => {
                let glued = i > 0 && (b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_' || b[i - 1] == b'.');
                let digits_end = |from: usize| (from..b.len()).find(|&k| !b[k].is_ascii_digit()).unwrap_or(b.len());
                let j = digits_end(i);
                let point = j + 1 < b.len() && b[j] == b'.' && b[j + 1].is_ascii_digit();
                let k = if point { digits_end(j + 1) } else { j };
                let second = point && k + 1 < b.len() && b[k] == b'.' && b[k + 1].is_ascii_digit();
                let assigned = text[..i].trim_end_matches(['-', '+']).ends_with("= ");
                if point && !glued && !second && !assigned {
                    out.push_str(&text[done..j]);
                    out.push(',');
                    done = j + 1;
                }
                i = k;
                continue;
            }
            None => {}
        }
        i += 1;
    }
    out.push_str(&text[done..]);
    out
}

struct Tr<'a> {
    lang: Language,
    memo: &'a mut HashMap<String, Option<String>>,
    /// Steps left: a pathological text gives up instead of searching long.
    budget: &'a mut usize,
}

impl Tr<'_> {
    fn text(&mut self, s: &str, depth: usize) -> Option<String> {
        if !has_prose(s) {
            return Some(s.to_string());
        }
        if let Some(r) = self.memo.get(s) {
            return r.clone();
        }
        if depth > 64 || *self.budget == 0 {
            return None;
        }
        *self.budget -= 1;
        let r = self.whole(s, depth).or_else(|| self.joined(s, depth));
        self.memo.insert(s.to_string(), r.clone());
        r
    }

    /// One wording matching `s` whole.
    fn whole(&mut self, s: &str, depth: usize) -> Option<String> {
        // a sentence's first letter may have been capitalised or not
        for w in wordings() {
            let mut caps = Vec::new();
            if self.fit(&w.en, s, depth, &mut caps) {
                let target = if self.lang == Language::Uk { &w.uk } else { &w.ru };
                let mut out = target.clone();
                for (n, c) in caps.iter().rev() {
                    out = out.replace(&format!("{{{n}}}"), c);
                }
                return Some(out);
            }
        }
        None
    }

    /// Whether `pieces` match `s` whole; the holes' translations in `caps`.
    fn fit(&mut self, pieces: &[Piece], s: &str, depth: usize, caps: &mut Vec<(usize, String)>) -> bool {
        match pieces {
            [] => s.is_empty(),
            [Piece::Text(t), rest @ ..] => s.strip_prefix(t.as_str()).is_some_and(|r| self.fit(rest, r, depth, caps)),
            [Piece::Raw(n)] if !s.is_empty() => {
                caps.push((*n, s.to_string()));
                true
            }
            [Piece::Hole(n)] => match self.text(s, depth + 1) {
                Some(c) if !s.is_empty() => {
                    caps.push((*n, c));
                    true
                }
                _ => false,
            },
            [hole @ (Piece::Hole(n) | Piece::Raw(n)), Piece::Text(t), ..] => {
                let mut from = 0;
                while let Some(p) = s[from..].find(t.as_str()).map(|p| from + p) {
                    if p > 0 {
                        let mark = caps.len();
                        let c = match hole {
                            Piece::Raw(_) => Some(s[..p].to_string()),
                            _ => self.text(&s[..p], depth + 1),
                        };
                        if let Some(c) = c {
                            caps.push((*n, c));
                            if self.fit(&pieces[1..], &s[p..], depth, caps) {
                                return true;
                            }
                        }
                        caps.truncate(mark);
                    }
                    from = p + s[p..].chars().next().map_or(1, char::len_utf8);
                    if *self.budget == 0 {
                        return false;
                    }
                    *self.budget -= 1;
                }
                false
            }
            // two holes side by side cannot be told apart
            _ => false,
        }
    }

    /// `s` as parts joined by one of [`JOINS`], each part translated.
    fn joined(&mut self, s: &str, depth: usize) -> Option<String> {
        for j in JOINS {
            let mut from = 0;
            while let Some(p) = s[from..].find(j).map(|p| from + p) {
                let (a, b) = (&s[..p], &s[p + j.len()..]);
                if !a.is_empty()
                    && !b.is_empty()
                    && let Some(ta) = self.text(a, depth + 1)
                    && let Some(tb) = self.text(b, depth + 1)
                {
                    return Some(format!("{ta}{j}{tb}"));
                }
                from = p + j.len();
            }
        }
        None
    }
}
