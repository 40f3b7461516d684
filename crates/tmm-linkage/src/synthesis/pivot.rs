//! The crank pivot of a four-bar by the time ratio (синтез шарнирного
//! четырёхзвенника по коэффициенту K): the rocker's pivot D and the two
//! extreme positions C1, C2 of its joint with the coupler are known; the crank
//! pivot O lies on the inscribed-angle locus ([`Locus`]) and one extra
//! condition fixes it — the crank length, the frame distance, a line the
//! pivot must lie on (a frame direction, a given coordinate, a pressure angle
//! at an extreme position) or, when nothing else is given, the largest margin
//! against the pressure-angle limits (the largest smallest transmission angle).
//!
//! A pivot is valid (derived here, docs/synthesis.md § 2) when
//! 1. the crank is the shortest link and Grashof's condition holds
//!    (l_min + l_max < sum of the other two: the crank turns fully);
//! 2. C1 and C2 lie on the same side of the frame line OD, so both extreme
//!    positions belong to one assembly branch (circuit) of the four-bar.
//!
//! The transmission angle μ (угол передачи) between coupler and rocker
//! follows from |AD|² = l1² + d² − 2·l1·d·cos(φ − φ_D):
//! cos μ = (l2² + l3² − |AD|²)/(2·l2·l3) (Artobolevsky, ТММ, 1988, § 26;
//! Norton, Design of Machinery, eq. 4.32); the pressure angle is |90° − μ|,
//! monotonic in φ between φ_D and φ_D + π, so its largest value on a stroke is
//! at an end of the stroke or at φ_D, φ_D + π when they fall inside it.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use tmm_geom::{Vec2, cross, perp};

use super::error::SynthesisError;
use super::limits::Limits;
use super::locus::Locus;
use super::search::maximize;

/// The extra condition that fixes the crank pivot on the locus.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PivotCondition {
    /// The crank length l1, m.
    CrankLength(f64),
    /// The frame distance |OD|, m.
    FrameDistance(f64),
    /// The pivot lies on the line through `point` along `dir`.
    OnLine {
        /// A point of the line, m.
        point: Vec2,
        /// Direction of the line.
        dir: Vec2,
    },
    /// The largest pressure angle of the four-bar over the cycle, rad (seed
    /// 003 § 3: 38°).
    MaxPressure(f64),
    /// The pressure angle at one of the two dead positions, rad: the pivot on
    /// a line through an extreme position C at ϑ to C's velocity (seed 003 § 3:
    /// 38° in the extreme position K1).
    ExtremePressure(f64),
    /// The best margin against the limits (no limits: the largest smallest
    /// transmission angle).
    Optimum,
}

/// A valid crank pivot and the four-bar it makes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FourBar {
    /// Crank pivot O.
    pub o: Vec2,
    /// Rocker pivot D.
    pub d: Vec2,
    /// Crank l1, coupler l2, rocker l3, frame |OD|, m.
    pub l1: f64,
    /// Coupler.
    pub l2: f64,
    /// Rocker.
    pub l3: f64,
    /// Frame.
    pub frame: f64,
    /// The extreme position at which crank and coupler are extended.
    pub c_ext: Vec2,
    /// The one at which they are folded.
    pub c_fold: Vec2,
    /// Crank angle at the extended dead position, rad.
    pub phi_ext: f64,
    /// Crank angle at the folded dead position, rad.
    pub phi_fold: f64,
    /// Largest pressure angle on the working and return strokes, rad.
    pub pressure: (f64, f64),
    /// Which side of the chord C1C2 the pivot is on (±1).
    pub side: f64,
    /// The extreme position at which the working (slower) stroke ends.
    pub work_end: Vec2,
}

/// The result of the pivot choice.
#[derive(Debug, Clone, PartialEq)]
pub struct PivotChoice {
    /// The four-bar.
    pub bar: FourBar,
    /// The locus.
    pub locus: Locus,
    /// How many valid pivots met the condition.
    pub candidates: usize,
    /// Why this pivot.
    pub reason: String,
}

