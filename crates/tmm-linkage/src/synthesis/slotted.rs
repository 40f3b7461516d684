//! Slotted-lever (кулисный) mechanism of a shaper: crank OA, block A sliding
//! in the slotted lever 3 pivoted at E, the lever's arm EC, coupler CD, ram D
//! on a guide (seed 002, example 3).
//!
//! - Rotating slotted lever (вращающаяся кулиса, r = l_OA > l_OE): the ram is
//!   at its extremes when EC lies along the ram's guide through E, so the
//!   slot (perpendicular to EC) is perpendicular to OE and the crank pin is on
//!   the perpendicular to OE through E: sin(θ/2) = l_OE/r, r = l_OE / sin(θ/2),
//!   and H = 2·l_EC (seed 002, example 3: the rays from O at θ/2 to that
//!   perpendicular).
//! - Oscillating slotted lever (качающаяся кулиса, r < l_OE): the lever is at
//!   its extremes when the slot is tangent to the crank circle; the crank turns
//!   by π ∓ θ between them and the lever swings by ψ = θ, so
//!   r = l_OE·sin(θ/2); with the ram guide perpendicular to OE through the
//!   middle of the sagitta of C's arc, y = l_EC (1 + cos(θ/2))/2, the two ends
//!   of the stroke are at equal heights and H = 2·l_EC·sin(θ/2)
//!   (Artobolevsky, ТММ, 1988, § 26; derived here, docs/synthesis.md § 5).
//!
//! Names: crank OA (1), block A (2), slotted lever EC (3), coupler CD (4),
//! ram D (5); frame points O, E.

use std::f64::consts::FRAC_PI_2;

use tmm_geom::Vec2;

use crate::model::{AssemblyHint, HintKind, InputDef, LinkDef, MechanismDef, SliderDef};

use super::check::{Expect, check_cycle, check_extremes, check_limits};
use super::error::{SynthesisError, positive};
use super::limits::{Drive, Limits};
use super::result::{Construction, FreeParameter, Kind, Stroke, Synthesis};
use super::time_ratio::theta_from_k;

/// Which slotted lever.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Lever {
    /// The lever turns fully (r > l_OE).
    Rotating,
    /// The lever oscillates (r < l_OE).
    Oscillating,
}

/// How the coupler CD is given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Coupler {
    /// The ratio l_CD / l_EC (seed 002, example 3: 3).
    Ratio(f64),
    /// The length l_CD, m.
    Length(f64),
}

/// A slotted-lever request.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlottedRequest {
    /// Ram stroke H, m.
    pub stroke: f64,
    /// K > 1.
    pub k: f64,
    /// Distance between the crank pivot and the lever pivot l_OE, m.
    pub pivots: f64,
    /// The coupler.
    pub coupler: Coupler,
    /// Rotating or oscillating lever.
    pub lever: Lever,
    /// Crank direction and speed.
    pub drive: Drive,
    /// Pressure-angle limits.
    pub limits: Limits,
}

