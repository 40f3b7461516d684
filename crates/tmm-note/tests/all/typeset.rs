//! End-to-end: the sample note typeset in each language, with and without the
//! frame; the PDF's text extracted (pdf-extract) and checked for the headings
//! of the chosen language, the numbers with its decimal separator, the
//! literal user text, and the title block's labels.

use crate::common;

use common::{TRICKY_NAME, sample_note};
use tmm_note::{Block, Lang, Note, NoteError, Section, Span, Text, typeset, typeset_with_warnings};

/// The text of a PDF, with every run of whitespace made one space (the
/// extractor splits lines and inserts spaces between positioned runs).
fn pdf_text(pdf: &[u8]) -> String {
    let raw = pdf_extract::extract_text_from_mem(pdf).expect("the PDF's text can be extracted");
    raw.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// Typesets and asserts no warnings (typst's, and no missing glyph).
fn strict(note: &Note) -> (Vec<u8>, usize) {
    let t = typeset_with_warnings(note).unwrap_or_else(|e| panic!("{e}"));
    assert!(t.warnings.is_empty(), "warnings: {:#?}", t.warnings);
    assert!(t.pdf.starts_with(b"%PDF-"));
    (t.pdf, t.pages)
}

fn save(name: &str, pdf: &[u8]) {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("note-samples");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join(name), pdf).unwrap();
}

fn assert_contains(text: &str, needles: &[&str]) {
    for n in needles {
        assert!(text.contains(n), "{n:?} missing from the PDF's text:\n{text}");
    }
}

#[test]
fn russian_note_has_russian_headings_and_decimal_commas() {
    let (pdf, pages) = strict(&sample_note(Lang::Ru, false, 1));
    save("note-ru.pdf", &pdf);
    assert!(pages > 1, "{pages} pages");
    let text = pdf_text(&pdf);
    assert_contains(
        &text,
        &[
            "ПОЯСНИТЕЛЬНАЯ ЗАПИСКА",
            "Техническое задание",
            "Содержание",
            "Список использованных источников",
            "Приложение А",
            "Рисунок 1.1",
            "Таблица 2.1",
            "Таблица 1 ", // not numbered by section: the assignment's table is in no section
            "12,35",
            "0,125",
            "9,95",
            "(2.1)",
            "(1.1)",
            "Рисунок А.1",
        ],
    );
    // the power of ten's dot is narrowed by kerns on both sides, where
    // the extractor puts a space ("1,5 · 10")
    assert!(text.replace(' ', "").contains("1,5·10"), "no 1,5·10 in the PDF's text:\n{text}");
    // The extractor spaces out the glyphs of a formula's number; compare
    // without spaces.
    let packed: String = text.chars().filter(|c| !c.is_whitespace()).collect();
    assert!(packed.contains("=−𝑚𝑎𝑆(А.1)"), "the appendix formula is numbered (А.1)");
    assert!(!text.contains("12.35 "), "a decimal point in a Russian note");
}

#[test]
fn ukrainian_note_has_ukrainian_headings() {
    let (pdf, pages) = strict(&sample_note(Lang::Uk, false, 1));
    save("note-uk.pdf", &pdf);
    assert!(pages > 1);
    let text = pdf_text(&pdf);
    assert_contains(
        &text,
        &[
            "ПОЯСНЮВАЛЬНА ЗАПИСКА",
            "Зміст",
            "Перелік джерел посилання",
            "Додаток А",
            "Рисунок 1.1",
            "Таблиця 2.1",
            "12,35",
            "9,95",
        ],
    );
    assert!(!text.contains("Содержание"));
}

#[test]
fn english_note_has_english_headings_and_decimal_points() {
    let (pdf, pages) = strict(&sample_note(Lang::En, false, 1));
    save("note-en.pdf", &pdf);
    assert!(pages > 1);
    let text = pdf_text(&pdf);
    assert_contains(
        &text,
        &[
            "EXPLANATORY NOTE",
            "Contents",
            "References",
            "Appendix A",
            "Figure 1.1",
            "Table 2.1",
            "12.35",
            "9.95",
        ],
    );
    assert!(!text.contains("12,35"));
}

