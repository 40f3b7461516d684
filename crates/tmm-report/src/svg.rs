//! A small SVG canvas in world coordinates (metres or any model unit, y up),
//! mapped onto paper in millimetres (y down), with the primitives the course
//! drawings need: lines, polylines, circles, arcs, arrows, text, dashed and
//! thin/thick line styles, and a plot frame with axes.
//!
//! Every drawing module of tmm-report builds on this one file.

use std::fmt::Write as _;

use crate::picture::{Element, PathData, Picture};

/// Line style of a stroke.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Style {
    /// Stroke width on paper, mm.
    pub width: f64,
    /// Stroke colour (`#rrggbb` or a CSS name).
    pub color: &'static str,
    /// Dash pattern on paper, mm (None: solid).
    pub dash: Option<(f64, f64)>,
    /// Fill colour (None: no fill).
    pub fill: Option<&'static str>,
}

impl Style {
    /// Thick solid black line (contour lines, ГОСТ 2.303 "сплошная основная").
    pub const THICK: Style = Style {
        width: 0.7,
        color: "#000000",
        dash: None,
        fill: None,
    };
    /// Thin solid line (construction, dimension lines): s/3 … s/2 of the
    /// main line (GOST 2.303), 0.3 mm against 0.7 mm.
    pub const THIN: Style = Style {
        width: 0.3,
        color: "#000000",
        dash: None,
        fill: None,
    };
    /// Thin dash-dot line (centre lines, pitch circles): GOST 2.303 dashes of
    /// 5 … 30 mm with gaps of 3 … 5 mm holding a dot. A dash longer than
    /// 8 mm (the longest dash of a dashed line) is drawn dash-dot.
    pub const AXIS: Style = Style {
        width: 0.3,
        color: "#000000",
        dash: Some((10.0, 3.0)),
        fill: None,
    };
    /// Thin dashed line (hidden or auxiliary): dashes of 2 … 8 mm.
    pub const DASHED: Style = Style {
        width: 0.3,
        color: "#000000",
        dash: Some((2.0, 1.5)),
        fill: None,
    };

    /// The same style in another colour.
    pub const fn colored(self, color: &'static str) -> Style {
        Style { color, ..self }
    }
    /// The same style with another width.
    pub const fn widened(self, width: f64) -> Style {
        Style { width, ..self }
    }
    /// The same style filled.
    pub const fn filled(self, fill: &'static str) -> Style {
        Style { fill: Some(fill), ..self }
    }
}

/// Text anchor.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Anchor {
    /// Text starts at the point.
    Start,
    /// Text is centred on the point.
    Middle,
    /// Text ends at the point.
    End,
}

/// An SVG document: a paper of `width × height` mm, with a world window.
#[derive(Debug, Clone)]
pub struct Canvas {
    width: f64,
    height: f64,
    scale: f64,
    ox: f64,
    oy: f64,
    /// The elements drawn, in order.
    els: Vec<Element>,
    /// Attributes of the root element (`data-scale="1:2"`).
    root: Vec<(String, String)>,
    /// Every straight piece drawn, on paper (mm, y down): what labels avoid.
    segs: crate::seg_index::SegIndex,
    /// The boxes of the texts written and of the places kept free.
    boxes: Vec<Rect>,
}

impl Canvas {
    /// A blank paper of the given size in mm, world = paper (1 unit = 1 mm, y up,
    /// origin at the bottom-left corner).
    pub fn new(width_mm: f64, height_mm: f64) -> Self {
        Canvas {
            width: width_mm,
            height: height_mm,
            scale: 1.0,
            ox: 0.0,
            oy: 0.0,
            els: Vec::new(),
            root: Vec::new(),
            segs: crate::seg_index::SegIndex::new(width_mm, height_mm),
            boxes: Vec::new(),
        }
    }

    /// Map the world box `[xmin, xmax] × [ymin, ymax]` into the paper box
    /// `(left, bottom, width, height)` mm, keeping the aspect ratio (centred).
    /// Returns the scale: paper mm per world unit.
    pub fn fit(&mut self, world: (f64, f64, f64, f64), paper: (f64, f64, f64, f64)) -> f64 {
        let (xmin, xmax, ymin, ymax) = world;
        let (left, bottom, w, h) = paper;
        let ww = (xmax - xmin).abs().max(1e-12);
        let wh = (ymax - ymin).abs().max(1e-12);
        let s = (w / ww).min(h / wh);
        self.scale = s;
        self.ox = left + 0.5 * (w - s * ww) - s * xmin;
        self.oy = bottom + 0.5 * (h - s * wh) - s * ymin;
        s
    }

    /// Set the mapping directly: paper = origin + scale · world (y up).
    pub fn set_transform(&mut self, scale: f64, origin_mm: (f64, f64)) {
        self.scale = scale;
        self.ox = origin_mm.0;
        self.oy = origin_mm.1;
    }

    /// The current scale, paper mm per world unit.
    pub fn scale(&self) -> f64 {
        self.scale
    }

    /// World point to paper coordinates (mm, y down as SVG wants).
    pub fn to_paper(&self, x: f64, y: f64) -> (f64, f64) {
        (self.ox + self.scale * x, self.height - (self.oy + self.scale * y))
    }

    /// A line segment between two world points.
    pub fn line(&mut self, a: (f64, f64), b: (f64, f64), s: Style) {
        if !finite(&[a.0, a.1, b.0, b.1]) {
            return;
        }
        let (x1, y1) = self.to_paper(a.0, a.1);
        let (x2, y2) = self.to_paper(b.0, b.1);
        self.segs.push(((x1, y1), (x2, y2)));
        self.els.push(Element::Line {
            a: (x1, y1),
            b: (x2, y2),
            style: s,
            round: true,
        });
    }

    /// An open polyline through world points (non-finite points are skipped).
    pub fn polyline(&mut self, pts: &[(f64, f64)], s: Style) {
        self.poly(pts, s, false);
    }

    /// A closed polygon through world points.
    pub fn polygon(&mut self, pts: &[(f64, f64)], s: Style) {
        self.poly(pts, s, true);
    }

    fn poly(&mut self, pts: &[(f64, f64)], s: Style, closed: bool) {
        // a non-finite point lifts the pen: each run between them is drawn
        // on its own (a curve with gaps where a mechanism does not assemble)
        let runs: Vec<&[(f64, f64)]> = pts
            .split(|p| !(p.0.is_finite() && p.1.is_finite()))
            .filter(|r| !r.is_empty())
            .collect();
        let closed = closed && runs.len() == 1;
        for run in runs {
            let mut points = Vec::with_capacity(run.len());
            let mut prev: Option<(f64, f64)> = None;
            let first = self.to_paper(run[0].0, run[0].1);
            for &(x, y) in run {
                let (px, py) = self.to_paper(x, y);
                if let Some(q) = prev {
                    self.segs.push((q, (px, py)));
                }
                prev = Some((px, py));
                points.push((px, py));
            }
            if let (true, Some(a)) = (closed, prev) {
                self.segs.push((a, first));
            }
            self.els.push(Element::Poly { points, style: s, closed });
        }
    }

    /// A circle of world radius `r`.
    pub fn circle(&mut self, c: (f64, f64), r: f64, s: Style) {
        if !finite(&[c.0, c.1, r]) {
            return;
        }
        let (x, y) = self.to_paper(c.0, c.1);
        self.els.push(Element::Circle {
            c: (x, y),
            r: (r * self.scale).abs(),
            style: s,
        });
    }

    /// A dot of paper radius `r_mm` (a joint, a point of a plan).
    pub fn dot(&mut self, c: (f64, f64), r_mm: f64, fill: &'static str) {
        if !finite(&[c.0, c.1]) {
            return;
        }
        let (x, y) = self.to_paper(c.0, c.1);
        self.els.push(Element::Dot { c: (x, y), r: r_mm, fill });
    }

    /// A revolute joint: a small open circle of paper radius `r_mm`.
    pub fn joint(&mut self, c: (f64, f64), r_mm: f64) {
        self.dot(c, r_mm, "#ffffff");
    }

