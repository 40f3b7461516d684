//! Packing the drawings of a sheet into its field (компоновка листа): the
//! maximal-rectangles method — the free space is kept as the list of the
//! largest empty rectangles, each box goes to the top-most, then left-most
//! free place it fits, and the rectangles it covers are split. Obstacles
//! (the title block) are occupied before the first box, so no box can
//! reach them; boxes never overlap one another and never leave the field.

/// An axis-aligned rectangle on the sheet, mm, y down: `(x, y)` is the
/// top-left corner.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rect {
    /// Left edge.
    pub x: f64,
    /// Top edge.
    pub y: f64,
    /// Width.
    pub w: f64,
    /// Height.
    pub h: f64,
}

impl Rect {
    /// Right edge.
    pub fn right(&self) -> f64 {
        self.x + self.w
    }
    /// Bottom edge.
    pub fn bottom(&self) -> f64 {
        self.y + self.h
    }
    /// Whether the interiors of two rectangles meet (touching edges do not).
    ///
    /// ```
    /// use tmm_report::sheets::layout::Rect;
    /// let a = Rect { x: 0.0, y: 0.0, w: 10.0, h: 10.0 };
    /// assert!(a.intersects(&Rect { x: 9.0, y: 9.0, w: 5.0, h: 5.0 }));
    /// assert!(!a.intersects(&Rect { x: 10.0, y: 0.0, w: 5.0, h: 5.0 }));
    /// ```
    pub fn intersects(&self, o: &Rect) -> bool {
        const EPS: f64 = 1e-9;
        self.x < o.right() - EPS && o.x < self.right() - EPS && self.y < o.bottom() - EPS && o.y < self.bottom() - EPS
    }
    /// Whether `o` lies inside this rectangle.
    pub fn contains(&self, o: &Rect) -> bool {
        const EPS: f64 = 1e-9;
        o.x >= self.x - EPS && o.y >= self.y - EPS && o.right() <= self.right() + EPS && o.bottom() <= self.bottom() + EPS
    }
}

/// The free space of a field: the maximal empty rectangles.
#[derive(Debug, Clone)]
pub struct Packer {
    free: Vec<Rect>,
}

impl Packer {
    /// An empty field.
    pub fn new(field: Rect) -> Self {
        Packer { free: vec![field] }
    }

    /// Mark `r` as taken: every free rectangle it meets is replaced by the
    /// up to four parts of it that lie left, right, above and below `r`.
    pub fn occupy(&mut self, r: Rect) {
        let mut next = Vec::with_capacity(self.free.len() + 4);
        for f in &self.free {
            if !f.intersects(&r) {
                next.push(*f);
                continue;
            }
            if r.x > f.x {
                next.push(Rect { w: r.x - f.x, ..*f });
            }
            if r.right() < f.right() {
                next.push(Rect {
                    x: r.right(),
                    w: f.right() - r.right(),
                    ..*f
                });
            }
            if r.y > f.y {
                next.push(Rect { h: r.y - f.y, ..*f });
            }
            if r.bottom() < f.bottom() {
                next.push(Rect {
                    y: r.bottom(),
                    h: f.bottom() - r.bottom(),
                    ..*f
                });
            }
        }
        // keep only the maximal ones
        let mut keep: Vec<Rect> = Vec::with_capacity(next.len());
        for (i, a) in next.iter().enumerate() {
            if a.w <= 1e-9 || a.h <= 1e-9 {
                continue;
            }
            let inside_other = next
                .iter()
                .enumerate()
                .any(|(j, b)| j != i && b.contains(a) && !(a.contains(b) && j > i));
            if !inside_other {
                keep.push(*a);
            }
        }
        self.free = keep;
    }

    /// The top-most, then left-most place for a `w × h` box, taken; `None`
    /// when it fits nowhere.
    ///
    /// ```
    /// use tmm_report::sheets::layout::{Packer, Rect};
    /// let mut p = Packer::new(Rect { x: 0.0, y: 0.0, w: 100.0, h: 50.0 });
    /// p.occupy(Rect { x: 60.0, y: 30.0, w: 40.0, h: 20.0 }); // a title block
    /// let a = p.place(60.0, 40.0).unwrap();
    /// assert_eq!((a.x, a.y), (0.0, 0.0));
    /// let b = p.place(40.0, 30.0).unwrap();
    /// assert_eq!((b.x, b.y), (60.0, 0.0));
    /// assert!(p.place(40.0, 30.0).is_none());
    /// ```
    pub fn place(&mut self, w: f64, h: f64) -> Option<Rect> {
        self.place_by(w, h, false)
    }

    /// As [`Packer::place`], or, with `columns`, the left-most, then
    /// top-most place (the drawings fill columns instead of rows).
    pub fn place_by(&mut self, w: f64, h: f64, columns: bool) -> Option<Rect> {
        let key = |r: &Rect| if columns { (r.x, r.y) } else { (r.y, r.x) };
        let best = self
            .free
            .iter()
            .filter(|f| w <= f.w + 1e-9 && h <= f.h + 1e-9)
            .min_by(|a, b| key(a).partial_cmp(&key(b)).unwrap_or(std::cmp::Ordering::Equal))
            .copied()?;
        let r = Rect {
            x: best.x,
            y: best.y,
            w,
            h,
        };
        self.occupy(r);
        Some(r)
    }
}
