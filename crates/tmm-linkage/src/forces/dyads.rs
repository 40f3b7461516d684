//! Dyads whose reactions are written out for their pair kinds, prepared
//! once: the links, each joint's local vector on the link whose equations
//! use it, and the side of each pair, so that a position costs two
//! equilibrium equations and no branching on the pair kinds. The same
//! elimination as [`solve_dyad`](super::group::solve_dyad) (docs/forces.md, "Dyads: the course's
//! elimination"), the same results and the same singularity test; a dyad
//! of any other kind or order goes to [`solve_dyad`](super::group::solve_dyad).
//!
//! - [`RrrDyad`]: three revolute pairs (the first kind);
//! - [`RrpDyad`]: revolute, revolute, and a slider on a guide (the second
//!   kind, the crank-slider's rod and slider).

use tmm_geom::{Vec2, cross, perp};

use super::group::{PairForce, is_ordered_dyad};
use crate::mechanism::Pair;
use crate::state::{LinkState, rot};

/// A dyad of three revolute pairs (RRR, the first kind), prepared once: the
/// links, each joint's local vector on the link whose equations use it, and
/// the side of each pair, so that a position costs two moment equations and
/// no branching on the pair kinds.
///
/// The same elimination as [`solve_dyad`](super::group::solve_dyad) (docs/forces.md, "Dyads: the
/// course's elimination") written out for revolute pairs, derived here
/// (seed 001 sheet 3: "ΣM(C) = 0 ⇒ R^τ"): with
/// joints J₁ (outer, link x), J₂ (inner) and J₃ (outer, link y), the force
/// F on x from y satisfies, by the moments about J₁ of link x and about J₃
/// of link y,
/// `(J₂ − J₁) × F = −M_x(J₁)` and `(J₂ − J₃) × F = M_y(J₃)`,
/// where `M(J) = M_o − (J − o) × Q` is the moment of the applied load
/// `(Q, M_o about the link's origin o)` about J; then the outer reactions
/// follow from each link's ΣF = 0: `F₁ = −Q_x − F`, `F₃ = −Q_y + F`.
#[derive(Debug, Clone, Copy)]
pub struct RrrDyad {
    x: usize,
    y: usize,
    /// J₁, J₂ on link x; J₂, J₃ on link y, local.
    j1x: Vec2,
    j2x: Vec2,
    j2y: Vec2,
    j3y: Vec2,
    /// The pair's first link (`a`) is the one on which the force is found:
    /// x for pairs 0 and 1, y for pair 2 (else the force is reversed).
    a_is: [bool; 3],
}

impl RrrDyad {
    /// Prepare a dyad ordered as [`is_ordered_dyad`] says; `None` unless all
    /// three pairs are revolute.
    pub fn new(pairs: &[&Pair], links: &[usize]) -> Option<Self> {
        if !is_ordered_dyad(pairs, links) {
            return None;
        }
        let (x, y) = (links[0], links[1]);
        let local = |p: &Pair, l: usize| match *p {
            Pair::R { a, la, lb, .. } => Some(if a == l { la } else { lb }),
            Pair::P { .. } => None,
        };
        let first = |p: &Pair| p.links().0;
        Some(RrrDyad {
            x,
            y,
            j1x: local(pairs[0], x)?,
            j2x: local(pairs[1], x)?,
            j2y: local(pairs[1], y)?,
            j3y: local(pairs[2], y)?,
            a_is: [first(pairs[0]) == x, first(pairs[1]) == x, first(pairs[2]) == y],
        })
    }

    /// Same contract as [`solve_dyad`](super::group::solve_dyad).
    #[inline(always)]
    pub fn solve(&self, states: &[LinkState], q: &[(Vec2, f64)], out: &mut [PairForce]) -> bool {
        let (sx, sy) = (&states[self.x], &states[self.y]);
        let (r1, r2x) = (rot(sx.u, self.j1x), rot(sx.u, self.j2x));
        let (r2y, r3) = (rot(sy.u, self.j2y), rot(sy.u, self.j3y));
        let (qx, qy) = (q[0], q[1]);
        let mx1 = qx.1 - cross(r1, qx.0);
        let my3 = qy.1 - cross(r3, qy.0);
        let (d1, d3) = (r2x - r1, r2y - r3);
        // d × F = d.x·F.y − d.y·F.x: rows (−d1.y, d1.x) = −mx1, (−d3.y, d3.x) = my3
        let det = cross(d1, d3);
        let size = (d1.x.abs() + d1.y.abs()) * (d3.x.abs() + d3.y.abs());
        if det.abs() <= 1e-12 * size || !det.is_finite() {
            return false;
        }
        let id = 1.0 / det;
        let f = Vec2::new((-mx1 * d3.x - d1.x * my3) * id, (-d1.y * my3 - mx1 * d3.y) * id);
        let forces = [-qx.0 - f, f, f - qy.0];
        // the joints, from the vectors found above (no rotation of their own)
        let at = [sx.o + r1, sx.o + r2x, sy.o + r3];
        for k in 0..3 {
            let force = if self.a_is[k] { forces[k] } else { -forces[k] };
            out[k] = PairForce {
                force,
                at: at[k],
                couple: 0.0,
            };
        }
        out[..3].iter().all(|f| f.force.x.is_finite() && f.force.y.is_finite())
    }
}

