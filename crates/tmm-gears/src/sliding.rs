//! Specific sliding (удельное скольжение) along the line of action.

use crate::Pair;

/// One point of the line of action with the specific sliding of both profiles.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlidingPoint {
    /// Distance from N1 along N1N2, m (= ρ1, the pinion's radius of curvature).
    pub s: f64,
    /// Wheel 2's radius of curvature at the contact, m.
    pub rho2: f64,
    /// ϑ1 = 1 − ρ2 / (u·ρ1).
    pub theta1: f64,
    /// ϑ2 = 1 − u·ρ1 / ρ2.
    pub theta2: f64,
}

impl Pair {
    /// Specific sliding of the pinion's profile at `s` from N1:
    /// `ϑ1 = (v1 − v2)/v1 = 1 − ρ2 / (u ρ1)` with the tangential velocities
    /// `v1 = ω1 ρ1`, `v2 = ω2 ρ2`, `ω2/ω1 = 1/u` (Артоболевский И.И., ТММ, 1988, §22.9;
    /// seed 001 §V, seed 003 §15). Infinite at N1.
    #[inline]
    pub fn theta1_at(&self, s: f64) -> f64 {
        1.0 - self.rho2_at(s) / (self.u * s)
    }

    /// Specific sliding of wheel 2's profile: `ϑ2 = 1 − u ρ1 / ρ2` (same source).
    #[inline]
    pub fn theta2_at(&self, s: f64) -> f64 {
        1.0 - self.u * s / self.rho2_at(s)
    }

    /// The largest |ϑ1| on the active line (it is at the pinion's lower active
    /// point, the start of the active line); `None` when that point lies at or
    /// beyond N1 (interference).
    pub fn theta1_max(&self) -> Option<f64> {
        let s = self.s_start;
        (s > 0.0).then(|| self.theta1_at(s).abs().max(self.theta1_at(self.s_end).abs()))
    }

    /// The largest |ϑ2| on the active line (at wheel 2's lower active point,
    /// the end of the active line); `None` when that point lies beyond N2.
    pub fn theta2_max(&self) -> Option<f64> {
        let s = self.s_end;
        (self.rho2_at(s) > 0.0).then(|| self.theta2_at(s).abs().max(self.theta2_at(self.s_start).abs()))
    }

    /// `n ≥ 2` points evenly spaced over the active line, ends included.
    pub fn sliding_table(&self, n: usize) -> Vec<SlidingPoint> {
        let n = n.max(2);
        (0..n)
            .map(|i| {
                let s = self.s_start + (self.s_end - self.s_start) * i as f64 / (n - 1) as f64;
                SlidingPoint {
                    s,
                    rho2: self.rho2_at(s),
                    theta1: self.theta1_at(s),
                    theta2: self.theta2_at(s),
                }
            })
            .collect()
    }
}
