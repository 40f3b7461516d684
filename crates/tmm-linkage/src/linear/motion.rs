//! The motion of the cylinder-driven mechanism in its travel s by the
//! energy equation (уравнение движения в энергетической форме), BMSTU
//! textbook (Chernaya & Timofeev 2019), appendix П5, p. 146–147:
//!
//! A_Σ(s) = ∫₀^s (F_прC + F_прДВ) ds = m_пр(s) V²/2 (start from rest), so
//! V(s) = √(2A_Σ/m_пр) — the sign of A_Σ kept: A_Σ < 0 means the piston
//! cannot get there (the book prints |A_Σ|, an error); from the
//! differential form m_пр a + ½ m′_пр V² = F_прΣ,
//! a(s) = (F_прΣ − ½ m′_пр V²)/m_пр; t(s) = ∫₀^s ds/V.
//!
//! **The ends** (derived here, docs/dynamics.md): near s = 0,
//! V ≈ √(2F_прΣ(0) s/m_пр(0)) and 1/V is integrable; the first interval is
//! integrated with s = s₁w², which makes the integrand smooth. The control
//! force's zero work gives V(s_max) = 0, and F_K = |F_прC(s_max)| gives
//! F_прΣ(s_max) = 0 too: then A_Σ(s) = −∫_s^{s_max} F_прΣ ≈ ½k(s_max − s)²,
//! k = F′_прΣ(s_max) (> 0: the piston decelerates into the end),
//! V ≈ (s_max − s)/τ with τ = √(m_пр(s_max)/k), and the remaining travel
//! decays as e^(−t/τ): the end is reached only asymptotically (t → ∞), and
//! [`EndReached::Asymptotic`] says so instead of a finite time. Were
//! F_прΣ(s_max) < 0, V ≈ √(2|F_прΣ|(s_max − s)/m_пр) and the time is finite
//! (the last interval by s = s_max − h w²).
//!
//! A_C is integrated by 5-point Gauss–Legendre per interval (F_прC is
//! smooth), the control force's work exactly; A_Σ at a node is accumulated
//! from the nearer end of the travel (from s_max backwards as
//! −∫_s^{s_max} F_прΣ, which the zero work allows), so V near either end is
//! not lost in the rounding of the whole travel's work.

use super::control::ControlLaw;
use super::cylinder::{CylinderDrive, CylinderState};
use super::gauss;
use super::reduced::{CylinderMasses, ReducedPoint, reduce};
use crate::dynamics::DynamicsError;
use crate::dynamics::error::show;

/// The fewest and most intervals of the travel.
pub const POINTS_RANGE: (usize, usize) = (10, 100_000);

/// One node of the travel.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MotionRow {
    /// The reduced model there.
    pub reduced: ReducedPoint,
    /// F_прДВ, N.
    pub control: f64,
    /// F_прΣ = F_прC + F_прДВ, N.
    pub total: f64,
    /// A_C(s) = ∫₀^s F_прC, J.
    pub work_resistance: f64,
    /// A_ДВ(s), J.
    pub work_control: f64,
    /// A_Σ(s), J.
    pub work_total: f64,
    /// V = ds/dt, m/s.
    pub speed: f64,
    /// a = dV/dt, m/s².
    pub accel: f64,
    /// t(s), s; `None` where it is infinite (the end reached asymptotically).
    pub time: Option<f64>,
}

/// How the end of the travel is reached.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum EndReached {
    /// At a finite time t(s_max), s.
    Finite {
        /// t(s_max), s.
        time: f64,
    },
    /// Only as t → ∞: V(s_max) = 0 and F_прΣ(s_max) = 0.
    Asymptotic {
        /// τ = √(m_пр/F′_прΣ) at s_max, s: the remaining travel decays
        /// as e^(−t/τ); `None` when F′_прΣ(s_max) ≤ 0 (slower still).
        time_constant: Option<f64>,
    },
}

/// The motion over the whole travel.
#[derive(Debug, Clone, PartialEq)]
pub struct CylinderMotion {
    /// The mechanism.
    pub drive: CylinderDrive,
    /// Its masses.
    pub masses: CylinderMasses,
    /// The control force.
    pub control: ControlLaw,
    /// A_C over the travel, J.
    pub resistance_work: f64,
    /// The nodes s_i = i·s_max/n, i = 0…n.
    pub rows: Vec<MotionRow>,
    /// How the end is reached.
    pub end: EndReached,
}

