//! Crank-rocker four-bar by the two extreme positions of its rocker with
//! the rocker's pivot D given (синтез кривошипно-коромыслового механизма по
//! крайним положениям коромысла), BMSTU textbook (Chernaya & Timofeev 2019),
//! appendix П1.2, and the same with K given and the frame's abscissa X_D
//! unknown, П1.3. Names as the book: crank AB (1) about A = (0, 0), coupler
//! BC (2), rocker DC (3) about D = (X_D, Y_D); γ is the direction of D→C.
//!
//! **Closed form (derived here, docs/synthesis.md § 14).** At an extreme
//! position of the rocker the crank and the coupler are collinear: at the
//! extended one ("н", B between A and C) |AC_н| = l1 + l2, at the folded one
//! ("к") |AC_к| = l2 − l1, with C_н,к = D + l3·(cos γ, sin γ). Hence
//!
//! l1 = (|AC_н| − |AC_к|)/2,  l2 = (|AC_н| + |AC_к|)/2,
//! φ1н = arg C_н,  θ = arg C_к − arg C_н
//!
//! — the book's four equations (p. 112–113) solved without a first guess.
//! With K given (П1.3) θ = π(K − 1)/(K + 1) and X_D is the root of the one
//! equation arg C_к(X_D) − arg C_н(X_D) = θ; every root lies within
//! 2R + 2·l3 + |Y_D| of the origin (R = |C_нC_к|/(2 sin θ), the circle of
//! points that see the chord at θ), so a scan of that range and Brent's
//! method find them all.

use std::f64::consts::PI;

use tmm_geom::Vec2;
use tmm_geom::angle::wrap_pi;
use tmm_geom::root::brent;

use crate::model::{AssemblyHint, HintKind, InputDef, LinkDef, MechanismDef};

use super::check::{ASSEMBLY_OFFSET, Expect, check_cycle, check_extremes, check_limits};
use super::error::{SynthesisError, finite, positive, show};
use super::limits::{Drive, Limits};
use super::pivot::polar;
use super::result::{CheckReport, Construction, FreeParameter, Kind, Stroke, Synthesis};
use super::time_ratio::theta_from_k;

/// What fixes the frame's abscissa.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Abscissa {
    /// X_D given, m (П1.2).
    Given(f64),
    /// K given, X_D unknown (П1.3).
    ByK(f64),
}

/// A request: the rocker's pivot ordinate, its length and its two extreme
/// angles, and X_D or K.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExtremesRequest {
    /// X_D or K.
    pub abscissa: Abscissa,
    /// Y_D, m.
    pub frame_y: f64,
    /// Rocker l3 = |DC|, m.
    pub rocker: f64,
    /// γн: the rocker's angle at the extended position (crank and coupler
    /// in line, B between A and C), rad.
    pub gamma_start: f64,
    /// γк: the rocker's angle at the folded position, rad.
    pub gamma_end: f64,
    /// Crank direction and speed.
    pub drive: Drive,
    /// Limits.
    pub limits: Limits,
}

/// The book's four-bar A-B-C-D: crank AB about A at the origin, coupler BC,
/// rocker DC about `d`, assembled at crank angle `phi` with C near `c_near`.
pub fn four_bar(d: Vec2, (l1, l2, l3): (f64, f64, f64), omega: f64, c_near: Vec2, phi: f64) -> MechanismDef {
    MechanismDef {
        fixed: vec![("A".into(), Vec2::ZERO), ("D".into(), d)],
        links: vec![
            LinkDef::bar("1", "A", "B", l1),
            LinkDef::bar("2", "B", "C", l2),
            LinkDef::bar("3", "D", "C", l3),
        ],
        input: Some(InputDef::crank("1", "A", "B", omega)),
        hints: vec![AssemblyHint {
            point: "C".into(),
            kind: HintKind::Near(c_near),
        }],
        assembly_angle: phi,
        output: Some("3".into()),
        ..Default::default()
    }
}

/// The closed form for a given D: (l1, l2, φ1н, θ, C_н, C_к).
fn closed_form(d: Vec2, l3: f64, g0: f64, g1: f64) -> (f64, f64, f64, f64, Vec2, Vec2) {
    let (c0, c1) = (d + polar(g0) * l3, d + polar(g1) * l3);
    let (a, b) = (c0.hypot(), c1.hypot());
    (0.5 * (a - b), 0.5 * (a + b), c0.atan2(), wrap_pi(c1.atan2() - c0.atan2()), c0, c1)
}

