//! The control (driving) force of the cylinder (управляющая сила), BMSTU
//! textbook (Chernaya & Timofeev 2019), appendix П5, p. 146: along the
//! cylinder's axis between piston and cylinder, F_H on [0, s_c], linear
//! from F_H to F_K on [s_c, s_max]. F_K = |F_прC(s_max)| holds the load in
//! the final position; F_H makes the work over the travel zero with the
//! resistance's A_C (start from rest, stop at rest):
//! F_H s_c + (F_H + F_K)(s_max − s_c)/2 = −A_C, so
//! F_H = (−A_C − F_K (s_max − s_c)/2) / ((s_max + s_c)/2).

use crate::dynamics::DynamicsError;
use crate::dynamics::error::show;

/// A piecewise-linear control force.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ControlLaw {
    /// s_c, m: where the force starts to change.
    pub switch: f64,
    /// s_max, m.
    pub travel: f64,
    /// F_H, N: the level on [0, s_c].
    pub start: f64,
    /// F_K, N: the force at s_max.
    pub end: f64,
}

impl ControlLaw {
    /// The law whose work over the travel is −`resistance_work` (A_C, J),
    /// ending at F_K = |`end_resistance`| (F_прC(s_max), N).
    ///
    /// ```
    /// use tmm_linkage::linear::ControlLaw;
    /// let c = ControlLaw::zero_work(0.18, 0.25, -300.0, -1000.0).unwrap();
    /// assert_eq!(c.end, 1000.0);
    /// // its work over the travel returns the resistance's
    /// assert!((c.work(0.0, 0.25) - 300.0).abs() < 1e-9);
    /// ```
    pub fn zero_work(switch: f64, travel: f64, resistance_work: f64, end_resistance: f64) -> Result<Self, DynamicsError> {
        if !(travel.is_finite() && travel > 0.0) {
            return Err(DynamicsError::spec("cylinder.h_max", "the travel must be positive"));
        }
        if !(switch.is_finite() && switch > 0.0 && switch <= travel) {
            return Err(DynamicsError::spec(
                "cylinder.switch",
                format!(
                    "the control force's switch point s_c = {} m must lie within the piston's travel, 0 < s_c ≤ s_max = {} m",
                    show(switch),
                    show(travel)
                ),
            ));
        }
        let end = end_resistance.abs();
        let start = (-resistance_work - end * 0.5 * (travel - switch)) / (0.5 * (travel + switch));
        Ok(ControlLaw {
            switch,
            travel,
            start,
            end,
        })
    }

    /// F_прДВ(s), N (the level F_H before 0 and F_K past s_max).
    pub fn force(&self, s: f64) -> f64 {
        if s <= self.switch || self.travel <= self.switch {
            self.start
        } else if s >= self.travel {
            self.end
        } else {
            self.start + (self.end - self.start) * (s - self.switch) / (self.travel - self.switch)
        }
    }

    /// dF_прДВ/ds, N/m (the right-hand derivative at s_c).
    pub fn slope(&self, s: f64) -> f64 {
        if s < self.switch || s > self.travel || self.travel <= self.switch {
            0.0
        } else {
            (self.end - self.start) / (self.travel - self.switch)
        }
    }

    /// ∫ F_прДВ ds from `a` to `b` (J), exactly: the trapezoid of each
    /// linear piece.
    pub fn work(&self, a: f64, b: f64) -> f64 {
        let (lo, hi, sign) = if a <= b { (a, b, 1.0) } else { (b, a, -1.0) };
        let mut w = 0.0;
        let mut x = lo;
        for brk in [self.switch, self.travel] {
            if brk > x && brk < hi {
                w += 0.5 * (self.force(x) + self.force(brk)) * (brk - x);
                x = brk;
            }
        }
        w += 0.5 * (self.force(x) + self.force(hi)) * (hi - x);
        sign * w
    }
}
