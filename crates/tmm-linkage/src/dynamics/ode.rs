//! An adaptive Runge–Kutta integrator for the equation of motion: the
//! explicit Dormand–Prince 5(4) pair with the 4th-order error estimate,
//! "first same as last", local extrapolation and the standard step-size
//! control (Hairer E., Nørsett S. P., Wanner G., *Solving Ordinary
//! Differential Equations I*, 2nd ed., Springer 1993, § II.5, table 5.2
//! (coefficients) and § II.4 (step control, eq. 4.11–4.13)). Between steps
//! the solution is read off the cubic Hermite interpolant of the step's end
//! values and slopes (ibid. § II.6), which is 4th-order accurate.
//!
//! The state is two numbers (crank angle, crank speed); nothing allocates.

use super::error::DynamicsError;
// the Dormand–Prince tableau, one copy for both integrators
use super::rk::{
    A21, A31, A32, A41, A42, A43, A51, A52, A53, A54, A61, A62, A63, A64, A65, A71, A73, A74, A75, A76, C2, C3, C4, C5, E1, E3, E4, E5, E6,
    E7,
};

/// A two-component state.
pub type State = [f64; 2];

#[inline(always)]
fn axpy(y: &State, h: f64, terms: &[(f64, &State)]) -> State {
    let mut out = *y;
    for &(c, k) in terms {
        out[0] += h * c * k[0];
        out[1] += h * c * k[1];
    }
    out
}

/// One Dormand–Prince step of size `h` from `(t, y)` with slope `k1`: the
/// 5th-order solution, its slope, and the stages k3…k6 (for the error).
#[inline]
fn stages(
    t: f64,
    y: &State,
    k1: &State,
    h: f64,
    rhs: &mut impl FnMut(f64, &State) -> Result<State, DynamicsError>,
) -> Result<(State, State, [State; 4]), DynamicsError> {
    let k2 = rhs(t + C2 * h, &axpy(y, h, &[(A21, k1)]))?;
    let k3 = rhs(t + C3 * h, &axpy(y, h, &[(A31, k1), (A32, &k2)]))?;
    let k4 = rhs(t + C4 * h, &axpy(y, h, &[(A41, k1), (A42, &k2), (A43, &k3)]))?;
    let k5 = rhs(t + C5 * h, &axpy(y, h, &[(A51, k1), (A52, &k2), (A53, &k3), (A54, &k4)]))?;
    let k6 = rhs(t + h, &axpy(y, h, &[(A61, k1), (A62, &k2), (A63, &k3), (A64, &k4), (A65, &k5)]))?;
    let y1 = axpy(y, h, &[(A71, k1), (A73, &k3), (A74, &k4), (A75, &k5), (A76, &k6)]);
    let k7 = rhs(t + h, &y1)?;
    Ok((y1, k7, [k3, k4, k5, k6]))
}

/// The integrator's state between steps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dopri {
    /// Time, s.
    pub t: f64,
    /// State at `t`.
    pub y: State,
    /// Its derivative at `t`.
    pub f: State,
    /// Time at the start of the last step.
    pub t_prev: f64,
    /// State there.
    pub y_prev: State,
    /// Derivative there.
    pub f_prev: State,
    /// Next step to try, s.
    pub h: f64,
    /// Largest step, s.
    pub h_max: f64,
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance per component.
    pub atol: State,
    /// Steps accepted.
    pub accepted: usize,
    /// Steps rejected.
    pub rejected: usize,
}

