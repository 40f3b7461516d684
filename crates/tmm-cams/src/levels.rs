//! The textbook's level-line method (метод линий уровня) for the centre of a
//! cam driving an oscillating follower (Chernaya, Timofeev, *ТММ. Курсовое
//! проектирование*, BMSTU 2019, appendix П6.5, p. 153–154).
//!
//! The book's frame: the follower's pivot A at the origin, its arm of length l
//! along +x in the lowest position, turning by κ·s (κ = +1: counter-clockwise
//! on the rise, as the book draws it). At each cam angle the point
//! `N = (l − σκ·l·s′)·u`, u the arm's direction, is the apex of the cone of
//! admissible cam centres (tmm's K, docs/cams.md §3: `K = B − σκ·l·ψ′·u`);
//! the book draws one side of each cone, the line through N at the allowed
//! angle to the roller centre's velocity, on the driving side: a centre O is
//! admissible for the position when `n·O ≥ n·N` with
//! `n = −t·d + sg·u`, `d = κ·J·u`, `t = tan ϑ_allowed`, and `sg = −σκ` on the
//! rise, `+σκ` on the return (for σ = κ = +1 the book's slopes
//! `tan(φ₂ + π/2 ± ϑ)`; derived here, docs/cams.md §10).
//!
//! 1. Point 1: the lines at the largest-speed points of the rise and the
//!    return, intersected.
//! 2. The level line through point 1, along the arm's lowest direction w:
//!    each line crosses it at `X(φ) = (n·N − n·P₁)/(n·w)` from P₁; the most
//!    restrictive line of a phase is the one with the largest `X` where
//!    `n·w > 0` (the admissible side is `X ≥ X(φ)`), the smallest where
//!    `n·w < 0` — the book's minimum on the rise and maximum on the return.
//! 3. Point 2, the cam centre: those two lines intersected; the centre
//!    distance `a_w = |AO|` and the initial angle φ₂₀ between AO and the arm.
//!
//! Point 2 lies on the two most restrictive lines *at the level of point 1*;
//! at its own level another line of the envelope can pass a little beyond it,
//! so the limit can be exceeded slightly. Repeating steps 2–3 with the level
//! through the last point 2 converges to the vertex of the two envelopes, the
//! exact centre the construction aims at (`vertex`).

use crate::extreme::maximize;
use crate::mechanism::{Mechanism, quarter};
use crate::program::{PhaseKind, Program};
use crate::spec::Limits;
use crate::{CamError, positive};
use tmm_geom::Vec2;

/// Samples per phase for the scans before golden-section refinement.
const SCAN: usize = 512;

/// The most level-line passes for the vertex.
const MAX_PASSES: usize = 100;

/// One limiting line `n·O = c` at a cam angle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LimitLine {
    /// Normal (admissible side `n·O ≥ c`).
    pub n: Vec2,
    /// Offset `n·N`.
    pub c: f64,
    /// The apex N, m.
    pub apex: Vec2,
}

/// The result of the level-line method.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LevelLines {
    /// Cam angle of the largest |s′| on the rise (the book's f_л for a
    /// counter-clockwise cam), rad.
    pub speed_rise: f64,
    /// Cam angle of the largest |s′| on the return (f_п), rad.
    pub speed_return: f64,
    /// Point 1 (X₁, Y₁), m, in the book's frame (pivot at the origin).
    pub point1: Vec2,
    /// The cam angle of the rise's most restrictive line at the level of point 1 (φ_Vmin), rad.
    pub level_rise: f64,
    /// The return's (φ_Vmax), rad.
    pub level_return: f64,
    /// The level-line values there: `X(φ)` from point 1 along the level, m.
    pub level_values: (f64, f64),
    /// Point 2 (X₂, Y₂), the cam centre, m.
    pub point2: Vec2,
    /// The vertex of the two envelopes (the level-line steps repeated to convergence), m.
    pub vertex: Vec2,
    /// Passes taken for the vertex.
    pub passes: usize,
}

/// The centre distance a_w = |AO| and the initial angle φ₂₀ between the arm's
/// lowest direction and AO (the book's `atan|Y₂/X₂|` when X₂ > 0), rad.
pub fn distance_and_angle(o: Vec2) -> (f64, f64) {
    (o.hypot(), o.y.abs().atan2(o.x))
}

/// The knife-edge mechanism with the cam centre at `o` in the book's frame:
/// tmm's pivot is A − O = −o.
pub fn mechanism(o: Vec2, arm: f64, kappa: f64) -> Mechanism {
    Mechanism::OscillatingRoller {
        pivot: -o,
        arm,
        psi0: 0.0,
        kappa,
        roller: 0.0,
    }
}

/// The driving-side limit line of phase `k` at `x` from its start.
pub fn limit_line(prog: &Program, sigma: f64, kappa: f64, limits: Limits, arm: f64, k: usize, x: f64) -> LimitLine {
    let ph = &prog.phases()[k];
    let (t, sg) = match ph.kind {
        PhaseKind::Rise => (limits.rise.tan(), -sigma * kappa),
        _ => (limits.ret.tan(), sigma * kappa),
    };
    let m = prog.eval_in(k, x);
    let psi = kappa * m.s;
    let u = Vec2::new(psi.cos(), psi.sin());
    let d = quarter(u) * kappa;
    let apex = u * (arm - sigma * kappa * arm * m.v);
    let n = -d * t + u * sg;
    LimitLine { n, c: n.dot(apex), apex }
}

fn cross(a: LimitLine, b: LimitLine) -> Option<Vec2> {
    let det = a.n.x * b.n.y - a.n.y * b.n.x;
    if det.abs() <= 1e-14 * a.n.hypot() * b.n.hypot() {
        return None;
    }
    Some(Vec2::new((a.c * b.n.y - a.n.y * b.c) / det, (a.n.x * b.c - a.c * b.n.x) / det))
}