/// Why a four-bar by this D fails (None: it is a crank-rocker reaching both
/// extremes on one assembly branch).
fn invalid(d: Vec2, l3: f64, g0: f64, g1: f64) -> Option<String> {
    let (l1, l2, _, _, c0, c1) = closed_form(d, l3, g0, g1);
    if l1.is_nan() || l1 <= 0.0 {
        return Some(format!(
            "|AC_н| = {} m is not longer than |AC_к| = {} m, so the first position cannot be the extended one (l1 = (|AC_н| − |AC_к|)/2 ≤ 0)",
            show(l2 + l1),
            show(l2 - l1)
        ));
    }
    let f = d.hypot();
    let mut ls = [l1, l2, l3, f];
    ls.sort_by(f64::total_cmp);
    if !(ls[0] == l1 && ls[0] + ls[3] < ls[1] + ls[2]) {
        return Some(format!(
            "the crank l1 = {} m does not turn fully (Grashof: the crank must be the shortest link and l_min + l_max < the sum of the other two; l2 = {} m, l3 = {} m, |AD| = {} m)",
            show(l1),
            show(l2),
            show(l3),
            show(f)
        ));
    }
    let side = |c: Vec2| d.x * c.y - d.y * c.x;
    if side(c0) * side(c1) <= 0.0 {
        return Some(
            "C_н and C_к lie on the two sides of the frame line AD: they belong to two assembly branches, which the mechanism cannot both reach".into(),
        );
    }
    None
}

/// Every root X_D of arg C_к − arg C_н = θ (θ > 0) with the ordinate `yd`.
pub fn frame_abscissae(yd: f64, l3: f64, g0: f64, g1: f64, theta: f64) -> Vec<f64> {
    let g = |x: f64| {
        let d = Vec2::new(x, yd);
        let (c0, c1) = (d + polar(g0) * l3, d + polar(g1) * l3);
        wrap_pi(c1.atan2() - c0.atan2()) - theta
    };
    let chord = (polar(g1) - polar(g0)).hypot() * l3;
    let r = chord / (2.0 * theta.sin());
    let span = 2.0 * r + 2.0 * l3 + yd.abs();
    let n = 4000;
    let mut roots: Vec<f64> = Vec::new();
    let mut prev = (-span, g(-span));
    for i in 1..=n {
        let x = -span + 2.0 * span * i as f64 / n as f64;
        let v = g(x);
        // a sign change that is not the jump of arg by 2π where C passes A
        if v.is_finite() && prev.1.is_finite() && (v > 0.0) != (prev.1 > 0.0) && (v - prev.1).abs() < PI {
            if let Some(root) = brent(g, prev.0, x, 1e-15 * span.max(1.0)) {
                if g(root).abs() < 1e-9 && roots.iter().all(|q| (q - root).abs() > 1e-9 * span) {
                    roots.push(root);
                }
            }
        }
        prev = (x, v);
    }
    roots
}

