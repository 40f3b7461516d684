//! The smallest cam (минимальный радиус r₀) for the pressure-angle limits of a
//! roller follower, and for convexity of a flat-faced one.
//!
//! Roller followers: on the s–ds/dφ diagram the cam centre O must lie, for
//! every position, inside the cone with apex K (the diagram point) whose half
//! angle is the allowed pressure angle ϑ, opening away from the direction of
//! the rise (the course's construction: rays at the allowed angle tangent to the
//! diagram). Each cone is two half-planes. For a translating follower all the
//! half-planes of one phase share two directions, so the admissible region is
//! cut by at most four lines — each at the extreme of a smooth function found
//! to rounding — and the smallest r₀ is an exact nearest-point problem
//! (derived here, docs/cams.md §3). For an oscillating follower the cone axes
//! turn with the arm; the region is the polygon cut by the cones of a dense
//! set of positions.
//!
//! Flat faces: the radius of curvature of the working profile is
//! `ρ = r₀ + s + d²s/dφ²` (Geronimus; Artobolevsky, ТММ, the chapter on cam mechanisms), so the
//! smallest base circle is `r₀ = ρ_min − min(s + d²s/dφ²)`.

use crate::extreme::{maximize, minimize};
use crate::halfplane::{HalfPlane, Region, nearest_few};
use crate::mechanism::{Mechanism, quarter};
use crate::program::{PhaseKind, Program};
use crate::spec::Limits;
use crate::{CamError, positive};
use tmm_geom::Vec2;

/// Samples per phase for the extreme searches.
const SCAN: usize = 256;

/// Maximum over the moving phases of `f(k, φ from phase start)` on each phase
/// with its own limit: returns, per moving phase, `(t = tan ϑ, max f)`.
fn phase_max(prog: &Program, limits: Limits, mut f: impl FnMut(usize, f64, f64) -> f64) -> Vec<(usize, f64, f64)> {
    let mut out = Vec::new();
    for (k, ph) in prog.phases().iter().enumerate() {
        let lim = match ph.kind {
            PhaseKind::Rise => limits.rise,
            PhaseKind::Return => limits.ret,
            PhaseKind::Dwell => continue,
        };
        let t = lim.tan();
        let (_, m) = maximize(|x| f(k, x, t), 0.0, ph.angle, SCAN);
        out.push((k, t, m));
    }
    out
}

/// Translating roller (or knife-edge) follower: the offset e and the height
/// s₀ of the lowest roller centre giving the smallest `r₀ = √(e² + s₀²)` with
/// the pressure angle within `limits`; with `offset = Some(e)` the smallest
/// r₀ for that offset.
///
/// With `x = e`, `y = s₀`, a phase with `t = tan ϑ_allowed` requires
/// `t·y + x ≥ max(σ·s′ − t·s)` and `t·y − x ≥ max(−σ·s′ − t·s)`
/// (from `|σs′ − e| ≤ t·(s₀ + s)`, Norton, ch. 8).
///
/// ```
/// use tmm_cams::{sizing, spec};
/// use tmm_cams::program::Program;
/// let prog = Program::new(0.013, spec::parse_phases("rise 108 const-accel(u=1/3); dwell 15; return 108 const-accel(u=1/3); dwell 129").unwrap()).unwrap();
/// let lim = spec::parse_limits("rise 75, return 60", true).unwrap();
/// let (e, s0) = sizing::translating_roller(&prog, 1.0, lim, None).unwrap();
/// let r0 = e.hypot(s0);
/// assert!(r0 > 0.013 && r0 < 0.2);
/// ```
pub fn translating_roller(prog: &Program, sigma: f64, limits: Limits, offset: Option<f64>) -> Result<(f64, f64), CamError> {
    let plus = phase_max(prog, limits, |k, x, t| {
        let m = prog.eval_in(k, x);
        sigma * m.v - t * m.s
    });
    let minus = phase_max(prog, limits, |k, x, t| {
        let m = prog.eval_in(k, x);
        -sigma * m.v - t * m.s
    });
    // half-planes in (x = e, y = s₀): x + t·y ≥ c₊ and −x + t·y ≥ c₋
    let mut hs: Vec<HalfPlane> = Vec::with_capacity(2 * plus.len());
    for (&(_, t, cp), &(_, _, cm)) in plus.iter().zip(&minus) {
        hs.push(HalfPlane {
            n: Vec2::new(1.0, t),
            c: cp,
        });
        hs.push(HalfPlane {
            n: Vec2::new(-1.0, t),
            c: cm,
        });
    }
    let (e, s0) = match offset {
        Some(e) => {
            if !e.is_finite() {
                return Err(CamError::Dimension {
                    field: "offset",
                    reason: "must be a finite length".into(),
                });
            }
            // s₀ ≥ (c − n.x·e)/t for every half-plane
            let s0 = hs.iter().map(|h| (h.c - h.n.x * e) / h.n.y).fold(0.0f64, f64::max);
            (e, s0)
        }
        None => {
            let p = nearest_few(&hs, Vec2::ZERO)
                .ok_or_else(|| CamError::Infeasible("no cam centre satisfies the pressure-angle limits".into()))?;
            (p.x, p.y)
        }
    };
    if !positive(s0) {
        return Err(CamError::Infeasible(format!(
            "the pressure-angle limits give a degenerate cam (s₀ = {s0:e} m)"
        )));
    }
    Ok((e, s0))
}

