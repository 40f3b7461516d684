//! Lever driven by an oscillating (rocking) cylinder (механизм с качающимся
//! гидро- или пневмоцилиндром), BMSTU textbook (Chernaya & Timofeev 2019),
//! appendix П1.5: the lever OB about O = (0, 0), the cylinder pivoted at
//! D = (X_D, Y_D), the piston rod pinned to the lever at B, |DB| = h + l_шт
//! (h: from D to the piston, h_min … h_max; l_шт: the rod). The lever turns
//! counter-clockwise by β from the initial position (h_min, lever angle φ1)
//! to the final one (h_max, φ1 + β). Pressure angle at B, the angle between
//! B's velocity and the rod's force: θ = (lever angle + π/2) − φ3, φ3 the
//! direction D→B.
//!
//! **Closed form (derived here, docs/synthesis.md § 16).** Held in the frame
//! of the lever at the position g where the pressure angle θ_g is given
//! (B at (l1, 0)), D = (l1 − s_g sin θ_g, −s_g cos θ_g), s_g = |DB| there.
//! At the other position o the lever has turned by δ (−β from the final to
//! the initial, +β the other way), so D seen from the lever is R(−δ)·D and
//! |R(−δ)·D − (l1, 0)| = s_o, a quadratic in l1:
//!
//! 4 sin²(β/2)·l1² − 2 [p (1 − cos δ) − q sin δ]·l1 + s_g² − s_o² = 0,
//! p = s_g sin θ_g, q = s_g cos θ_g.
//!
//! Given θ at the final position (s_g > s_o) it has two positive roots or
//! none; at the initial position one. |OD| and both pressure angles follow
//! from l1; the five equations of the book leave the configuration's turn
//! about O free (variants 2, 3), which Y_D fixes: D = |OD|·e^{iα} with
//! sin α = Y_D/|OD| (X_D ≥ 0 taken, the book's guess X_D = 2 h_max > 0).
//!
//! The [`MechanismDef`] takes the lever as the input crank: the piston rod
//! is a slider block at B on a guide of the cylinder, a bar D–E turning
//! about D (E: the cylinder's far end, h_max from D along its axis); the
//! working range is φ1 … φ1 + β only.

use std::f64::consts::{FRAC_PI_2, PI};

use tmm_geom::Vec2;
use tmm_geom::angle::wrap_pi;

use crate::mechanism::Mechanism;
use crate::model::{AssemblyHint, HintKind, InputDef, LinkDef, MechanismDef, SliderDef};

use super::check::check_limits;
use super::error::{SynthesisError, finite, positive, show};
use super::limits::{Drive, Limits};
use super::pivot::polar;
use super::result::{CheckReport, Construction, FreeParameter, Kind, Stroke, Synthesis};

/// Where the pressure angle is given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PressureAt {
    /// θн at the initial position (h_min), rad (variant 3).
    Start(f64),
    /// θк at the final position (h_max), rad (variants 1, 2).
    End(f64),
}

/// A request (П1.5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CylinderRequest {
    /// h_min, m (D to the piston at the initial position).
    pub h_min: f64,
    /// h_max, m.
    pub h_max: f64,
    /// The rod l_шт, m.
    pub rod: f64,
    /// The lever's turn β, rad, in (0, π).
    pub swing: f64,
    /// The pressure-angle condition.
    pub pressure: PressureAt,
    /// Y_D, m; `None`: left free, D put on +x (Y_D = 0).
    pub frame_y: Option<f64>,
    /// Lever speed and direction of the generated mechanism (the lever turns
    /// counter-clockwise from the initial position to the final one).
    pub drive: Drive,
    /// Limits on the largest pressure angle over the travel.
    pub limits: Limits,
}

/// One solution of the quadratic, placed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placed {
    /// Lever l1 = |OB|, m.
    pub l1: f64,
    /// The cylinder's pivot D, m.
    pub d: Vec2,
    /// The lever's initial angle φ1, rad.
    pub phi1: f64,
    /// Directions of D→B at the initial and final positions, rad.
    pub phi3: (f64, f64),
    /// Pressure angles θн, θк, rad.
    pub theta: (f64, f64),
}

