//! Crank-knee press with a bell-crank rocker (кривошипно-коленный пресс с
//! двуплечим коромыслом), seed 002, example 2 read literally: the data
//! l_BC = l_CD = 0.22 m, l_BC/l_BD = 2, l_DF = 0.2 m describe a rigid rocker
//! B–C–D turning about C (the triangle with sides CB, CD and BD), whose arm
//! CD and the link DF form the knee that pushes the slide F along the
//! vertical through C, while the four-bar O-A-B-C (crank OA, coupler AB)
//! drives the rocker at B.
//!
//! Stage 1 (as [`super::knee_press`] with the knee C–D–F): F is lowest with
//! CD at δ from the straight line CF; depth(β) = l_CD cos β +
//! √(l_DF² − l_CD² sin² β) falls monotonically on [0, min(90°, arcsin(l_DF/l_CD))],
//! so the upper extreme β″ is the root of depth(δ) − depth(β″) = H_F.
//! Stage 2: B is D turned about C by the bell crank's angle
//! ∠DCB = 2·arcsin(l_BD/(2 l_CB)) towards the crank pivot's side, so B′, B″
//! follow from D′, D″, and the crank pivot lies on the inscribed-angle locus of
//! B′B″ at θ ([`super::pivot`]), fixed by its horizontal distance from C
//! (the seed's l^x_CO) or another condition, among the pivots whose slower
//! (working) stroke is the pressing one.
//!
//! Placement: C at the origin, the guide vertical, F below C, the knee D
//! on the left (β from the downward vertical towards −x), the arm B turned
//! from D counter-clockwise, the crank pivot on the right. Names: crank OA
//! (1), coupler AB (2), bell crank B–C–D (3), link DF (4), slide F (5).

use std::f64::consts::FRAC_PI_2;

use tmm_geom::Vec2;
use tmm_geom::root::brent;

use crate::model::{AssemblyHint, HintKind, InputDef, LinkDef, MechanismDef, SliderDef};

use super::check::{ASSEMBLY_OFFSET, Expect, check_cycle, check_extremes, check_limits};
use super::error::{SynthesisError, finite, positive, show};
use super::knee_press::KneePivot;
use super::limits::{Drive, Limits};
use super::locus::Locus;
use super::pivot::{PivotCondition, choose};
use super::result::{Construction, FreeParameter, Kind, Stroke, Synthesis};
use super::time_ratio::theta_from_k;

/// A bell-crank knee-press request.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BellKneeRequest {
    /// Stroke of the slide H_F, m.
    pub stroke: f64,
    /// K ≥ 1.
    pub k: f64,
    /// The knee's arm l_CD, m.
    pub knee: f64,
    /// The knee's link l_DF, m.
    pub link: f64,
    /// The bell crank's arm l_CB to the coupler, m.
    pub arm: f64,
    /// The bell crank's side l_BD, m (seed 002: l_BC/l_BD = 2).
    pub chord: f64,
    /// Angle δ of CD from the line CF at the bottom, rad (> 0).
    pub delta: f64,
    /// The crank pivot's condition.
    pub pivot: KneePivot,
    /// Crank direction and speed.
    pub drive: Drive,
    /// Limits.
    pub limits: Limits,
}

/// Depth of F below C with CD at β from the downward vertical.
fn depth(l: f64, lf: f64, beta: f64) -> f64 {
    l * beta.cos() + (lf * lf - (l * beta.sin()).powi(2)).max(0.0).sqrt()
}

