//! Lettering of the drawings (надписи на чертежах): GOST 2.304 lettering
//! sizes, typeset indices (d_w1 → d with the subscript w1, a^τ_CB), numbers
//! with the decimal comma of ru/uk, a placer that keeps the labels' boxes
//! apart and inside the paper, and the GOST 2.303 dash-dot lines.
//!
//! The drawings draw their lines on a [`Canvas`](crate::svg::Canvas); the
//! labels are collected by a [`Placer`] and written into the finished SVG by
//! [`finish`], which also writes the drawing's standard scale on the root
//! element (`data-scale="1:2"`, read by the sheets' title block).

use crate::line_grid::LineGrid;
use crate::picture::Picture;
use crate::project::Language;
use crate::svg::Style;

/// The capital height per em of the lowest-capped face a drawing's text
/// may be printed in: osifont 1510/2048 = 0.737, DejaVu Sans 0.729, and the
/// faces the PDF typesetter falls back to when none of the SVG's families
/// is at hand, New Computer Modern 683/1000 and Libertinus Serif Italic
/// 645/1000 (each font's OS/2 `sCapHeight` over its units per em). A
/// letter size of h / CAP_PER_EM mm has capitals at least h mm high
/// wherever it is printed.
pub const CAP_PER_EM: f64 = 0.645;
/// The letter size (em, mm) whose capitals are GOST 2.304's smallest
/// height, 2.5 mm, in every face that may print it: the floor of every
/// drawing, on the sheets and in the note ([`lettering_floor`]).
pub const MIN_EM: f64 = 2.5 / CAP_PER_EM;

thread_local! {
    /// The smallest letter size the SVG writer puts down, mm.
    static FLOOR: std::cell::Cell<f64> = const { std::cell::Cell::new(MIN_EM) };
}

/// Run `f` with every text and index its drawings write raised to at
/// least `floor` mm (em) instead of [`MIN_EM`]. Every drawing — the
/// sheets', the note's, the page's — is made with [`MIN_EM`], so no
/// capital prints under 2.5 mm; the text boxes the labels are placed by
/// ([`Placer`], [`crate::svg::text_box`]) are measured at the raised size,
/// so the labels keep apart at the size they print.
///
/// ```
/// use tmm_report::labels::{lettering_floor, with_lettering_floor, MIN_EM};
/// assert_eq!(lettering_floor(), MIN_EM);
/// assert_eq!(with_lettering_floor(0.0, lettering_floor), 0.0);
/// assert_eq!(lettering_floor(), MIN_EM);
/// ```
pub fn with_lettering_floor<T>(floor: f64, f: impl FnOnce() -> T) -> T {
    let before = FLOOR.with(|c| c.replace(floor));
    let out = f();
    FLOOR.with(|c| c.set(before));
    out
}

/// The smallest letter size the SVG writer puts down now, mm.
pub fn lettering_floor() -> f64 {
    FLOOR.with(std::cell::Cell::get)
}

/// Lettering heights of GOST 2.304, mm (шрифт чертёжный): labels of points
/// and circles, headings, titles.
pub const H_LABEL: f64 = 3.5;
/// Heading lettering height, mm.
pub const H_HEAD: f64 = 5.0;
/// Title lettering height, mm.
pub const H_TITLE: f64 = 7.0;

/// The advance of one character as a share of the lettering size (DejaVu
/// Sans / GOST type B: about 0.6; taken generously).
pub const CHAR_WIDTH: f64 = 0.62;

/// Thin dash-dot line of GOST 2.303 (штрихпунктирная тонкая): axes, centre
/// lines, reference circles. Written by the canvas as a marker dash pattern
/// that [`finish`] turns into dash 12, gap 3, dot, gap 3.
pub const DASH_DOT: Style = Style {
    width: 0.25,
    color: "#000000",
    dash: Some((12.01, 3.0)),
    fill: None,
};
/// Thin dash-dot line with two dots (штрихпунктирная с двумя точками), used
/// for the operating circles.
pub const DASH_DOT_DOT: Style = Style {
    width: 0.25,
    color: "#000000",
    dash: Some((12.02, 3.0)),
    fill: None,
};

