//! The textbook's sizing of a translating roller follower by the tangents to
//! the s–ds/dφ diagram (фазовый портрет; Chernaya, Timofeev, *ТММ. Курсовое
//! проектирование*, BMSTU 2019, appendix П6.4, p. 150–152), beside which tmm
//! puts its exact sizing ([`crate::sizing::translating_roller`]).
//!
//! The book bounds the pressure angle on its driving side only: one ray per
//! moving phase, on the rise the side where the follower is pushed up, on the
//! return the other. In tmm's terms (docs/cams.md §3) a phase with
//! `t = tan ϑ_allowed` and `g = sign(σ·s′)` on it (σ on the rise, −σ on the
//! return) asks `g·e + t·s₀ ≥ |s′| − t·s` at every position. The book solves
//! it three ways:
//!
//! 1. *Approximately*, at the points of the largest |s′| of each phase
//!    (f_п, f_л): the two equations `g·e + t·s₀ = |s′| − t·s` there.
//! 2. *Tangency*: the point where the diagram's tangent has the ray's
//!    slope, `|s′|/|s″| = tan δ = cot ϑ` (`d(|s′| − t·s)/dφ = 0`): the
//!    maximum of `|s′| − t·s` over the phase, found to rounding.
//! 3. *Method 1*: the two tangent lines drawn on the diagram in the book's
//!    coordinates `X = v_q = −σ·s′`, `Y = s` (the ray through a point with
//!    `X > 0` rises at `tan δ`, the other at `tan(π − δ)`), intersected:
//!    the cam centre is `(X, Y) = (e_book, −s₀)`, `e_book = −e`. *Method 2*:
//!    the equations of step 1 written at the tangency points. Both give the
//!    vertex of the two half-planes — the same point, computed two ways.
//!
//! With both sides of each phase bounded (tmm: `|ϑ| ≤ ϑ_allowed` on the
//! phase) the region has up to four lines and its nearest point to the
//! lowest roller centre can lie elsewhere: the report gives both.

use crate::extreme::maximize;
use crate::mechanism::Mechanism;
use crate::profile::pressure_extremes;
use crate::program::{PhaseKind, Program};
use crate::spec::Limits;
use crate::{CamError, positive};

/// Samples per phase for the scans before golden-section refinement.
const SCAN: usize = 512;

/// A placement of the translating follower: the offset e (tmm's sign: the
/// follower moves on the line x = e) and the height s₀ of the lowest roller
/// centre above the cam centre.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Centre {
    /// Offset e, m (the book's e is −e: it measures it the other way).
    pub e: f64,
    /// Height s₀ of the lowest roller centre, m.
    pub s0: f64,
}

impl Centre {
    /// r₀ = √(e² + s₀²), the radius of the roller centre's lowest circle.
    pub fn r0(&self) -> f64 {
        self.e.hypot(self.s0)
    }
    /// The knife-edge mechanism with this placement (for pressure angles).
    pub fn mechanism(&self) -> Mechanism {
        Mechanism::TranslatingRoller {
            e: self.e,
            s0: self.s0,
            roller: 0.0,
        }
    }
}

/// The book's steps for a cycle of one rise and one return.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TangentSizing {
    /// Index of the rise phase.
    pub rise: usize,
    /// Index of the return phase.
    pub ret: usize,
    /// Cam angle of the largest |s′| on the rise (the book's f_п for a
    /// clockwise cam), rad from the start of the cycle.
    pub speed_rise: f64,
    /// Cam angle of the largest |s′| on the return (f_л), rad.
    pub speed_return: f64,
    /// Step 1: the approximate centre from the largest-speed points.
    pub approximate: Centre,
    /// Step 2: the cam angle where the rise's ray touches the diagram (φ_п), rad.
    pub tangent_rise: f64,
    /// The cam angle where the return's ray touches the diagram (φ_л), rad.
    pub tangent_return: f64,
    /// Method 1: the intersection of the two tangent lines on the diagram.
    pub method1: Centre,
    /// The intersection in the book's diagram coordinates (X = v_q, Y = s):
    /// `(e_book, −s₀)`, m.
    pub method1_xy: (f64, f64),
    /// Method 2: the step-1 equations at the tangency points.
    pub method2: Centre,
}