/// Oscillating roller follower of arm `arm`: the pivot position and arm
/// direction giving the smallest r₀ = |O B₀| with the pressure angle within
/// `limits`; with `pivot = Some(a)` the smallest r₀ for the pivot distance a.
///
/// Both senses of the arm's swing relative to the cam's rotation are tried.
/// Returns the mechanism with a zero roller radius.
pub fn oscillating_roller(
    prog: &Program,
    sigma: f64,
    limits: Limits,
    arm: f64,
    pivot: Option<f64>,
    samples: usize,
) -> Result<Mechanism, CamError> {
    oscillating_roller_senses(prog, sigma, limits, arm, pivot, samples, &[1.0, -1.0])
}

/// [`oscillating_roller`] with the arm's senses of turning on the rise to try
/// (`&[1.0]`: counter-clockwise only, the textbook's arrangement).
pub fn oscillating_roller_senses(
    prog: &Program,
    sigma: f64,
    limits: Limits,
    arm: f64,
    pivot: Option<f64>,
    samples: usize,
    senses: &[f64],
) -> Result<Mechanism, CamError> {
    if !positive(arm) {
        return Err(CamError::Dimension {
            field: "arm",
            reason: format!("the arm length must be positive, got {arm}"),
        });
    }
    if prog.stroke() >= std::f64::consts::PI {
        return Err(CamError::Dimension {
            field: "stroke",
            reason: "an oscillating follower's stroke is an angle below 180°".into(),
        });
    }
    if let Some(a) = pivot
        && !positive(a)
    {
        return Err(CamError::Dimension {
            field: "pivot",
            reason: format!("the pivot distance must be positive, got {a}"),
        });
    }
    let mut best: Option<(f64, Mechanism)> = None;
    let b0 = Vec2::new(arm, 0.0);
    for &kappa in senses {
        let hs = oscillating_cones(prog, sigma, limits, arm, kappa, samples);
        let o = nearest_by_cuts(&hs, b0, arm, pivot);
        let Some(o) = o else { continue };
        let r0 = (o - b0).hypot();
        if r0 > 1e-9 * arm && best.as_ref().is_none_or(|(r, _)| r0 < *r) {
            best = Some((
                r0,
                Mechanism::OscillatingRoller {
                    pivot: -o,
                    arm,
                    psi0: 0.0,
                    kappa,
                    roller: 0.0,
                },
            ));
        }
    }
    best.map(|(_, m)| m).ok_or_else(|| {
        CamError::Infeasible(match pivot {
            Some(a) => format!("no cam centre at the pivot distance {:.3} mm keeps the pressure angle within the limits; try another pivot distance or omit it", a * 1e3),
            None => "no cam centre keeps the pressure angle within the limits for this arm and stroke; lengthen the arm, reduce the stroke or allow larger pressure angles".into(),
        })
    })
}

