//! The mechanism at any crank angle (положение механизма при заданном угле
//! кривошипа): the frames of the animation with the traced paths of its
//! points, and the plans, force drawings and Zhukovsky's lever at the angle
//! the slider or the dragged crank sets. The drawings come from the same
//! code as the CLI's files (`tmm_report::linkage::drawings`,
//! `tmm_report::forces::drawings`), asked for one position.

use std::f64::consts::TAU;

use serde_json::{Value, json};
use tmm_linkage::cycle::Cycle;
use tmm_linkage::mechanism::Pair;

use crate::page::Page;
use crate::reply;

/// A guide's line at one frame: a point of it, its unit direction (both in
/// the frame of the machine, m) and the slider's place along it from that
/// point, m.
type GuidePose = ([f64; 2], [f64; 2], f64);

/// The links drawn as segments between their turning joints, as pairs of
/// point indices (a link with more than three joints is drawn as a chain).
fn link_segments(m: &tmm_linkage::Mechanism) -> Vec<(usize, usize)> {
    let mut segs = Vec::new();
    for li in 1..m.link_names.len() {
        let mut joints: Vec<usize> = Vec::new();
        for p in m.pairs.iter().filter(|p| matches!(p, Pair::R { .. })) {
            let (a, b) = p.links();
            if (a == li || b == li) && !joints.contains(&p.point()) {
                joints.push(p.point());
            }
        }
        for i in 0..joints.len() {
            for j in i + 1..joints.len() {
                if joints.len() <= 3 || j == i + 1 {
                    segs.push((joints[i], joints[j]));
                }
            }
        }
    }
    segs
}

/// The mechanism at `n` crank angles equally spaced over one revolution from
/// the start of the working stroke, in the direction of rotation:
/// `{"names", "segments", "pivot", "pin", "start", "direction", "phi": [n],
/// "xy": [n][points][2], "sliders": [{"point", "angle": [n]}], "guides":
/// [{"fixed": true, "from", "to"} | {"fixed": false, "frames": [n][2][2]}]}`
/// (m, rad; a guide spans its slider's travel and a fifth more at each end).
/// `{"none": true}` without a linkage.
pub fn frames(p: &Page, n: usize) -> String {
    let n = n.clamp(2, 3600);
    let Some(loaded) = &p.linkage else {
        return json!({ "none": true }).to_string();
    };
    let m = &loaded.mech;
    let cycle = match Cycle::new(m, loaded.task.working) {
        Ok(c) => c,
        Err(e) => return reply::from_error(&p.task, &tmm_report::linkage::locate(&p.task, &loaded.task, &e)).to_string(),
    };
    let sg = m.crank.omega.signum();
    let mut sol = m.solution();
    let mut phis = Vec::with_capacity(n);
    let mut xy = Vec::with_capacity(n);
    // per prismatic pair: the guide's pose and the slider's place along it
    let prismatic: Vec<&Pair> = m.pairs.iter().filter(|p| matches!(p, Pair::P { .. })).collect();
    let mut guide_poses: Vec<Vec<GuidePose>> = vec![Vec::with_capacity(n); prismatic.len()];
    for k in 0..n {
        let phi = tmm_geom::angle::wrap_2pi(cycle.start + sg * TAU * k as f64 / n as f64);
        if let Err(e) = m.solve(phi, &mut sol) {
            return reply::from_error(&p.task, &tmm_report::linkage::locate(&p.task, &loaded.task, &e)).to_string();
        }
        phis.push(phi);
        let pts: Vec<[f64; 2]> = sol.points.iter().map(|s| [s.p.x, s.p.y]).collect();
        for (pp, poses) in prismatic.iter().zip(guide_poses.iter_mut()) {
            if let Pair::P { guide, q, d, point, .. } = **pp {
                let l = &sol.links[guide];
                let rot = |v: tmm_geom::Vec2| [l.u.x * v.x - l.u.y * v.y, l.u.y * v.x + l.u.x * v.y];
                let (qg, dg) = (rot(q), rot(d));
                let qg = [l.o.x + qg[0], l.o.y + qg[1]];
                let pt = pts[point];
                let t = (pt[0] - qg[0]) * dg[0] + (pt[1] - qg[1]) * dg[1];
                poses.push((qg, dg, t));
            }
        }
        xy.push(pts);
    }
    // the guides: a line along each prismatic pair over the slider's travel
    // (a fifth longer at each end), fixed or carried by its link
    let mut sliders = Vec::new();
    let mut guides = Vec::new();
    for (pp, poses) in prismatic.iter().zip(&guide_poses) {
        let Pair::P { guide, point, .. } = **pp else { continue };
        let (lo, hi) = poses
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.2), b.max(p.2)));
        let pad = 0.2 * (hi - lo).max(0.02);
        let seg = |(q, d, _): &GuidePose| {
            [
                [q[0] + d[0] * (lo - pad), q[1] + d[1] * (lo - pad)],
                [q[0] + d[0] * (hi + pad), q[1] + d[1] * (hi + pad)],
            ]
        };
        let angles: Vec<f64> = poses.iter().map(|(_, d, _)| d[1].atan2(d[0])).collect();
        sliders.push(json!({ "point": point, "angle": angles }));
        if guide == 0 {
            let [a, b] = seg(&poses[0]);
            guides.push(json!({ "fixed": true, "from": a, "to": b }));
        } else {
            let fr: Vec<[[f64; 2]; 2]> = poses.iter().map(seg).collect();
            guides.push(json!({ "fixed": false, "frames": fr }));
        }
    }
    let names: Vec<&str> = m.points.iter().map(|q| q.name.as_str()).collect();
    let segs: Vec<[usize; 2]> = link_segments(m).into_iter().map(|(a, b)| [a, b]).collect();
    json!({
        "ok": true,
        "names": names,
        "segments": segs,
        "pivot": m.crank.pivot_point,
        "pin": m.crank.pin,
        "start": cycle.start,
        "direction": sg,
        "phi": phis,
        "xy": xy,
        "sliders": sliders,
        "guides": guides,
    })
    .to_string()
}

