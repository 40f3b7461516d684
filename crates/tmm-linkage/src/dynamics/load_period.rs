//! The period of the summed loads (период суммарной нагрузки): the least
//! part of the machine's cycle over which the reduced moment of the loads
//! M_c and the variable reduced inertia I_II repeat. Each cylinder of a
//! four-stroke engine has a cycle of two turns, but where several of them
//! fire in turn the sum may repeat sooner: in the textbook's opposed
//! two-cylinder engine (cranks at 180°, the right cylinder a cycle half
//! later) it repeats every turn, and the book "restricts the dynamic
//! analysis to [0, 2π], since the summed characteristics are 2π-periodic;
//! each cylinder's cycle is still 4π" (Chernaya & Timofeev 2019, П2,
//! p. 117–126).
//!
//! The test (derived here): the equation of motion
//! d(½·I·ω²)/dφ = M_c + M involves the loads only through M_c(φ) and
//! I_II(φ). If both have a period Φ/j (j a divisor of the cycle's turns),
//! then so have ΔT, T_I = ΔT − ½·I_II·ω_m², the energy–mass curve and the
//! exact motion; the work over the cycle is j times the work over Φ/j, so
//! the constant moment M = −A(Φ)/Φ = −A(Φ/j)/(Φ/j) is the same; and the
//! flywheel found over 0…Φ/j is the one found over 0…Φ. The tables of the
//! grid (n intervals over Φ, n a multiple of j) are compared node by node
//! with those Φ/j later.

use super::reduction::ReducedCycle;

/// Relative tolerance of the comparison: far above the round-off of the
/// kinematics (1e-13 of a value) and far below any real difference of a
/// load between two turns.
pub const TOLERANCE: f64 = 1e-9;

/// The least period of M_c and I_II within the cycle `c` of length
/// `period` (rad) made of `turns` turns: `period / j` for the largest
/// divisor j of `turns` at which both tables repeat, `period` itself when
/// none does.
///
/// ```
/// use tmm_linkage::dynamics::load_period::least_period;
/// // a sum that repeats every half of a two-turn cycle
/// let n = 8;
/// let m: Vec<f64> = (0..=n).map(|k| [1.0, 2.0, 3.0, 4.0][k % 4]).collect();
/// let i = vec![0.5; n + 1];
/// let p = 4.0 * std::f64::consts::PI;
/// assert_eq!(least_period(&m, &i, p, 2), 0.5 * p);
/// let m2: Vec<f64> = (0..=n).map(|k| k as f64).collect();
/// assert_eq!(least_period(&m2, &i, p, 2), p);
/// ```
pub fn least_period(moment: &[f64], inertia: &[f64], period: f64, turns: u32) -> f64 {
    let n = moment.len().saturating_sub(1);
    let scale = |v: &[f64]| v.iter().fold(0.0f64, |a, x| a.max(x.abs())).max(f64::MIN_POSITIVE);
    let (sm, si) = (scale(moment), scale(inertia));
    for j in (2..=turns as usize).rev() {
        if turns as usize % j != 0 || n % j != 0 {
            continue;
        }
        let shift = n / j;
        let repeats = |v: &[f64], s: f64| (0..n - shift).all(|k| (v[k] - v[k + shift]).abs() <= TOLERANCE * s);
        if repeats(moment, sm) && repeats(inertia, si) {
            return period / j as f64;
        }
    }
    period
}

/// [`least_period`] of a reduced cycle.
pub fn of_cycle(c: &ReducedCycle, period: f64, turns: u32) -> f64 {
    least_period(&c.moment, &c.inertia, period, turns)
}
