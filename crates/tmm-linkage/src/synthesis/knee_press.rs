//! Crank-knee press (кривошипно-коленный пресс), seed 002, example 2: a
//! four-bar O-A-B-C (crank OA, coupler AB, rocker CB) drives the knee: the
//! rocker CB and the link BF push the slide F along the guide through C.
//! Stage 1: the slide's stroke H_F and the knee's angle δ from the straight
//! line CF at the bottom give the rocker's extreme positions B′, B″ — F is
//! lowest at β = δ and F(β) = l_CB·cos β + √(l_BF² − l_CB²·sin² β) below C
//! falls monotonically in β ∈ [0, 90°], so β″ is the root of
//! F(δ) − F(β″) = H_F (closed form for l_CB = l_BF: cos β″ = cos δ − H/(2l)).
//! Stage 2: the crank pivot on the inscribed-angle locus of B′B″ at θ
//! ([`super::pivot`]) fixed by its horizontal distance from C (the seed's
//! l^x_CO) or any other pivot condition, among the pivots whose slower
//! (working) stroke is the pressing one, ending with the slide at the bottom.
//!
//! Placement: C at the origin, the guide vertical, F below C, B to the right
//! (β from the downward vertical towards +x). Names: crank OA (1), coupler
//! AB (2), rocker CB (3), link BF (4), slide F (5).

use std::f64::consts::FRAC_PI_2;

use tmm_geom::Vec2;
use tmm_geom::root::brent;

use crate::model::{AssemblyHint, HintKind, InputDef, LinkDef, MechanismDef, SliderDef};

use super::check::{ASSEMBLY_OFFSET, Expect, check_cycle, check_extremes, check_limits};
use super::error::{SynthesisError, finite, positive};
use super::limits::{Drive, Limits};
use super::locus::Locus;
use super::pivot::{PivotCondition, choose};
use super::result::{Construction, FreeParameter, Kind, Stroke, Synthesis};
use super::time_ratio::theta_from_k;

/// How the crank pivot is fixed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum KneePivot {
    /// Its horizontal distance from C, m (seed 002: l^x_CO = 0.28 m).
    Horizontal(f64),
    /// The crank length, m.
    Crank(f64),
    /// Its distance from C, m.
    Frame(f64),
    /// The largest margin against the limits.
    Optimum,
}

/// A knee-press request.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KneeRequest {
    /// Stroke of the slide H_F, m.
    pub stroke: f64,
    /// K ≥ 1.
    pub k: f64,
    /// Rocker l_CB, m.
    pub rocker: f64,
    /// Knee link l_BF, m.
    pub link: f64,
    /// Angle δ of the rocker from the line CF at the bottom, rad (> 0).
    pub delta: f64,
    /// The crank pivot's condition.
    pub pivot: KneePivot,
    /// Crank direction and speed.
    pub drive: Drive,
    /// Limits.
    pub limits: Limits,
}

/// Depth of F below C at the rocker angle β.
fn depth(l: f64, lf: f64, beta: f64) -> f64 {
    l * beta.cos() + (lf * lf - (l * beta.sin()).powi(2)).max(0.0).sqrt()
}

/// Synthesise and check.
///
/// ```
/// use tmm_linkage::synthesis::knee_press::*;
/// let s = synthesize(&KneeRequest { stroke: 0.09, k: 1.12, rocker: 0.22, link: 0.22,
///     delta: 5f64.to_radians(), pivot: KneePivot::Horizontal(0.28),
///     drive: Default::default(), limits: Default::default() }).unwrap();
/// assert!((s.check.k.unwrap() - 1.12).abs() < 1e-9);
/// assert!((s.frame[1].1.x - 0.28).abs() < 1e-12);
/// ```
pub fn synthesize(r: &KneeRequest) -> Result<Synthesis, SynthesisError> {
    let h = positive("stroke", r.stroke)?;
    let theta = theta_from_k(r.k)?;
    let l = positive("rocker", r.rocker)?;
    let lf = positive("link", r.link)?;
    let delta = finite("delta", r.delta)?;
    r.limits.validate()?;
    let omega = r.drive.signed_omega()?;
    if !(delta > 0.0 && delta < FRAC_PI_2) {
        return Err(SynthesisError::input(
            "delta",
            "the knee's angle from the straight line at the bottom must lie in (0°, 90°): at 0° the slide's dead position would not be the rocker's",
        ));
    }
    let top = if lf >= l { FRAC_PI_2 } else { (lf / l).asin() };
    let f0 = depth(l, lf, delta);
    let h_max = f0 - depth(l, lf, top);
    if top <= delta || h >= h_max {
        return Err(SynthesisError::infeasible(
            "stroke",
            format!(
                "the knee lifts the slide by less than {} m from δ = {:.4}° while the rocker stays within 90° of the line CF",
                super::error::show(h_max.max(0.0)),
                delta.to_degrees()
            ),
            Some(h_max.max(0.0) * (1.0 - 1e-6)),
        ));
    }
    let beta2 = brent(|b| f0 - depth(l, lf, b) - h, delta, top, 1e-15)
        .ok_or_else(|| SynthesisError::Check("no rocker angle gives this stroke".into()))?;
    let bpos = |b: f64| Vec2::new(b.sin(), -b.cos()) * l;
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
            // the nearest line offset along (−1, 0) → the nearest x
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
    let fpos = |bb: Vec2| Vec2::new(0.0, bb.y - (lf * lf - bb.x * bb.x).max(0.0).sqrt());
    let def = MechanismDef {
        slider_input: None,
        fixed: vec![("C".into(), c), ("O".into(), b.o)],
        links: vec![
            LinkDef::bar("1", "O", "A", b.l1),
            LinkDef::bar("2", "A", "B", b.l2),
            LinkDef::bar("3", "C", "B", l),
            LinkDef::bar("4", "B", "F", lf),
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
                kind: HintKind::Near(fpos(b.c_ext)),
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
        "B on the side of the crank pivot, F below C",
    )?;
    check_limits(&r.limits, &check)?;
    check_extremes(&check, "B", [b1, b2])?;
    Ok(Synthesis {
        kind: Kind::KneePress,
        given: vec![
            ("stroke".into(), h),
            ("k".into(), r.k),
            ("rocker".into(), l),
            ("link".into(), lf),
            ("delta".into(), delta),
        ],
        lengths: vec![
            ("OA".into(), b.l1),
            ("AB".into(), b.l2),
            ("CB".into(), l),
            ("BF".into(), lf),
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
                let mut v = vec![("guide".into(), c, fpos(b1))];
                // the seed's condition: the pivot on the vertical at l^x_CO from C
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
        angles: vec![],
        coordinates: vec![],
        shown: vec![],
    })
}
