//! The constraint equations of lower pairs, written once for any set of links:
//! used to solve groups of class III and higher by Newton's method, to find
//! their velocities and accelerations, and to count the rank of the whole
//! mechanism (redundant constraints, passive freedoms).
//!
//! Unknowns per link: the local origin `o = (x, y)` and the angle θ.
//! Revolute pair at a point with local coordinates `lᵢ`, `lⱼ` (derived here):
//! `Φ = oᵢ + R(θᵢ)lᵢ − oⱼ − R(θⱼ)lⱼ = 0` (two equations).
//! Prismatic pair, slider s on guide g (through `q`, direction `d`, normal
//! `n = R(θ_g)·d⊥`): `Φ₁ = n·((o_s + R_s p) − (o_g + R_g q)) = 0`,
//! `Φ₂ = θ_s − θ_g − κ = 0`.
//! The Jacobian is the same for positions (Newton), velocities
//! (`J·q̇ = −Φ_t`) and accelerations (`J·q̈ = −(J̇·q̇)`); only the right-hand
//! side changes (Haug, *Computer-Aided Kinematics and Dynamics of Mechanical
//! Systems*, 1989, §§ 3.3, 3.5).

use tmm_geom::{Vec2, perp};

use crate::mechanism::Pair;
use crate::state::{LinkState, conj, rot};

/// What to assemble.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// Residual of positions (right-hand side is −Φ).
    Position,
    /// Velocities.
    Velocity,
    /// Accelerations.
    Acceleration,
}

/// Column of a link among the unknowns, or `None` when the link is known.
#[inline]
fn col(unknown: &[usize], link: usize) -> Option<usize> {
    unknown.iter().position(|&l| l == link).map(|k| 3 * k)
}

/// Assemble `jac` (rows × 3·unknown.len(), row-major) and `rhs` for `pairs`.
/// Returns the number of rows written.
pub fn assemble(pairs: &[&Pair], unknown: &[usize], links: &[LinkState], mode: Mode, jac: &mut [f64], rhs: &mut [f64]) -> usize {
    let nc = 3 * unknown.len();
    let mut row = 0;
    for z in jac.iter_mut() {
        *z = 0.0;
    }
    // Put the coefficient (cx, cy, ct) of link `l` into row `r`; if the link is
    // known, move its known rate/acceleration term to the right-hand side.
    let put = |jac: &mut [f64], rhs: &mut [f64], r: usize, l: usize, c: (f64, f64, f64)| match col(unknown, l) {
        Some(k) => {
            jac[r * nc + k] += c.0;
            jac[r * nc + k + 1] += c.1;
            jac[r * nc + k + 2] += c.2;
        }
        None => {
            let s = &links[l];
            match mode {
                Mode::Position => {}
                Mode::Velocity => rhs[r] -= c.0 * s.v.x + c.1 * s.v.y + c.2 * s.omega,
                Mode::Acceleration => rhs[r] -= c.0 * s.a.x + c.1 * s.a.y + c.2 * s.eps,
            }
        }
    };
    for p in pairs {
        match **p {
            Pair::R { a, b, la, lb, .. } => {
                let (sa, sb) = (&links[a], &links[b]);
                let ra = rot(sa.u, la);
                let rb = rot(sb.u, lb);
                let (pa, pb) = (perp(ra), perp(rb));
                let res = sa.o + ra - sb.o - rb;
                let quad = -ra * (sa.omega * sa.omega) + rb * (sb.omega * sb.omega);
                for (k, (ca, cb)) in [((1.0, 0.0, pa.x), (-1.0, 0.0, -pb.x)), ((0.0, 1.0, pa.y), (0.0, -1.0, -pb.y))]
                    .into_iter()
                    .enumerate()
                {
                    let r = row + k;
                    rhs[r] = match mode {
                        Mode::Position => -[res.x, res.y][k],
                        Mode::Velocity => 0.0,
                        Mode::Acceleration => -[quad.x, quad.y][k],
                    };
                    put(jac, rhs, r, a, ca);
                    put(jac, rhs, r, b, cb);
                }
                row += 2;
            }
            Pair::P {
                slider: s,
                guide: g,
                ps,
                q,
                d,
                rel,
                ..
            } => {
                let (ss, sg) = (&links[s], &links[g]);
                let n = rot(sg.u, perp(d));
                let rs = rot(ss.u, ps);
                let rg = rot(sg.u, q);
                let e = ss.o + rs - sg.o - rg;
                let r = row;
                rhs[r] = match mode {
                    Mode::Position => -n.dot(e),
                    Mode::Velocity => 0.0,
                    Mode::Acceleration => {
                        let ndot = perp(n) * sg.omega;
                        let edot = ss.v + perp(rs) * ss.omega - sg.v - perp(rg) * sg.omega;
                        -(-(sg.omega * sg.omega) * n.dot(e)
                            + 2.0 * ndot.dot(edot)
                            + n.dot(-rs * (ss.omega * ss.omega) + rg * (sg.omega * sg.omega)))
                    }
                };
                put(jac, rhs, r, s, (n.x, n.y, n.dot(perp(rs))));
                put(jac, rhs, r, g, (-n.x, -n.y, perp(n).dot(e) - n.dot(perp(rg))));
                let r2 = row + 1;
                rhs[r2] = match mode {
                    Mode::Position => {
                        // θ_s − θ_g − κ, with u_s = u_g·rel at closure
                        let t = rot(ss.u, conj(rot(sg.u, rel)));
                        -t.y.atan2(t.x)
                    }
                    _ => 0.0,
                };
                put(jac, rhs, r2, s, (0.0, 0.0, 1.0));
                put(jac, rhs, r2, g, (0.0, 0.0, -1.0));
                row += 2;
            }
        }
    }
    row
}

