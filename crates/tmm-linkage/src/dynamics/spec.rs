//! What the user gives for the dynamics of the machine (динамика машины):
//! the coefficient of speed fluctuation δ (коэффициент неравномерности хода),
//! the driving moment (движущий момент) — constant, as the course assumes, or
//! an induction motor's characteristic through a gear ratio —, the constant
//! inertias already on the crank and motor shafts (rotor, gearbox), and the
//! flywheel's place, material and shape. The loads are those of the
//! kinetostatics ([`crate::forces::Loads`]); the nominal crank speed is the
//! mechanism's input speed.

use super::error::{DynamicsError, show};
use crate::forces::stroke::Working;

/// Steel density used by default for the flywheel, kg/m³.
pub const STEEL_DENSITY: f64 = 7850.0;

/// An induction motor (асинхронный двигатель) described by its synchronous
/// speed, nominal speed and nominal torque, its torque linear between them
/// (the working branch of the characteristic), driving the crank through a
/// gear ratio.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Motor {
    /// Synchronous speed ω_s, rad/s (> nominal).
    pub synchronous_speed: f64,
    /// Nominal speed ω_n, rad/s (0 < ω_n < ω_s).
    pub nominal_speed: f64,
    /// Nominal torque M_n on the motor shaft, N·m (> 0).
    pub nominal_torque: f64,
    /// Gear ratio u = ω_motor / ω_crank (передаточное отношение, > 0).
    pub ratio: f64,
}

impl Motor {
    /// Torque on the motor shaft at motor speed `w`, N·m:
    /// M = M_n·(ω_s − w)/(ω_s − ω_n) (the straight line through the synchronous point (ω_s, 0) and the
    /// nominal point (ω_n, M_n), the linearised working branch of the
    /// mechanical characteristic; docs/dynamics.md).
    ///
    /// ```
    /// use tmm_linkage::dynamics::Motor;
    /// let m = Motor { synchronous_speed: 157.08, nominal_speed: 150.0, nominal_torque: 20.0, ratio: 2.0 };
    /// assert!((m.torque(150.0) - 20.0).abs() < 1e-12);
    /// assert!(m.torque(157.08).abs() < 1e-12);
    /// ```
    #[inline]
    pub fn torque(&self, w: f64) -> f64 {
        self.nominal_torque * (self.synchronous_speed - w) / (self.synchronous_speed - self.nominal_speed)
    }

    /// The driving moment reduced to the crank at crank speed `omega`, N·m:
    /// M_d = u·M(u·ω) (equal power through a loss-free gear).
    #[inline]
    pub fn crank_moment(&self, omega: f64) -> f64 {
        self.ratio * self.torque(self.ratio * omega)
    }
}

/// The driving moment on the crank.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DrivingMoment {
    /// Constant over the cycle, from zero total work over the steady cycle
    /// (the course's assumption).
    Constant,
    /// An induction motor's characteristic (the flywheel is still sized
    /// with the constant moment it delivers on average; the motor drives the
    /// time integration: the run-up and the simulated steady cycle).
    Motor(Motor),
    /// An engine: the loads (gas forces) drive, and the driven machine's
    /// resistance is a constant moment from zero total work over the
    /// machine's cycle (Chernaya & Timofeev 2019, П2).
    Engine,
}

/// Which shaft carries the flywheel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FlywheelPlace {
    /// On the crank shaft.
    Crank,
    /// On the motor shaft (its inertia is the crank-shaft value / u²).
    Motor,
    /// On another shaft turning [`FlywheelSpec::speed_ratio`] times as fast
    /// as the crank (its inertia is the crank-shaft value / ratio²; the
    /// book's П3 puts it on a shaft of the reducer, I_M = I_прM·(12/22)²).
    Shaft,
}

