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
/// The fonts of the sheet's lettering, the GOST 2.304 faces first, then
/// fallbacks every viewer has. The open `osifont` is not named: it lacks
/// «ё» and «э», which the Russian titles need.
pub const FONTS: &str = "'GOST type A', ISOCPEUR, 'DejaVu Sans', Arial, sans-serif";

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
            } => {
                let anchor = match align {
                    Align::Start => "start",
                    Align::Middle => "middle",
                };
                // a text too long for its place is narrowed by a scale (not every
                // viewer honours textLength)
                let k = squeeze.map_or(1.0, |w| (w / text_width(text, *size)).min(1.0));
                let (x, y, tr) = if k < 1.0 {
                    (
                        0.0,
                        0.0,
                        format!(" transform=\"translate({:.2} {:.2}) scale({k:.4} 1)\"", at.0, at.1),
                    )
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
