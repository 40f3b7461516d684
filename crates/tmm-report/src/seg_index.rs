//! The drawn segments of a drawing bucketed by paper cells (индекс
//! отрезков), so that a label's placer counts the lines its box would cut
//! by looking at the segments near the box instead of every segment drawn.
//!
//! A segment is listed in every cell its bounding box covers (coordinates
//! clamped to the paper, so pieces off the paper go to the border cells);
//! a box asks the cells its own bounding box covers. Two boxes that overlap
//! share a cell (clamping is monotone), so every segment that can cut the
//! box is looked at; a segment listed in several cells the box covers is
//! counted only in the first cell of the two ranges' overlap. The count is
//! therefore exactly that of a scan over all segments. Segments with a
//! non-finite end or a very large box are kept aside and always looked at.

use crate::line_grid::Segment;

/// The side of a cell, mm.
const CELL_MM: f64 = 8.0;

/// A segment covering more cells than this is kept in the always-checked list.
const MAX_CELLS: usize = 64;

/// Segments by cell; see the module's description.
#[derive(Debug, Clone)]
pub struct SegIndex {
    nx: usize,
    ny: usize,
    /// Per cell, the indices of the segments whose box covers it.
    cells: Vec<Vec<u32>>,
    /// Per segment, its first cell `(i0, j0)` (unused for the aside ones).
    first: Vec<(u32, u32)>,
    /// Segments looked at by every query.
    aside: Vec<u32>,
    segs: Vec<Segment>,
}

impl SegIndex {
    /// An empty index over a paper of `width × height` mm.
    pub fn new(width: f64, height: f64) -> Self {
        let n = |v: f64| {
            if v.is_finite() && v > 0.0 {
                ((v / CELL_MM).ceil() as usize).clamp(1, 4096)
            } else {
                1
            }
        };
        let (nx, ny) = (n(width), n(height));
        SegIndex {
            nx,
            ny,
            cells: vec![Vec::new(); nx * ny],
            first: Vec::new(),
            aside: Vec::new(),
            segs: Vec::new(),
        }
    }

    /// The cell range `(i0, i1, j0, j1)` covered by a box, clamped to the paper.
    fn range(&self, x0: f64, y0: f64, x1: f64, y1: f64) -> (usize, usize, usize, usize) {
        let c = |v: f64, n: usize| ((v / CELL_MM).floor().max(0.0) as usize).min(n - 1);
        (c(x0, self.nx), c(x1, self.nx), c(y0, self.ny), c(y1, self.ny))
    }

    /// Add the segment `a`–`b` (paper mm, y down).
    pub fn push(&mut self, s: Segment) {
        let k = self.segs.len() as u32;
        self.segs.push(s);
        let ((ax, ay), (bx, by)) = s;
        if !(ax.is_finite() && ay.is_finite() && bx.is_finite() && by.is_finite()) {
            self.first.push((0, 0));
            self.aside.push(k);
            return;
        }
        let (i0, i1, j0, j1) = self.range(ax.min(bx), ay.min(by), ax.max(bx), ay.max(by));
        self.first.push((i0 as u32, j0 as u32));
        if (i1 - i0 + 1) * (j1 - j0 + 1) > MAX_CELLS {
            self.aside.push(k);
            return;
        }
        for j in j0..=j1 {
            for i in i0..=i1 {
                self.cells[j * self.nx + i].push(k);
            }
        }
    }

    /// Every segment added, in order.
    pub fn segments(&self) -> &[Segment] {
        &self.segs
    }

    /// How many segments meet the closed box `bbox = (x0, y0, x1, y1)` by
    /// `cut`: the same number as `segments().iter().filter(|s| cut(**s)).count()`
    /// for any `cut` that is false for a segment whose box misses `bbox`.
    ///
    /// ```
    /// use tmm_report::{labels::Rect, seg_index::SegIndex};
    /// let mut ix = SegIndex::new(100.0, 100.0);
    /// ix.push(((0.0, 50.0), (100.0, 50.0))); // across the paper
    /// ix.push(((10.0, 10.0), (12.0, 12.0))); // short, far away
    /// ix.push(((-1e6, 0.0), (1e6, 100.0))); // mostly off the paper
    /// let r = Rect { x0: 40.0, y0: 45.0, x1: 60.0, y1: 55.0 };
    /// let count = |r: Rect| ix.count((r.x0, r.y0, r.x1, r.y1), |s| r.cuts(s.0, s.1));
    /// assert_eq!(count(r), 2);
    /// assert_eq!(count(Rect { x0: 9.0, y0: 9.0, x1: 11.0, y1: 11.0 }), 1);
    /// ```
    pub fn count(&self, bbox: (f64, f64, f64, f64), cut: impl Fn(Segment) -> bool) -> usize {
        let (x0, y0, x1, y1) = bbox;
        let cut = |k: u32| cut(self.segs[k as usize]);
        let mut n = self.aside.iter().filter(|&&k| cut(k)).count();
        if !(x0.is_finite() && y0.is_finite() && x1.is_finite() && y1.is_finite()) {
            // no cell to ask: look at everything not counted yet
            let aside = |k: u32| self.aside.contains(&k);
            return n + (0..self.segs.len() as u32).filter(|&k| !aside(k) && cut(k)).count();
        }
        let (i0, i1, j0, j1) = self.range(x0.min(x1), y0.min(y1), x0.max(x1), y0.max(y1));
        for j in j0..=j1 {
            for i in i0..=i1 {
                for &k in &self.cells[j * self.nx + i] {
                    // count a segment in the first cell shared by both ranges only
                    let (si, sj) = self.first[k as usize];
                    if i == i0.max(si as usize) && j == j0.max(sj as usize) && cut(k) {
                        n += 1;
                    }
                }
            }
        }
        n
    }
}
