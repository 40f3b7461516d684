//! A rigid placement of a synthesised mechanism on the drawing (размещение):
//! the synthesis works where the construction is simplest and the result is
//! moved so that the crank pivot is at the origin and the frame line along x.

use tmm_geom::Vec2;

use super::result::{Construction, LocusCircle};

/// p ↦ R(−angle)·(p − origin).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placement {
    /// The point that goes to the origin.
    pub origin: Vec2,
    /// The direction that goes to +x, rad.
    pub angle: f64,
}

impl Placement {
    /// Move a point.
    ///
    /// ```
    /// use tmm_linkage::synthesis::placement::Placement;
    /// use tmm_geom::Vec2;
    /// let p = Placement { origin: Vec2::new(1.0, 1.0), angle: std::f64::consts::FRAC_PI_2 };
    /// let q = p.point(Vec2::new(1.0, 3.0)); // 2 m along the placed x-axis
    /// assert!((q.x - 2.0).abs() < 1e-15 && q.y.abs() < 1e-15);
    /// ```
    pub fn point(&self, p: Vec2) -> Vec2 {
        let (s, c) = self.angle.sin_cos();
        let q = p - self.origin;
        Vec2::new(c * q.x + s * q.y, -s * q.x + c * q.y)
    }

    /// Move an absolute angle.
    pub fn angle(&self, a: f64) -> f64 {
        a - self.angle
    }

    /// Move a locus circle.
    pub fn circle(&self, c: LocusCircle) -> LocusCircle {
        LocusCircle {
            center: self.point(c.center),
            radius: c.radius,
            arc_start: self.angle(c.arc_start),
            arc_sweep: c.arc_sweep,
        }
    }

    /// Move a whole construction.
    pub fn construction(&self, c: Construction) -> Construction {
        Construction {
            point: c.point,
            extremes: [self.point(c.extremes[0]), self.point(c.extremes[1])],
            locus: c.locus.map(|l| self.circle(l)),
            pivot: self.point(c.pivot),
            lines: c.lines.into_iter().map(|(n, a, b)| (n, self.point(a), self.point(b))).collect(),
        }
    }
}