impl Dopri {
    /// Start at `(t, y)` with the derivative `f` there.
    pub fn new(t: f64, y: State, f: State, h: f64, h_max: f64, rtol: f64, atol: State) -> Self {
        Dopri {
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
    /// demands). `rhs(t, y)` is the right-hand side.
    pub fn step(&mut self, mut rhs: impl FnMut(f64, &State) -> Result<State, DynamicsError>) -> Result<(), DynamicsError> {
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
            for i in 0..2 {
                let e = h * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i]);
                let sc = self.atol[i] + self.rtol * y[i].abs().max(y1[i].abs());
                err += (e / sc) * (e / sc);
            }
            let err = (err / 2.0).sqrt();
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
    pub fn state_at(
        &self,
        t: f64,
        mut rhs: impl FnMut(f64, &State) -> Result<State, DynamicsError>,
    ) -> Result<(State, State), DynamicsError> {
        let h = t - self.t_prev;
        if h == 0.0 {
            return Ok((self.y_prev, self.f_prev));
        }
        let (y, f, _) = stages(self.t_prev, &self.y_prev, &self.f_prev, h, &mut rhs)?;
        Ok((y, f))
    }

    /// Times inside the last step where the cubic Hermite interpolant of
    /// component `i` has a zero slope (at most two; `NaN` for none).
    pub fn stationary(&self, i: usize) -> [f64; 2] {
        let h = self.t - self.t_prev;
        let (y0, y1, f0, f1) = (self.y_prev[i], self.y[i], self.f_prev[i], self.f[i]);
        // d/ds of the interpolant: a·s² + b·s + c
        let a = 6.0 * (y0 - y1) + 3.0 * h * (f0 + f1);
        let b = -6.0 * (y0 - y1) - h * (4.0 * f0 + 2.0 * f1);
        let c = h * f0;
        let mut out = [f64::NAN; 2];
        let roots = if a.abs() <= 1e-14 * (b.abs() + c.abs()) {
            if b != 0.0 { [-c / b, f64::NAN] } else { [f64::NAN; 2] }
        } else {
            let disc = b * b - 4.0 * a * c;
            if disc < 0.0 {
                [f64::NAN; 2]
            } else {
                // the stable pair of roots
                let q = -0.5 * (b + b.signum() * disc.sqrt());
                [q / a, if q != 0.0 { c / q } else { f64::NAN }]
            }
        };
        for (o, s) in out.iter_mut().zip(roots) {
            if s > 0.0 && s < 1.0 {
                *o = self.t_prev + s * h;
            }
        }
        out
    }

    /// Component `i` of the state at `t` inside the last step (cubic Hermite).
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

    /// The time inside the last step at which component `i` reaches `value`
    /// (it must lie between the step's end values), by bisection on the
    /// interpolant.
    pub fn crossing(&self, i: usize, value: f64) -> f64 {
        let (mut a, mut b) = (self.t_prev, self.t);
        let up = self.y[i] >= self.y_prev[i];
        for _ in 0..200 {
            let m = 0.5 * (a + b);
            if m <= a || m >= b {
                break;
            }
            let below = self.interpolate(i, m) < value;
            if below == up {
                a = m;
            } else {
                b = m;
            }
        }
        0.5 * (a + b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// y'' = −y (harmonic oscillator): y = cos t, y' = −sin t, over 10 periods.
    #[test]
    fn harmonic_oscillator() {
        let rhs = |_t: f64, y: &State| -> Result<State, DynamicsError> { Ok([y[1], -y[0]]) };
        let mut d = Dopri::new(0.0, [1.0, 0.0], [0.0, -1.0], 0.01, 0.5, 1e-10, [1e-12, 1e-12]);
        let end = 20.0 * std::f64::consts::PI;
        while d.t < end {
            d.step(rhs).unwrap();
        }
        let y = d.interpolate(0, end);
        assert!((y - 1.0).abs() < 1e-7, "{y}");
        // the first zero of y' = −sin t after the last step's start: t = kπ
        let mut d = Dopri::new(0.0, [1.0, 0.0], [0.0, -1.0], 0.01, 0.5, 1e-10, [1e-12, 1e-12]);
        while d.y[0] > 0.0 {
            d.step(rhs).unwrap();
        }
        let tz = d.crossing(0, 0.0);
        assert!((tz - std::f64::consts::FRAC_PI_2).abs() < 1e-7, "{tz}");
        assert!(d.accepted < 5000);
    }

    /// y' = y: the error control keeps the relative error near rtol.
    #[test]
    fn exponential_growth() {
        let mut d = Dopri::new(0.0, [1.0, 0.0], [1.0, 0.0], 1e-3, 1.0, 1e-9, [1e-12, 1e-12]);
        while d.t < 5.0 {
            d.step(|_t, y| Ok([y[0], 0.0])).unwrap();
        }
        let exact = d.t.exp();
        assert!((d.y[0] / exact - 1.0).abs() < 1e-7);
    }
}