/// Synthesise and check.
///
/// ```
/// use tmm_linkage::synthesis::knee_bell_crank::*;
/// use tmm_linkage::synthesis::knee_press::KneePivot;
/// // seed 002, example 2, every given used
/// let s = synthesize(&BellKneeRequest { stroke: 0.09, k: 1.12, knee: 0.22, link: 0.2, arm: 0.22,
///     chord: 0.11, delta: 5f64.to_radians(), pivot: KneePivot::Horizontal(0.28),
///     drive: Default::default(), limits: Default::default() }).unwrap();
/// assert!((s.check.k.unwrap() - 1.12).abs() < 1e-9);
/// ```
pub fn synthesize(r: &BellKneeRequest) -> Result<Synthesis, SynthesisError> {
    let h = positive("stroke", r.stroke)?;
    let theta = theta_from_k(r.k)?;
    let l = positive("knee", r.knee)?;
    let lf = positive("link", r.link)?;
    let lb = positive("arm", r.arm)?;
    let bd = positive("chord", r.chord)?;
    let delta = finite("delta", r.delta)?;
    r.limits.validate()?;
    let omega = r.drive.signed_omega()?;
    if !(delta > 0.0 && delta < FRAC_PI_2) {
        return Err(SynthesisError::input(
            "delta",
            "the knee's angle from the straight line at the bottom must lie in (0°, 90°): at 0° the slide's dead position would not be the rocker's",
        ));
    }
    if bd >= 2.0 * lb {
        return Err(SynthesisError::input(
            "chord",
            format!(
                "the bell crank's side l_BD = {} m must be shorter than 2·l_CB = {} m (a triangle B–C–D)",
                show(bd),
                show(2.0 * lb)
            ),
        ));
    }
    let gamma = 2.0 * (0.5 * bd / lb).asin();
    let top = if lf >= l { FRAC_PI_2 } else { (lf / l).asin() };
    let f0 = depth(l, lf, delta);
    let h_max = f0 - depth(l, lf, top);
    if top <= delta || h >= h_max {
        return Err(SynthesisError::infeasible(
            "stroke",
            format!(
                "the knee lifts the slide by less than {} m from δ = {:.4}° while CD stays within 90° of the line CF",
                show(h_max.max(0.0)),
                delta.to_degrees()
            ),
            Some(h_max.max(0.0) * (1.0 - 1e-6)),
        ));
    }
    let beta2 = brent(|b| f0 - depth(l, lf, b) - h, delta, top, 1e-15)
        .ok_or_else(|| SynthesisError::Check("no angle of the knee gives this stroke".into()))?;
    // D on the left of the guide, B turned from D counter-clockwise by γ
    let dpos = |b: f64| Vec2::new(-b.sin(), -b.cos()) * l;
    let bpos = |b: f64| {
        let a = b - gamma;
        Vec2::new(-a.sin(), -a.cos()) * lb
    };
    let (d1, d2) = (dpos(delta), dpos(beta2));
    let (b1, b2) = (bpos(delta), bpos(beta2));
    let c = Vec2::ZERO;
    let locus = Locus::new(b1, b2, theta)?;
    let (cond, field) = match r.pivot {
        KneePivot::Horizontal(x) => (
            PivotCondition::OnLine {
                point: Vec2::new(finite("pivot.horizontal", x)?, 0.0),
                dir: Vec2::new(0.0, 1.0),
            },
            "pivot.horizontal",
        ),
        KneePivot::Crank(a) => (PivotCondition::CrankLength(positive("pivot.crank", a)?), "pivot.crank"),
        KneePivot::Frame(f) => (PivotCondition::FrameDistance(positive("pivot.frame", f)?), "pivot.frame"),
        KneePivot::Optimum => (PivotCondition::Optimum, "pivot.optimum"),
    };
    let choice = match choose(locus, c, omega.signum(), cond, &r.limits, field, Some(b1)) {
        Err(SynthesisError::Infeasible { field, condition, nearest }) if matches!(r.pivot, KneePivot::Horizontal(_)) => {
            let x0 = if let KneePivot::Horizontal(x) = r.pivot { x } else { 0.0 };
            return Err(SynthesisError::Infeasible {
                field,
                condition,
                nearest: nearest.map(|g| x0 - g),
            });
        }
        other => other?,
    };
    let b = choice.bar;
    // the bell crank's local frame: C at the origin, x-axis towards D
    let b_local = Vec2::new(gamma.cos(), gamma.sin()) * lb;
    let fpos = |dd: Vec2| Vec2::new(0.0, dd.y - (lf * lf - dd.x * dd.x).max(0.0).sqrt());
    // D where B is at the extended position (B turned back by γ about C)
    let d_ext = {
        let (s, co) = (-gamma).sin_cos();
        let v = b.c_ext * (l / lb);
        Vec2::new(co * v.x - s * v.y, s * v.x + co * v.y)
    };
    let def = MechanismDef {
        slider_input: None,
        fixed: vec![("C".into(), c), ("O".into(), b.o)],
        links: vec![
            LinkDef::bar("1", "O", "A", b.l1),
            LinkDef::bar("2", "A", "B", b.l2),
            LinkDef {
                name: "3".into(),
                points: vec![("C".into(), Vec2::ZERO), ("D".into(), Vec2::new(l, 0.0)), ("B".into(), b_local)],
                mass_center: Vec2::ZERO,
            },
            LinkDef::bar("4", "D", "F", lf),
            LinkDef::block("5", "F"),
        ],
        sliders: vec![SliderDef {
            slider: "5".into(),
            point: "F".into(),
            guide_link: crate::model::FRAME.into(),
            through: c,
            angle: FRAC_PI_2,
            angle_on_slider: 0.0,
        }],
        input: Some(InputDef::crank("1", "O", "A", omega)),
        hints: vec![
            AssemblyHint {
                point: "B".into(),
                kind: HintKind::Near(b.c_ext),
            },
            AssemblyHint {
                point: "F".into(),
                kind: HintKind::Near(fpos(d_ext)),
            },
        ],
        assembly_angle: b.phi_ext + ASSEMBLY_OFFSET,
        output: Some("5".into()),
    };
    let check = check_cycle(
        &def,
        &Expect {
            k: Some(r.k),
            stroke: Some(Stroke::Linear(h)),
        },
        "B on the side of the crank pivot, D on the other, F below C",
    )?;
    check_limits(&r.limits, &check)?;
    check_extremes(&check, "B", [b1, b2])?;
    check_extremes(&check, "D", [d1, d2])?;
    Ok(Synthesis {
        kind: Kind::KneePress,
        given: vec![
            ("stroke".into(), h),
            ("k".into(), r.k),
            ("knee".into(), l),
            ("link".into(), lf),
            ("arm".into(), lb),
            ("chord".into(), bd),
            ("delta".into(), delta),
        ],
        lengths: vec![
            ("OA".into(), b.l1),
            ("AB".into(), b.l2),
            ("CB".into(), lb),
            ("CD".into(), l),
            ("BD".into(), bd),
            ("DF".into(), lf),
            ("OC".into(), b.frame),
        ],
        frame: def.fixed.clone(),
        k: r.k,
        theta,
        stroke: Some(Stroke::Linear(h)),
        free_parameter: Some(FreeParameter {
            name: "position of the crank pivot on the locus".into(),
            value: b.l1,
            reason: choice.reason,
        }),
        construction: Construction {
            point: "B".into(),
            extremes: [b1, b2],
            locus: locus.circle(b.side),
            pivot: b.o,
            lines: {
                let mut v = vec![("guide".into(), c, fpos(d1))];
                if let KneePivot::Horizontal(x) = r.pivot {
                    let ys = [b1.y, b2.y, b.o.y, c.y];
                    let (lo, hi) = ys.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |a, &y| (a.0.min(y), a.1.max(y)));
                    v.push(("pivot line x = l_CO".into(), Vec2::new(x, lo), Vec2::new(x, hi)));
                }
                v
            },
        },
        def,
        check,
        angles: vec![("angle_BCD".into(), gamma), ("beta_top".into(), beta2)],
        coordinates: vec![("O_y".into(), b.o.y)],
        shown: vec![],
    })
}