impl TangentSizing {
    /// The book's relative changes of step 3 against step 1:
    /// `Δ_r = (r₀ − r₀пр)/r₀`, `Δ_e = (e − e_пр)/e` (method 1 against the
    /// approximate centre).
    pub fn deltas(&self) -> (f64, f64) {
        let (r, rp) = (self.method1.r0(), self.approximate.r0());
        let (e, ep) = (self.method1.e, self.approximate.e);
        ((r - rp) / r, if e != 0.0 { (e - ep) / e } else { 0.0 })
    }
}

/// The phase's bound data: `(t, g)` with `t = tan ϑ_allowed`, `g` the sign of
/// σ·s′ on the phase.
fn bound(kind: PhaseKind, sigma: f64, limits: Limits) -> (f64, f64) {
    match kind {
        PhaseKind::Rise => (limits.rise.tan(), sigma),
        _ => (limits.ret.tan(), -sigma),
    }
}

/// Solve `g₁·e + t₁·s₀ = c₁`, `g₂·e + t₂·s₀ = c₂` (g₂ = −g₁, so the
/// determinant `g₁t₂ − g₂t₁ = g₁(t₁ + t₂)` is never zero).
fn solve2((g1, t1, c1): (f64, f64, f64), (g2, t2, c2): (f64, f64, f64)) -> Centre {
    let det = g1 * t2 - g2 * t1;
    Centre {
        e: (c1 * t2 - c2 * t1) / det,
        s0: (g1 * c2 - g2 * c1) / det,
    }
}