/// The level-line method for a cycle with one rise and one return: the cam
/// turning by σ, the arm of length `arm` turning by κ on the rise, the stroke
/// an angle (rad).
///
/// ```
/// use tmm_cams::{levels, program::Program, spec};
/// let prog = Program::new(0.3, spec::parse_phases("rise 120 sine; dwell 60; return 120 sine; dwell 60").unwrap()).unwrap();
/// let lim = spec::parse_limits("rise 30, return 45", false).unwrap();
/// let l = levels::level_lines(&prog, 1.0, 1.0, lim, 0.1).unwrap();
/// // the vertex is on both envelopes: the largest driving-side angle there is the limit
/// let (a, _) = levels::distance_and_angle(l.vertex);
/// assert!(a > 0.0 && l.passes < 100);
/// ```
pub fn level_lines(prog: &Program, sigma: f64, kappa: f64, limits: Limits, arm: f64) -> Result<LevelLines, CamError> {
    let limits = limits.check()?;
    if !positive(arm) {
        return Err(CamError::Dimension {
            field: "arm",
            reason: format!("the arm length must be positive, got {arm}"),
        });
    }
    let rises: Vec<usize> = (0..prog.phases().len())
        .filter(|&k| prog.phases()[k].kind == PhaseKind::Rise)
        .collect();
    let rets: Vec<usize> = (0..prog.phases().len())
        .filter(|&k| prog.phases()[k].kind == PhaseKind::Return)
        .collect();
    let (&[rise], &[ret]) = (rises.as_slice(), rets.as_slice()) else {
        return Err(CamError::Sequence(format!(
            "the book's level-line method (П6.5) takes one rise and one return; this cycle has {} rises and {} returns",
            rises.len(),
            rets.len()
        )));
    };
    let line = |k: usize, x: f64| limit_line(prog, sigma, kappa, limits, arm, k, x);
    let speed = |k: usize| maximize(|x| prog.eval_in(k, x).v.abs(), 0.0, prog.phases()[k].angle, SCAN).0;
    let (xr, xl) = (speed(rise), speed(ret));
    let degenerate = || CamError::Infeasible("the level-line method's lines are parallel: no cam centre is found".into());
    let point1 = cross(line(rise, xr), line(ret, xl)).ok_or_else(degenerate)?;
    let w = Vec2::new(1.0, 0.0);
    // the most restrictive line of phase k crossing the level through p: its
    // position on the level, signed so that larger is more restrictive
    let restrict = |k: usize, p: Vec2| {
        let g = |x: f64| {
            let l = line(k, x);
            let nw = l.n.dot(w);
            (l.c - l.n.dot(p)) / nw * nw.signum()
        };
        let (x, v) = maximize(g, 0.0, prog.phases()[k].angle, SCAN);
        let nw = line(k, x).n.dot(w);
        (x, v * nw.signum())
    };
    let step = |p: Vec2| -> Result<(f64, f64, (f64, f64), Vec2), CamError> {
        let (a, va) = restrict(rise, p);
        let (b, vb) = restrict(ret, p);
        let q = cross(line(rise, a), line(ret, b)).ok_or_else(degenerate)?;
        Ok((a, b, (va, vb), q))
    };
    let (a, b, values, point2) = step(point1)?;
    let mut vertex = point2;
    let mut passes = 1;
    for _ in 0..MAX_PASSES {
        let (_, _, _, q) = step(vertex)?;
        let moved = (q - vertex).hypot();
        vertex = q;
        passes += 1;
        if moved <= 1e-13 * arm {
            break;
        }
    }
    if ![point1.x, point1.y, point2.x, point2.y, vertex.x, vertex.y]
        .iter()
        .all(|v| v.is_finite())
    {
        return Err(degenerate());
    }
    Ok(LevelLines {
        speed_rise: prog.start(rise) + xr,
        speed_return: prog.start(ret) + xl,
        point1,
        level_rise: prog.start(rise) + a,
        level_return: prog.start(ret) + b,
        level_values: values,
        point2,
        vertex,
        passes,
    })
}

/// The pressure angle of the knife edge with the cam centre at `o` (book's
/// frame), signed as the book's `θ = atan{[σκ·l·s′ + a_w cos(φ₂₀ + φ₂) − l] /
/// [a_w sin(φ₂₀ + φ₂)]}`: positive on the rise's driving side. In vectors
/// `tan θ = σκ·(O − N)·u / ((O − N)·(−d))` (docs/cams.md §3).
///
/// ```
/// use tmm_cams::{levels::signed_pressure, program::Program, spec};
/// use tmm_geom::Vec2;
/// let prog = Program::new(0.3, spec::parse_phases("rise 180 cosine; return 180 cosine").unwrap()).unwrap();
/// // at φ = 0 (s = s′ = 0): the book's formula with φ₂ = 0
/// let o = Vec2::new(0.12, -0.05);
/// let (aw, f) = (o.hypot(), (0.05f64).atan2(0.12));
/// let book = ((aw * f.cos() - 0.1) / (aw * f.sin())).atan();
/// assert!((signed_pressure(&prog, 1.0, 1.0, 0.1, o, 0.0) - book).abs() < 1e-14);
/// ```
pub fn signed_pressure(prog: &Program, sigma: f64, kappa: f64, arm: f64, o: Vec2, phi: f64) -> f64 {
    let m = prog.eval(phi);
    let psi = kappa * m.s;
    let u = Vec2::new(psi.cos(), psi.sin());
    let d = quarter(u) * kappa;
    let apex = u * (arm - sigma * kappa * arm * m.v);
    let r = o - apex;
    (sigma * kappa * r.dot(u)).atan2(-r.dot(d))
}
