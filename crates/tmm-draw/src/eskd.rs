//! The ESKD sheet (лист ЕСКД) as a scene: the format's trimming edge, the
//! inner frame (GOST 2.301, 2.104: 20 mm from the binding edge, 5 mm from
//! the others, main line), the main title block form 1 (основная надпись,
//! GOST 2.104-2006, 185 × 55 mm in the bottom-right corner) and graph 26
//! (70 × 14 mm, the designation turned by 180°, top left).
//!
//! Every text of the title block is fitted to its cell at a GOST 2.304
//! size: the largest size not above the cell's own (7 mm for the
//! designation, 5 for the name and the scale, 3.5 for the organisation,
//! 2.5 for captions) at which the text, wrapped at spaces with lines 1.7 h
//! apart (type B's line step, GOST 2.304 table 2), keeps its printed ink
//! ([`crate::face::ink`]) [`CLEAR_MM`] from the edges of the cell's lines
//! ([`fit`] tells where a cell cannot, and what is kept there). No field
//! is narrowed: a text that does not fit at 2.5 mm keeps the lines that
//! fit, the last ending with "…", and is reported; only the form's own
//! captions of its changes' row are narrowed, where type B cannot keep
//! [`FORM_CLEAR_MM`] in the form's 7 mm column.

use kurbo::Point;

use crate::{Anchor, DrawError, Geom, LineType, Rich, Scale, Scene, Shape, Text, TextHeight, Thickness};

/// A sheet format of GOST 2.301, landscape.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// 841 × 594 mm.
    A1,
    /// 594 × 420 mm.
    A2,
    /// 420 × 297 mm.
    A3,
}

impl Format {
    /// Width × height, mm, landscape.
    pub fn size_mm(self) -> (f64, f64) {
        match self {
            Format::A1 => (841.0, 594.0),
            Format::A2 => (594.0, 420.0),
            Format::A3 => (420.0, 297.0),
        }
    }
}

/// The binding margin, mm.
pub const LEFT_MM: f64 = 20.0;
/// The other margins, mm.
pub const EDGE_MM: f64 = 5.0;
/// Type B's line step as a multiple of the letter height (GOST 2.304).
pub const LINE_STEP: f64 = 1.7;

/// The words printed in the title block's captions (the caller's language).
#[derive(Clone, Debug, PartialEq)]
pub struct Captions {
    /// Изм., Лист, № докум., Подп., Дата.
    pub changes: [String; 5],
    /// Разраб., Пров., Т.контр., Н.контр., Утв.
    pub roles: [String; 5],
    /// Лит., Масса, Масштаб, Лист, Листов.
    pub right: [String; 5],
}

impl Default for Captions {
    fn default() -> Self {
        let s = |v: [&str; 5]| v.map(String::from);
        Captions {
            changes: s(["Изм.", "Лист", "№ докум.", "Подп.", "Дата"]),
            roles: s(["Разраб.", "Пров.", "Т.контр.", "Н.контр.", "Утв."]),
            right: s(["Лит.", "Масса", "Масштаб", "Лист", "Листов"]),
        }
    }
}

/// What the title block says.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TitleBlock {
    /// The captions.
    pub captions: Captions,
    /// The designation (графа 2).
    pub designation: String,
    /// The sheet's name (графа 1).
    pub title: String,
    /// The scale field (графа 6): "1:2,5", or for a sheet of diagrams
    /// without one scale, "—" (the ESKD convention).
    pub scale: String,
    /// This sheet's number.
    pub sheet: usize,
    /// How many sheets.
    pub sheets: usize,
    /// Разраб.
    pub student: String,
    /// Пров.
    pub teacher: String,
    /// The organisation (графа 9): university, department, group.
    pub organisation: String,
    /// The document's letter (литера, графа 4: "У" for a student's
    /// document, GOST 2.103), in the first of the three cells.
    pub letter: String,
}

/// A text that did not fit its cell at 2.5 mm and was cut.
#[derive(Clone, Debug, PartialEq)]
pub struct Overflow {
    /// The text as given.
    pub text: String,
}

