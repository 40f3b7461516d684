//! Four-bar through three positions with the rocker's pivot D and its
//! length l3 given and the crank's starting angle unknown (синтез по трём
//! положениям), BMSTU textbook (Chernaya & Timofeev 2019), appendix П1.4:
//! the crank AB about A = (0, 0) at φ1н + Δφj, the rocker DC at γj,
//! j = 1, 2, 3, with Δφ1 = 0. The book writes six loop equations in l1, l2,
//! φ1н and the three coupler angles φ2j (p. 113–114), which Freudenstein's
//! equation on absolute angles with the scale free ([`super::function_gen`])
//! does not pose: here D and l3 fix the scale and the frame.
//!
//! **Closed form (derived here, docs/synthesis.md § 15).** C_j = D + l3·e^{iγj}
//! are known. The coupler's length is the same in the three positions,
//! |C_j − B_j| = l2 with B_j = R(Δφj)·B_1, i.e. |R(−Δφj)·C_j − B_1| = l2:
//! B_1 is equidistant from the points C_j′ = R(−Δφj)·C_j (the rocker's
//! points seen from the crank held still — kinematic inversion), so it is
//! their circumcentre, the solution of the linear system
//! 2 (C_j′ − C_1′)·B_1 = |C_j′|² − |C_1′|², j = 2, 3.
//! Then l1 = |B_1|, φ1н = arg B_1, l2 = |C_1 − B_1|, φ2j = arg(C_j − B_j):
//! one solution (or none when the C_j′ are collinear), no first guess.

use std::f64::consts::FRAC_PI_2;

use tmm_geom::Vec2;
use tmm_geom::angle::wrap_pi;

use crate::cycle::pressure_angles;
use crate::mechanism::Mechanism;

use super::check::{Expect, check_cycle, check_limits, points_at};
use super::error::{SynthesisError, finite, positive, show};
use super::limits::{Drive, Limits};
use super::pivot::polar;
use super::result::{CheckReport, Construction, FreeParameter, Kind, Synthesis};
use super::rocker_extremes::four_bar;

/// A request (П1.4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThreePositionsRequest {
    /// The rocker's pivot D, m.
    pub frame: Vec2,
    /// Rocker l3 = |DC|, m.
    pub rocker: f64,
    /// The rocker's angles γ1, γ2, γ3, rad.
    pub gammas: [f64; 3],
    /// The crank's rotations from position 1, φ12 and φ13, rad (signed,
    /// counter-clockwise positive).
    pub crank_turns: [f64; 2],
    /// Crank direction and speed.
    pub drive: Drive,
    /// Limits (over the travel from position 1 to position 3).
    pub limits: Limits,
}

/// The closed form: (l1, l2, φ1н) or `None` when the inverted points are
/// collinear.
pub fn closed_form(d: Vec2, l3: f64, gammas: [f64; 3], turns: [f64; 3]) -> Option<(f64, f64, f64)> {
    let c: Vec<Vec2> = gammas.iter().map(|&g| d + polar(g) * l3).collect();
    let inv: Vec<Vec2> = c
        .iter()
        .zip(turns)
        .map(|(p, t)| {
            let (s, co) = (-t).sin_cos();
            Vec2::new(co * p.x - s * p.y, s * p.x + co * p.y)
        })
        .collect();
    let (e1, e2) = (inv[1] - inv[0], inv[2] - inv[0]);
    let (r1, r2) = (
        0.5 * (inv[1].dot(inv[1]) - inv[0].dot(inv[0])),
        0.5 * (inv[2].dot(inv[2]) - inv[0].dot(inv[0])),
    );
    let det = e1.x * e2.y - e1.y * e2.x;
    let scale = e1.hypot() * e2.hypot();
    if det.is_nan() || det.abs() <= 1e-12 * scale {
        return None;
    }
    let b1 = Vec2::new((r1 * e2.y - e1.y * r2) / det, (e1.x * r2 - e2.x * r1) / det);
    Some((b1.hypot(), (c[0] - b1).hypot(), b1.atan2()))
}

