//! The JSON document of the `[forces]` section (SI, angles in radians).
//! Per position: `phi`, `loads` per link (inertia plus external, reduced to the
//! centre of mass: `fx`, `fy`, and `m` about S), `reactions` (the force
//! exerted by link `from` on link `on`), `balancing_moment` (the torque the
//! drive applies to the input link, counter-clockwise positive),
//! `balancing_force` (at the crank pin, perpendicular to the crank, positive
//! along k × crank), `frame_reaction_with_balancing_force` (the frame's
//! reaction on the crank when that force holds it instead of the torque),
//! `zhukovsky_moment`.

use serde_json::{Map, Value, json};

use super::task::ForcesTask;
use super::{Analysis, Row};
use crate::linkage::Loaded;
use crate::output::num;

/// The name of a pair: its point (`B`), the same the user gave.
pub fn pair_name(l: &Loaded, pair: usize) -> String {
    l.mech.points[l.mech.pairs[pair].point()].name.clone()
}

fn position(l: &Loaded, r: &Row) -> Value {
    let m = &l.mech;
    let f = &r.fs;
    let mut loads = Map::new();
    for (i, lf) in f.links.iter().enumerate().skip(1) {
        loads.insert(
            m.link_names[i].clone(),
            json!({
                "fx": num(lf.force.x), "fy": num(lf.force.y), "m": num(lf.moment),
                "s": [num(lf.s.x), num(lf.s.y)],
                "inertia_force": [num(lf.inertia_force.x), num(lf.inertia_force.y)],
                "inertia_moment": num(lf.inertia_moment),
                "weight": [num(lf.weight.x), num(lf.weight.y)],
                "external_force": [num(lf.external_force.x), num(lf.external_force.y)],
                "external_moment": num(lf.external_moment),
            }),
        );
    }
    let reactions: Vec<Value> = f
        .reactions
        .iter()
        .map(|x| {
            json!({
                "pair": pair_name(l, x.pair),
                "kind": if x.prismatic { "P" } else { "R" },
                "from": m.link_names[x.from],
                "on": m.link_names[x.on],
                "fx": num(x.force.x), "fy": num(x.force.y), "magnitude": num(x.force.hypot()),
                "normal": num(x.normal), "tangential": num(x.tangential),
                "at": [num(x.at.x), num(x.at.y)],
                "offset": num(x.offset),
            })
        })
        .collect();
    let mut v = json!({
        "label": r.label,
        "phi": num(r.phi),
        "omega1": num(r.sol.links[m.crank.link].omega),
        "epsilon1": num(r.sol.links[m.crank.link].eps),
        "psi": num(r.psi),
        "working_stroke": f.phase.map(|p| p.working),
        "resistance": f.resistance.iter().map(|&v| num(v)).collect::<Vec<_>>(),
        "loads": loads,
        "reactions": reactions,
        "balancing_moment": num(f.balancing_moment),
        "balancing_force": num(f.balancing_force),
        "balancing_force_vector": [num(f.balancing_force_vec.x), num(f.balancing_force_vec.y)],
        // the frame's reaction on the crank when the balancing force, not
        // the torque, holds the crank (the input link's force plan)
        "frame_reaction_with_balancing_force": [num(f.pivot_reaction_with_force.x), num(f.pivot_reaction_with_force.y)],
        "zhukovsky_moment": num(f.zhukovsky_moment),
        "relative_difference": num(f.relative_difference()),
    });
    // the loads on sliders (gas forces, forces on a stroke, friction), N,
    // and the angle of the machine's cycle, when there are any
    if !f.slider_forces.is_empty() {
        if let Some(o) = v.as_object_mut() {
            o.insert("cycle_angle".into(), json!(num(f.cycle_angle)));
            o.insert(
                "slider_forces".into(),
                json!(f.slider_forces.iter().map(|p| [num(p.x), num(p.y)]).collect::<Vec<_>>()),
            );
        }
    }
    v
}