#[test]
fn a_name_with_markup_characters_typesets_literally() {
    let (pdf, _) = strict(&sample_note(Lang::Ru, false, 1));
    let text = pdf_text(&pdf);
    assert_contains(&text, &["O'Brien #1 *bold* $x$ _u_ @me <tag> [b] \\n"]);
    assert_eq!(TRICKY_NAME, "O'Brien #1 *bold* $x$ _u_ @me <tag> [b] \\n");
    // The same characters in a heading, a caption, a table header, a list
    // item and a source.
    let mut s = Section::new(format!("H {TRICKY_NAME}"));
    s.blocks.push(Block::Table {
        caption: format!("C {TRICKY_NAME}"),
        header: vec![format!("T {TRICKY_NAME}")],
        rows: vec![vec![tmm_note::Cell::Text(Text::plain("= - + / ~ ` ' \" -- ..."))]],
        units: vec![],
        label: None,
    });
    s.blocks.push(Block::List(vec![Text::plain(format!("L {TRICKY_NAME}"))]));
    let note = Note {
        sections: vec![s],
        sources: vec![format!("S {TRICKY_NAME}")],
        ..Note::default()
    };
    let (pdf, _) = strict(&note);
    let text = pdf_text(&pdf);
    for prefix in ["H", "C", "T", "L", "S"] {
        assert_contains(&text, &[&format!("{prefix} {TRICKY_NAME}")]);
    }
    assert_contains(&text, &["= - + / ~ ` ' \" -- ..."]);
}

#[test]
fn the_frame_carries_the_title_block_labels() {
    for (lang, labels) in [
        (
            Lang::Ru,
            ["Разраб.", "Пров.", "Н. контр.", "Утв.", "Лит.", "Листов", "Изм.", "№ докум."],
        ),
        (
            Lang::Uk,
            ["Розроб.", "Перев.", "Н. контр.", "Затв.", "Літ.", "Арків.", "Змн.", "№ докум."],
        ),
    ] {
        let mut note = sample_note(lang, true, 1);
        note.project.student = "Иванов И. И.".into();
        let (pdf, pages) = strict(&note);
        save(&format!("note-{}-frame.pdf", lang.code()), &pdf);
        let text = pdf_text(&pdf);
        assert_contains(&text, &labels);
        assert_contains(&text, &["ТММ.КП.012.00.000 ПЗ", &pages.to_string()]);
        // Form 2 once, form 2a on every later page: the designation is printed
        // on every framed page (all but the title page and the assignment).
        let framed = text.matches("ТММ.КП.012.00.000 ПЗ").count();
        assert!(framed >= pages - 2, "{framed} designations on {pages} pages");
        let form2 = text.matches(labels[0]).count();
        assert_eq!(form2, 1, "form 2 (with «{}») must be on one page only", labels[0]);
    }
}

#[test]
fn pangrams_in_each_language_need_no_missing_glyph() {
    let pangrams = [
        (Lang::Ru, "Съешь же ещё этих мягких французских булок, да выпей чаю. ЁЪЫЭ ёъыэ"),
        (Lang::Uk, "Чуєш їх, доцю, га? Кумедна ж ти, прощайся без ґольфів! Ґ Є І Ї ґ є і ї ’"),
        (Lang::En, "The quick brown fox jumps over the lazy dog. –—«»№°±×"),
    ];
    for (lang, pangram) in pangrams {
        let mut s = Section::new(pangram);
        s.blocks.push(Block::Paragraph(
            Text::plain(pangram)
                .with(Span::Strong(pangram.into()))
                .with(Span::Emph(pangram.into())),
        ));
        s.blocks.push(Block::Paragraph(Text(vec![
            Span::Strong(pangram.into()),
            Span::Emph(pangram.into()),
        ])));
        s.blocks.push(Block::Formula {
            typst_math: format!("F_\"{pangram}\" = 1"),
            label: None,
        });
        let note = Note {
            lang,
            sections: vec![s],
            frame: true,
            ..Note::default()
        };
        strict(&note);
    }
}