/// The flywheel's shape, in proportions of its outer diameter D.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FlywheelShape {
    /// A solid disc (диск) of width b = ψ·D.
    Disc {
        /// ψ = b/D (> 0).
        width_ratio: f64,
    },
    /// A rim (обод) of width b = ψ_b·D and radial thickness h = ψ_h·D; the
    /// hub and spokes are neglected.
    Rim {
        /// ψ_b = b/D (> 0).
        width_ratio: f64,
        /// ψ_h = h/D (0 < ψ_h < 0.5; 0.5 would be the disc).
        thickness_ratio: f64,
    },
}

/// The flywheel to size.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlywheelSpec {
    /// Its shaft.
    pub place: FlywheelPlace,
    /// Material density ρ, kg/m³.
    pub density: f64,
    /// Its shape.
    pub shape: FlywheelShape,
    /// With [`FlywheelPlace::Shaft`]: ω_shaft/ω_crank (> 0); else unused.
    pub speed_ratio: f64,
}

impl Default for FlywheelSpec {
    fn default() -> Self {
        FlywheelSpec {
            place: FlywheelPlace::Crank,
            density: STEEL_DENSITY,
            shape: FlywheelShape::Disc { width_ratio: 0.2 },
            speed_ratio: 1.0,
        }
    }
}

/// The most intervals of the crank angle over the cycle (0.01° apart): every
/// interval is solved and kept, so the bound keeps the time and the files
/// small.
pub const MAX_POINTS: usize = 36_000;

/// The largest nominal motor torque accepted, N·m (the largest motors built
/// give some 1e7 N·m; beyond 1e9 the reduced moments and their products
/// with the speeds leave the range where the integration stays exact).
pub const MAX_TORQUE: f64 = 1e9;

/// The largest constant inertia accepted on a shaft, kg·m² (the largest
/// flywheels built, of rolling mills and pulsed generators, have some
/// 1e6–1e7 kg·m²; beyond 1e12 the kinetic energies at the crank's speeds
/// leave the range where the energy equation is computed exactly).
pub const MAX_INERTIA: f64 = 1e12;

/// The largest synchronous speed of a motor accepted, rad/s (about
/// 1e7 rpm, some fifty times the fastest electric machines built).
pub const MAX_MOTOR_SPEED: f64 = 1e6;

/// The gear ratio u = ω_motor/ω_crank accepted: from 1/[`MAX_RATIO`] to
/// [`MAX_RATIO`] (u² multiplies the motor shaft's inertia and the slope of
/// its characteristic at the crank).
pub const MAX_RATIO: f64 = 1e6;

/// The whole specification of the dynamics (the `[dynamics]` section).
#[derive(Debug, Clone, PartialEq)]
pub struct DynamicsSpec {
    /// Coefficient of speed fluctuation δ = (ω_max − ω_min)/ω_m, 0 < δ < 1.
    pub delta: f64,
    /// Intervals of the crank angle over the cycle (≥ 360, a multiple of 12
    /// so that the course's 12 positions fall on the grid).
    pub points: usize,
    /// The driving moment.
    pub driving: DrivingMoment,
    /// Constant inertia on the crank shaft besides the crank itself (a gear
    /// wheel, a coupling), kg·m².
    pub inertia_crank_shaft: f64,
    /// Constant inertia on the motor shaft (rotor, gearbox reduced to the motor
    /// shaft), kg·m²; needs a motor or [`DynamicsSpec::motor_speed`] (for its ratio).
    pub inertia_motor_shaft: f64,
    /// The motor shaft's speed when the driving moment is not a motor's
    /// characteristic (rad/s, > 0): the motor shaft then turns
    /// u = motor_speed/ω_m times as fast as the crank (П3: the rotor's
    /// I₀ reduced to the crank as I₀·(ω_рот/ω_cp)², Chernaya & Timofeev
    /// 2019, p. 133).
    pub motor_speed: Option<f64>,
    /// The flywheel.
    pub flywheel: FlywheelSpec,
    /// Which stroke of the output is the working one (for resistance laws).
    pub working: Working,
}

