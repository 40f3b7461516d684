//! The reactions of one Assur group from the equilibrium of its links.
//!
//! Every link of the group is in equilibrium (kinetostatics: given loads plus
//! inertia loads plus pair reactions). Written with the constraint Jacobian
//! J of the group's pairs (crates/tmm-linkage/src/constraints.rs), the
//! reactions are Lagrange multipliers λ and the equilibrium of the k links
//! (3k equations: Σx, Σy, Σ moments about each link's local origin) is
//!
//! `Jᵀ·λ + Q = 0`,
//!
//! where Q holds the applied loads reduced to each link's origin (Haug,
//! *Computer-Aided Kinematics and Dynamics of Mechanical Systems*, 1989, § 6.3;
//! derived for these pairs in docs/forces.md). A group with 3k/2 pairs has
//! exactly 3k multipliers, so any group — a dyad of any kind or a class-III
//! triad — is solved by one dense 3k×3k system.
//!
//! Meaning of λ (derived here from the Jacobian's columns):
//! - revolute pair (a, b): `(λ₁, λ₂)` is the force on link `a` from link `b`
//!   at the joint; `b` gets the opposite;
//! - prismatic pair (slider s on guide g): `λ₁·n` is the normal force on the
//!   slider at its point (n = the guide's normal) and `λ₂` a couple on it; the
//!   guide gets the opposite force at the same point and the opposite couple.
//!   The couple is the reaction's shift along the guide: the single resultant
//!   acts at `x = λ₂/λ₁` along the guide from the slider's point.

use tmm_geom::{Vec2, cross, perp};

use crate::constraints::{self, Mode};
use crate::mechanism::Pair;
use crate::state::{LinkState, rot};

pub use super::dyads::RrrDyad;

/// Buffers of a group solve, sized once.
#[derive(Debug, Clone)]
pub struct GroupWork {
    jac: Vec<f64>,
    jt: Vec<f64>,
    rhs: Vec<f64>,
}

impl GroupWork {
    /// Buffers for groups of up to `max_links` links.
    pub fn new(max_links: usize) -> Self {
        let n = 3 * max_links.max(1);
        GroupWork {
            jac: vec![0.0; n * n],
            jt: vec![0.0; n * n],
            rhs: vec![0.0; n],
        }
    }
}

/// The reaction of one pair as the group solve finds it: the force on the
/// pair's first link (`a` of a revolute pair, the slider of a prismatic pair)
/// from the other, its global point of application, and a couple (prismatic
/// pairs only).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PairForce {
    /// Force on the first link, N.
    pub force: Vec2,
    /// Point of application (the joint, or the slider's point), global.
    pub at: Vec2,
    /// Couple on the first link, N·m (prismatic pairs).
    pub couple: f64,
}

/// Solve the reactions of the pairs `pairs` of a group whose links are
/// `links`, given the applied loads `q[i] = (force, moment about the link's
/// local origin)` of `links[i]`. Writes one [`PairForce`] per pair into `out`.
/// Returns `false` when the equilibrium equations are singular.
pub fn solve_group(
    pairs: &[&Pair],
    links: &[usize],
    states: &[LinkState],
    q: &[(Vec2, f64)],
    work: &mut GroupWork,
    out: &mut [PairForce],
) -> bool {
    let n = 3 * links.len();
    let jac = &mut work.jac[..n * n];
    let rows = constraints::assemble(pairs, links, states, Mode::Velocity, jac, &mut work.rhs[..n]);
    if rows != n {
        return false;
    }
    let jt = &mut work.jt[..n * n];
    for r in 0..n {
        for c in 0..n {
            jt[c * n + r] = jac[r * n + c];
        }
    }
    let b = &mut work.rhs[..n];
    for (i, &(f, m)) in q.iter().enumerate() {
        b[3 * i] = -f.x;
        b[3 * i + 1] = -f.y;
        b[3 * i + 2] = -m;
    }
    if !constraints::solve_dense(jt, b, n, 1e-12) {
        return false;
    }
    for (k, p) in pairs.iter().enumerate() {
        out[k] = pair_force(p, states, b[2 * k], b[2 * k + 1]);
    }
    true
}

/// The reactions of a dyad (class II group) by eliminating its outer pairs:
/// the course's method in matrix form, derived in docs/forces.md.
///
/// Links `l1`, `l2`; pairs ordered outer `e1` (on `l1` only), inner `m`,
/// outer `e2` (on `l2` only). Each link's three equilibrium equations read
/// `A·λ_e + M·λ_m = b`; the combination `nᵀ` with `n = a₁ × a₂` (the cross
/// product of the two columns of A) removes the outer pair's two unknowns —
/// for a revolute outer pair it is the moment equation about that joint, as
/// in seed 001 ("ΣM(C) = 0 ⇒ R^τ"). The two links give a 2×2 system for the
/// inner pair's λ_m; then each outer pair's λ_e follows from its link's
/// equations (least squares of a consistent 3×2 system, exact).
///
/// Same contract as [`solve_group`] for a dyad, without the 6×6 elimination.
pub fn solve_dyad(
    pairs: &[&Pair],
    links: &[usize],
    states: &[LinkState],
    q: &[(Vec2, f64)],
    _work: &mut GroupWork,
    out: &mut [PairForce],
) -> bool {
    let (x, y) = (links[0], links[1]);
    let [a10, a11] = columns(pairs[0], x, states);
    let [m10, m11] = columns(pairs[1], x, states);
    let [m20, m21] = columns(pairs[1], y, states);
    let [a20, a21] = columns(pairs[2], y, states);
    let b1 = [-q[0].0.x, -q[0].0.y, -q[0].1];
    let b2 = [-q[1].0.x, -q[1].0.y, -q[1].1];
    let n1 = cross3(a10, a11);
    let n2 = cross3(a20, a21);
    let (p, qq, r, s) = (dot3(n1, m10), dot3(n1, m11), dot3(n2, m20), dot3(n2, m21));
    let (u, v) = (dot3(n1, b1), dot3(n2, b2));
    let det = p * s - qq * r;
    let size = (p.abs() + qq.abs()) * (r.abs() + s.abs());
    if det.abs() <= 1e-12 * size || !det.is_finite() {
        return false;
    }
    let id = 1.0 / det;
    let lm = [(u * s - qq * v) * id, (p * v - u * r) * id];
    let le1 = outer(pairs[0], x, a10, m10, m11, b1, lm);
    let le2 = outer(pairs[2], y, a20, m20, m21, b2, lm);
    for (k, l) in [le1, lm, le2].into_iter().enumerate() {
        out[k] = pair_force(pairs[k], states, l[0], l[1]);
    }
    out[..3]
        .iter()
        .all(|f| f.force.x.is_finite() && f.force.y.is_finite() && f.couple.is_finite())
}

