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
        let (l1, l2) = (b[2 * k], b[2 * k + 1]);
        out[k] = match **p {
            Pair::R { a, la, .. } => PairForce {
                force: Vec2::new(l1, l2),
                at: states[a].pos(la),
                couple: 0.0,
            },
            Pair::P { slider, guide, ps, d, .. } => {
                let nrm = rot(states[guide].u, perp(d));
                PairForce {
                    force: nrm * l1,
                    at: states[slider].pos(ps),
                    couple: l2,
                }
            }
        };
    }
    true
}

/// The generalised load of a force `f` at global point `p` and a couple `c`
/// on a link with origin `o`: the force and its moment about `o`.
#[inline(always)]
pub fn about_origin(o: Vec2, f: Vec2, p: Vec2, c: f64) -> (Vec2, f64) {
    (f, cross(p - o, f) + c)
}
