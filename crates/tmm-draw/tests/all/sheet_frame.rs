//! The ESKD sheet as a scene: the frame, graph 26 and title block form 1
//! with every text inside its cell at an allowed size.

use tmm_draw::eskd::{CLEAR_MM, Captions, FORM_CLEAR_MM, Format, TIGHT_MM, TitleBlock, clearances, sheet};
use tmm_draw::face::ink;
use tmm_draw::{Anchor, Geom, LineType, Rich, Shape, Text, TextHeight, svg};

fn block() -> TitleBlock {
    TitleBlock {
        designation: "ТММ.КП.017.00.000".into(),
        title: "Кинематический и силовой анализ рычажного механизма".into(),
        scale: "1:2,5".into(),
        sheet: 1,
        sheets: 4,
        student: "Иванов И. И.".into(),
        teacher: "Петров П. П.".into(),
        organisation: "Национальный технический университет «ХПИ», каф. ТММ, гр. МШ-21".into(),
        ..TitleBlock::default()
    }
}

#[test]
fn frame_lies_twenty_and_five_mm_inside_the_edges() {
    let (scene, _) = sheet(Format::A1, &block()).unwrap();
    let frame = scene.items().iter().find_map(|i| match &i.shape {
        Shape::Stroke {
            line: LineType::Main,
            geom: Geom::Polyline { points, closed: true },
        } => Some(points.clone()),
        _ => None,
    });
    let f = frame.expect("the inner frame");
    assert_eq!((f[0].x, f[0].y, f[2].x, f[2].y), (20.0, 5.0, 836.0, 589.0));
}

/// The rule of the title block, checked on a scene: every text at 2.5 mm
/// or more, its ink 1 mm (`CLEAR_MM`) from the edges of the lines beside
/// it and above and below it; in a cell one 5 mm row high (which cannot
/// hold 2.95 mm capitals and their descenders 1 mm from both lines) centred
/// and off them; the form's own captions of the changes' row (Изм. …
/// Дата, narrowed where type B cannot keep 0.5 mm) and a text in a cell
/// 10 mm wide or less (the letter) at least 0.5 mm from the sides; no two texts' inks overlapping.
pub fn assert_title_block_clear(scene: &tmm_draw::Scene, what: &str) {
    let c = clearances(scene);
    assert!(c.len() > 15, "{what}: {c:?}");
    for t in &c {
        assert!(t.height >= 2.5, "{what}: {t:?}");
        // the changes' row: 20 … 25 mm under the block's top (y 35 … 40 on A1)
        let form_row = t.ink.1 > 35.0 && t.ink.3 < 40.0 && t.ink.2 < 651.0 + 65.0;
        let narrow = form_row || t.cell.0 <= 10.0 + 1e-6;
        let sides = if narrow { FORM_CLEAR_MM } else { CLEAR_MM };
        assert!(
            t.sides >= sides - 1e-6,
            "{what}: {:?} {:.2} mm from the side lines: {t:?}",
            t.text,
            t.sides
        );
        if t.cell.1 > 5.0 + 1e-6 {
            assert!(
                t.above >= CLEAR_MM - 1e-6 && t.below >= CLEAR_MM - 1e-6,
                "{what}: {:?} {:.2} / {:.2} mm under / over the lines: {t:?}",
                t.text,
                t.above,
                t.below
            );
        } else {
            assert!(t.above >= TIGHT_MM - 1e-6 && t.below >= TIGHT_MM - 1e-6, "{what}: {t:?}");
            // a line without accents keeps 0.2 mm (capitals and a
            // descender, 3.82 mm of ink, between main lines: 0.24 mm)
            if !t.text.chars().any(|c| "ЙЁЇЄҐ\"'()[]{}".contains(c)) {
                assert!(t.above >= 0.2, "{what}: {t:?}");
            }
            assert!((t.above - t.below).abs() < 1e-6, "{what}: not centred in its row: {t:?}");
        }
    }
    for (i, a) in c.iter().enumerate() {
        for b in &c[i + 1..] {
            let apart = a.ink.2 <= b.ink.0 || b.ink.2 <= a.ink.0 || a.ink.3 <= b.ink.1 || b.ink.3 <= a.ink.1;
            assert!(apart, "{what}: {:?} and {:?} overlap", a.text, b.text);
        }
    }
}

#[test]
fn every_title_block_text_fits_its_cell_at_an_allowed_size() {
    let (scene, cut) = sheet(Format::A1, &block()).unwrap();
    assert!(cut.is_empty(), "{cut:?}");
    assert_title_block_clear(&scene, "ru");
    let texts: Vec<_> = scene
        .items()
        .iter()
        .filter_map(|i| match &i.shape {
            Shape::Text(t) if t.rotation_deg == 0.0 => Some(t.clone()),
            _ => None,
        })
        .collect();
    // the long university name wraps into several lines rather than shrinking below 2.5 mm
    let org: Vec<_> = texts.iter().filter(|t| t.at.x > 786.0 && t.at.y < 20.0).collect();
    assert!(org.len() >= 2, "{org:?}");
    // the scale field is filled, whole on one line: 5 mm type B is 15.5 mm
    // wide plus its lean, more than its 18 mm cell less 1 mm each side
    let scale: Vec<_> = texts.iter().filter(|t| t.at.x > 818.0 && t.at.y > 25.0 && t.at.y < 40.0).collect();
    assert_eq!(scale.len(), 1, "{scale:?}");
    assert_eq!((scale[0].rich.plain(), scale[0].height.mm()), ("1:2,5".to_string(), 3.5));
    // the names of people at 2.5 mm, whole
    for name in ["Иванов И. И.", "Петров П. П."] {
        assert!(
            texts.iter().any(|t| t.rich == Rich::plain_text(name) && t.height.mm() == 2.5),
            "{name}"
        );
    }
    // the letter У under Лит., in its 5 mm cell
    let mut b = block();
    b.letter = "У".into();
    let (scene, cut) = sheet(Format::A1, &b).unwrap();
    assert!(cut.is_empty(), "{cut:?}");
    assert_title_block_clear(&scene, "ru, У");
}

