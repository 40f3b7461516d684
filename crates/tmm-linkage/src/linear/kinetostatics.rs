//! Kinetostatics of the cylinder-driven mechanism at one travel s with the
//! true speed V and acceleration a (силовой расчёт), BMSTU textbook
//! (Chernaya & Timofeev 2019), appendix П5, p. 147–148, the system
//! corrected as GIVENS.md states (the load's inertia force in the force
//! equations of link 1, the moment arms with their own coordinates).
//!
//! ε_k = ε_qk V² + ω_qk a, a_P = a_qP V² + V_qP a; Φ = −m a_S, M_Φ = −I_S ε.
//! Nine unknowns (the book's order): R_A (frame on 1 at A), R_B (1 on 2
//! at B), R_32 (the piston's normal force on the cylinder along
//! e(φ₃ − π/2), at C), M_32 (the couple of 2 on 3), R_D (frame on 3 at D),
//! F_ур (the balancing force, +e₃ on the piston at C, −e₃ on the cylinder).
//! Equations: forces and moments of the lever 1 (about A), of the piston 2
//! (about C) and of the cylinder 3 (about D) — nine linear equations,
//! solved by Gaussian elimination with partial pivoting on a fixed 9×9
//! array (nothing allocated).
//!
//! F_ур is the force the cylinder must exert at that s; with the true
//! motion it equals F_прДВ(s) (virtual power: F_ур + F_прC − m_пр a −
//! ½ m′_пр V² = 0), the check the report prints.

use tmm_geom::{Vec2, cross, perp};

use super::cylinder::{CylinderDrive, CylinderState};
use super::reduced::CylinderMasses;
use crate::dynamics::DynamicsError;

/// The reactions and loads at one s.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CylinderReactions {
    /// s, m.
    pub s: f64,
    /// V, m/s.
    pub speed: f64,
    /// a, m/s².
    pub accel: f64,
    /// ε₁, rad/s².
    pub eps1: f64,
    /// ε₃ = ε₂, rad/s².
    pub eps3: f64,
    /// Φ₂ = −m₂ a_S2, N.
    pub inertia_piston: Vec2,
    /// Φ = −M a_K, N (the load).
    pub inertia_load: Vec2,
    /// M_Φ1, M_Φ2, M_Φ3 = −I_kS ε_k, N·m.
    pub inertia_moments: [f64; 3],
    /// R_A: the frame on the lever at A, N.
    pub r_a: Vec2,
    /// R_B: the lever on the piston's rod at B, N.
    pub r_b: Vec2,
    /// R_32: the piston's normal force on the cylinder along e(φ₃ − π/2), N.
    pub r_32: f64,
    /// M_32: the couple of the piston on the cylinder, N·m.
    pub m_32: f64,
    /// R_D: the frame on the cylinder at D, N.
    pub r_d: Vec2,
    /// F_ур: the balancing force along the axis (+e₃ on the piston), N.
    pub balancing: f64,
}

impl CylinderReactions {
    /// The nine unknowns in the book's order: R_AX, R_AY, R_BX, R_BY, R_32,
    /// M_32, R_DX, R_DY, F_ур.
    pub fn unknowns(&self) -> [f64; 9] {
        [
            self.r_a.x,
            self.r_a.y,
            self.r_b.x,
            self.r_b.y,
            self.r_32,
            self.m_32,
            self.r_d.x,
            self.r_d.y,
            self.balancing,
        ]
    }
}

