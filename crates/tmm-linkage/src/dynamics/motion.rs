//! The true motion of the crank over the steady cycle (истинный закон
//! движения звена приведения): from the energy equation
//! I(φ)·ω²/2 = T₀ + ΔT(φ), ω(φ) = √(2·(T₀ + ΔT)/I); from the equation of
//! motion in the energy form, I·ε + ½·I′·ω² = M_d + M_c, the angular
//! acceleration ε(φ) = (M_d + M_c)/I − ω²·I′/(2I) (derived in
//! docs/dynamics.md from the energy equation; Артоболевский 1988, the
//! equation of motion of the link of reduction); the time from the start of
//! the cycle t(φ) = ∫ dφ/ω (trapezoid rule on the grid; 1/ω is smooth, the
//! error is below 1e-9 of the cycle time on 3600 intervals).

use super::error::DynamicsError;
use super::reduced::Reducer;
use super::reduction::ReducedCycle;
use crate::Solution;

/// The steady motion over the grid, speeds in the direction of rotation (> 0).
#[derive(Debug, Clone, PartialEq)]
pub struct Motion {
    /// The constant inertia I_I on the crank shaft (with the flywheel), kg·m².
    pub inertia_constant: f64,
    /// The kinetic energy at the start of the cycle T₀, J.
    pub energy_start: f64,
    /// ω(φ), rad/s.
    pub omega: Vec<f64>,
    /// ε(φ), rad/s².
    pub epsilon: Vec<f64>,
    /// t(φ), s.
    pub time: Vec<f64>,
    /// The time of one cycle, s.
    pub cycle_time: f64,
    /// The largest speed over the cycle (refined between nodes), rad/s.
    pub omega_max: f64,
    /// The smallest, rad/s.
    pub omega_min: f64,
    /// (ω_max + ω_min)/2, rad/s.
    pub omega_mean: f64,
    /// (ω_max − ω_min)/ω_mean.
    pub delta: f64,
}

impl Motion {
    /// The motion on the grid for constant inertia `inertia` and start energy
    /// `t0`, with the refined extremes `omega_max`, `omega_min`.
    pub fn new(cyc: &ReducedCycle, inertia: f64, t0: f64, omega_max: f64, omega_min: f64) -> Result<Self, DynamicsError> {
        let n = cyc.phi.len();
        let mut omega = Vec::with_capacity(n);
        let mut epsilon = Vec::with_capacity(n);
        let mut time = Vec::with_capacity(n);
        let md = cyc.driving_moment;
        for k in 0..n {
            let i = inertia + cyc.inertia[k];
            let w2 = 2.0 * (t0 + cyc.energy[k]) / i;
            if !(w2 > 0.0 && w2.is_finite()) {
                return Err(DynamicsError::NonFinite {
                    what: format!("the crank speed at φ = {:.3}°", cyc.phi[k].to_degrees()),
                });
            }
            omega.push(w2.sqrt());
            epsilon.push((md + cyc.moment[k]) / i - 0.5 * w2 * cyc.inertia_derivative[k] / i);
        }
        let mut t = 0.0;
        time.push(0.0);
        for k in 1..n {
            t += 0.5 * (cyc.phi[k] - cyc.phi[k - 1]) * (1.0 / omega[k] + 1.0 / omega[k - 1]);
            time.push(t);
        }
        let mean = 0.5 * (omega_max + omega_min);
        Ok(Motion {
            inertia_constant: inertia,
            energy_start: t0,
            omega,
            epsilon,
            time,
            cycle_time: t,
            omega_max,
            omega_min,
            omega_mean: mean,
            delta: (omega_max - omega_min) / mean,
        })
    }

    /// The crank's true speed and acceleration at absolute crank angle `phi`
    /// (rad), signed as the mechanism's input (counter-clockwise positive):
    /// what the kinetostatics needs to run with the true motion
    /// (`[forces] crank_motion = "dynamics"`). Evaluated exactly at `phi`,
    /// not interpolated.
    pub fn at(&self, red: &Reducer, cyc: &ReducedCycle, phi: f64, sol: &mut Solution) -> Result<(f64, f64), DynamicsError> {
        let psi = (red.dir * (phi - red.phi_start)).rem_euclid(red.period);
        self.at_cycle(red, cyc, psi, phi, sol)
    }

    /// As [`Motion::at`] at cycle angle `psi` (rad from the start of the
    /// cycle, 0…period; over a 720° cycle the crank angle `phi` alone does
    /// not tell which turn it is).
    pub fn at_cycle(&self, red: &Reducer, cyc: &ReducedCycle, psi: f64, phi: f64, sol: &mut Solution) -> Result<(f64, f64), DynamicsError> {
        let p = cyc.at(red, psi, sol)?;
        let i = self.inertia_constant + p.reduced.inertia;
        let w2 = 2.0 * (self.energy_start + p.energy) / i;
        if !(w2 > 0.0 && w2.is_finite()) {
            return Err(DynamicsError::NonFinite {
                what: format!("the crank speed at φ = {:.3}°", phi.to_degrees()),
            });
        }
        let eps = p.moment / i - 0.5 * w2 * p.reduced.inertia_derivative / i;
        Ok((red.dir * w2.sqrt(), red.dir * eps))
    }
}