/// A number with `digits` decimals and the decimal separator of `lang`
/// (comma in ru/uk, GOST 2.105; point in en); `-0` is printed as `0`; a
/// value that is not finite as the marker the output check refuses
/// ([`crate::output::NONFINITE`]).
///
/// ```
/// use tmm_report::{labels::num, project::Language};
/// assert_eq!(num(Language::Ru, 87.5, 2), "87,50");
/// assert_eq!(num(Language::En, -0.0001, 2), "0.00");
/// ```
pub fn num(lang: Language, v: f64, digits: usize) -> String {
    if !v.is_finite() {
        return crate::output::NONFINITE.to_string();
    }
    let mut s = format!("{v:.digits$}");
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s.remove(0);
    }
    match lang {
        Language::En => s,
        _ => s.replace('.', ","),
    }
}

/// The parts of a label: (text, shift) with shift 0 on the line, −1 a
/// subscript, +1 a superscript. `_x` and `^x` take the rest of the word
/// (up to a space or the other mark); `_{…}` a group.
///
/// ```
/// use tmm_report::labels::parts;
/// assert_eq!(parts("d_w1"), vec![("d".to_string(), 0), ("w1".to_string(), -1)]);
/// assert_eq!(parts("a^τ_CB = 2"), vec![("a".into(), 0), ("τ".into(), 1), ("CB".into(), -1), (" = 2".into(), 0)]);
/// ```
pub fn parts(text: &str) -> Vec<(String, i8)> {
    let mut out: Vec<(String, i8)> = Vec::new();
    let mut cur = String::new();
    let mut shift = 0i8;
    let mut chars = text.chars().peekable();
    let mut group = false;
    while let Some(ch) = chars.next() {
        match ch {
            '_' | '^' if !group => {
                if !cur.is_empty() {
                    out.push((std::mem::take(&mut cur), shift));
                }
                shift = if ch == '_' { -1 } else { 1 };
                if chars.peek() == Some(&'{') {
                    chars.next();
                    group = true;
                }
            }
            '}' if group => {
                out.push((std::mem::take(&mut cur), shift));
                shift = 0;
                group = false;
            }
            ' ' | '=' | ',' | '(' | ')' | '/' if shift != 0 && !group => {
                out.push((std::mem::take(&mut cur), shift));
                shift = 0;
                cur.push(ch);
            }
            _ => cur.push(ch),
        }
    }
    if !cur.is_empty() {
        out.push((cur, shift));
    }
    out
}

/// The label as plain text, marks dropped (`d_w1` → `dw1`).
pub fn plain(text: &str) -> String {
    parts(text).into_iter().map(|p| p.0).collect()
}

/// A box on the paper, mm from the top-left corner.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rect {
    /// Left edge.
    pub x0: f64,
    /// Top edge.
    pub y0: f64,
    /// Right edge.
    pub x1: f64,
    /// Bottom edge.
    pub y1: f64,
}

impl Rect {
    /// Do the boxes overlap (with a gap `gap` mm counted as overlap)?
    pub fn hits(&self, o: &Rect, gap: f64) -> bool {
        self.x0 < o.x1 + gap && o.x0 < self.x1 + gap && self.y0 < o.y1 + gap && o.y0 < self.y1 + gap
    }
    /// Is the box inside `o`?
    pub fn inside(&self, o: &Rect) -> bool {
        self.x0 >= o.x0 && self.y0 >= o.y0 && self.x1 <= o.x1 && self.y1 <= o.y1
    }
    /// Does the segment `a`–`b` pass through the box's inside (Liang–Barsky)?
    pub fn cuts(&self, a: (f64, f64), b: (f64, f64)) -> bool {
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for (p, q) in [(-dx, a.0 - self.x0), (dx, self.x1 - a.0), (-dy, a.1 - self.y0), (dy, self.y1 - a.1)] {
            if p == 0.0 {
                if q <= 0.0 {
                    return false;
                }
            } else {
                let r = q / p;
                if p < 0.0 {
                    t0 = t0.max(r);
                } else {
                    t1 = t1.min(r);
                }
            }
        }
        t0 < t1
    }
}

/// The box of a label of `chars` visible characters written at `h` mm
/// (its letter size raised to the lettering floor, [`crate::picture::em`],
/// as the SVG writes it), centred at `c` (paper mm).
pub fn text_label_box(c: (f64, f64), chars: usize, h: f64) -> Rect {
    label_box(c, chars, crate::picture::em(h))
}

