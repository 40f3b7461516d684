//! The cylinder-driven mechanism reduced to the piston's travel s
//! (приведённая масса и приведённая сила), BMSTU textbook (Chernaya &
//! Timofeev 2019), appendix П5, p. 145:
//!
//! m_пр(s) = I₁S ω_q1² + (I₂S + I₃S) ω_q3² + m₂ |V_qS2|² + M |V_qK|²
//! (S₁ at A and S₃ at D do not move), and, differentiated (derived here),
//! m′_пр = 2 [I₁S ω_q1 ε_q1 + (I₂S + I₃S) ω_q3 ε_q3 + m₂ V_qS2·a_qS2 + M V_qK·a_qK];
//!
//! the reduced force of gravity (g along −Y; G₁ at A and G₃ at D do no
//! work) F_прC = −g (m₂ V_qS2,y + M V_qK,y), and its derivative
//! F′_прC = −g (m₂ a_qS2,y + M a_qK,y).

use super::cylinder::{CylinderDrive, CylinderState};
use crate::dynamics::DynamicsError;
use crate::dynamics::error::show;

/// The masses and inertias of the links and the load.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CylinderMasses {
    /// m₁, kg (centre of mass at A).
    pub lever_mass: f64,
    /// I₁S, kg·m².
    pub lever_inertia: f64,
    /// m₂ (piston and rod), kg.
    pub piston_mass: f64,
    /// I₂S, kg·m².
    pub piston_inertia: f64,
    /// m₃ (cylinder), kg (centre of mass at D).
    pub cylinder_mass: f64,
    /// I₃S, kg·m².
    pub cylinder_inertia: f64,
    /// The load M at K, kg.
    pub load_mass: f64,
    /// g, m/s² (along −Y).
    pub gravity: f64,
}

impl CylinderMasses {
    /// Refuse a negative or non-finite value (field names as in a task's
    /// `[cylinder]`), or a mechanism with no inertia at all.
    pub fn check(&self) -> Result<(), DynamicsError> {
        for (f, v) in [
            ("cylinder.lever.mass", self.lever_mass),
            ("cylinder.lever.inertia", self.lever_inertia),
            ("cylinder.piston.mass", self.piston_mass),
            ("cylinder.piston.inertia", self.piston_inertia),
            ("cylinder.body.mass", self.cylinder_mass),
            ("cylinder.body.inertia", self.cylinder_inertia),
            ("cylinder.load.mass", self.load_mass),
            ("cylinder.gravity", self.gravity),
        ] {
            if !(v.is_finite() && v >= 0.0) {
                return Err(DynamicsError::spec(f, format!("must be zero or positive, got {}", show(v))));
            }
        }
        if self.lever_inertia + self.piston_mass + self.piston_inertia + self.cylinder_inertia + self.load_mass <= 0.0 {
            return Err(DynamicsError::spec(
                "cylinder.load.mass",
                "the moving links have no mass and no inertia: the reduced mass would be zero; give the load's mass or the links' masses",
            ));
        }
        Ok(())
    }
}

/// The reduced model at one s.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ReducedPoint {
    /// s, m.
    pub s: f64,
    /// m_пр, kg.
    pub mass: f64,
    /// dm_пр/ds, kg/m.
    pub mass_derivative: f64,
    /// F_прC, N (the reduced force of gravity; negative where it resists
    /// the piston's travel).
    pub force: f64,
    /// dF_прC/ds, N/m.
    pub force_derivative: f64,
}

/// The reduced model at travel `s`, with the mechanism solved into `st`.
///
/// ```
/// use tmm_linkage::linear::{CylinderDrive, CylinderState, CylinderMasses, reduced::reduce};
/// use tmm_geom::Vec2;
/// let drive = CylinderDrive::new(Vec2::new(0.6, 0.05), 0.3, 0.05, 0.3, 0.39, 1.6).unwrap().with_load(0.2, 2.6);
/// let m = CylinderMasses { load_mass: 100.0, gravity: 9.81, ..Default::default() };
/// let mut st = CylinderState::default();
/// let r = reduce(&drive, &m, 0.1, &mut st).unwrap();
/// // a point load alone: m_пр = M |V_qK|², F_пр = −M g V_qK,y
/// assert!((r.mass - 100.0 * st.k.v.hypot2()).abs() < 1e-9);
/// assert!((r.force + 100.0 * 9.81 * st.k.v.y).abs() < 1e-9);
/// ```
pub fn reduce(drive: &CylinderDrive, m: &CylinderMasses, s: f64, st: &mut CylinderState) -> Result<ReducedPoint, DynamicsError> {
    drive.solve(s, st)?;
    let i23 = m.piston_inertia + m.cylinder_inertia;
    let mass = m.lever_inertia * st.omega_q1 * st.omega_q1
        + i23 * st.omega_q3 * st.omega_q3
        + m.piston_mass * st.s2.v.hypot2()
        + m.load_mass * st.k.v.hypot2();
    let mass_derivative = 2.0
        * (m.lever_inertia * st.omega_q1 * st.eps_q1
            + i23 * st.omega_q3 * st.eps_q3
            + m.piston_mass * st.s2.v.dot(st.s2.a)
            + m.load_mass * st.k.v.dot(st.k.a));
    let force = -m.gravity * (m.piston_mass * st.s2.v.y + m.load_mass * st.k.v.y);
    let force_derivative = -m.gravity * (m.piston_mass * st.s2.a.y + m.load_mass * st.k.a.y);
    Ok(ReducedPoint {
        s,
        mass,
        mass_derivative,
        force,
        force_derivative,
    })
}
