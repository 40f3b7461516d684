//! The loads a user gives (заданные силы): mass and moment of inertia of
//! every link, gravity, external forces at points, external moments, and the
//! useful resistance (сила / момент полезного сопротивления).
//!
//! The seeds' empirical rules are helpers here: mass proportional to length,
//! m = q·l (seed 001: q = 10 kg/m; seed 003: 30 kg/m; seed 004: 2.4 kg/m), and
//! J_S = k·m·l² about the centre of mass (seed 001: k = 0.1…0.125;
//! seeds 003 and 004: k = 1/12, the thin uniform rod).

use tmm_geom::Vec2;

use super::error::ForceError;
use super::resistance::Resistance;
use super::slider_load::SliderLoad;
use crate::Mechanism;

/// A force at a point of a link, fixed in direction in the global frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointForce {
    /// The point in the link's local coordinates, m.
    pub local: Vec2,
    /// The force, global components, N.
    pub force: Vec2,
}

/// Mass, inertia and external loads of one link.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LinkLoad {
    /// Mass m, kg.
    pub mass: f64,
    /// Moment of inertia J_S about the centre of mass, kg·m².
    pub inertia: f64,
    /// External forces at points.
    pub forces: Vec<PointForce>,
    /// External moment (a couple) on the link, N·m, counter-clockwise positive.
    pub moment: f64,
}

/// All loads of a mechanism. `links` is indexed as
/// [`Mechanism::link_names`] (entry 0, the frame, is ignored).
#[derive(Debug, Clone, PartialEq)]
pub struct Loads {
    /// Per link.
    pub links: Vec<LinkLoad>,
    /// Gravity acceleration vector g, m/s² (`(0, −9.81)` for y up; zero
    /// when the weight is neglected, as seed 001 does).
    pub gravity: Vec2,
    /// The useful resistance (none, one, or several).
    pub resistance: Vec<Resistance>,
    /// Loads on sliders: gas forces by indicator diagram, forces by travel
    /// on one stroke, friction.
    pub sliders: Vec<SliderLoad>,
    /// The machine's cycle the loads repeat over.
    pub cycle: MachineCycle,
}

/// The machine's cycle (цикл машины): one turn of the crank, or two for a
/// four-stroke engine (Chernaya & Timofeev 2019, П2: "one working cycle =
/// two revolutions"), and where it starts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MachineCycle {
    /// Turns of the crank per cycle: 1 or 2.
    pub turns: u32,
    /// Absolute crank angle where the cycle starts, rad; `None`: at the
    /// start of the working stroke of the output (crank angle 0 when it has
    /// none).
    pub start: Option<f64>,
}

impl Default for MachineCycle {
    fn default() -> Self {
        MachineCycle { turns: 1, start: None }
    }
}

impl MachineCycle {
    /// The cycle's length in crank angle, rad: 2π·turns.
    ///
    /// ```
    /// let c = tmm_linkage::forces::MachineCycle { turns: 2, start: None };
    /// assert!((c.period() - 4.0 * std::f64::consts::PI).abs() < 1e-15);
    /// ```
    pub fn period(&self) -> f64 {
        2.0 * std::f64::consts::PI * self.turns as f64
    }
}

impl Loads {
    /// No loads at all on a mechanism's links.
    pub fn new(m: &Mechanism) -> Self {
        Loads {
            links: vec![LinkLoad::default(); m.link_names.len()],
            gravity: Vec2::ZERO,
            resistance: Vec::new(),
            sliders: Vec::new(),
            cycle: MachineCycle::default(),
        }
    }

