//! Runge–Kutta integrators for a state of `N` numbers (the unsteady stroke
//! carries the crank angle, its speed, the motor's torque and the motor's
//! work): the adaptive Dormand–Prince 5(4) pair with "first same as last",
//! local extrapolation and the standard step-size control (Hairer E.,
//! Nørsett S. P., Wanner G., *Solving Ordinary Differential Equations I*,
//! 2nd ed., Springer 1993, § II.5, table 5.2 (coefficients) and § II.4
//! (step control, eq. 4.11–4.13)), the same pair as [`super::ode`] for two
//! components; and the classical fixed-step 4th-order method (ibid. § II.1,
//! table 1.2, "the" Runge–Kutta method), used as the independent second
//! integrator of the checks.
//!
//! Nothing allocates: the states are arrays.
//!
//! ```
//! use tmm_linkage::dynamics::rk::{Adaptive, rk4};
//! // y' = −y from 1: e^(−t)
//! let f = |_t: f64, y: &[f64; 1]| -> Result<[f64; 1], tmm_linkage::dynamics::DynamicsError> { Ok([-y[0]]) };
//! let mut a = Adaptive::new(0.0, [1.0], [-1.0], 0.1, 1.0, 1e-10, [1e-12]);
//! while a.t < 2.0 { a.step(f).unwrap(); }
//! let (y, _) = a.state_at(2.0, f).unwrap();
//! assert!((y[0] - (-2.0f64).exp()).abs() < 1e-9);
//! let y4 = rk4(0.0, [1.0], 2.0, 200, f).unwrap();
//! assert!((y4[0] - (-2.0f64).exp()).abs() < 1e-8);
//! ```

use super::error::DynamicsError;

// The Dormand–Prince 5(4) tableau (Hairer, Nørsett, Wanner, table 5.2),
// shared with the two-component integrator of [`super::ode`].

pub(super) const C2: f64 = 1.0 / 5.0;
pub(super) const C3: f64 = 3.0 / 10.0;
pub(super) const C4: f64 = 4.0 / 5.0;
pub(super) const C5: f64 = 8.0 / 9.0;
pub(super) const A21: f64 = 1.0 / 5.0;
pub(super) const A31: f64 = 3.0 / 40.0;
pub(super) const A32: f64 = 9.0 / 40.0;
pub(super) const A41: f64 = 44.0 / 45.0;
pub(super) const A42: f64 = -56.0 / 15.0;
pub(super) const A43: f64 = 32.0 / 9.0;
pub(super) const A51: f64 = 19372.0 / 6561.0;
pub(super) const A52: f64 = -25360.0 / 2187.0;
pub(super) const A53: f64 = 64448.0 / 6561.0;
pub(super) const A54: f64 = -212.0 / 729.0;
pub(super) const A61: f64 = 9017.0 / 3168.0;
pub(super) const A62: f64 = -355.0 / 33.0;
pub(super) const A63: f64 = 46732.0 / 5247.0;
pub(super) const A64: f64 = 49.0 / 176.0;
pub(super) const A65: f64 = -5103.0 / 18656.0;
pub(super) const A71: f64 = 35.0 / 384.0;
pub(super) const A73: f64 = 500.0 / 1113.0;
pub(super) const A74: f64 = 125.0 / 192.0;
pub(super) const A75: f64 = -2187.0 / 6784.0;
pub(super) const A76: f64 = 11.0 / 84.0;
pub(super) const E1: f64 = 71.0 / 57600.0;
pub(super) const E3: f64 = -71.0 / 16695.0;
pub(super) const E4: f64 = 71.0 / 1920.0;
pub(super) const E5: f64 = -17253.0 / 339200.0;
pub(super) const E6: f64 = 22.0 / 525.0;
pub(super) const E7: f64 = -1.0 / 40.0;

#[inline(always)]
fn axpy<const N: usize>(y: &[f64; N], h: f64, terms: &[(f64, &[f64; N])]) -> [f64; N] {
    let mut out = *y;
    for &(c, k) in terms {
        for i in 0..N {
            out[i] += h * c * k[i];
        }
    }
    out
}

