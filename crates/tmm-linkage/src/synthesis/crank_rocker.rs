//! Crank-rocker four-bar by the time ratio (синтез кривошипно-коромыслового
//! механизма по коэффициенту Kω): given K, the rocker length l3 and its swing
//! ψ, the rocker's extreme positions C1, C2 are fixed (placed symmetric about
//! the swing's bisector), the crank pivot lies on the inscribed-angle locus
//! of C1C2 at θ ([`super::locus`]) and one extra condition fixes it: the crank
//! length, the frame distance, the frame line's direction, or the largest
//! smallest transmission angle (seed 002, example 1; Artobolevsky, ТММ, 1988,
//! § 26). Names: crank OA (1), coupler AB (2), rocker CB (3), frame OC.

use std::f64::consts::{FRAC_PI_2, PI};

use tmm_geom::Vec2;

use crate::model::{AssemblyHint, HintKind, InputDef, LinkDef, MechanismDef};

use super::check::{ASSEMBLY_OFFSET, Expect, check_cycle, check_extremes, check_limits};
use super::error::{SynthesisError, finite, positive, show};
use super::limits::{Drive, Limits};
use super::locus::Locus;
use super::pivot::{PivotCondition, choose, evaluate, polar};
use super::placement::Placement;
use super::result::{Construction, FreeParameter, Kind, Stroke, Synthesis};
use super::search::maximize;
use super::time_ratio::theta_from_k;

/// The extra condition of a crank-rocker request.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RockerCondition {
    /// The crank length l_OA, m (seed 002, example 1).
    Crank(f64),
    /// The frame distance l_OC, m.
    Frame(f64),
    /// The angle δ from the frame line OC to the bisector of the rocker's
    /// swing, rad (δ = 90°: the frame line perpendicular to the bisector, as
    /// in seed 002, example 1).
    FrameAngle(f64),
    /// The largest smallest transmission angle (or margin against the limits).
    Optimum,
}

/// A crank-rocker request.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CrankRockerRequest {
    /// K = ω_return/ω_working ≥ 1.
    pub k: f64,
    /// Rocker length l_CB, m.
    pub rocker: f64,
    /// Swing of the rocker ψ, rad, in (0, π).
    pub swing: f64,
    /// The extra condition.
    pub condition: RockerCondition,
    /// Crank direction and speed.
    pub drive: Drive,
    /// Pressure / transmission angle limits.
    pub limits: Limits,
}

/// The frame angle δ (from the frame line to the swing's bisector, +y) of
/// the valid pivot nearest in δ to `want`; δ is taken modulo 180°, since
/// δ and δ + 180° give the same frame line through the rocker's pivot `d`.
fn nearest_frame_angle(locus: &Locus, d: Vec2, sg: f64, want: f64) -> Option<f64> {
    let off = |o: Vec2| {
        let r = (FRAC_PI_2 - (o - d).atan2() - want).rem_euclid(PI);
        if r > FRAC_PI_2 { r - PI } else { r }
    };
    let (lo, hi) = locus.domain();
    let mut best: Option<f64> = None;
    for side in [1.0, -1.0] {
        let score = |w: f64| {
            let o = locus.point(side, w);
            evaluate(locus, d, o, sg).map_or(f64::NAN, |_| -off(o).abs())
        };
        if let Some((w, _)) = maximize(score, lo, hi, 720) {
            let x = off(locus.point(side, w));
            if best.is_none_or(|b| x.abs() < b.abs()) {
                best = Some(x);
            }
        }
    }
    best.map(|x| want + x)
}