/// Transmission angle μ at crank angle `phi`.
fn mu(b: &FourBar, phi_d: f64, phi: f64) -> f64 {
    let ad2 = b.l1 * b.l1 + b.frame * b.frame - 2.0 * b.l1 * b.frame * (phi - phi_d).cos();
    ((b.l2 * b.l2 + b.l3 * b.l3 - ad2) / (2.0 * b.l2 * b.l3)).clamp(-1.0, 1.0).acos()
}

/// Largest pressure angle on the crank travel from `start` over `len` in the
/// direction `sg`.
fn stroke_pressure(b: &FourBar, sg: f64, start: f64, len: f64) -> f64 {
    let phi_d = (b.d - b.o).atan2();
    let th = |phi: f64| (FRAC_PI_2 - mu(b, phi_d, phi)).abs();
    let mut worst = th(start).max(th(start + sg * len));
    for x in [phi_d, phi_d + PI] {
        if (sg * (x - start)).rem_euclid(TAU) < len {
            worst = worst.max(th(x));
        }
    }
    worst
}

/// The four-bar of pivot `o`, when valid; `sg` the crank's direction.
pub fn evaluate(locus: &Locus, d: Vec2, o: Vec2, sg: f64) -> Option<FourBar> {
    let (l1, l2) = locus.lengths(o);
    let l3 = (locus.c1 - d).hypot();
    let frame = (o - d).hypot();
    let scale = l2.max(l3).max(frame);
    if !(l1 > 1e-9 * scale && scale.is_finite()) {
        return None;
    }
    let s1 = cross(d - o, locus.c1 - o);
    let s2 = cross(d - o, locus.c2 - o);
    if s1 * s2 <= 1e-12 * scale.powi(4) {
        return None;
    }
    let mut ls = [l1, l2, l3, frame];
    ls.sort_by(f64::total_cmp);
    if ls[0] != l1 || l1 + ls[3] > ls[1] + ls[2] - 1e-9 * scale {
        return None;
    }
    let (c_ext, c_fold) = if (o - locus.c1).hypot() > (o - locus.c2).hypot() {
        (locus.c1, locus.c2)
    } else {
        (locus.c2, locus.c1)
    };
    let phi_ext = (c_ext - o).atan2();
    let phi_fold = (c_fold - o).atan2() + PI;
    let mut b = FourBar {
        o,
        d,
        l1,
        l2,
        l3,
        frame,
        c_ext,
        c_fold,
        phi_ext,
        phi_fold,
        pressure: (0.0, 0.0),
        side: if cross(locus.c2 - locus.c1, o - locus.c1) > 0.0 {
            1.0
        } else {
            -1.0
        },
        work_end: c_ext,
    };
    // working stroke: the slower one
    let t_fe = (sg * (phi_ext - phi_fold)).rem_euclid(TAU);
    let (ws, wl) = if t_fe >= PI { (phi_fold, t_fe) } else { (phi_ext, TAU - t_fe) };
    b.work_end = if t_fe >= PI { c_ext } else { c_fold };
    let w = stroke_pressure(&b, sg, ws, wl);
    let r = stroke_pressure(&b, sg, ws + sg * wl, TAU - wl);
    b.pressure = (w, r);
    Some(b)
}

/// [`evaluate`], keeping only a four-bar whose working stroke ends at
/// `work_end` when one is asked for (a press's working stroke ends at the
/// bottom).
pub fn evaluate_ending(locus: &Locus, d: Vec2, o: Vec2, sg: f64, work_end: Option<Vec2>) -> Option<FourBar> {
    let b = evaluate(locus, d, o, sg)?;
    match work_end {
        Some(w) if (b.work_end - w).hypot() > 1e-9 * locus.h => None,
        _ => Some(b),
    }
}

/// The value a condition constrains, at a pivot `o`.
fn value_of(cond: &PivotCondition, b: &FourBar) -> f64 {
    match *cond {
        PivotCondition::CrankLength(_) => b.l1,
        PivotCondition::FrameDistance(_) => b.frame,
        PivotCondition::OnLine { point, dir } => cross(dir * (1.0 / dir.hypot()), b.o - point),
        PivotCondition::MaxPressure(_) => b.pressure.0.max(b.pressure.1),
        PivotCondition::ExtremePressure(_) | PivotCondition::Optimum => 0.0,
    }
}