/// The clearance kept between a title-block text's ink and the edge of its
/// cell's lines, mm, on every side where the cell has the room: at least
/// the width of a line of 2.5 mm lettering, so no letter reads as touching
/// a line at print size.
pub const CLEAR_MM: f64 = 1.0;

/// The clearance to the sides kept where a cell cannot keep [`CLEAR_MM`]
/// at 2.5 mm: by the form's own captions of the changes' row (Изм., Лист,
/// Дата), narrowed to it in the form's 7 and 10 mm columns, and by a text
/// of one line in a cell too narrow for the rule (the letter under Лит.),
/// mm.
pub const FORM_CLEAR_MM: f64 = 0.5;

/// A cell narrower than this between its lines' edges, mm, keeps only
/// [`FORM_CLEAR_MM`] to the sides of a text that cannot keep [`CLEAR_MM`]
/// at 2.5 mm (the 5 mm letter cells under Лит.); a wider one wraps or cuts.
pub const NARROW_MM: f64 = 10.0;

/// The least clearance above and below one line of 2.5 mm lettering in a
/// cell one 5 mm row high, mm: its ink is centred between the lines'
/// edges and must not reach them. Between the thin lines of the form's
/// rows (4.75 mm) that leaves 0.9 mm to capitals alone, 0.46 mm to a line
/// with descenders (3.82 mm of ink at print size) and next to nothing to
/// one with both an accented capital (Й Ё Ї) and a descender (4.6 mm).
pub const TIGHT_MM: f64 = 0.0;

/// Half the width of the lines a cell is taken to be bounded by when only
/// its size is known ([`fit`]): the main line of an A1 sheet, 0.7 mm.
const MAIN_HALF_MM: f64 = 0.35;

/// Whether one line of text at `size` keeps [`CLEAR_MM`] to both sides of
/// a cell `iw` mm wide between its lines' edges.
fn line_fits(line: &str, size: TextHeight, iw: f64) -> bool {
    let k = crate::face::ink(line, size);
    k.right - k.left + 2.0 * CLEAR_MM <= iw + 1e-9
}

/// `text` broken into lines that each fit `iw` at `size`, at spaces; with
/// `break_words`, a word longer than a line is broken between letters.
fn wrap_ink(text: &str, size: TextHeight, iw: f64, break_words: bool) -> Option<Vec<String>> {
    crate::text::wrap_with(text, |s| line_fits(s, size, iw), break_words)
}

/// The ink height of `lines` at `size`, 1.7 h apart: the first line's top
/// to the last line's deepest foot, mm.
fn block_ink(lines: &[String], size: TextHeight) -> f64 {
    match (lines.first(), lines.last()) {
        (Some(a), Some(b)) => {
            crate::face::ink(a, size).above + LINE_STEP * size.mm() * (lines.len() as f64 - 1.0) + crate::face::ink(b, size).below
        }
        _ => 0.0,
    }
}