    /// A fixed pivot: a joint with the hatched ground triangle beneath it.
    pub fn fixed_pivot(&mut self, c: (f64, f64), r_mm: f64) {
        let (x, y) = self.to_paper(c.0, c.1);
        if !finite(&[x, y]) {
            return;
        }
        let h = 3.0 * r_mm;
        // labels keep off the ground symbol too
        let (l, r, b) = ((x - h, y + 1.6 * h), (x + h, y + 1.6 * h), (x, y));
        for s in [(b, l), (l, r), (r, b)] {
            self.segs.push(s);
        }
        let mut hatch = Vec::with_capacity(5);
        for i in 0..5 {
            let hx = x - 1.3 * h + i as f64 * 0.65 * h;
            self.segs.push(((hx + 0.6 * h, y + 1.6 * h), (hx, y + 2.3 * h)));
            hatch.push(((hx + 0.6 * h, y + 1.6 * h), (hx, y + 2.3 * h)));
        }
        self.els.push(Element::Ground {
            triangle: [b, l, r],
            hatch,
        });
        self.joint(c, r_mm);
    }

    /// A circular arc of world radius `r` from angle `a0` to `a1` (rad, CCW).
    pub fn arc(&mut self, c: (f64, f64), r: f64, a0: f64, a1: f64, s: Style) {
        let n = ((a1 - a0).abs() / 0.02).ceil().clamp(2.0, 2000.0) as usize;
        let pts: Vec<(f64, f64)> = (0..=n)
            .map(|i| {
                let a = a0 + (a1 - a0) * i as f64 / n as f64;
                (c.0 + r * a.cos(), c.1 + r * a.sin())
            })
            .collect();
        self.polyline(&pts, s);
    }

    /// An arrow from `a` to `b` (world) with a head of paper length `head_mm`.
    pub fn arrow(&mut self, a: (f64, f64), b: (f64, f64), s: Style, head_mm: f64) {
        if !finite(&[a.0, a.1, b.0, b.1]) {
            return;
        }
        let p1 = self.to_paper(a.0, a.1);
        let p2 = self.to_paper(b.0, b.1);
        self.arrow_paper(p1, p2, s, head_mm);
    }

    /// An arrow on paper coordinates (mm from the top-left corner).
    pub fn arrow_paper(&mut self, (x1, y1): (f64, f64), (x2, y2): (f64, f64), s: Style, head_mm: f64) {
        if !finite(&[x1, y1, x2, y2]) {
            return;
        }
        let (dx, dy) = (x2 - x1, y2 - y1);
        let len = (dx * dx + dy * dy).sqrt();
        self.segs.push(((x1, y1), (x2, y2)));
        self.els.push(Element::Line {
            a: (x1, y1),
            b: (x2, y2),
            style: Style { fill: None, ..s },
            round: false,
        });
        if len < 1e-9 {
            return;
        }
        let h = head_mm.min(0.5 * len);
        let (ux, uy) = (dx / len, dy / len);
        let (bx, by) = (x2 - h * ux, y2 - h * uy);
        let w = 0.3 * h;
        self.els.push(Element::Head {
            points: [(x2, y2), (bx - w * uy, by + w * ux), (bx + w * uy, by - w * ux)],
            color: s.color,
        });
    }

    /// Text at a world point, `size_mm` high.
    pub fn text(&mut self, at: (f64, f64), text: &str, size_mm: f64, anchor: Anchor) {
        self.text_colored(at, text, size_mm, anchor, "#000000");
    }

    /// Coloured text at a world point.
    pub fn text_colored(&mut self, at: (f64, f64), text: &str, size_mm: f64, anchor: Anchor, color: &str) {
        if !finite(&[at.0, at.1]) {
            return;
        }
        let (x, y) = self.to_paper(at.0, at.1);
        self.text_paper((x, y), text, size_mm, anchor, color);
    }

    /// Text at a paper position (mm from the top-left corner).
    pub fn text_paper(&mut self, at: (f64, f64), text: &str, size_mm: f64, anchor: Anchor, color: &str) {
        self.els.push(Element::Text {
            at,
            text: text.to_string(),
            size: size_mm,
            anchor,
            color: color.to_string(),
            rich: false,
        });
        self.reserve(text_box(at, size_mm, anchor, text.chars().count()));
    }

    /// The drawing's name (наименование изображения: "План скоростей"),
    /// typeset (see [`rich`]) at a paper point in a group of class
    /// [`TITLE`](crate::picture::TITLE), its box kept free. The name alone:
    /// the scale, μ and the drawing's parameters go on a line of their own
    /// under it, so that the note, which names a figure in its caption
    /// (GOST 2.105), leaves the name out
    /// ([`Picture::without_title`](crate::picture::Picture::without_title))
    /// and keeps them; the sheets and the loose files print both.
    pub fn title(&mut self, at: (f64, f64), name: &str, size_mm: f64, anchor: Anchor) {
        self.begin_group_data(crate::picture::TITLE, &[]);
        self.rich_paper(at, name, size_mm, anchor, "#000");
        self.end_group();
    }

    /// A line on paper coordinates (mm from the top-left corner).
    pub fn line_paper(&mut self, a: (f64, f64), b: (f64, f64), s: Style) {
        self.segs.push((a, b));
        self.els.push(Element::Line {
            a,
            b,
            style: s,
            round: false,
        });
    }

    /// Open a group (`<g>`) with an id, e.g. a layer; close it with [`Canvas::end_group`].
    pub fn begin_group(&mut self, id: &str) {
        self.els.push(Element::GroupOpen {
            id: Some(id.to_string()),
            class: None,
            data: Vec::new(),
        });
    }

    /// A segment of a class on paper, its ends written to 0.1 µm (a chord
    /// whose length a reader measures); labels keep off it only when it is
    /// reserved ([`Canvas::reserve_segment`]).
    pub fn line_classed(&mut self, class: &str, a: (f64, f64), b: (f64, f64), s: Style) {
        self.els.push(Element::Classed {
            class: class.to_string(),
            a,
            b,
            style: s,
        });
    }

    /// Open a group of a class with data attributes (`data-label`,
    /// `data-kind` of a plan's vector); close it with [`Canvas::end_group`].
    pub fn begin_group_data(&mut self, class: &str, data: &[(&str, &str)]) {
        self.els.push(Element::GroupOpen {
            id: None,
            class: Some(class.to_string()),
            data: data.iter().map(|(k, v)| (k.to_string(), v.to_string())).collect(),
        });
    }

    /// Close the last group.
    pub fn end_group(&mut self) {
        self.els.push(Element::GroupClose);
    }

    /// An attribute of the root element, e.g. `data-scale="1:2"` that the
    /// sheet's title block reads.
    pub fn root_attr(&mut self, name: &str, value: &str) {
        self.root.push((name.to_string(), value.to_string()));
    }

    /// A path of a class through paper points (mm from the top-left
    /// corner): a non-finite point lifts the pen. The labels placed later
    /// do not see it (reserve its chords with [`Canvas::reserve_segment`]).
    pub fn path_paper(&mut self, class: Option<&str>, pts: &[(f64, f64)], s: Style) {
        let runs: Vec<Vec<(f64, f64)>> = pts
            .split(|p| !(p.0.is_finite() && p.1.is_finite()))
            .filter(|r| !r.is_empty())
            .map(<[(f64, f64)]>::to_vec)
            .collect();
        self.els.push(Element::Path {
            class: class.map(str::to_string),
            data: PathData::Runs(runs),
            style: s,
        });
    }

    /// Separate segments on paper drawn as one path of a class (a grid),
    /// not seen by the labels.
    pub fn segments_paper(&mut self, class: Option<&str>, segs: Vec<((f64, f64), (f64, f64))>, s: Style) {
        self.els.push(Element::Path {
            class: class.map(str::to_string),
            data: PathData::Segments(segs),
            style: s,
        });
    }

    /// An open marker circle of a class at a paper point (the points of a
    /// curve, a legend's sample), `r_mm` in radius.
    pub fn marker_paper(&mut self, class: &str, at: (f64, f64), r_mm: f64, s: Style) {
        if finite(&[at.0, at.1]) {
            self.els.push(Element::Marker {
                class: class.to_string(),
                c: at,
                r: r_mm,
                style: s,
            });
        }
    }

