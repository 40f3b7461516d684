//! Reduction to the crank (приведение к звену приведения): at any crank
//! angle, the variable part of the reduced moment of inertia I_II
//! (переменная часть приведённого момента инерции), its derivative
//! dI_II/dφ, and the reduced moment of the loads M_c (приведённый момент
//! сил сопротивления и тяжести), all from the exact velocity and
//! acceleration analogues of the linkage core: the mechanism is solved with
//! the crank turning at unit speed in its own direction and without angular
//! acceleration, so that every velocity *is* the analogue dx/dφ and every
//! acceleration the second analogue d²x/dφ².
//!
//! Formulas (Артоболевский И. И., *Теория механизмов и машин*, 1988, the
//! reduction of masses and forces;
//! the derivative derived in docs/dynamics.md):
//!
//! - I_II(φ) = Σ_{i≠1} [m_i·|v_Si/ω₁|² + J_Si·(ω_i/ω₁)²];
//! - dI_II/dφ = 2·Σ_{i≠1} [m_i·(v_Si/ω₁)·(a_Si/ω₁²) + J_Si·(ω_i/ω₁)·(ε_i/ω₁²)] at ε₁ = 0;
//! - M_c(φ) = Σ (F·v_F + M·ω)/ω₁ over weights, external forces and moments
//!   and the useful resistance of every link (the crank included); inertia
//!   forces are not loads here, they are in I_II.
//!
//! φ here is the crank angle turned in the direction of rotation from the
//! start of the cycle (the start of the working stroke when the output has
//! one), so that ω₁ > 0 in the equation of motion whatever the direction.

use std::f64::consts::PI;

use tmm_geom::Vec2;

use super::error::DynamicsError;
use crate::forces::stroke::{Stroke, Working};
use crate::forces::{ActiveSliderLoad, Kinetostatics, Loads, MachineCycle};
use crate::{Mechanism, Solution};

/// The reduced quantities at one crank angle.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Reduced {
    /// Variable part of the reduced moment of inertia I_II, kg·m².
    pub inertia: f64,
    /// Its derivative dI_II/dφ, kg·m²/rad.
    pub inertia_derivative: f64,
    /// Reduced moment of the loads M_c, N·m (negative when they resist).
    pub moment: f64,
}

/// Gauss–Legendre 3-point nodes on [−1, 1] and weights (Abramowitz & Stegun
/// 1964, table 25.4): exact for polynomials of degree 5.
const GL3: [(f64, f64); 3] = [
    (-0.774_596_669_241_483_4, 5.0 / 9.0),
    (0.0, 8.0 / 9.0),
    (0.774_596_669_241_483_4, 5.0 / 9.0),
];

/// Evaluates the reduced quantities of one mechanism under given loads.
#[derive(Debug, Clone)]
pub struct Reducer {
    /// The mechanism with its crank at unit speed (in its direction), ε₁ = 0.
    pub unit: Mechanism,
    /// The loads.
    pub loads: Loads,
    /// The output's stroke, when there is one.
    pub stroke: Option<Stroke>,
    /// Absolute crank angle of the start of the cycle, rad.
    pub phi_start: f64,
    /// Direction of rotation: +1 counter-clockwise, −1 clockwise.
    pub dir: f64,
    /// The crank's own moment of inertia about its pivot, J_S1 + m₁·|AS₁|², kg·m².
    pub inertia_crank: f64,
    /// The machine cycle's length, rad: 2π, or 4π for a four-stroke engine.
    pub period: f64,
    /// The slider loads (gas forces, forces on a stroke, friction), prepared.
    pub sliders: Vec<ActiveSliderLoad>,
    /// Angles of the cycle where a load law may jump or kink (the dead
    /// positions of the output and of every loaded slider, the changes of
    /// process), rad from the start of the cycle, increasing, in [0, period).
    breaks: Vec<f64>,
    /// Some resistance law needs the phase of the cycle.
    needs_phase: bool,
}

