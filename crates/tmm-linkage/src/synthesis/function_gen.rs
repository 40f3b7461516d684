//! A four-bar that generates a function by given positions (синтез по
//! заданным положениям входного и выходного звеньев): pairs (φi, ψi) of the
//! crank and rocker angles, measured from the frame line O→C, three solved
//! exactly and more by least squares, with Freudenstein's equation
//! (F. Freudenstein, Trans. ASME 77, 1955; Norton, Design of Machinery, § 5.12):
//!
//! K1·cos ψ − K2·cos φ + K3 = cos(φ − ψ),
//! K1 = d/a, K2 = d/c, K3 = (a² − b² + c² + d²)/(2ac),
//!
//! from the loop a·e^{iφ} + b·e^{iβ} = d + c·e^{iψ}. The equation is linear in
//! K1, K2, K3; the frame d only scales the result. A negative a (or c) is a
//! crank (rocker) pointing the other way: a·e^{iφ} = |a|·e^{i(φ+π)}.
//! The check solves the mechanism at every φi with the linkage core and
//! compares the rocker angle with ψi.

use std::f64::consts::{FRAC_PI_2, PI};

use tmm_geom::Vec2;

use crate::cycle::{Cycle, OutputKind, Working, pressure_angles};
use crate::mechanism::Mechanism;
use crate::model::{AssemblyHint, HintKind, InputDef, LinkDef, MechanismDef};

use super::check::{check_limits, points_at};
use super::error::{SynthesisError, finite, positive};
use super::limits::Limits;
use super::pivot::polar;
use super::result::{CheckReport, Construction, FreeParameter, Kind, Stroke, Synthesis};

/// A function-generation request.
#[derive(Debug, Clone, PartialEq)]
pub struct FunctionRequest {
    /// Pairs (φi, ψi), rad: crank and rocker angles from the frame line.
    pub positions: Vec<(f64, f64)>,
    /// Frame length |OC|, m (the scale).
    pub frame: f64,
    /// Crank speed, rad/s (signed).
    pub omega: f64,
    /// Pressure / transmission angle limits over the travel from the first
    /// position to the last (the same on both "strokes").
    pub limits: Limits,
}

/// Solve the 3×3 system `m·x = r` by Cramer's rule.
fn solve3(m: [[f64; 3]; 3], r: [f64; 3]) -> Option<[f64; 3]> {
    let det = |a: [[f64; 3]; 3]| {
        a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
            + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
    };
    let d = det(m);
    let scale = m.iter().flatten().fold(0.0f64, |s, v| s.max(v.abs())).powi(3);
    if d.is_nan() || d.abs() <= 1e-12 * scale {
        return None;
    }
    let mut x = [0.0; 3];
    for (j, xj) in x.iter_mut().enumerate() {
        let mut mj = m;
        for i in 0..3 {
            mj[i][j] = r[i];
        }
        *xj = det(mj) / d;
    }
    Some(x)
}

/// Freudenstein's coefficients (K1, K2, K3) from the positions: exact for
/// three, least squares (normal equations) for more.
pub fn coefficients(positions: &[(f64, f64)]) -> Option<[f64; 3]> {
    let mut ata = [[0.0; 3]; 3];
    let mut atb = [0.0; 3];
    for &(phi, psi) in positions {
        let row = [psi.cos(), -phi.cos(), 1.0];
        let rhs = (phi - psi).cos();
        for i in 0..3 {
            for j in 0..3 {
                ata[i][j] += row[i] * row[j];
            }
            atb[i] += row[i] * rhs;
        }
    }
    solve3(ata, atb)
}

/// The most positions (φ, ψ) of a function generation: each adds a row to
/// every table and a line to every drawing of the result.
pub const MAX_POSITIONS: usize = 1000;

