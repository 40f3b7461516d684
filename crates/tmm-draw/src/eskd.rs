//! The ESKD sheet (лист ЕСКД) as a scene: the format's trimming edge, the
//! inner frame (GOST 2.301, 2.104: 20 mm from the binding edge, 5 mm from
//! the others, main line), the main title block form 1 (основная надпись,
//! GOST 2.104-2006, 185 × 55 mm in the bottom-right corner) and graph 26
//! (70 × 14 mm, the designation turned by 180°, top left).
//!
//! Every text of the title block is fitted to its cell at a GOST 2.304
//! size: the largest size not above the cell's own (7 mm for the
//! designation, 5 for the name and the scale, 3.5 for the organisation,
//! 2.5 for captions) at which the text, wrapped at spaces, fits the cell's
//! width and height with lines 1.7 h apart (type B's line step, GOST 2.304
//! table 2). Nothing is narrowed: a text that does not fit at 2.5 mm keeps
//! the lines that fit, the last ending with "…", and is reported.

use kurbo::Point;

use crate::{Anchor, DrawError, Geom, LineType, Rich, Scale, Scene, Shape, Text, TextHeight, Thickness, wrap};

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

/// The lines and height of `text` fitted into a `w` × `h` mm cell, at most
/// `max` high; `None` as the third value when it fits.
///
/// ```
/// use tmm_draw::{eskd::fit, TextHeight};
/// let (h, lines, cut) = fit("Кинематический анализ рычажного механизма", TextHeight::H5, 69.0, 24.0);
/// assert!(h.mm() >= 2.5 && cut.is_none());
/// assert!(lines.len() >= 2);
/// ```
pub fn fit(text: &str, max: TextHeight, w: f64, h: f64) -> (TextHeight, Vec<String>, Option<Overflow>) {
    for size in TextHeight::series().rev().filter(|s| s.mm() <= max.mm() + 1e-9) {
        if let Some(lines) = wrap(text, size, w) {
            let need = size.mm() + LINE_STEP * size.mm() * (lines.len() as f64 - 1.0);
            if need <= h + 1e-9 {
                return (size, lines, None);
            }
        }
    }
    let size = TextHeight::H2_5;
    let fits = (((h - size.mm()) / (LINE_STEP * size.mm())).floor() as usize + 1).max(1);
    let mut lines = wrap(text, size, w).unwrap_or_default();
    lines.truncate(fits);
    if let Some(last) = lines.last_mut() {
        while !last.is_empty() && Rich::plain_text(&format!("{last}…")).width(size) > w {
            last.pop();
        }
        last.push('…');
    }
    (size, lines, Some(Overflow { text: text.to_string() }))
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
        let (size, lines, over) = fit(&tb.designation, TextHeight::H7, 66.0, 12.0);
        cut.extend(over);
        // turned about the box's middle: the baseline lies above it
        let at = p(gx + 35.0, gy - 7.0 + size.mm() / 2.0);
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
    }
}

