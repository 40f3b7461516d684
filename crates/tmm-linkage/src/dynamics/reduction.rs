//! The reduced model over the whole cycle (диаграммы приведённых величин):
//! I_II, dI_II/dφ and M_c on a uniform grid of the crank angle, the work of
//! the loads A_c(φ) = ∫₀^φ M_c dφ (работа сил сопротивления), the constant
//! driving moment from zero work over the steady cycle,
//! M_d = −A_c(2π)/(2π) (Артоболевский 1988, steady motion: "за цикл установившегося
//! движения работа движущих сил равна работе сил сопротивления"), its work
//! A_d = M_d·φ, and the change of kinetic energy ΔT = A_d + A_c.
//!
//! The work is integrated piecewise: 3-point Gauss–Legendre on every grid
//! interval, the interval cut at the output's dead positions where a load
//! law jumps or kinks; the error is below 1e-10 of the cycle work on the
//! seeds (docs/dynamics.md). Between grid nodes the model is evaluated
//! exactly ([`ReducedCycle::at`]): the node's work plus the integral from it.

use super::error::DynamicsError;
use super::reduced::{Reduced, Reducer};
use crate::Solution;

/// The reduced model and energy at one crank angle.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct EnergyPoint {
    /// Cycle angle, rad.
    pub phi: f64,
    /// Reduced inertia, moment of the loads and derivative.
    pub reduced: Reduced,
    /// ΔT = A_d + A_c from the start of the cycle, J.
    pub energy: f64,
    /// M_d + M_c, N·m (dΔT/dφ).
    pub moment: f64,
}

/// The reduced model on a uniform grid over one cycle.
#[derive(Debug, Clone)]
pub struct ReducedCycle {
    /// Cycle angle φ of each node (0…2π, `n + 1` nodes), rad.
    pub phi: Vec<f64>,
    /// I_II, kg·m².
    pub inertia: Vec<f64>,
    /// dI_II/dφ, kg·m²/rad.
    pub inertia_derivative: Vec<f64>,
    /// M_c, N·m.
    pub moment: Vec<f64>,
    /// A_c(φ) = ∫₀^φ M_c dφ, J (negative when the loads resist).
    pub work_loads: Vec<f64>,
    /// A_d(φ) = M_d·φ, J.
    pub work_driving: Vec<f64>,
    /// ΔT(φ) = A_d + A_c, J (zero at both ends of the cycle).
    pub energy: Vec<f64>,
    /// The constant moment M_d = −A_c(period)/period, N·m: the driving
    /// moment of a working machine (> 0), the resisting one of an engine (< 0).
    pub driving_moment: f64,
    /// Grid step, rad.
    pub step: f64,
}

impl ReducedCycle {
    /// Evaluate the reduced model at `n + 1` nodes and integrate the work;
    /// the loads must resist on the whole (a working machine), and the
    /// constant moment is the driving one.
    pub fn new(red: &Reducer, n: usize, sol: &mut Solution) -> Result<Self, DynamicsError> {
        Self::build(red, n, sol, false)
    }

    /// As [`ReducedCycle::new`] for an engine: the loads (gas forces) drive
    /// on the whole, and the constant moment M = −A(cycle)/period is the
    /// resistance of the driven machine (negative; Chernaya & Timofeev
    /// 2019, П2: M_прC = −(1/4π)∫₀^{4π} M_прДВ dφ).
    pub fn for_engine(red: &Reducer, n: usize, sol: &mut Solution) -> Result<Self, DynamicsError> {
        Self::build(red, n, sol, true)
    }

    fn build(red: &Reducer, n: usize, sol: &mut Solution, engine: bool) -> Result<Self, DynamicsError> {
        let h = red.period / n as f64;
        let mut c = ReducedCycle {
            phi: Vec::with_capacity(n + 1),
            inertia: Vec::with_capacity(n + 1),
            inertia_derivative: Vec::with_capacity(n + 1),
            moment: Vec::with_capacity(n + 1),
            work_loads: Vec::with_capacity(n + 1),
            work_driving: Vec::with_capacity(n + 1),
            energy: Vec::with_capacity(n + 1),
            driving_moment: 0.0,
            step: h,
        };
        // one sweep solves every node without trigonometry per position
        red.unit.sweep(red.phi_start, red.dir * h, n + 1, sol, |k, s| {
            let r = red.reduce(h * k as f64, s);
            c.phi.push(h * k as f64);
            c.inertia.push(r.inertia);
            c.inertia_derivative.push(r.inertia_derivative);
            c.moment.push(r.moment);
        })?;
        // the node at 2π is the node at 0 (the law at the start of the working stroke)
        c.moment[n] = c.moment[0];
        let mut a = 0.0;
        c.work_loads.push(0.0);
        for k in 0..n {
            a += red.work(c.phi[k], c.phi[k + 1], sol)?;
            c.work_loads.push(a);
        }
        if !(a.is_finite()
            && c.inertia
                .iter()
                .chain(&c.inertia_derivative)
                .chain(&c.moment)
                .all(|x| x.is_finite()))
        {
            return Err(DynamicsError::NonFinite {
                what: "the reduced inertia, moment or work of the loads".into(),
            });
        }
        // conservative loads (weights, fixed forces on the rocker) do zero
        // work up to rounding: a cycle work within 1e-9 of the work of |M_c|
        // is no resistance
        let gross = c.moment.iter().map(|m| m.abs()).sum::<f64>() * h;
        if engine {
            if a <= 1e-9 * gross {
                return Err(DynamicsError::NoDrive { work: a });
            }
        } else if a >= -1e-9 * gross {
            return Err(DynamicsError::NoResistance { work: a });
        }
        let md = -a / red.period;
        c.driving_moment = md;
        for k in 0..=n {
            let ad = md * c.phi[k];
            c.work_driving.push(ad);
            c.energy.push(ad + c.work_loads[k]);
        }
        c.energy[n] = 0.0;
        Ok(c)
    }

    /// Number of intervals.
    pub fn len(&self) -> usize {
        self.phi.len() - 1
    }

    /// `true` when the grid is empty (never, once built).
    pub fn is_empty(&self) -> bool {
        self.phi.len() < 2
    }

    /// The model at any cycle angle (taken modulo 2π): I_II, I_II′ and M_c
    /// solved exactly there, ΔT from the nearest node below plus the integral.
    pub fn at(&self, red: &Reducer, phi: f64, sol: &mut Solution) -> Result<EnergyPoint, DynamicsError> {
        let p = phi.rem_euclid(red.period);
        let n = self.len();
        let k = ((p / self.step) as usize).min(n - 1);
        let w = if p > self.phi[k] { red.work(self.phi[k], p, sol)? } else { 0.0 };
        let r = red.eval(p, sol)?;
        let energy = self.work_loads[k] + w + self.driving_moment * p;
        Ok(EnergyPoint {
            phi,
            reduced: r,
            energy,
            moment: self.driving_moment + r.moment,
        })
    }
}