/// The roots l1 > 0 of the quadratic, each placed with D at angle `alpha`
/// from O (rad).
pub fn solutions(s0: f64, s1: f64, beta: f64, at: PressureAt, alpha: impl Fn(f64) -> Option<f64>) -> Vec<Placed> {
    let (sg, so, delta, th) = match at {
        PressureAt::End(t) => (s1, s0, -beta, t),
        PressureAt::Start(t) => (s0, s1, beta, t),
    };
    let (p, q) = (sg * th.sin(), sg * th.cos());
    let a = 4.0 * (0.5 * beta).sin().powi(2);
    let b = p * (1.0 - delta.cos()) - q * delta.sin();
    let c = sg * sg - so * so;
    let disc = b * b - a * c;
    if disc.is_nan() || disc < 0.0 || a <= 0.0 {
        return vec![];
    }
    let mut out = Vec::new();
    for l1 in [(b - disc.sqrt()) / a, (b + disc.sqrt()) / a] {
        if l1.is_nan() || l1 <= 0.0 || out.iter().any(|x: &Placed| x.l1 == l1) {
            continue;
        }
        let dg = Vec2::new(l1 - p, -q);
        let od = dg.hypot();
        let Some(al) = alpha(od) else { continue };
        let phig = al - dg.atan2();
        let phi1 = match at {
            PressureAt::End(_) => phig - beta,
            PressureAt::Start(_) => phig,
        };
        let d = polar(al) * od;
        let (b0, b1) = (polar(phi1) * l1, polar(phi1 + beta) * l1);
        let (f0, f1) = ((b0 - d).atan2(), (b1 - d).atan2());
        out.push(Placed {
            l1,
            d,
            phi1: wrap_pi(phi1),
            phi3: (f0, f1),
            theta: (wrap_pi(phi1 + FRAC_PI_2 - f0), wrap_pi(phi1 + beta + FRAC_PI_2 - f1)),
        });
    }
    out
}

/// The lever with the cylinder: lever OB (1) as the input crank, piston rod
/// (2) a block at B sliding on the cylinder (3), a bar from its pivot D to
/// its far end E at `h_max` along the axis D→B, assembled at lever angle
/// `phi`.
pub fn mechanism(l1: f64, d: Vec2, h_max: f64, omega: f64, phi: f64) -> MechanismDef {
    let b = polar(phi) * l1;
    let e = d + (b - d) * (h_max / (b - d).hypot());
    MechanismDef {
        slider_input: None,
        fixed: vec![("O".into(), Vec2::ZERO), ("D".into(), d)],
        links: vec![
            LinkDef::bar("1", "O", "B", l1),
            LinkDef::block("2", "B"),
            LinkDef::bar("3", "D", "E", h_max),
        ],
        sliders: vec![SliderDef {
            slider: "2".into(),
            point: "B".into(),
            guide_link: "3".into(),
            through: Vec2::ZERO,
            angle: 0.0,
            angle_on_slider: 0.0,
        }],
        input: Some(InputDef::crank("1", "O", "B", omega)),
        hints: vec![AssemblyHint {
            point: "E".into(),
            kind: HintKind::Near(e),
        }],
        assembly_angle: phi,
        output: Some("3".into()),
    }
}

