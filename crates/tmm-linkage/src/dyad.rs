//! The five class-II Assur groups (диады) solved in closed form: positions,
//! velocities and accelerations.
//!
//! Each solver forms the very vector equations the course draws as velocity
//! and acceleration plans (планы скоростей и ускорений), e.g. for RRR
//! `V_C = V_B + V_CB = V_D + V_CD` and
//! `a_C = a_B + aⁿ_CB + aᵗ_CB = a_D + aⁿ_CD + aᵗ_CD`, and solves them
//! analytically as 2×2 linear systems (Artobolevsky 1988, §§ 13–16;
//! Uicker, Pennock, Shigley, *Theory of Machines and Mechanisms*, 5th ed., ch. 3–4).
//! A slider on a guide carried by a rotating link adds the Coriolis term
//! `aᵏ = 2 ω_guide × v_rel` (Artobolevsky § 15).
//!
//! Positions (derived here; see docs/linkage.md):
//! - RRR: intersection of two circles — `a = (l1² − l2² + d²)/(2d)`,
//!   `h = √(l1² − a²)`, `B = A + a·ê + σ·h·ê⊥` with the branch σ = ±1.
//! - RRP: a circle about A and the line of the slider's joint —
//!   `s = −m·ĝ ± √((m·ĝ)² − |m|² + l²)`.
//! - RPR: in the guide link's frame, the far joint lies on a line and at a fixed
//!   distance from the near one — the same quadratic, then the rotation
//!   `u = (Y − X)/(Y_G − X_G)` as a complex quotient.
//! - PRP, RPP: two straight lines, a 2×2 linear system.

use tmm_geom::{Vec2, perp};

use crate::state::{LinkState, PointState, conj, rot, solve2, unrotate};

/// Why a dyad failed at a position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DyadFail {
    /// Two circles do not meet: distance `d`, radii `r1`, `r2`.
    Circles { d: f64, r1: f64, r2: f64 },
    /// A circle and a line do not meet: distance of the centre from the line
    /// `h` greater than the radius `r`.
    CircleLine { h: f64, r: f64 },
    /// Two guide lines are parallel.
    Parallel,
    /// The velocity equations are singular or nearly so: `sine` is the sine of
    /// the angle between the two columns of the group's 2×2 Jacobian (its
    /// determinant over the product of the columns' lengths), below
    /// [`MIN_SINE`].
    Singular {
        /// |det J| / (|J₁|·|J₂|), 0 … 1.
        sine: f64,
    },
    /// Newton's method found no closure of a larger group near the guess.
    NoClosure,
}

impl std::fmt::Display for DyadFail {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            DyadFail::Circles { d, r1, r2 } => {
                if d > r1 + r2 {
                    write!(
                        f,
                        "the outer joints are {d:.6} m apart, more than the two links reach ({r1:.6} + {r2:.6} = {:.6} m)",
                        r1 + r2
                    )
                } else {
                    write!(
                        f,
                        "the outer joints are {d:.6} m apart, less than the difference of the links ({:.6} m)",
                        (r1 - r2).abs()
                    )
                }
            }
            DyadFail::CircleLine { h, r } => write!(f, "the joint is {h:.6} m from the guide line, more than the link length {r:.6} m"),
            DyadFail::Parallel => write!(
                f,
                "the two guide lines are parallel or within {:.4}° of it",
                MIN_SINE.asin().to_degrees()
            ),
            DyadFail::Singular { sine } if !sine.is_finite() => write!(
                f,
                "the group's velocity equations are singular (a pivot below 1e-11 of the largest entry, lengths scaled by the size of the mechanism): it is at or next to a dead centre, where velocities grow without bound"
            ),
            DyadFail::Singular { sine } => write!(
                f,
                "the group is at or within {:.2e}° of its dead centre (the sine of the angle between the columns of its velocity equations is {sine:.1e}, below {MIN_SINE:.0e}): velocities and accelerations there grow without bound",
                sine.clamp(0.0, 1.0).asin().to_degrees()
            ),
            DyadFail::NoClosure => write!(
                f,
                "the group's loop does not close near the previous position (Newton's method did not converge)"
            ),
        }
    }
}