/// Multiply the angle columns (every third, from the third) of a rows×cols
/// row-major matrix by `f`: with `f = 1/L` the unknown angle θ becomes the arc
/// length θ·L, so every column is a length and relative pivot tests do not
/// depend on the unit of length (L the size of the mechanism).
///
/// ```
/// let mut j = [1.0, 0.0, 2.0, 0.0, 1.0, 4.0];
/// tmm_linkage::constraints::scale_angle_columns(&mut j, 2, 3, 0.5);
/// assert_eq!(j, [1.0, 0.0, 1.0, 0.0, 1.0, 2.0]);
/// ```
pub fn scale_angle_columns(jac: &mut [f64], rows: usize, cols: usize, f: f64) {
    for r in 0..rows {
        for c in (2..cols).step_by(3) {
            jac[r * cols + c] *= f;
        }
    }
}

/// Solve the square system `a·x = b` (n×n, row-major) in place by Gaussian
/// elimination with partial pivoting; the solution is left in `b`. Returns
/// `false` when a pivot is below `tol` times the largest entry.
pub fn solve_dense(a: &mut [f64], b: &mut [f64], n: usize, tol: f64) -> bool {
    let scale = a.iter().fold(0.0f64, |m, v| m.max(v.abs())).max(1e-300);
    for k in 0..n {
        let mut p = k;
        for i in k + 1..n {
            if a[i * n + k].abs() > a[p * n + k].abs() {
                p = i;
            }
        }
        if a[p * n + k].abs() <= tol * scale {
            return false;
        }
        if p != k {
            for j in 0..n {
                a.swap(k * n + j, p * n + j);
            }
            b.swap(k, p);
        }
        let piv = a[k * n + k];
        for i in k + 1..n {
            let f = a[i * n + k] / piv;
            if f != 0.0 {
                for j in k..n {
                    a[i * n + j] -= f * a[k * n + j];
                }
                b[i] -= f * b[k];
            }
        }
    }
    for k in (0..n).rev() {
        let mut s = b[k];
        for j in k + 1..n {
            s -= a[k * n + j] * b[j];
        }
        b[k] = s / a[k * n + k];
    }
    b.iter().all(|v| v.is_finite())
}

/// Numerical rank of a rows×cols matrix (row-major) by Gaussian elimination
/// with full pivoting, relative tolerance `tol`.
///
/// ```
/// let m = [1.0, 2.0, 2.0, 4.0];
/// assert_eq!(tmm_linkage::constraints::rank(&m, 2, 2, 1e-10), 1);
/// ```
pub fn rank(m: &[f64], rows: usize, cols: usize, tol: f64) -> usize {
    let mut a = m.to_vec();
    let scale = a.iter().fold(0.0f64, |x, v| x.max(v.abs())).max(1e-300);
    let mut r = 0;
    let mut used_cols = vec![false; cols];
    for _ in 0..rows.min(cols) {
        // full pivot among rows r.. and unused columns
        let (mut bi, mut bj, mut best) = (0, 0, 0.0);
        for i in r..rows {
            for j in 0..cols {
                if !used_cols[j] && a[i * cols + j].abs() > best {
                    best = a[i * cols + j].abs();
                    bi = i;
                    bj = j;
                }
            }
        }
        if best <= tol * scale {
            break;
        }
        for j in 0..cols {
            a.swap(r * cols + j, bi * cols + j);
        }
        used_cols[bj] = true;
        let piv = a[r * cols + bj];
        for i in r + 1..rows {
            let f = a[i * cols + bj] / piv;
            for j in 0..cols {
                a[i * cols + j] -= f * a[r * cols + j];
            }
        }
        r += 1;
    }
    r
}

/// Newton–Raphson on the positions of the `unknown` links of a group, from
/// their current states. Returns the number of iterations, or `None` if it did
/// not converge (the group cannot be assembled near this guess).
pub fn newton(pairs: &[&Pair], unknown: &[usize], links: &mut [LinkState], jac: &mut [f64], rhs: &mut [f64], scale: f64) -> Option<usize> {
    let n = 3 * unknown.len();
    for it in 0..60 {
        let rows = assemble(pairs, unknown, links, Mode::Position, jac, rhs);
        debug_assert_eq!(rows, n);
        // residual as lengths: a prismatic pair's angle row times the size
        let mut res = 0.0f64;
        for (k, p) in pairs.iter().enumerate() {
            let w = if matches!(p, Pair::P { .. }) { scale } else { 1.0 };
            res = res.max(rhs[2 * k].abs()).max(rhs[2 * k + 1].abs() * w);
        }
        if res < 1e-14 * scale && it > 0 {
            return Some(it);
        }
        // unknown angles as arc lengths θ·scale (see `scale_angle_columns`)
        scale_angle_columns(&mut jac[..n * n], n, n, 1.0 / scale);
        if !solve_dense(&mut jac[..n * n], &mut rhs[..n], n, 1e-13) {
            return None;
        }
        // limit the step to a fraction of the size of the mechanism
        let step = rhs[..n].iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let f = if step > 0.5 * scale { 0.5 * scale / step } else { 1.0 };
        for (k, &l) in unknown.iter().enumerate() {
            let s = &mut links[l];
            s.o.x += f * rhs[3 * k];
            s.o.y += f * rhs[3 * k + 1];
            let dt = f * rhs[3 * k + 2] / scale;
            let (sn, cs) = dt.sin_cos();
            s.u = rot(s.u, Vec2::new(cs, sn));
            let norm = s.u.hypot();
            s.u *= 1.0 / norm;
        }
        if step * f < 1e-15 * scale {
            return Some(it);
        }
    }
    None
}