/// The fitting of a text into a cell `iw` × `ih` mm between its lines'
/// edges: the size, the lines, what was cut.
///
/// The largest GOST 2.304 size not above `max` whose lines, wrapped at
/// spaces, each keep [`CLEAR_MM`] to the cell's sides by their printed
/// ink (osifont's advances and heights, the slant's lean: [`crate::face::ink`])
/// and whose block keeps it above and below. A cell one line high (the
/// form's 5 mm rows, 4.75 mm between thin lines) cannot hold 2.5 mm
/// lettering, which prints 2.95 mm high with 0.87 mm descenders, 1 mm
/// clear of both lines, nor can a 5 mm wide one (the letter under Лит.)
/// hold a letter: where no size keeps [`CLEAR_MM`], one line at 2.5 mm is
/// taken when its ink keeps [`TIGHT_MM`] above and below, centred on the
/// lines, and [`CLEAR_MM`] to the sides ([`FORM_CLEAR_MM`] in a cell
/// under [`NARROW_MM`]). Words are broken
/// between letters only when no size holds them whole; a text that fits
/// at no size keeps the lines that fit at 2.5 mm, the last ending in "…".
fn fit_inside(text: &str, max: TextHeight, iw: f64, ih: f64) -> (TextHeight, Vec<String>, Option<Overflow>) {
    let sizes: Vec<TextHeight> = TextHeight::series().rev().filter(|s| s.mm() <= max.mm() + 1e-9).collect();
    let strict = |lines: &[String], size: TextHeight| block_ink(lines, size) + 2.0 * CLEAR_MM <= ih + 1e-9;
    let tight = |lines: &[String], size: TextHeight| {
        size == TextHeight::H2_5 && lines.len() == 1 && block_ink(lines, size) + 2.0 * TIGHT_MM <= ih + 1e-9
    };
    // the tight rule keeps FORM_CLEAR_MM to the sides: the lines wrapped
    // to a cell wider by the difference keep it
    let loose = if iw < NARROW_MM {
        iw + 2.0 * (CLEAR_MM - FORM_CLEAR_MM)
    } else {
        iw
    };
    for break_words in [false, true] {
        for (vertical, room) in [(&strict as &dyn Fn(&[String], TextHeight) -> bool, iw), (&tight, loose)] {
            for &size in &sizes {
                if let Some(lines) = wrap_ink(text, size, room, break_words)
                    && !lines.is_empty()
                    && vertical(&lines, size)
                {
                    return (size, lines, None);
                }
            }
        }
    }
    let size = TextHeight::H2_5;
    let mut lines = wrap_ink(text, size, iw, true).unwrap_or_default();
    while lines.len() > 1 && !strict(&lines, size) {
        lines.pop();
    }
    if let Some(last) = lines.last_mut() {
        while !last.is_empty() && !line_fits(&format!("{last}…"), size, iw) {
            last.pop();
        }
        last.push('…');
    }
    (size, lines, Some(Overflow { text: text.to_string() }))
}

/// The lines and height of `text` fitted into a `w` × `h` mm cell (between
/// the axes of its lines, taken as main lines), at most `max` high; `None`
/// as the third value when it fits. The rule is [`CLEAR_MM`] between the
/// printed ink and the lines' edges, as on the sheet's title block.
///
/// ```
/// use tmm_draw::{eskd::fit, TextHeight};
/// let (h, lines, cut) = fit("Кинематический анализ рычажного механизма", TextHeight::H5, 70.0, 25.0);
/// assert!(h.mm() >= 2.5 && cut.is_none());
/// assert!(lines.len() >= 2);
/// // a scale is never broken between its digits: it steps down instead
/// let (h, lines, _) = fit("1:2,5", TextHeight::H5, 18.0, 15.0);
/// assert_eq!((h.mm(), lines), (3.5, vec!["1:2,5".to_string()]));
/// ```
pub fn fit(text: &str, max: TextHeight, w: f64, h: f64) -> (TextHeight, Vec<String>, Option<Overflow>) {
    fit_inside(text, max, w - 2.0 * MAIN_HALF_MM, h - 2.0 * MAIN_HALF_MM)
}