impl Reducer {
    /// Prepare: check the loads and find the output's stroke as the
    /// kinetostatics does (the cycle starts at the beginning of the working
    /// stroke; at crank angle 0 when the output has no dead positions).
    pub fn new(m: &Mechanism, loads: &Loads, working: Working) -> Result<Self, DynamicsError> {
        let k = Kinetostatics::with_working(m, loads.clone(), working)?;
        let stroke = match k.stroke {
            Some(s) => Some(s),
            None => Stroke::find(m, m.output, working).ok(),
        };
        let dir = m.crank.omega.signum();
        let mut unit = m.clone();
        unit.crank.omega = dir;
        unit.crank.eps = 0.0;
        let period = loads.cycle.period();
        let (phi_start, mut breaks) = match &stroke {
            Some(s) => (s.phi_start, vec![0.0, s.work_span]),
            None => (0.0, Vec::new()),
        };
        let plain = loads.cycle == MachineCycle::default() && k.sliders.is_empty();
        let phi_start = if plain { phi_start } else { k.cycle_start };
        if !plain {
            // every dead position (the output's, each loaded slider's) on
            // every turn of the cycle, and the changes of process
            let turns = loads.cycle.turns;
            let mut dead: Vec<f64> = stroke.iter().flat_map(|s| [s.phi_start, s.phi_end]).collect();
            dead.extend(k.sliders.iter().flat_map(|a| a.dead_positions()));
            breaks.clear();
            for d in dead {
                let first = (dir * (d - phi_start)).rem_euclid(2.0 * PI);
                breaks.extend((0..turns).map(|t| first + 2.0 * PI * t as f64));
            }
            breaks.extend(k.sliders.iter().flat_map(|a| a.process_bounds()));
            breaks.iter_mut().for_each(|b| *b = b.rem_euclid(period));
            breaks.sort_by(f64::total_cmp);
            breaks.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
        }
        let c = m.crank.link;
        let ld = &loads.links[c];
        let r = m.mass_centers[c] - m.crank.pivot_local;
        Ok(Reducer {
            unit,
            loads: loads.clone(),
            stroke,
            phi_start,
            dir,
            inertia_crank: ld.inertia + ld.mass * r.hypot2(),
            period,
            sliders: k.sliders.clone(),
            breaks,
            needs_phase: loads.resistance.iter().any(|r| r.law.needs_stroke()),
        })
    }

    /// A solution buffer for [`Reducer::eval`].
    pub fn solution(&self) -> Solution {
        self.unit.solution()
    }

    /// Absolute crank angle of cycle angle `psi`, rad.
    #[inline]
    pub fn crank_angle(&self, psi: f64) -> f64 {
        self.phi_start + self.dir * psi
    }

    /// The reduced quantities at cycle angle `psi` (rad from the start of the
    /// cycle in the direction of rotation). Allocates nothing.
    pub fn eval(&self, psi: f64, sol: &mut Solution) -> Result<Reduced, DynamicsError> {
        self.unit.solve(self.crank_angle(psi), sol)?;
        Ok(self.reduce(psi, sol))
    }

    /// The reduced quantities of a position solved at unit crank speed, at
    /// cycle angle `psi` (rad; it chooses the processes of the indicator
    /// diagrams).
    #[inline]
    pub fn reduce(&self, psi: f64, sol: &Solution) -> Reduced {
        let m = &self.unit;
        let loads = &self.loads;
        let c = m.crank.link;
        let (mut inertia, mut dinertia, mut power) = (0.0, 0.0, 0.0);
        for l in 1..m.link_names.len() {
            let ld = &loads.links[l];
            let st = &sol.links[l];
            let s = st.pos(m.mass_centers[l]);
            let (vs, as_) = st.kin_at(s);
            if l != c {
                inertia += ld.mass * vs.hypot2() + ld.inertia * st.omega * st.omega;
                dinertia += 2.0 * (ld.mass * vs.dot(as_) + ld.inertia * st.omega * st.eps);
            }
            power += (loads.gravity * ld.mass).dot(vs) + ld.moment * st.omega;
            for pf in &ld.forces {
                power += pf.force.dot(st.kin_at(st.pos(pf.local)).0);
            }
        }
        if !loads.resistance.is_empty() {
            let phase = if self.needs_phase {
                self.stroke.as_ref().map(|s| s.phase(sol)).unwrap_or_default()
            } else {
                Default::default()
            };
            for r in &loads.resistance {
                let st = &sol.links[r.link];
                let (f, p, cpl) = r.apply(st, r.law.value(&phase));
                power += f.dot(st.kin_at(p).0) + cpl * st.omega;
            }
        }
        if !self.sliders.is_empty() {
            let psi = psi.rem_euclid(self.period);
            for a in &self.sliders {
                let (f, p) = a.force(sol, psi);
                power += f.dot(sol.links[a.load.link].kin_at(p).0);
            }
        }
        // the crank turns at unit speed: the power is the moment
        Reduced {
            inertia,
            inertia_derivative: dinertia,
            moment: power,
        }
    }