/// The right-hand side y' = f(t, y).
pub trait Rhs<const N: usize>: FnMut(f64, &[f64; N]) -> Result<[f64; N], DynamicsError> {}
impl<const N: usize, F: FnMut(f64, &[f64; N]) -> Result<[f64; N], DynamicsError>> Rhs<N> for F {}

type Stages<const N: usize> = ([f64; N], [f64; N], [[f64; N]; 4]);

/// One Dormand–Prince step of size `h` from `(t, y)` with slope `k1`: the
/// 5th-order solution, its slope, and the stages k3…k6 (for the error).
#[inline]
fn stages<const N: usize>(t: f64, y: &[f64; N], k1: &[f64; N], h: f64, rhs: &mut impl Rhs<N>) -> Result<Stages<N>, DynamicsError> {
    let k2 = rhs(t + C2 * h, &axpy(y, h, &[(A21, k1)]))?;
    let k3 = rhs(t + C3 * h, &axpy(y, h, &[(A31, k1), (A32, &k2)]))?;
    let k4 = rhs(t + C4 * h, &axpy(y, h, &[(A41, k1), (A42, &k2), (A43, &k3)]))?;
    let k5 = rhs(t + C5 * h, &axpy(y, h, &[(A51, k1), (A52, &k2), (A53, &k3), (A54, &k4)]))?;
    let k6 = rhs(t + h, &axpy(y, h, &[(A61, k1), (A62, &k2), (A63, &k3), (A64, &k4), (A65, &k5)]))?;
    let y1 = axpy(y, h, &[(A71, k1), (A73, &k3), (A74, &k4), (A75, &k5), (A76, &k6)]);
    let k7 = rhs(t + h, &y1)?;
    Ok((y1, k7, [k3, k4, k5, k6]))
}

/// The adaptive Dormand–Prince 5(4) integrator's state between steps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Adaptive<const N: usize> {
    /// Time, s.
    pub t: f64,
    /// State at `t`.
    pub y: [f64; N],
    /// Its derivative at `t`.
    pub f: [f64; N],
    /// Time at the start of the last step.
    pub t_prev: f64,
    /// State there.
    pub y_prev: [f64; N],
    /// Derivative there.
    pub f_prev: [f64; N],
    /// Next step to try, s.
    pub h: f64,
    /// Largest step, s.
    pub h_max: f64,
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance per component.
    pub atol: [f64; N],
    /// Steps accepted.
    pub accepted: usize,
    /// Steps rejected.
    pub rejected: usize,
}

impl<const N: usize> Adaptive<N> {
    /// Start at `(t, y)` with the derivative `f` there, first step `h`.
    pub fn new(t: f64, y: [f64; N], f: [f64; N], h: f64, h_max: f64, rtol: f64, atol: [f64; N]) -> Self {
        Adaptive {
            t,
            y,
            f,
            t_prev: t,
            y_prev: y,
            f_prev: f,
            h: h.min(h_max),
            h_max,
            rtol,
            atol,
            accepted: 0,
            rejected: 0,
        }
    }