/// The nearest value of the constrained quantity that some valid pivot has.
fn nearest(locus: &Locus, d: Vec2, sg: f64, work_end: Option<Vec2>, cond: &PivotCondition, target: f64) -> Option<f64> {
    let mut best: Option<(f64, f64, f64)> = None; // (|g − target|, side, w)
    let (lo, hi) = locus.domain();
    for side in [1.0, -1.0] {
        let r = maximize(
            |w| match evaluate_ending(locus, d, locus.point(side, w), sg, work_end) {
                Some(b) => -(value_of(cond, &b) - target).abs(),
                None => f64::NAN,
            },
            lo,
            hi,
            720,
        );
        if let Some((w, v)) = r {
            if best.is_none_or(|(bv, _, _)| -v < bv) {
                best = Some((-v, side, w));
            }
        }
    }
    let (_, side, w) = best?;
    evaluate_ending(locus, d, locus.point(side, w), sg, work_end).map(|b| value_of(cond, &b))
}

/// Choose the crank pivot. `field` names the condition's field in errors;
/// for [`PivotCondition::OnLine`] the error's nearest value is the signed
/// offset (along the line's left normal) of the nearest line that works.
pub fn choose(
    locus: Locus,
    d: Vec2,
    sg: f64,
    cond: PivotCondition,
    limits: &Limits,
    field: &str,
    work_end: Option<Vec2>,
) -> Result<PivotChoice, SynthesisError> {
    let ev = |o: Vec2| evaluate_ending(&locus, d, o, sg, work_end);
    // margin first; among equal margins the more compact four-bar
    let score = |b: &FourBar| limits.margin(b.pressure.0, b.pressure.1) - 1e-9 * (b.l2 + b.frame) / b.l3;
    let mut cands: Vec<FourBar> = Vec::new();
    let (lo, hi) = locus.domain();
    let what;
    match cond {
        PivotCondition::CrankLength(l1) => {
            what = format!("the crank length l1 = {} m", super::error::show(l1));
            if locus.theta == 0.0 {
                // K = 1: every pivot has l1 = h; the crank length must be h
                if (l1 - locus.h).abs() > 1e-9 * locus.h {
                    return Err(SynthesisError::infeasible(
                        field,
                        format!(
                            "with K = 1 the crank pivot lies on the line of the extreme positions and the crank is half their distance, {} m; {} m was given",
                            super::error::show(locus.h),
                            super::error::show(l1)
                        ),
                        Some(locus.h),
                    ));
                }
                return choose(locus, d, sg, PivotCondition::Optimum, limits, field, work_end);
            }
            let s = l1 * (0.5 * locus.theta).cos() / locus.h;
            if s < 1.0 {
                let w = s.asin();
                for side in [1.0, -1.0] {
                    for ww in [w, -w] {
                        if let Some(b) = ev(locus.point(side, ww)) {
                            cands.push(b);
                        }
                    }
                }
            }
        }
        PivotCondition::FrameDistance(f) => {
            what = format!("the frame distance |OD| = {} m", super::error::show(f));
            for side in [1.0, -1.0] {
                for o in locus.meet_circle(side, d, f) {
                    if let Some(b) = ev(o) {
                        cands.push(b);
                    }
                }
            }
        }
        PivotCondition::OnLine { point, dir } => {
            what = "the line given for the crank pivot".to_string();
            for side in [1.0, -1.0] {
                for o in locus.meet_line(side, point, dir) {
                    if let Some(b) = ev(o) {
                        cands.push(b);
                    }
                }
            }
        }
        PivotCondition::MaxPressure(p) => {
            what = format!("the largest pressure angle {:.4}°", p.to_degrees());
            let n = 720;
            for side in [1.0, -1.0] {
                let f = |w: f64| ev(locus.point(side, w)).map_or(f64::NAN, |b| b.pressure.0.max(b.pressure.1) - p);
                let h = (hi - lo) / (n + 1) as f64;
                let mut prev = (lo + h, f(lo + h));
                for k in 2..=n {
                    let w = lo + h * k as f64;
                    let v = f(w);
                    if prev.1.is_finite() && v.is_finite() && prev.1.signum() != v.signum() {
                        if let Some(root) = tmm_geom::root::brent(f, prev.0, w, 1e-15) {
                            if let Some(b) = ev(locus.point(side, root)) {
                                cands.push(b);
                            }
                        }
                    }
                    prev = (w, v);
                }
            }
        }
        PivotCondition::ExtremePressure(p) => {
            what = format!("the pressure angle {:.4}° at a dead position", p.to_degrees());
            for c in [locus.c1, locus.c2] {
                let v = perp(c - d);
                for a in [p, -p] {
                    let (s, co) = a.sin_cos();
                    let dir = Vec2::new(co * v.x - s * v.y, s * v.x + co * v.y);
                    for side in [1.0, -1.0] {
                        for o in locus.meet_line(side, c, dir) {
                            if let Some(b) = ev(o) {
                                cands.push(b);
                            }
                        }
                    }
                }
            }
        }
        PivotCondition::Optimum => {
            let mut best: Option<FourBar> = None;
            for side in [1.0, -1.0] {
                let r = maximize(|w| ev(locus.point(side, w)).map_or(f64::NAN, |b| score(&b)), lo, hi, 360);
                if let Some((w, _)) = r {
                    if let Some(b) = ev(locus.point(side, w)) {
                        if best.is_none_or(|x| score(&b) > score(&x)) {
                            best = Some(b);
                        }
                    }
                }
            }
            let Some(bar) = best else {
                return Err(SynthesisError::infeasible(
                    field,
                    "no crank pivot on the locus makes a crank-rocker with these extreme positions",
                    None,
                ));
            };
            let reason = if limits.any() {
                format!(
                    "the pivot on the locus with the largest margin against the pressure-angle limits ({:.4}°)",
                    score(&bar).to_degrees()
                )
            } else {
                format!(
                    "the pivot on the locus with the largest smallest transmission angle ({:.4}°)",
                    (FRAC_PI_2 - bar.pressure.0.max(bar.pressure.1)).to_degrees()
                )
            };
            return Ok(PivotChoice {
                bar,
                locus,
                candidates: 1,
                reason,
            });
        }
    }
    let n = cands.len();
    let Some(bar) = cands.into_iter().max_by(|a, b| score(a).total_cmp(&score(b))) else {
        if let PivotCondition::ExtremePressure(_) = cond {
            return Err(SynthesisError::infeasible(
                field,
                format!("no crank pivot on the locus of K gives a crank-rocker with {what}"),
                None,
            ));
        }
        let target = match cond {
            PivotCondition::CrankLength(l) => l,
            PivotCondition::FrameDistance(f) => f,
            PivotCondition::MaxPressure(p) => p,
            _ => 0.0,
        };
        return Err(SynthesisError::infeasible(
            field,
            format!(
                "no crank pivot on the locus of K (θ = {:.4}°) gives a crank-rocker with {what} (the crank must be the shortest link, turn fully by Grashof's condition, and both extreme positions must lie on one assembly branch)",
                locus.theta.to_degrees()
            ),
            nearest(&locus, d, sg, work_end, &cond, target),
        ));
    };
    let reason = if n > 1 {
        format!(
            "{what}; of the {n} pivots on the locus meeting it, the one with the {}",
            if limits.any() {
                "largest margin against the pressure-angle limits"
            } else {
                "largest smallest transmission angle"
            }
        )
    } else {
        format!("{what}; the only pivot on the locus meeting it")
    };
    Ok(PivotChoice {
        bar,
        locus,
        candidates: n,
        reason,
    })
}

/// Unit vector at angle `a`.
pub fn polar(a: f64) -> Vec2 {
    Vec2::new(a.cos(), a.sin())
}

/// The left normal of a direction.
pub fn normal(d: Vec2) -> Vec2 {
    perp(d * (1.0 / d.hypot()))
}