/// Synthesise and check.
///
/// ```
/// use tmm_linkage::synthesis::three_positions::*;
/// use tmm_geom::Vec2;
/// // BMSTU textbook П1.4
/// let r = ThreePositionsRequest { frame: Vec2::new(0.5, -0.1), rocker: 0.5,
///     gammas: [70f64, 80.0, 120.0].map(f64::to_radians), crank_turns: [30f64, 120.0].map(f64::to_radians),
///     drive: Default::default(), limits: Default::default() };
/// let s = synthesize(&r).unwrap();
/// // the coupler has one length in the three positions
/// assert!(s.free_parameter.unwrap().value < 1e-9);
/// ```
pub fn synthesize(r: &ThreePositionsRequest) -> Result<Synthesis, SynthesisError> {
    let d = Vec2::new(finite("frame_x", r.frame.x)?, finite("frame_y", r.frame.y)?);
    let l3 = positive("rocker", r.rocker)?;
    for (i, g) in r.gammas.iter().enumerate() {
        finite(&format!("gamma{}", i + 1), *g)?;
    }
    let p12 = finite("phi12", r.crank_turns[0])?;
    let p13 = finite("phi13", r.crank_turns[1])?;
    if p12 * p13 <= 0.0 || p12 == p13 {
        return Err(SynthesisError::input(
            "phi13",
            "the crank's rotations φ12 and φ13 from position 1 must be different, non-zero and of one sense",
        ));
    }
    r.limits.validate()?;
    let omega = r.drive.signed_omega()?;
    let turns = [0.0, p12, p13];
    let Some((l1, l2, phi0)) = closed_form(d, l3, r.gammas, turns) else {
        return Err(SynthesisError::infeasible(
            "gamma3",
            "the rocker's points turned back by the crank's rotations, R(−Δφj)·C_j, lie on one line: no crank pin is equidistant from them",
            None,
        ));
    };
    if l1.is_nan() || l1 <= 1e-9 * l3 || !l2.is_finite() {
        return Err(SynthesisError::infeasible(
            "gamma3",
            format!("the crank comes out of length {} m: the positions give no crank", show(l1)),
            None,
        ));
    }
    let c: Vec<Vec2> = r.gammas.iter().map(|&g| d + polar(g) * l3).collect();
    let phis: Vec<f64> = turns.iter().map(|t| phi0 + t).collect();
    let b: Vec<Vec2> = phis.iter().map(|&p| polar(p) * l1).collect();
    let phi2: Vec<f64> = (0..3).map(|j| (c[j] - b[j]).atan2()).collect();
    // residual of the book's six equations (the coupler's length at j = 2, 3)
    let resid = (0..3).map(|j| ((c[j] - b[j]).hypot() - l2).abs()).fold(0.0, f64::max);
    let def = four_bar(d, (l1, l2, l3), omega, c[0], phi0);
    // the check: the linkage core moves the crank from position 1 to 3 on
    // the branch of position 1 and must meet the rocker's angles
    let m = Mechanism::new(&def)?;
    let mut sol = m.solution();
    let far = if p13.abs() >= p12.abs() { p13 } else { p12 };
    let mut order = [0usize, 1, 2];
    order.sort_by(|&i, &j| turns[i].abs().total_cmp(&turns[j].abs()));
    let n = 360;
    let mut buf = Vec::with_capacity(2);
    let mut pmax = 0.0f64;
    let mut worst = 0.0f64;
    let mut next = 0;
    for k in 0..=n {
        let t = far * k as f64 / n as f64;
        // a given position passed on the way is solved at its own angle
        // before the step, on the same branch
        while next < 3 && turns[order[next]].abs() <= t.abs() {
            let j = order[next];
            m.solve(phi0 + turns[j], &mut sol)
                .map_err(|e| SynthesisError::infeasible("gamma3", format!("position {} cannot be reached: {e}", j + 1), None))?;
            worst = worst.max(wrap_pi(sol.links[3].angle() - r.gammas[j]).abs());
            next += 1;
        }
        m.solve(phi0 + t, &mut sol).map_err(|e| {
            SynthesisError::infeasible("gamma3", format!("the four-bar cannot move through the three positions: {e}"), None)
        })?;
        pressure_angles(&m, &sol, &mut buf);
        pmax = buf.iter().fold(pmax, |s, &(_, t)| s.max(t));
    }
    if next < 3 || worst > 1e-7 {
        return Err(SynthesisError::infeasible(
            "gamma3",
            format!(
                "the four-bar through the three positions reaches them on different assembly branches: moving the crank from the first, the rocker misses by {:.4}°",
                worst.to_degrees()
            ),
            None,
        ));
    }
    let mut ls = [l1, l2, l3, d.hypot()];
    ls.sort_by(f64::total_cmp);
    let grashof = ls[0] == l1 && ls[0] + ls[3] < ls[1] + ls[2];
    let check = match grashof {
        true => check_cycle(&def, &Expect { k: None, stroke: None }, "C on the branch of position 1")?,
        false => CheckReport {
            k: None,
            theta: None,
            stroke: None,
            pressure_angle_max: (pmax, pmax),
            transmission_angle_min: FRAC_PI_2 - pmax,
            crank_turns_fully: false,
            branch: "C on the branch of position 1".into(),
            dead_phi: vec![],
            dead_positions: vec![],
        },
    };
    check_limits(&r.limits, &check)?;
    let pts: Vec<Vec<(String, Vec2)>> = phis.iter().map(|&p| points_at(&m, p)).collect::<Result<_, _>>()?;
    let at = |j: usize, name: &str| pts[j].iter().find(|(n, _)| n == name).map_or(Vec2::ZERO, |(_, p)| *p);
    let mut lines = Vec::new();
    for j in 0..3 {
        lines.push((format!("crank position {}", j + 1), Vec2::ZERO, at(j, "B")));
    }
    Ok(Synthesis {
        kind: Kind::CrankRocker,
        given: vec![
            ("frame_x".into(), d.x),
            ("frame_y".into(), d.y),
            ("rocker".into(), l3),
            ("gamma1".into(), r.gammas[0]),
            ("gamma2".into(), r.gammas[1]),
            ("gamma3".into(), r.gammas[2]),
            ("phi12".into(), p12),
            ("phi13".into(), p13),
        ],
        lengths: vec![("AB".into(), l1), ("BC".into(), l2), ("DC".into(), l3), ("AD".into(), d.hypot())],
        frame: def.fixed.clone(),
        k: check.k.unwrap_or(1.0),
        theta: check.theta.unwrap_or(0.0),
        stroke: check.stroke,
        free_parameter: Some(FreeParameter {
            name: "largest residual of the coupler's length over the three positions, m".into(),
            value: resid,
            reason: format!(
                "three positions with D and l3 given: the crank pin B1 is the circumcentre of the rocker's points turned back by the crank's rotations (closed form); the linkage core meets the rocker's angles to {:.1e} rad{}",
                worst,
                if grashof {
                    ""
                } else {
                    "; the crank does not turn fully (Grashof), so the check covers positions 1 to 3 only"
                }
            ),
        }),
        construction: Construction {
            point: "C".into(),
            extremes: [c[0], c[2]],
            locus: None,
            pivot: Vec2::ZERO,
            lines,
        },
        def,
        check,
        angles: vec![
            ("phi1_start".into(), phi0),
            ("phi2_1".into(), phi2[0]),
            ("phi2_2".into(), phi2[1]),
            ("phi2_3".into(), phi2[2]),
        ],
        coordinates: vec![],
        shown: phis,
    })
}
