//! The sheet's frame (рамка, GOST 2.301 and 2.104) as the packing sees it:
//! the inner frame 20 mm from the left (binding) edge and 5 mm from the
//! other three, and graph 26's box in its top-left corner. The frame, graph
//! 26 and the title block are drawn by `tmm_draw::eskd`.

use crate::project::SheetFormat;
use crate::sheets::layout::Rect;

/// The binding margin on the left, mm (GOST 2.104, 4.1).
pub const LEFT_MM: f64 = 20.0;
/// The margin on the top, right and bottom, mm.
pub const EDGE_MM: f64 = 5.0;
/// The fonts of the drawings' captions on a sheet: the lettering's list
/// ([`tmm_draw::svg::FONT_FAMILY`], osifont first; Э э Ё ё from tmm's
/// supplement, [`tmm_draw::svg::lettering`]).
pub const FONTS: &str = tmm_draw::svg::FONT_FAMILY;

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

/// The estimated width of `text` at font size `size`, mm: 0.6 em per
/// character (a sans face's average with capitals and digits).
pub fn text_width(text: &str, size: f64) -> f64 {
    0.6 * size * text.chars().count() as f64
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
