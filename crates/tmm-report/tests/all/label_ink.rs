//! Labels against the lines of a drawing by their printed ink: each text's
//! box from osifont's advances and glyph bounds as printed
//! ([`tmm_draw::face::ink`], the 75° slant, descenders and capitals
//! included), scaled to the letter size the SVG writes, and every straight
//! piece the drawing strokes (lines, polylines, polygons, paths, circles,
//! arrowheads), all read from the drawing's elements, not from the code
//! that placed the labels; the distances are `tmm_testkit::plane`'s,
//! written apart from the placement code.

use tmm_report::picture::{Element, PathData, Picture, em, index_em};
use tmm_testkit::plane::Rect;

/// A text's printed ink on the paper, mm, y down.
#[derive(Debug, Clone)]
pub struct InkBox {
    pub x0: f64,
    pub y0: f64,
    pub x1: f64,
    pub y1: f64,
    pub text: String,
}

impl InkBox {
    /// The box without its words.
    pub fn rect(&self) -> Rect {
        Rect::from([self.x0, self.y0, self.x1, self.y1])
    }

    /// The gap between two boxes (0 when they touch or overlap).
    pub fn gap(&self, o: &InkBox) -> f64 {
        self.rect().gap(&o.rect())
    }

    /// The distance from the box to the segment `a`–`b` (0 when it meets it).
    pub fn distance(&self, a: (f64, f64), b: (f64, f64)) -> f64 {
        self.rect().segment_distance(a, b)
    }
}

/// The ink of `plain` at the em size `em_mm` (mm), about the start of its
/// baseline: (left, right, above, below), from osifont at 2.5 mm scaled.
fn ink_at(plain: &str, em_mm: f64) -> (f64, f64, f64, f64) {
    let k = em_mm * tmm_report::labels::CAP_PER_EM / 2.5;
    let i = tmm_draw::face::ink(plain, tmm_draw::TextHeight::H2_5);
    (k * i.left, k * i.right.max(i.width), k * i.above, k * i.below)
}

/// The printed ink box of every text of `pic` (rotated texts turned).
pub fn texts(pic: &Picture) -> Vec<InkBox> {
    let mut out = Vec::new();
    for e in &pic.elements {
        match e {
            Element::Text {
                at,
                text,
                size,
                anchor,
                rich,
                ..
            } => {
                let parts = if *rich {
                    tmm_report::labels::parts(text)
                } else {
                    vec![(text.clone(), 0)]
                };
                out.push(boxed(*at, &parts, em(*size), *anchor));
            }
            Element::Label { c, text, size, start, .. } => {
                let e = em(*size);
                let at = (c.0, c.1 + 0.35 * e);
                let anchor = if *start {
                    tmm_report::svg::Anchor::Start
                } else {
                    tmm_report::svg::Anchor::Middle
                };
                out.push(boxed(at, &tmm_report::labels::parts(text), e, anchor));
            }
            Element::Upward { at, text, size } => {
                // turned to read upwards about its baseline's middle
                let b = boxed(*at, &[(text.clone(), 0)], em(*size), tmm_report::svg::Anchor::Middle);
                let (dx0, dx1) = (b.x0 - at.0, b.x1 - at.0);
                let (dy0, dy1) = (b.y0 - at.1, b.y1 - at.1);
                out.push(InkBox {
                    x0: at.0 + dy0,
                    x1: at.0 + dy1,
                    y0: at.1 - dx1,
                    y1: at.1 - dx0,
                    text: b.text,
                });
            }
            _ => {}
        }
    }
    out
}

/// The box of a text of `parts` (text, index level: 1 superscript, −1
/// subscript) at em `e`, its baseline at `at` with `anchor`.
fn boxed(at: (f64, f64), parts: &[(String, i8)], e: f64, anchor: tmm_report::svg::Anchor) -> InkBox {
    let plain: String = parts.iter().map(|p| p.0.as_str()).collect();
    let ie = index_em(e);
    let (left, right, mut above, mut below) = ink_at(&plain, e.max(ie));
    for (t, lvl) in parts {
        let (_, _, a, b) = ink_at(t, if *lvl == 0 { e } else { ie });
        // an index is shifted 0.35 em up or down (the Label's tspans;
        // the rich text's baseline-shift is within that)
        match lvl.signum() {
            1 => above = above.max(a + 0.5 * e),
            -1 => below = below.max(b + 0.35 * e),
            _ => {}
        }
    }
    let width = right;
    let x = match anchor {
        tmm_report::svg::Anchor::Start => at.0,
        tmm_report::svg::Anchor::Middle => at.0 - 0.5 * width,
        tmm_report::svg::Anchor::End => at.0 - width,
    };
    InkBox {
        x0: x + left.min(0.0),
        x1: x + right,
        y0: at.1 - above,
        y1: at.1 + below,
        text: plain,
    }
}

