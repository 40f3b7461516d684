//! An induction motor (асинхронный двигатель) by Kloss's formula (формула
//! Клосса): the whole mechanical characteristic, both its stable working
//! branch and the unstable one below the breakdown (critical) speed, from
//! the synchronous speed n₀, the breakdown speed n_K and the breakdown
//! (maximum) torque M_K:
//!
//!   M(S) = 2·M_K/(S/S_K + S_K/S) = 2·M_K·S·S_K/(S² + S_K²),
//!   S = 1 − n/n₀ (slip, скольжение), S_K = 1 − n_K/n₀,
//!
//! (Вольдек А. И., *Электрические машины*, 3rd ed., 1978, the simplified
//! Kloss formula for the torque of an induction machine; Chernaya &
//! Timofeev 2019, appendix П4, p. 139, in the second form, which is zero at
//! S = 0). The torque is largest, M_K, at S = S_K; above the synchronous
//! speed (S < 0) the machine brakes as a generator. Reduced to the crank
//! through a loss-free reducer of ratio u = n_motor/n_crank: n = u·ω/(2π),
//! M_прДВ(ω) = u·M(n(ω)) (equal power).
//!
//! ```
//! use tmm_linkage::dynamics::KlossMotor;
//! use std::f64::consts::PI;
//! // П4: n₀ = 16.7 rev/s, n_K = 12.3 rev/s, M_K = 5.24 kN·m, u = 18.6
//! let m = KlossMotor { synchronous_speed: 2.0 * PI * 16.7, breakdown_speed: 2.0 * PI * 12.3, breakdown_torque: 5.24e3, ratio: 18.6 };
//! assert!((m.torque(2.0 * PI * 12.3) - 5.24e3).abs() < 1e-9);   // the breakdown point
//! assert_eq!(m.torque(2.0 * PI * 16.7), 0.0);                  // the synchronous speed
//! assert!((m.crank_moment(m.crank_breakdown_speed()) - 18.6 * 5.24e3).abs() < 1e-6);
//! ```

/// An induction motor by Kloss's formula, through a reducer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KlossMotor {
    /// Synchronous speed ω₀ = 2π·n₀ on the motor shaft, rad/s (> 0).
    pub synchronous_speed: f64,
    /// Breakdown (critical) speed ω_K = 2π·n_K on the motor shaft, rad/s
    /// (0 < ω_K < ω₀): where the torque is largest.
    pub breakdown_speed: f64,
    /// Breakdown (maximum) torque M_K on the motor shaft, N·m (> 0).
    pub breakdown_torque: f64,
    /// Reducer ratio u = ω_motor/ω_crank (передаточное отношение, > 0).
    pub ratio: f64,
}

impl KlossMotor {
    /// The breakdown slip S_K = 1 − ω_K/ω₀.
    #[inline]
    pub fn breakdown_slip(&self) -> f64 {
        1.0 - self.breakdown_speed / self.synchronous_speed
    }

    /// The slip at motor speed `w` (rad/s): S = 1 − ω/ω₀.
    #[inline]
    pub fn slip(&self, w: f64) -> f64 {
        1.0 - w / self.synchronous_speed
    }

    /// The torque on the motor shaft at motor speed `w` (rad/s), N·m:
    /// 2·M_K·S·S_K/(S² + S_K²).
    #[inline]
    pub fn torque(&self, w: f64) -> f64 {
        let (s, sk) = (self.slip(w), self.breakdown_slip());
        2.0 * self.breakdown_torque * s * sk / (s * s + sk * sk)
    }

    /// The driving moment reduced to the crank at crank speed `omega`
    /// (rad/s), N·m: u·M(u·ω).
    #[inline]
    pub fn crank_moment(&self, omega: f64) -> f64 {
        self.ratio * self.torque(self.ratio * omega)
    }

    /// The synchronous speed seen at the crank, ω₀/u, rad/s.
    #[inline]
    pub fn crank_synchronous_speed(&self) -> f64 {
        self.synchronous_speed / self.ratio
    }

    /// The breakdown speed seen at the crank, ω_K/u, rad/s.
    #[inline]
    pub fn crank_breakdown_speed(&self) -> f64 {
        self.breakdown_speed / self.ratio
    }
}
