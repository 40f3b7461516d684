//! Every symbol a "где …" / "де …" / "where …" line explains stands in
//! its formula in the same form (GOST 2.105, 4.2.15): read back from the
//! PDF, where typst's math sets a letter in math italic (𝜃, 𝐾) and a
//! quoted or operator subscript upright (`max`, `ур`), so an upright `θ`
//! or `W` in the line under an italic 𝜃 or 𝑊 of the formula, an italic
//! 𝑀 under an upright M, or a symbol the formula does not hold, fails.
//!
//! Each formula of the composed note with the line under it is typeset
//! alone between two markers; the line's entries are split at `;`, the
//! symbols of an entry are what stands before " — " (the English " is ",
//! " the " …), split at `,`; each, spaces and the vector arrows removed,
//! must be found in the formula's text. A definition (`inv α = tg α − α`)
//! is no symbol of the formula and is left out.

use tmm_note::{Block, Note, Section, Text, compose, typeset_with_warnings};
use tmm_report::project::Language;
use tmm_report::run::run_task_in;

use super::fixtures::task;

/// The where-line's first word in each language.
const PREFIXES: [&str; 3] = ["где ", "де ", "where "];
/// What ends the symbols of an entry.
const VERBS: [&str; 7] = [" — ", " is ", " are ", " the ", " as ", " its ", " their "];

fn plain_start(t: &Text) -> String {
    match t.0.first() {
        Some(tmm_note::Span::Plain(s)) => s.chars().filter(|c| *c != '\u{E000}' && *c != '\u{E001}').collect(),
        _ => String::new(),
    }
}

/// Every formula with the line under it, in order.
fn pairs(note: &Note) -> Vec<(Block, Block)> {
    fn walk(ss: &[Section], out: &mut Vec<(Block, Block)>) {
        for s in ss {
            for w in s.blocks.windows(2) {
                if let (Block::Formula { .. }, Block::Paragraph(t)) = (&w[0], &w[1]) {
                    let start = plain_start(t);
                    if PREFIXES.iter().any(|p| start.starts_with(p)) {
                        out.push((w[0].clone(), w[1].clone()));
                    }
                }
            }
            walk(&s.subsections, out);
        }
    }
    let mut out = Vec::new();
    walk(&note.sections, &mut out);
    out
}

/// The text with no white space and no combining arrow (a vector's
/// arrow sits over the letter; the line names the magnitude).
fn squeeze(s: &str) -> String {
    s.chars()
        .filter(|c| !c.is_whitespace() && !matches!(c, '\u{20D7}' | '\u{20D1}' | '\u{AD}'))
        .collect()
}

/// Whether the formula's text holds the symbol: as printed, or with a
/// power between its letter and its subscript (the PDF's text gives 𝑟₀²
/// as 𝑟, 2, 0).
fn in_formula(formula: &str, sym: &str) -> bool {
    if formula.contains(sym) {
        return true;
    }
    let f: Vec<char> = formula.chars().collect();
    let s: Vec<char> = sym.chars().collect();
    s.len() > 1 && (0..f.len().saturating_sub(s.len())).any(|i| f[i] == s[0] && f[i + 2..].starts_with(&s[1..]))
}

/// The symbols of one where-line's text as printed.
fn symbols(line: &str) -> Vec<String> {
    let line = line.split_whitespace().collect::<Vec<_>>().join(" ");
    let mut rest = line.as_str();
    for p in PREFIXES {
        if let Some(r) = line.strip_prefix(p.trim_end()) {
            rest = r;
        }
    }
    let mut out = Vec::new();
    for entry in rest.split(';') {
        let entry = format!("{} ", entry.trim());
        let end = VERBS.iter().filter_map(|v| entry.find(v)).min().unwrap_or(0);
        let head = &entry[..end];
        if head.contains('=') {
            continue;
        }
        out.extend(head.split(',').map(squeeze).filter(|s| !s.is_empty()));
    }
    out
}

/// The text without the pages' numbers: a line of digits alone between
/// two empty lines (the footer's, which a where-line running over a page
/// break would otherwise read as part of a symbol: `7𝜑`).
fn without_page_numbers(text: &str) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let empty = |i: Option<&&str>| i.is_none_or(|l| l.trim().is_empty());
    let mut out = Vec::new();
    for (i, l) in lines.iter().enumerate() {
        let digits = !l.trim().is_empty() && l.trim().chars().all(|c| c.is_ascii_digit());
        if digits && i > 0 && empty(lines.get(i - 1)) && empty(lines.get(i + 1)) {
            continue;
        }
        out.push(*l);
    }
    out.join("\n")
}

