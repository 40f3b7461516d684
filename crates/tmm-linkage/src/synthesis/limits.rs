//! What every synthesis request may add: the allowed pressure angles
//! (допускаемые углы давления) on the working and return strokes, the
//! smallest allowed transmission angle (угол передачи γ = 90° − ϑ), and how
//! the crank turns.
//!
//! Source: seed 000 § 1.2.3 — about 30° on the working stroke, 45° on the
//! return stroke, 10–20° in piston machines.

use super::error::{SynthesisError, positive};

/// Direction of the crank's rotation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Rotation {
    /// Counter-clockwise (ω1 > 0), the default.
    #[default]
    Ccw,
    /// Clockwise (ω1 < 0).
    Cw,
}

impl Rotation {
    /// +1 for counter-clockwise, −1 for clockwise.
    pub fn sign(self) -> f64 {
        match self {
            Rotation::Ccw => 1.0,
            Rotation::Cw => -1.0,
        }
    }
}

/// The crank's drive: direction and speed put into the mechanism description.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Drive {
    /// Direction of rotation.
    pub rotation: Rotation,
    /// |ω1|, rad/s (a placeholder of 1 rad/s unless the task gives it).
    pub omega: f64,
}

impl Default for Drive {
    fn default() -> Self {
        Drive {
            rotation: Rotation::Ccw,
            omega: 1.0,
        }
    }
}

impl Drive {
    /// Signed ω1, rad/s.
    pub fn signed_omega(&self) -> Result<f64, SynthesisError> {
        Ok(self.rotation.sign() * positive("omega", self.omega)?)
    }
}

/// Allowed pressure angles and transmission angle, rad. `None`: no limit.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Limits {
    /// Largest allowed pressure angle on the working stroke [ϑ]_w.
    pub pressure_working: Option<f64>,
    /// Largest allowed pressure angle on the return stroke [ϑ]_r.
    pub pressure_return: Option<f64>,
    /// Smallest allowed transmission angle [γ]_min (the same on both strokes).
    pub transmission_min: Option<f64>,
}

impl Limits {
    /// Validate: each limit in (0, π/2).
    pub fn validate(&self) -> Result<(), SynthesisError> {
        for (name, v) in [
            ("limits.pressure_working", self.pressure_working),
            ("limits.pressure_return", self.pressure_return),
            ("limits.transmission_min", self.transmission_min),
        ] {
            if let Some(x) = v {
                if !(x.is_finite() && x > 0.0 && x < std::f64::consts::FRAC_PI_2) {
                    return Err(SynthesisError::input(
                        name,
                        format!("an angle limit must lie between 0° and 90°, got {:.4}°", x.to_degrees()),
                    ));
                }
            }
        }
        Ok(())
    }

    /// The allowed pressure angle on each stroke (working, return), combining
    /// the pressure limits with the transmission limit (ϑ = 90° − γ).
    ///
    /// ```
    /// let l = tmm_linkage::synthesis::Limits { pressure_working: Some(0.3), pressure_return: None,
    ///     transmission_min: Some(1.2) };
    /// let (w, r) = l.pressure();
    /// assert_eq!(w, Some(0.3)); // the stricter of 0.3 and 90° − 1.2
    /// assert!((r.unwrap() - (std::f64::consts::FRAC_PI_2 - 1.2)).abs() < 1e-15);
    /// ```
    pub fn pressure(&self) -> (Option<f64>, Option<f64>) {
        let t = self.transmission_min.map(|g| std::f64::consts::FRAC_PI_2 - g);
        let both = |p: Option<f64>| match (p, t) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        };
        (both(self.pressure_working), both(self.pressure_return))
    }

    /// Whether any limit is set.
    pub fn any(&self) -> bool {
        self.pressure_working.is_some() || self.pressure_return.is_some() || self.transmission_min.is_some()
    }

    /// Margin of a design against the limits, rad: min over strokes of
    /// ([ϑ] − ϑ); with no limits, the negated largest pressure angle (so the
    /// best design has the largest smallest transmission angle).
    pub fn margin(&self, working: f64, ret: f64) -> f64 {
        let (lw, lr) = self.pressure();
        if lw.is_none() && lr.is_none() {
            return -working.max(ret);
        }
        let mw = lw.map_or(f64::INFINITY, |l| l - working);
        let mr = lr.map_or(f64::INFINITY, |l| l - ret);
        mw.min(mr)
    }
}
