//! A note figure cut to its content (обрезка рисунка по содержимому): the
//! drawings are made for a slot of a fixed size (on A4 165 mm wide and up
//! to 215 mm high), and a plan limited by the width, a flat velocity plan
//! or a force plan beside its free body fills a small part of it. On the
//! note's page ([`crate::run::note_figures`]) each drawing is cut to the
//! box of its ink plus a margin, and an empty band between the drawing and
//! its title lines (or a line under it, the polygon's closure) is closed to
//! a small gap. Nothing drawn is scaled: every element moves as a whole, the
//! drawing's own geometry by one and the same shift, so the "М 1:n" and μ
//! it prints still measure on the page (`tests/all/scales_pdf.rs`).
//!
//! The ink of a text is taken wide enough never to be cut: the advances of
//! its characters in the drawing face ([`tmm_draw::face::advance_em`]; 0.6
//! em for a character it lacks), each at the text's full size (an index is
//! smaller), the 75° slant's lean, and an index's rise and drop above and
//! below the line.

use crate::picture::{Element, P, PathData, Picture, em};
use crate::svg::{Anchor, TEXT_ASCENT, TEXT_DESCENT};

/// The margin kept round a cut figure's ink, mm.
pub const MARGIN_MM: f64 = 2.0;

/// The gap an empty band between a drawing and its title or closing lines
/// is closed to, mm (a line's height of 3.5 mm type).
pub const GAP_MM: f64 = 4.0;

/// A box on paper: x0, y0, x1, y1 (mm, y down).
pub type Extent = [f64; 4];

/// The width of a text's ink at letter size `size` (mm): the face's
/// advances, the markup of indices (`_`, `^`, braces) dropped.
fn ink_width(text: &str, size: f64) -> f64 {
    let e = em(size);
    text.chars()
        .filter(|c| !matches!(c, '_' | '^' | '{' | '}'))
        .map(|c| tmm_draw::face::advance_em(c).unwrap_or(0.6))
        .sum::<f64>()
        * e
}

/// The box of a text written at the baseline point `at`: the slant leans
/// the top right by tan 15° of the ascent and the foot left, an index rises
/// or drops by 0.4 of the size.
fn text_extent(at: P, text: &str, size: f64, anchor: Anchor) -> Extent {
    let e = em(size);
    let w = ink_width(text, size);
    let x0 = match anchor {
        Anchor::Start => at.0,
        Anchor::Middle => at.0 - 0.5 * w,
        Anchor::End => at.0 - w,
    };
    let lean = 15f64.to_radians().tan();
    let (up, down) = ((TEXT_ASCENT + 0.4) * e, (TEXT_DESCENT + 0.4) * e);
    [x0 - lean * down, at.1 - up, x0 + w + lean * up, at.1 + down]
}

/// The box of points grown by `pad`.
fn points_extent<'a>(pts: impl IntoIterator<Item = &'a P>, pad: f64) -> Option<Extent> {
    let mut b: Option<Extent> = None;
    for p in pts {
        if !(p.0.is_finite() && p.1.is_finite()) {
            continue;
        }
        b = Some(match b {
            None => [p.0, p.1, p.0, p.1],
            Some(b) => [b[0].min(p.0), b[1].min(p.1), b[2].max(p.0), b[3].max(p.1)],
        });
    }
    b.map(|b| [b[0] - pad, b[1] - pad, b[2] + pad, b[3] + pad])
}

