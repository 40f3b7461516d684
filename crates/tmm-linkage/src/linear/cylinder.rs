//! The lever driven by an oscillating cylinder with the piston's travel s as
//! the input (механизм с качающимся цилиндром, входное звено — поршень),
//! BMSTU textbook (Chernaya & Timofeev 2019), appendix П5, p. 143–144:
//! lever 1 = AB about A = (0, 0), the cylinder 3 pivoted at D, the piston
//! with its rod 2 (piston C, rod end B pinned to the lever; l_шт = |CB|),
//! a load at K fixed to the lever (|AK| = l_AK, direction φ₁ − α). The
//! piston is h_min + s from D, so |DB| = L(s) = h_min + s + l_шт; the
//! piston and rod turn with the cylinder (ω₂ = ω₃).
//!
//! **Positions** (derived here, docs/dynamics.md § "A linear generalized
//! coordinate"): B is where the circle of radius l_AB about A meets the
//! circle of radius L about D; with u the unit vector D→A, |AD| = d and
//! cos γ = (L² + d² − l_AB²)/(2Ld), e₃ = u cos γ + σ u⊥ sin γ, σ = ±1 the
//! assembly kept from the start, B = D + L e₃.
//!
//! **Analogues** (derived here): from B = D + L e₃ = l_AB e₁,
//! dB/ds = e₃ + L ω_q3 n₃ = l_AB ω_q1 n₁ (n = e rotated by +90°); its
//! components along e₃ and n₃ give
//! ω_q1 = 1/(l_AB cos θ), θ = φ₁ + π/2 − φ₃ (the pressure angle at B), and
//! ω_q3 = l_AB ω_q1 cos(φ₁ − φ₃)/L. Differentiating once more,
//! 2ω_q3 n₃ + L ε_q3 n₃ − L ω_q3² e₃ = l_AB (ε_q1 n₁ − ω_q1² e₁), so
//! ε_q1 = (l_AB ω_q1² cos(φ₁ − φ₃) − L ω_q3²)/(l_AB cos θ) and
//! ε_q3 = (l_AB ε_q1 cos(φ₁ − φ₃) − l_AB ω_q1² sin(φ₁ − φ₃) − 2ω_q3)/L.
//! A point at r along the axis from D (C: r = h_min + s; S₂: r + l_CS2)
//! has V_q = (dr/ds) e₃ + r ω_q3 n₃, a_q = 2 (dr/ds) ω_q3 n₃ + r ε_q3 n₃ − r ω_q3² e₃
//! (dr/ds = 1); a point of the lever at ρ e(φ₁ + β) has V_q = ρ ω_q1 n,
//! a_q = ρ (ε_q1 n − ω_q1² e).
//!
//! [`CylinderDrive::solve`] fills a [`CylinderState`] and allocates
//! nothing, in the style of [`crate::Mechanism::solve`].

use tmm_geom::{Vec2, cross, perp};

use crate::dynamics::DynamicsError;
use crate::dynamics::error::show;

/// A point's position and its first and second analogues d/ds.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PointQ {
    /// Position, m.
    pub p: Vec2,
    /// V_q = dP/ds (dimensionless).
    pub v: Vec2,
    /// a_q = d²P/ds², 1/m.
    pub a: Vec2,
}

impl PointQ {
    /// The true velocity at speed V = ds/dt: V_q·V, m/s.
    pub fn velocity(&self, speed: f64) -> Vec2 {
        self.v * speed
    }

    /// The true acceleration at V = ds/dt and a = dV/dt: a_q V² + V_q a, m/s².
    pub fn acceleration(&self, speed: f64, accel: f64) -> Vec2 {
        self.a * (speed * speed) + self.v * accel
    }
}

/// The mechanism at one s: every link's angle and analogues, every point's
/// position and analogues.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CylinderState {
    /// The piston's travel s, m.
    pub s: f64,
    /// |DB| = h_min + s + l_шт, m.
    pub length: f64,
    /// The lever's angle φ₁, rad.
    pub phi1: f64,
    /// The cylinder's (and the piston's) axis direction D→B, φ₃, rad.
    pub phi3: f64,
    /// ω_q1 = dφ₁/ds, rad/m.
    pub omega_q1: f64,
    /// ω_q3 = ω_q2 = dφ₃/ds, rad/m.
    pub omega_q3: f64,
    /// ε_q1 = d²φ₁/ds², rad/m².
    pub eps_q1: f64,
    /// ε_q3 = ε_q2, rad/m².
    pub eps_q3: f64,
    /// The pressure angle at B, θ = φ₁ + π/2 − φ₃, rad.
    pub pressure_angle: f64,
    /// The rod's end B (on the lever).
    pub b: PointQ,
    /// The piston C.
    pub c: PointQ,
    /// The centre of mass S₂ of the piston and rod.
    pub s2: PointQ,
    /// The load's point K on the lever.
    pub k: PointQ,
}

