//! The independent check of a synthesised mechanism (проверка синтеза) by the
//! linkage core, not by the synthesis formulas: the mechanism is compiled,
//! assembled over the whole turn of the crank (so the crank turns fully), its
//! dead positions are found as roots of ds/dφ = 0 ([`Cycle`]), and K and the
//! stroke or swing are compared with the request to 1e-9. The pressure angle
//! curve of every dyad is scanned over the cycle and its largest value on
//! each stroke refined by golden-section search.

use std::f64::consts::{FRAC_PI_2, TAU};

use tmm_geom::Vec2;

use crate::cycle::{Cycle, OutputKind, Working, pressure_angles};
use crate::mechanism::{Mechanism, Solution};
use crate::model::MechanismDef;

use super::error::SynthesisError;
use super::limits::Limits;
use super::result::{CheckReport, Stroke};

/// Relative tolerance on K and on the stroke.
pub const TOL: f64 = 1e-9;

/// What the check must find.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Expect {
    /// K requested (`None`: whatever the mechanism gives).
    pub k: Option<f64>,
    /// Stroke or swing requested.
    pub stroke: Option<Stroke>,
}

/// Largest pressure angle over the dyads at crank angle `phi` (0 when the
/// position cannot be solved, which the cycle analysis has already excluded).
fn worst_at(m: &Mechanism, phi: f64, sol: &mut Solution, buf: &mut Vec<(usize, f64)>) -> f64 {
    if m.solve(phi, sol).is_err() {
        return 0.0;
    }
    pressure_angles(m, sol, buf);
    buf.iter().fold(0.0f64, |a, &(_, t)| a.max(t))
}

/// Largest pressure angle on the crank travel [ψ0, ψ1] from `start` in the
/// direction `sg`: a scan of 90 steps, then golden-section refinement of the
/// best step to 1e-10 rad.
fn stroke_max(m: &Mechanism, start: f64, sg: f64, (psi0, psi1): (f64, f64), sol: &mut Solution, buf: &mut Vec<(usize, f64)>) -> f64 {
    let n = 90;
    let h = (psi1 - psi0) / n as f64;
    let mut best = (psi0, f64::NEG_INFINITY);
    for k in 0..=n {
        let psi = psi0 + h * k as f64;
        let v = worst_at(m, start + sg * psi, sol, buf);
        if v > best.1 {
            best = (psi, v);
        }
    }
    // golden section on [best − h, best + h] ∩ [ψ0, ψ1]
    let (mut a, mut b) = ((best.0 - h).max(psi0), (best.0 + h).min(psi1));
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let mut c = b - g * (b - a);
    let mut d = a + g * (b - a);
    let mut fc = worst_at(m, start + sg * c, sol, buf);
    let mut fd = worst_at(m, start + sg * d, sol, buf);
    for _ in 0..60 {
        if fc > fd {
            b = d;
            d = c;
            fd = fc;
            c = b - g * (b - a);
            fc = worst_at(m, start + sg * c, sol, buf);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + g * (b - a);
            fd = worst_at(m, start + sg * d, sol, buf);
        }
        if b - a < 1e-10 {
            break;
        }
    }
    best.1.max(fc).max(fd)
}

/// Every named point of the mechanism at crank angle `phi`.
pub fn points_at(m: &Mechanism, phi: f64) -> Result<Vec<(String, tmm_geom::Vec2)>, SynthesisError> {
    let mut sol = m.solution();
    m.solve(phi, &mut sol)?;
    Ok(m.points.iter().zip(&sol.points).map(|(p, s)| (p.name.clone(), s.p)).collect())
}

