//! The cam design as one JSON document: SI, angles in radians, `"units": "SI"`.

use serde_json::{Map, Value, json};
use tmm_cams::design::{CamDesign, CamTask};
use tmm_cams::mechanism::Mechanism;

use crate::output::num;

fn opt(x: Option<f64>) -> Value {
    x.map_or(Value::Null, num)
}

fn arr(it: impl Iterator<Item = f64>) -> Value {
    Value::Array(it.map(num).collect())
}

/// Per-phase summary: kind, start, angle, law, continuity order, peak analogs.
pub fn phases(task: &CamTask) -> Value {
    let p = &task.program;
    let items: Vec<Value> = p
        .phases()
        .iter()
        .enumerate()
        .map(|(k, ph)| {
            let mut m = Map::new();
            m.insert("kind".into(), ph.kind.name().into());
            m.insert("start".into(), num(p.start(k)));
            m.insert("angle".into(), num(ph.angle));
            if let Some(law) = &ph.law {
                m.insert("law".into(), law.kind().to_string().into());
                m.insert("continuity".into(), law.continuity().into());
                let n = 2000;
                let (mut v, mut a, mut j) = (0.0f64, 0.0f64, 0.0f64);
                for i in 0..=n {
                    let q = p.eval_in(k, ph.angle * i as f64 / n as f64);
                    v = v.max(q.v.abs());
                    a = a.max(q.a.abs());
                    j = j.max(q.j.abs());
                }
                m.insert("ds_dphi_max".into(), num(v));
                m.insert("d2s_dphi2_max".into(), num(a));
                m.insert("d3s_dphi3_max".into(), num(j));
            }
            Value::Object(m)
        })
        .collect();
    Value::Array(items)
}

/// The whole document.
pub fn document(task: &CamTask, d: &CamDesign) -> Value {
    let w = task.omega;
    let prof = &d.profile;
    let mut doc = json!({
        "units": "SI",
        "follower": task.follower.name(),
        "rotation": task.rotation.name(),
        "stroke": num(task.program.stroke()),
        "omega": num(w),
        "r0": num(d.r0),
        "rb": num(d.rb),
        "e": opt(d.offset()),
        "roller_radius": num(d.roller),
        "roller_radius_rule": opt(d.roller_rule),
        "pressure_angle_max_rise": num(d.pressure_max_rise),
        "pressure_angle_max_return": num(d.pressure_max_return),
        "pressure_angle_limit_rise": if d.mechanism.is_flat() { Value::Null } else { num(task.limits.rise) },
        "pressure_angle_limit_return": if d.mechanism.is_flat() { Value::Null } else { num(task.limits.ret) },
        "rho_min": num(d.rho_min),
        "rho_min_convex": num(d.rho_min_convex),
        "rho_min_concave": opt(d.rho_min_concave),
        "rho_min_pitch": opt(d.rho_min_pitch.filter(|r| r.is_finite())),
        // a roller at least as large as the pitch curve's smallest convex radius loops the profile
        "undercut": d.rho_min_pitch.is_some_and(|r| d.roller > 0.0 && d.roller >= r),
        "phases": phases(task),
    });
    let m = doc.as_object_mut().expect("object");
    if let Some(f) = d.face {
        m.insert("face_width".into(), num(f.width));
        m.insert("face_contact_min".into(), num(f.contact_min));
        m.insert("face_contact_max".into(), num(f.contact_max));
        m.insert("face_margin".into(), num(task.face_margin));
    }
    match d.mechanism {
        Mechanism::OscillatingRoller {
            pivot, arm, psi0, kappa, ..
        } => {
            m.insert("pivot".into(), json!([num(pivot.x), num(pivot.y)]));
            m.insert("pivot_distance".into(), num(pivot.hypot()));
            m.insert("arm".into(), num(arm));
            m.insert("arm_angle_start".into(), num(psi0));
            m.insert("arm_turns_ccw_on_rise".into(), (kappa > 0.0).into());
        }
        Mechanism::OscillatingFlat { a, delta0 } => {
            m.insert("pivot".into(), json!([num(a), 0.0]));
            m.insert("pivot_distance".into(), num(a));
            m.insert("face_angle_start".into(), num(delta0));
        }
        Mechanism::TranslatingRoller { s0, .. } => {
            m.insert("s0".into(), num(s0));
        }
        Mechanism::TranslatingFlat { .. } => {}
    }
    m.insert("phi".into(), arr(prof.phi.iter().copied()));
    m.insert("time".into(), arr(prof.phi.iter().map(|p| p / w)));
    m.insert("s".into(), arr(prof.motion.iter().map(|q| q.s)));
    m.insert("ds_dphi".into(), arr(prof.motion.iter().map(|q| q.v)));
    m.insert("d2s_dphi2".into(), arr(prof.motion.iter().map(|q| q.a)));
    m.insert("d3s_dphi3".into(), arr(prof.motion.iter().map(|q| q.j)));
    m.insert("velocity".into(), arr(prof.motion.iter().map(|q| q.v * w)));
    m.insert("acceleration".into(), arr(prof.motion.iter().map(|q| q.a * w * w)));
    m.insert("jerk".into(), arr(prof.motion.iter().map(|q| q.j * w * w * w)));
    m.insert("pressure_angle".into(), arr(prof.pressure.iter().copied()));
    m.insert("pitch_x".into(), arr(prof.pitch.iter().map(|p| p.x)));
    m.insert("pitch_y".into(), arr(prof.pitch.iter().map(|p| p.y)));
    m.insert("working_x".into(), arr(prof.working.iter().map(|p| p.x)));
    m.insert("working_y".into(), arr(prof.working.iter().map(|p| p.y)));
    m.insert("curvature".into(), arr(prof.curvature.iter().copied()));
    doc
}
