//! The main title block of a drawing (основная надпись, GOST 2.104-2006,
//! form 1): 185 × 55 mm in the bottom-right corner against the frame.
//!
//! The grid, from the block's top-left corner (mm, y down), in eleven rows
//! of 5 mm:
//!
//! * left part, 65 mm: columns 7 (Изм.), 10 (Лист), 23 (№ докум.),
//!   15 (Подп.), 10 (Дата); four rows of changes, the captions' row at
//!   20 … 25, then the rows Разраб., Пров., Т.контр., a free row, Н.контр.,
//!   Утв. (the first two columns merged into one of 17 mm);
//! * right part, 120 mm: the designation (графа 2) 120 × 15 on top; below
//!   it the name (графа 1) 70 × 25 and, on its right, the captions Лит.
//!   (3 × 5), Масса (17), Масштаб (18), their values 15 mm high, and the
//!   row Лист (20) / Листов (30); at the bottom the material (графа 3)
//!   70 × 15 and the organisation (графа 9) 50 × 15.

use crate::project::Language;
use crate::sheets::frame::{Align, Mark, fitted};
use crate::sheets::layout::Rect;
use crate::words::word;

/// The block's width, mm.
pub const WIDTH_MM: f64 = 185.0;
/// The block's height, mm.
pub const HEIGHT_MM: f64 = 55.0;

/// What a sheet writes into its title block.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Fields {
    /// The document's designation (обозначение документа, графа 2).
    pub designation: String,
    /// The sheet's title (наименование, графа 1).
    pub title: String,
    /// The scale of the sheet's main drawing (масштаб, графа 6).
    pub scale: String,
    /// This sheet's number (лист, графа 7).
    pub sheet: usize,
    /// How many sheets (листов, графа 8).
    pub sheets: usize,
    /// Who drew it (Разраб.).
    pub student: String,
    /// Who checks it (Пров.).
    pub teacher: String,
    /// The organisation's lines: university, department, group (графа 9).
    pub organisation: Vec<String>,
}

/// Where the block goes inside the frame `frame`: its bottom-right corner
/// on the frame's.
pub fn place(frame: Rect) -> Rect {
    Rect {
        x: frame.right() - WIDTH_MM,
        y: frame.bottom() - HEIGHT_MM,
        w: WIDTH_MM,
        h: HEIGHT_MM,
    }
}

