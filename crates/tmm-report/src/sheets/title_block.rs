//! The main title block of a drawing (основная надпись, GOST 2.104-2006,
//! form 1): 185 × 55 mm in the bottom-right corner against the frame, the
//! place the packing keeps free; `tmm_draw::eskd` draws it.
//!
//! The grid, from the block's top-left corner (mm, y down), in eleven rows
//! of 5 mm:
//!
//! * left part, 65 mm: columns 7 (Изм.), 10 (Лист), 23 (№ докум.),
//!   15 (Подп.), 10 (Дата); four rows of changes, the captions' row at
//!   20 … 25, then the rows Разраб., Пров., Т.контр., a free row, Н.контр.,
//!   Утв. (the first two columns merged into one of 17 mm);
//! * right part, 120 mm: the designation (графа 2) 120 × 15 on top; below
//!   it the name (графа 1) 70 × 25 and, on its right, the captions Лит.
//!   (3 × 5), Масса (17), Масштаб (18), their values 15 mm high, and the
//!   row Лист (20) / Листов (30); at the bottom the material (графа 3)
//!   70 × 15 and the organisation (графа 9) 50 × 15.

use crate::sheets::layout::Rect;

/// The block's width, mm.
pub const WIDTH_MM: f64 = 185.0;
/// The block's height, mm.
pub const HEIGHT_MM: f64 = 55.0;

/// Where the block goes inside the frame `frame`: its bottom-right corner
/// on the frame's.
pub fn place(frame: Rect) -> Rect {
    Rect {
        x: frame.right() - WIDTH_MM,
        y: frame.bottom() - HEIGHT_MM,
        w: WIDTH_MM,
        h: HEIGHT_MM,
    }
}
