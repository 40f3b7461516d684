//! The JSON document of a synthesis (SI, angles in radians): the contract
//! `kind`, `given`, `lengths`, `frame`, `k`, `theta`, `stroke` or `swing`,
//! `pressure_angle_max`, `transmission_angle_min`, `free_parameter`, `task`.

use serde_json::{Map, Value, json};
use tmm_geom::Vec2;
use tmm_linkage::synthesis::sweep::Variant;

use super::{Comparison, Solved, stroke_of};
use crate::output::num;

fn xy(p: Vec2) -> Value {
    json!([num(p.x), num(p.y)])
}

fn named(v: &[(String, f64)]) -> Value {
    Value::Object(v.iter().map(|(n, x)| (n.clone(), num(*x))).collect())
}

/// The whole document.
pub fn document(s: &Solved, variants: Option<&[Variant]>, cmp: Option<&Comparison>) -> Value {
    let y = &s.syn;
    let c = &y.check;
    let mut d = Map::new();
    d.insert("units".into(), "SI".into());
    d.insert("kind".into(), s.spec.kind.into());
    d.insert("given".into(), named(&y.given));
    d.insert("lengths".into(), named(&y.lengths));
    d.insert(
        "frame".into(),
        Value::Object(y.frame.iter().map(|(n, p)| (n.clone(), xy(*p))).collect()),
    );
    // the further unknowns of the textbook's problems (φ1н, θ, X_D, …)
    d.insert("angles".into(), named(&y.angles));
    d.insert("coordinates".into(), named(&y.coordinates));
    d.insert("shown_phi".into(), y.shown.iter().map(|&p| num(p)).collect());
    d.insert("k".into(), num(y.k));
    d.insert("theta".into(), num(y.theta));
    if let Some((v, _, word)) = stroke_of(y.stroke) {
        d.insert(word.into(), num(v));
    }
    d.insert(
        "pressure_angle_max".into(),
        json!({"working": num(c.pressure_angle_max.0), "return": num(c.pressure_angle_max.1)}),
    );
    d.insert("transmission_angle_min".into(), num(c.transmission_angle_min));
    d.insert(
        "free_parameter".into(),
        match &y.free_parameter {
            Some(f) => json!({"name": f.name, "value": num(f.value), "reason": f.reason}),
            None => Value::Null,
        },
    );
    let mut check = Map::new();
    check.insert("k".into(), c.k.map_or(Value::Null, num));
    check.insert("theta".into(), c.theta.map_or(Value::Null, num));
    if let Some((v, _, word)) = stroke_of(c.stroke) {
        check.insert(word.into(), num(v));
    }
    check.insert("crank_turns_fully".into(), c.crank_turns_fully.into());
    check.insert("branch".into(), c.branch.clone().into());
    check.insert("dead_phi".into(), c.dead_phi.iter().map(|&p| num(p)).collect());
    d.insert("check".into(), Value::Object(check));
    d.insert("overall_size".into(), num(y.overall_size()));
    let k = &y.construction;
    d.insert(
        "construction".into(),
        json!({
            "point": k.point,
            "extremes": [xy(k.extremes[0]), xy(k.extremes[1])],
            "locus": k.locus.map(|l| json!({"center": xy(l.center), "radius": num(l.radius), "arc_start": num(l.arc_start), "arc_sweep": num(l.arc_sweep)})),
            "pivot": xy(k.pivot),
            "lines": k.lines.iter().map(|(n, a, b)| json!({"name": n, "from": xy(*a), "to": xy(*b)})).collect::<Vec<_>>(),
        }),
    );
    d.insert("task".into(), s.linkage.clone().into());
    if let Some(v) = variants {
        d.insert("variants".into(), self::variants_rows(v));
    }
    if let Some(c) = cmp {
        d.insert("given_linkage".into(), json!({"k": num(c.k), "stroke": num(c.stroke)}));
    }
    Value::Object(d)
}

fn variants_rows(v: &[Variant]) -> Value {
    v.iter()
        .map(|x| match &x.outcome {
            Ok(r) => json!({
                "value": num(x.value),
                "feasible": true,
                "lengths": named(&r.lengths),
                "k": r.k.map_or(Value::Null, num),
                "pressure_angle_max": {"working": num(r.pressure_angle_max.0), "return": num(r.pressure_angle_max.1)},
                "transmission_angle_min": num(r.transmission_angle_min),
                "size": num(r.size),
            }),
            Err(e) => json!({"value": num(x.value), "feasible": false, "error": e.to_string()}),
        })
        .collect()
}

/// The variants of a sweep as a JSON array.
pub fn variants(_spec: &super::Spec, v: &[Variant]) -> Value {
    variants_rows(v)
}