/// The smallest sine of the angle between the two columns of a dyad's velocity
/// equations (its links, or a link and a guide, this far from alignment) at
/// which the dyad is solved. Below it the group is at or next to its dead
/// centre: velocities grow as 1/sin and accelerations as 1/sin³, and round-off
/// in the position (relative 1e-16/sin²) stops being negligible. At 1e-4 (the
/// links 0.0057° from alignment) the relative round-off of the velocities is
/// still about 1e-8. Dimensionless, so it does not depend on the size of the
/// mechanism.
pub const MIN_SINE: f64 = 1e-4;

/// The sine of the angle between two columns `c1`, `c2` (0 when either is 0).
#[inline(always)]
fn sine(c1: Vec2, c2: Vec2) -> f64 {
    let d = (c1.x * c2.y - c1.y * c2.x).abs();
    let n = c1.hypot() * c2.hypot();
    if n > 0.0 { d / n } else { 0.0 }
}

/// `solve2` with the relative test: `Err(Singular)` when the columns are
/// within [`MIN_SINE`] of parallel.
#[inline(always)]
fn solve2_rel(c1: Vec2, c2: Vec2, r: Vec2, n1: f64, n2: f64) -> Result<(f64, f64), DyadFail> {
    solve2(c1, c2, r, MIN_SINE * n1 * n2).ok_or(DyadFail::Singular { sine: sine(c1, c2) })
}

/// An outer revolute joint: a point of a known link.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KnownPoint {
    /// The known link.
    pub link: usize,
    /// Local coordinates on the known link.
    pub local: Vec2,
}

impl KnownPoint {
    #[inline(always)]
    fn state(&self, links: &[LinkState]) -> PointState {
        if self.link == 0 {
            // a fixed point: the frame does not move
            PointState {
                p: self.local,
                v: Vec2::ZERO,
                a: Vec2::ZERO,
            }
        } else {
            links[self.link].point(self.local)
        }
    }
}

/// A guide line on a known link.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KnownGuide {
    /// The guide link.
    pub link: usize,
    /// A point of the line, local on the guide link.
    pub through: Vec2,
    /// Unit direction, local on the guide link.
    pub dir: Vec2,
}

/// Geometry of one dyad, by kind. Field names follow the course's letters for
/// an RRR dyad A–B–C with inner joint B.
#[derive(Debug, Clone, PartialEq)]
pub enum DyadGeom {
    /// RRR: links `l1` (A, B) and `l2` (B, C).
    Rrr {
        /// First link.
        l1: usize,
        /// Second link.
        l2: usize,
        /// Outer joint A on a known link.
        a: KnownPoint,
        /// A on `l1`, local.
        a1: Vec2,
        /// Unit direction A→B on `l1`, local.
        dir1: Vec2,
        /// |AB|.
        len1: f64,
        /// Outer joint C on a known link.
        c: KnownPoint,
        /// C on `l2`, local.
        c2: Vec2,
        /// Unit direction C→B on `l2`, local.
        dir2: Vec2,
        /// |CB|.
        len2: f64,
        /// `1/|AB|`, `1/|CB|`, `|AB|² − |CB|²` (constants of the solve).
        inv: (f64, f64, f64),
    },
    /// RRP: `l1` (A, B) and the slider `l2` (B on it) on a guide of a known link.
    Rrp {
        /// First link.
        l1: usize,
        /// The slider.
        l2: usize,
        /// Outer joint A.
        a: KnownPoint,
        /// A on `l1`, local.
        a1: Vec2,
        /// Unit direction A→B on `l1`, local.
        dir1: Vec2,
        /// |AB|.
        len1: f64,
        /// B on the slider minus the slider's point on the line, slider-local.
        b_off: Vec2,
        /// B on `l2`, local.
        b2: Vec2,
        /// The guide.
        guide: KnownGuide,
        /// Slider orientation relative to the guide link: `u2 = u_guide·rel`.
        rel: Vec2,
    },
    /// RPR: guide link `g` (outer joint X) and slider `s` (outer joint Y),
    /// the slider moving on a guide of `g`.
    Rpr {
        /// Link carrying the guide.
        g: usize,
        /// The sliding link.
        s: usize,
        /// Outer joint X (on `g`).
        x: KnownPoint,
        /// X on `g`, local.
        xg: Vec2,
        /// Outer joint Y (on `s`).
        y: KnownPoint,
        /// Y on `s`, local.
        ys: Vec2,
        /// Y's locus in g's frame at s = 0: `q + rot(rel, ys − ps)`.
        w: Vec2,
        /// Guide direction on `g`, local unit.
        dir: Vec2,
        /// `u_s = u_g·rel`.
        rel: Vec2,
    },
    /// PRP: two sliders on guides of known links, joined at B.
    Prp {
        /// First slider link.
        l1: usize,
        /// Second slider link.
        l2: usize,
        /// Guide of `l1`.
        g1: KnownGuide,
        /// `u1 = u_guide1·rel1`.
        rel1: Vec2,
        /// B relative to l1's point on its line, l1-local.
        off1: Vec2,
        /// B on `l1`, local.
        b1: Vec2,
        /// Guide of `l2`.
        g2: KnownGuide,
        /// `u2 = u_guide2·rel2`.
        rel2: Vec2,
        /// B relative to l2's point on its line, l2-local.
        off2: Vec2,
        /// B on `l2`, local.
        b2: Vec2,
    },
    /// RPP: `l1` with outer joint A slides on `l2` (or `l2` on `l1`), and `l2`
    /// slides on a guide of a known link.
    Rpp {
        /// Link with the outer joint.
        l1: usize,
        /// Link on the outer guide.
        l2: usize,
        /// Outer joint A.
        a: KnownPoint,
        /// A on `l1`, local.
        a1: Vec2,
        /// Outer guide (of `l2`).
        guide: KnownGuide,
        /// `u2 = u_guide·rel2`.
        rel2: Vec2,
        /// `l2`'s point on the outer line, local.
        p2: Vec2,
        /// `u1 = u2·relm`.
        relm: Vec2,
        /// The inner guide: through, local on its carrier.
        qm: Vec2,
        /// Inner guide direction, local on its carrier (unit).
        dm: Vec2,
        /// The slider's point on the inner line, local on the slider.
        pm: Vec2,
        /// `true` when the inner guide is on `l2` (l1 slides), else on `l1`.
        guide_on_l2: bool,
    },
}

