//! The single stroke under a constant driving moment by the energy method
//! (the book's variant 2 of П4, Chernaya & Timofeev 2019, p. 141–142): a
//! second physical model beside the motor-driven one, the motor replaced
//! by its breakdown torque (or another constant torque) through the reducer,
//! M_прДВ = u·M. From the energy equation (теорема об изменении
//! кинетической энергии):
//!
//!   A_Σ(φ) = M_прДВ·φ + ∫₀^φ M_c dφ,
//!   ω(φ) = √{[2·A_Σ(φ) + ω_нач²·I_Σ(0)]/I_Σ(φ)},
//!   ε(φ) = (M_прДВ + M_c)/I_Σ − ω²·I′_Σ/(2·I_Σ),
//!   t(φ) = ∫₀^φ dφ/ω.
//!
//! The work of the loads is Gauss–Legendre quadrature between the nodes,
//! cut at the output's dead positions and halved where a load table kinks
//! ([`super::single_stroke::work`]); the time is the
//! trapezoid rule with its Euler–Maclaurin end correction, exact to the
//! fourth order: with g = 1/ω, g′ = −ε/ω³ (since dω/dφ = ε/ω),
//! ∫ g ≈ h·(g₀ + g₁)/2 − h²·(g₁′ − g₀′)/12 (derived in docs/dynamics.md).

use super::error::DynamicsError;
use super::reduced::Reducer;
use super::single_stroke::{StrokeSpec, angles, stall, travel, work as work_between};
use crate::Solution;

/// One row of the constant-moment stroke.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct EnergyRow {
    /// Cycle angle φ, rad.
    pub phi: f64,
    /// The output's travel from the start of its working stroke, m or rad.
    pub travel: f64,
    /// I_Σ, kg·m².
    pub inertia_total: f64,
    /// M_c, N·m.
    pub moment_loads: f64,
    /// ∫₀^φ M_c dφ, J.
    pub work_loads: f64,
    /// A_Σ(φ), J.
    pub work_total: f64,
    /// ω, rad/s.
    pub omega: f64,
    /// ε, rad/s².
    pub epsilon: f64,
    /// t, s.
    pub time: f64,
}

/// The constant-moment stroke.
#[derive(Debug, Clone, PartialEq)]
pub struct EnergyStroke {
    /// The constant driving moment at the crank, M_прДВ = u·M, N·m.
    pub driving_moment: f64,
    /// The rows (the same angles as the motor-driven stroke's).
    pub rows: Vec<EnergyRow>,
    /// The design position's row, if any.
    pub design: Option<EnergyRow>,
    /// A_Σ(2π), J.
    pub work_end: f64,
    /// ω(2π), rad/s.
    pub omega_end: f64,
    /// t(2π), s.
    pub time_end: f64,
    /// The smallest speed on the rows, rad/s.
    pub omega_min: f64,
}

impl EnergyStroke {
    /// The stroke for `spec` (its `constant_torque`, start speed and
    /// inertia), on the output angles of `spec`.
    pub fn compute(red: &Reducer, spec: &StrokeSpec, sol: &mut Solution) -> Result<Self, DynamicsError> {
        let md = spec.motor.ratio * spec.constant_torque;
        let i_const = red.inertia_crank + spec.inertia_constant;
        let (phis, design_at) = angles(spec, red.period);
        let w0 = spec.start_speed;
        let mut rows: Vec<EnergyRow> = Vec::with_capacity(phis.len());
        let mut t0_energy = 0.0;
        let mut work = 0.0;
        for (k, &phi) in phis.iter().enumerate() {
            if k > 0 {
                work += work_between(red, phis[k - 1], phi, sol)?;
            }
            let r = red.eval(phi, sol)?;
            let i = i_const + r.inertia;
            if k == 0 {
                t0_energy = 0.5 * w0 * w0 * i;
            }
            let a = md * phi + work;
            let w2 = (2.0 * a + 2.0 * t0_energy) / i;
            if w2.is_nan() || w2 <= 0.0 || !w2.is_finite() {
                // the speed reaches zero between the previous node and this one
                let lo = phis[k.saturating_sub(1)];
                let (mut a_, mut b_) = (lo, phi);
                let base = rows.last().map_or(0.0, |r| r.work_loads);
                for _ in 0..60 {
                    let m = 0.5 * (a_ + b_);
                    let e = md * m + base + work_between(red, lo, m, sol)? + t0_energy;
                    if e > 0.0 {
                        a_ = m;
                    } else {
                        b_ = m;
                    }
                }
                return Err(stall(red, "constant-moment model", 0.5 * (a_ + b_), None, md, sol));
            }
            let w = w2.sqrt();
            let eps = (md + r.moment) / i - 0.5 * w2 * r.inertia_derivative / i;
            let time = match rows.last() {
                None => 0.0,
                Some(p) => {
                    let h = phi - p.phi;
                    let (g0, g1) = (1.0 / p.omega, 1.0 / w);
                    let (d0, d1) = (-p.epsilon / p.omega.powi(3), -eps / w.powi(3));
                    p.time + 0.5 * h * (g0 + g1) - h * h * (d1 - d0) / 12.0
                }
            };
            rows.push(EnergyRow {
                phi,
                travel: travel(red, sol),
                inertia_total: i,
                moment_loads: r.moment,
                work_loads: work,
                work_total: a,
                omega: w,
                epsilon: eps,
                time,
            });
        }
        let last = *rows.last().ok_or_else(|| DynamicsError::NonFinite {
            what: "the constant-moment stroke".into(),
        })?;
        Ok(EnergyStroke {
            driving_moment: md,
            design: design_at.map(|k| rows[k]),
            work_end: last.work_total,
            omega_end: last.omega,
            time_end: last.time,
            omega_min: rows.iter().map(|r| r.omega).fold(f64::INFINITY, f64::min),
            rows,
        })
    }
}
