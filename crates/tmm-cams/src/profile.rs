//! The cam profile by kinematic inversion (метод обращения движения): the
//! theoretical (pitch, центровой) and working (practical, рабочий) profiles
//! as dense point lists in the cam's own frame, the radius of curvature along
//! the working profile, the pressure angle over the cycle, and the exact
//! extremes of both.
//!
//! Curvature of a parametric curve: `κ = (x′y″ − y′x″)/|X′|³` (any calculus
//! text, e.g. Korn & Korn, *Mathematical Handbook*, ch. 17). The working
//! profile of a roller is the inner offset of the pitch curve, so its radius is
//! `ρ_w = ρ_p − r_roller` (signed, positive where convex); a convex pitch arc
//! with `ρ_p < r_roller` gives a looped, undercut profile (подрезание). A flat
//! face's profile is the envelope of its lines `n(α)·X = p`, with
//! `ρ = p + d²p/dα²` (support-function form; for a translating face this is
//! Geronimus' `r₀ + s + s″`; docs/cams.md §5).

use crate::extreme::{maximize, minimize};
use crate::mechanism::{Mechanism, quarter, rotate};
use crate::program::{Motion, PhaseKind, Program};
use tmm_geom::Vec2;

/// Derivatives of the pitch curve as seen from the cam, expressed in the frame
/// orientation (curvature does not depend on the rotation).
#[inline]
pub fn pitch_derivatives(mech: &Mechanism, m: &Motion, sigma: f64) -> (Vec2, Vec2) {
    let j = mech.frame_point(m);
    let d1 = j.d1 - quarter(j.p) * sigma;
    let d2 = j.d2 - quarter(j.d1) * (2.0 * sigma) - j.p;
    (d1, d2)
}

/// Curvature of the pitch curve, positive where it is convex (bulges away from
/// the cam centre).
#[inline]
pub fn pitch_curvature(mech: &Mechanism, m: &Motion, sigma: f64) -> f64 {
    let (d1, d2) = pitch_derivatives(mech, m, sigma);
    let h = d1.hypot();
    // the cam-frame curve runs clockwise for σ = +1: orientation −σ
    -sigma * tmm_geom::cross(d1, d2) / (h * h * h)
}

/// Radius of curvature of a flat face's working profile (positive convex).
#[inline]
pub fn flat_rho(mech: &Mechanism, m: &Motion, sigma: f64) -> f64 {
    let l = mech.frame_line(m);
    let a1 = l.alpha[1] - sigma;
    let a2 = l.alpha[2];
    l.p[0] + (l.p[2] * a1 - l.p[1] * a2) / (a1 * a1 * a1)
}

/// Smallest radius of curvature of a flat face's working profile over the
/// cycle, searched on every smooth piece.
pub fn min_flat_rho(prog: &Program, mech: &Mechanism, sigma: f64, scan: usize) -> f64 {
    over_pieces(prog, scan / prog.phases().len().max(1), |m| flat_rho(mech, m, sigma), false)
}

/// Extreme (max with `max = true`, else min) of `f(motion)` over the cycle,
/// searched piece by piece (phases and the joints inside a law), both sides of
/// every joint included.
pub fn over_pieces(prog: &Program, scan: usize, mut f: impl FnMut(&Motion) -> f64, max: bool) -> f64 {
    let mut best = if max { f64::NEG_INFINITY } else { f64::INFINITY };
    for (k, ph) in prog.phases().iter().enumerate() {
        let mut cuts = vec![0.0];
        if let Some(l) = &ph.law {
            cuts.extend(l.breaks().into_iter().map(|x| x * ph.angle));
        }
        cuts.push(ph.angle);
        for w in cuts.windows(2) {
            let mut g = |x: f64| f(&prog.eval_in(k, x));
            let v = if max {
                maximize(&mut g, w[0], w[1], scan.max(8)).1
            } else {
                minimize(&mut g, w[0], w[1], scan.max(8)).1
            };
            let (ga, gb) = (g(w[0]), g(w[1]));
            best = if max {
                best.max(v).max(ga).max(gb)
            } else {
                best.min(v).min(ga).min(gb)
            };
        }
    }
    best
}

/// The largest pressure angle on the rises and on the returns, rad.
pub fn pressure_extremes(prog: &Program, mech: &Mechanism, sigma: f64) -> (f64, f64) {
    let (mut rise, mut ret) = (0.0f64, 0.0f64);
    for (k, ph) in prog.phases().iter().enumerate() {
        if ph.kind == PhaseKind::Dwell {
            continue;
        }
        let (_, m) = maximize(|x| mech.pressure_angle(&prog.eval_in(k, x), sigma), 0.0, ph.angle, 256);
        let ends = mech
            .pressure_angle(&prog.eval_in(k, 0.0), sigma)
            .max(mech.pressure_angle(&prog.eval_in(k, ph.angle), sigma));
        let m = m.max(ends);
        if ph.kind == PhaseKind::Rise {
            rise = rise.max(m);
        } else {
            ret = ret.max(m);
        }
    }
    (rise, ret)
}

/// The cam's profile over one turn at `n` equal steps of the cam angle.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Profile {
    /// Cam angle φ, rad.
    pub phi: Vec<f64>,
    /// Follower motion at φ (displacement and analogs).
    pub motion: Vec<Motion>,
    /// Theoretical (pitch) profile in the cam frame, m.
    pub pitch: Vec<Vec2>,
    /// Working profile in the cam frame, m.
    pub working: Vec<Vec2>,
    /// Signed curvature of the working profile, 1/m (positive convex).
    pub curvature: Vec<f64>,
    /// Pressure angle, rad (magnitude).
    pub pressure: Vec<f64>,
}

impl Profile {
    /// Evaluate the profile at `n` points (allocates the arrays once; the loop
    /// allocates nothing).
    pub fn new(prog: &Program, mech: &Mechanism, sigma: f64, n: usize) -> Self {
        let mut p = Profile {
            phi: Vec::with_capacity(n),
            motion: Vec::with_capacity(n),
            pitch: Vec::with_capacity(n),
            working: Vec::with_capacity(n),
            curvature: Vec::with_capacity(n),
            pressure: Vec::with_capacity(n),
        };
        let r = mech.roller();
        for i in 0..n {
            let phi = std::f64::consts::TAU * i as f64 / n as f64;
            let m = prog.eval(phi);
            let back = -sigma * phi;
            let jet = mech.frame_point(&m);
            let pitch = rotate(jet.p, back);
            let (work, curv) = if mech.is_flat() {
                let c = mech.contact_frame(&m, sigma);
                (rotate(c, back), 1.0 / flat_rho(mech, &m, sigma))
            } else {
                let (d1, _) = pitch_derivatives(mech, &m, sigma);
                let kp = pitch_curvature(mech, &m, sigma);
                // inward normal: for the clockwise (σ = +1) cam-frame curve it is −J·T̂
                let nin = rotate(quarter(d1) * (-sigma / d1.hypot()), back);
                (pitch + nin * r, kp / (1.0 - r * kp))
            };
            p.phi.push(phi);
            p.motion.push(m);
            p.pitch.push(pitch);
            p.working.push(work);
            p.curvature.push(curv);
            p.pressure.push(mech.pressure_angle(&m, sigma));
        }
        p
    }
}