/// Form 1 with its top-left corner at `top_left` (paper mm, y up).
fn title_block(s: &mut Scene, top_left: Point, tb: &TitleBlock, cut: &mut Vec<Overflow>) -> Result<(), DrawError> {
    let (x0, y0) = (top_left.x, top_left.y);
    // offsets as the standard's drawing gives them: from the top-left, y down
    let at = |x: f64, d: f64| Point::new(x0 + x, y0 - d);
    let line = |s: &mut Scene, a: (f64, f64), b: (f64, f64), thick: bool| {
        s.stroke(
            "FRAME",
            if thick { LineType::Main } else { LineType::Thin },
            Geom::Line(at(a.0, a.1), at(b.0, b.1)),
        )
    };
    line(s, (0.0, 0.0), (185.0, 0.0), true)?;
    line(s, (0.0, 0.0), (0.0, 55.0), true)?;
    for k in 1..11 {
        let y = 5.0 * k as f64;
        line(s, (0.0, y), (65.0, y), k == 4 || k == 5)?;
    }
    line(s, (7.0, 0.0), (7.0, 25.0), true)?;
    for x in [17.0, 40.0, 55.0, 65.0] {
        line(s, (x, 0.0), (x, 55.0), true)?;
    }
    line(s, (65.0, 15.0), (185.0, 15.0), true)?;
    line(s, (135.0, 15.0), (135.0, 55.0), true)?;
    line(s, (135.0, 20.0), (185.0, 20.0), true)?;
    line(s, (135.0, 35.0), (185.0, 35.0), true)?;
    line(s, (65.0, 40.0), (185.0, 40.0), true)?;
    line(s, (140.0, 20.0), (140.0, 35.0), false)?;
    line(s, (145.0, 20.0), (145.0, 35.0), false)?;
    line(s, (150.0, 15.0), (150.0, 35.0), true)?;
    line(s, (167.0, 15.0), (167.0, 35.0), true)?;
    line(s, (155.0, 35.0), (155.0, 40.0), true)?;

    // a text in the cell x..x+w, d..d+h (y down from the top), 0.3 mm
    // clear of its sides and of the lean of its 75° slant (h·tan 15° at the
    // top of the last letter), lines centred vertically; the form's own
    // short captions of the changes' row ("Изм." in 7 mm) are fitted to the
    // whole cell, as the standard's form draws them
    let mut cell = |s: &mut Scene, x: f64, d: f64, w: f64, h: f64, max: TextHeight, anchor: Anchor, text: &str| -> Result<(), DrawError> {
        if text.trim().is_empty() {
            return Ok(());
        }
        // the lean of the printed letters: capitals and ascenders reach
        // 0.7 em in the faces a PDF prints (New Computer Modern's 0.683 and
        // 0.694), at the font size the SVG writes (h / CAP_EM)
        let lean = 0.7 * max.mm() / crate::svg::CAP_EM * crate::svg::SLANT_DEG.to_radians().tan();
        let room = if h <= 5.0 && d == 20.0 { w } else { w - 0.6 - lean };
        let (size, lines, over) = fit(text, max, room, h - 0.6);
        cut.extend(over);
        let hh = size.mm();
        let block = hh + LINE_STEP * hh * (lines.len() as f64 - 1.0);
        let top_base = d + (h - block) / 2.0 + hh;
        let ax = match anchor {
            Anchor::Start => x + 0.3,
            // centred with the lean: the letters' feet left of the middle by half of it
            Anchor::Middle => x + (w - if room < w { lean } else { 0.0 }) / 2.0,
            Anchor::End => x + w - 0.3,
        };
        for (i, l) in lines.iter().enumerate() {
            s.text("FRAME", text_at(at(ax, top_base + LINE_STEP * hh * i as f64), size, l, anchor))?;
        }
        Ok(())
    };
    let c = &tb.captions;
    for ((x, w), t) in [(0.0, 7.0), (7.0, 10.0), (17.0, 23.0), (40.0, 15.0), (55.0, 10.0)]
        .iter()
        .zip(&c.changes)
    {
        cell(s, *x, 20.0, *w, 5.0, TextHeight::H2_5, Anchor::Middle, t)?;
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
    cell(s, 135.0, 35.0, 10.0, 5.0, TextHeight::H2_5, Anchor::Start, &c.right[3])?;
    cell(s, 145.0, 35.0, 10.0, 5.0, TextHeight::H2_5, Anchor::Middle, &tb.sheet.to_string())?;
    cell(s, 155.0, 35.0, 16.0, 5.0, TextHeight::H2_5, Anchor::Start, &c.right[4])?;
    cell(s, 171.0, 35.0, 14.0, 5.0, TextHeight::H2_5, Anchor::Middle, &tb.sheets.to_string())?;
    cell(s, 65.0, 0.0, 120.0, 15.0, TextHeight::H7, Anchor::Middle, &tb.designation)?;
    cell(s, 65.0, 15.0, 70.0, 25.0, TextHeight::H5, Anchor::Middle, &tb.title)?;
    cell(s, 135.0, 40.0, 50.0, 15.0, TextHeight::H3_5, Anchor::Middle, &tb.organisation)?;
    Ok(())
}
