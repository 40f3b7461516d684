//! Points, segments and axis-aligned boxes on the paper (плоская геометрия
//! зазоров): the distances a clearance test compares with its least gap,
//! and whether a line meets or enters a text's box. Coordinates are paper
//! millimetres, y down as in SVG (the formulas do not depend on it).
//!
//! Written apart from the drawing code on purpose: the tests measure what
//! the labels' placement (`tmm_report::labels`, `svg::Rect::cuts`) did,
//! and a measure shared with it would share its faults.

/// A point, (x, y).
pub type Pt = (f64, f64);

/// The distance from the point `p` to the segment `a`–`b`.
///
/// Derived here: the segment's points are `a + t·(b − a)`, t ∈ [0, 1]; the
/// squared distance to `p` is a parabola in t whose least value is at the
/// projection t* = (p − a)·(b − a) / |b − a|², so the nearest point is at
/// t* clamped to [0, 1] (an end when the projection falls outside). A
/// segment of zero length is its point `a`.
///
/// ```
/// use tmm_testkit::plane::point_segment;
/// // above the middle, past an end, on the segment, a zero-length segment
/// assert_eq!(point_segment((5.0, 3.0), (0.0, 0.0), (10.0, 0.0)), 3.0);
/// assert_eq!(point_segment((13.0, 4.0), (0.0, 0.0), (10.0, 0.0)), 5.0);
/// assert_eq!(point_segment((2.0, 2.0), (0.0, 0.0), (4.0, 4.0)), 0.0);
/// assert_eq!(point_segment((3.0, 4.0), (0.0, 0.0), (0.0, 0.0)), 5.0);
/// ```
pub fn point_segment(p: Pt, a: Pt, b: Pt) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p.0 - a.0 - t * dx).hypot(p.1 - a.1 - t * dy)
}

/// The z component of (a − o) × (b − o): positive when o, a, b turn
/// counter-clockwise in x-right, y-up axes.
fn turn(o: Pt, a: Pt, b: Pt) -> f64 {
    (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0)
}

/// The distance between the segments `p`–`q` and `a`–`b` (0 when they
/// cross or touch).
///
/// Derived here: two segments cross at interior points when the ends of
/// each lie strictly on opposite sides of the other's line (the signs of
/// the turns [`turn`] differ). Otherwise the least distance is taken at an
/// end of one of them: |P(s) − Q(t)|² is a convex quadratic on the square
/// [0, 1]²; for lines that are not parallel its only zero is where the
/// lines cross, outside the square here, so its least value lies on the
/// square's edge, where s or t is 0 or 1; for parallel lines it is
/// constant along a direction that reaches that edge. So it is the least
/// of the four distances of an end to the other segment
/// ([`point_segment`]), 0 when one touches the other.
///
/// ```
/// use tmm_testkit::plane::segment_segment;
/// // crossing, parallel 2 apart, in line 3 apart, a T 1 short
/// assert_eq!(segment_segment((0.0, 0.0), (4.0, 4.0), (0.0, 4.0), (4.0, 0.0)), 0.0);
/// assert_eq!(segment_segment((0.0, 0.0), (4.0, 0.0), (1.0, 2.0), (9.0, 2.0)), 2.0);
/// assert_eq!(segment_segment((0.0, 0.0), (4.0, 0.0), (7.0, 0.0), (9.0, 0.0)), 3.0);
/// assert_eq!(segment_segment((0.0, 0.0), (4.0, 0.0), (2.0, 1.0), (2.0, 5.0)), 1.0);
/// ```
pub fn segment_segment(p: Pt, q: Pt, a: Pt, b: Pt) -> f64 {
    let (d1, d2) = (turn(a, b, p), turn(a, b, q));
    let (d3, d4) = (turn(p, q, a), turn(p, q, b));
    if d1 * d2 < 0.0 && d3 * d4 < 0.0 {
        return 0.0;
    }
    point_segment(p, a, b)
        .min(point_segment(q, a, b))
        .min(point_segment(a, p, q))
        .min(point_segment(b, p, q))
}

/// An axis-aligned box on the paper, `x0 ≤ x1`, `y0 ≤ y1`: a text's ink,
/// a figure's content.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rect {
    /// Left.
    pub x0: f64,
    /// Top (y down) or bottom (y up): the smaller y.
    pub y0: f64,
    /// Right.
    pub x1: f64,
    /// The larger y.
    pub y1: f64,
}

impl From<[f64; 4]> for Rect {
    /// A box from `[x0, y0, x1, y1]`.
    fn from(b: [f64; 4]) -> Rect {
        Rect {
            x0: b[0],
            y0: b[1],
            x1: b[2],
            y1: b[3],
        }
    }
}

impl Rect {
    /// The gap between two boxes: 0 when they touch or overlap, else the
    /// distance of their nearest points (derived here: the gaps along x
    /// and along y, each 0 where the boxes' spans overlap, are the legs of
    /// the nearest points' offset).
    ///
    /// ```
    /// use tmm_testkit::plane::Rect;
    /// let a = Rect::from([0.0, 0.0, 2.0, 2.0]);
    /// assert_eq!(a.gap(&Rect::from([5.0, 1.0, 6.0, 9.0])), 3.0);
    /// assert_eq!(a.gap(&Rect::from([5.0, 6.0, 6.0, 9.0])), 5.0);
    /// assert_eq!(a.gap(&Rect::from([1.0, 1.0, 6.0, 9.0])), 0.0);
    /// ```
    pub fn gap(&self, o: &Rect) -> f64 {
        let dx = (o.x0 - self.x1).max(self.x0 - o.x1).max(0.0);
        let dy = (o.y0 - self.y1).max(self.y0 - o.y1).max(0.0);
        dx.hypot(dy)
    }

