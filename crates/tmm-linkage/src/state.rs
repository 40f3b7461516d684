//! Kinematic state of links and points: position, velocity and acceleration,
//! and the rigid-body transfer between points of one link.
//!
//! A link's orientation is kept as a unit vector `u = (cos θ, sin θ)` rather
//! than the angle θ: rotating a local vector is then a complex product (no
//! trigonometry in the hot loop); θ = atan2(u) is taken only for output.
//!
//! Rigid-body kinematics (Artobolevsky 1988, §§ 8–9):
//! `v_P = v_O + ω k × r`, `a_P = a_O + ε k × r − ω² r`, `r = P − O`.

use tmm_geom::{Vec2, perp};

/// Rotate local vector `l` by the orientation `u = (cos θ, sin θ)`.
///
/// ```
/// use tmm_geom::Vec2;
/// let r = tmm_linkage::state::rot(Vec2::new(0.0, 1.0), Vec2::new(2.0, 0.0));
/// assert!((r - Vec2::new(0.0, 2.0)).hypot() < 1e-15);
/// ```
#[inline(always)]
pub fn rot(u: Vec2, l: Vec2) -> Vec2 {
    Vec2::new(u.x * l.x - u.y * l.y, u.x * l.y + u.y * l.x)
}

/// Undo the local direction `d` of a link's reference line: `v·conj(d)`,
/// free when `d` is the local x-axis (every bar).
#[inline(always)]
pub fn unrotate(v: Vec2, d: Vec2) -> Vec2 {
    if d.y == 0.0 && d.x == 1.0 { v } else { rot(v, conj(d)) }
}

/// Complex conjugate: the inverse rotation of a unit vector.
#[inline(always)]
pub fn conj(u: Vec2) -> Vec2 {
    Vec2::new(u.x, -u.y)
}

/// State of a point: position, velocity, acceleration (global, SI).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct PointState {
    /// Position, m.
    pub p: Vec2,
    /// Velocity, m/s.
    pub v: Vec2,
    /// Acceleration, m/s².
    pub a: Vec2,
}

/// State of a link: its local origin's motion and its rotation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinkState {
    /// Position of the local origin, m.
    pub o: Vec2,
    /// Velocity of the local origin, m/s.
    pub v: Vec2,
    /// Acceleration of the local origin, m/s².
    pub a: Vec2,
    /// Orientation `(cos θ, sin θ)`.
    pub u: Vec2,
    /// Angular velocity ω, rad/s (> 0 counter-clockwise).
    pub omega: f64,
    /// Angular acceleration ε, rad/s².
    pub eps: f64,
}

impl Default for LinkState {
    fn default() -> Self {
        LinkState {
            o: Vec2::ZERO,
            v: Vec2::ZERO,
            a: Vec2::ZERO,
            u: Vec2::new(1.0, 0.0),
            omega: 0.0,
            eps: 0.0,
        }
    }
}

impl LinkState {
    /// Absolute angle θ of the link's local x-axis, rad in (−π, π].
    #[inline]
    pub fn angle(&self) -> f64 {
        self.u.y.atan2(self.u.x)
    }

    /// Global position of a local point.
    #[inline(always)]
    pub fn pos(&self, l: Vec2) -> Vec2 {
        self.o + rot(self.u, l)
    }

    /// Velocity and acceleration of the link's material point now at global `x`.
    #[inline(always)]
    pub fn kin_at(&self, x: Vec2) -> (Vec2, Vec2) {
        let d = x - self.o;
        let pd = perp(d);
        (self.v + self.omega * pd, self.a + self.eps * pd - self.omega * self.omega * d)
    }

    /// Full state of a local point.
    #[inline(always)]
    pub fn point(&self, l: Vec2) -> PointState {
        // most points lie on the link's axis (bars, centres of mass)
        let r = if l.y == 0.0 { self.u * l.x } else { rot(self.u, l) };
        let pr = perp(r);
        PointState {
            p: self.o + r,
            v: self.v + pr * self.omega,
            a: self.a + pr * self.eps - r * (self.omega * self.omega),
        }
    }

    /// The link state given the state of one of its points (local `l`) and its
    /// rotation.
    #[inline(always)]
    pub fn from_point(pt: &PointState, l: Vec2, u: Vec2, omega: f64, eps: f64) -> Self {
        if l == Vec2::ZERO {
            // the point is the link's origin
            return LinkState {
                o: pt.p,
                v: pt.v,
                a: pt.a,
                u,
                omega,
                eps,
            };
        }
        let d = -rot(u, l);
        let pd = perp(d);
        LinkState {
            o: pt.p + d,
            v: pt.v + omega * pd,
            a: pt.a + eps * pd - omega * omega * d,
            u,
            omega,
            eps,
        }
    }
}

/// Solve the 2×2 system `x·c1 + y·c2 = r`; `None` when `|det|` is below
/// `tol` (the columns are parallel).
#[inline(always)]
pub fn solve2(c1: Vec2, c2: Vec2, r: Vec2, tol: f64) -> Option<(f64, f64)> {
    let det = c1.x * c2.y - c1.y * c2.x;
    if det.abs() <= tol || !det.is_finite() {
        return None;
    }
    let inv = 1.0 / det;
    Some(((r.x * c2.y - r.y * c2.x) * inv, (c1.x * r.y - c1.y * r.x) * inv))
}