/// The (formula, line) pairs of a note that do not agree.
fn mismatches(note: &Note) -> (usize, Vec<String>) {
    let pairs = pairs(note);
    let mut test = Note {
        lang: note.lang,
        ..Note::default()
    };
    let mut s = Section::new("where");
    for (k, (f, w)) in pairs.iter().enumerate() {
        s.blocks.push(Block::Paragraph(Text::plain(format!("@@{k}@@"))));
        s.blocks.push(f.clone());
        s.blocks.push(w.clone());
    }
    s.blocks.push(Block::Paragraph(Text::plain(format!("@@{}@@", pairs.len()))));
    test.sections.push(s);
    let t = typeset_with_warnings(&test).unwrap();
    assert!(t.warnings.is_empty(), "{:#?}", t.warnings);
    let text = without_page_numbers(&pdf_extract::extract_text_from_mem(&t.pdf).unwrap());
    let mut bad = Vec::new();
    let mut checked = 0;
    for k in 0..pairs.len() {
        let a = text.find(&format!("@@{k}@@")).unwrap() + format!("@@{k}@@").len();
        let b = text.find(&format!("@@{}@@", k + 1)).unwrap();
        let chunk = &text[a..b];
        let at = PREFIXES
            .iter()
            .filter_map(|p| chunk.find(p.trim_end()))
            .min()
            .unwrap_or_else(|| panic!("pair {k}: no where-line in {chunk:?}"));
        let (formula, line) = chunk.split_at(at);
        let formula = squeeze(formula);
        let syms = symbols(line);
        assert!(!syms.is_empty(), "pair {k}: no symbol read in {line:?}");
        for sym in syms {
            checked += 1;
            if !in_formula(&formula, &sym) {
                bad.push(format!("{sym:?} not in {formula:?}"));
            }
        }
    }
    (checked, bad)
}

#[test]
fn the_symbol_reader_reads_each_language() {
    assert_eq!(symbols("где 𝜃 — угол, °; 𝐾𝑣 — коэффициент."), ["𝜃", "𝐾𝑣"]);
    assert_eq!(
        symbols("where 𝑣𝐵, 𝑣𝐶 are the speeds; 𝑙 the length; inv 𝛼 = tan 𝛼 − 𝛼 the function"),
        ["𝑣𝐵", "𝑣𝐶", "𝑙"]
    );
    assert!(in_formula("𝑠0=√𝑟20−𝑒2", "𝑟0") && !in_formula("𝑠0=√𝑟20−𝑒2", "𝑟1"));
}

#[test]
fn every_where_line_symbol_stands_in_its_formula_as_set_there() {
    let mut report = Vec::new();
    for (name, langs) in [
        ("default", &[Language::Ru, Language::Uk, Language::En][..]),
        ("seed-003-sixbar.toml", &[Language::Ru, Language::En][..]),
        ("synth-seed-003-six-bar.toml", &[Language::Ru][..]),
        ("planetary-sun-planet-ring.toml", &[Language::Ru, Language::En][..]),
    ] {
        let src = task(name);
        for lang in langs {
            let run = run_task_in(&src, Some(*lang)).unwrap();
            let note = compose(&run, &src).unwrap();
            let (checked, bad) = mismatches(&note);
            println!("{name} {lang:?}: {checked} symbols checked, {} not as in the formula", bad.len());
            assert!(checked > 0, "{name} {lang:?}");
            report.extend(bad.into_iter().map(|b| format!("{name} {lang:?}: {b}")));
        }
    }
    assert!(report.is_empty(), "{} symbols:\n{}", report.len(), report.join("\n"));
}

#[test]
fn the_check_fails_on_an_upright_symbol_under_an_italic_one() {
    let mut note = Note::default();
    let mut s = Section::new("x");
    s.blocks.push(Block::Formula {
        typst_math: "W = 3 n".into(),
        label: None,
    });
    // W and n as plain text: upright, unlike the formula's 𝑊 and 𝑛
    s.blocks
        .push(Block::Paragraph(Text::plain("где W — подвижность; n — число звеньев.")));
    note.sections.push(s);
    let (checked, bad) = mismatches(&note);
    assert_eq!((checked, bad.len()), (2, 2), "{bad:?}");
}