impl CylinderMotion {
    /// The motion with the control force switching at `switch` (s_c, m),
    /// tabulated at `points` intervals. Refused: a control force that
    /// cannot lift the load — V² < 0 somewhere, with that s.
    ///
    /// ```
    /// use tmm_linkage::linear::{CylinderDrive, CylinderMasses, CylinderMotion, EndReached};
    /// use tmm_geom::Vec2;
    /// let drive = CylinderDrive::new(Vec2::new(0.6, 0.05), 0.3, 0.05, 0.3, 0.39, 1.6).unwrap().with_load(0.2, 2.6);
    /// let m = CylinderMasses { load_mass: 100.0, lever_inertia: 1.0, gravity: 9.81, ..Default::default() };
    /// if let Ok(mo) = CylinderMotion::compute(&drive, &m, 0.18, 200) {
    ///     // from rest to rest
    ///     assert_eq!(mo.rows[0].speed, 0.0);
    ///     assert!(mo.rows.last().unwrap().speed.abs() < 1e-6);
    ///     assert!(matches!(mo.end, EndReached::Asymptotic { .. }));
    /// }
    /// ```
    pub fn compute(drive: &CylinderDrive, masses: &CylinderMasses, switch: f64, points: usize) -> Result<Self, DynamicsError> {
        masses.check()?;
        if !(POINTS_RANGE.0..=POINTS_RANGE.1).contains(&points) {
            return Err(DynamicsError::spec(
                "cylinder.points",
                format!(
                    "the travel is cut into {}…{} intervals, got {points}",
                    POINTS_RANGE.0, POINTS_RANGE.1
                ),
            ));
        }
        let smax = drive.travel();
        let mut st = CylinderState::default();
        let n = points;
        let node = |i: usize| if i == n { smax } else { smax * i as f64 / n as f64 };
        // A_C per interval
        let mut piece = vec![0.0; n];
        for (i, p) in piece.iter_mut().enumerate() {
            *p = gauss(node(i), node(i + 1), |s| {
                Ok::<f64, DynamicsError>(reduce(drive, masses, s, &mut st)?.force)
            })?;
        }
        let mut fwd = vec![0.0; n + 1];
        for i in 0..n {
            fwd[i + 1] = fwd[i] + piece[i];
        }
        let mut back = vec![0.0; n + 1];
        for i in (0..n).rev() {
            back[i] = back[i + 1] + piece[i];
        }
        let a_c = fwd[n];
        let end_red = reduce(drive, masses, smax, &mut st)?;
        let control = ControlLaw::zero_work(switch, smax, a_c, end_red.force)?;
        let mut mo = CylinderMotion {
            drive: *drive,
            masses: *masses,
            control,
            resistance_work: a_c,
            rows: Vec::with_capacity(n + 1),
            end: EndReached::Finite { time: 0.0 },
        };
        let tol = mo.tolerance();
        for i in 0..=n {
            let s = node(i);
            let r = reduce(drive, masses, s, &mut st)?;
            let f = control.force(s);
            let a_sum = if 2 * i <= n {
                fwd[i] + control.work(0.0, s)
            } else {
                -(back[i] + control.work(s, smax))
            };
            let a_sum = if i == 0 || i == n { a_sum.max(0.0) } else { a_sum };
            let v = (2.0 * a_sum.max(0.0) / r.mass).sqrt();
            let total = r.force + f;
            mo.rows.push(MotionRow {
                reduced: r,
                control: f,
                total,
                work_resistance: if 2 * i <= n { fwd[i] } else { a_c - back[i] },
                work_control: control.work(0.0, s),
                work_total: a_sum,
                speed: v,
                accel: (total - 0.5 * r.mass_derivative * v * v) / r.mass,
                time: None,
            });
        }
        if let Some(i) = (1..n).find(|&i| mo.rows[i].work_total <= tol) {
            return Err(mo.cannot_lift(node(i - 1), node(i), &mut st));
        }
        if mo.rows[0].total <= 0.0 {
            return Err(mo.cannot_lift(0.0, node(1), &mut st));
        }
        // the end: F_прΣ(s_max) > 0 with A_Σ(s_max) = 0 means A_Σ < 0 just before
        let f_end = mo.rows[n].total;
        let f_scale = tol / smax;
        if f_end > f_scale {
            return Err(mo.cannot_lift(node(n - 1), smax, &mut st));
        }
        // t(s)
        let mut t = 0.0;
        mo.rows[0].time = Some(0.0);
        for i in 0..n {
            let (a, b) = (node(i), node(i + 1));
            let dt = if i == 0 {
                // s = b w²: ds/V = 2 b w dw / V(b w²)
                gauss(0.0, 1.0, |w| {
                    Ok::<f64, DynamicsError>(2.0 * b * w / mo.speed_at(b * w * w, &mut st)?)
                })?
            } else if i + 1 == n {
                if f_end.abs() <= f_scale {
                    let r = mo.rows[n].reduced;
                    let k = r.force_derivative + control.slope(smax);
                    mo.end = EndReached::Asymptotic {
                        time_constant: (k > 0.0).then(|| (r.mass / k).sqrt()),
                    };
                    break;
                }
                let h = b - a;
                gauss(0.0, 1.0, |w| {
                    Ok::<f64, DynamicsError>(2.0 * h * w / mo.speed_at(b - h * w * w, &mut st)?)
                })?
            } else {
                gauss(a, b, |s| Ok::<f64, DynamicsError>(1.0 / mo.speed_at(s, &mut st)?))?
            };
            t += dt;
            if !t.is_finite() {
                return Err(DynamicsError::NonFinite {
                    what: format!("the time to s = {} m", show(b)),
                });
            }
            mo.rows[i + 1].time = Some(t);
        }
        if let (EndReached::Finite { .. }, Some(time)) = (mo.end, mo.rows[n].time) {
            mo.end = EndReached::Finite { time };
        }
        Ok(mo)
    }