/// The box of a label of `chars` visible characters, `h` mm lettering,
/// centred at `c` (paper mm): width `CHAR_WIDTH·h·chars`, height `1.2·h`.
pub fn label_box(c: (f64, f64), chars: usize, h: f64) -> Rect {
    let w = CHAR_WIDTH * h * chars as f64;
    let hh = 1.2 * h;
    Rect {
        x0: c.0 - 0.5 * w,
        y0: c.1 - 0.5 * hh,
        x1: c.0 + 0.5 * w,
        y1: c.1 + 0.5 * hh,
    }
}

/// Collects the labels of one drawing, each at the first of its candidate
/// places whose box is inside the paper and clear of the boxes placed
/// before it and of the reserved areas.
#[derive(Debug, Clone)]
pub struct Placer {
    paper: Rect,
    taken: Vec<Rect>,
    /// The labels written, in order.
    items: Vec<crate::picture::Element>,
    /// The drawn lines to keep off, once [`Placer::avoid_lines`] is called.
    lines: Option<LineGrid>,
    /// The printed ink of each label written ([`ink_rect`]).
    inks: Vec<Rect>,
    /// The areas kept free by [`Placer::reserve`].
    reserved: Vec<Rect>,
    /// After [`Placer::keep_clear`]: the paper (mm) a label's ink keeps
    /// from the lines and from the other labels' ink.
    clear: Option<f64>,
}

/// The half width of the widest line a label keeps clear of (a diagram's
/// curve, 0.7 mm), mm.
const HALF_MAIN: f64 = 0.35;

/// The box of the printed ink of a label of `text` (with index marks) at
/// `h` mm ([`crate::picture::em`]), centred at `c` as [`Placer::put`]
/// writes it (or starting there, with `start`), paper mm, y down: osifont's
/// ink ([`tmm_draw::face::ink`], the 75° slant, capitals 1.14 of the
/// capital height, descenders) at type B's widths, which are at least
/// osifont's own, an index raised or lowered by 0.35 of the letter size
/// as the SVG writes it.
///
/// ```
/// use tmm_report::labels::ink_rect;
/// let r = ink_rect((50.0, 20.0), "φдс", 2.5, false);
/// // centred, about 6 mm wide, capitals and descenders about the baseline
/// assert!((r.x0 + r.x1 - 100.0).abs() < 1.0 && r.x1 - r.x0 > 4.0 && r.x1 - r.x0 < 8.0);
/// assert!(r.y0 < 20.0 && r.y1 > 21.5);
/// ```
pub fn ink_rect(c: (f64, f64), text: &str, h: f64, start: bool) -> Rect {
    InkShape::of(text, h).at(c, start)
}

/// What [`ink_rect`] measures of a label's text, wherever it stands: the
/// text is read and measured once, and each place tried ([`InkShape::at`])
/// only adds the position, in the same order of operations, so the
/// rectangle is the same to the last bit.
#[derive(Debug, Clone, Copy)]
struct InkShape {
    /// Half the text's advance at its size (a centred label starts there).
    half_width: f64,
    /// 0.35 of the lettering's em: the baseline below the label's middle.
    drop: f64,
    left: f64,
    right: f64,
    above: f64,
    below: f64,
    /// The visible characters ([`text_label_box`]).
    chars: usize,
}

impl InkShape {
    fn of(text: &str, h: f64) -> InkShape {
        let e = crate::picture::em(h);
        let ie = crate::picture::index_em(h);
        let k = |em: f64| em * CAP_PER_EM / 2.5;
        let parts = parts(text);
        let all: String = parts.iter().map(|p| p.0.as_str()).collect();
        let i = tmm_draw::face::ink(&all, tmm_draw::TextHeight::H2_5);
        let kk = k(e.max(ie));
        let (left, right) = (kk * i.left, kk * i.right.max(i.width));
        let (mut above, mut below) = (kk * i.above, kk * i.below);
        for (t, lvl) in &parts {
            let j = tmm_draw::face::ink(t, tmm_draw::TextHeight::H2_5);
            match lvl.signum() {
                1 => above = above.max(k(ie) * j.above + 0.35 * e),
                -1 => below = below.max(k(ie) * j.below + 0.35 * e),
                _ => {}
            }
        }
        InkShape {
            half_width: 0.5 * kk * i.width,
            drop: 0.35 * e,
            left,
            right,
            above,
            below,
            chars: all.chars().count(),
        }
    }

