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

    /// The largest |ϑ1| on the real active line. ϑ1 rises monotonically along
    /// N1N2 (from −∞ at N1 to 1 at N2: dϑ1/ds = ρ2(N1)/(u s²) > 0 with
    /// ρ2 = g ∓ s), so the largest magnitude lies at one of the line's ends —
    /// usually the start (the pinion's lower active point), but the end when
    /// the whole line lies near the pole; both ends are compared. `None` when
    /// the line starts at N1 (ϑ1 infinite there).
    pub fn theta1_max(&self) -> Option<f64> {
        let s = self.s_start;
        (s > 0.0).then(|| self.theta1_at(s).abs().max(self.theta1_at(self.s_end).abs()))
    }

    /// The largest |ϑ2| on the real active line: ϑ2 falls monotonically
    /// (to −∞ at N2), so again one of the ends, usually wheel 2's lower active
    /// point (the end of the line); `None` when the line ends at N2.
    pub fn theta2_max(&self) -> Option<f64> {
        let s = self.s_end;
        (self.rho2_at(s) > 0.0).then(|| self.theta2_at(s).abs().max(self.theta2_at(self.s_start).abs()))
    }

    /// `n ≥ 2` points evenly spaced over the real active line, ends included;
    /// an end that lies on N1 or N2 (where ϑ is infinite) is moved half a
    /// step inward, so every value is finite. Empty when the real active line
    /// is empty (no involute contact at all).
    ///
    /// ```
    /// use tmm_gears::{Pair, PairSpec};
    /// // z1 = 10 unshifted is undercut and its line of action runs past N1.
    /// let p = Pair::new(&PairSpec::external(10, 60, 0.001, 0.0, 0.0)).unwrap();
    /// let t = p.sliding_table(11);
    /// assert!(t[0].s > 0.0 && t.iter().all(|q| q.theta1.is_finite() && q.theta1 < 1.0));
    /// ```
    pub fn sliding_table(&self, n: usize) -> Vec<SlidingPoint> {
        let n = n.clamp(2, 1_000_000);
        if self.s_end <= self.s_start {
            // no real active line (the pair has no involute contact at all)
            return Vec::new();
        }
        let step = (self.s_end - self.s_start) / (n - 1) as f64;
        let (mut a, mut b) = (self.s_start, self.s_end);
        if a <= 0.0 {
            a += step / 2.0;
        }
        if self.rho2_at(b) <= 0.0 {
            b -= step / 2.0;
        }
        (0..n)
            .map(|i| {
                let s = a + (b - a) * i as f64 / (n - 1) as f64;
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