    /// One accepted step (retrying with smaller steps as the error control
    /// demands).
    pub fn step(&mut self, mut rhs: impl Rhs<N>) -> Result<(), DynamicsError> {
        let (t, y, k1) = (self.t, self.y, self.f);
        loop {
            let h = self.h;
            if !(h.is_finite() && h > 1e-14 * t.abs().max(1e-3)) {
                return Err(DynamicsError::NoConvergence {
                    what: format!("the time integration (step size underflow at t = {t:.6} s)"),
                });
            }
            let (y1, k7, [k3, k4, k5, k6]) = stages(t, &y, &k1, h, &mut rhs)?;
            let mut err = 0.0;
            for i in 0..N {
                let e = h * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i]);
                let sc = self.atol[i] + self.rtol * y[i].abs().max(y1[i].abs());
                err += (e / sc) * (e / sc);
            }
            let err = (err / N as f64).sqrt();
            if !err.is_finite() {
                self.h *= 0.25;
                self.rejected += 1;
                continue;
            }
            // eq. (4.13) with safety factor 0.9, the factor kept in [0.2, 5]
            let fac = if err == 0.0 { 5.0 } else { (0.9 * err.powf(-0.2)).clamp(0.2, 5.0) };
            if err <= 1.0 {
                self.t_prev = t;
                self.y_prev = y;
                self.f_prev = k1;
                self.t = t + h;
                self.y = y1;
                self.f = k7;
                self.h = (h * fac).min(self.h_max);
                self.accepted += 1;
                return Ok(());
            }
            self.h = h * fac.min(1.0);
            self.rejected += 1;
        }
    }

    /// The state at time `t` inside the last step by a Dormand–Prince step
    /// from its start (5th order, as accurate as the steps themselves), and
    /// its slope there.
    pub fn state_at(&self, t: f64, mut rhs: impl Rhs<N>) -> Result<([f64; N], [f64; N]), DynamicsError> {
        let h = t - self.t_prev;
        if h == 0.0 {
            return Ok((self.y_prev, self.f_prev));
        }
        let (y, f, _) = stages(self.t_prev, &self.y_prev, &self.f_prev, h, &mut rhs)?;
        Ok((y, f))
    }

    /// Component `i` of the state at `t` inside the last step, on the cubic
    /// Hermite interpolant of the step's end values and slopes (ibid.
    /// § II.6; 4th order).
    #[inline]
    pub fn interpolate(&self, i: usize, t: f64) -> f64 {
        let h = self.t - self.t_prev;
        if h <= 0.0 {
            return self.y[i];
        }
        let s = (t - self.t_prev) / h;
        let (s2, s3) = (s * s, s * s * s);
        let h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
        let h10 = s3 - 2.0 * s2 + s;
        let h01 = -2.0 * s3 + 3.0 * s2;
        let h11 = s3 - s2;
        h00 * self.y_prev[i] + h10 * h * self.f_prev[i] + h01 * self.y[i] + h11 * h * self.f[i]
    }

    /// The time inside the last step at which component `i` reaches
    /// `value`, which must lie between the step's end values: bisection on
    /// the interpolant, then Newton steps on exact Dormand–Prince steps from
    /// the step's start (the slope of component `i` is `f[i]`). Returns the
    /// time, the state and its slope there.
    pub fn locate(&self, i: usize, value: f64, mut rhs: impl Rhs<N>) -> Result<(f64, [f64; N], [f64; N]), DynamicsError> {
        let (mut a, mut b) = (self.t_prev, self.t);
        let up = self.y[i] >= self.y_prev[i];
        for _ in 0..60 {
            let m = 0.5 * (a + b);
            if m <= a || m >= b {
                break;
            }
            if (self.interpolate(i, m) < value) == up {
                a = m;
            } else {
                b = m;
            }
        }
        let mut tc = 0.5 * (a + b);
        let (mut y, mut f) = self.state_at(tc, &mut rhs)?;
        for _ in 0..3 {
            if f[i] == 0.0 || !f[i].is_finite() {
                break;
            }
            let next = (tc - (y[i] - value) / f[i]).clamp(self.t_prev, self.t);
            if next == tc {
                break;
            }
            tc = next;
            (y, f) = self.state_at(tc, &mut rhs)?;
        }
        Ok((tc, y, f))
    }
}

/// The classical 4th-order Runge–Kutta method with `n` equal steps from
/// `(t0, y0)` to `t1` (Hairer, Nørsett, Wanner 1993, § II.1, table 1.2).
pub fn rk4<const N: usize>(t0: f64, y0: [f64; N], t1: f64, n: usize, mut rhs: impl Rhs<N>) -> Result<[f64; N], DynamicsError> {
    let h = (t1 - t0) / n.max(1) as f64;
    let mut y = y0;
    for k in 0..n.max(1) {
        let t = t0 + h * k as f64;
        let k1 = rhs(t, &y)?;
        let k2 = rhs(t + 0.5 * h, &axpy(&y, h, &[(0.5, &k1)]))?;
        let k3 = rhs(t + 0.5 * h, &axpy(&y, h, &[(0.5, &k2)]))?;
        let k4 = rhs(t + h, &axpy(&y, h, &[(1.0, &k3)]))?;
        y = axpy(&y, h, &[(1.0 / 6.0, &k1), (2.0 / 6.0, &k2), (2.0 / 6.0, &k3), (1.0 / 6.0, &k4)]);
    }
    Ok(y)
}
