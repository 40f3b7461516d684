//! The JSON document of a gear pair (SI, angles in rad, `"units": "SI"`).

use serde_json::{Map, Value, json};
use tmm_gears::generate::ToothProfile;
use tmm_gears::{Kind, Limits, Pair};

use super::solve::Solved;
use crate::output::num;

/// The pair as JSON: the keys of the issue (`a, aw, alpha_w, …, theta2_max`),
/// the checks with value, limit and verdict, the sliding table, and how the
/// shifts were obtained.
pub fn pair_json(s: &Solved, lim: &Limits, profiles: Option<(&ToothProfile, &ToothProfile)>) -> Value {
    let p: &Pair = &s.pair;
    let mut o = Map::new();
    o.insert("units".into(), "SI".into());
    let sp = &p.spec;
    o.insert(
        "kind".into(),
        if sp.kind == Kind::Internal { "internal" } else { "external" }.into(),
    );
    o.insert("z1".into(), sp.z1.into());
    o.insert("z2".into(), sp.z2.into());
    o.insert("m".into(), num(sp.m));
    o.insert("x1".into(), num(sp.x1));
    o.insert("x2".into(), num(sp.x2));
    o.insert("rack".into(), json!({"alpha": num(sp.rack.alpha), "ha": num(sp.rack.ha), "c": num(sp.rack.c), "hl": num(sp.rack.hl), "rho_f": num(sp.rack.fillet_radius() * sp.m), "rho_f_reduced": s.fillet.reduced}));
    let kv: [(&str, f64); 27] = [
        ("a", p.a),
        ("inv_alpha_w", p.inv_alpha_w),
        ("aw", p.aw),
        ("alpha_w", p.alpha_w),
        ("y", p.y),
        ("dy", p.dy),
        ("u", p.u),
        ("p", p.p),
        ("pb", p.pb),
        ("d1", p.w1.d),
        ("d2", p.w2.d),
        ("db1", p.w1.db),
        ("db2", p.w2.db),
        ("dw1", p.w1.dw),
        ("dw2", p.w2.dw),
        ("da1", p.w1.da),
        ("da2", p.w2.da),
        ("df1", p.w1.df),
        ("df2", p.w2.df),
        ("h1", p.w1.h),
        ("h2", p.w2.h),
        ("s1", p.w1.s),
        ("s2", p.w2.s),
        ("sa1", p.w1.sa),
        ("sa2", p.w2.sa),
        ("eps_alpha", p.eps_alpha),
        ("eps_alpha_gost", p.eps_alpha_gost),
    ];
    for (k, v) in kv {
        o.insert(k.into(), num(v));
    }
    let more: [(&str, f64); 9] = [
        ("alpha_a1", p.w1.alpha_a),
        ("alpha_a2", p.w2.alpha_a),
        ("rho_p1", p.w1.rho_p),
        ("rho_p2", p.w2.rho_p),
        ("rho_l1", p.w1.rho_l),
        ("rho_l2", p.w2.rho_l),
        ("g", p.g),
        ("active_start", p.s_start),
        ("active_end", p.s_end),
    ];
    for (k, v) in more {
        o.insert(k.into(), num(v));
    }
    o.insert("xmin1".into(), p.w1.xmin.map_or(Value::Null, num));
    o.insert("xmin2".into(), p.w2.xmin.map_or(Value::Null, num));
    o.insert("theta1_max".into(), p.theta1_max().map_or(Value::Null, num));
    o.insert("theta2_max".into(), p.theta2_max().map_or(Value::Null, num));
    // null above means unbounded: the real active line reaches N1 (N2)
    o.insert("theta1_unbounded".into(), p.theta1_max().is_none().into());
    o.insert("theta2_unbounded".into(), p.theta2_max().is_none().into());
    if let Some(t) = p.tip_interference {
        o.insert("tip_interference".into(), num(t));
    }
    let mut checks = Map::new();
    for c in p.checks(lim).as_slice() {
        checks.insert(
            c.kind.key(),
            json!({"value": num(c.value), "limit": num(c.limit), "pass": c.pass, "what": c.kind.describe()}),
        );
    }
    o.insert("checks".into(), Value::Object(checks));
    o.insert("all_checks_pass".into(), p.checks(lim).all_pass().into());
    let table: Vec<Value> = p
        .sliding_table(11)
        .iter()
        .map(|q| json!({"s": num(q.s), "rho1": num(q.s), "rho2": num(q.rho2), "theta1": num(q.theta1), "theta2": num(q.theta2)}))
        .collect();
    o.insert("sliding".into(), Value::Array(table));
    let mut how = Map::new();
    how.insert("criterion".into(), s.criterion.map_or(Value::Null, |c| c.name().into()));
    how.insert("reason".into(), s.reason.clone().map_or(Value::Null, Value::from));
    how.insert("aw_required".into(), s.aw_required.map_or(Value::Null, num));
    o.insert("shifts".into(), Value::Object(how));
    if let Some((t1, t2)) = profiles {
        let pts = |t: &ToothProfile| -> Value { Value::Array(t.tooth_outline().iter().map(|&(x, y)| json!([num(x), num(y)])).collect()) };
        o.insert("profiles".into(), json!({"tooth1": pts(t1), "tooth2": pts(t2)}));
    }
    Value::Object(o)
}