/// The generalised force on link `l` (force x, y and moment about its
/// origin) per unit of each of the pair's two multipliers: the pair's two
/// rows of the constraint Jacobian restricted to the link's columns
/// (crates/tmm-linkage/src/constraints.rs, derived there), written out so
/// that a dyad needs no assembly.
#[inline(always)]
fn columns(p: &Pair, l: usize, st: &[LinkState]) -> [[f64; 3]; 2] {
    match *p {
        Pair::R { a, b, la, lb, .. } => {
            if a == l {
                let r = rot(st[a].u, la);
                [[1.0, 0.0, -r.y], [0.0, 1.0, r.x]]
            } else {
                let r = rot(st[b].u, lb);
                [[-1.0, 0.0, r.y], [0.0, -1.0, -r.x]]
            }
        }
        Pair::P {
            slider, guide, ps, q, d, ..
        } => {
            let (ss, sg) = (&st[slider], &st[guide]);
            let n = rot(sg.u, perp(d));
            let rs = rot(ss.u, ps);
            if slider == l {
                [[n.x, n.y, n.dot(perp(rs))], [0.0, 0.0, 1.0]]
            } else {
                let rg = rot(sg.u, q);
                let e = ss.o + rs - sg.o - rg;
                [[-n.x, -n.y, perp(n).dot(e) - n.dot(perp(rg))], [0.0, 0.0, -1.0]]
            }
        }
    }
}

#[inline(always)]
fn cross3(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

#[inline(always)]
fn dot3(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Solve the consistent `[a0 a1]·λ = b − [m0 m1]·lm` for the outer pair `p`
/// of link `l` in closed form, from the structure of its two columns (see
/// [`columns`]): for a revolute pair the first two rows are ±I, so
/// λ = ±(r₀, r₁); for a prismatic pair a0 = ±(n, c) with |n| = 1 and
/// a1 = (0, 0, ±1), so λ₀ = ±n·(r₀, r₁) and λ₁ follows from the third row.
/// Derived here; no division, the same solution as the least squares of the
/// consistent 3×2 system.
#[inline(always)]
fn outer(p: &Pair, l: usize, a0: [f64; 3], m0: [f64; 3], m1: [f64; 3], b: [f64; 3], lm: [f64; 2]) -> [f64; 2] {
    let rr = [
        b[0] - m0[0] * lm[0] - m1[0] * lm[1],
        b[1] - m0[1] * lm[0] - m1[1] * lm[1],
        b[2] - m0[2] * lm[0] - m1[2] * lm[1],
    ];
    match *p {
        Pair::R { a, .. } => {
            if a == l {
                [rr[0], rr[1]]
            } else {
                [-rr[0], -rr[1]]
            }
        }
        Pair::P { slider, .. } => {
            // a0 = s·(n, c), a1 = (0, 0, s) with s = ±1: n·(r₀, r₁) = s·λ₀,
            // c·s·λ₀ + s·λ₁ = r₂
            let l0 = a0[0] * rr[0] + a0[1] * rr[1];
            if slider == l {
                [l0, rr[2] - a0[2] * l0]
            } else {
                [l0, a0[2] * l0 - rr[2]]
            }
        }
    }
}

#[inline(always)]
fn pair_force(p: &Pair, states: &[LinkState], l1: f64, l2: f64) -> PairForce {
    match *p {
        Pair::R { a, la, .. } => PairForce {
            force: Vec2::new(l1, l2),
            at: states[a].pos(la),
            couple: 0.0,
        },
        Pair::P { slider, guide, ps, d, .. } => PairForce {
            force: rot(states[guide].u, perp(d)) * l1,
            at: states[slider].pos(ps),
            couple: l2,
        },
    }
}

/// `true` when a group's pairs are ordered as [`solve_dyad`] needs: two links,
/// three pairs, the first only on `links[0]`, the second on both, the third
/// only on `links[1]`.
pub fn is_ordered_dyad(pairs: &[&Pair], links: &[usize]) -> bool {
    if links.len() != 2 || pairs.len() != 3 {
        return false;
    }
    let on = |p: &Pair, l: usize| {
        let (a, b) = p.links();
        a == l || b == l
    };
    let (x, y) = (links[0], links[1]);
    on(pairs[0], x) && !on(pairs[0], y) && on(pairs[1], x) && on(pairs[1], y) && on(pairs[2], y) && !on(pairs[2], x)
}

/// The generalised load of a force `f` at global point `p` and a couple `c`
/// on a link with origin `o`: the force and its moment about `o`.
#[inline(always)]
pub fn about_origin(o: Vec2, f: Vec2, p: Vec2, c: f64) -> (Vec2, f64) {
    (f, cross(p - o, f) + c)
}