/// Synthesise a crank-rocker four-bar and check it over the cycle.
///
/// ```
/// use tmm_linkage::synthesis::crank_rocker::*;
/// use tmm_linkage::synthesis::Drive;
/// let r = CrankRockerRequest { k: 1.28, rocker: 0.245, swing: 60f64.to_radians(),
///     condition: RockerCondition::Crank(0.1), drive: Drive::default(), limits: Default::default() };
/// let s = synthesize(&r).unwrap();
/// assert!((s.length("OA").unwrap() - 0.1).abs() < 1e-12);
/// assert!((s.check.k.unwrap() - 1.28).abs() < 1e-9);
/// ```
pub fn synthesize(r: &CrankRockerRequest) -> Result<Synthesis, SynthesisError> {
    let theta = theta_from_k(r.k)?;
    let l3 = positive("rocker", r.rocker)?;
    let psi = positive("swing", r.swing)?;
    if psi >= std::f64::consts::PI {
        return Err(SynthesisError::input("swing", "the rocker's swing must be less than 180°"));
    }
    r.limits.validate()?;
    let omega = r.drive.signed_omega()?;
    let sg = omega.signum();
    // rocker pivot at the origin, swing symmetric about +y
    let d = Vec2::ZERO;
    let c1 = polar(FRAC_PI_2 + 0.5 * psi) * l3;
    let c2 = polar(FRAC_PI_2 - 0.5 * psi) * l3;
    // when no pivot at all works, K is too large for this swing: the error
    // names K and the largest K for which the locus has a valid pivot
    // (bisection on t = θ/π, so that any K ≥ 1 can be asked)
    let any = |t: f64| {
        Locus::new(c1, c2, std::f64::consts::PI * t)
            .and_then(|l| choose(l, d, sg, PivotCondition::Optimum, &Limits::default(), "k", None))
            .is_ok()
    };
    let k_too_large = || {
        let (mut lo, mut hi) = (0.0, theta / std::f64::consts::PI);
        if !any(lo) {
            return None;
        }
        for _ in 0..48 {
            let mid = 0.5 * (lo + hi);
            if any(mid) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Some(SynthesisError::infeasible(
            "k",
            format!(
                "no crank-rocker swings a rocker by {:.4}° with K = {}: the crank pivots on the locus all fail Grashof's condition or put the extreme positions on two assembly branches",
                psi.to_degrees(),
                show(r.k)
            ),
            Some((1.0 + lo) / (1.0 - lo)),
        ))
    };
    let locus = match Locus::new(c1, c2, theta) {
        Ok(l) => l,
        Err(e) => return Err(k_too_large().unwrap_or(e)),
    };
    let (cond, field, what) = match r.condition {
        RockerCondition::Crank(l1) => (PivotCondition::CrankLength(positive("crank", l1)?), "crank", "crank length given"),
        RockerCondition::Frame(f) => (
            PivotCondition::FrameDistance(positive("frame", f)?),
            "frame",
            "frame distance given",
        ),
        RockerCondition::FrameAngle(a) => (
            PivotCondition::OnLine {
                point: d,
                dir: polar(FRAC_PI_2 - finite("frame_angle", a)?),
            },
            "frame_angle",
            "frame line's direction given",
        ),
        RockerCondition::Optimum => (PivotCondition::Optimum, "optimum", "optimum"),
    };
    let choice = match choose(locus, d, sg, cond, &r.limits, field, None) {
        Ok(c) => c,
        Err(e) => {
            if !any(theta / std::f64::consts::PI)
                && let Some(k) = k_too_large()
            {
                return Err(k);
            }
            // the pivot condition's own nearest value is an offset of the
            // line; for a frame direction the nearest direction is wanted
            if let (RockerCondition::FrameAngle(want), SynthesisError::Infeasible { field, condition, .. }) = (r.condition, &e) {
                return Err(SynthesisError::infeasible(
                    field.clone(),
                    condition.clone(),
                    nearest_frame_angle(&locus, d, sg, want),
                ));
            }
            return Err(e);
        }
    };
    let b = choice.bar;
    let place = Placement {
        origin: b.o,
        angle: (b.d - b.o).atan2(),
    };
    let c_ext = place.point(b.c_ext);
    let def = MechanismDef {
        fixed: vec![("O".into(), Vec2::ZERO), ("C".into(), Vec2::new(b.frame, 0.0))],
        links: vec![
            LinkDef::bar("1", "O", "A", b.l1),
            LinkDef::bar("2", "A", "B", b.l2),
            LinkDef::bar("3", "C", "B", b.l3),
        ],
        input: Some(InputDef::crank("1", "O", "A", omega)),
        hints: vec![AssemblyHint {
            point: "B".into(),
            kind: HintKind::Near(c_ext),
        }],
        assembly_angle: place.angle(b.phi_ext) + ASSEMBLY_OFFSET,
        output: Some("3".into()),
        ..Default::default()
    };
    let side = if c_ext.y > 0.0 { "above" } else { "below" };
    let check = check_cycle(
        &def,
        &Expect {
            k: Some(r.k),
            stroke: Some(Stroke::Angular(psi)),
        },
        &format!("B {side} the frame line OC"),
    )?;
    check_limits(&r.limits, &check)?;
    check_extremes(&check, "B", [place.point(c1), place.point(c2)])?;
    let construction = place.construction(Construction {
        point: "B".into(),
        extremes: [c1, c2],
        locus: locus.circle(b.side),
        pivot: b.o,
        lines: vec![],
    });
    let free_value = match r.condition {
        RockerCondition::Crank(_) => b.frame,
        _ => b.l1,
    };
    Ok(Synthesis {
        kind: Kind::CrankRocker,
        given: {
            let mut g = vec![("k".into(), r.k), ("rocker".into(), l3), ("swing".into(), psi)];
            match r.condition {
                RockerCondition::Crank(x) | RockerCondition::Frame(x) | RockerCondition::FrameAngle(x) => g.push((field.into(), x)),
                RockerCondition::Optimum => {}
            }
            g
        },
        lengths: vec![
            ("OA".into(), b.l1),
            ("AB".into(), b.l2),
            ("BC".into(), b.l3),
            ("OC".into(), b.frame),
        ],
        frame: def.fixed.clone(),
        k: r.k,
        theta,
        stroke: Some(Stroke::Angular(psi)),
        free_parameter: Some(FreeParameter {
            name: format!(
                "position of the crank pivot on the locus ({what}); {}",
                if matches!(r.condition, RockerCondition::Crank(_)) {
                    "frame OC"
                } else {
                    "crank OA"
                }
            ),
            value: free_value,
            reason: choice.reason,
        }),
        construction,
        def,
        check,
        angles: vec![],
        coordinates: vec![],
        shown: vec![],
    })
}