#[test]
fn a_character_no_font_has_is_reported() {
    let mut s = Section::new("Test");
    s.blocks.push(Block::Paragraph(Text::plain("漢字 ☃")));
    let note = Note {
        sections: vec![s],
        ..Note::default()
    };
    let t = typeset_with_warnings(&note).unwrap();
    assert!(t.warnings.iter().any(|w| w.contains('漢')), "{:?}", t.warnings);
}

#[test]
fn bad_notes_are_typed_errors() {
    let with = |b: Block| Note {
        sections: vec![Section {
            blocks: vec![b],
            ..Section::new("S")
        }],
        ..Note::default()
    };
    let e = typeset(&with(Block::Paragraph(Text(vec![Span::Ref("nowhere".into())])))).unwrap_err();
    assert!(matches!(e, NoteError::UnknownLabel { .. }), "{e}");
    let e = typeset(&with(Block::Paragraph(Text(vec![Span::Cite(1)])))).unwrap_err();
    assert!(matches!(e, NoteError::UnknownSource { number: 1, count: 0 }), "{e}");
    let e = typeset(&with(Block::Paragraph(Text(vec![Span::Number {
        value: f64::NAN,
        digits: 3,
        unit: String::new(),
    }]))))
    .unwrap_err();
    assert!(matches!(e, NoteError::NonFinite { .. }), "{e}");
    let e = typeset(&with(Block::Formula {
        typst_math: "x $ #panic()".into(),
        label: None,
    }))
    .unwrap_err();
    assert!(matches!(e, NoteError::MathDelimiter { .. }), "{e}");
    let e = typeset(&with(Block::Formula {
        typst_math: "x".into(),
        label: Some("bad label".into()),
    }))
    .unwrap_err();
    assert!(matches!(e, NoteError::InvalidLabel { .. }), "{e}");
    let e = typeset(&with(Block::Table {
        caption: "T".into(),
        header: vec!["a".into(), "b".into()],
        rows: vec![vec![tmm_note::Cell::Empty]],
        units: vec![],
        label: None,
    }))
    .unwrap_err();
    assert!(matches!(e, NoteError::TableShape { found: 1, expected: 2, .. }), "{e}");
    let e = typeset(&with(Block::Figure {
        caption: "F".into(),
        svg: String::new(),
        width_mm: f64::INFINITY,
        label: None,
    }))
    .unwrap_err();
    assert!(matches!(e, NoteError::FigureWidth { .. }), "{e}");
    // A malformed formula or SVG is the compiler's error, with a place.
    let e = typeset(&with(Block::Formula {
        typst_math: "frac(".into(),
        label: None,
    }))
    .unwrap_err();
    assert!(
        matches!(&e, NoteError::Typst { messages } if messages.iter().any(|m| m.contains("/main.typ:"))),
        "{e}"
    );
    let e = typeset(&with(Block::Figure {
        caption: "F".into(),
        svg: "<svg".into(),
        width_mm: 50.0,
        label: None,
    }))
    .unwrap_err();
    assert!(matches!(e, NoteError::Typst { .. }), "{e}");
}

#[test]
fn the_output_is_reproducible() {
    let note = sample_note(Lang::Uk, true, 1);
    assert_eq!(typeset(&note).unwrap(), typeset(&note).unwrap());
}

#[test]
fn the_benchmark_note_is_about_thirty_pages() {
    let (_, pages) = strict(&sample_note(Lang::Ru, true, 8));
    assert!((25..=40).contains(&pages), "{pages} pages");
}