/// Synthesise and check.
///
/// ```
/// use tmm_linkage::synthesis::slotted::*;
/// // seed 002, example 3: H = 0.4 m, l_OE = 0.05 m, CD = 3·EC, K = 1.5
/// let s = synthesize(&SlottedRequest { stroke: 0.4, k: 1.5, pivots: 0.05, coupler: Coupler::Ratio(3.0),
///     lever: Lever::Rotating, drive: Default::default(), limits: Default::default() }).unwrap();
/// assert!((s.length("OA").unwrap() - 0.05 / 18f64.to_radians().sin()).abs() < 1e-12);
/// assert!((s.length("EC").unwrap() - 0.2).abs() < 1e-12);
/// ```
pub fn synthesize(r: &SlottedRequest) -> Result<Synthesis, SynthesisError> {
    let h = positive("stroke", r.stroke)?;
    let theta = theta_from_k(r.k)?;
    let loe = positive("pivots", r.pivots)?;
    r.limits.validate()?;
    let omega = r.drive.signed_omega()?;
    let sg = omega.signum();
    if theta == 0.0 {
        return Err(SynthesisError::infeasible(
            "k",
            "a slotted-lever mechanism has K > 1 (θ = 0 needs l_OE = 0 or an infinite crank)",
            Some(1.0 + 1e-6),
        ));
    }
    let half = 0.5 * theta;
    let (r1, lec) = match r.lever {
        Lever::Rotating => (loe / half.sin(), 0.5 * h),
        Lever::Oscillating => (loe * half.sin(), h / (2.0 * half.sin())),
    };
    let lcd = match r.coupler {
        Coupler::Ratio(q) => positive("coupler_ratio", q)? * lec,
        Coupler::Length(l) => positive("coupler", l)?,
    };
    // the coupler must reach the ram's guide from every position of C
    let reach = match r.lever {
        Lever::Rotating => lec,
        Lever::Oscillating => 0.5 * lec * (1.0 - half.cos()),
    };
    if lcd <= reach {
        return Err(SynthesisError::infeasible(
            "coupler",
            format!(
                "the coupler CD must be longer than {} m to reach the ram's guide from every position of C",
                super::error::show(reach)
            ),
            Some(reach * (1.0 + 1e-6)),
        ));
    }
    // placement: E at the origin
    let (o, c_ext, d_ext, phi_ext, slot_angle, guide_y);
    match r.lever {
        Lever::Rotating => {
            // O on the left of E; with ccw rotation the crank pin at the top
            // (A on the perpendicular through E) starts the slow stroke.
            o = Vec2::new(-loe, 0.0);
            let y = (r1 * r1 - loe * loe).sqrt();
            phi_ext = Vec2::new(loe, sg * y).atan2();
            slot_angle = sg * FRAC_PI_2;
            c_ext = Vec2::new(lec, 0.0);
            d_ext = Vec2::new(lec + lcd, 0.0);
            guide_y = 0.0;
        }
        Lever::Oscillating => {
            // O above E; the lever swings about +y by ±θ/2; the ram's guide
            // horizontal through the middle of the sagitta.
            o = Vec2::new(0.0, loe);
            guide_y = 0.5 * lec * (1.0 + half.cos());
            let beta = FRAC_PI_2 - half;
            c_ext = Vec2::new(beta.cos(), beta.sin()) * lec;
            let dy = guide_y - c_ext.y;
            d_ext = Vec2::new(c_ext.x + (lcd * lcd - dy * dy).sqrt(), guide_y);
            // crank pin at the foot of the perpendicular from O to the slot
            let u = Vec2::new(beta.cos(), beta.sin());
            let a = u * o.dot(u);
            phi_ext = (a - o).atan2();
            slot_angle = 0.0;
        }
    }
    let def = MechanismDef {
        slider_input: None,
        fixed: vec![("O".into(), o), ("E".into(), Vec2::ZERO)],
        links: vec![
            LinkDef::bar("1", "O", "A", r1),
            LinkDef::block("2", "A"),
            LinkDef::bar("3", "E", "C", lec),
            LinkDef::bar("4", "C", "D", lcd),
            LinkDef::block("5", "D"),
        ],
        sliders: vec![
            SliderDef {
                slider: "2".into(),
                point: "A".into(),
                guide_link: "3".into(),
                through: Vec2::ZERO,
                angle: slot_angle,
                angle_on_slider: 0.0,
            },
            SliderDef {
                slider: "5".into(),
                point: "D".into(),
                guide_link: crate::model::FRAME.into(),
                through: Vec2::new(0.0, guide_y),
                angle: 0.0,
                angle_on_slider: 0.0,
            },
        ],
        input: Some(InputDef::crank("1", "O", "A", omega)),
        hints: vec![
            AssemblyHint {
                point: "C".into(),
                kind: HintKind::Near(c_ext),
            },
            AssemblyHint {
                point: "D".into(),
                kind: HintKind::Near(d_ext),
            },
        ],
        assembly_angle: phi_ext + sg * 0.02,
        output: Some("5".into()),
    };
    let check = check_cycle(
        &def,
        &Expect {
            k: Some(r.k),
            stroke: Some(Stroke::Linear(h)),
        },
        "C and D on the side of the ram's stroke given by the extreme positions",
    )?;
    check_limits(&r.limits, &check)?;
    // the ram at the lever's two extreme angles
    let d_other = match r.lever {
        Lever::Rotating => Vec2::new(lcd - lec, 0.0),
        Lever::Oscillating => Vec2::new(d_ext.x - 2.0 * c_ext.x, guide_y),
    };
    check_extremes(&check, "D", [d_ext, d_other])?;
    let pin = |p: f64| o + Vec2::new(p.cos(), p.sin()) * r1;
    let dp = &check.dead_phi;
    let (a1, a2) = (pin(dp.first().copied().unwrap_or(0.0)), pin(dp.get(1).copied().unwrap_or(0.0)));
    Ok(Synthesis {
        kind: Kind::SlottedLever,
        given: vec![
            ("stroke".into(), h),
            ("k".into(), r.k),
            ("pivots".into(), loe),
            (
                "coupler".into(),
                match r.coupler {
                    Coupler::Ratio(q) | Coupler::Length(q) => q,
                },
            ),
        ],
        lengths: vec![("OA".into(), r1), ("OE".into(), loe), ("EC".into(), lec), ("CD".into(), lcd)],
        frame: def.fixed.clone(),
        k: r.k,
        theta,
        stroke: Some(Stroke::Linear(h)),
        free_parameter: match r.lever {
            Lever::Rotating => None,
            Lever::Oscillating => Some(FreeParameter {
                name: "height of the ram's guide above E".into(),
                value: guide_y,
                reason: "through the middle of the sagitta of C's arc: the smallest largest pressure angle on the ram, and both ends of the stroke at one height".into(),
            }),
        },
        construction: Construction {
            point: "A".into(),
            extremes: [a1, a2],
            locus: None,
            pivot: o,
            lines: vec![
                ("ray O-A'".into(), o, a1),
                ("ray O-A''".into(), o, a2),
                ("guide".into(), Vec2::new(-lec, guide_y), d_ext),
            ],
        },
        def,
        check,
        angles: vec![],
        coordinates: vec![],
        shown: vec![],
    })
}