    /// The ink's rectangle with the label centred at `c` (or starting at
    /// `c.0` when `start`).
    fn at(&self, c: (f64, f64), start: bool) -> Rect {
        let x = if start { c.0 } else { c.0 - self.half_width };
        let base = c.1 + self.drop;
        Rect {
            x0: x + self.left.min(0.0),
            y0: base - self.above,
            x1: x + self.right,
            y1: base + self.below,
        }
    }
}

/// A label placed by [`Placer::place_near`]: its centre and, when it stands
/// off its point, the leader line from the label to the point (the caller
/// draws it, GOST 2.316: a leader ending on a line ends with an arrow).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Near {
    /// The label's centre, paper mm.
    pub centre: (f64, f64),
    /// The leader: (from the label's edge, to the point), if any.
    pub leader: Option<((f64, f64), (f64, f64))>,
}

/// The distances from a point to the nearest edge of its label tried by
/// [`Placer::place_near`], mm: next to the point first, then farther out on
/// a leader.
const NEAR_MM: [f64; 13] = [0.8, 1.5, 2.5, 4.0, 6.0, 8.0, 11.0, 14.0, 18.0, 23.0, 29.0, 36.0, 45.0];
/// Up to this distance the label is read as the point's without a leader.
const NO_LEADER_MM: f64 = 2.5;

impl Placer {
    /// A placer for a paper `width × height` mm.
    pub fn new(width: f64, height: f64) -> Self {
        Placer {
            paper: Rect {
                x0: 0.5,
                y0: 0.5,
                x1: width - 0.5,
                y1: height - 0.5,
            },
            taken: Vec::new(),
            items: Vec::new(),
            lines: None,
            inks: Vec::new(),
            reserved: Vec::new(),
            clear: None,
        }
    }

    /// From now on a label fits only where its printed ink ([`ink_rect`])
    /// keeps `mm` of paper from the lines given to [`Placer::avoid_lines`]
    /// (from their edges, lines up to 0.7 mm wide) and from every other
    /// label's ink, and its lettering box ([`text_label_box`]) overlaps no
    /// other.
    pub fn keep_clear(&mut self, mm: f64) {
        self.clear = Some(mm);
    }

    /// From now on keep the labels off the segments `segs` (paper mm): a
    /// label whose box comes within a grid cell of one of them does not fit.
    pub fn avoid_lines(&mut self, segs: &[crate::line_grid::Segment]) {
        let mut g = LineGrid::new(self.paper.x1 + 0.5, self.paper.y1 + 0.5);
        for &(a, b) in segs {
            g.add(a, b);
        }
        self.lines = Some(g);
    }

    /// Place `text` near the first of `anchors` (paper mm, in the order of
    /// preference) where its box fits — inside the paper, off the other
    /// labels and, after [`Placer::avoid_lines`], off the lines — trying
    /// every anchor next to it first and then farther out; a label farther
    /// than 2.5 mm from its anchor gets a leader, which must not cross
    /// another label and which the later labels keep off. `None` when no
    /// place within 45 mm fits (nothing is written).
    pub fn place_near(&mut self, anchors: &[(f64, f64)], text: &str, h: f64, color: &str) -> Option<Near> {
        // the text measured once for all the places tried
        let shape = InkShape::of(text, h);
        let n = shape.chars;
        let e = crate::picture::em(h);
        let (w, hh) = (CHAR_WIDTH * e * n as f64, 1.2 * e);
        for d in NEAR_MM {
            for &p in anchors.iter().filter(|p| p.0.is_finite() && p.1.is_finite()) {
                for k in 0..16 {
                    let th = std::f64::consts::TAU * k as f64 / 16.0;
                    let (c, s) = (th.cos(), -th.sin());
                    // the centre so that the box's nearest edge is `d` from the point
                    let t = (0.5 * w / c.abs().max(1e-9)).min(0.5 * hh / s.abs().max(1e-9));
                    let centre = (p.0 + c * (d + t), p.1 + s * (d + t));
                    if !self.fits_shaped(centre, &shape, h) {
                        continue;
                    }
                    let leader = if d > NO_LEADER_MM {
                        // from 0.3 mm off the box's edge to the point
                        let from = (p.0 + c * (d - 0.3), p.1 + s * (d - 0.3));
                        // (the box kept free around the point itself does not count)
                        let at_p = |b: &Rect| p.0 >= b.x0 && p.0 <= b.x1 && p.1 >= b.y0 && p.1 <= b.y1;
                        let cut = self.taken.iter().any(|b| b.cuts(from, p) && !at_p(b))
                            || self.clear.is_some_and(|g| {
                                // (after keep_clear) the leader keeps off the others' ink
                                self.inks.iter().any(|b| {
                                    let r = Rect {
                                        x0: b.x0 - g,
                                        y0: b.y0 - g,
                                        x1: b.x1 + g,
                                        y1: b.y1 + g,
                                    };
                                    r.cuts(from, p) && !at_p(&r)
                                })
                            });
                        if cut {
                            continue;
                        }
                        Some((from, p))
                    } else {
                        None
                    };
                    if let (Some((a, b)), Some(g)) = (leader, self.lines.as_mut()) {
                        g.add(a, b);
                    }
                    self.put(centre, text, h, color);
                    return Some(Near { centre, leader });
                }
            }
        }
        None
    }

