//! Intersections of half-planes `a·p ≥ c` and the point of such a region
//! nearest to a given point: the admissible region of the cam centre on the
//! s–ds/dφ diagram (область допустимых положений центра кулачка).
//!
//! Source: the region is convex; its nearest point to `q` is either `q`, the
//! projection of `q` on one boundary line, or a vertex (Karush–Kuhn–Tucker
//! conditions of a convex quadratic program with linear constraints;
//! Boyd & Vandenberghe, *Convex Optimization*, ch. 5).

use tmm_geom::Vec2;

/// A half-plane `n·p ≥ c`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HalfPlane {
    /// Inward normal (not necessarily unit).
    pub n: Vec2,
    /// Offset.
    pub c: f64,
}

impl HalfPlane {
    /// Signed slack `n·p − c` scaled by |n| (distance inside, negative outside).
    #[inline]
    pub fn slack(&self, p: Vec2) -> f64 {
        (self.n.dot(p) - self.c) / self.n.hypot()
    }
}

/// The point of `∩ hᵢ` nearest to `q`, for a handful of half-planes, by
/// checking every KKT candidate. `None` when the region is empty.
///
/// ```
/// use tmm_cams::halfplane::{nearest_few, HalfPlane};
/// use tmm_geom::Vec2;
/// // x ≥ 1 and y ≥ 2: nearest to the origin is the corner (1, 2)
/// let h = [HalfPlane { n: Vec2::new(1.0, 0.0), c: 1.0 }, HalfPlane { n: Vec2::new(0.0, 1.0), c: 2.0 }];
/// let p = nearest_few(&h, Vec2::ZERO).unwrap();
/// assert!((p - Vec2::new(1.0, 2.0)).hypot() < 1e-12);
/// ```
pub fn nearest_few(hs: &[HalfPlane], q: Vec2) -> Option<Vec2> {
    let scale = hs.iter().map(|h| h.c.abs() / h.n.hypot()).fold(q.hypot(), f64::max).max(1e-300);
    let tol = 1e-12 * scale;
    let feasible = |p: Vec2| hs.iter().all(|h| h.slack(p) >= -tol);
    let mut best: Option<(f64, Vec2)> = None;
    let mut take = |p: Vec2| {
        if p.x.is_finite() && p.y.is_finite() && feasible(p) {
            let d = (p - q).hypot();
            if best.is_none_or(|(bd, _)| d < bd) {
                best = Some((d, p));
            }
        }
    };
    take(q);
    for h in hs {
        let nn = h.n.dot(h.n);
        take(q + h.n * ((h.c - h.n.dot(q)) / nn));
    }
    for i in 0..hs.len() {
        for j in i + 1..hs.len() {
            let (a, b) = (hs[i], hs[j]);
            let det = a.n.x * b.n.y - a.n.y * b.n.x;
            if det.abs() > 1e-14 * a.n.hypot() * b.n.hypot() {
                take(Vec2::new((a.c * b.n.y - a.n.y * b.c) / det, (a.n.x * b.c - a.c * b.n.x) / det));
            }
        }
    }
    best.map(|(_, p)| p)
}

/// A convex polygon (counter-clockwise vertices) cut from a box by many
/// half-planes (Sutherland–Hodgman clipping against one line at a time).
#[derive(Debug, Clone, Default)]
pub struct Region {
    /// The vertices, counter-clockwise.
    pub vertices: Vec<Vec2>,
    scratch: Vec<Vec2>,
}

impl Region {
    /// The square of half-size `r` centred at `c`.
    pub fn square(c: Vec2, r: f64) -> Self {
        let v = vec![
            c + Vec2::new(-r, -r),
            c + Vec2::new(r, -r),
            c + Vec2::new(r, r),
            c + Vec2::new(-r, r),
        ];
        Region {
            vertices: v,
            scratch: Vec::new(),
        }
    }

    /// A convex polygon from its counter-clockwise vertices.
    pub fn from_vertices(vertices: Vec<Vec2>) -> Self {
        Region {
            vertices,
            scratch: Vec::new(),
        }
    }

    /// Keep the part with `n·p ≥ c`.
    pub fn clip(&mut self, h: HalfPlane) {
        self.scratch.clear();
        let m = self.vertices.len();
        for i in 0..m {
            let p = self.vertices[i];
            let q = self.vertices[(i + 1) % m];
            let (fp, fq) = (h.n.dot(p) - h.c, h.n.dot(q) - h.c);
            if fp >= 0.0 {
                self.scratch.push(p);
            }
            if (fp >= 0.0) != (fq >= 0.0) {
                let t = fp / (fp - fq);
                self.scratch.push(p + (q - p) * t);
            }
        }
        std::mem::swap(&mut self.vertices, &mut self.scratch);
    }

    /// `true` when nothing is left.
    pub fn is_empty(&self) -> bool {
        self.vertices.len() < 3
    }

    /// `true` when `p` is inside (or on the boundary, to `tol`).
    pub fn contains(&self, p: Vec2, tol: f64) -> bool {
        let m = self.vertices.len();
        m >= 3
            && (0..m).all(|i| {
                let a = self.vertices[i];
                let b = self.vertices[(i + 1) % m];
                tmm_geom::cross(b - a, p - a) >= -tol * (b - a).hypot()
            })
    }

    /// The point of the polygon nearest to `q`.
    pub fn nearest(&self, q: Vec2) -> Option<Vec2> {
        if self.is_empty() {
            return None;
        }
        if self.contains(q, 0.0) {
            return Some(q);
        }
        let m = self.vertices.len();
        let mut best = (f64::INFINITY, q);
        for i in 0..m {
            let a = self.vertices[i];
            let b = self.vertices[(i + 1) % m];
            let ab = b - a;
            let t = ((q - a).dot(ab) / ab.dot(ab).max(1e-300)).clamp(0.0, 1.0);
            let p = a + ab * t;
            let d = (p - q).hypot();
            if d < best.0 {
                best = (d, p);
            }
        }
        Some(best.1)
    }

    /// Points where the circle `|p − c| = r` crosses the polygon's edges.
    pub fn circle_crossings(&self, c: Vec2, r: f64) -> Vec<Vec2> {
        let mut out = Vec::new();
        let m = self.vertices.len();
        for i in 0..m {
            let a = self.vertices[i];
            let d = self.vertices[(i + 1) % m] - a;
            let f = a - c;
            let (qa, qb, qc) = (d.dot(d), 2.0 * f.dot(d), f.dot(f) - r * r);
            let disc = qb * qb - 4.0 * qa * qc;
            if qa <= 0.0 || disc < 0.0 {
                continue;
            }
            for t in [(-qb - disc.sqrt()) / (2.0 * qa), (-qb + disc.sqrt()) / (2.0 * qa)] {
                if (0.0..=1.0).contains(&t) {
                    // back onto the circle exactly (the quadratic loses digits on long edges)
                    let p = a + d * t - c;
                    out.push(c + p * (r / p.hypot()));
                }
            }
        }
        out
    }
}
