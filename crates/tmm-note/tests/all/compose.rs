//! The note composed from a run of the default course project, in each
//! language: it typesets without a warning (no missing glyph), its text has
//! the section headings of the language and the key numbers as the report
//! gives them rounded as printed; a task with only a gear pair has no
//! linkage section; a sheet's PDF has the SVG's page size.

use tmm_note::compose::{DIGITS, Words};
use tmm_note::notation::{MATH_CLOSE, MATH_OPEN};
use tmm_note::number::format_number;
use tmm_note::{Block, Lang, Note, Section, Span, compose, sheet_pdf, typeset_with_warnings};
use tmm_report::TaskSource;
use tmm_report::project::Language;
use tmm_report::run::{DEFAULT_TASK, run_task_in};

fn language(lang: Lang) -> Language {
    match lang {
        Lang::Ru => Language::Ru,
        Lang::Uk => Language::Uk,
        Lang::En => Language::En,
    }
}

/// The PDF's text with every run of white space made one space and the
/// soft hyphens of line breaks removed.
fn pdf_text(pdf: &[u8]) -> String {
    let raw = pdf_extract::extract_text_from_mem(pdf).expect("the PDF's text extracts");
    raw.replace('\u{00AD}', "").split_whitespace().collect::<Vec<_>>().join(" ")
}

/// `value` as the note prints it in `lang`.
fn printed(value: f64, lang: Lang) -> String {
    format_number(value, DIGITS, lang).unwrap().mantissa
}

fn ptr(report: &serde_json::Value, p: &str) -> f64 {
    report
        .pointer(p)
        .and_then(serde_json::Value::as_f64)
        .unwrap_or_else(|| panic!("no {p}"))
}

fn default_note(lang: Lang) -> (String, serde_json::Value, usize, Note) {
    let task = TaskSource::new("default.toml", DEFAULT_TASK);
    let run = run_task_in(&task, Some(language(lang))).unwrap();
    let note = compose(&run, &task).unwrap();
    assert_eq!(note.lang, lang);
    let t = typeset_with_warnings(&note).unwrap();
    assert!(t.warnings.is_empty(), "{lang:?}: {:#?}", t.warnings);
    (pdf_text(&t.pdf), run.report, t.pages, note)
}

/// Every paragraph's text of a note, as composed (math runs between their
/// markers).
fn paragraphs(note: &Note) -> Vec<String> {
    fn walk(ss: &[Section], out: &mut Vec<String>) {
        for s in ss {
            for b in &s.blocks {
                if let Block::Paragraph(t) = b {
                    out.push(
                        t.0.iter()
                            .map(|sp| match sp {
                                Span::Plain(p) | Span::Strong(p) | Span::Emph(p) => p.clone(),
                                Span::Math(m) => format!("{MATH_OPEN}{m}{MATH_CLOSE}"),
                                _ => String::new(),
                            })
                            .collect(),
                    );
                }
            }
            walk(&s.subsections, out);
        }
    }
    let mut out = Vec::new();
    walk(&note.sections, &mut out);
    out
}

fn check_default(lang: Lang) {
    let (text, r, pages, note) = default_note(lang);
    assert!(pages >= 20, "{lang:?}: {pages} pages");
    let w = Words::load(lang).unwrap();
    for key in [
        "sec_synthesis",
        "sec_linkage",
        "sec_forces",
        "sec_dynamics",
        "sec_gear",
        "sec_planetary",
        "sec_cam",
    ] {
        let h = w.get(key).unwrap();
        assert!(text.contains(h), "{lang:?}: heading {h:?} missing");
    }
    // the key numbers as the report gives them, rounded as printed
    for p in [
        "/forces/detail/balancing_moment",
        "/forces/detail/zhukovsky_moment",
        "/dynamics/driving_moment",
        "/dynamics/flywheel_inertia",
        "/gear/eps_alpha",
    ] {
        let s = printed(ptr(&r, p), lang);
        assert!(text.contains(&s), "{lang:?}: {p} = {s} missing");
    }
    // a given as the task writes it: the cam's ω = 200 rad/s, not 200,0
    let task: toml::Table = toml::from_str(DEFAULT_TASK).unwrap();
    let omega = task["cam"]["omega"].as_str().unwrap().split_whitespace().next().unwrap();
    let given = format!("{omega} {}", w.get("u_rad_s").unwrap());
    assert!(text.contains(&given), "{lang:?}: the cam's ω {given} missing");
    // εα of z1 = 15, z2 = 20, m = 5, x1 = 0.2, x2 = 0.85 is 1.2048 (seed 001,
    // with its typo corrected; recomputed in tmm-gears' tests): 1.205
    // typeset as ε with the subscript α: in the conclusion a math run ε_α
    // before the number (the PDF's text of the note without its drawings,
    // whose lettering is their own, has no flat εα: `notation.rs`)
    let eps_num = if lang == Lang::En { "1.205" } else { "1,205" };
    let eps = format!("{MATH_OPEN}ε_α{MATH_CLOSE} = {eps_num}");
    assert!(paragraphs(&note).iter().any(|p| p.contains(&eps)), "{lang:?}: {eps} missing");
    // the decimal separator of the language, never the other one in a number
    let m_d = ptr(&r, "/dynamics/driving_moment");
    let other = format_number(m_d, DIGITS, if lang == Lang::En { Lang::Ru } else { Lang::En })
        .unwrap()
        .mantissa;
    assert!(!text.contains(&other), "{lang:?}: {other} printed with the wrong separator");
}