/// The drawings at the crank angle `phi` (rad): `{"ok", "phi", "psi",
/// "velocity_plan", "acceleration_plan"}` (SVG text) and, when `with_forces`
/// and the task has forces, `"forces": {"files": {name: svg},
/// "balancing_moment", "zhukovsky_moment"}` (the animation asks for the plans
/// only; a still angle gets the forces too).
pub fn at_angle(p: &Page, phi: f64, with_forces: bool) -> String {
    if !phi.is_finite() {
        return reply::error_json("the crank angle must be a finite number", None, None);
    }
    match try_at_angle(p, phi, with_forces) {
        Ok(v) => v.to_string(),
        Err(e) => reply::from_error(&p.task, &e).to_string(),
    }
}

fn try_at_angle(p: &Page, phi: f64, with_forces: bool) -> Result<Value, tmm_report::Error> {
    let Some(l) = &p.linkage else {
        return Ok(json!({ "none": true }));
    };
    // Only the position at the angle: the mechanism is already loaded and
    // no cycle or diagram is recomputed, so a frame of the animation costs
    // one solution and two plans.
    let m = &l.mech;
    let mut sol = m.solution();
    m.solve(phi, &mut sol)
        .map_err(|e| tmm_report::linkage::locate(&p.task, &l.task, &e))?;
    let (velocity, acceleration) = tmm_report::linkage::plan_drawings(l, &sol, phi, &p.task);
    let psi = p.cycle_start.map(|start| (m.crank.omega.signum() * (phi - start)).rem_euclid(TAU));
    let mut v = json!({
        "ok": true,
        "phi": phi,
        "psi": psi,
        "velocity_plan": velocity,
        "acceleration_plan": acceleration,
    });
    if with_forces && let Some((fl, ft)) = &p.forces {
        let fa = tmm_report::forces::analyse(&p.task, fl, ft, Some(phi))?;
        let fd = tmm_report::forces::drawings(fl, ft, &fa, &p.task)?;
        let mut files = serde_json::Map::new();
        for d in fd.iter().filter(|d| d.extension() == "svg" && !d.path.starts_with("strength")) {
            files.insert(d.path.clone(), d.as_text().unwrap_or_default().into());
        }
        let j = tmm_report::forces::json_document(fl, ft, &fa);
        v["forces"] = json!({
            "files": files,
            "balancing_moment": j["detail"]["balancing_moment"],
            "zhukovsky_moment": j["detail"]["zhukovsky_moment"],
        });
    }
    Ok(v)
}

/// The plans' vectors at the crank angle `phi` (rad), for a frame of the
/// animation: `{"ok", "phi", "psi", "velocity": [v], "acceleration": [v]}`
/// with each `v = {"label", "kind", "from": [x, y], "to": [x, y]}` (m/s,
/// m/s²; the pole at the origin). One solution of the loaded mechanism and
/// its plans ([`tmm_linkage::plans::plans`]); the page draws them while the
/// crank turns and shows the drawings of [`at_angle`] when it stops.
///
/// ```
/// let p = tmm_web::page::Page::new("t.toml", tmm_report::run::DEFAULT_TASK, None).unwrap();
/// let v: serde_json::Value = serde_json::from_str(&tmm_web::angle::plan_vectors(&p, 1.0)).unwrap();
/// assert_eq!(v["ok"], true);
/// assert!(v["velocity"].as_array().unwrap().iter().any(|x| x["label"] == "V_B" && x["kind"] == "Absolute"));
/// ```
pub fn plan_vectors(p: &Page, phi: f64) -> String {
    if !phi.is_finite() {
        return reply::error_json("the crank angle must be a finite number", None, None);
    }
    let Some(l) = &p.linkage else {
        return json!({ "none": true }).to_string();
    };
    let m = &l.mech;
    let mut sol = m.solution();
    if let Err(e) = m.solve(phi, &mut sol) {
        return reply::from_error(&p.task, &tmm_report::linkage::locate(&p.task, &l.task, &e)).to_string();
    }
    let plans = tmm_linkage::plans::plans(m, &sol);
    let list = |v: &[tmm_linkage::plans::PlanVector]| -> Vec<Value> {
        v.iter()
            .map(|x| {
                json!({
                    "label": x.label,
                    "kind": format!("{:?}", x.kind),
                    "from": [x.from.x, x.from.y],
                    "to": [x.to.x, x.to.y],
                })
            })
            .collect()
    };
    let psi = p.cycle_start.map(|start| (m.crank.omega.signum() * (phi - start)).rem_euclid(TAU));
    json!({
        "ok": true,
        "phi": phi,
        "psi": psi,
        "velocity": list(&plans.velocity),
        "acceleration": list(&plans.acceleration),
    })
    .to_string()
}
