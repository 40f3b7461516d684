//! The accepted ranges of the quantities a mechanism is given (допустимые
//! диапазоны): what the core refuses with [`LinkageError::Range`] before it
//! could overflow, lose every significant digit, or describe something that is
//! not a machine. Documented in docs/linkage.md (§ "Accepted ranges").
//!
//! The bounds are wide — from a watch movement to a crane — and each has its
//! reason:
//! - coordinates and lengths up to [`MAX_LENGTH`] = 1e4 m: every tolerance of
//!   the core is relative to the mechanism's size, so a mechanism behaves the
//!   same in any unit inside this range, while squares of lengths (1e8 m²)
//!   and accelerations stay far from overflow;
//! - the shortest link at least [`MIN_RELATIVE_LENGTH`] = 1e-6 of the size:
//!   below that a link is lost in the round-off of the others' positions
//!   (1e-16 of the size, squared in the circle intersections);
//! - |ω₁| from [`MIN_OMEGA`] = 1e-9 rad/s (a quasi-static crank) to [`MAX_OMEGA`] = 1e5 rad/s
//!   (about 1e6 rpm, beyond any rotor) and |ε₁| up to [`MAX_EPSILON`] = 1e10 rad/s²:
//!   accelerations ω²·L stay below 1e14 m/s² and their squares finite;
//! - crank angles |φ| up to [`MAX_ANGLE`] = 1e5 rad (16 000 turns), where
//!   `sin_cos` still resolves 1e-11 rad.

use crate::error::LinkageError;

/// Largest coordinate or length, m.
pub const MAX_LENGTH: f64 = 1e4;
/// Shortest link length relative to the mechanism's size.
pub const MIN_RELATIVE_LENGTH: f64 = 1e-6;
/// Smallest crank speed |ω₁|, rad/s.
pub const MIN_OMEGA: f64 = 1e-9;
/// Largest crank speed |ω₁|, rad/s.
pub const MAX_OMEGA: f64 = 1e5;
/// Largest crank angular acceleration |ε₁|, rad/s².
pub const MAX_EPSILON: f64 = 1e10;
/// The most moving links of a mechanism: the rank check of the constraints
/// (`constraints::rank`) costs the cube of their number, and a whole run
/// with [forces], [dynamics] and the note grows with them (249 links took
/// 14 s of CPU, 101 links 5 s; a textbook mechanism has fewer than 10), so
/// 150 keeps a whole run under 10 s on one core.
pub const MAX_LINKS: usize = 150;
/// Largest crank angle |φ| (input and assembly angles, guide angles), rad.
pub const MAX_ANGLE: f64 = 1e5;

fn range(field: &str, value: String, range: &str, why: &str) -> LinkageError {
    LinkageError::Range {
        field: field.to_string(),
        value,
        range: range.to_string(),
        why: why.to_string(),
    }
}

/// A coordinate (or an offset) of a point, m: finite and |x| ≤ [`MAX_LENGTH`].
///
/// ```
/// use tmm_linkage::limits::coordinate;
/// assert!(coordinate("fixed.A", 0.51).is_ok());
/// assert!(coordinate("fixed.A", 1e9).unwrap_err().to_string().contains("fixed.A"));
/// assert!(coordinate("fixed.A", f64::NAN).is_err());
/// ```
pub fn coordinate(field: &str, x: f64) -> Result<(), LinkageError> {
    if x.is_finite() && x.abs() <= MAX_LENGTH {
        Ok(())
    } else {
        Err(range(
            field,
            format!("{x:e} m"),
            "−1e4 m … 1e4 m",
            " (a lever mechanism up to 10 km across; give lengths in SI metres)",
        ))
    }
}

/// An angle of the description (a guide's direction, the assembly angle) or a
/// crank angle to solve at, rad: finite and |a| ≤ [`MAX_ANGLE`].
///
/// ```
/// assert!(tmm_linkage::limits::angle("phi", 7.0).is_ok());
/// assert!(tmm_linkage::limits::angle("phi", 1e300).is_err());
/// ```
pub fn angle(field: &str, a: f64) -> Result<(), LinkageError> {
    if a.is_finite() && a.abs() <= MAX_ANGLE {
        Ok(())
    } else {
        Err(range(
            field,
            format!("{a:e} rad"),
            "−1e5 rad … 1e5 rad",
            " (about 16 000 turns; beyond that the angle's last digits are lost); reduce it modulo 360°",
        ))
    }
}

/// The crank speed ω₁ (rad/s, signed) and angular acceleration ε₁ (rad/s²).
///
/// ```
/// use tmm_linkage::limits::speed;
/// assert!(speed(94.2, 0.0).is_ok());
/// assert!(speed(1e300, 0.0).is_err());
/// assert!(speed(0.0, 0.0).is_err());
/// ```
pub fn speed(omega: f64, eps: f64) -> Result<(), LinkageError> {
    if !(omega.is_finite() && omega.abs() >= MIN_OMEGA && omega.abs() <= MAX_OMEGA) {
        return Err(range(
            "input.speed",
            format!("{omega:e} rad/s"),
            "1e-9 rad/s ≤ |ω₁| ≤ 1e5 rad/s (up to about 1e6 rpm)",
            ", in either direction; the crank must turn",
        ));
    }
    if !(eps.is_finite() && eps.abs() <= MAX_EPSILON) {
        return Err(range("input.epsilon", format!("{eps:e} rad/s²"), "|ε₁| ≤ 1e10 rad/s²", ""));
    }
    Ok(())
}

/// The slowest driving slider accepted, m/s.
pub const MIN_SLIDER_SPEED: f64 = 1e-9;
/// The fastest driving slider accepted, m/s.
pub const MAX_SLIDER_SPEED: f64 = 1e4;
/// The largest acceleration of a driving slider accepted, m/s².
pub const MAX_SLIDER_ACCELERATION: f64 = 1e9;

/// The speed v (m/s, signed) and acceleration a (m/s²) of a driving slider.
///
/// ```
/// use tmm_linkage::limits::slider_speed;
/// assert!(slider_speed(0.5, 0.0).is_ok());
/// assert!(slider_speed(0.0, 0.0).is_err());
/// assert!(slider_speed(0.5, f64::NAN).is_err());
/// ```
pub fn slider_speed(v: f64, a: f64) -> Result<(), LinkageError> {
    if !(v.is_finite() && v.abs() >= MIN_SLIDER_SPEED && v.abs() <= MAX_SLIDER_SPEED) {
        return Err(range(
            "input.speed",
            format!("{v:e} m/s"),
            "1e-9 m/s ≤ |v| ≤ 1e4 m/s",
            ", in either direction along the guide; the driving slider must move",
        ));
    }
    if !(a.is_finite() && a.abs() <= MAX_SLIDER_ACCELERATION) {
        return Err(range("input.acceleration", format!("{a:e} m/s²"), "|a| ≤ 1e9 m/s²", ""));
    }
    Ok(())
}

/// A link length `len` against the mechanism's size `size`, m.
pub fn link_length(field: &str, len: f64, size: f64) -> Result<(), LinkageError> {
    if len >= MIN_RELATIVE_LENGTH * size && len > 0.0 {
        Ok(())
    } else {
        Err(range(
            field,
            format!("{len:e} m"),
            &format!("≥ {:e} m (1e-6 of the mechanism's size {size:e} m)", MIN_RELATIVE_LENGTH * size),
            "; a shorter link is lost in the round-off of the others",
        ))
    }
}