/// A sheet: the format's scene at 1:1 (a sheet of several drawings carries
/// its drawings' scales in their captions), s = 0.7 mm, with the frame,
/// graph 26 and the title block drawn on the FRAME layer. Returns the
/// scene and the texts that had to be cut.
pub fn sheet(format: Format, tb: &TitleBlock) -> Result<(Scene, Vec<Overflow>), DrawError> {
    let (w, h) = format.size_mm();
    let mut s = Scene::new(w, h, Scale::NATURAL, Thickness::A1)?;
    let p = Point::new;
    let rect = |s: &mut Scene, x0: f64, y0: f64, x1: f64, y1: f64, line: LineType| {
        s.stroke(
            "FRAME",
            line,
            Geom::Polyline {
                points: vec![p(x0, y0), p(x1, y0), p(x1, y1), p(x0, y1)],
                closed: true,
            },
        )
    };
    rect(&mut s, 0.0, 0.0, w, h, LineType::Thin)?;
    rect(&mut s, LEFT_MM, EDGE_MM, w - EDGE_MM, h - EDGE_MM, LineType::Main)?;
    let mut cut = Vec::new();
    // graph 26: top left, the designation turned by 180°
    let (gx, gy) = (LEFT_MM, h - EDGE_MM);
    s.stroke("FRAME", LineType::Main, Geom::Line(p(gx + 70.0, gy), p(gx + 70.0, gy - 14.0)))?;
    s.stroke("FRAME", LineType::Main, Geom::Line(p(gx, gy - 14.0), p(gx + 70.0, gy - 14.0)))?;
    if !tb.designation.trim().is_empty() {
        // the box lies between the frame (main) and its own main lines
        let (size, lines, over) = fit(&tb.designation, TextHeight::H7, 70.0, 14.0);
        cut.extend(over);
        // turned by 180° about the anchor: the ink hangs under the
        // baseline and leans left, so both are centred the other way
        let k = crate::face::ink(&lines[0], size);
        let at = p(gx + 35.0 + (k.left + k.right - k.width) / 2.0, gy - 7.0 + (k.above - k.below) / 2.0);
        s.add("FRAME", Shape::Text(text_at(at, size, &lines[0], Anchor::Middle).rotated(180.0)))?;
    }
    title_block(&mut s, p(w - EDGE_MM - 185.0, EDGE_MM + 55.0), tb, &mut cut)?;
    Ok((s, cut))
}

fn text_at(at: Point, h: TextHeight, s: &str, anchor: Anchor) -> Text {
    Text {
        at,
        height: h,
        rich: Rich::plain_text(s),
        anchor,
        rotation_deg: 0.0,
        width_factor: 1.0,
    }
}

/// A line of the form: from, to (the standard's offsets, mm) and whether
/// it is a main line.
type FormLine = ((f64, f64), (f64, f64), bool);