    /// Text turned to read upwards, its baseline's middle at a paper point
    /// (the name of a vertical axis).
    pub fn text_upward(&mut self, at: (f64, f64), text: &str, size_mm: f64) {
        self.els.push(Element::Upward {
            at,
            text: text.to_string(),
            size: size_mm,
        });
    }

    /// The paper size, mm.
    pub fn size(&self) -> (f64, f64) {
        (self.width, self.height)
    }

    /// Every straight piece drawn so far, on paper (mm, y down).
    pub fn segments(&self) -> &[crate::line_grid::Segment] {
        self.segs.segments()
    }

    /// How many straight pieces drawn so far cut the paper box `r` (mm,
    /// y down), and how many kept boxes it overlaps: 0 when a text whose
    /// ink is `r` crosses no line and no kept place.
    pub fn occupied(&self, r: Rect) -> usize {
        self.segs.count((r.x0, r.y0, r.x1, r.y1), |s| r.cuts(s.0, s.1)) + self.boxes.iter().filter(|b| b.overlaps(&r)).count()
    }

    /// Put a centred rich label at `at` and reserve its ink box, given as
    /// (left, right, above, below) of the anchor in mm; the box.
    fn put_rich_reserved(&mut self, at: (f64, f64), text: &str, size_mm: f64, color: &str, ink: (f64, f64, f64, f64)) -> Rect {
        let (bx0, bx1, up, down) = ink;
        self.els.push(Element::Text {
            at,
            text: text.to_string(),
            size: size_mm,
            anchor: Anchor::Middle,
            color: color.to_string(),
            rich: true,
        });
        let r = Rect {
            x0: at.0 + bx0,
            y0: at.1 - up,
            x1: at.0 + bx1,
            y1: at.1 + down,
        };
        self.reserve(r);
        r
    }

    /// Keep a paper box free of labels placed later.
    pub fn reserve(&mut self, r: Rect) {
        self.boxes.push(r);
    }

    /// Keep labels placed later off a paper segment that is drawn some
    /// other way (a piece of a curve drawn as one path).
    pub fn reserve_segment(&mut self, a: (f64, f64), b: (f64, f64)) {
        self.segs.push((a, b));
    }

    /// Keep a small square around a world point free (a joint, a pole).
    pub fn reserve_point(&mut self, at: (f64, f64), half_mm: f64) {
        let (x, y) = self.to_paper(at.0, at.1);
        self.boxes.push(Rect {
            x0: x - half_mm,
            y0: y - half_mm,
            x1: x + half_mm,
            y1: y + half_mm,
        });
    }

    /// Typeset text (see [`rich`]) at a paper point, its box kept free.
    pub fn rich_paper(&mut self, at: (f64, f64), text: &str, size_mm: f64, anchor: Anchor, color: &str) {
        self.els.push(Element::Text {
            at,
            text: text.to_string(),
            size: size_mm,
            anchor,
            color: color.to_string(),
            rich: true,
        });
        self.reserve(text_box(at, size_mm, anchor, shown_len(text)));
    }

    /// A label for the world point `at`: typeset `text` put at the first of
    /// the places around the point whose box stays inside the paper, clear
    /// of every other label and of every line drawn so far (a greedy
    /// placer; draw the lines first, then the labels). Returns the box.
    pub fn label(&mut self, at: (f64, f64), text: &str, size_mm: f64, color: &str) -> Rect {
        let p = self.to_paper(at.0, at.1);
        self.label_paper(p, text, size_mm, color)
    }

    /// [`Canvas::label`] at a paper point.
    pub fn label_paper(&mut self, p: (f64, f64), text: &str, size_mm: f64, color: &str) -> Rect {
        let n = shown_len(text);
        let at = self
            .best_spot(p, n, size_mm, &[0.8, 2.0, 3.5, 5.5, 8.0, 12.0, 17.0], false)
            .map_or(p, |b| b.at);
        self.rich_paper(at, text, size_mm, Anchor::Middle, color);
        text_box(at, size_mm, Anchor::Middle, n)
    }

    /// [`Canvas::label`] with the label's box as printed: the ink of the
    /// typeset text in the drawing face ([`rich_ink`]), kept `clear_mm`
    /// off every line drawn so far (off its edge: the line's half width of
    /// up to 0.4 mm added) and off every other text and kept place. The
    /// places tried: sixteen directions round the point, the box's nearest
    /// edge `clear_mm` … 30 mm from it; when none is clear the least
    /// crowded. Returns the ink's box.
    pub fn label_clear(&mut self, at: (f64, f64), text: &str, size_mm: f64, color: &str, clear_mm: f64) -> Rect {
        self.label_clear_near(&[at], text, size_mm, color, clear_mm)
    }

