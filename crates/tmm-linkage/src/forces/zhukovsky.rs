//! Zhukovsky's lever (рычаг Жуковского): the balancing torque found
//! independently of the reactions, from virtual power (the principle of
//! virtual work with the real velocities as virtual ones):
//!
//! `M_b·ω₁ + Σ F·v + Σ M·ω = 0`
//!
//! over every load — weights, inertia forces at the centres of mass, inertia
//! torques, external forces at their points, external moments and the useful
//! resistance. The pair reactions do no work (no friction).
//! Zhukovsky's construction is the same equation drawn: the velocity plan
//! turned by 90° with each force at the image of its point; the moment of F at
//! the image `k × v` about the pole is `(k × v) × F = −F·v`, so the lever is
//! in equilibrium exactly when the virtual power vanishes (Artobolevsky 1988,
//! § 15; seed 001 sheet 3).

use tmm_geom::{Vec2, perp};

use super::inertia::inertia_load;
use super::loads::Loads;
use crate::{Mechanism, Solution};

/// The balancing torque on the input link by virtual power, N·m
/// (counter-clockwise positive), from the raw loads and `resistance`
/// (the magnitude of each useful resistance at this position).
pub fn balancing_moment(m: &Mechanism, loads: &Loads, sol: &Solution, resistance: &[f64]) -> f64 {
    let mut power = 0.0;
    for l in 1..m.link_names.len() {
        let ld = &loads.links[l];
        let st = &sol.links[l];
        let (fi, s, mi) = inertia_load(st, m.mass_centers[l], ld.mass, ld.inertia);
        let (vs, _) = st.kin_at(s);
        power += (fi + loads.gravity * ld.mass).dot(vs) + (mi + ld.moment) * st.omega;
        for pf in &ld.forces {
            power += pf.force.dot(st.point(pf.local).v);
        }
    }
    for (r, &val) in loads.resistance.iter().zip(resistance) {
        let st = &sol.links[r.link];
        let (f, p, c) = r.apply(st, val);
        power += f.dot(st.kin_at(p).0) + c * st.omega;
    }
    -power / sol.links[m.crank.link].omega
}

/// One force drawn on Zhukovsky's lever.
#[derive(Debug, Clone, PartialEq)]
pub struct LeverForce {
    /// What it is (`Fu2`, `G3`, `Pb`, `Mu2'`…).
    pub label: String,
    /// The image of its point: the velocity turned by +90°, m/s.
    pub image: Vec2,
    /// The force, N.
    pub force: Vec2,
}

/// The velocity plan turned by +90°: image of every named point, m/s.
pub fn lever_points(m: &Mechanism, sol: &Solution) -> Vec<(String, Vec2)> {
    m.points.iter().zip(&sol.points).map(|(p, s)| (p.name.clone(), perp(s.v))).collect()
}

/// The forces on the lever: weights and inertia forces at the images of the
/// centres of mass, external forces at their points, couples replaced by pairs
/// of forces at the images of two points of the link (as the course does),
/// the balancing force at the image of the crank pin. The sum of their moments
/// about the pole is zero (up to rounding).
pub fn lever_forces(m: &Mechanism, loads: &Loads, sol: &Solution, fs: &super::ForceSolution) -> Vec<LeverForce> {
    let mut out = Vec::new();
    for l in 1..m.link_names.len() {
        let ld = &loads.links[l];
        let st = &sol.links[l];
        let name = &m.link_names[l];
        let lf = &fs.links[l];
        let vs = st.kin_at(lf.s).0;
        let g = lf.inertia_force + lf.weight;
        if g.hypot() > 0.0 {
            out.push(LeverForce {
                label: format!("Fu{name}+G{name}"),
                image: perp(vs),
                force: g,
            });
        }
        for (k, pf) in ld.forces.iter().enumerate() {
            out.push(LeverForce {
                label: format!("F{name}.{k}"),
                image: perp(st.point(pf.local).v),
                force: pf.force,
            });
        }
        let couple = lf.inertia_moment + ld.moment;
        let mut couple = couple;
        for (r, &val) in loads.resistance.iter().zip(&fs.resistance) {
            if r.link == l {
                let (f, p, c) = r.apply(st, val);
                if f.hypot() > 0.0 {
                    out.push(LeverForce {
                        label: format!("Fr{name}"),
                        image: perp(st.kin_at(p).0),
                        force: f,
                    });
                }
                couple += c;
            }
        }
        if couple != 0.0 {
            // two points of the link as far apart as possible
            let pts: Vec<Vec2> = m.pairs.iter().filter_map(|p| pair_local(p, l)).collect();
            if let Some((a, b)) = farthest(&pts) {
                let (pa, pb) = (st.pos(a), st.pos(b));
                let d = pb - pa;
                let f = perp(d) * (couple / d.hypot2());
                out.push(LeverForce {
                    label: format!("M{name}'"),
                    image: perp(st.kin_at(pb).0),
                    force: f,
                });
                out.push(LeverForce {
                    label: format!("M{name}''"),
                    image: perp(st.kin_at(pa).0),
                    force: -f,
                });
            }
        }
    }
    let pin = &sol.points[m.crank.pin];
    out.push(LeverForce {
        label: "Pb".into(),
        image: perp(pin.v),
        force: fs.balancing_force_vec,
    });
    out
}

fn pair_local(p: &crate::mechanism::Pair, l: usize) -> Option<Vec2> {
    match *p {
        crate::mechanism::Pair::R { a, b, la, lb, .. } => {
            if a == l {
                Some(la)
            } else if b == l {
                Some(lb)
            } else {
                None
            }
        }
        crate::mechanism::Pair::P { slider, ps, .. } => (slider == l).then_some(ps),
    }
}

fn farthest(p: &[Vec2]) -> Option<(Vec2, Vec2)> {
    let mut best: Option<(f64, Vec2, Vec2)> = None;
    for (i, a) in p.iter().enumerate() {
        for b in &p[i + 1..] {
            let d = (*a - *b).hypot();
            if d > 1e-12 && best.is_none_or(|x| d > x.0) {
                best = Some((d, *a, *b));
            }
        }
    }
    best.map(|(_, a, b)| (a, b))
}