    /// The scale below which a work is rounding, J.
    fn tolerance(&self) -> f64 {
        let c = &self.control;
        1e-10 * (self.resistance_work.abs() + (c.start.abs() + c.end.abs()) * c.travel)
    }

    /// ∫ F_прΣ ds from `a` to `b` (J).
    fn work_between(&self, a: f64, b: f64, st: &mut CylinderState) -> Result<f64, DynamicsError> {
        let wc = gauss(a, b, |s| Ok::<f64, DynamicsError>(reduce(&self.drive, &self.masses, s, st)?.force))?;
        Ok(wc + self.control.work(a, b))
    }

    /// A_Σ(s) at any s of the travel, from the nearer node on the side of
    /// the nearer end, J.
    pub fn work_at(&self, s: f64, st: &mut CylinderState) -> Result<f64, DynamicsError> {
        let n = self.rows.len() - 1;
        let smax = self.control.travel;
        let s = s.clamp(0.0, smax);
        let j = (((s / smax) * n as f64).floor() as usize).min(n - 1);
        if 2.0 * s <= smax {
            Ok(self.rows[j].work_total + self.work_between(self.rows[j].reduced.s, s, st)?)
        } else {
            Ok(self.rows[j + 1].work_total - self.work_between(s, self.rows[j + 1].reduced.s, st)?)
        }
    }

    /// V(s), m/s (a rounding-small negative A_Σ read as rest).
    pub fn speed_at(&self, s: f64, st: &mut CylinderState) -> Result<f64, DynamicsError> {
        let a = self.work_at(s, st)?;
        let r = reduce(&self.drive, &self.masses, s, st)?;
        Ok((2.0 * a.max(0.0) / r.mass).sqrt())
    }

    /// The true V and a at `s` (m/s, m/s²), with the mechanism solved into
    /// `st` there (for the kinetostatics).
    pub fn motion_at(&self, s: f64, st: &mut CylinderState) -> Result<(f64, f64), DynamicsError> {
        let w = self.work_at(s, st)?;
        let r = reduce(&self.drive, &self.masses, s, st)?;
        let v = (2.0 * w.max(0.0) / r.mass).sqrt();
        let total = r.force + self.control.force(s);
        Ok((v, (total - 0.5 * r.mass_derivative * v * v) / r.mass))
    }

    /// The control force cannot lift the load: the first s in (lo, hi]
    /// where A_Σ turns negative.
    fn cannot_lift(&self, lo: f64, hi: f64, st: &mut CylinderState) -> DynamicsError {
        let tol = self.tolerance();
        let mut f = |s: f64| -> f64 { self.work_at(s, st).map_or(f64::NAN, |w| w - tol) };
        let at = if f(lo) > 0.0 && f(hi) <= 0.0 {
            tmm_geom::root::brent(&mut f, lo, hi, 1e-12 * self.control.travel).unwrap_or(hi)
        } else {
            lo
        };
        DynamicsError::spec(
            "cylinder.switch",
            format!(
                "the control force cannot lift the load: V² = 2A_Σ/m_пр < 0 from s = {} m of the travel s_max = {} m (the forces' work A_Σ turns negative there; the control force of zero work, F_H = {} N up to s_c = {} m, then linear to F_K = {} N, is too weak there); move the switch point s_c",
                show(round_mm(at)),
                show(self.control.travel),
                show(self.control.start),
                show(self.control.switch),
                show(self.control.end)
            ),
        )
    }
}

fn round_mm(s: f64) -> f64 {
    (s * 1e6).round() / 1e6
}
