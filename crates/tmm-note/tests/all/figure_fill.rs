//! Every figure of the note fills its box (issue 22, point 8: "no
//! half-empty pages: crop each figure to its content"). For every figure
//! the composed note sets, of the default project and of every example
//! under examples/ (the textbook's included), the ink is read from the
//! figure's SVG as printed — every line, polyline, polygon, circle and
//! path by its coordinates, every text by its box as `figure_fit.rs`
//! measures it (the face's advances, the slant; rotated texts by their
//! anchor) — and:
//!
//! - the ink's box covers at least [`SHARE`] of the figure's width and of
//!   its height (the figure is cut to its content, none is a small drawing
//!   in a large sheet);
//! - no empty band across the figure's whole width is taller than
//!   [`BAND`] of its height (a title far above its drawing, a closure line
//!   far below it).
//!
//! Since a figure's box is then its ink, the checklist's page fill
//! (`checklist.rs`, which counts a figure's box as filled) measures ink.

use tmm_note::Block;
use tmm_report::run::run_task;

use tmm_testkit::examples;
use tmm_testkit::svg::{attr, num, points, view_box};

use super::figure_fit::text_boxes;
use super::fixtures::{note_figures, task};

/// The least share of the figure's width and height its ink's box covers.
const SHARE: f64 = 0.6;
/// The tallest empty band across a figure, as a share of its height.
const BAND: f64 = 0.25;

/// The boxes (x0, y0, x1, y1) of everything drawn in `svg`, the white
/// sheet under it left out.
fn ink(svg: &str) -> Vec<[f64; 4]> {
    let mut out: Vec<[f64; 4]> = text_boxes(svg).into_iter().map(|t| t.1).collect();
    let mut rest = svg;
    while let Some(i) = rest.find('<') {
        let r = &rest[i + 1..];
        let end = r.find('>').unwrap_or(r.len());
        let tag = &r[..end];
        rest = &r[end..];
        let name = tag.split_whitespace().next().unwrap_or("");
        let pts: Vec<(f64, f64)> = match name {
            "line" => match (num(tag, "x1"), num(tag, "y1"), num(tag, "x2"), num(tag, "y2")) {
                (Some(a), Some(b), Some(c), Some(d)) => vec![(a, b), (c, d)],
                _ => vec![],
            },
            "polyline" | "polygon" => points(attr(tag, "points").unwrap_or("")),
            "path" => points(attr(tag, "d").unwrap_or("")),
            "circle" => match (num(tag, "cx"), num(tag, "cy"), num(tag, "r")) {
                (Some(x), Some(y), Some(r)) => vec![(x - r, y - r), (x + r, y + r)],
                _ => vec![],
            },
            // rotated lettering (an axis' name): its anchor
            "text" if tag.contains("rotate(") => match (num(tag, "x"), num(tag, "y")) {
                (Some(x), Some(y)) => vec![(x, y)],
                _ => vec![],
            },
            _ => vec![],
        };
        if let Some(&(x, y)) = pts.first() {
            let b = pts
                .iter()
                .fold([x, y, x, y], |b, p| [b[0].min(p.0), b[1].min(p.1), b[2].max(p.0), b[3].max(p.1)]);
            out.push(b);
        }
    }
    out
}