impl DynamicsSpec {
    /// The course's defaults for a given δ: 3600 intervals, a constant driving
    /// moment, nothing else on the shafts, a steel disc on the crank shaft
    /// with b/D = 0.2.
    ///
    /// ```
    /// let s = tmm_linkage::dynamics::DynamicsSpec::new(0.02);
    /// assert!(s.check().is_ok());
    /// assert!(tmm_linkage::dynamics::DynamicsSpec::new(1.0).check().is_err());
    /// ```
    pub fn new(delta: f64) -> Self {
        DynamicsSpec {
            delta,
            points: 3600,
            driving: DrivingMoment::Constant,
            inertia_crank_shaft: 0.0,
            inertia_motor_shaft: 0.0,
            motor_speed: None,
            flywheel: FlywheelSpec::default(),
            working: Working::Slower,
        }
    }

    /// The motor, if the driving moment is one.
    pub fn motor(&self) -> Option<&Motor> {
        match &self.driving {
            DrivingMoment::Motor(m) => Some(m),
            DrivingMoment::Constant | DrivingMoment::Engine => None,
        }
    }

    /// The motor shaft's speed ratio u = ω_motor/ω_crank at the crank's
    /// nominal speed `omega_m`: the motor's gear ratio, else
    /// `motor_speed/ω_m`, else 1 (no motor shaft).
    ///
    /// ```
    /// let mut s = tmm_linkage::dynamics::DynamicsSpec::new(0.05);
    /// s.motor_speed = Some(100.0);
    /// assert!((s.motor_ratio(4.0) - 25.0).abs() < 1e-12);
    /// ```
    pub fn motor_ratio(&self, omega_m: f64) -> f64 {
        match (self.motor(), self.motor_speed) {
            (Some(m), _) => m.ratio,
            (None, Some(w)) => w / omega_m.abs(),
            (None, None) => 1.0,
        }
    }