/// The admissible region of the cam centre for a translating roller follower
/// on the s–ds/dφ diagram: coordinates with the lowest roller centre at the
/// origin and the follower moving along +y, so the centre is at `(−e, −s₀)`;
/// cut from a square of half-size `size` about the origin.
pub fn translating_region(prog: &Program, sigma: f64, limits: Limits, size: f64) -> Region {
    let mut region = Region::square(Vec2::ZERO, size);
    for (k, ph) in prog.phases().iter().enumerate() {
        let lim = match ph.kind {
            PhaseKind::Rise => limits.rise,
            PhaseKind::Return => limits.ret,
            PhaseKind::Dwell => continue,
        };
        let t = lim.tan();
        for sg in [1.0, -1.0] {
            let (_, c) = maximize(
                |x| {
                    let m = prog.eval_in(k, x);
                    sg * sigma * m.v - t * m.s
                },
                0.0,
                ph.angle,
                SCAN,
            );
            // x + t·y ≥ c in (e, s₀) is −X·sg… in (X, Y) = (−e, −s₀): −sg·X − t·Y ≥ c
            region.clip(HalfPlane { n: Vec2::new(-sg, -t), c });
        }
    }
    region
}

/// The admissible region of the cam centre for an oscillating roller
/// follower, in the frame with the pivot at the origin and the lowest roller
/// centre at `(arm, 0)`; `kappa = ±1` is the arm's sense of turning on the
/// rise. Each of `samples + 1` positions per moving phase cuts its cone: apex
/// `K = B − σκ·l·ψ′·u`, axis `−d`, half-angle ϑ (derived here, docs/cams.md §3).
pub fn oscillating_region(prog: &Program, sigma: f64, limits: Limits, arm: f64, kappa: f64, samples: usize) -> Region {
    let mut region = Region::square(Vec2::new(arm, 0.0), 1e3 * arm);
    for h in oscillating_cones(prog, sigma, limits, arm, kappa, samples) {
        region.clip(h);
    }
    region
}

/// The half-planes of the cones of an oscillating roller follower's centre
/// (two per position, `samples + 1` positions per moving phase), in the frame
/// of [`oscillating_region`].
pub fn oscillating_cones(prog: &Program, sigma: f64, limits: Limits, arm: f64, kappa: f64, samples: usize) -> Vec<HalfPlane> {
    let mut hs = Vec::new();
    for (k, ph) in prog.phases().iter().enumerate() {
        let lim = match ph.kind {
            PhaseKind::Rise => limits.rise,
            PhaseKind::Return => limits.ret,
            PhaseKind::Dwell => continue,
        };
        let t = lim.tan();
        let n = samples.max(16);
        // equal steps, and the joints inside the law: where s″ jumps the
        // apex curve (s, s′ only) has a corner and the pressure angle its
        // peak, which a step would cut off to first order
        let joints = ph.law.as_ref().map(|l| l.breaks()).unwrap_or_default();
        let at = (0..=n)
            .map(|i| ph.angle * i as f64 / n as f64)
            .chain(joints.iter().filter(|&&x| x < 1.0).map(|&x| x * ph.angle));
        for x in at {
            let m = prog.eval_in(k, x);
            let psi = kappa * m.s;
            let u = Vec2::new(psi.cos(), psi.sin());
            let d = quarter(u) * kappa;
            let kp = u * arm - u * (sigma * kappa * arm * m.v);
            for sg in [1.0, -1.0] {
                let nrm = -d * t + u * sg;
                hs.push(HalfPlane { n: nrm, c: nrm.dot(kp) });
            }
        }
    }
    hs
}

/// The point of `∩ hs` nearest to `q` (or, with `radius = Some(a)`, the
/// nearest such point on the circle |p| = a), by cutting planes: start from a
/// polygon cut by every 32nd half-plane, take its nearest point, and add the
/// most violated half-plane until none is violated. The answer is exact for
/// the whole set: a nearest point of a larger region that satisfies every
/// constraint is the nearest point of the smaller one.
fn nearest_by_cuts(hs: &[HalfPlane], q: Vec2, scale: f64, radius: Option<f64>) -> Option<Vec2> {
    let mut region = Region::square(q, 1e3 * scale);
    for h in hs.iter().step_by(32) {
        region.clip(*h);
    }
    let tol = 1e-12 * scale;
    for _ in 0..hs.len() {
        if region.is_empty() {
            return None;
        }
        let o = match radius {
            None => region.nearest(q)?,
            Some(a) => {
                let mut cands = region.circle_crossings(Vec2::ZERO, a);
                let toward = q * (a / q.hypot());
                if region.contains(toward, 1e-12 * a) {
                    cands.push(toward);
                }
                cands.into_iter().min_by(|p, r| (*p - q).hypot().total_cmp(&(*r - q).hypot()))?
            }
        };
        let worst = hs.iter().map(|h| (h.slack(o), h)).min_by(|a, b| a.0.total_cmp(&b.0));
        match worst {
            Some((sl, h)) if sl < -tol => region.clip(*h),
            _ => return Some(o),
        }
    }
    None
}

