//! The drawn lines of a drawing as a grid of occupied cells (растр линий),
//! for the labels to keep off them: a label whose box meets an occupied
//! cell would touch a line.
//!
//! A segment marks every cell it passes through (sampled at a quarter of
//! a cell, so no crossed cell is missed by more than that); a box is
//! tested against the cells it overlaps grown by one cell on each side, so
//! a box that does not hit the grid keeps at least a little off every line
//! (between nothing and one cell: conservative, never optimistic).

use crate::labels::Rect;

/// A straight piece on paper: its two ends (mm, y down).
pub type Segment = ((f64, f64), (f64, f64));

/// The side of a cell, mm.
pub const CELL_MM: f64 = 0.25;

/// The occupied cells of a paper `width × height` mm.
#[derive(Debug, Clone)]
pub struct LineGrid {
    nx: usize,
    ny: usize,
    on: Vec<bool>,
}

impl LineGrid {
    /// An empty grid over a paper of `width × height` mm.
    pub fn new(width: f64, height: f64) -> Self {
        let n = |v: f64| {
            if v.is_finite() && v > 0.0 {
                (v / CELL_MM).ceil() as usize + 1
            } else {
                1
            }
        };
        let (nx, ny) = (n(width), n(height));
        LineGrid {
            nx,
            ny,
            on: vec![false; nx * ny],
        }
    }

    fn cell(&self, x: f64, y: f64) -> Option<usize> {
        if !(x.is_finite() && y.is_finite()) || x < 0.0 || y < 0.0 {
            return None;
        }
        let (i, j) = ((x / CELL_MM) as usize, (y / CELL_MM) as usize);
        (i < self.nx && j < self.ny).then_some(j * self.nx + i)
    }

    /// Mark the segment `a`–`b` (paper mm, y down).
    ///
    /// ```
    /// use tmm_report::{labels::Rect, line_grid::LineGrid};
    /// let mut g = LineGrid::new(50.0, 50.0);
    /// g.add((0.0, 10.0), (50.0, 10.0));
    /// assert!(g.hits(&Rect { x0: 20.0, y0: 8.0, x1: 25.0, y1: 12.0 }));
    /// assert!(!g.hits(&Rect { x0: 20.0, y0: 12.0, x1: 25.0, y1: 16.0 }));
    /// ```
    pub fn add(&mut self, a: (f64, f64), b: (f64, f64)) {
        if !(a.0.is_finite() && a.1.is_finite() && b.0.is_finite() && b.1.is_finite()) {
            return;
        }
        let len = (b.0 - a.0).hypot(b.1 - a.1);
        // a segment longer than the paper's diagonal is a fault of the caller
        let n = ((len / (0.25 * CELL_MM)).ceil() as usize).clamp(1, 4 * (self.nx + self.ny) * 4);
        for k in 0..=n {
            let t = k as f64 / n as f64;
            if let Some(c) = self.cell(a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)) {
                self.on[c] = true;
            }
        }
    }

    /// Whether the box `r` (paper mm) comes near a marked cell.
    pub fn hits(&self, r: &Rect) -> bool {
        if !(r.x0.is_finite() && r.y0.is_finite() && r.x1.is_finite() && r.y1.is_finite()) {
            return true;
        }
        let lo = |v: f64| ((v / CELL_MM).floor() - 1.0).max(0.0) as usize;
        let hi = |v: f64, n: usize| (((v / CELL_MM).floor() + 1.0).max(0.0) as usize).min(n - 1);
        let (i0, i1) = (lo(r.x0), hi(r.x1, self.nx));
        let (j0, j1) = (lo(r.y0), hi(r.y1, self.ny));
        (j0..=j1).any(|j| (i0..=i1).any(|i| self.on[j * self.nx + i]))
    }
}
