//! The vectors of the course's velocity and acceleration plans (планы
//! скоростей и ускорений) at one position, group by group from the crank.
//!
//! For a point Y of a link whose point X is already known (Artobolevsky § 14):
//! `V_Y = V_X + V_YX`, `V_YX = ω × XY` (⊥ XY);
//! `a_Y = a_X + aⁿ_YX + aᵗ_YX`, `aⁿ_YX = −ω²·XY` (along YX, towards X),
//! `aᵗ_YX = ε × XY` (⊥ XY).
//! For a slider point Y on a guide of link g, with Y_g the point of g that
//! coincides with Y (Artobolevsky § 15):
//! `V_Y = V_Yg + V_rel` (along the guide), `a_Y = a_Yg + aᵏ + aʳ`,
//! Coriolis `aᵏ = 2 ω_g × V_rel`, relative `aʳ` along the guide.
//! Plan points are the ends of the absolute vectors from the pole; each
//! relative vector joins two of them, as drawn in the course.

use tmm_geom::{Vec2, perp};

use crate::mechanism::{Mechanism, Pair, Solution};

/// The kind of a plan vector.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum VectorKind {
    /// From the pole to a point's image.
    Absolute,
    /// Relative rotation velocity `V_YX`.
    Relative,
    /// Normal acceleration `aⁿ_YX`.
    Normal,
    /// Tangential acceleration `aᵗ_YX`.
    Tangential,
    /// Sliding velocity or relative acceleration along a guide.
    Sliding,
    /// Coriolis acceleration `aᵏ`.
    Coriolis,
}

/// One vector of a plan, in plan space (m/s or m/s²), pole at the origin.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanVector {
    /// Label as the course writes it: `V_B`, `V_CB`, `a^n_CB`, `a^k_B3B2`.
    pub label: String,
    /// Start of the vector.
    pub from: Vec2,
    /// End of the vector.
    pub to: Vec2,
    /// Kind.
    pub kind: VectorKind,
}

/// Both plans at one position.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Plans {
    /// Velocity plan vectors.
    pub velocity: Vec<PlanVector>,
    /// Acceleration plan vectors.
    pub acceleration: Vec<PlanVector>,
}

fn pv(label: String, from: Vec2, to: Vec2, kind: VectorKind) -> PlanVector {
    PlanVector { label, from, to, kind }
}

/// Build both plans for a solved position.
pub fn plans(m: &Mechanism, sol: &Solution) -> Plans {
    let mut out = Plans::default();
    let name = |i: usize| m.points[i].name.as_str();
    // absolute vectors of every point not on the frame
    for (i, p) in m.points.iter().enumerate() {
        if p.link == 0 {
            continue;
        }
        let s = &sol.points[i];
        out.velocity
            .push(pv(format!("V_{}", p.name), Vec2::ZERO, s.v, VectorKind::Absolute));
        out.acceleration
            .push(pv(format!("a_{}", p.name), Vec2::ZERO, s.a, VectorKind::Absolute));
    }
    // links in solving order: crank, then each group's links
    let mut order = vec![m.crank.link];
    for g in &m.groups {
        order.extend(g.info.link_ids.iter().copied());
    }
    for &l in &order {
        let ls = &sol.links[l];
        // the link's base point: its first revolute joint shared with an earlier link or the frame
        let joints: Vec<usize> = m
            .points
            .iter()
            .enumerate()
            .filter(|(_, p)| on_link(m, p.name.as_str(), l))
            .map(|(i, _)| i)
            .collect();
        let Some(&base) = joints.iter().find(|&&i| {
            m.pairs
                .iter()
                .any(|pr| matches!(pr, Pair::R { .. }) && pr.point() == i && is_on(pr, l))
        }) else {
            continue;
        };
        let x = &sol.points[base];
        for &j in &joints {
            // relative vectors join joints; other points (centres of mass)
            // are found on the plan by similarity and get only their absolute vector
            if j == base || !m.pairs.iter().any(|pr| pr.point() == j) {
                continue;
            }
            let y = &sol.points[j];
            let r = y.p - x.p;
            let an = -r * (ls.omega * ls.omega);
            let at = perp(r) * ls.eps;
            out.velocity
                .push(pv(format!("V_{}{}", name(j), name(base)), x.v, y.v, VectorKind::Relative));
            out.acceleration
                .push(pv(format!("a^n_{}{}", name(j), name(base)), x.a, x.a + an, VectorKind::Normal));
            out.acceleration.push(pv(
                format!("a^t_{}{}", name(j), name(base)),
                x.a + an,
                x.a + an + at,
                VectorKind::Tangential,
            ));
        }
    }
    // sliding pairs
    for p in &m.pairs {
        if let Pair::P { slider, guide, point, .. } = *p {
            let y = &sol.points[point];
            let g = &sol.links[guide];
            let (vg, ag) = g.kin_at(y.p);
            let vrel = y.v - vg;
            let cor = perp(vrel) * (2.0 * g.omega);
            // the frame is link 0 in the course's labels
            let (ns, ng) = (&m.link_names[slider], if guide == 0 { "0" } else { m.link_names[guide].as_str() });
            let yn = name(point);
            if guide != 0 {
                out.velocity.push(pv(format!("V_{yn}{ng}"), Vec2::ZERO, vg, VectorKind::Absolute));
                out.acceleration
                    .push(pv(format!("a_{yn}{ng}"), Vec2::ZERO, ag, VectorKind::Absolute));
            }
            out.velocity.push(pv(format!("V_{yn}{ns}{yn}{ng}"), vg, y.v, VectorKind::Sliding));
            if guide != 0 {
                out.acceleration
                    .push(pv(format!("a^k_{yn}{ns}{yn}{ng}"), ag, ag + cor, VectorKind::Coriolis));
            }
            out.acceleration
                .push(pv(format!("a^r_{yn}{ns}{yn}{ng}"), ag + cor, y.a, VectorKind::Sliding));
        }
    }
    out
}

fn is_on(p: &Pair, l: usize) -> bool {
    let (a, b) = p.links();
    a == l || b == l
}

fn on_link(m: &Mechanism, point: &str, l: usize) -> bool {
    m.points.iter().any(|p| p.name == point && p.link == l)
        || m.pairs.iter().any(|pr| match *pr {
            Pair::R { a, b, point: k, .. } => (a == l || b == l) && m.points[k].name == point,
            Pair::P { .. } => false,
        })
}