    /// ∫ M_c dφ from `a` to `b` (a ≤ b, cycle angles, rad): 3-point
    /// Gauss–Legendre on each piece between the dead positions of the output,
    /// where a load law may jump or kink. Allocates nothing.
    pub fn work(&self, a: f64, b: f64, sol: &mut Solution) -> Result<f64, DynamicsError> {
        let mut lo = a;
        let mut total = 0.0;
        // cut points strictly inside (a, b), in increasing order, taken
        // modulo the cycle: the breaks are sorted, and so is each shifted copy
        for k in -1..=1 {
            for &br in &self.breaks {
                let x = br + self.period * k as f64;
                if x > a + 1e-12 && x < b - 1e-12 {
                    total += self.gauss(lo, x, sol)?;
                    lo = x;
                }
            }
        }
        total += self.gauss(lo, b, sol)?;
        Ok(total)
    }

    fn gauss(&self, a: f64, b: f64, sol: &mut Solution) -> Result<f64, DynamicsError> {
        let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
        let mut s = 0.0;
        for (x, w) in GL3 {
            s += w * self.eval(mid + half * x, sol)?.moment;
        }
        Ok(s * half)
    }
}

/// The mechanism with its crank at a given speed and acceleration (for the
/// kinetostatics with the true motion of the crank, ω₁ and ε₁ from the
/// dynamics): signed, counter-clockwise positive.
///
/// ```
/// # use tmm_linkage::*; use tmm_geom::Vec2;
/// # let def = MechanismDef { fixed: vec![("A".into(), Vec2::ZERO), ("D".into(), Vec2::new(0.51, 0.0))],
/// #   links: vec![LinkDef::bar("1", "A", "B", 0.12), LinkDef::bar("2", "B", "C", 0.48), LinkDef::bar("3", "D", "C", 0.38)],
/// #   input: Some(InputDef { link: "1".into(), pivot: "A".into(), pin: "B".into(), omega: 10.0, epsilon: 0.0 }), ..Default::default() };
/// let m = Mechanism::new(&def).unwrap();
/// let m2 = tmm_linkage::dynamics::with_crank_motion(&m, 12.0, -3.0).unwrap();
/// let mut s = m2.solution();
/// m2.solve(0.4, &mut s).unwrap();
/// assert_eq!((s.links[1].omega, s.links[1].eps), (12.0, -3.0));
/// ```
pub fn with_crank_motion(m: &Mechanism, omega: f64, eps: f64) -> Result<Mechanism, DynamicsError> {
    if !(omega.is_finite() && omega != 0.0 && eps.is_finite()) {
        return Err(DynamicsError::spec(
            "crank_motion",
            format!("the crank speed must be finite and non-zero and its acceleration finite (ω₁ = {omega}, ε₁ = {eps})"),
        ));
    }
    let mut m2 = m.clone();
    m2.crank.omega = omega;
    m2.crank.eps = eps;
    Ok(m2)
}

/// Kinetic energy of every moving link at a solved position, J: Σ ½·m·|v_S|² + ½·J_S·ω²
/// (König's theorem), the crank included.
pub fn kinetic_energy(m: &Mechanism, loads: &Loads, sol: &Solution) -> f64 {
    let mut t = 0.0;
    for l in 1..m.link_names.len() {
        let ld = &loads.links[l];
        let st = &sol.links[l];
        let v: Vec2 = st.point(m.mass_centers[l]).v;
        t += 0.5 * (ld.mass * v.hypot2() + ld.inertia * st.omega * st.omega);
    }
    t
}