    /// [`Canvas::label_clear`] for a label that may stand by any of the
    /// world points `near` (along a line it names): the nearest clear
    /// place round the first point, else round the next …, the distances
    /// tried in turn for all the points.
    pub fn label_clear_near(&mut self, near: &[(f64, f64)], text: &str, size_mm: f64, color: &str, clear_mm: f64) -> Rect {
        let pts: Vec<(f64, f64)> = near.iter().map(|q| self.to_paper(q.0, q.1)).collect();
        let p = pts.first().copied().unwrap_or((0.0, 0.0));
        // the coordinates and sizes are written rounded: a hair more
        let clear_mm = clear_mm + 0.02;
        let (w, up, down) = rich_ink(text, size_mm);
        let lean = 15f64.to_radians().tan();
        // the ink's box about the anchor (the middle of the advances, on the baseline)
        let (bx0, bx1) = (-0.5 * w - lean * down, 0.5 * w + lean * up);
        let (bw, bh) = (bx1 - bx0, up + down);
        let mut best: Option<(usize, f64, (f64, f64))> = None;
        'search: for d in [0.0, 0.5, 1.0, 1.8, 2.8, 4.0, 5.5, 7.5, 10.0, 13.0, 17.0, 22.0, 30.0] {
            let d = clear_mm + d;
            for (k, p) in (0..16).flat_map(|k| pts.iter().map(move |p| (k, *p))) {
                let th = std::f64::consts::TAU * k as f64 / 16.0 + std::f64::consts::FRAC_PI_4;
                let (c, sn) = (th.cos(), th.sin());
                let reach = |half: f64, dir: f64| half * dir.abs().min(1.0) / c.abs().max(sn.abs()).max(1e-9);
                let (cx, cy) = (p.0 + c * (d + reach(0.5 * bw, c)), p.1 - sn * (d + reach(0.5 * bh, sn)));
                let r = Rect {
                    x0: cx - 0.5 * bw,
                    y0: cy - 0.5 * bh,
                    x1: cx + 0.5 * bw,
                    y1: cy + 0.5 * bh,
                };
                let grown = |g: f64| Rect {
                    x0: r.x0 - g,
                    y0: r.y0 - g,
                    x1: r.x1 + g,
                    y1: r.y1 + g,
                };
                let (rb, rl) = (grown(clear_mm), grown(clear_mm + 0.4));
                let inside = r.x0 >= 0.5 && r.y0 >= 0.5 && r.x1 <= self.width - 0.5 && r.y1 <= self.height - 0.5;
                let hits = self.boxes.iter().filter(|b| b.overlaps(&rb)).count()
                    + self.segs.count((rl.x0, rl.y0, rl.x1, rl.y1), |s| rl.cuts(s.0, s.1))
                    + if inside { 0 } else { 1000 };
                let anchor = (cx - 0.5 * (bx0 + bx1), cy + 0.5 * (up - down));
                if best.is_none_or(|b| hits < b.0) {
                    best = Some((hits, d, anchor));
                }
                if hits == 0 {
                    break 'search;
                }
            }
        }
        let at = best.map_or(p, |b| b.2);
        self.put_rich_reserved(at, text, size_mm, color, (bx0, bx1, up, down))
    }

    /// A label that names the segment `a`–`b` (world points; an arm of
    /// Zhukovsky's lever), its ink's box beside the segment: `clear_mm`
    /// off the segment's line and every line drawn so far and every other
    /// text (as [`Canvas::label_clear`] keeps them), its nearest edge no
    /// more than `reach_mm` from the segment. The places tried: the box
    /// set off the segment's line square to it, on either side, its middle
    /// over points every 2.5 % of the segment from 10 % past `b` back to
    /// 5 % from `a` (`b` the end away from the lines' crossing), then the box
    /// round `b` as `label_clear` sets it; the first gap from the line
    /// (from `clear_mm` by 0.25 mm) at which one is clear wins. `None`,
    /// nothing written, when no place within `reach_mm` is clear.
    pub fn label_beside(
        &mut self,
        (a, b): ((f64, f64), (f64, f64)),
        text: &str,
        size_mm: f64,
        color: &str,
        clear_mm: f64,
        reach_mm: f64,
    ) -> Option<Rect> {
        let (pa, pb) = (self.to_paper(a.0, a.1), self.to_paper(b.0, b.1));
        let (dx, dy) = (pb.0 - pa.0, pb.1 - pa.1);
        let len = dx.hypot(dy);
        if len.is_nan() || len <= 1e-9 {
            return None;
        }
        let (ux, uy) = (dx / len, dy / len);
        let clear = clear_mm + 0.02;
        let (w, up, down) = rich_ink(text, size_mm);
        let lean = 15f64.to_radians().tan();
        let (bx0, bx1) = (-0.5 * w - lean * down, 0.5 * w + lean * up);
        let (hw, hh) = (0.5 * (bx1 - bx0), 0.5 * (up + down));
        // the box's half extent along a unit direction (its support)
        let support = |nx: f64, ny: f64| hw * nx.abs() + hh * ny.abs();
        let fits = |c: &Self, cx: f64, cy: f64| {
            let r = Rect {
                x0: cx - hw,
                y0: cy - hh,
                x1: cx + hw,
                y1: cy + hh,
            };
            let rb = Rect {
                x0: r.x0 - clear,
                y0: r.y0 - clear,
                x1: r.x1 + clear,
                y1: r.y1 + clear,
            };
            let rl = Rect {
                x0: rb.x0 - 0.4,
                y0: rb.y0 - 0.4,
                x1: rb.x1 + 0.4,
                y1: rb.y1 + 0.4,
            };
            let inside = r.x0 >= 0.5 && r.y0 >= 0.5 && r.x1 <= c.width - 0.5 && r.y1 <= c.height - 0.5;
            inside
                && !c.boxes.iter().any(|q| q.overlaps(&rb))
                && c.segs.count((rl.x0, rl.y0, rl.x1, rl.y1), |s| rl.cuts(s.0, s.1)) == 0
                && dist_segment(&r, pa, pb) >= clear - 1e-9
        };
        let mut found = None;
        let steps = ((reach_mm - clear) / 0.25).floor().max(0.0) as usize;
        'search: for gi in 0..=steps {
            let g = clear + 0.25 * gi as f64;
            // square off the line, either side, along the segment from b
            for k in (0..=42).map(|k| 1.1 - 0.025 * k as f64) {
                let (px, py) = (pa.0 + dx * k, pa.1 + dy * k);
                for side in [1.0, -1.0] {
                    let (nx, ny) = (-uy * side, ux * side);
                    let off = g + support(nx, ny);
                    let (cx, cy) = (px + nx * off, py + ny * off);
                    if fits(self, cx, cy) && dist_segment(&Rect::centred((cx, cy), hw, hh), pa, pb) <= reach_mm {
                        found = Some((cx, cy));
                        break 'search;
                    }
                }
            }
            // round b
            for k in 0..16 {
                let th = std::f64::consts::TAU * k as f64 / 16.0;
                let (c, sn) = (th.cos(), th.sin());
                let off = g + support(c, sn);
                let (cx, cy) = (pb.0 + c * off, pb.1 - sn * off);
                if fits(self, cx, cy) && dist_segment(&Rect::centred((cx, cy), hw, hh), pa, pb) <= reach_mm {
                    found = Some((cx, cy));
                    break 'search;
                }
            }
        }
        let (cx, cy) = found?;
        let at = (cx - 0.5 * (bx0 + bx1), cy + 0.5 * (up - down));
        Some(self.put_rich_reserved(at, text, size_mm, color, (bx0, bx1, up, down)))
    }

    /// [`Canvas::label`], but when no place within 17 mm of the point is
    /// clear of the lines and the other texts, the label goes farther out
    /// (up to 47 mm) where it is clear, on a thin leader line to the point
    /// that crosses no other text; only when that fails too is the least
    /// crowded near place taken.
    pub fn label_led(&mut self, at: (f64, f64), text: &str, size_mm: f64, color: &str) -> Rect {
        let p = self.to_paper(at.0, at.1);
        let n = shown_len(text);
        let near = self.best_spot(p, n, size_mm, &[0.8, 2.0, 3.5, 5.5, 8.0, 12.0, 17.0], false);
        if near.is_some_and(|b| b.hits > 0) {
            let far = self.best_spot(p, n, size_mm, &[23.0, 30.0, 38.0, 47.0], true);
            if let Some(f) = far.filter(|f| f.hits == 0) {
                let (c, s) = f.dir;
                let from = (p.0 + c * (f.d - 0.3), p.1 - s * (f.d - 0.3));
                self.line_paper(from, p, Style::THIN);
                self.rich_paper(f.at, text, size_mm, Anchor::Middle, color);
                return text_box(f.at, size_mm, Anchor::Middle, n);
            }
        }
        let at = near.map_or(p, |b| b.at);
        self.rich_paper(at, text, size_mm, Anchor::Middle, color);
        text_box(at, size_mm, Anchor::Middle, n)
    }

    /// [`Canvas::label`] for a position number at its crank pin, out
    /// along the crank (`toward`, radians from the x axis, y up), away from
    /// the lines that meet at the pivot:
    /// 1. the nearest place clear of every line and text within 67.5° of
    ///    `toward`, up to 5 mm from the pin;
    /// 2. else (a number among the rods that leave the crank circle) a
    ///    clear place farther out (8 … 30 mm) within 45° of `toward`, on a
    ///    thin leader line to the pin that crosses no other text;
    /// 3. else the nearest clear place round the pin, up to 8 mm;
    /// 4. else a clear place farther out in any direction, on a leader;
    /// 5. else the least crowded of the near places.
    pub fn label_toward(&mut self, at: (f64, f64), toward: f64, text: &str, size_mm: f64, color: &str) -> Rect {
        const NEAR: [f64; 7] = [0.5, 1.0, 1.6, 2.3, 3.0, 4.0, 5.0];
        let p = self.to_paper(at.0, at.1);
        let n = shown_len(text);
        // the number and, kept free of the labels placed later, a margin
        // of NUMBER_GAP round it (so that two numbers stand apart)
        let put = |c: &mut Self, at: (f64, f64)| {
            c.rich_paper(at, text, size_mm, Anchor::Middle, color);
            let r = text_box(at, size_mm, Anchor::Middle, n);
            c.reserve(Rect {
                x0: r.x0 - NUMBER_GAP,
                y0: r.y0 - NUMBER_GAP,
                x1: r.x1 + NUMBER_GAP,
                y1: r.y1 + NUMBER_GAP,
            });
            r
        };
        let out = self.best_spot_from(p, n, size_mm, &NEAR, false, Some((toward, 7)));
        if let Some(o) = out.filter(|o| o.hits == 0) {
            return put(self, o.at);
        }
        let far = self.best_spot_from(p, n, size_mm, &[8.0, 11.0, 14.0, 18.0, 23.0, 30.0], true, Some((toward, 5)));
        if let Some(f) = far.filter(|f| f.hits == 0) {
            let (from, to) = leader(p, &text_box(f.at, size_mm, Anchor::Middle, n));
            self.line_paper(from, to, Style::THIN);
            return put(self, f.at);
        }
        let round = self.best_spot_from(
            p,
            n,
            size_mm,
            &[0.5, 1.0, 1.6, 2.3, 3.0, 4.0, 5.0, 6.5, 8.0],
            false,
            Some((toward, 16)),
        );
        if let Some(r) = round.filter(|r| r.hits == 0) {
            return put(self, r.at);
        }
        let far = self.best_spot_from(p, n, size_mm, &[11.0, 14.0, 18.0, 23.0, 30.0], true, Some((toward, 16)));
        if let Some(f) = far.filter(|f| f.hits == 0) {
            let (from, to) = leader(p, &text_box(f.at, size_mm, Anchor::Middle, n));
            self.line_paper(from, to, Style::THIN);
            return put(self, f.at);
        }
        let at = [round, out].into_iter().flatten().min_by_key(|b| b.hits).map_or(p, |b| b.at);
        put(self, at)
    }

    /// The best place for a label of `n` characters around the paper point
    /// `p`, its nearest edge at one of the distances `dists`: the fewest
    /// lines and boxes hit (the paper's edge counting 1000), then the
    /// nearest. With `lead`, the leader from the box to the point counts a
    /// hit for every text box it crosses.
    fn best_spot(&self, p: (f64, f64), n: usize, size_mm: f64, dists: &[f64], lead: bool) -> Option<Spot> {
        self.best_spot_from(p, n, size_mm, dists, lead, None)
    }

    /// [`Canvas::best_spot`]; with `toward` (an angle and a count k of
    /// directions), only the k of the sixteen directions nearest that
    /// angle are tried (0, +22.5°, −22.5°, +45° …), nearest first.
    fn best_spot_from(
        &self,
        p: (f64, f64),
        n: usize,
        size_mm: f64,
        dists: &[f64],
        lead: bool,
        toward: Option<(f64, usize)>,
    ) -> Option<Spot> {
        let w = text_width(size_mm, n);
        let e = crate::picture::em(size_mm);
        let (up, down) = (TEXT_ASCENT * e, TEXT_DESCENT * e);
        let h = up + down;
        let mut best: Option<Spot> = None;
        let step = std::f64::consts::TAU / 16.0;
        let k_to = toward.map_or(16, |t| t.1.min(16));
        {
            for &d in dists {
                for k in 0..k_to {
                    let th = match toward.map(|t| t.0) {
                        // 0, +1, −1, +2, −2 … steps from `toward`
                        Some(a) => a + step * (if k % 2 == 1 { k.div_ceil(2) as f64 } else { -((k / 2) as f64) }),
                        None => std::f64::consts::TAU * k as f64 / 16.0 + std::f64::consts::FRAC_PI_4,
                    };
                    let (c, s) = (th.cos(), th.sin());
                    // the box's centre so that its nearest edge is `d` from the point
                    let cx = p.0 + c * (d + 0.5 * w * c.abs().min(1.0) / c.abs().max(s.abs()).max(1e-9));
                    let cy = p.1 - s * (d + 0.5 * h * s.abs().min(1.0) / c.abs().max(s.abs()).max(1e-9));
                    let at = (cx, cy + 0.5 * h - down);
                    let r = Rect {
                        x0: cx - 0.5 * w,
                        y0: cy - 0.5 * h,
                        x1: cx + 0.5 * w,
                        y1: cy + 0.5 * h,
                    };
                    let inside = r.x0 >= 0.5 && r.y0 >= 0.5 && r.x1 <= self.width - 0.5 && r.y1 <= self.height - 0.5;
                    // the lines kept 0.15 mm off the box (a line grazing its corner counts)
                    let rl = Rect {
                        x0: r.x0 - 0.15,
                        y0: r.y0 - 0.15,
                        x1: r.x1 + 0.15,
                        y1: r.y1 + 0.15,
                    };
                    let mut hits = self.boxes.iter().filter(|b| b.overlaps(&r)).count()
                        + self.segs.count((rl.x0, rl.y0, rl.x1, rl.y1), |s| rl.cuts(s.0, s.1))
                        + if inside { 0 } else { 1000 };
                    if lead {
                        let (from, to) = leader(p, &r);
                        let at_p = |b: &&Rect| p.0 >= b.x0 && p.0 <= b.x1 && p.1 >= b.y0 && p.1 <= b.y1;
                        hits += self.boxes.iter().filter(|b| !at_p(b) && b.cuts(from, to)).count();
                    }
                    let cost = d + 0.01 * k as f64;
                    if best.is_none_or(|b| (hits, cost) < (b.hits, b.cost)) {
                        best = Some(Spot {
                            hits,
                            cost,
                            at,
                            d,
                            dir: (c, s),
                        });
                    }
                    if hits == 0 {
                        return best;
                    }
                }
            }
        }
        best
    }

    /// The drawing: its SVG text and its scene ([`Picture`]).
    pub fn finish(&self) -> Picture {
        Picture::new(self.width, self.height, self.root.clone(), self.els.clone())
    }
}