/// The paper box an element covers, `None` for a group's mark.
///
/// ```
/// use tmm_report::{crop::extent, picture::Element, svg::Style};
/// let l = Element::Line { a: (10.0, 20.0), b: (30.0, 5.0), style: Style::THIN, round: false };
/// let b = extent(&l).unwrap();
/// assert!(b[0] < 10.0 && b[0] > 9.0 && b[3] > 20.0 && b[3] < 21.0);
/// assert!(extent(&Element::GroupClose).is_none());
/// ```
pub fn extent(e: &Element) -> Option<Extent> {
    match e {
        Element::Line { a, b, style, .. } | Element::Classed { a, b, style, .. } => points_extent([a, b], 0.5 * style.width),
        Element::Poly { points, style, .. } => points_extent(points, 0.5 * style.width),
        Element::Circle { c, r, style } | Element::Marker { c, r, style, .. } => points_extent([c], r + 0.5 * style.width),
        Element::Dot { c, r, .. } => points_extent([c], r + 0.15),
        Element::Ground { triangle, hatch } => points_extent(triangle.iter().chain(hatch.iter().flat_map(|(a, b)| [a, b])), 0.2),
        Element::Head { points, .. } => points_extent(points, 0.0),
        Element::Text {
            at, text, size, anchor, ..
        } => Some(text_extent(*at, text, *size, *anchor)),
        Element::Label { c, text, size, start, .. } => {
            // written with its baseline 0.35 of the size under `c`
            let at = (c.0, c.1 + 0.35 * em(*size));
            Some(text_extent(at, text, *size, if *start { Anchor::Start } else { Anchor::Middle }))
        }
        Element::Upward { at, text, size } => {
            // turned to read upwards: the width runs along y
            let (w, e) = (ink_width(text, *size), em(*size));
            Some([
                at.0 - (TEXT_ASCENT + 0.3) * e,
                at.1 - 0.5 * w - 0.3 * e,
                at.0 + (TEXT_DESCENT + 0.3) * e,
                at.1 + 0.5 * w + 0.3 * e,
            ])
        }
        Element::Path { data, style, .. } => match data {
            PathData::Runs(runs) => points_extent(runs.iter().flatten(), 0.5 * style.width),
            PathData::Segments(segs) => points_extent(segs.iter().flat_map(|(a, b)| [a, b]), 0.5 * style.width),
        },
        Element::GroupOpen { .. } | Element::GroupClose => None,
    }
}

/// An element moved by (dx, dy) mm.
fn shift(e: &mut Element, dx: f64, dy: f64) {
    let m = |p: &mut P| {
        p.0 += dx;
        p.1 += dy;
    };
    match e {
        Element::Line { a, b, .. } | Element::Classed { a, b, .. } => {
            m(a);
            m(b);
        }
        Element::Poly { points, .. } => points.iter_mut().for_each(m),
        Element::Circle { c, .. } | Element::Marker { c, .. } | Element::Dot { c, .. } | Element::Label { c, .. } => m(c),
        Element::Ground { triangle, hatch } => {
            triangle.iter_mut().for_each(m);
            hatch.iter_mut().for_each(|(a, b)| {
                m(a);
                m(b);
            });
        }
        Element::Head { points, .. } => points.iter_mut().for_each(m),
        Element::Text { at, .. } | Element::Upward { at, .. } => m(at),
        Element::Path { data, .. } => match data {
            PathData::Runs(runs) => runs.iter_mut().flatten().for_each(m),
            PathData::Segments(segs) => segs.iter_mut().for_each(|(a, b)| {
                m(a);
                m(b);
            }),
        },
        Element::GroupOpen { .. } | Element::GroupClose => {}
    }
}

/// The id of a group holding a legend (its sample strokes and words): on
/// the note's page it moves like lettering.
pub const LEGEND: &str = "legend";

/// For each element, whether it is lettering rather than a part of the
/// drawing: a text (a title, a scale's line, a label) or anything inside
/// a [`LEGEND`] group.
fn lettering(elements: &[Element]) -> Vec<bool> {
    let mut depth_in_legend: Option<usize> = None;
    let mut depth = 0usize;
    elements
        .iter()
        .map(|e| match e {
            Element::GroupOpen { id, .. } => {
                depth += 1;
                if depth_in_legend.is_none() && id.as_deref() == Some(LEGEND) {
                    depth_in_legend = Some(depth);
                }
                true
            }
            Element::GroupClose => {
                if depth_in_legend == Some(depth) {
                    depth_in_legend = None;
                }
                depth = depth.saturating_sub(1);
                true
            }
            Element::Text { .. } | Element::Label { .. } => true,
            _ => depth_in_legend.is_some(),
        })
        .collect()
}