/// The kinetostatics with the mechanism solved at s in `st`, at speed `v`
/// and acceleration `a`.
///
/// ```
/// use tmm_linkage::linear::{CylinderDrive, CylinderMasses, CylinderState, kinetostatics, reduced::reduce};
/// use tmm_geom::Vec2;
/// let drive = CylinderDrive::new(Vec2::new(0.6, 0.05), 0.3, 0.05, 0.3, 0.39, 1.6).unwrap().with_load(0.2, 2.6);
/// let m = CylinderMasses { load_mass: 100.0, lever_inertia: 1.0, piston_mass: 10.0, gravity: 9.81, ..Default::default() };
/// let mut st = CylinderState::default();
/// let r = reduce(&drive, &m, 0.1, &mut st).unwrap();
/// let (v, a) = (0.3, 0.5);
/// let k = kinetostatics(&drive, &m, &st, v, a).unwrap();
/// // virtual power: F_ур = m_пр a + ½ m′_пр V² − F_прC
/// let vp = r.mass * a + 0.5 * r.mass_derivative * v * v - r.force;
/// assert!((k.balancing - vp).abs() < 1e-9 * vp.abs().max(1.0));
/// ```
pub fn kinetostatics(
    drive: &CylinderDrive,
    m: &CylinderMasses,
    st: &CylinderState,
    v: f64,
    a: f64,
) -> Result<CylinderReactions, DynamicsError> {
    let g = m.gravity;
    let eps1 = st.eps_q1 * v * v + st.omega_q1 * a;
    let eps3 = st.eps_q3 * v * v + st.omega_q3 * a;
    let phi2 = -st.s2.acceleration(v, a) * m.piston_mass;
    let phil = -st.k.acceleration(v, a) * m.load_mass;
    let mphi = [-m.lever_inertia * eps1, -m.piston_inertia * eps3, -m.cylinder_inertia * eps3];
    let (b, c, s2, k, d) = (st.b.p, st.c.p, st.s2.p, st.k.p, drive.d);
    let e3 = Vec2::new(st.phi3.cos(), st.phi3.sin());
    let n = -perp(e3); // e(φ₃ − π/2)
    let gl = Vec2::new(0.0, -m.load_mass * g) + phil;
    let g2 = Vec2::new(0.0, -m.piston_mass * g) + phi2;
    let (bc, sc, cd) = (b - c, s2 - c, c - d);
    // unknowns: 0 R_AX, 1 R_AY, 2 R_BX, 3 R_BY, 4 R_32, 5 M_32, 6 R_DX, 7 R_DY, 8 F_ур
    let mut mat = [[0.0f64; 10]; 9];
    // lever 1: R_A − R_B + G₁ + G + Φ = 0; about A: B × (−R_B) + K × (G + Φ) + M_Φ1 = 0
    mat[0][0] = 1.0;
    mat[0][2] = -1.0;
    mat[0][9] = -gl.x;
    mat[1][1] = 1.0;
    mat[1][3] = -1.0;
    mat[1][9] = -(gl.y - m.lever_mass * g);
    mat[2][2] = b.y;
    mat[2][3] = -b.x;
    mat[2][9] = -(cross(k, gl) + mphi[0]);
    // piston 2: R_B − R_32 n + F_ур e₃ + G₂ + Φ₂ = 0; about C: (B − C) × R_B − M_32 + (S₂ − C) × (G₂ + Φ₂) + M_Φ2 = 0
    mat[3][2] = 1.0;
    mat[3][4] = -n.x;
    mat[3][8] = e3.x;
    mat[3][9] = -g2.x;
    mat[4][3] = 1.0;
    mat[4][4] = -n.y;
    mat[4][8] = e3.y;
    mat[4][9] = -g2.y;
    mat[5][2] = -bc.y;
    mat[5][3] = bc.x;
    mat[5][5] = -1.0;
    mat[5][9] = -(cross(sc, g2) + mphi[1]);
    // cylinder 3: R_D + R_32 n − F_ур e₃ + G₃ = 0; about D: (C − D) × (R_32 n − F_ур e₃) + M_32 + M_Φ3 = 0
    mat[6][6] = 1.0;
    mat[6][4] = n.x;
    mat[6][8] = -e3.x;
    mat[7][7] = 1.0;
    mat[7][4] = n.y;
    mat[7][8] = -e3.y;
    mat[7][9] = m.cylinder_mass * g;
    mat[8][4] = cross(cd, n);
    mat[8][8] = -cross(cd, e3);
    mat[8][5] = 1.0;
    mat[8][9] = -mphi[2];
    let x = solve9(&mut mat).ok_or_else(|| DynamicsError::NonFinite {
        what: "the kinetostatics' system (singular at this position)".into(),
    })?;
    let out = CylinderReactions {
        s: st.s,
        speed: v,
        accel: a,
        eps1,
        eps3,
        inertia_piston: phi2,
        inertia_load: phil,
        inertia_moments: mphi,
        r_a: Vec2::new(x[0], x[1]),
        r_b: Vec2::new(x[2], x[3]),
        r_32: x[4],
        m_32: x[5],
        r_d: Vec2::new(x[6], x[7]),
        balancing: x[8],
    };
    if out.unknowns().iter().all(|v| v.is_finite()) {
        Ok(out)
    } else {
        Err(DynamicsError::NonFinite { what: "a reaction".into() })
    }
}

/// Gaussian elimination with partial pivoting of the augmented 9×10 system.
fn solve9(m: &mut [[f64; 10]; 9]) -> Option<[f64; 9]> {
    let scale = m.iter().flat_map(|r| r[..9].iter()).fold(0.0f64, |a, v| a.max(v.abs()));
    for col in 0..9 {
        let piv = (col..9).max_by(|&i, &j| m[i][col].abs().total_cmp(&m[j][col].abs()))?;
        let p = m[piv][col].abs();
        if p.is_nan() || p <= 1e-13 * scale {
            return None;
        }
        m.swap(col, piv);
        for r in col + 1..9 {
            let f = m[r][col] / m[col][col];
            if f != 0.0 {
                let pivot_row = m[col];
                for (x, p) in m[r][col..].iter_mut().zip(&pivot_row[col..]) {
                    *x -= f * p;
                }
            }
        }
    }
    let mut x = [0.0; 9];
    for r in (0..9).rev() {
        let mut s = m[r][9];
        for c in r + 1..9 {
            s -= m[r][c] * x[c];
        }
        x[r] = s / m[r][r];
    }
    Some(x)
}