/// A stroked piece: its ends (paper mm) and half its stroke's width.
pub type Seg = ((f64, f64), (f64, f64), f64);

/// Every straight piece `pic` strokes, paper mm (circles as 72-gons),
/// with half its stroke's width.
pub fn segments(pic: &Picture) -> Vec<Seg> {
    let mut out = Vec::new();
    let ring = |c: (f64, f64), r: f64, w: f64, out: &mut Vec<Seg>| {
        let n = 72;
        let p = |i: usize| {
            let a = std::f64::consts::TAU * i as f64 / n as f64;
            (c.0 + r * a.cos(), c.1 + r * a.sin())
        };
        for i in 0..n {
            out.push((p(i), p(i + 1), 0.5 * w));
        }
    };
    for e in &pic.elements {
        match e {
            Element::Line { a, b, style, .. } | Element::Classed { a, b, style, .. } => out.push((*a, *b, 0.5 * style.width)),
            // a filled area drawn without a stroke has no line
            Element::Poly { points, closed, style } if style.width > 0.0 && !style.color.eq_ignore_ascii_case("#ffffff") => {
                let h = 0.5 * style.width;
                for w in points.windows(2) {
                    out.push((w[0], w[1], h));
                }
                if *closed && points.len() > 2 {
                    out.push((points[points.len() - 1], points[0], h));
                }
            }
            Element::Path { data, style, .. } => {
                let h = 0.5 * style.width;
                match data {
                    PathData::Runs(runs) => {
                        for r in runs {
                            for w in r.windows(2) {
                                out.push((w[0], w[1], h));
                            }
                        }
                    }
                    PathData::Segments(s) => out.extend(s.iter().map(|(a, b)| (*a, *b, h))),
                }
            }
            Element::Circle { c, r, style } | Element::Marker { c, r, style, .. } => ring(*c, *r, style.width, &mut out),
            Element::Dot { c, r, .. } => ring(*c, *r, 0.25, &mut out),
            Element::Ground { triangle, hatch } => {
                for i in 0..3 {
                    out.push((triangle[i], triangle[(i + 1) % 3], 0.175));
                }
                out.extend(hatch.iter().map(|(a, b)| (*a, *b, 0.125)));
            }
            Element::Head { points, .. } => {
                for i in 0..3 {
                    out.push((points[i], points[(i + 1) % 3], 0.0));
                }
            }
            _ => {}
        }
    }
    out
}

/// The faults of the texts of `pic` whose words `pick` accepts: one within
/// `clear` mm of a line, or of another text's ink (any text, picked or not).
pub fn faults(pic: &Picture, clear: f64, pick: impl Fn(&str) -> bool) -> Vec<String> {
    let segs = segments(pic);
    let all = texts(pic);
    let mut out = Vec::new();
    for (i, t) in all.iter().enumerate() {
        if !pick(&t.text) {
            continue;
        }
        if let Some((a, b, _)) = segs.iter().find(|(a, b, w)| t.distance(*a, *b) - w < clear - 1e-9) {
            out.push(format!(
                "«{}» ({:.2}, {:.2})–({:.2}, {:.2}) within {clear} mm of the line ({:.2}, {:.2})–({:.2}, {:.2})",
                t.text, t.x0, t.y0, t.x1, t.y1, a.0, a.1, b.0, b.1
            ));
        }
        for (j, o) in all.iter().enumerate() {
            if j != i && (j > i || !pick(&o.text)) && t.gap(o) < clear - 1e-9 {
                out.push(format!("«{}» within {clear} mm of «{}» ({:.2} mm)", t.text, o.text, t.gap(o)));
            }
        }
    }
    out
}
