//! The linear-velocity picture (картина линейных скоростей) and the
//! angular-velocity diagram (план угловых скоростей) of a 2K-H train, built
//! as the course draws them, and the ratio read off them.
//!
//! The picture lies in the plane (v, r): the vertical axis is the radius from
//! the main axis, the horizontal one the tangential velocity of a point at that
//! radius (positive in the sense of ω1 > 0). Each member's velocities lie on a
//! straight line: the lines of wheel 1 and of the carrier pass through the
//! origin, the planet's through the mesh points `a` (with wheel 1) and `c`
//! (with the fixed wheel 3, velocity zero: the planet's instant centre).

use serde::Serialize;

use crate::scheme::{ModuleRatio, Scheme, Teeth, centre_distance};

/// A point of the picture: velocity `v` (m/s) at radius `r` (m).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PicturePoint {
    /// Tangential velocity, m/s.
    pub v: f64,
    /// Radius from the main axis, m.
    pub r: f64,
}

/// The linear-velocity picture and what it gives.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct VelocityPicture {
    /// `a`: the pitch point of mesh 1–2, on wheel 1's pitch circle.
    pub a: PicturePoint,
    /// `b`: the planet's axis (on the carrier), found on the planet's line.
    pub b: PicturePoint,
    /// `c`: the pitch point of mesh 2′–3 (velocity zero, wheel 3 fixed).
    pub c: PicturePoint,
    /// Angular velocity of wheel 1, rad/s (the slope of line 0–a).
    pub omega1: f64,
    /// Angular velocity of the carrier, rad/s (the slope of line 0–b).
    pub omega_h: f64,
    /// Absolute angular velocity of the planet block, rad/s (the slope of line a–c).
    pub omega_planet: f64,
    /// The ratio read off the picture, `tan ψ1 / tan ψH` of the lines 0–a and 0–b.
    pub ratio: f64,
}

/// Build the velocity picture for module `module` (m_I, m) and `ω1` (rad/s).
///
/// Construction (Artobolevsky, ТММ, 1988, картина скоростей планетарного
/// механизма): `a = (ω1·r1, r1)`; `c = (0, r3)`; the planet line runs through
/// `a` and `c`; `b` is where it crosses the level `r = a_w`; the carrier line
/// runs from the origin to `b`. The ratio is the ratio of the slopes
/// `v/r` of the lines 0–a and 0–b.
///
/// ```
/// use tmm_planetary::{picture::velocity_picture, ModuleRatio, Scheme, Teeth};
/// let p = velocity_picture(Scheme::SunPlanetRing, &Teeth::single(30, 30, 90), ModuleRatio::ONE, 1e-3, 1.0);
/// assert!((p.ratio - 4.0).abs() < 1e-12);
/// assert!((p.b.v - 0.5 * p.a.v).abs() < 1e-15); // the planet's axis moves at half the sun's pitch speed
/// ```
pub fn velocity_picture(scheme: Scheme, t: &Teeth, q: ModuleRatio, module: f64, omega1: f64) -> VelocityPicture {
    let m2 = module * q.value();
    let r1 = 0.5 * module * f64::from(t.z1);
    let r3 = 0.5 * m2 * f64::from(t.z3);
    let aw = module * centre_distance(scheme, t);
    let a = PicturePoint { v: omega1 * r1, r: r1 };
    let c = PicturePoint { v: 0.0, r: r3 };
    // Intersection of the line a–c with the horizontal line r = aw.
    let s = (aw - a.r) / (c.r - a.r);
    let b = PicturePoint {
        v: a.v + s * (c.v - a.v),
        r: aw,
    };
    let slope = |p: PicturePoint| p.v / p.r;
    let omega_planet = (a.v - c.v) / (a.r - c.r);
    VelocityPicture {
        a,
        b,
        c,
        omega1: slope(a),
        omega_h: slope(b),
        omega_planet,
        ratio: slope(a) / slope(b),
    }
}

/// The angular-velocity diagram: from a pole at distance `h` from a horizontal
/// ω-axis, rays parallel to the lines of the velocity picture cut the axis at
/// `x_i = h·ω_i/ω1` (the picture drawn with wheel 1's line at 45°). Returns the segments of wheel 1, the carrier, the planet (wheel 3's
/// is zero) and the ratio `x_1/x_H` read off the diagram.
///
/// ```
/// use tmm_planetary::{picture::{angular_diagram, velocity_picture}, ModuleRatio, Scheme, Teeth};
/// let p = velocity_picture(Scheme::SunPlanetRing, &Teeth::single(30, 30, 90), ModuleRatio::ONE, 1e-3, 1.0);
/// let d = angular_diagram(&p, 50.0);
/// assert!((d.x1 - 50.0).abs() < 1e-12 && (d.xh - 12.5).abs() < 1e-12 && (d.ratio - 4.0).abs() < 1e-12);
/// ```
pub fn angular_diagram(p: &VelocityPicture, h: f64) -> AngularDiagram {
    // Drawn with the picture's scales μ_r (m per mm) and μ_v (m/s per mm), a line
    // of slope dv/dr has the paper slope dX/dY = (dv/dr)·μ_r/μ_v; the ray from
    // the pole (0, −h) parallel to it meets the ω-axis Y = 0 at X = h·(dv/dr)·μ_r/μ_v.
    // The scales are chosen with μ_r/μ_v = 1/ω1 (wheel 1's line at 45°).
    let kappa = 1.0 / p.omega1;
    let cut = |dv_dr: f64| h * dv_dr * kappa;
    let (x1, xh, x2) = (cut(p.a.v / p.a.r), cut(p.b.v / p.b.r), cut(p.omega_planet));
    AngularDiagram {
        x1,
        xh,
        x2,
        ratio: x1 / xh,
    }
}

/// Segments of the angular-velocity diagram (paper units of `h`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AngularDiagram {
    /// Wheel 1.
    pub x1: f64,
    /// The carrier.
    pub xh: f64,
    /// The planet block.
    pub x2: f64,
    /// `x1 / xH`: the ratio read off the diagram.
    pub ratio: f64,
}
