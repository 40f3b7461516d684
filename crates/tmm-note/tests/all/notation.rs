//! The note's notation is typeset: in the PDF's text of the default
//! project's note (and of the engine and six-bar examples), in ru, uk and
//! en, no raw `K_v`, `M_ур`, `R^τ`, `h_a*`-style token is left — every
//! subscript and superscript of the note's words, tables, headers and
//! captions went through math. The drawings are blanked first: their
//! lettering is the drawings' own (tmm-report), not the note's text.

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
}

#[test]
fn no_raw_notation_in_the_default_note() {
    for lang in [Language::Ru, Language::Uk, Language::En] {
        let text = pdf_text_of("default.toml", DEFAULT_TASK, lang);
        let raw = raw_tokens(&text);
        assert!(raw.is_empty(), "{lang:?}: {} raw tokens: {raw:#?}", raw.len());
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
    }
}