    /// Keep labels out of `r` (a table, a legend, a title).
    pub fn reserve(&mut self, r: Rect) {
        self.taken.push(r);
        self.reserved.push(r);
    }

    /// Would a label of `text` at `h` fit centred at `c`?
    pub fn fits(&self, c: (f64, f64), text: &str, h: f64) -> bool {
        self.fits_shaped(c, &InkShape::of(text, h), h)
    }

    /// [`Placer::fits`] of a text already measured.
    fn fits_shaped(&self, c: (f64, f64), shape: &InkShape, h: f64) -> bool {
        let b = text_label_box(c, shape.chars, h);
        if let Some(gap) = self.clear {
            let i = shape.at(c, false);
            let grown = Rect {
                x0: i.x0 - gap - HALF_MAIN,
                y0: i.y0 - gap - HALF_MAIN,
                x1: i.x1 + gap + HALF_MAIN,
                y1: i.y1 + gap + HALF_MAIN,
            };
            return i.inside(&self.paper)
                && b.inside(&self.paper)
                && !self.taken.iter().any(|t| t.hits(&b, 0.0))
                && !self.inks.iter().any(|t| t.hits(&i, gap))
                && !self.reserved.iter().any(|t| t.hits(&i, gap))
                && !self.lines.as_ref().is_some_and(|g| g.hits(&grown));
        }
        b.inside(&self.paper) && !self.taken.iter().any(|t| t.hits(&b, 0.4)) && !self.lines.as_ref().is_some_and(|g| g.hits(&b))
    }

    /// Place `text` (with `_`/`^` marks) at the first candidate centre that
    /// fits; returns the centre used, `None` when none fits (then nothing is
    /// written).
    pub fn place(&mut self, candidates: &[(f64, f64)], text: &str, h: f64, color: &str) -> Option<(f64, f64)> {
        let shape = InkShape::of(text, h);
        let c = candidates
            .iter()
            .copied()
            .find(|&c| c.0.is_finite() && c.1.is_finite() && self.fits_shaped(c, &shape, h))?;
        self.put(c, text, h, color);
        Some(c)
    }

    /// Place `text` centred at `c` whatever is there (a title).
    pub fn put(&mut self, c: (f64, f64), text: &str, h: f64, color: &str) {
        self.write(c, text, h, color, false);
    }

    /// Write the drawing's name (see [`crate::svg::Canvas::title`]) with
    /// its box's middle at `c`, whatever is there, in a group of class
    /// [`crate::picture::TITLE`].
    pub fn put_title(&mut self, c: (f64, f64), text: &str, h: f64) {
        self.begin_title();
        self.write(c, text, h, "#000", false);
        self.end_title();
    }

    /// Open the group of the drawing's name (a name of several lines);
    /// close it with [`Placer::end_title`].
    pub fn begin_title(&mut self) {
        self.items.push(crate::picture::Element::GroupOpen {
            id: None,
            class: Some(crate::picture::TITLE.to_string()),
            data: Vec::new(),
        });
    }

    /// Close the group [`Placer::begin_title`] opened.
    pub fn end_title(&mut self) {
        self.items.push(crate::picture::Element::GroupClose);
    }

    /// Write `text` starting at `x`, its box's middle at height `y` (a
    /// table row), whatever is there.
    pub fn put_left(&mut self, (x, y): (f64, f64), text: &str, h: f64, color: &str) {
        self.write((x, y), text, h, color, true);
    }