    /// The distance from the point `p` to the box (0 inside or on it).
    ///
    /// ```
    /// use tmm_testkit::plane::Rect;
    /// let a = Rect::from([0.0, 0.0, 2.0, 2.0]);
    /// assert_eq!(a.point_distance((5.0, 6.0)), 5.0);
    /// assert_eq!(a.point_distance((1.0, -0.5)), 0.5);
    /// assert_eq!(a.point_distance((1.0, 2.0)), 0.0);
    /// ```
    pub fn point_distance(&self, p: Pt) -> f64 {
        let dx = (self.x0 - p.0).max(p.0 - self.x1).max(0.0);
        let dy = (self.y0 - p.1).max(p.1 - self.y1).max(0.0);
        dx.hypot(dy)
    }

    /// The part of the segment `a`–`b` inside the box, as the interval of
    /// the parameter t of `a + t·(b − a)`, by Liang and Barsky's clipping
    /// (Y.-D. Liang, B. A. Barsky, "A New Concept and Method for Line
    /// Clipping", ACM Transactions on Graphics 3 (1), 1984, pp. 1–11): each
    /// side k gives p_k·t ≤ q_k with (p, q) = (−dx, x_a − x0), (dx, x1 − x_a),
    /// (−dy, y_a − y0), (dy, y1 − y_a); a side with p_k < 0 is entered at
    /// t = q_k/p_k, one with p_k > 0 left there, and a side the segment runs
    /// parallel to (p_k = 0) keeps all of it or nothing by the sign of q_k.
    /// `strict`: the box's inside only (its sides left out).
    fn clip(&self, a: Pt, b: Pt, strict: bool) -> bool {
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for (p, q) in [(-dx, a.0 - self.x0), (dx, self.x1 - a.0), (-dy, a.1 - self.y0), (dy, self.y1 - a.1)] {
            if p == 0.0 {
                if q < 0.0 || (strict && q == 0.0) {
                    return false;
                }
            } else if p < 0.0 {
                t0 = t0.max(q / p);
            } else {
                t1 = t1.min(q / p);
            }
        }
        if strict { t0 < t1 } else { t0 <= t1 }
    }

    /// Whether the segment `a`–`b` meets the box, its sides included (a
    /// touch counts) — [`Rect::clip`].
    ///
    /// ```
    /// use tmm_testkit::plane::Rect;
    /// let a = Rect::from([0.0, 0.0, 2.0, 2.0]);
    /// assert!(a.meets((-1.0, 1.0), (3.0, 1.0)));
    /// assert!(a.meets((-1.0, 2.0), (3.0, 2.0)), "along a side");
    /// assert!(a.meets((-1.0, 1.0), (1.0, 3.0)), "through a corner");
    /// assert!(!a.meets((-1.0, 2.5), (3.0, 2.5)));
    /// assert!(!a.meets((3.0, 0.0), (5.0, -9.0)));
    /// ```
    pub fn meets(&self, a: Pt, b: Pt) -> bool {
        self.clip(a, b, false)
    }

    /// Whether the segment `a`–`b` passes through the inside of the box
    /// (along a side or through a corner does not count) — [`Rect::clip`].
    ///
    /// ```
    /// use tmm_testkit::plane::Rect;
    /// let a = Rect::from([0.0, 0.0, 2.0, 2.0]);
    /// assert!(a.enters((-1.0, 1.0), (3.0, 1.0)));
    /// assert!(a.enters((1.0, 1.0), (1.0, 1.5)), "wholly inside");
    /// assert!(!a.enters((-1.0, 2.0), (3.0, 2.0)), "along a side");
    /// assert!(!a.enters((-1.0, 1.0), (1.0, 3.0)), "through a corner");
    /// ```
    pub fn enters(&self, a: Pt, b: Pt) -> bool {
        self.clip(a, b, true)
    }

    /// The distance from the segment `a`–`b` to the box: 0 when it meets
    /// the box ([`Rect::meets`]), else the least distance to the box's four
    /// sides ([`segment_segment`]; a segment outside a box is nearest to
    /// its boundary).
    ///
    /// ```
    /// use tmm_testkit::plane::Rect;
    /// let a = Rect::from([2.0, 4.0, 6.0, 6.0]);
    /// assert_eq!(a.segment_distance((0.0, 0.0), (10.0, 10.0)), 0.0);
    /// assert_eq!(a.segment_distance((0.0, 0.0), (0.0, 10.0)), 2.0);
    /// // a diagonal passing a corner: the corner (6, 4) is √2 from y = x − 4
    /// let d = a.segment_distance((4.0, 0.0), (10.0, 6.0));
    /// assert!((d - 2f64.sqrt()).abs() < 1e-12, "{d}");
    /// ```
    pub fn segment_distance(&self, a: Pt, b: Pt) -> f64 {
        if self.meets(a, b) {
            return 0.0;
        }
        let c = [(self.x0, self.y0), (self.x1, self.y0), (self.x1, self.y1), (self.x0, self.y1)];
        (0..4)
            .map(|i| segment_segment(c[i], c[(i + 1) % 4], a, b))
            .fold(f64::INFINITY, f64::min)
    }
}