    /// Check that the loads fit the mechanism and are physical.
    pub fn check(&self, m: &Mechanism) -> Result<(), ForceError> {
        if self.links.len() != m.link_names.len() {
            return Err(ForceError::load(
                "links",
                format!("{} link loads for {} links", self.links.len(), m.link_names.len()),
            ));
        }
        if !(self.gravity.x.is_finite() && self.gravity.y.is_finite()) {
            return Err(ForceError::load("gravity", "must be finite"));
        }
        for (i, l) in self.links.iter().enumerate().skip(1) {
            let name = &m.link_names[i];
            if !(l.mass.is_finite() && l.mass >= 0.0) {
                return Err(ForceError::load(
                    format!("links.{name}.mass"),
                    format!("the mass must be ≥ 0 kg, not {}", l.mass),
                ));
            }
            if !(l.inertia.is_finite() && l.inertia >= 0.0) {
                return Err(ForceError::load(
                    format!("links.{name}.inertia"),
                    format!("the moment of inertia must be ≥ 0 kg·m², not {}", l.inertia),
                ));
            }
            if !l.moment.is_finite() {
                return Err(ForceError::load(format!("links.{name}.moment"), "must be finite"));
            }
            for (k, f) in l.forces.iter().enumerate() {
                if ![f.local.x, f.local.y, f.force.x, f.force.y].iter().all(|v| v.is_finite()) {
                    return Err(ForceError::load(format!("links.{name}.forces[{k}]"), "must be finite"));
                }
            }
        }
        for (k, r) in self.resistance.iter().enumerate() {
            if r.link == 0 || r.link >= m.link_names.len() {
                return Err(ForceError::load(
                    format!("resistance[{k}].link"),
                    "the useful resistance must act on a moving link",
                ));
            }
            r.law.check(&format!("resistance[{k}]"))?;
        }
        if !(self.cycle.turns == 1 || self.cycle.turns == 2) {
            return Err(ForceError::load(
                "cycle.turns",
                format!(
                    "the machine's cycle is 1 turn of the crank (360°) or 2 (720°, a four-stroke engine), not {}",
                    self.cycle.turns
                ),
            ));
        }
        if let Some(s) = self.cycle.start {
            if !s.is_finite() {
                return Err(ForceError::load("cycle.start", "must be finite"));
            }
        }
        for (k, s) in self.sliders.iter().enumerate() {
            if s.link == 0 || s.link >= m.link_names.len() {
                return Err(ForceError::load(
                    format!("sliders[{k}].link"),
                    "a slider load must act on a moving link",
                ));
            }
        }
        Ok(())
    }
}

/// Mass proportional to length, m = q·l (seed 001, sheet 3: "массы звеньев
/// считаем пропорциональными их длинам – mᵢ = (10…20)·lᵢ").
///
/// ```
/// assert!((tmm_linkage::forces::loads::mass_per_length(10.0, 0.48) - 4.8).abs() < 1e-12);
/// ```
pub fn mass_per_length(q: f64, length: f64) -> f64 {
    q * length
}

/// Moment of inertia about the centre of mass, J_S = k·m·l² (seed 001:
/// "Jsi = (0,1 … 0,125)·lᵢ²·mᵢ"; k = 1/12 is the thin uniform rod,
/// Timoshenko & Young, *Engineering Mechanics*, table of moments of inertia).
///
/// ```
/// // seed 001: J_S2 = 0.1 · 4.8 · 0.48² = 0.110592 kg·m²
/// assert!((tmm_linkage::forces::loads::inertia_k(0.1, 4.8, 0.48) - 0.110592).abs() < 1e-12);
/// ```
pub fn inertia_k(k: f64, mass: f64, length: f64) -> f64 {
    k * mass * length * length
}

/// The length of a link for its distributed weight and inertia: the largest
/// distance between two of its points (its joints, wherever they are stored,
/// and its other named points) — for a bar the distance between its two
/// joints, for a three-joint rocker E–B–C with B and C on opposite sides of
/// E the whole |BC|; 0 for a slider block whose only point is its joint.
pub fn link_length(m: &Mechanism, link: usize) -> f64 {
    let mut pts = m.points.iter().filter(|p| p.link == link).map(|p| p.local);
    // points shared with earlier links are stored on the first link only;
    // use the pairs to find every joint of the link
    let mut locals: Vec<Vec2> = Vec::new();
    for p in &m.pairs {
        if let crate::mechanism::Pair::R { a, b, la, lb, .. } = *p {
            if a == link {
                locals.push(la);
            }
            if b == link {
                locals.push(lb);
            }
        }
    }
    locals.extend(pts.by_ref());
    let mut best = 0.0f64;
    for (i, p) in locals.iter().enumerate() {
        for q in &locals[i + 1..] {
            best = best.max((*p - *q).hypot());
        }
    }
    best
}
