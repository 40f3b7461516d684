//! The textbook's rules for the roller radius (выбор радиуса ролика;
//! Chernaya, Timofeev, *ТММ. Курсовое проектирование*, BMSTU 2019, p. 111):
//! `r_рол = (0.25…0.40)·r₀`, and `r_рол < 0.8·ρ_min`, ρ_min the smallest
//! convex radius of curvature of the centre (pitch) profile — and, whatever
//! the margin, below ρ_min itself, else the working profile loops (undercut,
//! docs/cams.md §4).

/// The lower end of the book's range, as a fraction of r₀.
pub const LOW: f64 = 0.25;
/// The upper end of the book's range, as a fraction of r₀.
pub const HIGH: f64 = 0.40;
/// The book's margin against the pitch curve's smallest radius of curvature.
pub const RHO_FRACTION: f64 = 0.8;

/// The rules checked for one roller.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollerCheck {
    /// The roller radius, m.
    pub roller: f64,
    /// 0.25·r₀, m.
    pub low: f64,
    /// 0.40·r₀, m.
    pub high: f64,
    /// The smallest convex radius of curvature of the pitch curve, m (∞ when it has none).
    pub rho_pitch: f64,
    /// 0.8·ρ_min, m.
    pub rho_bound: f64,
}

impl RollerCheck {
    /// Check `roller` against `r0` and the pitch curve's `rho_pitch`.
    ///
    /// ```
    /// // r0 = 60 mm: 15…24 mm; ρmin = 35 mm: below 28 mm
    /// let c = tmm_cams::roller_rules::RollerCheck::new(0.02, 0.06, 0.035);
    /// assert!(c.in_range() && c.below_rho_bound() && c.below_rho());
    /// let big = tmm_cams::roller_rules::RollerCheck::new(0.02, 0.0474, 0.035); // 0.42·r₀
    /// assert!(big.above_low() && !big.below_high() && !big.in_range());
    /// assert!(!tmm_cams::roller_rules::RollerCheck::new(0.02, 0.1, 0.035).in_range()); // 0.2·r₀
    /// ```
    pub fn new(roller: f64, r0: f64, rho_pitch: f64) -> Self {
        RollerCheck {
            roller,
            low: LOW * r0,
            high: HIGH * r0,
            rho_pitch,
            rho_bound: RHO_FRACTION * rho_pitch,
        }
    }
    /// `0.25·r₀ ≤ r_рол ≤ 0.40·r₀`.
    pub fn in_range(&self) -> bool {
        self.roller >= self.low && self.roller <= self.high
    }
    /// `r_рол ≥ 0.25·r₀`.
    pub fn above_low(&self) -> bool {
        self.roller >= self.low
    }
    /// `r_рол ≤ 0.40·r₀`.
    pub fn below_high(&self) -> bool {
        self.roller <= self.high
    }
    /// `r_рол < 0.8·ρ_min`.
    pub fn below_rho_bound(&self) -> bool {
        self.roller < self.rho_bound
    }
    /// `r_рол < ρ_min` (no undercut).
    pub fn below_rho(&self) -> bool {
        self.roller < self.rho_pitch
    }
}
