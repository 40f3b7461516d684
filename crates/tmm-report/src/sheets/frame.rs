//! The sheet's frame (рамка, GOST 2.301 and 2.104): the outer trimming
//! edge of the format and the inner frame in the main line, 20 mm from the
//! left (binding) edge and 5 mm from the other three; and the marks both
//! the frame and the title block are drawn with, written once as SVG and
//! read back into DXF by the same converter as the drawings.

use std::fmt::Write as _;

use crate::project::SheetFormat;
use crate::sheets::layout::Rect;
use crate::svg::escape;

/// The binding margin on the left, mm (GOST 2.104, 4.1).
pub const LEFT_MM: f64 = 20.0;
/// The margin on the top, right and bottom, mm.
pub const EDGE_MM: f64 = 5.0;
/// The main (thick) line of the frame and the title block, mm (GOST 2.303:
/// s = 0.5 … 1.4 mm).
pub const MAIN_LINE_MM: f64 = 0.7;
/// The thin line, mm (s/3 … s/2).
pub const THIN_LINE_MM: f64 = 0.25;
/// The fonts of the sheet's lettering, the GOST 2.304 faces first (the open
/// `osifont`, Debian's `fonts-osifont`, has the whole Cyrillic of ru and uk),
/// then fallbacks every viewer has. None is embedded in tmm: osifont's font
/// exception covers documents, not a program that carries it.
pub const FONTS: &str = "'GOST type A', ISOCPEUR, osifont, 'DejaVu Sans', Arial, sans-serif";

/// The inner frame of a sheet of `format`, landscape.
///
/// ```
/// use tmm_report::{project::SheetFormat, sheets::frame::inner_frame};
/// let f = inner_frame(SheetFormat::A1);
/// assert_eq!((f.x, f.y, f.right(), f.bottom()), (20.0, 5.0, 836.0, 589.0));
/// ```
pub fn inner_frame(format: SheetFormat) -> Rect {
    let (w, h) = format.size_mm();
    Rect {
        x: LEFT_MM,
        y: EDGE_MM,
        w: w - LEFT_MM - EDGE_MM,
        h: h - 2.0 * EDGE_MM,
    }
}

/// Where a text sits on its point.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Align {
    /// The point is the start of the baseline.
    Start,
    /// The point is the middle of the baseline.
    Middle,
}

/// One mark of the frame or the title block.
#[derive(Debug, Clone, PartialEq)]
pub enum Mark {
    /// A line, main (`thick`) or thin.
    Line {
        /// From (mm, y down).
        a: (f64, f64),
        /// To.
        b: (f64, f64),
        /// The main line.
        thick: bool,
    },
    /// A text on its baseline; `squeeze` is the width it must fit in
    /// (the SVG is told to compress it there when it is wider).
    Text {
        /// The point (mm, y down).
        at: (f64, f64),
        /// The font size, mm.
        size: f64,
        /// How the text sits on the point.
        align: Align,
        /// The words.
        text: String,
        /// The width the text must fit in, if the estimate says it does not.
        squeeze: Option<f64>,
        /// Turned by 180° about the middle of its box (GOST 2.104, graph 26:
        /// the designation upside down in the top-left corner).
        turned: bool,
    },
}

/// The estimated width of `text` at font size `size`, mm: 0.6 em per
/// character (a sans face's average with capitals and digits).
pub fn text_width(text: &str, size: f64) -> f64 {
    0.6 * size * text.chars().count() as f64
}

/// A text mark fitted into `width` mm: the largest of the GOST 2.304 sizes
/// not above `max` that fits, else the smallest allowed (2.5 mm) squeezed.
pub fn fitted(at: (f64, f64), max: f64, align: Align, text: &str, width: f64) -> Mark {
    let size = [14.0, 10.0, 7.0, 5.0, 3.5, 2.5]
        .into_iter()
        .filter(|&s| s <= max + 1e-9)
        .find(|&s| text_width(text, s) <= width)
        .unwrap_or(2.5_f64.min(max));
    let squeeze = (text_width(text, size) > width).then_some(width);
    Mark::Text {
        at,
        size,
        align,
        text: text.to_string(),
        squeeze,
        turned: false,
    }
}

/// The frame's marks: the inner frame in the main line (the trimming edge
/// is the sheet's own border, drawn thin).
pub fn frame_marks(format: SheetFormat) -> Vec<Mark> {
    let (w, h) = format.size_mm();
    let f = inner_frame(format);
    let mut out = Vec::new();
    let mut rect = |r: Rect, thick: bool| {
        let c = [(r.x, r.y), (r.right(), r.y), (r.right(), r.bottom()), (r.x, r.bottom())];
        for i in 0..4 {
            out.push(Mark::Line {
                a: c[i],
                b: c[(i + 1) % 4],
                thick,
            });
        }
    };
    rect(Rect { x: 0.0, y: 0.0, w, h }, false);
    rect(f, true);
    out
}

