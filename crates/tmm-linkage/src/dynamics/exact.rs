//! The exact steady motion (установившееся движение): the periodic solution
//! of the energy equation I(φ)·ω²/2 = T₀ + ΔT(φ), I = I_I + I_II(φ), with
//! the constant inertia I_I and the start energy T₀ chosen so that the
//! fastest and slowest crank speeds over the cycle are exactly
//! ω_max = ω_m·(1 + δ/2) and ω_min = ω_m·(1 − δ/2) (the definitions
//! ω_m = (ω_max + ω_min)/2, δ = (ω_max − ω_min)/ω_m). Derived here
//! (docs/dynamics.md): with the points a, b where ω² is largest and smallest,
//! the two conditions are linear in (I_I, T₀):
//! T₀ + ΔT_a = k_max·(I_I + I_a), T₀ + ΔT_b = k_min·(I_I + I_b), k = ω²/2.
//! The points move with (I_I, T₀): the iteration finds them anew on the
//! motion ω(φ) itself until nothing changes. When I_I is given (the flywheel
//! is not needed), only T₀ is found, for the mean speed ω_m.
//!
//! The points a, b are searched over the period of the summed loads
//! ([`super::load_period`]): where M_c and I_II repeat within the cycle, ΔT
//! and ω(φ) repeat with them (the work over each period is the same, so the
//! constant moment makes ΔT zero at each period's end), and the extremes of
//! ω over the first period are those over the cycle. The time integration
//! over the whole cycle checks it (docs/dynamics.md).

use super::error::DynamicsError;
use super::extremum::{intervals_in, maximize, minimize};
use super::reduced::Reducer;
use super::reduction::{EnergyPoint, ReducedCycle};
use crate::Solution;

/// The steady motion found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Steady {
    /// The constant part of the reduced inertia I_I, kg·m².
    pub inertia: f64,
    /// The kinetic energy at the start of the cycle T₀, J.
    pub energy_start: f64,
    /// Cycle angle of ω_max (within the span searched), rad.
    pub phi_max: f64,
    /// Cycle angle of ω_min (within the span searched), rad.
    pub phi_min: f64,
    /// ω_max, rad/s.
    pub omega_max: f64,
    /// ω_min, rad/s.
    pub omega_min: f64,
    /// Iterations taken.
    pub iterations: usize,
}

/// What to solve for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Target {
    /// I_I and T₀ for a coefficient δ.
    Delta(f64),
    /// T₀ only, for this I_I (kg·m²).
    Inertia(f64),
}

/// ω² = 2·(T₀ + ΔT)/(I_I + I_II) at a point.
#[inline]
fn omega2(p: &EnergyPoint, inertia: f64, t0: f64) -> f64 {
    2.0 * (t0 + p.energy) / (inertia + p.reduced.inertia)
}

/// Solve the steady motion for mean speed `omega_m` (rad/s), starting from
/// the constant inertia `guess` (Mertsalov's, say), its extreme speeds
/// searched over the first `span` radians of the cycle (the period of the
/// summed loads; the cycle's length for all of it).
pub fn steady(
    red: &Reducer,
    cyc: &ReducedCycle,
    sol: &mut Solution,
    omega_m: f64,
    target: Target,
    guess: f64,
    span: f64,
) -> Result<Steady, DynamicsError> {
    let mut ii = match target {
        Target::Delta(_) => guess,
        Target::Inertia(i) => i,
    };
    let m = intervals_in(cyc, span);
    let (inertia, energy) = (&cyc.inertia[..=m], &cyc.energy[..=m]);
    let imin = inertia.iter().fold(f64::INFINITY, |a, &b| a.min(b));
    if ii + imin <= 0.0 {
        ii = 1e-9 * (1.0 + inertia.iter().fold(0.0f64, |a, &b| a.max(b))) - imin;
    }
    let km = 0.5 * omega_m * omega_m;
    let emax = energy.iter().fold(f64::NEG_INFINITY, |a, &b| a.max(b));
    let emin = energy.iter().fold(f64::INFINITY, |a, &b| a.min(b));
    // any start energy that keeps T > 0 over the cycle
    let mut t0 = (km * (ii + imin) - emin).max(emax - emin + 1e-9 * emax.abs().max(1.0));
    for it in 1..=100 {
        let g = |e: f64, i: f64| (t0 + e) / (ii + i);
        let dg = |p: &EnergyPoint| p.moment * (ii + p.reduced.inertia) - (t0 + p.energy) * p.reduced.inertia_derivative;
        let (a, _) = maximize(red, cyc, sol, span, g, dg)?;
        let (b, _) = minimize(red, cyc, sol, span, g, dg)?;
        let (ni, nt) = match target {
            Target::Delta(delta) => {
                let wmax = omega_m * (1.0 + 0.5 * delta);
                let wmin = omega_m * (1.0 - 0.5 * delta);
                let (kx, kn) = (0.5 * wmax * wmax, 0.5 * wmin * wmin);
                let i = ((a.energy - kx * a.reduced.inertia) - (b.energy - kn * b.reduced.inertia)) / (kx - kn);
                (i, kx * (i + a.reduced.inertia) - a.energy)
            }
            Target::Inertia(i) => {
                let mean = |t: f64| 0.5 * (omega2(&a, i, t).max(0.0).sqrt() + omega2(&b, i, t).max(0.0).sqrt()) - omega_m;
                let lo = -a.energy.min(b.energy);
                let hi = km * (i + a.reduced.inertia.max(b.reduced.inertia)) - a.energy.min(b.energy);
                let t = tmm_geom::root::brent(mean, lo, hi, 1e-15 * hi.abs().max(1.0)).ok_or_else(|| DynamicsError::NoConvergence {
                    what: "the start energy of the steady motion".into(),
                })?;
                (i, t)
            }
        };
        if !(ni.is_finite() && nt.is_finite()) || ni + imin <= 0.0 {
            return Err(DynamicsError::NoConvergence {
                what: "the constant inertia of the steady motion".into(),
            });
        }
        let done = (ni - ii).abs() <= 1e-13 * ni.abs() && (nt - t0).abs() <= 1e-13 * nt.abs();
        ii = ni;
        t0 = nt;
        if done {
            return Ok(Steady {
                inertia: ii,
                energy_start: t0,
                phi_max: a.phi,
                phi_min: b.phi,
                omega_max: omega2(&a, ii, t0).sqrt(),
                omega_min: omega2(&b, ii, t0).sqrt(),
                iterations: it,
            });
        }
    }
    Err(DynamicsError::NoConvergence {
        what: "the steady motion (constant inertia and start energy)".into(),
    })
}