/// The book's three steps (see the module header) for a cycle with exactly
/// one rise and one return, the cam turning by σ.
///
/// ```
/// use tmm_cams::{program::Program, spec, tangents::tangent_sizing};
/// // cosine rise and return of 90° each, 20 mm, ϑ ≤ 30° both: symmetric, so e = 0
/// let prog = Program::new(0.02, spec::parse_phases("rise 90 cosine; dwell 90; return 90 cosine; dwell 90").unwrap()).unwrap();
/// let lim = spec::parse_limits("30", false).unwrap();
/// let t = tangent_sizing(&prog, 1.0, lim).unwrap();
/// assert!(t.method1.e.abs() < 1e-12 && (t.method1.s0 - t.method2.s0).abs() < 1e-12);
/// // the largest speed is mid-phase: s′ = (h/2)(π/β) sin(πφ/β) peaks at φ = β/2
/// assert!((t.speed_rise - 45f64.to_radians()).abs() < 1e-9);
/// ```
pub fn tangent_sizing(prog: &Program, sigma: f64, limits: Limits) -> Result<TangentSizing, CamError> {
    let limits = limits.check()?;
    let moving: Vec<(usize, PhaseKind)> = prog
        .phases()
        .iter()
        .enumerate()
        .filter(|(_, p)| p.kind != PhaseKind::Dwell)
        .map(|(k, p)| (k, p.kind))
        .collect();
    let rises: Vec<usize> = moving.iter().filter(|m| m.1 == PhaseKind::Rise).map(|m| m.0).collect();
    let rets: Vec<usize> = moving.iter().filter(|m| m.1 == PhaseKind::Return).map(|m| m.0).collect();
    let (&[rise], &[ret]) = (rises.as_slice(), rets.as_slice()) else {
        return Err(CamError::Sequence(format!(
            "the book's tangent methods (П6.4) draw one ray for the rise and one for the return; this cycle has {} rises and {} returns",
            rises.len(),
            rets.len()
        )));
    };
    let phases = [rise, ret];
    let mut speed = [0.0; 2];
    let mut tangent = [0.0; 2];
    let mut at_speed = [(0.0, 0.0, 0.0); 2];
    let mut at_tangent = [(0.0, 0.0, 0.0); 2];
    let mut book_pts = [(0.0, 0.0, 0.0); 2];
    for (i, &k) in phases.iter().enumerate() {
        let ph = &prog.phases()[k];
        let (t, g) = bound(ph.kind, sigma, limits);
        // step 1: the largest |s′| of the phase
        let (x1, _) = maximize(|x| prog.eval_in(k, x).v.abs(), 0.0, ph.angle, SCAN);
        let m1 = prog.eval_in(k, x1);
        speed[i] = prog.start(k) + x1;
        at_speed[i] = (g, t, m1.v.abs() - t * m1.s);
        // step 2: the tangency, the maximum of |s′| − t·s
        let (x2, c) = maximize(
            |x| {
                let m = prog.eval_in(k, x);
                m.v.abs() - t * m.s
            },
            0.0,
            ph.angle,
            SCAN,
        );
        let m2 = prog.eval_in(k, x2);
        tangent[i] = prog.start(k) + x2;
        at_tangent[i] = (g, t, c);
        // the diagram point in the book's coordinates and the ray's slope
        let x = -sigma * m2.v;
        let slope = if x >= 0.0 { 1.0 / t } else { -1.0 / t };
        book_pts[i] = (x, m2.s, slope);
    }
    let approximate = solve2(at_speed[0], at_speed[1]);
    let method2 = solve2(at_tangent[0], at_tangent[1]);
    // method 1: Y − Y₁ = m₁(X − X₁), Y − Y₂ = m₂(X − X₂)
    let ((x1, y1, m1), (x2, y2, m2)) = (book_pts[0], book_pts[1]);
    let bx = (y2 - y1 + m1 * x1 - m2 * x2) / (m1 - m2);
    let by = y1 + m1 * (bx - x1);
    let method1 = Centre { e: -bx, s0: -by };
    let out = TangentSizing {
        rise,
        ret,
        speed_rise: speed[0],
        speed_return: speed[1],
        approximate,
        tangent_rise: tangent[0],
        tangent_return: tangent[1],
        method1,
        method1_xy: (bx, by),
        method2,
    };
    for c in [approximate, method1, method2] {
        if !positive(c.s0) || !c.e.is_finite() {
            return Err(CamError::Infeasible(format!(
                "the book's tangent construction puts the cam centre above the lowest roller centre (s₀ = {:.3} mm): the rays do not meet below the diagram",
                c.s0 * 1e3
            )));
        }
    }
    Ok(out)
}

/// The pressure angle at cam angle φ, signed: positive on the side that
/// drives the follower up (the book's `tan θ = (v_q − e_book)/(s₀ + S)` for a
/// clockwise cam), `atan2(s′ − σe, s₀ + s)`.
///
/// ```
/// use tmm_cams::{program::Program, spec, tangents::{Centre, signed_pressure}};
/// let prog = Program::new(0.02, spec::parse_phases("rise 180 cosine; return 180 cosine").unwrap()).unwrap();
/// let c = Centre { e: 0.01, s0: 0.04 };
/// // at φ = 0 the follower is still: only the offset tilts the normal
/// assert!((signed_pressure(&prog, 1.0, c, 0.0) - (-0.25f64).atan()).abs() < 1e-15);
/// ```
pub fn signed_pressure(prog: &Program, sigma: f64, c: Centre, phi: f64) -> f64 {
    let m = prog.eval(phi);
    (m.v - sigma * c.e).atan2(c.s0 + m.s)
}

/// The largest pressure angles |ϑ| on the rise and on the return at a centre
/// (both sides), rad.
pub fn pressure_at(prog: &Program, sigma: f64, c: Centre) -> (f64, f64) {
    pressure_extremes(prog, &c.mechanism(), sigma)
}