/// The minimum of `s + d²s/dφ²` over the cycle (the left-hand side of
/// Geronimus' convexity condition without r₀), checking both sides of every
/// phase joint.
pub fn min_s_plus_a(prog: &Program) -> f64 {
    let mut best = f64::INFINITY;
    for (k, ph) in prog.phases().iter().enumerate() {
        let mut cuts = vec![0.0];
        if let Some(l) = &ph.law {
            cuts.extend(l.breaks().into_iter().map(|x| x * ph.angle));
        }
        cuts.push(ph.angle);
        for w in cuts.windows(2) {
            let (_, m) = minimize(
                |x| {
                    let q = prog.eval_in(k, x);
                    q.s + q.a
                },
                w[0],
                w[1],
                SCAN / 4,
            );
            best = best.min(m);
            for x in [w[0], w[1]] {
                let q = prog.eval_in(k, x);
                best = best.min(q.s + q.a);
            }
        }
    }
    best
}

/// Translating flat-faced follower: the smallest base circle with the working
/// profile's radius of curvature at least `rho_min` everywhere:
/// `r₀ = ρ_min − min(s + s″)` (Geronimus' condition `r₀ + s + s″ ≥ ρ_min`),
/// and never below `rho_min` itself.
///
/// ```
/// use tmm_cams::{sizing, spec};
/// use tmm_cams::program::Program;
/// let prog = Program::new(0.01, spec::parse_phases("rise 90 cosine; dwell 90; return 90 cosine; dwell 90").unwrap()).unwrap();
/// // rise: s + s″ = h/2 + (3h/2)·cos 2φ (β = 90°), least at the top: −h
/// let r0 = sizing::translating_flat(&prog, 0.002);
/// assert!((r0 - (0.002 + 0.01)).abs() < 1e-12);
/// ```
pub fn translating_flat(prog: &Program, rho_min: f64) -> f64 {
    (rho_min - min_s_plus_a(prog)).max(rho_min)
}

/// Oscillating flat face through the pivot at distance `a`: the smallest r₀
/// whose working profile has `ρ ≥ rho_min` everywhere (found by bisection on
/// r₀ over (0, a), the minimum of ρ over the cycle being evaluated from the
/// envelope formula of [`crate::profile`]).
pub fn oscillating_flat(prog: &Program, sigma: f64, a: f64, rho_min: f64) -> Result<f64, CamError> {
    if !positive(a) {
        return Err(CamError::Dimension {
            field: "pivot",
            reason: format!("the pivot distance must be positive, got {a}"),
        });
    }
    let h = prog.stroke();
    if h >= std::f64::consts::FRAC_PI_2 {
        return Err(CamError::Dimension {
            field: "stroke",
            reason: "an oscillating flat face needs a swing below 90°".into(),
        });
    }
    let margin = |r0: f64| -> f64 {
        let d0 = (r0 / a).asin();
        if d0 + h >= std::f64::consts::FRAC_PI_2 {
            return f64::NEG_INFINITY;
        }
        let mech = Mechanism::OscillatingFlat { a, delta0: d0 };
        crate::profile::min_flat_rho(prog, &mech, sigma, 720) - rho_min
    };
    // scan up from small r₀ to the first admissible one, then bisect
    let n = 200;
    let mut lo = 0.0;
    let mut hi = None;
    for i in 1..n {
        let r = a * i as f64 / n as f64;
        if margin(r) >= 0.0 {
            hi = Some(r);
            break;
        }
        lo = r;
    }
    let Some(mut hi) = hi else {
        return Err(CamError::Infeasible(format!(
            "no base circle makes the working profile convex with ρ ≥ {:.3} mm at the pivot distance {:.3} mm; increase the pivot distance",
            rho_min * 1e3,
            a * 1e3
        )));
    };
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if margin(mid) >= 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Ok(hi)
}