/// The least gap between a position number and a label placed after it,
/// mm (GOST 2.304's smallest letter height less half: numbers at 2.5 mm
/// stand at least a letter's width apart).
pub const NUMBER_GAP: f64 = 1.0;

/// The leader line from a label's box `r` to the paper point `p`: along
/// the line from the point to the box's centre, from 0.3 mm off the box
/// (where that line enters the box grown by 0.3 mm) to 0.8 mm off the
/// point (outside a joint's circle).
fn leader(p: (f64, f64), r: &Rect) -> ((f64, f64), (f64, f64)) {
    let centre = (0.5 * (r.x0 + r.x1), 0.5 * (r.y0 + r.y1));
    let (dx, dy) = (centre.0 - p.0, centre.1 - p.1);
    let enter = |lo: f64, hi: f64, from: f64, d: f64| {
        if d.abs() < 1e-12 {
            f64::MIN
        } else {
            ((if d > 0.0 { lo } else { hi }) - from) / d
        }
    };
    let t = enter(r.x0 - 0.3, r.x1 + 0.3, p.0, dx)
        .max(enter(r.y0 - 0.3, r.y1 + 0.3, p.1, dy))
        .clamp(0.0, 1.0);
    let len = dx.hypot(dy).max(1e-9);
    ((p.0 + t * dx, p.1 + t * dy), (p.0 + 0.8 * dx / len, p.1 + 0.8 * dy / len))
}

/// A place for a label found by `Canvas::best_spot`.
#[derive(Debug, Clone, Copy)]
struct Spot {
    /// Lines and boxes the label (and its leader) would hit.
    hits: usize,
    /// The distance with a tie-break by direction.
    cost: f64,
    /// The text's baseline point.
    at: (f64, f64),
    /// The distance from the point to the box's nearest edge, mm.
    d: f64,
    /// The direction from the point (cos, sin; y up).
    dir: (f64, f64),
}

/// The lettering's font (GOST 2.304 type B, ISO 3098): osifont first (an
/// open face with the standard's letter shapes, upright; the note's
/// typesetter embeds it when it is installed), then upright fallbacks.
/// Every text is slanted to 75° by [`slant`] about its anchor, not by
/// `font-style="italic"` (osifont has no italic, and a synthetic oblique
/// differs between viewers); the letters osifont draws as boxes (Э э Ё ё)
/// are set in tmm's supplement ([`tmm_draw::svg::lettering`]).
pub const FONT: &str = "osifont, DejaVu Sans, Arial, sans-serif";

/// The SVG transform that slants a text anchored at (x, y) to GOST
/// 2.304's 75°: a shear of 15° about the anchor, so the baseline and the
/// anchor stay where they are.
///
/// ```
/// assert_eq!(tmm_report::svg::slant(1.0, 2.0), "translate(1.000 2.000) skewX(-15) translate(-1.000 -2.000)");
/// ```
pub fn slant(x: f64, y: f64) -> String {
    format!(
        "translate({x:.3} {y:.3}) skewX(-{}) translate({:.3} {:.3})",
        tmm_draw::svg::SLANT_DEG,
        -x,
        -y
    )
}

/// The part of the lettering height above the baseline a box counts.
pub const TEXT_ASCENT: f64 = 0.85;
/// The part below the baseline (descenders and subscripts).
pub const TEXT_DESCENT: f64 = 0.35;

/// The estimated width of `n` characters of lettering `size` mm high: 0.6 of
/// the height per character (GOST 2.304 type A is 5/7 wide at most for
/// capitals, less for lower case and digits; subscripts are smaller).
/// The size is the one written, raised to the lettering floor
/// ([`crate::picture::em`]).
pub fn text_width(size: f64, n: usize) -> f64 {
    0.6 * crate::picture::em(size) * n as f64
}

/// A box on paper, mm, y down.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rect {
    /// Left.
    pub x0: f64,
    /// Top.
    pub y0: f64,
    /// Right.
    pub x1: f64,
    /// Bottom.
    pub y1: f64,
}