/// A dyad of two revolute pairs and a slider (RRP, the second kind): link
/// x with the outer revolute joint J₁ and the inner joint J₂, link y (the
/// slider) with J₂ and the slider's point P on a guide of a known link g
/// with unit normal n, prepared once.
///
/// The elimination of [`solve_dyad`](super::group::solve_dyad) written out
/// for these pairs, derived here (docs/forces.md, "Dyads written out"):
/// the slider's ΣF = 0 gives the force F on
/// x from y at J₂ as `F = Q_y + λ·n`, λ the guide's normal force on the
/// slider; x's moments about J₁, `M_x(J₁) + (J₂ − J₁) × F = 0`, then give
/// `λ = −(M_x(J₁) + (J₂ − J₁) × Q_y) / ((J₂ − J₁) × n)`; the outer
/// reaction on x is `F₁ = −Q_x − F` (x's ΣF = 0) and the guide's couple on
/// the slider `c = −M_y + r₂ × F − r_P × λn` (y's moments about its origin,
/// r₂ and r_P the joint and the slider's point from it). `M(J) = M_o − (J − o)
/// × Q` is the moment about J of the applied load `(Q, M_o about the link's
/// origin o)`.
#[derive(Debug, Clone, Copy)]
pub struct RrpDyad {
    x: usize,
    y: usize,
    /// The guide's link.
    g: usize,
    /// J₁, J₂ on link x; J₂ on link y, local.
    j1x: Vec2,
    j2x: Vec2,
    j2y: Vec2,
    /// The slider's point P, y-local.
    p: Vec2,
    /// The guide's normal, g-local (the direction turned +90°).
    n: Vec2,
    /// The revolute pairs' first link (`a`) is x (else the force is reversed).
    a_is_x: [bool; 2],
}

impl RrpDyad {
    /// Prepare a dyad ordered as [`is_ordered_dyad`] says; `None` unless its
    /// pairs are revolute, revolute and a slider `links[1]` on a guide.
    pub fn new(pairs: &[&Pair], links: &[usize]) -> Option<Self> {
        if !is_ordered_dyad(pairs, links) {
            return None;
        }
        let (x, y) = (links[0], links[1]);
        let local = |p: &Pair, l: usize| match *p {
            Pair::R { a, la, lb, .. } => Some(if a == l { la } else { lb }),
            Pair::P { .. } => None,
        };
        let Pair::P { slider, guide, ps, d, .. } = *pairs[2] else {
            return None;
        };
        if slider != y {
            return None;
        }
        Some(RrpDyad {
            x,
            y,
            g: guide,
            j1x: local(pairs[0], x)?,
            j2x: local(pairs[1], x)?,
            j2y: local(pairs[1], y)?,
            p: ps,
            n: perp(d),
            a_is_x: [pairs[0].links().0 == x, pairs[1].links().0 == x],
        })
    }

    /// Same contract as [`solve_dyad`](super::group::solve_dyad), with the
    /// same test of a singular position.
    #[inline(always)]
    pub fn solve(&self, states: &[LinkState], q: &[(Vec2, f64)], out: &mut [PairForce]) -> bool {
        let (sx, sy) = (&states[self.x], &states[self.y]);
        let (r1, r2x) = (rot(sx.u, self.j1x), rot(sx.u, self.j2x));
        let (r2y, rp) = (rot(sy.u, self.j2y), rot(sy.u, self.p));
        let n = rot(states[self.g].u, self.n);
        let (qx, qy) = (q[0], q[1]);
        let mx1 = qx.1 - cross(r1, qx.0);
        let d1 = r2x - r1;
        let det = cross(d1, n);
        let size = (d1.x.abs() + d1.y.abs()) * (n.x.abs() + n.y.abs());
        if det.abs() <= 1e-12 * size || !det.is_finite() {
            return false;
        }
        // the reciprocal depends on the positions only: off the loads' path
        let inv = 1.0 / det;
        let lambda = -(mx1 + cross(d1, qy.0)) * inv;
        let normal = n * lambda;
        let f = qy.0 + normal;
        let forces = [-qx.0 - f, f];
        // the joints, from the vectors found above (no rotation of their own)
        let at = [sx.o + r1, sx.o + r2x];
        for k in 0..2 {
            out[k] = PairForce {
                force: if self.a_is_x[k] { forces[k] } else { -forces[k] },
                at: at[k],
                couple: 0.0,
            };
        }
        out[2] = PairForce {
            force: normal,
            at: sy.o + rp,
            couple: cross(r2y, f) - cross(rp, normal) - qy.1,
        };
        out[..3]
            .iter()
            .all(|f| f.force.x.is_finite() && f.force.y.is_finite() && f.couple.is_finite())
    }
}