impl DyadGeom {
    /// Kind letters.
    pub fn kind(&self) -> &'static str {
        match self {
            DyadGeom::Rrr { .. } => "RRR",
            DyadGeom::Rrp { .. } => "RRP",
            DyadGeom::Rpr { .. } => "RPR",
            DyadGeom::Prp { .. } => "PRP",
            DyadGeom::Rpp { .. } => "RPP",
        }
    }

    /// Whether the kind has two assembly branches.
    pub fn has_branches(&self) -> bool {
        matches!(self, DyadGeom::Rrr { .. } | DyadGeom::Rrp { .. } | DyadGeom::Rpr { .. })
    }

    /// Solve positions, velocities and accelerations of the dyad's two links
    /// from the known links, on branch `sign` (±1). Writes `links[l1]`,
    /// `links[l2]`.
    #[inline(always)]
    // `!(x >= tol)` is meant: it is also true for NaN
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    pub fn solve(&self, sign: f64, links: &mut [LinkState]) -> Result<(), DyadFail> {
        match *self {
            DyadGeom::Rrr {
                l1,
                l2,
                a,
                a1,
                dir1,
                len1,
                c,
                c2,
                dir2,
                len2,
                inv,
            } => {
                let pa = a.state(links);
                let pc = c.state(links);
                let d = pc.p - pa.p;
                let dd = d.x * d.x + d.y * d.y;
                // B − A = α·d + σ·β·d⊥ with α = x/|d|, β = h/|d|: one division
                // and one square root, independent of each other's results
                // (x = (l1² − l2² + |d|²)/(2|d|), h² = l1² − x²)
                let inv_dd = 1.0 / dd;
                let alpha = 0.5 * (inv.2 + dd) * inv_dd;
                let l1sq = len1 * len1;
                let beta2 = l1sq * inv_dd - alpha * alpha;
                // one comparison also catches |d| = 0 (∞ − ∞) and NaN
                if !(beta2 >= -1e-12 * l1sq * inv_dd) {
                    return Err(DyadFail::Circles {
                        d: dd.sqrt(),
                        r1: len1,
                        r2: len2,
                    });
                }
                let beta2 = beta2.max(0.0);
                let beta = beta2.sqrt();
                let inv_b2 = 1.0 / beta2;
                let ab = d * alpha + perp(d) * (sign * beta);
                let b = pa.p + ab;
                let cb = b - pc.p;
                // ω1·(AB)⊥ − ω2·(CB)⊥ = V_C − V_A; its determinant is
                // −cross(AB, CB) = −σ·β·|d|², so 1/det needs no division of its own
                // |cross(AB, CB)| / (l1·l2) = β|d|²/(l1·l2): the sine of the angle at B
                if !(beta * dd > MIN_SINE * len1 * len2) {
                    return Err(DyadFail::Singular {
                        sine: (beta * dd / (len1 * len2)).min(1.0),
                    });
                }
                let inv_det = -sign * beta * inv_b2 * inv_dd;
                let (k1, k2) = (perp(ab), -perp(cb));
                let r1 = Vec2::new(k2.y, -k2.x) * inv_det;
                let r2 = Vec2::new(-k1.y, k1.x) * inv_det;
                let rv = pc.v - pa.v;
                let (w1, w2) = (r1.dot(rv), r2.dot(rv));
                let ra = pc.a - pa.a + ab * (w1 * w1) - cb * (w2 * w2);
                let (e1, e2) = (r1.dot(ra), r2.dot(ra));
                let u1 = unrotate(ab * inv.0, dir1);
                let u2 = unrotate(cb * inv.1, dir2);
                links[l1] = LinkState::from_point(&pa, a1, u1, w1, e1);
                links[l2] = LinkState::from_point(&pc, c2, u2, w2, e2);
                Ok(())
            }
            DyadGeom::Rrp {
                l1,
                l2,
                a,
                a1,
                dir1,
                len1,
                b_off,
                b2,
                guide,
                rel,
            } => {
                let pa = a.state(links);
                let gl = links[guide.link];
                let q = gl.pos(guide.through);
                let ug = rot(gl.u, guide.dir);
                let u2 = rot(gl.u, rel);
                let m = q + rot(u2, b_off) - pa.p;
                let mg = m.dot(ug);
                let disc = mg * mg - m.dot(m) + len1 * len1;
                if disc < -1e-12 * len1 * len1 || !disc.is_finite() {
                    let h = (m - ug * mg).hypot();
                    return Err(DyadFail::CircleLine { h, r: len1 });
                }
                let s = -mg + sign * disc.max(0.0).sqrt();
                let b = pa.p + m + ug * s;
                let ab = b - pa.p;
                let (vg, ag) = gl.kin_at(b);
                let c1 = perp(ab);
                let c2v = -ug;
                let (w1, sd) = solve2_rel(c1, c2v, vg - pa.v, len1, 1.0)?;
                let r = ag + perp(ug) * (2.0 * gl.omega * sd) - pa.a + ab * (w1 * w1);
                let (e1, _sdd) = solve2_rel(c1, c2v, r, len1, 1.0)?;
                let u1 = rot(ab * (1.0 / len1), conj(dir1));
                links[l1] = LinkState::from_point(&pa, a1, u1, w1, e1);
                let pbs = PointState {
                    p: b,
                    v: pa.v + perp(ab) * w1,
                    a: pa.a + perp(ab) * e1 - ab * (w1 * w1),
                };
                links[l2] = LinkState::from_point(&pbs, b2, u2, gl.omega, gl.eps);
                Ok(())
            }
            DyadGeom::Rpr {
                g,
                s,
                x,
                xg,
                y,
                ys,
                w,
                dir,
                rel,
            } => {
                let px = x.state(links);
                let py = y.state(links);
                let yx = py.p - px.p;
                let rho2 = yx.dot(yx);
                let m = w - xg;
                let md = m.dot(dir);
                let disc = md * md - m.dot(m) + rho2;
                if disc < -1e-12 * rho2.max(1e-300) || !disc.is_finite() || rho2 == 0.0 {
                    let h = (m - dir * md).hypot();
                    return Err(DyadFail::CircleLine { h, r: rho2.sqrt() });
                }
                let sl = -md + sign * disc.max(0.0).sqrt();
                let yg = m + dir * sl; // Y − X in g's frame
                let ug = rot(yx, conj(yg)) * (1.0 / yg.dot(yg));
                let ugn = ug * (1.0 / ug.hypot());
                let gdir = rot(ugn, dir);
                let c1 = perp(yx);
                let rho = rho2.sqrt();
                let (wg, sd) = solve2_rel(c1, gdir, py.v - px.v, rho, 1.0)?;
                let r = py.a - px.a + yx * (wg * wg) - perp(gdir) * (2.0 * wg * sd);
                let (eg, _sdd) = solve2_rel(c1, gdir, r, rho, 1.0)?;
                links[g] = LinkState::from_point(&px, xg, ugn, wg, eg);
                links[s] = LinkState::from_point(&py, ys, rot(ugn, rel), wg, eg);
                Ok(())
            }
            DyadGeom::Prp {
                l1,
                l2,
                g1,
                rel1,
                off1,
                b1,
                g2,
                rel2,
                off2,
                b2,
            } => {
                let k1 = links[g1.link];
                let k2 = links[g2.link];
                let u1 = rot(k1.u, rel1);
                let u2 = rot(k2.u, rel2);
                let d1 = rot(k1.u, g1.dir);
                let d2 = rot(k2.u, g2.dir);
                let o1 = k1.pos(g1.through) + rot(u1, off1);
                let o2 = k2.pos(g2.through) + rot(u2, off2);
                let (s1, _s2) = solve2(d1, -d2, o2 - o1, MIN_SINE).ok_or(DyadFail::Parallel)?;
                let b = o1 + d1 * s1;
                let (v1, a1) = k1.kin_at(b);
                let (v2, a2) = k2.kin_at(b);
                let (sd1, sd2) = solve2_rel(d1, -d2, v2 - v1, 1.0, 1.0)?;
                let r = a2 + perp(d2) * (2.0 * k2.omega * sd2) - a1 - perp(d1) * (2.0 * k1.omega * sd1);
                let (sdd1, _) = solve2_rel(d1, -d2, r, 1.0, 1.0)?;
                let pb = PointState {
                    p: b,
                    v: v1 + d1 * sd1,
                    a: a1 + perp(d1) * (2.0 * k1.omega * sd1) + d1 * sdd1,
                };
                links[l1] = LinkState::from_point(&pb, b1, u1, k1.omega, k1.eps);
                links[l2] = LinkState::from_point(&pb, b2, u2, k2.omega, k2.eps);
                Ok(())
            }
            DyadGeom::Rpp {
                l1,
                l2,
                a,
                a1,
                guide,
                rel2,
                p2,
                relm,
                qm,
                dm,
                pm,
                guide_on_l2,
            } => {
                let pa = a.state(links);
                let k = links[guide.link];
                let u2 = rot(k.u, rel2);
                let u1 = rot(u2, relm);
                let g = rot(k.u, guide.dir);
                let q = k.pos(guide.through);
                let o2_0 = q - rot(u2, p2);
                let (gm, base) = if guide_on_l2 {
                    let o1 = o2_0 + rot(u2, qm) - rot(u1, pm);
                    (rot(u2, dm), o1 + rot(u1, a1))
                } else {
                    let o1 = o2_0 + rot(u2, pm) - rot(u1, qm);
                    (-rot(u1, dm), o1 + rot(u1, a1))
                };
                let (s2, _s1) = solve2(g, gm, pa.p - base, MIN_SINE).ok_or(DyadFail::Parallel)?;
                let (vk, ak) = k.kin_at(pa.p);
                let (sd2, sd1) = solve2_rel(g, gm, pa.v - vk, 1.0, 1.0)?;
                let r = pa.a - ak - (perp(g) * sd2 + perp(gm) * sd1) * (2.0 * k.omega);
                let (sdd2, _sdd1) = solve2_rel(g, gm, r, 1.0, 1.0)?;
                links[l1] = LinkState::from_point(&pa, a1, u1, k.omega, k.eps);
                let o2 = o2_0 + g * s2;
                let (vo, ao) = k.kin_at(o2);
                links[l2] = LinkState {
                    o: o2,
                    v: vo + g * sd2,
                    a: ao + perp(g) * (2.0 * k.omega * sd2) + g * sdd2,
                    u: u2,
                    omega: k.omega,
                    eps: k.eps,
                };
                Ok(())
            }
        }
    }
}
