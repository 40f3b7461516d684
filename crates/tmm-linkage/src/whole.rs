//! The mobility of a mechanism that does not decompose into Assur groups
//! (подвижность по рангу): the whole mechanism is assembled at one crank
//! angle by a damped Gauss–Newton solve of all its pair constraints at once,
//! and the rank of the constraint Jacobian there gives the true mobility, the
//! redundant constraints (избыточные связи) and the passive freedoms
//! (местные подвижности).
//!
//! This is what Chebyshev's W = 3n − 2p5 cannot see: a double parallelogram
//! (a parallelogram four-bar with a third crank parallel to the other two)
//! has W = 3·4 − 2·6 = 0 yet moves with mobility 1, because one of its
//! constraints repeats the others (q = 1): W = W_rank − q (Malyshev's count
//! with the redundant constraints; Artobolevsky 1988, § 5; Reshetov,
//! *Самоустанавливающиеся механизмы*, 1991, ch. 1).
//!
//! Least squares with Levenberg's damping: `(JᵀJ + μ·diag(JᵀJ)) δ = −JᵀΦ`
//! (Nocedal & Wright, *Numerical Optimization*, 2nd ed., § 10.3), angles
//! scaled to arc lengths at the mechanism's size so that the solve does not
//! depend on the unit of length.

use tmm_geom::Vec2;

use crate::constraints::{self, Mode};
use crate::mechanism::Pair;
use crate::state::{LinkState, rot};

/// The rank count at an assembled position.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RankCount {
    /// Mobility from the rank: 3n − rank.
    pub dof: i64,
    /// Redundant constraints: 2p5 − rank.
    pub redundant: i64,
    /// Passive freedoms: the mobility left with the crank held.
    pub passive: i64,
}

/// The rank count of the constraint equations of `pairs` among `n_links`
/// links (0 the frame) at the states `links`, with the input link `crank`
/// held for the passive freedoms by the row `held` on its (x, y, θ)
/// columns: `[0, 0, 1]` holds a crank's rotation, `[dx, dy, 0]` a driving
/// slider's travel along its guide d. Angles are scaled by `1/scale`.
pub fn rank_count(pairs: &[Pair], n_links: usize, crank: usize, held: [f64; 3], links: &[LinkState], scale: f64) -> RankCount {
    let n = n_links - 1;
    let unknown: Vec<usize> = (1..=n).collect();
    let prs: Vec<&Pair> = pairs.iter().collect();
    let rows = 2 * prs.len();
    let cols = 3 * n;
    let mut jac = vec![0.0; (rows + 1) * cols];
    let mut rhs = vec![0.0; rows + 1];
    constraints::assemble(&prs, &unknown, links, Mode::Velocity, &mut jac[..rows * cols], &mut rhs[..rows]);
    constraints::scale_angle_columns(&mut jac[..rows * cols], rows, cols, 1.0 / scale);
    let r = constraints::rank(&jac[..rows * cols], rows, cols, 1e-9);
    for (k, h) in held.iter().enumerate() {
        jac[rows * cols + 3 * (crank - 1) + k] = *h;
    }
    let r_held = constraints::rank(&jac, rows + 1, cols, 1e-9);
    RankCount {
        dof: cols as i64 - r as i64,
        redundant: rows as i64 - r as i64,
        passive: cols as i64 - r_held as i64,
    }
}

/// Assemble every link but the frame and the crank (whose state is in
/// `links[crank]`) so that all pairs close, from `starts` pseudo-random
/// guesses about `centre` within `scale`, points of `near` placed first.
/// Returns the assembled states, or `None`.
pub fn assemble_all(
    pairs: &[Pair],
    links: &[LinkState],
    crank: usize,
    near: &[(usize, Vec2, Vec2)],
    centre: Vec2,
    scale: f64,
    starts: usize,
) -> Option<Vec<LinkState>> {
    let nl = links.len();
    let unknown: Vec<usize> = (1..nl).filter(|&l| l != crank).collect();
    let prs: Vec<&Pair> = pairs.iter().collect();
    let rows = 2 * prs.len();
    let cols = 3 * unknown.len();
    if cols == 0 {
        return None;
    }
    let mut jac = vec![0.0; rows * cols];
    let mut res = vec![0.0; rows];
    let mut nrm = vec![0.0; cols * cols];
    let mut g = vec![0.0; cols];
    let mut rng = 0x2545_F491_4F6C_DD1Du64;
    let mut next = move || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        (rng >> 11) as f64 / (1u64 << 53) as f64
    };
    for start in 0..starts {
        let mut st = links.to_vec();
        for &l in &unknown {
            let th = std::f64::consts::TAU * next();
            let u = Vec2::new(th.cos(), th.sin());
            let mut o = centre + Vec2::new(next() - 0.5, next() - 0.5) * scale;
            if start % 2 == 0 {
                for &(nl_, local, q) in near {
                    if nl_ == l {
                        o = q - rot(u, local);
                    }
                }
            }
            st[l] = LinkState {
                o,
                u,
                ..Default::default()
            };
        }
        let mut mu = 1e-3;
        let mut last = f64::INFINITY;
        for _ in 0..200 {
            constraints::assemble(&prs, &unknown, &st, Mode::Position, &mut jac, &mut res);
            // |Φ| as lengths (prismatic angle rows times the size)
            let mut err = 0.0f64;
            for (k, p) in prs.iter().enumerate() {
                let w = if matches!(p, Pair::P { .. }) { scale } else { 1.0 };
                err = err.max(res[2 * k].abs()).max(res[2 * k + 1].abs() * w);
            }
            if err < 1e-13 * scale {
                return Some(st);
            }
            mu = if err < last {
                (mu * 0.3f64).max(1e-12)
            } else {
                (mu * 10.0f64).min(1e6)
            };
            last = err;
            constraints::scale_angle_columns(&mut jac, rows, cols, 1.0 / scale);
            for i in 0..cols {
                g[i] = (0..rows).map(|r| jac[r * cols + i] * res[r]).sum();
                for j in 0..cols {
                    nrm[i * cols + j] = (0..rows).map(|r| jac[r * cols + i] * jac[r * cols + j]).sum();
                }
            }
            for i in 0..cols {
                nrm[i * cols + i] += mu * nrm[i * cols + i].max(1e-12);
            }
            if !constraints::solve_dense(&mut nrm, &mut g, cols, 1e-15) {
                break;
            }
            let step = g.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            let f = if step > 0.5 * scale { 0.5 * scale / step } else { 1.0 };
            for (k, &l) in unknown.iter().enumerate() {
                let s = &mut st[l];
                s.o.x += f * g[3 * k];
                s.o.y += f * g[3 * k + 1];
                let dt = f * g[3 * k + 2] / scale;
                s.u = rot(s.u, Vec2::new(dt.cos(), dt.sin()));
                s.u *= 1.0 / s.u.hypot();
            }
        }
    }
    None
}