/// The longer words of the Ukrainian and English forms, long fields and
/// many sheets: every field still in its cell by the rule.
#[test]
fn longer_captions_and_fields_keep_clear_of_the_lines() {
    let s = |v: [&str; 5]| v.map(String::from);
    let uk = Captions {
        changes: s(["Зм.", "Арк.", "№ докум.", "Підпис", "Дата"]),
        roles: s(["Розроб.", "Перевір.", "Т.контр.", "Н.контр.", "Затв."]),
        right: s(["Літ.", "Маса", "Масштаб", "Арк.", "Аркушів"]),
    };
    let en = Captions {
        changes: s(["Rev.", "Sheet", "Doc. No.", "Sign.", "Date"]),
        roles: s(["Drawn", "Checked", "T.contr.", "N.contr.", "Appr."]),
        right: s(["Lit.", "Mass", "Scale", "Sheet", "Sheets"]),
    };
    for (lang, captions, title) in [
        ("uk", uk, "Важільний механізм: синтез і кінематичний аналіз (продовження)"),
        ("en", en, "Linkage: synthesis and kinematic analysis (continued)"),
    ] {
        let mut b = block();
        b.captions = captions;
        b.title = title.into();
        b.scale = "1:2,5".into();
        b.sheet = 12;
        b.sheets = 12;
        b.student = "Йорданов-Щербаков Й. Й.".into();
        b.letter = "У".into();
        let (scene, _) = sheet(Format::A1, &b).unwrap();
        assert_title_block_clear(&scene, lang);
    }
}

/// The check itself fails on a text that crosses a line or comes closer
/// than 1 mm to one: "1:2,5" at 5 mm (17 mm of ink) set in the 18 mm scale
/// cell, and a name moved 0.5 mm from its cell's left line.
#[test]
fn the_title_block_check_catches_a_text_on_a_line() {
    for (at, size, text) in [
        (kurbo::Point::new(827.0, 26.0), TextHeight::H5, "1:2,5"),
        (kurbo::Point::new(651.0 + 17.0 + 0.35 + 0.5, 31.5), TextHeight::H2_5, "Иванов"),
    ] {
        let (mut scene, _) = sheet(Format::A1, &block()).unwrap();
        let t = Text::new(at, size, text)
            .unwrap()
            .anchored(if size == TextHeight::H5 { Anchor::Middle } else { Anchor::Start });
        scene.text("FRAME", t).unwrap();
        let r = std::panic::catch_unwind(|| assert_title_block_clear(&scene, "a text put on a line"));
        assert!(r.is_err(), "{text} passed the check");
    }
}

/// The ink model against the printed sheet: poppler's 600 dpi rendering of
/// sheet 1 of the default project measured (by the darkest pixels between
/// the name cell's lines) the first line of its name, "Рычажный механизм:
/// синтез и" at 3.5 mm, 67.61 mm wide (type B: 67.73) and its capitals
/// 3.98 mm high.
#[test]
fn the_ink_model_matches_a_measured_print() {
    let k = ink("Рычажный механизм: синтез и", TextHeight::H3_5);
    assert!((k.width - 67.725).abs() < 1e-9, "{k:?}");
    assert!((k.right - k.left - 67.61).abs() < 0.3, "{k:?}");
    let caps = ink("РМ", TextHeight::H3_5);
    assert!((caps.above - 3.98).abs() < 0.1, "{caps:?}");
}

#[test]
fn a_text_too_long_for_its_cell_is_cut_and_reported_not_narrowed() {
    let mut b = block();
    b.organisation = "очень ".repeat(60);
    let (scene, cut) = sheet(Format::A1, &b).unwrap();
    assert_eq!(cut.len(), 1);
    // what is left of it keeps the rule, at 2.5 mm, not narrowed
    assert_title_block_clear(&scene, "cut");
    let org: Vec<_> = clearances(&scene).into_iter().filter(|c| c.text.contains("очень")).collect();
    assert!(!org.is_empty() && org.iter().all(|c| c.height == 2.5 && c.width_factor == 1.0));
    assert!(org.last().unwrap().text.ends_with('…'));
}

/// With `TMM_DRAW_DUMP=DIR`, the A1 frame is written there as SVG and DXF.
#[test]
fn dump_the_frame_when_asked() {
    let Ok(dir) = std::env::var("TMM_DRAW_DUMP") else { return };
    let (scene, _) = sheet(Format::A1, &block()).unwrap();
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(format!("{dir}/frame-a1.svg"), svg::render(&scene)).unwrap();
    std::fs::write(format!("{dir}/frame-a1.dxf"), tmm_draw::dxf::render(&scene)).unwrap();
}
