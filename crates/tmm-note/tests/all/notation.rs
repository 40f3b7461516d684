//! The note's notation is typeset: in the PDF's text of the default
//! project's note (and of the engine and six-bar examples), in ru, uk and
//! en, no raw `K_v`, `M_ур`, `R^τ`, `h_a*`-style token is left — every
//! subscript and superscript of the note's words, tables, headers and
//! captions went through math; nor a Greek letter written flat with its
//! index (`εα`, `ωmax`, `φ20`, `ΔTmax`: typst's math sets the letter in
//! math italic, U+1D6FC …, so a plain Greek letter followed at once by a
//! plain letter or digit was never typeset as a symbol), nor a plain Greek
//! letter standing alone (`угол φ` under a formula's 𝜑). The drawings are
//! blanked first: their lettering is the drawings' own (tmm-report), not
//! the note's text.

use tmm_note::{Block, Note, Section, compose, typeset_with_warnings};
use tmm_report::TaskSource;
use tmm_report::project::Language;
use tmm_report::run::{DEFAULT_TASK, run_task_in};

const BLANK: &str = r#"<svg xmlns="http://www.w3.org/2000/svg" width="10mm" height="10mm" viewBox="0 0 10 10"></svg>"#;

fn blank_figures(note: &mut Note) {
    fn walk(ss: &mut [Section]) {
        for s in ss {
            for b in &mut s.blocks {
                if let Block::Figure { svg, .. } = b {
                    *svg = BLANK.to_string();
                }
            }
            walk(&mut s.subsections);
        }
    }
    // the assignment's scheme too (its figure stands outside the sections)
    for b in &mut note.assignment {
        if let Block::Figure { svg, .. } = b {
            *svg = BLANK.to_string();
        }
    }
    walk(&mut note.sections);
    walk(&mut note.appendices);
}

/// The raw notation tokens of a text: a letter, `_` or `^`, a letter or digit.
fn raw_tokens(text: &str) -> Vec<String> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    for i in 1..chars.len().saturating_sub(1) {
        if matches!(chars[i], '_' | '^') && chars[i - 1].is_alphabetic() && chars[i + 1].is_alphanumeric() {
            let from = i.saturating_sub(6);
            let to = (i + 7).min(chars.len());
            out.push(chars[from..to].iter().collect());
        }
    }
    out
}

/// A character of typst's math alphabets (math italic 𝑇, 𝜔 …): the PDF's
/// text gives a letter set as a math symbol in this block.
fn math_letter(c: char) -> bool {
    ('\u{1D400}'..='\u{1D7FF}').contains(&c)
}

/// A plain letter or digit (not one of math's alphabets, not a
/// superscript such as the ² of dφ²).
fn plain_alnum(c: char) -> bool {
    (c.is_alphabetic() || c.is_ascii_digit()) && !math_letter(c)
}

/// Greek letters written flat with an index: a plain lower-case Greek
/// letter right after a non-letter and right before a plain letter or digit
/// (`εα`, `ωmax`, `φ20`), or `Δ` before a plain letter or digit (`ΔT`,
/// `ΔTmax`, `Δy`); and a plain Greek letter standing alone (`угол φ`,
/// `θ —`), which the formulas set in math italic (𝜑, 𝜃).
fn flat_greek(text: &str) -> Vec<String> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    for i in 0..chars.len() {
        let c = chars[i];
        let after_gap = i == 0 || !chars[i - 1].is_alphanumeric();
        let next = chars.get(i + 1).copied();
        let greek = ('α'..='ω').contains(&c) || matches!(c, 'ϑ' | 'ϕ');
        let flat = after_gap
            && (greek && (next.is_some_and(plain_alnum) || next.is_none_or(|n| !n.is_alphanumeric()))
                || c == 'Δ' && next.is_some_and(plain_alnum));
        if flat {
            out.push(chars[i.saturating_sub(6)..(i + 7).min(chars.len())].iter().collect());
        }
    }
    out
}

fn pdf_text_of(name: &str, text: &str, lang: Language) -> String {
    let task = TaskSource::new(name, text);
    let run = run_task_in(&task, Some(lang)).unwrap();
    let mut note = compose(&run, &task).unwrap();
    blank_figures(&mut note);
    let t = typeset_with_warnings(&note).unwrap();
    assert!(t.warnings.is_empty(), "{name} {lang:?}: {:#?}", t.warnings);
    pdf_extract::extract_text_from_mem(&t.pdf).unwrap()
}