/// Synthesise and check.
///
/// ```
/// use tmm_linkage::synthesis::function_gen::*;
/// let p = [(40f64, 70f64), (75.0, 95.0), (110.0, 112.0)].map(|(a, b)| (a.to_radians(), b.to_radians()));
/// let s = synthesize(&FunctionRequest { positions: p.to_vec(), frame: 0.3, omega: 1.0, limits: Default::default() }).unwrap();
/// assert!(s.free_parameter.unwrap().value < 1e-9); // the largest residual, rad
/// ```
pub fn synthesize(r: &FunctionRequest) -> Result<Synthesis, SynthesisError> {
    if r.positions.len() > MAX_POSITIONS {
        return Err(SynthesisError::input(
            "positions",
            format!("at most {MAX_POSITIONS} pairs (φ, ψ) are taken, {} given", r.positions.len()),
        ));
    }
    if r.positions.len() < 3 {
        return Err(SynthesisError::input(
            "positions",
            format!("at least three pairs (φ, ψ) are needed, {} given", r.positions.len()),
        ));
    }
    for (i, &(a, b)) in r.positions.iter().enumerate() {
        finite(&format!("positions.{i}.phi"), a)?;
        finite(&format!("positions.{i}.psi"), b)?;
    }
    let d = positive("frame", r.frame)?;
    r.limits.validate()?;
    let omega = finite("omega", r.omega)?;
    if omega == 0.0 {
        return Err(SynthesisError::input("omega", "the crank speed must not be zero"));
    }
    let Some([k1, k2, k3]) = coefficients(&r.positions) else {
        return Err(SynthesisError::infeasible(
            "positions",
            "the positions give a singular Freudenstein system (two crank or two rocker angles repeat, or all lie symmetric)",
            None,
        ));
    };
    let (a, c) = (d / k1, d / k2);
    let b2 = a * a + c * c + d * d - 2.0 * a * c * k3;
    if !(a.is_finite() && c.is_finite() && b2 > 0.0 && b2.is_finite()) {
        return Err(SynthesisError::infeasible(
            "positions",
            format!(
                "Freudenstein's coefficients K1 = {}, K2 = {}, K3 = {} give no real four-bar (b² = {} m²)",
                super::error::show(k1),
                super::error::show(k2),
                super::error::show(k3),
                super::error::show(b2)
            ),
            None,
        ));
    }
    let b = b2.sqrt();
    let (off_a, off_c) = (if a < 0.0 { PI } else { 0.0 }, if c < 0.0 { PI } else { 0.0 });
    let (la, lc) = (a.abs(), c.abs());
    let (phi0, psi0) = r.positions[0];
    let b_first = Vec2::new(d, 0.0) + polar(psi0 + off_c) * lc;
    let def = MechanismDef {
        fixed: vec![("O".into(), Vec2::ZERO), ("C".into(), Vec2::new(d, 0.0))],
        links: vec![
            LinkDef::bar("1", "O", "A", la),
            LinkDef::bar("2", "A", "B", b),
            LinkDef::bar("3", "C", "B", lc),
        ],
        input: Some(InputDef::crank("1", "O", "A", omega)),
        hints: vec![AssemblyHint {
            point: "B".into(),
            kind: HintKind::Near(b_first),
        }],
        assembly_angle: phi0 + off_a,
        output: Some("3".into()),
        ..Default::default()
    };
    let m = Mechanism::new(&def)?;
    let mut sol = m.solution();
    let mut worst = 0.0f64;
    for (i, &(phi, psi)) in r.positions.iter().enumerate() {
        m.solve(phi + off_a, &mut sol)
            .map_err(|e| SynthesisError::infeasible("positions", format!("position {i} cannot be reached: {e}"), None))?;
        let got = sol.links[3].angle() - off_c;
        worst = worst.max(tmm_geom::angle::wrap_pi(got - psi).abs());
    }
    if r.positions.len() == 3 && worst > 1e-7 {
        return Err(SynthesisError::infeasible(
            "positions",
            format!(
                "the four-bar through the three positions reaches them on different assembly branches (circuits): the rocker misses by {:.4}° on the branch of the first one",
                worst.to_degrees()
            ),
            None,
        ));
    }
    // pressure angles over the travel from the first to the last position
    let (first, last) = (phi0, r.positions[r.positions.len() - 1].0);
    let n = 360;
    let mut buf = Vec::with_capacity(2);
    let mut pmax = 0.0f64;
    for k in 0..=n {
        let phi = first + (last - first) * k as f64 / n as f64 + off_a;
        m.solve(phi, &mut sol).map_err(|e| {
            SynthesisError::infeasible(
                "positions",
                format!("the mechanism cannot move from the first position to the last: {e}"),
                None,
            )
        })?;
        pressure_angles(&m, &sol, &mut buf);
        pmax = buf.iter().fold(pmax, |s, &(_, t)| s.max(t));
    }
    let mut ls = [la, b, lc, d];
    ls.sort_by(f64::total_cmp);
    let grashof_crank = ls[0] == la && ls[0] + ls[3] < ls[1] + ls[2];
    let cycle = if grashof_crank {
        Cycle::new(&m, Working::Slower).ok()
    } else {
        None
    };
    let (k, theta, stroke, dead_phi) = match &cycle {
        Some(c) if c.dead.len() == 2 => (
            Some(c.kv),
            Some(c.theta),
            Some(match c.output.kind {
                OutputKind::Linear => Stroke::Linear(c.stroke),
                OutputKind::Angular => Stroke::Angular(c.stroke),
            }),
            c.dead.clone(),
        ),
        _ => (None, None, None, vec![]),
    };
    let dead_positions = dead_phi.iter().map(|&p| points_at(&m, p)).collect::<Result<Vec<_>, _>>()?;
    let check = CheckReport {
        k,
        theta,
        stroke,
        pressure_angle_max: (pmax, pmax),
        transmission_angle_min: FRAC_PI_2 - pmax,
        crank_turns_fully: cycle.is_some(),
        branch: "B on the branch through the first position".into(),
        dead_phi,
        dead_positions,
    };
    check_limits(&r.limits, &check)?;
    let b_at = |phi: f64| -> Result<Vec2, SynthesisError> {
        let pts = points_at(&m, phi + off_a)?;
        Ok(pts.iter().find(|(x, _)| x == "B").map_or(Vec2::ZERO, |(_, p)| *p))
    };
    let (b_first, b_last) = (b_at(first)?, b_at(last)?);
    let mut given: Vec<(String, f64)> = Vec::new();
    for (i, &(p, q)) in r.positions.iter().enumerate() {
        given.push((format!("phi{}", i + 1), p));
        given.push((format!("psi{}", i + 1), q));
    }
    given.push(("frame".into(), d));
    Ok(Synthesis {
        kind: Kind::FunctionGeneration,
        given,
        lengths: vec![("OA".into(), la), ("AB".into(), b), ("BC".into(), lc), ("OC".into(), d)],
        frame: def.fixed.clone(),
        k: 1.0,
        theta: 0.0,
        stroke: None,
        free_parameter: Some(FreeParameter {
            name: "largest residual of the rocker angle over the given positions, rad".into(),
            value: worst,
            reason: if r.positions.len() == 3 {
                "three positions: Freudenstein's equations solved exactly; the frame length given sets the scale".into()
            } else {
                format!(
                    "{} positions: Freudenstein's equations solved by least squares; the frame length given sets the scale",
                    r.positions.len()
                )
            },
        }),
        construction: Construction {
            point: "B".into(),
            extremes: [b_first, b_last],
            locus: None,
            pivot: Vec2::ZERO,
            lines: vec![],
        },
        def,
        check,
        angles: vec![],
        coordinates: vec![],
        shown: vec![],
    })
}