/// The width of graph 26, mm (GOST 2.104-2006, 4.1 and form 1: the
/// additional graph in the top-left corner of the frame, 70 × 14 mm).
pub const GRAPH_26_W_MM: f64 = 70.0;
/// The height of graph 26, mm.
pub const GRAPH_26_H_MM: f64 = 14.0;

/// Where graph 26 goes: against the top-left corner of the inner frame
/// `frame`, its long side along the top edge (the title block lies along the
/// long side of a landscape sheet, so the designation in it is turned by
/// 180°, GOST 2.104-2006, 4.1).
///
/// ```
/// use tmm_report::{project::SheetFormat, sheets::frame::{graph_26_place, inner_frame}};
/// let g = graph_26_place(inner_frame(SheetFormat::A1));
/// assert_eq!((g.x, g.y, g.w, g.h), (20.0, 5.0, 70.0, 14.0));
/// ```
pub fn graph_26_place(frame: Rect) -> Rect {
    Rect {
        x: frame.x,
        y: frame.y,
        w: GRAPH_26_W_MM,
        h: GRAPH_26_H_MM,
    }
}

/// Graph 26's marks: its right and bottom sides in the main line (the other
/// two are the frame's) and the document's `designation` turned by 180°,
/// centred in the box, at the largest GOST 2.304 size up to 7 mm (the
/// title block's designation size) that fits the box less 2 mm at each end.
/// An empty designation leaves the box empty.
///
/// ```
/// use tmm_report::sheets::{frame::{graph_26_marks, Mark}, layout::Rect};
/// let m = graph_26_marks(Rect { x: 20.0, y: 5.0, w: 70.0, h: 14.0 }, "ТММ.КП.017.00.000");
/// assert!(m.iter().any(|m| matches!(m, Mark::Text { turned: true, .. })));
/// ```
pub fn graph_26_marks(at: Rect, designation: &str) -> Vec<Mark> {
    let mut out = vec![
        Mark::Line {
            a: (at.right(), at.y),
            b: (at.right(), at.bottom()),
            thick: true,
        },
        Mark::Line {
            a: (at.x, at.bottom()),
            b: (at.right(), at.bottom()),
            thick: true,
        },
    ];
    if !designation.trim().is_empty() {
        let (cx, cy) = (at.x + 0.5 * at.w, at.y + 0.5 * at.h);
        if let Mark::Text { size, .. } = fitted((0.0, 0.0), 7.0, Align::Middle, designation, at.w - 4.0) {
            let mut m = fitted((cx, cy + 0.35 * size), 7.0, Align::Middle, designation, at.w - 4.0);
            if let Mark::Text { turned, .. } = &mut m {
                *turned = true;
            }
            out.push(m);
        }
    }
    out
}

/// The marks as SVG elements (mm, y down).
pub fn marks_svg(marks: &[Mark]) -> String {
    let mut s = String::new();
    for m in marks {
        match m {
            Mark::Line { a, b, thick } => {
                let _ = writeln!(
                    s,
                    "<line x1=\"{:.2}\" y1=\"{:.2}\" x2=\"{:.2}\" y2=\"{:.2}\" stroke=\"#000000\" stroke-width=\"{}\" stroke-linecap=\"square\"/>",
                    a.0,
                    a.1,
                    b.0,
                    b.1,
                    if *thick { MAIN_LINE_MM } else { THIN_LINE_MM }
                );
            }
            Mark::Text {
                at,
                size,
                align,
                text,
                squeeze,
                turned,
            } => {
                let anchor = match align {
                    Align::Start => "start",
                    Align::Middle => "middle",
                };
                // a text too long for its place is narrowed by a scale (not every
                // viewer honours textLength)
                let k = squeeze.map_or(1.0, |w| (w / text_width(text, *size)).min(1.0));
                // graph 26 is upside down: the text turned about the middle of
                // its box (the baseline lies 0.35 of the size below it)
                let turn = if *turned {
                    format!("rotate(180 {:.2} {:.2})", at.0, at.1 - 0.35 * size)
                } else {
                    String::new()
                };
                let (x, y, tr) = if k < 1.0 {
                    (
                        0.0,
                        0.0,
                        format!(
                            " transform=\"{turn}{}translate({:.2} {:.2}) scale({k:.4} 1)\"",
                            if turn.is_empty() { "" } else { " " },
                            at.0,
                            at.1
                        ),
                    )
                } else if *turned {
                    (at.0, at.1, format!(" transform=\"{turn}\""))
                } else {
                    (at.0, at.1, String::new())
                };
                let _ = writeln!(
                    s,
                    "<text x=\"{x:.2}\" y=\"{y:.2}\"{tr} font-size=\"{size}\" font-family=\"{FONTS}\" font-style=\"italic\" text-anchor=\"{anchor}\" fill=\"#000000\">{}</text>",
                    escape(text)
                );
            }
        }
    }
    s
}
