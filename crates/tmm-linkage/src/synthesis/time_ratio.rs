//! The time ratio (коэффициент изменения средней скорости Kv, Kω) and the
//! angle θ (угол перекрытия) between the crank's working and return strokes.
//!
//! Source: seed 000 § 1.2, formulas (1.2)–(1.3); seed 002 § 1:
//! K = (π + θ)/(π − θ), θ = π (K − 1)/(K + 1).

use std::f64::consts::PI;

use super::error::SynthesisError;

/// θ from K: θ = π (K − 1)/(K + 1) (seed 000, formula 1.3).
///
/// ```
/// use tmm_linkage::synthesis::time_ratio::theta_from_k;
/// // seed 002, example 3: Kv = 1.5 → θ = 36°
/// assert!((theta_from_k(1.5).unwrap().to_degrees() - 36.0).abs() < 1e-12);
/// assert!(theta_from_k(0.9).is_err());
/// ```
pub fn theta_from_k(k: f64) -> Result<f64, SynthesisError> {
    if !k.is_finite() || k < 1.0 {
        return Err(SynthesisError::input(
            "k",
            format!("the time ratio K = v_return/v_working must be a finite number ≥ 1, got {k}"),
        ));
    }
    Ok(PI * (k - 1.0) / (k + 1.0))
}

/// K from θ: K = (π + θ)/(π − θ) (seed 000, formula 1.2).
///
/// ```
/// use tmm_linkage::synthesis::time_ratio::k_from_theta;
/// assert!((k_from_theta(36f64.to_radians()) - 1.5).abs() < 1e-12);
/// ```
pub fn k_from_theta(theta: f64) -> f64 {
    (PI + theta) / (PI - theta)
}