/// The drawing cut to its content: every empty horizontal band wider than
/// `gap` whose one side holds lettering only (the title and scale lines
/// above a plan, the closure line under a force polygon, a legend) closed
/// to `gap`,
/// then the paper cut to the ink's box plus `margin` — never larger than
/// it was. The elements move, none is scaled, so a scale printed on the
/// drawing stays true; a root `data-origin` (a point of the drawing, mm)
/// moves with them.
///
/// ```
/// use tmm_report::{crop::cropped, picture::{Element, Picture}, svg::{Anchor, Style}};
/// let title = Element::Text { at: (50.0, 10.0), text: "Plan".into(), size: 5.0, anchor: Anchor::Middle, color: "#000".into(), rich: false };
/// let line = Element::Line { a: (20.0, 80.0), b: (60.0, 90.0), style: Style::THICK, round: false };
/// let p = cropped(Picture::new(165.0, 165.0, vec![], vec![title, line]), 2.0, 4.0);
/// // the 65 mm between the title and the line closed to 4 mm, the paper cut round them
/// assert!(p.height < 40.0 && p.width < 50.0, "{} × {}", p.width, p.height);
/// let Element::Line { a, b, .. } = &p.elements[1] else { panic!() };
/// assert!(((b.0 - a.0) - 40.0).abs() < 1e-12 && ((b.1 - a.1) - 10.0).abs() < 1e-12);
/// ```
pub fn cropped(p: Picture, margin: f64, gap: f64) -> Picture {
    let Picture {
        width,
        height,
        mut root,
        mut elements,
        ..
    } = p;
    let boxes: Vec<Option<Extent>> = elements.iter().map(extent).collect();
    let mut spans: Vec<(f64, f64, bool)> = lettering(&elements)
        .into_iter()
        .zip(&boxes)
        .filter_map(|(t, b)| b.map(|b| (b[1], b[3], t)))
        .collect();
    if spans.is_empty() {
        return Picture::new(width, height, root, elements);
    }
    spans.sort_by(|a, b| a.0.total_cmp(&b.0));
    // the empty bands (top, bottom) and whether one side is lettering only
    let mut closed: Vec<(f64, f64)> = Vec::new();
    let mut reach = spans[0].1;
    for (i, s) in spans.iter().enumerate().skip(1) {
        if s.0 - reach > gap {
            let above_text = spans[..i].iter().all(|t| t.2);
            let below_text = spans[i..].iter().all(|t| t.2);
            if above_text || below_text {
                closed.push((reach, s.0));
            }
        }
        reach = reach.max(s.1);
    }
    // each element moved up by the bands closed above it
    let lift = |y0: f64| -> f64 { closed.iter().filter(|b| b.1 <= y0 + 1e-9).map(|b| b.1 - b.0 - gap).sum() };
    let mut ink: Option<Extent> = None;
    for (e, b) in elements.iter_mut().zip(&boxes) {
        let Some(b) = b else { continue };
        let dy = lift(b[1]);
        if dy != 0.0 {
            shift(e, 0.0, -dy);
        }
        let b = [b[0], b[1] - dy, b[2], b[3] - dy];
        ink = Some(match ink {
            None => b,
            Some(k) => [k[0].min(b[0]), k[1].min(b[1]), k[2].max(b[2]), k[3].max(b[3])],
        });
    }
    let Some(k) = ink else {
        return Picture::new(width, height, root, elements);
    };
    // the new paper: the ink plus the margin, inside the old one
    let x0 = (k[0] - margin).max(0.0);
    let y0 = (k[1] - margin).max(0.0);
    let w = ((k[2] + margin).min(width) - x0).max(1.0);
    let h = ((k[3] + margin).min(height - closed.iter().map(|b| b.1 - b.0 - gap).sum::<f64>()) - y0).max(1.0);
    for e in elements.iter_mut() {
        shift(e, -x0, -y0);
    }
    for (key, v) in root.iter_mut() {
        if key == "data-origin" {
            let xy: Vec<f64> = v.split_whitespace().filter_map(|t| t.parse().ok()).collect();
            if let [x, y] = xy[..] {
                let dy = lift(y);
                *v = format!("{:.4} {:.4}", x - x0, y - dy - y0);
            }
        }
    }
    let r = |v: f64| (v * 1000.0).round() / 1000.0;
    Picture::new(r(w), r(h), root, elements)
}
