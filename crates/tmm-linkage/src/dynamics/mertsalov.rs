//! Mertsalov's method as the course teaches it (метод Н. И. Мерцалова):
//! the kinetic energy of the links of variable inertia is taken at the mean
//! speed, T_II(φ) = I_II(φ)·ω_m²/2; the rest, T_I(φ) = ΔT(φ) − T_II(φ), is
//! the energy of the constant inertia (up to a constant), whose swing
//! ΔT_I = max T_I − min T_I must be held within ±δ/2 of ω_m:
//! I_I = ΔT_I/(δ·ω_m²) (Артоболевский И. И., *Теория механизмов и машин*, 1988, the
//! chapter on the regulation of the machine's motion by a flywheel;
//! Попов С. А., Тимофеев Г. А., *Курсовое проектирование по теории
//! механизмов и механике машин*, 2002, the dynamics sheet).
//!
//! The method is approximate: it takes ω = ω_m in T_II. The error is of
//! order δ (docs/dynamics.md), so it tends to the exact inertia as δ → 0.
//!
//! The swing is taken over the period of the summed loads (the whole cycle,
//! or its part over which M_c and I_II repeat, [`super::load_period`]): T_I
//! repeats with them, so its extremes over the period are those over the
//! cycle (Chernaya & Timofeev 2019, П2: the dynamics over 0…2π of the
//! 4π cycle).

use super::error::DynamicsError;
use super::extremum::{maximize, minimize};
use super::reduced::Reducer;
use super::reduction::ReducedCycle;
use crate::Solution;

/// The result of Mertsalov's method.
#[derive(Debug, Clone, PartialEq)]
pub struct Mertsalov {
    /// T_II(φ) = I_II·ω_m²/2 on the grid, J.
    pub energy_variable: Vec<f64>,
    /// T_I(φ) = ΔT − T_II on the grid, J.
    pub energy_constant: Vec<f64>,
    /// Cycle angle of max T_I (within the span searched), rad.
    pub phi_max: f64,
    /// max T_I, J.
    pub energy_max: f64,
    /// Cycle angle of min T_I (within the span searched), rad.
    pub phi_min: f64,
    /// min T_I, J.
    pub energy_min: f64,
    /// ΔT_I = max T_I − min T_I, J.
    pub energy_swing: f64,
    /// The required constant inertia I_I = ΔT_I/(δ·ω_m²), kg·m².
    pub inertia: f64,
}

/// Mertsalov's method for mean speed `omega_m` (rad/s) and coefficient
/// `delta`, its extremes searched over the first `span` radians of the cycle
/// (the period of the summed loads; the cycle's length for all of it).
pub fn mertsalov(
    red: &Reducer,
    cyc: &ReducedCycle,
    sol: &mut Solution,
    omega_m: f64,
    delta: f64,
    span: f64,
) -> Result<Mertsalov, DynamicsError> {
    let k = 0.5 * omega_m * omega_m;
    let energy_variable: Vec<f64> = cyc.inertia.iter().map(|i| k * i).collect();
    let energy_constant: Vec<f64> = cyc.energy.iter().zip(&energy_variable).map(|(e, t)| e - t).collect();
    let g = |e: f64, i: f64| e - k * i;
    let dg = |p: &super::reduction::EnergyPoint| p.moment - k * p.reduced.inertia_derivative;
    let (pmax, vmax) = maximize(red, cyc, sol, span, g, dg)?;
    let (pmin, vmin) = minimize(red, cyc, sol, span, g, dg)?;
    let swing = vmax - vmin;
    Ok(Mertsalov {
        energy_variable,
        energy_constant,
        phi_max: pmax.phi,
        energy_max: vmax,
        phi_min: pmin.phi,
        energy_min: vmin,
        energy_swing: swing,
        inertia: swing / (delta * omega_m * omega_m),
    })
}