impl Rect {
    /// The box of half extents `hw` × `hh` about `c`.
    pub fn centred(c: (f64, f64), hw: f64, hh: f64) -> Rect {
        Rect {
            x0: c.0 - hw,
            y0: c.1 - hh,
            x1: c.0 + hw,
            y1: c.1 + hh,
        }
    }

    /// Whether two boxes share an inner point.
    pub fn overlaps(&self, o: &Rect) -> bool {
        self.x0 < o.x1 && o.x0 < self.x1 && self.y0 < o.y1 && o.y0 < self.y1
    }

    /// Whether the segment `a`–`b` passes through the box (Liang–Barsky clipping).
    pub fn cuts(&self, a: (f64, f64), b: (f64, f64)) -> bool {
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for (p, q) in [(-dx, a.0 - self.x0), (dx, self.x1 - a.0), (-dy, a.1 - self.y0), (dy, self.y1 - a.1)] {
            if p == 0.0 {
                if q < 0.0 {
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

/// The box of a text of `n` characters written at `at` (its baseline point).
pub fn text_box(at: (f64, f64), size: f64, anchor: Anchor, n: usize) -> Rect {
    let w = text_width(size, n);
    let size = crate::picture::em(size);
    let x0 = match anchor {
        Anchor::Start => at.0,
        Anchor::Middle => at.0 - 0.5 * w,
        Anchor::End => at.0 - w,
    };
    Rect {
        x0,
        y0: at.1 - TEXT_ASCENT * size,
        x1: x0 + w,
        y1: at.1 + TEXT_DESCENT * size,
    }
}

/// The number of characters [`rich`] shows for `s` (the markup `^ _ { }` dropped).
pub fn shown_len(s: &str) -> usize {
    s.chars().filter(|c| !matches!(c, '^' | '_' | '{' | '}')).count()
}

/// The least distance between a box and the segment `a`–`b` (0 when the
/// segment enters it): the least of the segment's ends to the box and the
/// box's corners to the segment.
fn dist_segment(r: &Rect, a: (f64, f64), b: (f64, f64)) -> f64 {
    if r.cuts(a, b) {
        return 0.0;
    }
    let to_box = |p: (f64, f64)| {
        let dx = (r.x0 - p.0).max(p.0 - r.x1).max(0.0);
        let dy = (r.y0 - p.1).max(p.1 - r.y1).max(0.0);
        dx.hypot(dy)
    };
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = (dx * dx + dy * dy).max(1e-18);
    let to_seg = |p: (f64, f64)| {
        let t = (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0);
        (p.0 - a.0 - t * dx).hypot(p.1 - a.1 - t * dy)
    };
    [
        to_box(a),
        to_box(b),
        to_seg((r.x0, r.y0)),
        to_seg((r.x1, r.y0)),
        to_seg((r.x0, r.y1)),
        to_seg((r.x1, r.y1)),
    ]
    .into_iter()
    .fold(f64::INFINITY, f64::min)
}

/// The ink of `s` typeset by [`rich`] at letter size `size`, in the
/// drawing face (osifont's advances, [`tmm_draw::face::advance_em`], 0.6
/// em for a character it lacks): the advance width (an index at its own
/// smaller size, [`crate::picture::index_em`]), the height above the
/// baseline and the depth below it (an index raised by 0.4 of the size or
/// lowered by 0.25, as [`rich`] sets it), mm. The 75° slant is not in the
/// width: it leans the top by tan 15° of the height.
///
/// ```
/// // 10 mm letters: the index at 7 mm (above the lettering floor)
/// let (w, up, down) = tmm_report::svg::rich_ink("h_1 = 12", 10.0);
/// let (w0, up0, down0) = tmm_report::svg::rich_ink("h1 = 12", 10.0);
/// assert!(w < w0 && up == up0 && down > down0);
/// assert!((down - (2.5 + 0.35 * 7.0)).abs() < 1e-9);
/// ```
pub fn rich_ink(s: &str, size: f64) -> (f64, f64, f64) {
    // written at the lettering floor at least, the indices by that size
    let size = crate::picture::em(size);
    let (e, ie) = (size, crate::picture::index_em(size));
    let adv = |c: char| tmm_draw::face::advance_em(c).unwrap_or(0.6);
    let (mut w, mut up, mut down) = (0.0, TEXT_ASCENT * e, TEXT_DESCENT * e);
    // 0 on the line, 1 raised, -1 lowered
    let mut level = 0i8;
    let mut braced = false;
    let mut run_open = false;
    for ch in s.chars() {
        match ch {
            '^' | '_' => {
                level = if ch == '^' { 1 } else { -1 };
                braced = false;
                run_open = false;
            }
            '{' if level != 0 && !run_open => braced = true,
            '}' if braced => {
                level = 0;
                braced = false;
            }
            ' ' if level != 0 && !braced => {
                level = 0;
                w += adv(' ') * e;
            }
            c => {
                run_open = true;
                match level {
                    0 => w += adv(c) * e,
                    1 => {
                        w += adv(c) * ie;
                        up = up.max(0.4 * size + TEXT_ASCENT * ie);
                    }
                    _ => {
                        w += adv(c) * ie;
                        down = down.max(0.25 * size + TEXT_DESCENT * ie);
                    }
                }
            }
        }
    }
    (w, up, down)
}

/// Typeset a label of the course's notation as SVG text content: `^x` puts
/// `x` up (a superscript), `_x` down (a subscript) up to the next space,
/// `^`, `_` or the closing brace of `_{…}`. `a^τ_CB` is a, τ raised and CB
/// lowered; `R_{12}` is R with 12 lowered; plain text stays as it is.
///
/// ```
/// let t = tmm_report::svg::rich("a^τ_CB", 5.0);
/// assert!(t.starts_with("a<tspan") && t.contains(">τ</tspan>") && t.contains(">CB</tspan>"));
/// assert_eq!(tmm_report::svg::rich("p", 5.0), "p");
/// ```
pub fn rich(s: &str, size: f64) -> String {
    #[derive(PartialEq, Clone, Copy)]
    enum Level {
        Base,
        Up,
        Down,
    }
    let shift = |l: Level| match l {
        Level::Base => 0.0,
        Level::Up => -0.4 * size,
        Level::Down => 0.25 * size,
    };
    let mut out = String::new();
    let mut level = Level::Base;
    let mut run = String::new();
    let mut at = 0.0f64; // the current baseline shift
    let mut braced = false;
    let flush = |out: &mut String, run: &mut String, level: Level, at: &mut f64| {
        if run.is_empty() {
            return;
        }
        if level == Level::Base && *at == 0.0 {
            out.push_str(&tmm_draw::svg::lettering(run));
        } else {
            let dy = shift(level) - *at;
            let fs = if level == Level::Base {
                size
            } else {
                crate::picture::index_em(size)
            };
            let _ = write!(
                out,
                "<tspan dy=\"{dy:.2}\" font-size=\"{fs:.2}\">{}</tspan>",
                tmm_draw::svg::lettering(run)
            );
            *at = shift(level);
        }
        run.clear();
    };
    for ch in s.chars() {
        match ch {
            '^' | '_' => {
                flush(&mut out, &mut run, level, &mut at);
                level = if ch == '^' { Level::Up } else { Level::Down };
                braced = false;
            }
            '{' if level != Level::Base && run.is_empty() => braced = true,
            '}' if braced => {
                flush(&mut out, &mut run, level, &mut at);
                level = Level::Base;
                braced = false;
            }
            ' ' if level != Level::Base && !braced => {
                flush(&mut out, &mut run, level, &mut at);
                level = Level::Base;
                run.push(' ');
            }
            c => run.push(c),
        }
    }
    flush(&mut out, &mut run, level, &mut at);
    if at != 0.0 {
        let _ = write!(out, "<tspan dy=\"{:.2}\"></tspan>", -at);
    }
    out
}

/// A number as printed on a drawing in `lang`: `decimals` places, trailing
/// zeros dropped, a decimal comma in Russian and Ukrainian; a value that
/// is not finite as the marker the output check refuses
/// ([`crate::output::NONFINITE`]).
///
/// ```
/// use tmm_report::{project::Language, svg::num};
/// assert_eq!(num(0.05, 4, Language::Ru), "0,05");
/// assert_eq!(num(200.0, 2, Language::En), "200");
/// assert_eq!(num(-1.26, 1, Language::Uk), "-1,3");
/// ```
pub fn num(x: f64, decimals: usize, lang: crate::project::Language) -> String {
    if !x.is_finite() {
        return crate::output::NONFINITE.to_string();
    }
    let mut t = format!("{x:.decimals$}");
    if t.contains('.') {
        t = t.trim_end_matches('0').trim_end_matches('.').to_string();
    }
    if t == "-0" {
        t = "0".into();
    }
    comma(&t, lang)
}

/// [`num`] as a diagram's tick prints it: a negative value with the minus
/// sign − (U+2212, GOST 2.304), not the hyphen-minus.
///
/// ```
/// use tmm_report::{project::Language, svg::tick_num};
/// assert_eq!(tick_num(-40.0, 0, Language::Ru), "\u{2212}40");
/// assert_eq!(tick_num(2.5, 1, Language::Ru), "2,5");
/// ```
pub fn tick_num(x: f64, decimals: usize, lang: crate::project::Language) -> String {
    num(x, decimals, lang).replacen('-', "\u{2212}", 1)
}

/// A round scale factor μ as printed: its shortest exact decimal form.
///
/// ```
/// use tmm_report::{project::Language, svg::mu_text};
/// assert_eq!(mu_text(0.0025, Language::Ru), "0,0025");
/// assert_eq!(mu_text(200.0, Language::En), "200");
/// ```
pub fn mu_text(mu: f64, lang: crate::project::Language) -> String {
    // the round μ are 1, 2, 2.5, 4, 5 × 10^k: ten significant places hold them exactly
    let d = (10 - mu.abs().log10().floor() as i32).clamp(0, 16) as usize;
    num(mu, d, lang)
}

/// A standard scale as printed on a drawing of the language: GOST 2.302
/// writes "1:2,5"; an English drawing writes its decimal point.
///
/// ```
/// use tmm_report::{project::Language, svg::scale_text};
/// assert_eq!(scale_text("1:2,5", Language::En), "1:2.5");
/// assert_eq!(scale_text("1:2,5", Language::Uk), "1:2,5");
/// ```
pub fn scale_text(t: &str, lang: crate::project::Language) -> String {
    match lang {
        crate::project::Language::En => t.replace(',', "."),
        _ => t.to_string(),
    }
}

/// The decimal point of a printed number turned into a comma for ru and uk.
pub fn comma(t: &str, lang: crate::project::Language) -> String {
    match lang {
        crate::project::Language::En => t.to_string(),
        _ => t.replace('.', ","),
    }
}

fn finite(xs: &[f64]) -> bool {
    xs.iter().all(|x| x.is_finite())
}

/// Escape text for XML.
pub fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// One curve of a plot: a name, points and a colour.
#[derive(Debug, Clone)]
pub struct Series<'a> {
    /// Legend text.
    pub name: &'a str,
    /// The points (x, y).
    pub points: &'a [(f64, f64)],
    /// Line colour.
    pub color: &'static str,
}

/// A line plot with axes, ticks, labels and a legend on a `width × height` mm
/// paper: the kinematic diagrams, the balancing torque over the cycle, the
/// specific sliding, the motion laws.
pub fn plot(title: &str, xlabel: &str, ylabel: &str, series: &[Series<'_>], width: f64, height: f64) -> Picture {
    plot_with_impulses(title, xlabel, ylabel, series, &[], width, height)
}

/// [`plot`] with its tick labels in `lang` (a decimal comma in ru and uk);
/// the caller gives the title, the axes' names and the legend in `lang`.
///
/// ```
/// use tmm_report::{project::Language, svg::{Series, plot_in}};
/// let pts = [(0.0, 0.25), (1.0, 0.5)];
/// let s = [Series { name: "", points: &pts, color: "#000" }];
/// let svg = plot_in(Language::Ru, "t", "x", "y", &s, 100.0, 60.0);
/// assert!(svg.contains(">0,5<") && !svg.contains(">0.5<"));
/// ```
pub fn plot_in(
    lang: crate::project::Language,
    title: &str,
    xlabel: &str,
    ylabel: &str,
    series: &[Series<'_>],
    width: f64,
    height: f64,
) -> Picture {
    plot_with_impulses_in(lang, title, xlabel, ylabel, series, &[], width, height)
}

/// An impulse (a Dirac δ of the plotted quantity) at `x`, as the course marks
/// a jump of the next lower quantity: an arrow from the zero line to the edge
/// of the plot, up for a positive weight, with its label.
#[derive(Debug, Clone)]
pub struct Impulse {
    /// Where, in the x-axis' units.
    pub x: f64,
    /// The sign and size of the jump that causes it.
    pub weight: f64,
    /// The label, e.g. `Δa = +0.52 m/s²`.
    pub label: String,
}

/// [`plot`] with impulses marked as arrows.
pub fn plot_with_impulses(
    title: &str,
    xlabel: &str,
    ylabel: &str,
    series: &[Series<'_>],
    impulses: &[Impulse],
    width: f64,
    height: f64,
) -> Picture {
    plot_with_impulses_in(crate::project::Language::En, title, xlabel, ylabel, series, impulses, width, height)
}

/// [`plot_with_impulses`] with its tick labels in `lang`.
#[allow(clippy::too_many_arguments)]
pub fn plot_with_impulses_in(
    lang: crate::project::Language,
    title: &str,
    xlabel: &str,
    ylabel: &str,
    series: &[Series<'_>],
    impulses: &[Impulse],
    width: f64,
    height: f64,
) -> Picture {
    let mut c = Canvas::new(width, height);
    let (mut xmin, mut xmax, mut ymin, mut ymax) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
    for s in series {
        for &(x, y) in s.points.iter().filter(|p| p.0.is_finite() && p.1.is_finite()) {
            xmin = xmin.min(x);
            xmax = xmax.max(x);
            ymin = ymin.min(y);
            ymax = ymax.max(y);
        }
    }
    if !xmin.is_finite() {
        (xmin, xmax, ymin, ymax) = (0.0, 1.0, 0.0, 1.0);
    }
    ymin = ymin.min(0.0);
    ymax = ymax.max(0.0);
    if (ymax - ymin) < 1e-300 {
        ymax = ymin + 1.0;
    }
    if (xmax - xmin) < 1e-300 {
        xmax = xmin + 1.0;
    }
    // room for the impulses' arrows on their side of the zero line
    let reach = ymax.abs().max(ymin.abs());
    if impulses.iter().any(|i| i.weight < 0.0) {
        ymin = ymin.min(-reach);
    }
    if impulses.iter().any(|i| i.weight > 0.0) {
        ymax = ymax.max(reach);
    }
    let yt = Ticks::new(ymin, ymax, 6);
    let xt = Ticks::new(xmin, xmax, 8);
    let (yt0, yt1) = (yt.value(yt.first), yt.value(yt.last));
    let (xt0, xt1) = (xt.value(xt.first), xt.value(xt.last));
    let (left, bottom, pw, ph) = (22.0, 16.0, width - 30.0, height - 30.0);
    // independent scales on x and y
    let sx = pw / (xt1 - xt0);
    let sy = ph / (yt1 - yt0);
    let map = |x: f64, y: f64| (left + (x - xt0) * sx, height - (bottom + (y - yt0) * sy));
    c.title((width / 2.0, 7.0), title, 4.0, Anchor::Middle);
    // grid and ticks
    let grid = Style {
        width: 0.1,
        color: "#bbbbbb",
        dash: None,
        fill: None,
    };
    for i in yt.first..=yt.last {
        let y = yt.value(i);
        let (x0p, yp) = map(xt0, y);
        let (x1p, _) = map(xt1, y);
        c.line_paper((x0p, yp), (x1p, yp), grid);
        c.text_paper((x0p - 1.5, yp + 1.0), &yt.printed(i, lang), 2.6, Anchor::End, "#000");
    }
    for i in xt.first..=xt.last {
        let x = xt.value(i);
        let (xp, y0p) = map(x, yt0);
        let (_, y1p) = map(x, yt1);
        c.line_paper((xp, y0p), (xp, y1p), grid);
        c.text_paper((xp, y0p + 4.0), &xt.printed(i, lang), 2.6, Anchor::Middle, "#000");
    }
    // axes through zero
    let (ax0, ay0) = map(xt0, 0.0f64.clamp(yt0, yt1));
    let (ax1, _) = map(xt1, 0.0f64.clamp(yt0, yt1));
    c.line_paper((ax0, ay0), (ax1, ay0), Style::THIN.widened(0.35));
    let (bx, by0) = map(xt0, yt0);
    let (_, by1) = map(xt0, yt1);
    c.line_paper((bx, by0), (bx, by1), Style::THIN.widened(0.35));
    c.text_paper(((ax0 + ax1) / 2.0, height - 3.0), xlabel, 3.0, Anchor::Middle, "#000");
    c.text_upward((5.0, height / 2.0), ylabel, 3.5);
    for (k, s) in series.iter().enumerate() {
        let pts = mapped_path(s.points, map);
        c.path_paper(
            None,
            &pts,
            Style {
                width: 0.45,
                color: s.color,
                dash: None,
                fill: None,
            },
        );
        if series.len() > 1 || !s.name.is_empty() {
            let ly = 14.0 + 4.5 * k as f64;
            // the legend's column as far right as its longest name allows
            let longest = series.iter().map(|s| shown_len(s.name)).max().unwrap_or(0);
            let lx = (width - 2.0 - text_width(2.8, longest)).min(width - 40.0);
            c.line_paper(
                (lx - 8.0, ly - 1.0),
                (lx - 2.0, ly - 1.0),
                Style {
                    width: 0.6,
                    color: s.color,
                    dash: None,
                    fill: None,
                },
            );
            // the legend in the course's notation (R_{30x} is R₃₀ₓ)
            c.rich_paper((lx, ly), s.name, 2.8, Anchor::Start, "#000");
        }
    }
    for (k, imp) in impulses.iter().enumerate() {
        if !(imp.x.is_finite() && imp.weight.is_finite()) || imp.weight == 0.0 {
            continue;
        }
        let (xp, y0) = map(imp.x, 0.0f64.clamp(yt0, yt1));
        let yend = if imp.weight > 0.0 { map(imp.x, yt1).1 } else { map(imp.x, yt0).1 };
        c.arrow_paper((xp, y0), (xp, yend), Style::THIN.colored("#6a1b9a").widened(0.35), 2.0);
        // labels alternate sides and heights so neighbours do not collide
        let dy = if imp.weight > 0.0 {
            3.0 + 3.2 * (k % 3) as f64
        } else {
            -1.0 - 3.2 * (k % 3) as f64
        };
        c.text_paper((xp + 1.0, yend + dy), &imp.label, 2.2, Anchor::Start, "#6a1b9a");
    }
    c.finish()
}

/// Data points mapped onto paper for [`Canvas::path_paper`]: a point that is
/// not finite becomes the pen-up mark `(NaN, NaN)`, so the path breaks there.
///
/// ```
/// let p = tmm_report::svg::mapped_path(&[(1.0, 2.0), (f64::NAN, 0.0)], |x, y| (2.0 * x, y));
/// assert_eq!(p[0], (2.0, 2.0));
/// assert!(p[1].0.is_nan() && p[1].1.is_nan());
/// ```
pub fn mapped_path(pts: &[(f64, f64)], map: impl Fn(f64, f64) -> (f64, f64)) -> Vec<(f64, f64)> {
    pts.iter()
        .map(|&(x, y)| {
            if x.is_finite() && y.is_finite() {
                map(x, y)
            } else {
                (f64::NAN, f64::NAN)
            }
        })
        .collect()
}

/// Round tick marks covering `[lo, hi]` with about `n` steps: (first, last,
/// step), the step being 1, 2 or 5 × 10ⁿ.
///
/// ```
/// let (a, b, s) = tmm_report::svg::nice_ticks(0.0, 9.3, 5);
/// assert_eq!((a, b, s), (0.0, 10.0, 2.0));
/// ```
pub fn nice_ticks(lo: f64, hi: f64, n: usize) -> (f64, f64, f64) {
    let t = Ticks::new(lo, hi, n);
    (t.value(t.first), t.value(t.last), t.step())
}

/// Tick marks at whole multiples of a 1-2-5 step: the tick with index `i`
/// stands at `i·k·10^e`, so values are never accumulated and every label is
/// printed exactly from integers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ticks {
    /// Index of the first tick.
    pub first: i64,
    /// Index of the last tick.
    pub last: i64,
    /// The step's leading digit: 1, 2 or 5.
    pub k: i64,
    /// The step's power of ten.
    pub e: i32,
}

impl Ticks {
    /// About `n` steps covering `[lo, hi]`.
    ///
    /// ```
    /// let t = tmm_report::svg::Ticks::new(0.0, 7.5, 3);
    /// assert_eq!(t.step(), 2.0);
    /// let t = tmm_report::svg::Ticks::new(-0.3, 0.8, 5);
    /// assert_eq!((t.label(t.first), t.label(t.last), t.step()), ("-0.4".to_string(), "0.8".to_string(), 0.2));
    /// ```
    pub fn new(lo: f64, hi: f64, n: usize) -> Self {
        let (lo, hi) = if lo <= hi { (lo, hi) } else { (hi, lo) };
        let span = if (hi - lo).is_finite() && hi - lo > 0.0 {
            hi - lo
        } else {
            lo.abs().max(1.0)
        };
        let raw = span / n.max(1) as f64;
        let mut e = raw.log10().floor() as i32;
        let norm = raw / 10f64.powi(e);
        // the 1-2-5 step nearest to the raw one on a log scale
        let k = if norm < 2f64.sqrt() {
            1
        } else if norm < 10f64.sqrt() {
            2
        } else if norm < 50f64.sqrt() {
            5
        } else {
            e += 1;
            1
        };
        let step = k as f64 * 10f64.powi(e);
        let first = (lo / step + 1e-9).floor() as i64;
        let last = (hi / step - 1e-9).ceil() as i64;
        Ticks { first, last, k, e }
    }

    /// The step between ticks.
    pub fn step(&self) -> f64 {
        self.k as f64 * 10f64.powi(self.e)
    }

    /// The value of tick `i`.
    pub fn value(&self, i: i64) -> f64 {
        (i * self.k) as f64 * 10f64.powi(self.e)
    }

    /// The label of tick `i` as a drawing prints it in `lang`: the decimal
    /// comma of ru/uk and the minus sign − (U+2212, GOST 2.304's sign, not
    /// the hyphen-minus of [`Ticks::label`]).
    ///
    /// ```
    /// use tmm_report::{project::Language, svg::Ticks};
    /// let t = Ticks::new(-0.6, 1.6, 8);
    /// let all: Vec<String> = (t.first..=t.last).map(|i| t.printed(i, Language::Ru)).collect();
    /// assert!(all.contains(&"\u{2212}0,2".to_string()) && all.contains(&"1,4".to_string()), "{all:?}");
    /// assert!(all.iter().all(|l| !l.contains('-')));
    /// ```
    pub fn printed(&self, i: i64, lang: crate::project::Language) -> String {
        comma(&self.label(i), lang).replacen('-', "\u{2212}", 1)
    }

    /// The label of tick `i`, exact: `2.5`, `0.75`, `-40`, `1.2e6`.
    pub fn label(&self, i: i64) -> String {
        let n = i * self.k;
        if n == 0 {
            return "0".into();
        }
        let digits = n.unsigned_abs().to_string();
        let sign = if n < 0 { "-" } else { "" };
        // the value is digits × 10^e; its decimal exponent:
        let exp10 = self.e + digits.len() as i32 - 1;
        if !(-4..6).contains(&exp10) {
            let (head, tail) = digits.split_at(1);
            let tail = tail.trim_end_matches('0');
            let dot = if tail.is_empty() { "" } else { "." };
            return format!("{sign}{head}{dot}{tail}e{exp10}");
        }
        if self.e >= 0 {
            format!("{sign}{digits}{}", "0".repeat(self.e as usize))
        } else {
            let dec = (-self.e) as usize;
            let padded = format!("{digits:0>width$}", width = dec + 1);
            let (int, frac) = padded.split_at(padded.len() - dec);
            let frac = frac.trim_end_matches('0');
            if frac.is_empty() {
                format!("{sign}{int}")
            } else {
                format!("{sign}{int}.{frac}")
            }
        }
    }
}