    /// Check every field on its own (the motor against the crank's speed is
    /// checked with the mechanism).
    pub fn check(&self) -> Result<(), DynamicsError> {
        let e = |f: &str, m: String| DynamicsError::spec(f, m);
        if !(self.delta.is_finite() && self.delta > 0.0 && self.delta < 1.0) {
            return Err(e(
                "dynamics.delta",
                format!(
                    "the coefficient of speed fluctuation must be in (0, 1) (typically 0.01…0.1), not {}",
                    show(self.delta)
                ),
            ));
        }
        if self.points < 360 || self.points > MAX_POINTS || self.points % 12 != 0 {
            return Err(e(
                "dynamics.points",
                format!(
                    "the cycle needs 360 to {MAX_POINTS} intervals (0.01° apart at most), a multiple of 12; not {}",
                    self.points
                ),
            ));
        }
        for (f, v) in [
            ("dynamics.inertia.crank_shaft", self.inertia_crank_shaft),
            ("dynamics.inertia.motor_shaft", self.inertia_motor_shaft),
        ] {
            if !(v.is_finite() && (0.0..=MAX_INERTIA).contains(&v)) {
                return Err(e(
                    f,
                    format!(
                        "a moment of inertia must be ≥ 0 and at most {MAX_INERTIA:e} kg·m² (beyond the largest flywheels built), not {}",
                        show(v)
                    ),
                ));
            }
        }
        if let Some(m) = self.motor() {
            if !(m.synchronous_speed.is_finite() && m.synchronous_speed > 0.0 && m.synchronous_speed <= MAX_MOTOR_SPEED) {
                return Err(e(
                    "dynamics.motor.synchronous_speed",
                    format!(
                        "must be > 0 and at most {MAX_MOTOR_SPEED:e} rad/s (about 1e7 rpm), not {} rad/s",
                        show(m.synchronous_speed)
                    ),
                ));
            }
            if !(m.nominal_speed.is_finite() && m.nominal_speed > 0.0 && m.nominal_speed < m.synchronous_speed) {
                return Err(e(
                    "dynamics.motor.nominal_speed",
                    format!(
                        "the nominal speed must be > 0 and below the synchronous speed {} rad/s, not {} rad/s",
                        show(m.synchronous_speed),
                        show(m.nominal_speed)
                    ),
                ));
            }
            if !(m.nominal_torque.is_finite() && m.nominal_torque > 0.0 && m.nominal_torque <= MAX_TORQUE) {
                return Err(e(
                    "dynamics.motor.nominal_torque",
                    format!(
                        "must be > 0 and at most {MAX_TORQUE:e} N·m (beyond the largest motors built), not {:e}",
                        m.nominal_torque
                    ),
                ));
            }
            if !(m.ratio.is_finite() && (1.0 / MAX_RATIO..=MAX_RATIO).contains(&m.ratio)) {
                return Err(e(
                    "dynamics.motor.ratio",
                    format!(
                        "the gear ratio ω_motor/ω_crank must be from {:e} to {MAX_RATIO:e}, not {}",
                        1.0 / MAX_RATIO,
                        show(m.ratio)
                    ),
                ));
            }
        } else if let Some(w) = self.motor_speed {
            if !(w.is_finite() && w > 0.0 && w <= MAX_MOTOR_SPEED) {
                return Err(e(
                    "dynamics.inertia.motor_speed",
                    format!(
                        "the motor shaft's speed must be > 0 and at most {MAX_MOTOR_SPEED:e} rad/s (about 1e7 rpm), not {} rad/s",
                        show(w)
                    ),
                ));
            }
        } else {
            if self.inertia_motor_shaft > 0.0 {
                return Err(e(
                    "dynamics.inertia.motor_shaft",
                    "an inertia on the motor shaft needs a motor or the motor shaft's speed (inertia.motor_speed): its speed ratio reduces it to the crank".into(),
                ));
            }
            if self.flywheel.place == FlywheelPlace::Motor {
                return Err(e(
                    "dynamics.flywheel.place",
                    "a flywheel on the motor shaft needs a motor or the motor shaft's speed (inertia.motor_speed); put it on the crank shaft or give one".into(),
                ));
            }
        }
        let f = &self.flywheel;
        if f.place == FlywheelPlace::Shaft && !(f.speed_ratio.is_finite() && (1.0 / MAX_RATIO..=MAX_RATIO).contains(&f.speed_ratio)) {
            return Err(e(
                "dynamics.flywheel.speed_ratio",
                format!(
                    "the flywheel shaft's speed ratio ω_shaft/ω_crank must be from {:e} to {MAX_RATIO:e}, not {}",
                    1.0 / MAX_RATIO,
                    show(f.speed_ratio)
                ),
            ));
        }
        if !(f.density.is_finite() && f.density > 0.0) {
            return Err(e(
                "dynamics.flywheel.density",
                format!("must be > 0 kg/m³, not {}", show(f.density)),
            ));
        }
        match f.shape {
            FlywheelShape::Disc { width_ratio } => {
                if !(width_ratio.is_finite() && width_ratio > 0.0) {
                    return Err(e(
                        "dynamics.flywheel.width_ratio",
                        format!("b/D must be > 0, not {}", show(width_ratio)),
                    ));
                }
            }
            FlywheelShape::Rim {
                width_ratio,
                thickness_ratio,
            } => {
                if !(width_ratio.is_finite() && width_ratio > 0.0) {
                    return Err(e(
                        "dynamics.flywheel.width_ratio",
                        format!("b/D must be > 0, not {}", show(width_ratio)),
                    ));
                }
                if !(thickness_ratio.is_finite() && thickness_ratio > 0.0 && thickness_ratio < 0.5) {
                    return Err(e(
                        "dynamics.flywheel.thickness_ratio",
                        format!("the rim's h/D must be in (0, 0.5) (0.5 is a disc), not {}", show(thickness_ratio)),
                    ));
                }
            }
        }
        Ok(())
    }
}