/// Synthesise and check by the linkage core over the lever's travel.
///
/// ```
/// use tmm_linkage::synthesis::cylinder::*;
/// // BMSTU textbook П1.5, variant 1
/// let s = synthesize(&CylinderRequest { h_min: 0.05, h_max: 0.3, rod: 0.39, swing: 60f64.to_radians(),
///     pressure: PressureAt::End(50f64.to_radians()), frame_y: Some(0.05),
///     drive: Default::default(), limits: Default::default() }).unwrap();
/// assert!((s.frame[1].1.y - 0.05).abs() < 1e-12);
/// ```
pub fn synthesize(r: &CylinderRequest) -> Result<Synthesis, SynthesisError> {
    let h0 = positive("h_min", r.h_min)?;
    let h1 = positive("h_max", r.h_max)?;
    let rod = positive("rod", r.rod)?;
    let beta = positive("swing", r.swing)?;
    if h1 <= h0 {
        return Err(SynthesisError::input("h_max", "h_max must be larger than h_min"));
    }
    if beta >= PI {
        return Err(SynthesisError::input("swing", "the lever's turn β must be less than 180°"));
    }
    let (field, th) = match r.pressure {
        PressureAt::Start(t) => ("pressure_start", finite("pressure_start", t)?),
        PressureAt::End(t) => ("pressure_end", finite("pressure_end", t)?),
    };
    if th.abs() >= FRAC_PI_2 {
        return Err(SynthesisError::input(field, "the pressure angle must lie within ±90°"));
    }
    let yd = match r.frame_y {
        Some(y) => Some(finite("frame_y", y)?),
        None => None,
    };
    r.limits.validate()?;
    let omega = r.drive.signed_omega()?;
    let (s0, s1) = (h0 + rod, h1 + rod);
    // every root, with D placed at X_D ≥ 0
    let alpha = |od: f64| match yd {
        None => Some(0.0),
        Some(y) if y.abs() <= od => Some((y / od).asin()),
        Some(_) => None,
    };
    let all = solutions(s0, s1, beta, r.pressure, |_| Some(0.0));
    if all.is_empty() {
        return Err(SynthesisError::infeasible(
            field,
            format!(
                "no lever turns by {:.4}° while |DB| goes from {} m to {} m with this pressure angle (the quadratic in l1 has no positive root)",
                beta.to_degrees(),
                show(s0),
                show(s1)
            ),
            None,
        ));
    }
    let placed = solutions(s0, s1, beta, r.pressure, alpha);
    let worst = |p: &Placed| p.theta.0.abs().max(p.theta.1.abs());
    let mut notes = Vec::new();
    let mut best: Option<Placed> = None;
    for p in &all {
        let od = p.d.hypot();
        let mine = placed.iter().find(|q| q.l1 == p.l1);
        let why = if worst(p) >= FRAC_PI_2 {
            Some(format!(
                "rejected: a pressure angle of {:.4}° (θн = {:.4}°, θк = {:.4}°) — the rod would pull against the lever's motion",
                worst(p).to_degrees(),
                p.theta.0.to_degrees(),
                p.theta.1.to_degrees()
            ))
        } else if mine.is_none() {
            Some(format!("rejected: |Y_D| > |OD| = {} m", show(od)))
        } else {
            None
        };
        notes.push(format!(
            "l1 = {} m, |OD| = {} m{}",
            show(p.l1),
            show(od),
            why.as_ref().map_or(String::new(), |w| format!(", {w}"))
        ));
        if let (None, Some(q)) = (why, mine) {
            if best.is_none_or(|b| worst(q) < worst(&b)) {
                best = Some(*q);
            }
        }
    }
    let Some(p) = best else {
        let (fld, nearest) = match (
            yd,
            all.iter().filter(|p| worst(p) < FRAC_PI_2).map(|p| p.d.hypot()).reduce(f64::max),
        ) {
            (Some(y), Some(od)) if y.abs() > od => ("frame_y", Some(y.signum() * od * (1.0 - 1e-9))),
            _ => (field, None),
        };
        return Err(SynthesisError::infeasible(
            fld,
            format!("no solution places the cylinder: {}", notes.join("; ")),
            nearest,
        ));
    };
    // the check: the linkage core solves the mechanism over the lever's
    // travel; |DB| must run from s0 to s1 monotonically and the pressure
    // angles computed from its positions must be the construction's
    let def = mechanism(p.l1, p.d, h1, omega, p.phi1);
    let m = Mechanism::new(&def)?;
    let mut sol = m.solution();
    let (ib, id) = (
        m.point("B").ok_or_else(|| SynthesisError::Check("no point B".into()))?,
        m.point("D").ok_or_else(|| SynthesisError::Check("no point D".into()))?,
    );
    let n = 180;
    let mut prev = f64::NEG_INFINITY;
    let mut tmax = 0.0f64;
    let mut ends = [(0.0, 0.0); 2];
    for k in 0..=n {
        let phi = p.phi1 + beta * k as f64 / n as f64;
        m.solve(phi, &mut sol)?;
        let (b, d) = (sol.points[ib].p, sol.points[id].p);
        let s = (b - d).hypot();
        let th = wrap_pi(phi + FRAC_PI_2 - (b - d).atan2());
        if s <= prev {
            return Err(SynthesisError::infeasible(
                field,
                format!(
                    "the rod does not extend monotonically over the lever's turn: |DB| stops growing at {:.4}° of it",
                    (beta * k as f64 / n as f64).to_degrees()
                ),
                None,
            ));
        }
        prev = s;
        tmax = tmax.max(th.abs());
        if k == 0 {
            ends[0] = (s, th);
        }
        if k == n {
            ends[1] = (s, th);
        }
    }
    let tol = 1e-9 * s1;
    if (ends[0].0 - s0).abs() > tol || (ends[1].0 - s1).abs() > tol {
        return Err(SynthesisError::Check(format!(
            "|DB| found {:.12} m … {:.12} m, {s0:.12} m … {s1:.12} m requested",
            ends[0].0, ends[1].0
        )));
    }
    let want = match r.pressure {
        PressureAt::Start(t) => (ends[0].1, t),
        PressureAt::End(t) => (ends[1].1, t),
    };
    if (want.0 - want.1).abs() > 1e-9 {
        return Err(SynthesisError::Check(format!(
            "pressure angle {:.9}° found, {:.9}° requested",
            want.0.to_degrees(),
            want.1.to_degrees()
        )));
    }
    let check = CheckReport {
        k: None,
        theta: None,
        stroke: Some(Stroke::Linear(ends[1].0 - ends[0].0)),
        pressure_angle_max: (tmax, tmax),
        transmission_angle_min: FRAC_PI_2 - tmax,
        crank_turns_fully: false,
        branch: "the lever turns counter-clockwise by β from h_min to h_max".into(),
        dead_phi: vec![],
        dead_positions: vec![],
    };
    check_limits(&r.limits, &check)?;
    let od = p.d.hypot();
    let variant = match (r.pressure, yd) {
        (PressureAt::End(_), Some(_)) => "Y_D given (variant 1)",
        (PressureAt::End(_), None) => "Y_D free (variant 2): D put on +x",
        (PressureAt::Start(_), Some(_)) => "Y_D given for the free turn about O (variant 3)",
        (PressureAt::Start(_), None) => "Y_D free (variant 3): D put on +x",
    };
    let mut given = vec![
        ("h_min".to_string(), h0),
        ("h_max".to_string(), h1),
        ("rod".to_string(), rod),
        ("swing".to_string(), beta),
        (field.to_string(), th),
    ];
    if let Some(y) = yd {
        given.push(("frame_y".into(), y));
    }
    let (b0, b1) = (polar(p.phi1) * p.l1, polar(p.phi1 + beta) * p.l1);
    Ok(Synthesis {
        kind: Kind::OscillatingCylinder,
        given,
        lengths: vec![
            ("OB".into(), p.l1),
            ("OD".into(), od),
            ("DB_start".into(), s0),
            ("DB_end".into(), s1),
        ],
        frame: def.fixed.clone(),
        k: 1.0,
        theta: 0.0,
        stroke: Some(Stroke::Linear(h1 - h0)),
        free_parameter: Some(FreeParameter {
            name: "Y_D, m: the turn of the whole configuration about O".into(),
            value: p.d.y,
            reason: format!(
                "{variant}. The pressure-angle condition and the four loop equations leave the turn about O free: l1, |OD| and both pressure angles do not depend on it; the family is D = |OD|·(cos α, sin α), φ1 = α {:+.4}°, φ3н = α {:+.4}°, φ3к = α {:+.4}°. Roots of the quadratic in l1: {}; taken: the one with the smaller largest pressure angle, X_D ≥ 0 (the other sign of X_D is the same family turned)",
                wrap_pi(p.phi1 - p.d.atan2()).to_degrees(),
                wrap_pi(p.phi3.0 - p.d.atan2()).to_degrees(),
                wrap_pi(p.phi3.1 - p.d.atan2()).to_degrees(),
                notes.join("; ")
            ),
        }),
        construction: Construction {
            point: "B".into(),
            extremes: [b0, b1],
            locus: None,
            pivot: Vec2::ZERO,
            lines: vec![("cylinder axis, initial".into(), p.d, b0), ("cylinder axis, final".into(), p.d, b1)],
        },
        def,
        check,
        angles: vec![
            ("phi1".into(), p.phi1),
            ("phi3_start".into(), p.phi3.0),
            ("phi3_end".into(), p.phi3.1),
            ("theta_start".into(), p.theta.0),
            ("theta_end".into(), p.theta.1),
        ],
        coordinates: vec![("X_D".into(), p.d.x), ("Y_D".into(), p.d.y)],
        shown: vec![p.phi1, p.phi1 + beta],
    })
}
