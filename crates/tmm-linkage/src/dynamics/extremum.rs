//! The extremum over the cycle of a function of the energy curve
//! g(ΔT(φ), I_II(φ)) — the largest and smallest kinetic energy of the
//! flywheel in Mertsalov's method, the supporting lines of Wittenbauer's
//! curve, the fastest and slowest crank speed — found on the grid, then
//! refined between the neighbouring nodes as the zero of its exact
//! derivative g′ = ∂g/∂ΔT·(M_d + M_c) + ∂g/∂I·I_II′ by Brent's method. A
//! maximum at a kink (a load law that jumps at a dead position) is the
//! node itself or the jump, which Brent's method finds as the sign change.
//!
//! The search walks the first `span` radians of the cycle: the whole cycle,
//! or the period of the summed loads ([`super::load_period`]) where they
//! repeat within it — then g repeats too, and its extremes over the first
//! period are those over the cycle.

use super::error::DynamicsError;
use super::reduced::Reducer;
use super::reduction::{EnergyPoint, ReducedCycle};
use crate::Solution;

/// The number of grid intervals in the first `span` radians of the cycle
/// (1…all of them): the nodes the extremes are searched on.
pub fn intervals_in(cyc: &ReducedCycle, span: f64) -> usize {
    let n = cyc.len();
    if span.is_finite() && span > 0.0 {
        ((span / cyc.step).round() as usize).clamp(1, n)
    } else {
        n
    }
}

/// Largest value over the first `span` radians of the cycle (see the
/// module's header) of `g(ΔT, I_II)` whose derivative along the cycle is
/// `dg(point)`. Returns the point where it is reached, its angle within
/// 0…span, and the value.
pub fn maximize(
    red: &Reducer,
    cyc: &ReducedCycle,
    sol: &mut Solution,
    span: f64,
    g: impl Fn(f64, f64) -> f64,
    dg: impl Fn(&EnergyPoint) -> f64,
) -> Result<(EnergyPoint, f64), DynamicsError> {
    let n = intervals_in(cyc, span);
    let mut j = 0;
    let mut best = f64::NEG_INFINITY;
    for k in 0..n {
        let v = g(cyc.energy[k], cyc.inertia[k]);
        if v > best {
            best = v;
            j = k;
        }
    }
    let h = cyc.step;
    let pj = cyc.phi[j];
    let node = cyc.at(red, pj, sol)?;
    let mut out = (node, g(node.energy, node.reduced.inertia));
    let mut err = None;
    for (a, b) in [(pj - h, pj), (pj, pj + h)] {
        let da = dg(&cyc.at(red, a, sol)?);
        let db = dg(&cyc.at(red, b, sol)?);
        if !(da > 0.0 && db < 0.0) {
            continue;
        }
        let root = tmm_geom::root::brent(
            |x| match cyc.at(red, x, sol) {
                Ok(p) => dg(&p),
                Err(e) => {
                    err = Some(e);
                    f64::NAN
                }
            },
            a,
            b,
            1e-13,
        );
        if let Some(e) = err.take() {
            return Err(e);
        }
        if let Some(x) = root {
            let p = cyc.at(red, x, sol)?;
            let v = g(p.energy, p.reduced.inertia);
            if v > out.1 {
                out = (p, v);
            }
        }
    }
    if !out.1.is_finite() {
        return Err(DynamicsError::NonFinite {
            what: "an extremum over the cycle".into(),
        });
    }
    // report the angle in 0…span (the node n is the node 0 of the next period)
    out.0.phi = out.0.phi.rem_euclid(cyc.step * n as f64);
    Ok(out)
}

/// Smallest value of `g` over the first `span` radians (the largest of −g).
pub fn minimize(
    red: &Reducer,
    cyc: &ReducedCycle,
    sol: &mut Solution,
    span: f64,
    g: impl Fn(f64, f64) -> f64,
    dg: impl Fn(&EnergyPoint) -> f64,
) -> Result<(EnergyPoint, f64), DynamicsError> {
    let (p, v) = maximize(red, cyc, sol, span, |e, i| -g(e, i), |p| -dg(p))?;
    Ok((p, -v))
}