/// Form 1 with its top-left corner at `top_left` (paper mm, y up).
fn title_block(s: &mut Scene, top_left: Point, tb: &TitleBlock, cut: &mut Vec<Overflow>) -> Result<(), DrawError> {
    let (x0, y0) = (top_left.x, top_left.y);
    // offsets as the standard's drawing gives them: from the top-left, y down
    let at = |x: f64, d: f64| Point::new(x0 + x, y0 - d);
    // (from, to, main line?) in the standard's offsets
    let mut lines: Vec<FormLine> = vec![((0.0, 0.0), (185.0, 0.0), true), ((0.0, 0.0), (0.0, 55.0), true)];
    for k in 1..11 {
        let y = 5.0 * k as f64;
        lines.push(((0.0, y), (65.0, y), k == 4 || k == 5));
    }
    lines.push(((7.0, 0.0), (7.0, 25.0), true));
    for x in [17.0, 40.0, 55.0, 65.0] {
        lines.push(((x, 0.0), (x, 55.0), true));
    }
    lines.extend([
        ((65.0, 15.0), (185.0, 15.0), true),
        ((135.0, 15.0), (135.0, 55.0), true),
        ((135.0, 20.0), (185.0, 20.0), true),
        ((135.0, 35.0), (185.0, 35.0), true),
        ((65.0, 40.0), (185.0, 40.0), true),
        ((140.0, 20.0), (140.0, 35.0), false),
        ((145.0, 20.0), (145.0, 35.0), false),
        ((150.0, 15.0), (150.0, 35.0), true),
        ((167.0, 15.0), (167.0, 35.0), true),
        ((155.0, 35.0), (155.0, 40.0), true),
    ]);
    for &(a, b, main) in &lines {
        s.stroke(
            "FRAME",
            if main { LineType::Main } else { LineType::Thin },
            Geom::Line(at(a.0, a.1), at(b.0, b.1)),
        )?;
    }
    // the frame's own main lines bound the block on the right and below
    lines.extend([((185.0, 0.0), (185.0, 55.0), true), ((0.0, 55.0), (185.0, 55.0), true)]);
    let (main_half, thin_half) = (s.s.mm() / 2.0, s.s.thin() / 2.0);
    // half the width of the line along a cell's side: the side at `v` on
    // the axis (x for a vertical side), through the middle `m` of the other
    let half = |vertical: bool, v: f64, m: f64| -> f64 {
        lines
            .iter()
            .filter(|(a, b, _)| {
                let (p, q) = if vertical { (a.0, b.0) } else { (a.1, b.1) };
                let (r0, r1) = if vertical {
                    (a.1.min(b.1), a.1.max(b.1))
                } else {
                    (a.0.min(b.0), a.0.max(b.0))
                };
                (p - v).abs() < 1e-9 && (q - v).abs() < 1e-9 && r0 <= m && m <= r1
            })
            .map(|&(_, _, main)| if main { main_half } else { thin_half })
            .fold(0.0, f64::max)
    };
    // the cell x..x+w, d..d+h (y down from the top) between its lines'
    // edges: (left, right, top, bottom)
    let inside = |x: f64, d: f64, w: f64, h: f64| {
        let (mx, md) = (x + w / 2.0, d + h / 2.0);
        (
            x + half(true, x, md),
            x + w - half(true, x + w, md),
            d + half(false, d, mx),
            d + h - half(false, d + h, mx),
        )
    };
    // Lines of text placed in a cell's inside: the block's ink centred
    // between the top and bottom lines, each line [`CLEAR_MM`] from the
    // sides (start, end) or its ink centred on them (middle).
    let place = |s: &mut Scene, (l, r, t, b): (f64, f64, f64, f64), size: TextHeight, lines: &[String], anchor: Anchor, narrow: f64| {
        let block = block_ink(lines, size);
        let mut base = t + (b - t - block) / 2.0;
        for (i, line) in lines.iter().enumerate() {
            let k = crate::face::ink_narrowed(line, size, narrow);
            if i == 0 {
                base += k.above;
            }
            let ax = match anchor {
                Anchor::Start => l + CLEAR_MM - k.left,
                Anchor::Middle => (l + r) / 2.0 - (k.left + k.right - k.width) / 2.0,
                Anchor::End => r - CLEAR_MM - k.right + k.width,
            };
            let mut text = text_at(at(ax, base), size, line, anchor);
            text.width_factor = narrow;
            s.text("FRAME", text)?;
            base += LINE_STEP * size.mm();
        }
        Ok::<(), DrawError>(())
    };
    // a field fitted to its cell by [`fit_inside`]
    let mut cell = |s: &mut Scene, x: f64, d: f64, w: f64, h: f64, max: TextHeight, anchor: Anchor, text: &str| -> Result<(), DrawError> {
        if text.trim().is_empty() {
            return Ok(());
        }
        let inner = inside(x, d, w, h);
        let (size, lines, over) = fit_inside(text, max, inner.1 - inner.0, inner.3 - inner.2);
        cut.extend(over);
        place(s, inner, size, &lines, anchor, 1.0)
    };
    let c = &tb.captions;
    // the form's own captions of the changes' row, 2.5 mm: "Изм." is 6.9 mm
    // wide in type B and its column 6.3 mm inside, so a caption that type
    // B cannot hold [`CLEAR_MM`] from the lines is narrowed to keep
    // [`FORM_CLEAR_MM`] (a form's printed words, not a field)
    for ((x, w), t) in [(0.0, 7.0), (7.0, 10.0), (17.0, 23.0), (40.0, 15.0), (55.0, 10.0)]
        .iter()
        .zip(&c.changes)
    {
        if t.trim().is_empty() {
            continue;
        }
        let inner = inside(*x, 20.0, *w, 5.0);
        let size = TextHeight::H2_5;
        let k = crate::face::ink(t, size);
        let iw = inner.1 - inner.0;
        let narrow = if k.right - k.left + 2.0 * CLEAR_MM <= iw {
            1.0
        } else {
            // the widest factor, to 0.001, at which the ink keeps FORM_CLEAR_MM
            let fits = |f: f64| {
                let k = crate::face::ink_narrowed(t, size, f);
                k.right - k.left + 2.0 * FORM_CLEAR_MM <= iw
            };
            let (mut lo, mut hi) = (0.3, 1.0);
            if fits(hi) {
                lo = hi;
            }
            while hi - lo > 1e-3 {
                let mid = (lo + hi) / 2.0;
                if fits(mid) { lo = mid } else { hi = mid }
            }
            lo
        };
        place(s, inner, size, std::slice::from_ref(t), Anchor::Middle, narrow)?;
    }
    let names = [tb.student.as_str(), tb.teacher.as_str(), "", "", ""];
    for ((d, role), name) in [25.0, 30.0, 35.0, 45.0, 50.0].iter().zip(&c.roles).zip(names) {
        cell(s, 0.0, *d, 17.0, 5.0, TextHeight::H2_5, Anchor::Start, role)?;
        cell(s, 17.0, *d, 23.0, 5.0, TextHeight::H2_5, Anchor::Start, name)?;
    }
    cell(s, 135.0, 15.0, 15.0, 5.0, TextHeight::H2_5, Anchor::Middle, &c.right[0])?;
    cell(s, 150.0, 15.0, 17.0, 5.0, TextHeight::H2_5, Anchor::Middle, &c.right[1])?;
    cell(s, 167.0, 15.0, 18.0, 5.0, TextHeight::H2_5, Anchor::Middle, &c.right[2])?;
    cell(s, 167.0, 20.0, 18.0, 15.0, TextHeight::H5, Anchor::Middle, &tb.scale)?;
    cell(s, 135.0, 20.0, 5.0, 15.0, TextHeight::H5, Anchor::Middle, &tb.letter)?;
    // «Лист N» and «Листов M»: the caption from the cell's left, the
    // number to its right, in one cell each (135 … 155, 155 … 185)
    cell(s, 135.0, 35.0, 20.0, 5.0, TextHeight::H2_5, Anchor::Start, &c.right[3])?;
    cell(s, 135.0, 35.0, 20.0, 5.0, TextHeight::H2_5, Anchor::End, &tb.sheet.to_string())?;
    cell(s, 155.0, 35.0, 30.0, 5.0, TextHeight::H2_5, Anchor::Start, &c.right[4])?;
    cell(s, 155.0, 35.0, 30.0, 5.0, TextHeight::H2_5, Anchor::End, &tb.sheets.to_string())?;
    cell(s, 65.0, 0.0, 120.0, 15.0, TextHeight::H7, Anchor::Middle, &tb.designation)?;
    cell(s, 65.0, 15.0, 70.0, 25.0, TextHeight::H5, Anchor::Middle, &tb.title)?;
    cell(s, 135.0, 40.0, 50.0, 15.0, TextHeight::H3_5, Anchor::Middle, &tb.organisation)?;
    Ok(())
}

