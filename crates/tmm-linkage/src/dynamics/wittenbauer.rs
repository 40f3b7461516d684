//! Wittenbauer's energy–mass diagram (диаграмма энергомасс Виттенбауэра):
//! the curve ΔT against I_II over the cycle. With the origin moved to
//! O′ = (−I_I, −T₀), the crank speed at a point is ω² = 2·(ΔT + T₀)/(I_II + I_I),
//! twice the slope of the ray from O′. The fastest and slowest speeds are the
//! two supporting lines of the curve at slopes k_max = ω_max²/2 (above) and
//! k_min = ω_min²/2 (below); O′ is their intersection:
//! b_max = max(ΔT − k_max·I_II), b_min = min(ΔT − k_min·I_II),
//! I_I = (b_max − b_min)/(k_max − k_min), T₀ = k_max·I_I − b_max
//! (Wittenbauer F., *Graphische Dynamik*, Springer, 1923; Артоболевский 1988,
//! the energy–mass diagram).
//! Done exactly (the supporting lines touch the exact curve), this is the
//! exact steady motion, not an approximation.
//!
//! The lines are found over the period of the summed loads
//! ([`super::load_period`]): where M_c and I_II repeat within the cycle the
//! curve retraces itself, and its supporting lines over the first period
//! are those over the cycle.

use super::error::DynamicsError;
use super::extremum::{maximize, minimize};
use super::reduced::Reducer;
use super::reduction::{EnergyPoint, ReducedCycle};
use crate::Solution;

/// One supporting line of the energy–mass curve, ΔT = slope·I_II + intercept.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tangent {
    /// Slope ω²/2, J/(kg·m²) = rad²/s².
    pub slope: f64,
    /// Intercept on the ΔT axis (at I_II = 0), J.
    pub intercept: f64,
    /// Cycle angle of the point of contact, rad.
    pub phi: f64,
    /// I_II at the point of contact, kg·m².
    pub inertia: f64,
    /// ΔT at the point of contact, J.
    pub energy: f64,
}

/// The result of Wittenbauer's construction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wittenbauer {
    /// The upper line, slope ω_max²/2.
    pub upper: Tangent,
    /// The lower line, slope ω_min²/2.
    pub lower: Tangent,
    /// The required constant inertia I_I, kg·m².
    pub inertia: f64,
    /// The kinetic energy at the start of the cycle, T₀, J.
    pub energy_start: f64,
}

/// Wittenbauer's construction for ω_max and ω_min (rad/s) over the first
/// `span` radians of the cycle (the period of the summed loads; the cycle's
/// length for all of it).
pub fn wittenbauer(
    red: &Reducer,
    cyc: &ReducedCycle,
    sol: &mut Solution,
    omega_max: f64,
    omega_min: f64,
    span: f64,
) -> Result<Wittenbauer, DynamicsError> {
    let (kmax, kmin) = (0.5 * omega_max * omega_max, 0.5 * omega_min * omega_min);
    let tangent = |p: EnergyPoint, slope: f64, b: f64| Tangent {
        slope,
        intercept: b,
        phi: p.phi,
        inertia: p.reduced.inertia,
        energy: p.energy,
    };
    let (pu, bu) = maximize(
        red,
        cyc,
        sol,
        span,
        |e, i| e - kmax * i,
        |p| p.moment - kmax * p.reduced.inertia_derivative,
    )?;
    let (pl, bl) = minimize(
        red,
        cyc,
        sol,
        span,
        |e, i| e - kmin * i,
        |p| p.moment - kmin * p.reduced.inertia_derivative,
    )?;
    let inertia = (bu - bl) / (kmax - kmin);
    Ok(Wittenbauer {
        upper: tangent(pu, kmax, bu),
        lower: tangent(pl, kmin, bl),
        inertia,
        energy_start: kmax * inertia - bu,
    })
}
