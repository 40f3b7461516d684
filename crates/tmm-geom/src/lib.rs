//! Shared 2-D primitives, units and numerics of tmm.
//!
//! Every core crate (linkage, gears, planetary, cams) builds on this one; it does
//! no I/O and prints nothing.
//!
//! - [`units`]: quantities as people write them (`"120 mm"`, `"900 rpm"`, `"15°"`)
//!   turned into SI (angles in radians).
//! - [`angle`]: wrapping and degree/radian helpers.
//! - [`root`]: scalar root finding (Brent) and a bracket scan.
//! - [`involute`]: the involute function and its inverse.
//! - [`Vec2`] and [`Point`] are `kurbo`'s plain `f64` types, re-exported.

pub mod angle;
pub mod involute;
pub mod root;
pub mod units;

pub use kurbo::{Point, Vec2};

/// 2-D cross product (z-component of `a × b`).
///
/// ```
/// use tmm_geom::{cross, Vec2};
/// assert_eq!(cross(Vec2::new(1.0, 0.0), Vec2::new(0.0, 1.0)), 1.0);
/// ```
#[inline]
pub fn cross(a: Vec2, b: Vec2) -> f64 {
    a.x * b.y - a.y * b.x
}

/// Rotate a vector by +90° (counter-clockwise): `k × v`.
///
/// The angular-velocity term of a rigid link is `ω k × r`, so
/// `v_B = v_A + ω · perp(r_AB)`.
///
/// ```
/// use tmm_geom::{perp, Vec2};
/// assert_eq!(perp(Vec2::new(1.0, 0.0)), Vec2::new(0.0, 1.0));
/// ```
#[inline]
pub fn perp(v: Vec2) -> Vec2 {
    Vec2::new(-v.y, v.x)
}

/// `true` when every number in the slice is finite (no NaN, no infinity).
///
/// ```
/// assert!(tmm_geom::all_finite(&[1.0, -2.0]));
/// assert!(!tmm_geom::all_finite(&[1.0, f64::NAN]));
/// ```
#[inline]
pub fn all_finite(xs: &[f64]) -> bool {
    xs.iter().all(|x| x.is_finite())
}
