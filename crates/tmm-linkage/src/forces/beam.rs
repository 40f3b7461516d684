//! A link as a beam (расчётная схема звена): the link is loaded by the
//! reactions of its pairs, its external loads, its weight and its inertia, and
//! is in equilibrium under them (kinetostatics). Cut at a distance z along its
//! axis, the part 0…z gives the internal forces (method of sections, метод
//! сечений; Feodosiev, *Сопротивление материалов*, §§ 1.4, 4.2):
//!
//! - N(z) = −Σ F_e (axial force, tension positive),
//! - Q(z) = Σ F_n (shear force),
//! - M(z) = Σ F_n·(z − zᵢ) − Σ Cᵢ (bending moment),
//!
//! sums over the loads left of the cut, e along the axis, n = e turned +90°,
//! C the couples (counter-clockwise positive). Then dM/dz = Q, and past the last
//! load N = Q = M = 0: the diagrams close because the link is in equilibrium.
//!
//! Weight and inertia are distributed along the axis, not lumped at S (seed 004,
//! §2, and the issue): the link is a rod of linear density ρ(z) = ρ₀ + ρ₁z with
//! mass m and centre of mass at z_S (uniform when S is mid-way);
//! ρ₁ = 12·m·(z_S − L/2)/L³, ρ₀ = m/L − ρ₁L/2 (derived in docs/forces.md). The
//! acceleration of the axis point z is a(z) = a_A + z·(ε·n − ω²·e), linear in z,
//! so the distributed load q(z) = ρ(z)·(g − a(z)) is a polynomial of degree ≤ 2
//! (linearly varying for a uniform rotating rod) and is integrated exactly.
//! The rod model's own inertia torque is J_line·ε, J_line = ∫ρ(z − z_S)²dz; the
//! difference from the given J_S (and any offset of S from the axis) is added
//! as a concentrated couple and force at S, so the beam stays in equilibrium
//! with the kinetostatic reactions exactly.

use tmm_geom::{Vec2, cross, perp};

use super::error::ForceError;
use super::kinetostatics::ForceSolution;
use super::loads::Loads;
use crate::{Mechanism, Solution};

/// A concentrated load on the beam.
#[derive(Debug, Clone, PartialEq)]
pub struct BeamLoad {
    /// What it is (`R B (2→3)`, `correction at S`…).
    pub label: String,
    /// Position along the axis, m.
    pub z: f64,
    /// Axial component (along e), N.
    pub fe: f64,
    /// Transverse component (along n), N.
    pub fn_: f64,
    /// Couple, N·m (includes the moment of an off-axis force about its axis point).
    pub couple: f64,
}

/// N, Q, M at one section.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BeamSample {
    /// Distance along the axis, m.
    pub z: f64,
    /// Axial force, N (tension positive).
    pub n: f64,
    /// Shear force, N.
    pub q: f64,
    /// Bending moment, N·m.
    pub m: f64,
}

/// A link as a beam at one position.
#[derive(Debug, Clone, PartialEq)]
pub struct Beam {
    /// The link.
    pub link: usize,
    /// Axis start (global), m.
    pub origin: Vec2,
    /// Axis unit vector e, global.
    pub axis: Vec2,
    /// Beam length between the two axis points, m.
    pub length: f64,
    /// Concentrated loads, sorted by z.
    pub loads: Vec<BeamLoad>,
    /// Distributed load along e: coefficients of q_e(z) = c₀ + c₁z + c₂z², N/m.
    pub qe: [f64; 3],
    /// Distributed load along n, N/m.
    pub qn: [f64; 3],
    /// The range of z with loads, m.
    pub z_range: (f64, f64),
}