/// The block's marks: its grid in main and thin lines, the captions in
/// `lang` and the fields.
///
/// ```
/// use tmm_report::{project::Language, sheets::{frame::Mark, layout::Rect, title_block::{marks, Fields}}};
/// let at = Rect { x: 651.0, y: 534.0, w: 185.0, h: 55.0 };
/// let f = Fields { designation: "ТММ.КП.017".into(), sheet: 1, sheets: 4, ..Fields::default() };
/// let m = marks(at, &f, Language::Ru);
/// let texts: Vec<&str> = m.iter().filter_map(|m| match m { Mark::Text { text, .. } => Some(text.as_str()), _ => None }).collect();
/// assert!(texts.contains(&"Разраб.") && texts.contains(&"ТММ.КП.017") && texts.contains(&"4"));
/// ```
pub fn marks(at: Rect, f: &Fields, lang: Language) -> Vec<Mark> {
    let (x0, y0) = (at.x, at.y);
    let mut m = Vec::new();
    let mut line = |a: (f64, f64), b: (f64, f64), thick: bool| {
        m.push(Mark::Line {
            a: (x0 + a.0, y0 + a.1),
            b: (x0 + b.0, y0 + b.1),
            thick,
        });
    };
    // outline
    line((0.0, 0.0), (185.0, 0.0), true);
    line((0.0, 0.0), (0.0, 55.0), true);
    // left part: horizontal rows (the captions' row bounded by main lines)
    for k in 1..11 {
        let y = 5.0 * k as f64;
        line((0.0, y), (65.0, y), k == 5 || k == 4);
    }
    // left part: columns (main lines)
    line((7.0, 0.0), (7.0, 25.0), true);
    for x in [17.0, 40.0, 55.0, 65.0] {
        line((x, 0.0), (x, 55.0), true);
    }
    // right part
    line((65.0, 15.0), (185.0, 15.0), true);
    line((135.0, 15.0), (135.0, 55.0), true);
    line((135.0, 20.0), (185.0, 20.0), true);
    line((135.0, 35.0), (185.0, 35.0), true);
    line((65.0, 40.0), (185.0, 40.0), true);
    line((140.0, 20.0), (140.0, 35.0), false);
    line((145.0, 20.0), (145.0, 35.0), false);
    line((150.0, 15.0), (150.0, 35.0), true);
    line((167.0, 15.0), (167.0, 35.0), true);
    line((155.0, 35.0), (155.0, 40.0), true);

    let w = |k: &str| word(lang, k).to_string();
    let mut text = |x: f64, y_mid: f64, max: f64, align: Align, s: &str, width: f64| {
        if s.trim().is_empty() {
            return;
        }
        let Mark::Text { size, .. } = fitted((0.0, 0.0), max, align, s, width) else {
            return;
        };
        let mark = fitted((x0 + x, y0 + y_mid + 0.35 * size), max, align, s, width);
        m.push(mark);
    };
    // captions: changes' row, signature rows, right part
    let caps = [
        (0.0, 7.0, "sheet.tb_change"),
        (7.0, 10.0, "sheet.tb_sheet"),
        (17.0, 23.0, "sheet.tb_document"),
        (40.0, 15.0, "sheet.tb_signature"),
        (55.0, 10.0, "sheet.tb_date"),
    ];
    for (x, cw, k) in caps {
        text(x + cw / 2.0, 22.5, 2.5, Align::Middle, &w(k), cw - 0.6);
    }
    let roles = [
        (27.5, "sheet.tb_drawn", f.student.as_str()),
        (32.5, "sheet.tb_checked", f.teacher.as_str()),
        (37.5, "sheet.tb_tech_control", ""),
        (47.5, "sheet.tb_norm_control", ""),
        (52.5, "sheet.tb_approved", ""),
    ];
    for (y, k, name) in roles {
        text(0.8, y, 2.5, Align::Start, &w(k), 15.6);
        text(17.8, y, 2.5, Align::Start, name, 21.6);
    }
    text(142.5, 17.5, 2.5, Align::Middle, &w("sheet.tb_letter"), 14.0);
    // the letter of a student's document in the first of the three cells
    text(137.5, 27.5, 5.0, Align::Middle, &w("sheet.tb_letter_value"), 4.4);
    text(158.5, 17.5, 2.5, Align::Middle, &w("sheet.tb_mass"), 16.0);
    text(176.0, 17.5, 2.5, Align::Middle, &w("sheet.tb_scale"), 17.0);
    text(176.0, 27.5, 5.0, Align::Middle, &f.scale, 17.0);
    let (sheet_w, sheets_w) = (w("sheet.tb_sheet"), w("sheet.tb_sheets"));
    text(136.0, 37.5, 2.5, Align::Start, &sheet_w, 10.0);
    text(149.0, 37.5, 2.5, Align::Middle, &f.sheet.to_string(), 10.0);
    text(156.0, 37.5, 2.5, Align::Start, &sheets_w, 16.0);
    text(177.0, 37.5, 2.5, Align::Middle, &f.sheets.to_string(), 14.0);
    // designation, name, organisation
    text(125.0, 7.5, 7.0, Align::Middle, &f.designation, 116.0);
    let name = wrap(&f.title, 24, 3);
    // one size for all the lines of the name
    let size = name
        .iter()
        .map(|l| match fitted((0.0, 0.0), 5.0, Align::Middle, l, 67.0) {
            Mark::Text { size, .. } => size,
            Mark::Line { .. } => 5.0,
        })
        .fold(5.0, f64::min);
    let step = 1.6 * size;
    let mut y = 27.5 - step * (name.len() as f64 - 1.0) / 2.0;
    for l in &name {
        text(100.0, y, size, Align::Middle, l, 67.0);
        y += step;
    }
    let org: Vec<&String> = f.organisation.iter().filter(|s| !s.trim().is_empty()).take(3).collect();
    let step = 4.5;
    let mut y = 47.5 - step * (org.len() as f64 - 1.0) / 2.0;
    for l in org {
        text(160.0, y, 3.5, Align::Middle, l, 48.0);
        y += step;
    }
    m
}

/// Break `s` into at most `lines` lines of about `chars` characters at
/// spaces; the last line takes the rest.
pub fn wrap(s: &str, chars: usize, lines: usize) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let mut cur = String::new();
    for word in s.split_whitespace() {
        if !cur.is_empty() && cur.chars().count() + 1 + word.chars().count() > chars && out.len() + 1 < lines {
            out.push(std::mem::take(&mut cur));
        }
        if !cur.is_empty() {
            cur.push(' ');
        }
        cur.push_str(word);
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    out
}
