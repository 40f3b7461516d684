//! The JSON document of `[cylinder]` (SI, angles in radians): `synthesis`
//! (when made), `geometry`, `analogues` (arrays over the tabulated
//! positions s = k·s_max/10, then the kinetostatics' s), `position` (φ₁,
//! φ₃ there), `control` (A_C, F_K, F_H, s_c), `motion` (arrays over the
//! travel's nodes; `time` is null where it is infinite), `end` (how s_max
//! is reached) and `kinetostatics` (the nine unknowns and the check).

use serde_json::{Map, Value, json};
use tmm_geom::Vec2;
use tmm_linkage::linear::{CylinderState, EndReached, MotionRow, PointQ};

use super::Analysis;
use crate::output::num;

fn col<T>(rows: &[T], f: impl Fn(&T) -> f64) -> Value {
    Value::Array(rows.iter().map(|r| num(f(r))).collect())
}

fn vec2(v: Vec2) -> Value {
    json!([num(v.x), num(v.y)])
}

fn point(rows: &[CylinderState], f: impl Fn(&CylinderState) -> PointQ) -> Value {
    json!({
        "position": Value::Array(rows.iter().map(|r| vec2(f(r).p)).collect()),
        "velocity_analogue": Value::Array(rows.iter().map(|r| vec2(f(r).v)).collect()),
        "acceleration_analogue": Value::Array(rows.iter().map(|r| vec2(f(r).a)).collect()),
    })
}

/// The whole document.
pub fn document(a: &Analysis) -> Value {
    let t = &a.task;
    let d = &t.drive;
    let m = &t.masses;
    let mo = &a.motion;
    let c = &mo.control;
    let mut doc = Map::new();
    if let Some(s) = &t.synthesis {
        let mut syn = Map::new();
        syn.insert("X_D".into(), num(d.d.x));
        syn.insert("Y_D".into(), num(d.d.y));
        syn.insert("l_AB".into(), num(d.lever));
        for (k, v) in &s.angles {
            syn.insert(k.clone(), num(*v));
        }
        // the synthesis' own givens (θ_к or θ_н, Y_D when given), SI and rad
        let given: Map<String, Value> = s.given.iter().map(|(k, v)| (k.clone(), num(*v))).collect();
        syn.insert("given".into(), Value::Object(given));
        if let Some(fp) = &s.free_parameter {
            syn.insert("free_parameter".into(), json!({"name": fp.name, "value": num(fp.value)}));
        }
        doc.insert("synthesis".into(), Value::Object(syn));
    }
    doc.insert(
        "geometry".into(),
        json!({
            "A": [0.0, 0.0], "D": vec2(d.d), "l_AB": num(d.lever), "h_min": num(d.h_min), "h_max": num(d.h_max),
            "rod": num(d.rod), "l_CS2": num(d.rod_center), "l_AK": num(d.load_arm), "alpha": num(d.load_angle),
            "travel": num(d.travel()), "swing": num(t.swing),
        }),
    );
    doc.insert(
        "masses".into(),
        json!({
            "m1": num(m.lever_mass), "I1S": num(m.lever_inertia), "m2": num(m.piston_mass), "I2S": num(m.piston_inertia),
            "m3": num(m.cylinder_mass), "I3S": num(m.cylinder_inertia), "load": num(m.load_mass), "gravity": num(m.gravity),
        }),
    );
    let rows: Vec<CylinderState> = a.table.iter().copied().chain([a.at]).collect();
    doc.insert(
        "analogues".into(),
        json!({
            "s": col(&rows, |r| r.s),
            "phi1": col(&rows, |r| r.phi1), "phi3": col(&rows, |r| r.phi3),
            "omega_q1": col(&rows, |r| r.omega_q1), "omega_q2": col(&rows, |r| r.omega_q3), "omega_q3": col(&rows, |r| r.omega_q3),
            "eps_q1": col(&rows, |r| r.eps_q1), "eps_q2": col(&rows, |r| r.eps_q3), "eps_q3": col(&rows, |r| r.eps_q3),
            "pressure_angle": col(&rows, |r| r.pressure_angle),
            "B": point(&rows, |r| r.b), "C": point(&rows, |r| r.c), "S2": point(&rows, |r| r.s2), "K": point(&rows, |r| r.k),
        }),
    );
    doc.insert(
        "position".into(),
        json!({"s": num(a.at.s), "phi1": num(a.at.phi1), "phi3": num(a.at.phi3)}),
    );
    doc.insert(
        "control".into(),
        json!({
            "work_resistance": num(mo.resistance_work), "F_K": num(c.end), "F_H": num(c.start),
            "switch": num(c.switch), "travel": num(c.travel),
        }),
    );
    let r: &[MotionRow] = &mo.rows;
    doc.insert(
        "motion".into(),
        json!({
            "s": col(r, |x| x.reduced.s),
            "reduced_mass": col(r, |x| x.reduced.mass),
            "reduced_mass_derivative": col(r, |x| x.reduced.mass_derivative),
            "force_resistance": col(r, |x| x.reduced.force),
            "force_control": col(r, |x| x.control),
            "force_total": col(r, |x| x.total),
            "work_resistance": col(r, |x| x.work_resistance),
            "work_control": col(r, |x| x.work_control),
            "work_total": col(r, |x| x.work_total),
            "speed": col(r, |x| x.speed),
            "acceleration": col(r, |x| x.accel),
            "time": Value::Array(r.iter().map(|x| x.time.map_or(Value::Null, num)).collect()),
        }),
    );
    doc.insert(
        "end".into(),
        match mo.end {
            EndReached::Asymptotic { time_constant } => json!({
                "reached": "asymptotically",
                "time": Value::Null,
                "time_constant": time_constant.map_or(Value::Null, num),
            }),
            EndReached::Finite { time } => json!({"reached": "finite", "time": num(time)}),
        },
    );
    let k = &a.reactions;
    doc.insert(
        "kinetostatics".into(),
        json!({
            "s": num(k.s), "speed": num(k.speed), "acceleration": num(k.accel),
            "eps1": num(k.eps1), "eps2": num(k.eps3), "eps3": num(k.eps3),
            "inertia_piston": vec2(k.inertia_piston), "inertia_load": vec2(k.inertia_load),
            "inertia_moments": [num(k.inertia_moments[0]), num(k.inertia_moments[1]), num(k.inertia_moments[2])],
            "R_AX": num(k.r_a.x), "R_AY": num(k.r_a.y), "R_BX": num(k.r_b.x), "R_BY": num(k.r_b.y),
            "R_32": num(k.r_32), "M_32": num(k.m_32), "R_DX": num(k.r_d.x), "R_DY": num(k.r_d.y),
            "F_balancing": num(k.balancing), "F_control": num(a.control_at),
            "check_difference": num(k.balancing - a.control_at),
        }),
    );
    Value::Object(doc)
}