/// The whole document.
pub fn document(l: &Loaded, t: &ForcesTask, a: &Analysis) -> Value {
    let m = &l.mech;
    let mut links = Map::new();
    for (i, ld) in t.loads.links.iter().enumerate().skip(1) {
        links.insert(
            m.link_names[i].clone(),
            json!({
                "mass": num(ld.mass), "inertia": num(ld.inertia),
                "mass_center_local": [num(m.mass_centers[i].x), num(m.mass_centers[i].y)],
                "moment": num(ld.moment),
                "forces": ld.forces.iter().map(|f| json!({"local": [num(f.local.x), num(f.local.y)], "force": [num(f.force.x), num(f.force.y)]})).collect::<Vec<_>>(),
            }),
        );
    }
    let max_diff = a.curve.iter().map(|c| rel(c[2], c[3])).fold(0.0, f64::max);
    let mut doc = json!({
        "units": "SI",
        "assumptions": format!(
            "rigid links, one-DOF pairs without clearances, {} (seed 000, assumptions 1.1–1.4); {}",
            if super::text::has_friction(t) {
                "friction neglected in the pairs, the given sliding friction on the guides taken"
            } else {
                "friction neglected"
            },
            match t.crank_motion {
                super::CrankMotion::Constant => "crank speed ω1 constant as given",
                super::CrankMotion::Dynamics => "the crank moves with its true ω1(φ), ε1(φ) from [dynamics]",
            }
        ),
        "structure": m.structure.formula,
        "gravity": [num(t.loads.gravity.x), num(t.loads.gravity.y)],
        // the flywheel's weight at the crank's pivot, N (null when not applied)
        "flywheel_weight": a.flywheel_weight.map(num),
        "omega1": num(m.crank.omega),
        "crank_motion": match t.crank_motion { super::CrankMotion::Constant => "constant", super::CrankMotion::Dynamics => "dynamics" },
        "links": links,
        "detail": position(l, &a.detail),
        "positions": a.rows.iter().map(|r| position(l, r)).collect::<Vec<_>>(),
        "cycle": a.curve.iter().map(|c| json!({"psi": num(c[0]), "phi": num(c[1]), "balancing_moment": num(c[2]), "zhukovsky_moment": num(c[3])})).collect::<Vec<_>>(),
        "max_relative_difference": num(max_diff),
        "lever": a.lever.iter().map(|x| json!({"label": x.label, "image": [num(x.image.x), num(x.image.y)], "force": [num(x.force.x), num(x.force.y)]})).collect::<Vec<_>>(),
    });
    if let Some(rc) = &a.reaction_cycle {
        doc["reaction_cycle"] = rc.json();
    }
    if !a.windows.is_empty() {
        doc["stroke_windows"] = json!(
            a.windows
                .iter()
                .map(|w| json!({
                    "load": t.slider_fields.get(w.load),
                    "window": [num(w.window.0), num(w.window.1)],
                    "stroke": num(w.stroke),
                    "phi_start": num(w.phi_start),
                    "start": num(w.on), "end": num(w.off), "return": num(w.back), "overrun": num(w.overrun),
                }))
                .collect::<Vec<_>>()
        );
    }
    if let Some(b) = &a.beam {
        let s = &b.sizes;
        let at = |i: usize| b.samples.get(i).map_or(Value::Null, |x| num(x.z));
        doc["strength"] = json!({
            "link": m.link_names[b.beam.link],
            "between": [b.names.0, b.names.1],
            "length": num(b.beam.length),
            "allowed_stress": num(b.allowed),
            "loads": b.beam.loads.iter().map(|x| json!({"label": x.label, "z": num(x.z), "axial": num(x.fe), "transverse": num(x.fn_), "couple": num(x.couple)})).collect::<Vec<_>>(),
            "distributed_axial": b.beam.qe.iter().map(|&v| num(v)).collect::<Vec<_>>(),
            "distributed_transverse": b.beam.qn.iter().map(|&v| num(v)).collect::<Vec<_>>(),
            "diagrams": b.samples.iter().map(|x| json!({"z": num(x.z), "N": num(x.n), "Q": num(x.q), "M": num(x.m)})).collect::<Vec<_>>(),
            "round": {"d": num(s.round_d), "dangerous_z": at(s.round_at)},
            "rectangle": {"b": num(s.rect_b), "h": num(s.rect_h), "h_over_b": num(b.k), "dangerous_z": at(s.rect_at)},
            "i_beam": s.ibeam.map(|(ib, i, sig)| json!({"gost_8239_number": ib.number, "area": num(ib.area), "w": num(ib.w), "stress": num(sig), "dangerous_z": at(i)})),
        });
    }
    doc
}

/// Relative difference of two values (0 when both are 0).
pub fn rel(a: f64, b: f64) -> f64 {
    let s = a.abs().max(b.abs());
    if s == 0.0 { 0.0 } else { (a - b).abs() / s }
}