/// How one text of a sheet's title block lies in its cell, as measured on
/// the scene: its printed ink ([`crate::face::ink_narrowed`]) against the
/// edges of the FRAME lines beside it.
#[derive(Clone, Debug, PartialEq)]
pub struct Clearance {
    /// The text.
    pub text: String,
    /// Its letter height, mm.
    pub height: f64,
    /// Its width factor (1 for type B).
    pub width_factor: f64,
    /// The least gap between the ink and the edge of a line left or right
    /// of it (a vertical line whose span meets the ink's), mm; negative
    /// when a line crosses the ink.
    pub sides: f64,
    /// The gap to the line above and to the line below, mm.
    pub above: f64,
    /// See `above`.
    pub below: f64,
    /// The width and height of the cell between the lines' axes, mm.
    pub cell: (f64, f64),
    /// The ink box (x0, y0, x1, y1), paper mm.
    pub ink: (f64, f64, f64, f64),
}

/// The [`Clearance`] of every text of the title block of `scene` (an
/// [`sheet`], alone or with drawings): the unturned texts of the FRAME
/// layer within 185 × 55 mm of the frame's bottom-right corner, measured
/// against that corner's FRAME lines and the frame.
///
/// ```
/// use tmm_draw::eskd::{clearances, sheet, Format, TitleBlock, CLEAR_MM};
/// let tb = TitleBlock { title: "Рычажный механизм".into(), ..TitleBlock::default() };
/// let (scene, _) = sheet(Format::A1, &tb).unwrap();
/// let c = clearances(&scene);
/// let title = c.iter().find(|c| c.text == "Рычажный механизм").unwrap();
/// assert!(title.sides >= CLEAR_MM && title.above >= CLEAR_MM && title.below >= CLEAR_MM);
/// ```
pub fn clearances(scene: &Scene) -> Vec<Clearance> {
    let (w, _) = (scene.width, scene.height);
    let (x_min, y_max) = (w - EDGE_MM - 185.0 - 1e-6, EDGE_MM + 55.0 + 1e-6);
    let Some(frame) = scene.layers().iter().position(|l| l.name == "FRAME") else {
        return Vec::new();
    };
    // (a, b, half width) of every straight FRAME line, the frame's sides too
    let mut segs: Vec<(Point, Point, f64)> = Vec::new();
    for it in scene.items().iter().filter(|i| i.layer == frame) {
        if let Shape::Stroke { line, geom } = &it.shape {
            let hw = line.width(scene.s) / 2.0;
            match geom {
                Geom::Line(a, b) => segs.push((*a, *b, hw)),
                Geom::Polyline { points, closed } => {
                    for k in 0..points.len() {
                        if k + 1 < points.len() {
                            segs.push((points[k], points[k + 1], hw));
                        } else if *closed {
                            segs.push((points[k], points[0], hw));
                        }
                    }
                }
                _ => {}
            }
        }
    }
    let mut out = Vec::new();
    for it in scene.items().iter().filter(|i| i.layer == frame) {
        let Shape::Text(t) = &it.shape else { continue };
        if t.rotation_deg != 0.0 || t.at.x < x_min || t.at.y > y_max {
            continue;
        }
        let plain = t.rich.plain();
        let k = crate::face::ink_narrowed(&plain, t.height, t.width_factor);
        let start = match t.anchor {
            Anchor::Start => t.at.x,
            Anchor::Middle => t.at.x - k.width / 2.0,
            Anchor::End => t.at.x - k.width,
        };
        let (x0, x1, y0, y1) = (start + k.left, start + k.right, t.at.y - k.below, t.at.y + k.above);
        let (mut sides, mut above, mut below) = (f64::INFINITY, f64::INFINITY, f64::INFINITY);
        let (mut cl, mut cr, mut ct, mut cb) = (f64::NEG_INFINITY, f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY);
        for &(a, b, hw) in &segs {
            if (a.x - b.x).abs() < 1e-9 {
                let (s0, s1) = (a.y.min(b.y), a.y.max(b.y));
                if s1 <= y0 || s0 >= y1 {
                    continue;
                }
                let gap = if a.x <= (x0 + x1) / 2.0 { x0 - (a.x + hw) } else { (a.x - hw) - x1 };
                sides = sides.min(if a.x > x0 - hw && a.x < x1 + hw { -1.0 } else { gap });
                if a.x <= (x0 + x1) / 2.0 {
                    cl = cl.max(a.x);
                } else {
                    cr = cr.min(a.x);
                }
            } else if (a.y - b.y).abs() < 1e-9 {
                let (s0, s1) = (a.x.min(b.x), a.x.max(b.x));
                if s1 <= x0 || s0 >= x1 {
                    continue;
                }
                if a.y >= (y0 + y1) / 2.0 {
                    above = above.min(if a.y - hw < y1 { -1.0 } else { a.y - hw - y1 });
                    ct = ct.min(a.y);
                } else {
                    below = below.min(if a.y + hw > y0 { -1.0 } else { y0 - (a.y + hw) });
                    cb = cb.max(a.y);
                }
            }
        }
        out.push(Clearance {
            text: plain,
            height: t.height.mm(),
            width_factor: t.width_factor,
            sides,
            above,
            below,
            cell: (cr - cl, ct - cb),
            ink: (x0, y0, x1, y1),
        });
    }
    out
}