/// Check a mechanism whose crank must turn fully: K, stroke, pressure angles.
pub fn check_cycle(def: &MechanismDef, expect: &Expect, branch: &str) -> Result<CheckReport, SynthesisError> {
    let m = Mechanism::new(def)?;
    // K = 1 (an axial crank-slider, a centred yoke): both strokes take the
    // same crank angle, so "the slower one" is undefined; the working stroke
    // is then the one on which the output coordinate increases.
    let cycle = match Cycle::new(&m, Working::Slower) {
        Ok(c) => c,
        Err(e) => Cycle::new(&m, Working::Increasing).map_err(|_| e)?,
    };
    if cycle.dead.len() != 2 {
        return Err(SynthesisError::Check(
            "the output has no two dead positions: it does not oscillate".into(),
        ));
    }
    if let Some(k) = expect.k {
        if (cycle.kv - k).abs() > TOL * k.max(1.0) {
            return Err(SynthesisError::Check(format!(
                "K = {:.12} found over the cycle, {k:.12} requested",
                cycle.kv
            )));
        }
    }
    let stroke = match cycle.output.kind {
        OutputKind::Linear => Stroke::Linear(cycle.stroke),
        OutputKind::Angular => Stroke::Angular(cycle.stroke),
    };
    match (expect.stroke, stroke) {
        (Some(Stroke::Linear(h)), Stroke::Linear(s)) | (Some(Stroke::Angular(h)), Stroke::Angular(s)) => {
            if (h - s).abs() > TOL * h.max(1.0) {
                return Err(SynthesisError::Check(format!(
                    "stroke {s:.12} found over the cycle, {h:.12} requested"
                )));
            }
        }
        (None, _) => {}
        _ => return Err(SynthesisError::Check("the output is not of the requested kind".into())),
    }
    let sg = m.crank.omega.signum();
    let mut sol = m.solution();
    let mut buf = Vec::with_capacity(4);
    let w = stroke_max(&m, cycle.start, sg, (0.0, cycle.working_angle), &mut sol, &mut buf);
    let r = stroke_max(&m, cycle.start, sg, (cycle.working_angle, TAU), &mut sol, &mut buf);
    let dead_positions = vec![points_at(&m, cycle.dead[0])?, points_at(&m, cycle.dead[1])?];
    Ok(CheckReport {
        k: Some(cycle.kv),
        theta: Some(cycle.theta),
        stroke: Some(stroke),
        pressure_angle_max: (w, r),
        transmission_angle_min: FRAC_PI_2 - w.max(r),
        crank_turns_fully: true,
        branch: branch.to_string(),
        dead_phi: cycle.dead.clone(),
        dead_positions,
    })
}

/// The limits against the checked pressure angles: an error naming the
/// limit that fails, the angle found and the limit; the nearest feasible
/// value is the one this design reaches.
pub fn check_limits(limits: &Limits, report: &CheckReport) -> Result<(), SynthesisError> {
    let (w, r) = report.pressure_angle_max;
    let eps = 1e-9;
    let fail = |field: &str, what: &str, found: f64, limit: f64| {
        Err(SynthesisError::infeasible(
            field,
            format!(
                "{what} is {:.4}°, the limit {:.4}° cannot be met",
                found.to_degrees(),
                limit.to_degrees()
            ),
            Some(found),
        ))
    };
    if let Some(l) = limits.pressure_working {
        if w > l + eps {
            return fail("limits.pressure_working", "the largest pressure angle on the working stroke", w, l);
        }
    }
    if let Some(l) = limits.pressure_return {
        if r > l + eps {
            return fail("limits.pressure_return", "the largest pressure angle on the return stroke", r, l);
        }
    }
    if let Some(g) = limits.transmission_min {
        let found = FRAC_PI_2 - w.max(r);
        if found < g - eps {
            return fail("limits.transmission_min", "the smallest transmission angle", found, g);
        }
    }
    Ok(())
}

/// The assembly angle is taken this far (rad) past the extended dead
/// position, where the hint "near the extreme position" still picks the
/// branch unambiguously and the scan for dead positions does not start on a
/// root of ds/dφ.
pub const ASSEMBLY_OFFSET: f64 = 0.1;

/// The named point's positions at the two dead positions found by the core
/// must be the construction's extreme positions (in either order) to 1e-9
/// of their size.
pub fn check_extremes(report: &CheckReport, name: &str, want: [Vec2; 2]) -> Result<(), SynthesisError> {
    let got: Vec<Vec2> = report
        .dead_positions
        .iter()
        .filter_map(|v| v.iter().find(|(n, _)| n == name).map(|(_, p)| *p))
        .collect();
    if got.len() != 2 {
        return Err(SynthesisError::Check(format!("point {name} is not in the mechanism")));
    }
    let scale = want[0].hypot().max(want[1].hypot()).max(1.0);
    let d = |a: Vec2, b: Vec2| (a - b).hypot();
    let err = (d(got[0], want[0]).max(d(got[1], want[1]))).min(d(got[0], want[1]).max(d(got[1], want[0])));
    if err > TOL * scale {
        return Err(SynthesisError::Check(format!(
            "the extreme positions of {name} found over the cycle, ({:.9}, {:.9}) and ({:.9}, {:.9}), are {err:.3e} m from the construction's",
            got[0].x, got[0].y, got[1].x, got[1].y
        )));
    }
    Ok(())
}