/// The mechanism: geometry and the assembly kept from the start.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylinderDrive {
    /// The cylinder's pivot D (A is the origin), m.
    pub d: Vec2,
    /// The lever l_AB, m.
    pub lever: f64,
    /// D to the piston at s = 0, m.
    pub h_min: f64,
    /// D to the piston at the end of the travel, m; s_max = h_max − h_min.
    pub h_max: f64,
    /// The rod l_шт = |CB|, m.
    pub rod: f64,
    /// l_CS2: the piston-and-rod's centre of mass from C towards B, m.
    pub rod_center: f64,
    /// l_AK, m.
    pub load_arm: f64,
    /// α: K's direction measured clockwise from AB, rad.
    pub load_angle: f64,
    /// σ = ±1: the side of the line DA that B is on.
    pub branch: f64,
}

impl CylinderDrive {
    /// The mechanism with the lever near angle `start_angle` (rad) at s = 0
    /// (that picks which of the two assemblies is meant); S₂ at mid-rod, no
    /// load arm (set them with [`CylinderDrive::with_rod_center`] and
    /// [`CylinderDrive::with_load`]). Refused: a non-positive size, a travel
    /// h_max ≤ h_min, and a cylinder that cannot reach the lever's pin over
    /// its whole travel (|DB| outside [|AD − l_AB|, AD + l_AB]), with the
    /// travel s where it stops reaching.
    pub fn new(d: Vec2, lever: f64, h_min: f64, h_max: f64, rod: f64, start_angle: f64) -> Result<Self, DynamicsError> {
        for (f, v) in [
            ("cylinder.lever_length", lever),
            ("cylinder.h_min", h_min),
            ("cylinder.h_max", h_max),
            ("cylinder.rod", rod),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(DynamicsError::spec(f, format!("must be a positive length, got {}", show(v))));
            }
        }
        if !(d.x.is_finite() && d.y.is_finite()) || d.hypot() <= 1e-9 * lever {
            return Err(DynamicsError::spec(
                "cylinder.frame",
                "the cylinder's pivot D must be a point apart from the lever's pivot A = (0, 0)",
            ));
        }
        if !start_angle.is_finite() {
            return Err(DynamicsError::spec("cylinder.start_angle", "must be a finite angle"));
        }
        if h_max <= h_min {
            return Err(DynamicsError::spec(
                "cylinder.h_max",
                format!(
                    "the piston must travel: h_max = {} m must be larger than h_min = {} m",
                    show(h_max),
                    show(h_min)
                ),
            ));
        }
        let dist = d.hypot();
        let (lo, hi) = ((dist - lever).abs(), dist + lever);
        let (l0, l1) = (h_min + rod, h_max + rod);
        let margin = 1e-9 * hi;
        if l0 <= lo + margin {
            return Err(DynamicsError::spec(
                "cylinder.h_min",
                format!(
                    "the cylinder is too short for its travel: at s = 0 |DB| = h_min + l_шт = {} m, but the lever's pin B can be no nearer to D than |AD − l_AB| = {} m (the lever would have to pass its dead position); make h_min + rod longer than {} m",
                    show(l0),
                    show(lo),
                    show(lo)
                ),
            ));
        }
        if l1 >= hi - margin {
            let s_stop = hi - l0;
            return Err(DynamicsError::spec(
                "cylinder.h_max",
                format!(
                    "the piston's travel is too long for the lever: |DB| = h + l_шт reaches AD + l_AB = {} m, the lever's straight dead position, at s = {} m, before the end of the travel s_max = {} m; make h_max + rod shorter than {} m",
                    show(hi),
                    show(s_stop),
                    show(h_max - h_min),
                    show(hi)
                ),
            ));
        }
        if l1 <= lo + margin || l0 >= hi - margin {
            return Err(DynamicsError::spec(
                "cylinder.h_max",
                "the cylinder cannot reach the lever's pin B over its travel",
            ));
        }
        let u = -d / dist;
        let near = Vec2::new(start_angle.cos(), start_angle.sin()) * lever - d;
        let branch = if cross(u, near) < 0.0 { -1.0 } else { 1.0 };
        Ok(CylinderDrive {
            d,
            lever,
            h_min,
            h_max,
            rod,
            rod_center: 0.5 * rod,
            load_arm: 0.0,
            load_angle: 0.0,
            branch,
        })
    }

    /// S₂ at `l` (m) from the piston C towards B.
    pub fn with_rod_center(mut self, l: f64) -> Self {
        self.rod_center = l;
        self
    }

    /// The load's point K at `arm` (m) from A, `angle` (rad) clockwise from AB.
    pub fn with_load(mut self, arm: f64, angle: f64) -> Self {
        self.load_arm = arm;
        self.load_angle = angle;
        self
    }

    /// The travel s_max = h_max − h_min, m.
    pub fn travel(&self) -> f64 {
        self.h_max - self.h_min
    }

    /// Positions and analogues at travel `s` (m, 0…s_max, a little beyond
    /// allowed while the lever can follow); allocates nothing.
    pub fn solve(&self, s: f64, st: &mut CylinderState) -> Result<(), DynamicsError> {
        let len = self.h_min + s + self.rod;
        let dist = self.d.hypot();
        let l = self.lever;
        let cg = (len * len + dist * dist - l * l) / (2.0 * len * dist);
        if !(cg.is_finite() && cg.abs() < 1.0) {
            return Err(DynamicsError::spec(
                "cylinder",
                format!(
                    "the cylinder cannot reach the lever's pin B at s = {} m (|DB| = {} m)",
                    show(s),
                    show(len)
                ),
            ));
        }
        let sg = self.branch * (1.0 - cg * cg).sqrt();
        let u = -self.d / dist;
        let e3 = u * cg + perp(u) * sg;
        let n3 = perp(e3);
        let b = self.d + e3 * len;
        let e1 = b / l;
        let n1 = perp(e1);
        let phi1 = e1.y.atan2(e1.x);
        let phi3 = e3.y.atan2(e3.x);
        // cos θ = n₁·e₃, sin θ = cos(φ₁ − φ₃) = e₁·e₃ = n₁·n₃, sin(φ₁ − φ₃) = e₁·e₃ = n₁·n₃, sin(φ₁ − φ₃) = e₁·n₃
        let cos_t = n1.dot(e3);
        let (c13, s13) = (e1.dot(e3), e1.dot(n3));
        if cos_t.abs() < 1e-12 {
            return Err(DynamicsError::spec(
                "cylinder",
                format!("the lever is at its dead position at s = {} m (pressure angle 90°)", show(s)),
            ));
        }
        let w1 = 1.0 / (l * cos_t);
        let w3 = l * w1 * c13 / len;
        let e1q = (l * w1 * w1 * c13 - len * w3 * w3) / (l * cos_t);
        let e3q = (l * e1q * c13 - l * w1 * w1 * s13 - 2.0 * w3) / len;
        let on_axis = |r: f64| PointQ {
            p: self.d + e3 * r,
            v: e3 + n3 * (r * w3),
            a: n3 * (2.0 * w3 + r * e3q) - e3 * (r * w3 * w3),
        };
        let on_lever = |rho: f64, dir: Vec2| {
            let nd = perp(dir);
            PointQ {
                p: dir * rho,
                v: nd * (rho * w1),
                a: (nd * e1q - dir * (w1 * w1)) * rho,
            }
        };
        let rc = self.h_min + s;
        let (sa, ca) = self.load_angle.sin_cos();
        // e(φ₁ − α) = e₁ cos α − n₁ sin α
        let ek = e1 * ca - n1 * sa;
        *st = CylinderState {
            s,
            length: len,
            phi1,
            phi3,
            omega_q1: w1,
            omega_q3: w3,
            eps_q1: e1q,
            eps_q3: e3q,
            pressure_angle: c13.atan2(cos_t),
            b: on_lever(l, e1),
            c: on_axis(rc),
            s2: on_axis(rc + self.rod_center),
            k: on_lever(self.load_arm, ek),
        };
        Ok(())
    }
}