/// How a figure fills its box: the ink's box as shares of the width and
/// the height, and the tallest empty band across it as a share of the height.
fn fill(svg: &str) -> (f64, f64, f64) {
    let v = view_box(svg).expect("a figure without its viewBox");
    let boxes = ink(svg);
    let Some(first) = boxes.first() else { return (0.0, 0.0, 1.0) };
    let b = boxes
        .iter()
        .fold(*first, |b, p| [b[0].min(p[0]), b[1].min(p[1]), b[2].max(p[2]), b[3].max(p[3])]);
    let clip = |lo: f64, hi: f64, a: f64, len: f64| (hi.min(a + len) - lo.max(a)).max(0.0) / len;
    let mut spans: Vec<(f64, f64)> = boxes.iter().map(|b| (b[1], b[3])).collect();
    spans.sort_by(|a, b| a.0.total_cmp(&b.0));
    // the empty bands: before the first span, between spans, after the last
    let (mut band, mut reach) = (spans[0].0 - v[1], spans[0].1);
    for s in &spans[1..] {
        band = band.max(s.0 - reach);
        reach = reach.max(s.1);
    }
    band = band.max(v[1] + v[3] - reach);
    (clip(b[0], b[2], v[0], v[2]), clip(b[1], b[3], v[1], v[3]), band / v[3])
}

#[test]
fn the_fill_finder_finds_what_it_must() {
    let svg = |body: &str| {
        format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100mm\" height=\"100mm\" viewBox=\"0 0 100 100\"><rect x=\"0\" y=\"0\" width=\"100\" height=\"100\" fill=\"#ffffff\"/>{body}</svg>"
        )
    };
    // a line over the middle half both ways
    let (w, h, band) = fill(&svg("<line x1=\"25\" y1=\"25\" x2=\"75\" y2=\"75\" stroke=\"#000\"/>"));
    assert!(
        (w - 0.5).abs() < 1e-9 && (h - 0.5).abs() < 1e-9 && (band - 0.25).abs() < 1e-9,
        "{w} {h} {band}"
    );
    // a path with H and V, a polygon, a circle
    let (w, h, _) = fill(&svg("<path d=\"M10,20H90V5L10,80\"/>"));
    assert!((w - 0.8).abs() < 1e-9 && (h - 0.75).abs() < 1e-9, "{w} {h}");
    let (w, h, _) = fill(&svg("<polygon points=\"0,0 100,0 50,10\"/><circle cx=\"50\" cy=\"90\" r=\"10\"/>"));
    assert!((w - 1.0).abs() < 1e-9 && (h - 1.0).abs() < 1e-9);
    // a title 60 mm above its drawing: an empty band of 0.6
    let (_, _, band) = fill(&svg(
        "<text x=\"50\" y=\"8\" font-size=\"5\" text-anchor=\"middle\">Plan</text><line x1=\"0\" y1=\"70\" x2=\"100\" y2=\"99\"/>",
    ));
    assert!(band > 0.55 && band < 0.65, "{band}");
}

/// The default project and every example under examples/.
fn names() -> Vec<String> {
    let mut out = vec!["default".to_string()];
    out.extend(examples::names());
    out
}

#[test]
fn every_note_figure_fills_its_box() {
    let mut faults = Vec::new();
    let (mut figures, mut least_w, mut least_h, mut widest_band) = (0, 1.0f64, 1.0f64, 0.0f64);
    for name in names() {
        let task = task(&name);
        let run = run_task(&task).expect("the task runs");
        let note = tmm_note::compose(&run, &task).expect("the note composes");
        for b in note_figures(&note) {
            let Block::Figure { caption, svg, .. } = b else { continue };
            let (w, h, band) = fill(svg);
            figures += 1;
            least_w = least_w.min(w);
            least_h = least_h.min(h);
            widest_band = widest_band.max(band);
            if w < SHARE || h < SHARE || band > BAND {
                faults.push(format!(
                    "{name}, \"{caption}\": ink over {:.0} % of the width, {:.0} % of the height, an empty band of {:.0} %",
                    w * 100.0,
                    h * 100.0,
                    band * 100.0
                ));
            }
        }
    }
    println!(
        "note figures: {figures}; the least ink share {:.0} % of a width, {:.0} % of a height; the tallest empty band {:.0} % of a height",
        least_w * 100.0,
        least_h * 100.0,
        widest_band * 100.0
    );
    assert!(figures > 100, "{figures} figures");
    assert!(faults.is_empty(), "{} figures not filled:\n{}", faults.len(), faults.join("\n"));
}