impl Beam {
    /// Build the beam of link `link` with its axis from local point `a` to
    /// local point `b`, from a solved position and its kinetostatics.
    pub fn new(
        m: &Mechanism,
        loads: &Loads,
        sol: &Solution,
        fs: &ForceSolution,
        link: usize,
        a: Vec2,
        b: Vec2,
    ) -> Result<Self, ForceError> {
        let name = &m.link_names[link];
        let st = &sol.links[link];
        let (pa, pb) = (st.pos(a), st.pos(b));
        let len = (pb - pa).hypot();
        if len <= 1e-12 || !len.is_finite() {
            return Err(ForceError::load(format!("strength.{name}"), "the beam's two axis points coincide"));
        }
        let e = (pb - pa) * (1.0 / len);
        let n = perp(e);
        let mut out = Vec::new();
        let mut push = |label: String, p: Vec2, f: Vec2, c: f64| {
            let r = p - pa;
            let z = r.dot(e);
            let h = r.dot(n);
            // the force at p = the force at the axis point z plus the couple of its offset h·n
            out.push(BeamLoad {
                label,
                z,
                fe: f.dot(e),
                fn_: f.dot(n),
                couple: c + cross(n * h, f),
            });
        };
        // pair reactions
        for r in &fs.reactions {
            let pt = &m.points[m.pairs[r.pair].point()].name;
            if r.on == link {
                push(format!("R{pt} ({}→{})", m.link_names[r.from], name), r.at, r.force, 0.0);
            } else if r.from == link {
                push(format!("R{pt} ({}→{})", m.link_names[r.on], name), r.at, -r.force, 0.0);
            }
        }
        // external forces, moments, resistance
        let ld = &loads.links[link];
        for (k, pf) in ld.forces.iter().enumerate() {
            push(format!("F{k}"), st.pos(pf.local), pf.force, 0.0);
        }
        let lf = &fs.links[link];
        if ld.moment != 0.0 {
            push("M".into(), lf.s, Vec2::ZERO, ld.moment);
        }
        for (r, &val) in loads.resistance.iter().zip(&fs.resistance) {
            if r.link == link {
                let (f, p, c) = r.apply(st, val);
                push("resistance".into(), p, f, c);
            }
        }
        // distributed weight and inertia of the rod model
        let mass = ld.mass;
        let (mut qe, mut qn) = ([0.0; 3], [0.0; 3]);
        if mass > 0.0 {
            let zs = (lf.s - pa).dot(e);
            let rho1 = 12.0 * mass * (zs - 0.5 * len) / len.powi(3);
            let rho0 = mass / len - 0.5 * rho1 * len;
            if rho0 < -1e-12 * mass / len || rho0 + rho1 * len < -1e-12 * mass / len {
                return Err(ForceError::load(
                    format!("strength.{name}"),
                    format!(
                        "the centre of mass is {:.4} of the way along the beam; a rod with density varying linearly needs it within 1/3…2/3 of the length",
                        zs / len
                    ),
                ));
            }
            let (_, a_a) = st.kin_at(pa);
            let k1 = n * st.eps - e * (st.omega * st.omega);
            let g = loads.gravity;
            let c0 = (g - a_a) * rho0;
            let c1 = (g - a_a) * rho1 - k1 * rho0;
            let c2 = -k1 * rho1;
            qe = [c0.dot(e), c1.dot(e), c2.dot(e)];
            qn = [c0.dot(n), c1.dot(n), c2.dot(n)];
            // the rod model's resultant is m(g − a(z_S)) at z_S with torque −J_line·ε;
            // correct it to the true inertia and weight at S with torque −J_S·ε
            let ps = pa + e * zs;
            let j_line = rho0 * len.powi(3) / 3.0 + rho1 * len.powi(4) / 4.0 - mass * zs * zs;
            let line_f = (g - (a_a + k1 * zs)) * mass;
            let true_f = lf.weight + lf.inertia_force;
            if (lf.s - ps).hypot() <= 1e-12 * len {
                // S on the axis: one concentrated remainder, the torque (J_line − J_S)·ε
                let (df, dc) = (true_f - line_f, lf.inertia_moment + j_line * st.eps);
                if df.hypot() > 1e-12 * (true_f.hypot() + line_f.hypot())
                    || dc.abs() > 1e-12 * (lf.inertia_moment.abs() + (j_line * st.eps).abs())
                {
                    push("S: J_S − J_rod torque".into(), ps, df, dc);
                }
            } else {
                push("S: rod model (removed)".into(), ps, -line_f, j_line * st.eps);
                push("S: weight + inertia (true)".into(), lf.s, true_f, lf.inertia_moment);
            }
        }
        out.sort_by(|x, y| x.z.total_cmp(&y.z));
        let zmin = out.first().map_or(0.0, |l| l.z).min(0.0);
        let zmax = out.last().map_or(len, |l| l.z).max(len);
        Ok(Beam {
            link,
            origin: pa,
            axis: e,
            length: len,
            loads: out,
            qe,
            qn,
            z_range: (zmin, zmax),
        })
    }

    /// N, Q, M just right of section z (loads at z included when `after`).
    pub fn at(&self, z: f64, after: bool) -> BeamSample {
        let (mut fe, mut fnn, mut mo) = (0.0, 0.0, 0.0);
        for l in &self.loads {
            if l.z < z || (after && l.z <= z) {
                fe += l.fe;
                fnn += l.fn_;
                mo += l.fn_ * (z - l.z) - l.couple;
            }
        }
        let zc = z.clamp(0.0, self.length);
        let i0 = |c: &[f64; 3]| c[0] * zc + c[1] * zc * zc / 2.0 + c[2] * zc.powi(3) / 3.0;
        let i1 = |c: &[f64; 3]| c[0] * zc * zc / 2.0 + c[1] * zc.powi(3) / 3.0 + c[2] * zc.powi(4) / 4.0;
        fe += i0(&self.qe);
        fnn += i0(&self.qn);
        mo += z * i0(&self.qn) - i1(&self.qn);
        BeamSample { z, n: -fe, q: fnn, m: mo }
    }

    /// The diagrams: `steps` equal intervals over the loaded range plus both
    /// sides of every concentrated load.
    pub fn diagrams(&self, steps: usize) -> Vec<BeamSample> {
        let (z0, z1) = self.z_range;
        let mut zs: Vec<(f64, bool)> = (0..=steps).map(|k| (z0 + (z1 - z0) * k as f64 / steps as f64, false)).collect();
        for l in &self.loads {
            zs.push((l.z, false));
            zs.push((l.z, true));
        }
        zs.push((z1, true));
        zs.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        zs.dedup();
        zs.into_iter().map(|(z, after)| self.at(z, after)).collect()
    }

    /// What is left past the last load (N, Q, M): zero for a link in
    /// equilibrium, up to rounding.
    pub fn closure(&self) -> BeamSample {
        self.at(self.z_range.1, true)
    }

    /// The section where σ = |N|/A + |M|/W is largest for a section with area
    /// `area` and section modulus `w`, among `samples`; returns (index, σ).
    pub fn dangerous(samples: &[BeamSample], area: f64, w: f64) -> (usize, f64) {
        let mut best = (0, 0.0);
        for (i, s) in samples.iter().enumerate() {
            let sig = s.n.abs() / area + s.m.abs() / w;
            if sig > best.1 {
                best = (i, sig);
            }
        }
        best
    }
}