#[test]
fn the_raw_token_finder_finds_what_it_must() {
    assert_eq!(raw_tokens("a K_v b").len(), 1);
    assert_eq!(raw_tokens("R^τ, Н").len(), 1);
    assert!(raw_tokens("K𝑣 = 1,107; 10^ _x").is_empty());
    assert_eq!(flat_greek("εα = 1,205; ωmax, φ20 и ΔTmax").len(), 4);
    assert_eq!(flat_greek("угол φ, ψ = 38°, (φ, ψ), Δy").len(), 5);
    assert!(flat_greek("𝜀𝛼 = 1,205; 𝜔max, Δ𝑇max, угол 𝜑, 𝜓 = 38°, (𝜑, 𝜓), Δ𝑦, d²s/dφ²").is_empty());
}

#[test]
fn no_raw_notation_in_the_default_note() {
    for lang in [Language::Ru, Language::Uk, Language::En] {
        let text = pdf_text_of("default.toml", DEFAULT_TASK, lang);
        let raw = raw_tokens(&text);
        assert!(raw.is_empty(), "{lang:?}: {} raw tokens: {raw:#?}", raw.len());
        let flat = flat_greek(&text);
        assert!(flat.is_empty(), "{lang:?}: {} flat Greek symbols: {flat:#?}", flat.len());
    }
}

#[test]
fn no_raw_notation_in_the_engine_and_six_bar_notes() {
    for file in ["compressor-two-stage.toml", "seed-003-sixbar.toml"] {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples").join(file);
        let task = std::fs::read_to_string(path).unwrap();
        let text = pdf_text_of(file, &task, Language::Ru);
        let raw = raw_tokens(&text);
        assert!(raw.is_empty(), "{file}: {} raw tokens: {raw:#?}", raw.len());
        let flat = flat_greek(&text);
        assert!(flat.is_empty(), "{file}: {} flat Greek symbols: {flat:#?}", flat.len());
    }
}

/// The plain (not typeset) Latin letters of an English words text that are
/// symbols: one standing alone at the text's end ("Module m", "Number of
/// planets k") or a lower-case one in a product of such letters ("k·m·l²",
/// "q·l"; not a unit's "kg·m" nor "N·m").
fn upright_symbols(marked: &str) -> Vec<String> {
    let pieces = tmm_note::notation::runs(marked);
    let mut found = Vec::new();
    for (n, (math, run)) in pieces.iter().enumerate() {
        if *math {
            continue;
        }
        let c: Vec<char> = run.chars().collect();
        let lone = |i: usize| {
            c[i].is_ascii_alphabetic()
                && (i == 0 || !c[i - 1].is_alphanumeric())
                && c.get(i + 1).is_none_or(|d| !d.is_alphanumeric() || matches!(d, '²' | '³'))
        };
        let last = n + 1 == pieces.len();
        // not the unit after a name's comma ("the lengths …, m")
        let unit = c.len() >= 3 && c[c.len() - 3] == ',';
        if last && !unit && c.len() >= 2 && c[c.len() - 2] == ' ' && lone(c.len() - 1) && !matches!(c[c.len() - 1], 'a' | 'A' | 'I') {
            found.push(run.clone());
        }
        for i in 0..c.len() {
            let product = c.get(i + 1) == Some(&'·') && c.get(i + 2).is_some_and(|d| d.is_ascii_lowercase()) && lone(i + 2)
                || i >= 2 && c[i - 1] == '·' && c[i - 2].is_ascii_lowercase() && lone(i - 2);
            if c[i].is_ascii_lowercase() && lone(i) && product {
                found.push(run.clone());
            }
        }
    }
    found
}

/// Every English words text sets its symbols as the formulas do: a letter
/// standing alone at a label's end (the module m, the planets' number k,
/// the follower's stroke h) and the letters of a product (q of m = q·l, k
/// of J_S = k·m·l²) are math, as the Russian and Ukrainian texts set them.
/// Failed before: `q_mass_per_length`, `q_inertia_k`, `q_module`,
/// `q_planets` and 20 more printed upright "q", "k", "m".
#[test]
fn english_labels_typeset_their_lone_and_product_symbols() {
    assert_eq!(upright_symbols("Module m").len(), 1);
    assert_eq!(upright_symbols("J_S = k·m·l²").len(), 3);
    assert!(upright_symbols("Moment, N·m; inertia, kg·m²; a share of a").is_empty());
    assert!(upright_symbols("the lengths of the links, m").is_empty());
    let words = tmm_note::compose::Words::load(tmm_note::Lang::En).unwrap();
    let mut raw = Vec::new();
    for key in words.keys() {
        let marked = tmm_note::notation::notation_with(words.get(key).unwrap(), false);
        let found = upright_symbols(&marked);
        if !found.is_empty() {
            raw.push(format!("{key}: {found:?}"));
        }
    }
    assert!(
        raw.is_empty(),
        "{} English texts with upright symbols:\n{}",
        raw.len(),
        raw.join("\n")
    );
}