#[test]
fn russian_note_of_the_default_task() {
    check_default(Lang::Ru);
}

#[test]
fn ukrainian_note_of_the_default_task() {
    check_default(Lang::Uk);
}

#[test]
fn english_note_of_the_default_task() {
    check_default(Lang::En);
}

#[test]
fn a_gear_only_task_has_no_linkage_section() {
    let task = TaskSource::new(
        "gear.toml",
        "[project]\nlang = \"en\"\n[gear]\nz1 = 15\nz2 = 20\nmodule = \"5 mm\"\nx1 = 0.2\nx2 = 0.85\n",
    );
    let run = run_task_in(&task, None).unwrap();
    let note = compose(&run, &task).unwrap();
    assert_eq!(note.sections.len(), 1);
    assert!(note.appendices.is_empty());
    let t = typeset_with_warnings(&note).unwrap();
    assert!(t.warnings.is_empty(), "{:#?}", t.warnings);
    let text = pdf_text(&t.pdf);
    let w = Words::load(Lang::En).unwrap();
    assert!(text.contains(w.get("sec_gear").unwrap()));
    for key in ["sec_linkage", "sec_forces", "sec_dynamics", "sec_cam", "app_kinematics"] {
        assert!(!text.contains(w.get(key).unwrap()), "{key} in a gear-only note");
    }
}

#[test]
fn the_three_body_word_files_have_the_same_keys() {
    let keys = |l| Words::load(l).unwrap().keys().map(str::to_string).collect::<Vec<_>>();
    assert_eq!(keys(Lang::Ru), keys(Lang::Uk));
    assert_eq!(keys(Lang::Ru), keys(Lang::En));
}

#[test]
fn a_sheet_is_one_page_of_the_svgs_size() {
    // an A2 sheet with the ESKD frame: 20 mm binding margin, 5 mm elsewhere
    let svg = r##"<?xml version="1.0" encoding="UTF-8"?>
<svg xmlns="http://www.w3.org/2000/svg" width="594mm" height="420mm" viewBox="0 0 594 420">
<rect x="20" y="5" width="569" height="410" fill="none" stroke="#000" stroke-width="0.7"/>
<text x="300" y="200" font-size="7" font-family="DejaVu Sans">Лист 1 Sheet</text>
</svg>"##;
    let pdf = sheet_pdf(svg).unwrap();
    let doc = pdf_extract::Document::load_mem(&pdf).unwrap();
    let pages = doc.get_pages();
    assert_eq!(pages.len(), 1);
    let page = doc.get_dictionary(*pages.values().next().unwrap()).unwrap();
    let mb = page.get(b"MediaBox").unwrap().as_array().unwrap();
    let pt = |o: &pdf_extract::Object| o.as_float().map(f64::from).or_else(|_| o.as_i64().map(|i| i as f64)).unwrap();
    // 594 × 420 mm in PostScript points (72 per inch, 25.4 mm per inch)
    assert!((pt(&mb[2]) - pt(&mb[0]) - 594.0 / 25.4 * 72.0).abs() < 0.1);
    assert!((pt(&mb[3]) - pt(&mb[1]) - 420.0 / 25.4 * 72.0).abs() < 0.1);
    // the SVG's text is drawn as outlines by the PDF export (an image keeps
    // its look, not its text), so the page has content but no text layer
    assert!(pdf.len() > 1000);
    // no size: a typed error, no panic
    assert!(sheet_pdf("<svg xmlns=\"http://www.w3.org/2000/svg\"/>").is_err());
    assert!(sheet_pdf("<svg width=\"-3mm\" height=\"10mm\"/>").is_err());
    assert!(sheet_pdf("not an svg").is_err());
}