    fn write(&mut self, c: (f64, f64), text: &str, h: f64, color: &str, start: bool) {
        let n = plain(text).chars().count();
        let w = CHAR_WIDTH * crate::picture::em(h) * n as f64;
        let centre = if start { (c.0 + 0.5 * w, c.1) } else { c };
        self.taken.push(text_label_box(centre, n, h));
        self.inks.push(ink_rect(c, text, h, start));
        self.items.push(crate::picture::Element::Label {
            c,
            text: text.to_string(),
            size: h,
            color: color.to_string(),
            start,
        });
    }

    /// Candidate centres around a point `p` (paper mm) for a label of
    /// `text`: right, above-right, above, left, below … at `gap` mm clear.
    pub fn around(p: (f64, f64), text: &str, h: f64, gap: f64) -> Vec<(f64, f64)> {
        let e = crate::picture::em(h);
        let w = CHAR_WIDTH * e * plain(text).chars().count() as f64;
        let (dx, dy) = (0.5 * w + gap, 0.6 * e + gap);
        let mut v = Vec::new();
        for k in 1..=3 {
            let f = k as f64;
            for (sx, sy) in [
                (1.0, -1.0),
                (-1.0, -1.0),
                (1.0, 1.0),
                (-1.0, 1.0),
                (1.0, 0.0),
                (-1.0, 0.0),
                (0.0, -1.0),
                (0.0, 1.0),
            ] {
                v.push((p.0 + sx * dx * f, p.1 + sy * dy * f));
            }
        }
        v
    }

    /// The boxes taken so far.
    pub fn boxes(&self) -> &[Rect] {
        &self.taken
    }

    /// The labels as elements of a drawing.
    pub fn elements(&self) -> &[crate::picture::Element] {
        &self.items
    }

    /// The labels as SVG elements.
    pub fn svg(&self) -> String {
        let p = crate::picture::Picture::new(1.0, 1.0, Vec::new(), self.items.clone());
        p.body("")
    }
}

/// Finish a drawing: the labels go in after its elements, the root carries
/// `data-scale` when the drawing is at a length scale (read by the sheets'
/// title block).
pub fn finish(pic: Picture, labels: &Placer, scale: Option<&str>) -> Picture {
    finish_all(pic, &[labels], scale)
}

/// [`finish`] with the labels of several placers, in order.
pub fn finish_all(pic: Picture, placers: &[&Placer], scale: Option<&str>) -> Picture {
    let more: Vec<crate::picture::Element> = placers.iter().flat_map(|p| p.items.iter().cloned()).collect();
    let root = scale.map(|sc| vec![("data-scale".to_string(), sc.to_string())]).unwrap_or_default();
    pic.extended(more, root)
}

/// `text` (with `_`/`^` index marks) broken at spaces into lines each no
/// wider than `room` mm at the letter size `size` as printed
/// ([`crate::svg::text_width`], at the lettering floor); a space inside an
/// index group (`T_{I max}`) does not break; a word wider than the room
/// keeps a line of its own.
///
/// ```
/// use tmm_report::labels::wrap_text;
/// let lines = wrap_text("крайнее положение; выбранная опора T_{I max}", 2.5, 40.0);
/// assert!(lines.len() >= 2);
/// assert!(lines.iter().any(|l| l.contains("T_{I max}")));
/// assert_eq!(wrap_text("O", 2.5, 40.0), vec!["O".to_string()]);
/// ```
pub fn wrap_text(text: &str, size: f64, room: f64) -> Vec<String> {
    // the words: split at spaces outside braces
    let mut words: Vec<String> = Vec::new();
    let mut cur = String::new();
    let mut depth = 0i32;
    for ch in text.chars() {
        match ch {
            '{' => depth += 1,
            '}' => depth -= 1,
            _ => {}
        }
        if ch == ' ' && depth <= 0 {
            words.push(std::mem::take(&mut cur));
        } else {
            cur.push(ch);
        }
    }
    words.push(cur);
    let width = |s: &str| crate::svg::text_width(size, crate::svg::shown_len(s));
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for w in words {
        if line.is_empty() {
            line = w;
            continue;
        }
        let cand = format!("{line} {w}");
        if width(cand.trim_end()) <= room {
            line = cand;
        } else {
            lines.push(std::mem::take(&mut line).trim_end().to_string());
            line = w;
        }
    }
    if !line.trim().is_empty() || lines.is_empty() {
        lines.push(line.trim_end().to_string());
    }
    lines
}