/// Synthesise and check over the cycle.
///
/// ```
/// use tmm_linkage::synthesis::rocker_extremes::*;
/// // BMSTU textbook П1.2: D = (0.8, −0.1) m, l3 = 0.5 m, γн = 70°, γк = 130°
/// let s = synthesize(&ExtremesRequest { abscissa: Abscissa::Given(0.8), frame_y: -0.1, rocker: 0.5,
///     gamma_start: 70f64.to_radians(), gamma_end: 130f64.to_radians(),
///     drive: Default::default(), limits: Default::default() }).unwrap();
/// let (l1, l2) = (s.length("AB").unwrap(), s.length("BC").unwrap());
/// // |AC_н| = l1 + l2 at the extended position
/// let c = tmm_geom::Vec2::new(0.8 + 0.5 * 70f64.to_radians().cos(), -0.1 + 0.5 * 70f64.to_radians().sin());
/// assert!((l1 + l2 - c.hypot()).abs() < 1e-12);
/// ```
pub fn synthesize(r: &ExtremesRequest) -> Result<Synthesis, SynthesisError> {
    let yd = finite("frame_y", r.frame_y)?;
    let l3 = positive("rocker", r.rocker)?;
    let g0 = finite("gamma_start", r.gamma_start)?;
    let g1 = finite("gamma_end", r.gamma_end)?;
    r.limits.validate()?;
    let omega = r.drive.signed_omega()?;
    let swing = wrap_pi(g1 - g0).abs();
    if swing < 1e-9 {
        return Err(SynthesisError::input(
            "gamma_end",
            "the two extreme angles of the rocker must differ",
        ));
    }
    let (xd, free) = match r.abscissa {
        Abscissa::Given(x) => (finite("frame_x", x)?, None),
        Abscissa::ByK(k) => {
            let theta = theta_from_k(k)?;
            if theta <= 0.0 {
                return Err(SynthesisError::input(
                    "k",
                    "K = 1 puts the crank pivot A on the line C_нC_к, which does not fix X_D by an angle; give frame_x instead (kind rocker-extremes)",
                ));
            }
            let roots = frame_abscissae(yd, l3, g0, g1, theta);
            let mut notes = Vec::new();
            let mut best: Option<(f64, f64)> = None;
            for &x in &roots {
                let why = invalid(Vec2::new(x, yd), l3, g0, g1).or_else(|| match solve_at(r, Vec2::new(x, yd), omega) {
                    Ok(s) => {
                        let t = s.check.transmission_angle_min;
                        if best.is_none_or(|b| t > b.1) {
                            best = Some((x, t));
                        }
                        None
                    }
                    Err(e) => Some(e.to_string()),
                });
                notes.push(match why {
                    None => format!("X_D = {} m: a crank-rocker", show(x)),
                    Some(w) => format!("X_D = {} m: rejected, {w}", show(x)),
                });
            }
            let Some((x, _)) = best else {
                return Err(SynthesisError::infeasible(
                    "k",
                    format!(
                        "no frame abscissa X_D gives a crank-rocker with these extreme positions and θ = {:.4}°: {}",
                        theta.to_degrees(),
                        if notes.is_empty() {
                            "the equation has no root".into()
                        } else {
                            notes.join("; ")
                        }
                    ),
                    None,
                ));
            };
            let valid = notes.iter().filter(|n| !n.contains("rejected")).count();
            (
                x,
                Some(FreeParameter {
                    name: "frame abscissa X_D, m (the root of arg C_к − arg C_н = θ)".into(),
                    value: x,
                    reason: format!(
                        "{} root(s) in |X_D| ≤ 2R + 2 l3 + |Y_D|: {}; taken: {}",
                        roots.len(),
                        notes.join("; "),
                        if valid > 1 {
                            "the crank-rocker with the largest smallest transmission angle"
                        } else {
                            "the only crank-rocker"
                        }
                    ),
                }),
            )
        }
    };
    let d = Vec2::new(xd, yd);
    if let Some(why) = invalid(d, l3, g0, g1) {
        let field = if matches!(r.abscissa, Abscissa::Given(_)) { "frame_x" } else { "k" };
        return Err(SynthesisError::infeasible(field, why, None));
    }
    let mut s = solve_at(r, d, omega)?;
    s.free_parameter = free;
    if matches!(r.abscissa, Abscissa::ByK(_)) {
        s.coordinates.push(("X_D".into(), xd));
    }
    Ok(s)
}

/// The mechanism for a frame point D (valid by [`invalid`]), checked.
fn solve_at(r: &ExtremesRequest, d: Vec2, omega: f64) -> Result<Synthesis, SynthesisError> {
    let (l3, g0, g1) = (r.rocker, r.gamma_start, r.gamma_end);
    let (l1, l2, phi0, theta, c0, c1) = closed_form(d, l3, g0, g1);
    let swing = wrap_pi(g1 - g0).abs();
    let k = (PI + theta.abs()) / (PI - theta.abs());
    let def = four_bar(d, (l1, l2, l3), omega, c0, phi0 + ASSEMBLY_OFFSET);
    let side = if d.x * c0.y - d.y * c0.x > 0.0 { "left of" } else { "right of" };
    let check: CheckReport = check_cycle(
        &def,
        &Expect {
            k: Some(k),
            stroke: Some(Stroke::Angular(swing)),
        },
        &format!("C {side} the frame line A→D"),
    )?;
    check_limits(&r.limits, &check)?;
    check_extremes(&check, "C", [c0, c1])?;
    let mut given = Vec::new();
    match r.abscissa {
        Abscissa::Given(x) => given.push(("frame_x".to_string(), x)),
        Abscissa::ByK(kk) => given.push(("k".to_string(), kk)),
    }
    given.extend([
        ("frame_y".to_string(), r.frame_y),
        ("rocker".to_string(), l3),
        ("gamma_start".to_string(), g0),
        ("gamma_end".to_string(), g1),
    ]);
    Ok(Synthesis {
        kind: Kind::CrankRocker,
        given,
        lengths: vec![("AB".into(), l1), ("BC".into(), l2), ("DC".into(), l3), ("AD".into(), d.hypot())],
        frame: def.fixed.clone(),
        k,
        theta: theta.abs(),
        stroke: Some(Stroke::Angular(swing)),
        free_parameter: None,
        construction: Construction {
            point: "C".into(),
            extremes: [c0, c1],
            locus: None,
            pivot: Vec2::ZERO,
            lines: vec![("rocker's swing".into(), c0, c1)],
        },
        def,
        check,
        angles: vec![("phi1_start".into(), phi0), ("theta".into(), theta)],
        coordinates: vec![],
        shown: vec![],
    })
}
