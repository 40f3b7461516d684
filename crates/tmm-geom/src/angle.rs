//! Angle helpers: wrapping into a range and degree/radian conversion.
//!
//! Convention (DESIGN.md): angles are measured from the global x-axis,
//! counter-clockwise positive, in radians inside the code.

use std::f64::consts::{PI, TAU};

/// Wrap an angle into `[0, 2π)`.
///
/// ```
/// use std::f64::consts::PI;
/// let a = tmm_geom::angle::wrap_2pi(-PI / 2.0);
/// assert!((a - 1.5 * PI).abs() < 1e-15);
/// ```
#[inline]
pub fn wrap_2pi(a: f64) -> f64 {
    let r = a.rem_euclid(TAU);
    if r >= TAU { 0.0 } else { r }
}

/// Wrap an angle into `(-π, π]`.
///
/// ```
/// use std::f64::consts::PI;
/// assert!((tmm_geom::angle::wrap_pi(1.5 * PI) + 0.5 * PI).abs() < 1e-15);
/// ```
#[inline]
pub fn wrap_pi(a: f64) -> f64 {
    let r = wrap_2pi(a);
    if r > PI { r - TAU } else { r }
}

/// Degrees to radians.
///
/// ```
/// assert!((tmm_geom::angle::deg(180.0) - std::f64::consts::PI).abs() < 1e-15);
/// ```
#[inline]
pub fn deg(d: f64) -> f64 {
    d.to_radians()
}

/// Radians to degrees.
///
/// ```
/// assert!((tmm_geom::angle::to_deg(std::f64::consts::FRAC_PI_2) - 90.0).abs() < 1e-12);
/// ```
#[inline]
pub fn to_deg(r: f64) -> f64 {
    r.to_degrees()
}

/// Signed smallest difference `b − a` wrapped into `(-π, π]`.
///
/// ```
/// use std::f64::consts::PI;
/// let d = tmm_geom::angle::diff(0.9 * 2.0 * PI, 0.1);
/// assert!((d - (0.1 + 0.2 * PI)).abs() < 1e-12);
/// ```
#[inline]
pub fn diff(a: f64, b: f64) -> f64 {
    wrap_pi(b - a)
}
