//! The JSON document of the `[linkage]` section (SI, angles in radians).

use serde_json::{Map, Value, json};

use super::{Analysis, Loaded, Row};
use crate::output::num;

/// One position: every point's and link's state, the output, the pressure angles.
pub(super) fn row_json(l: &Loaded, r: &Row) -> Value {
    let m = &l.mech;
    let mut points = Map::new();
    for (i, p) in m.points.iter().enumerate() {
        let s = &r.sol.points[i];
        points.insert(
            p.name.clone(),
            json!({"x": num(s.p.x), "y": num(s.p.y), "vx": num(s.v.x), "vy": num(s.v.y), "ax": num(s.a.x), "ay": num(s.a.y)}),
        );
    }
    let mut links = Map::new();
    for (i, n) in m.link_names.iter().enumerate().skip(1) {
        let s = &r.sol.links[i];
        // every link's centre of mass, slider blocks made by tmm included (the
        // point the kinetostatics loads with m·a_S)
        let c = m.mass_center(&r.sol, i);
        links.insert(
            n.clone(),
            json!({"angle": num(s.angle()), "omega": num(s.omega), "epsilon": num(s.eps),
                "mass_center": {"x": num(c.p.x), "y": num(c.p.y), "vx": num(c.v.x), "vy": num(c.v.y), "ax": num(c.a.x), "ay": num(c.a.y)}}),
        );
    }
    let mut pa = Map::new();
    for &(p, v) in &r.pressure {
        pa.insert(m.points[p].name.clone(), num(v));
    }
    json!({
        "label": r.pos.label,
        "phi": num(r.pos.phi),
        "psi": num(r.pos.psi),
        "points": points,
        "links": links,
        "output": {"s": num(r.analogs.0), "ds_dphi": num(r.analogs.1), "d2s_dphi2": num(r.analogs.2)},
        "pressure_angles": pa,
    })
}

/// The name of the point of a pair.
fn pair_point<'a>(p: &tmm_linkage::mechanism::Pair, m: &'a tmm_linkage::mechanism::Mechanism) -> &'a str {
    let i = match *p {
        tmm_linkage::mechanism::Pair::R { point, .. } | tmm_linkage::mechanism::Pair::P { point, .. } => point,
    };
    m.points.get(i).map_or("", |q| q.name.as_str())
}

/// The geometry as analysed (размеры звеньев): each link's points in its
/// own frame, the distance between every two of them (its lengths: l_OA,
/// l_CB, l_CD, l_BD of a three-joint rocker), its centre of mass; the frame's
/// fixed points and the distance between every two; each slider's guide.
fn geometry(l: &Loaded) -> Value {
    let d = &l.def;
    let pairwise = |pts: &[(String, tmm_geom::Vec2)]| -> Map<String, Value> {
        let mut m = Map::new();
        for (i, (a, pa)) in pts.iter().enumerate() {
            for (b, pb) in &pts[i + 1..] {
                m.insert(format!("{a}{b}"), num((*pb - *pa).hypot()));
            }
        }
        m
    };
    let mut links = Map::new();
    for k in &d.links {
        let mut pts = Map::new();
        for (n, p) in &k.points {
            pts.insert(n.clone(), json!([num(p.x), num(p.y)]));
        }
        links.insert(
            k.name.clone(),
            json!({"points": pts, "lengths": pairwise(&k.points),
                "mass_center": [num(k.mass_center.x), num(k.mass_center.y)]}),
        );
    }
    let mut fixed = Map::new();
    for (n, p) in &d.fixed {
        fixed.insert(n.clone(), json!([num(p.x), num(p.y)]));
    }
    let sliders: Vec<Value> = d
        .sliders
        .iter()
        .map(|s| {
            json!({"link": s.slider, "point": s.point, "guide_link": s.guide_link,
                "through": [num(s.through.x), num(s.through.y)], "angle": num(s.angle)})
        })
        .collect();
    json!({"links": links, "fixed": fixed, "frame_lengths": pairwise(&d.fixed), "sliders": sliders})
}

/// The vectors of a plan.
pub(super) fn plan_vectors(v: &[tmm_linkage::plans::PlanVector]) -> Vec<Value> {
    v.iter()
        .map(|p| json!({"label": p.label, "kind": p.kind, "from": [num(p.from.x), num(p.from.y)], "to": [num(p.to.x), num(p.to.y)]}))
        .collect()
}

/// The parts of the document that do not depend on the input's kind: the
/// structure, the geometry and the output link.
pub(super) fn common(l: &Loaded, a: &Analysis) -> Value {
    let m = &l.mech;
    let s = &m.structure;
    let groups: Vec<Value> = s
        .groups
        .iter()
        .map(|g| {
            let pair_names: Vec<&str> = g
                .pair_ids
                .iter()
                .filter_map(|&i| m.pairs.get(i))
                .map(|p| pair_point(p, m))
                .collect();
            json!({"class": g.class, "order": g.order, "kind": g.kind, "links": g.links, "pairs": pair_names})
        })
        .collect();
    // the kinematic pairs (кинематические пары): the point that names each,
    // its two links, its kind; every pair of a linkage is a lower pair of
    // class 5 (one freedom)
    let pairs: Vec<Value> = m
        .pairs
        .iter()
        .map(|p| {
            let (a, b) = p.links();
            let kind = match p.kind() {
                tmm_linkage::structure::PairKind::R => "R",
                tmm_linkage::structure::PairKind::P => "P",
            };
            json!({"point": pair_point(p, m), "links": [m.link_names[a], m.link_names[b]], "kind": kind, "class": 5})
        })
        .collect();
    let out = a.reading.output;
    json!({
        "units": "SI",
        "structure": {
            "dof": s.dof, "n": s.n, "p5": s.p5, "p4": s.p4, "groups": groups, "pairs": pairs,
            "formula": s.formula, "class": s.class,
            "dof_by_rank": s.dof_rank, "redundant_constraints": s.redundant, "passive_freedoms": s.passive,
        },
        "geometry": geometry(l),
        "output": {"link": m.link_names[out.link], "kind": match out.kind { tmm_linkage::cycle::OutputKind::Linear => "linear", tmm_linkage::cycle::OutputKind::Angular => "angular" }},
    })
}

/// The whole document.
pub fn document(l: &Loaded, a: &Analysis) -> Value {
    if let Some(t) = a.travel {
        return super::travel::document(l, a, t);
    }
    let m = &l.mech;
    let w = m.crank.omega.abs();
    let vec = plan_vectors;
    let pmax: Vec<Value> = a
        .pressure_max
        .iter()
        .map(|&(p, v, phi)| json!({"point": m.points[p].name, "max": num(v), "phi": num(phi)}))
        .collect();
    let mut doc = common(l, a);
    let more = json!({
        // the time of one turn of the crank T = 2π/|ω1| = 60/n1 (s)
        "input": {"link": m.link_names[m.crank.link], "omega": num(m.crank.omega), "epsilon": num(m.crank.eps),
            "revolution_time": num(if w > 0.0 { std::f64::consts::TAU / w } else { 0.0 })},
        "positions": a.rows.iter().map(|r| row_json(l, r)).collect::<Vec<_>>(),
        "pressure_angle_max": pmax,
        "diagrams": {
            "phi": a.diagram.iter().map(|d| num(d[0])).collect::<Vec<_>>(),
            "s": a.diagram.iter().map(|d| num(d[1])).collect::<Vec<_>>(),
            "ds_dphi": a.diagram.iter().map(|d| num(d[2])).collect::<Vec<_>>(),
            "d2s_dphi2": a.diagram.iter().map(|d| num(d[3])).collect::<Vec<_>>(),
            "t": a.diagram.iter().map(|d| num(d[0] / w)).collect::<Vec<_>>(),
            "v": a.diagram.iter().map(|d| num(d[2] * w)).collect::<Vec<_>>(),
            "a": a.diagram.iter().map(|d| num(d[3] * w * w)).collect::<Vec<_>>(),
        },
        "plans": {"phi": num(a.plan_row.pos.phi), "velocity": vec(&a.plans.velocity), "acceleration": vec(&a.plans.acceleration)},
    });
    if let (Value::Object(o), Value::Object(more)) = (&mut doc, more) {
        o.extend(more);
    }
    if let Value::Object(o) = &mut doc {
        o.insert("range".into(), json!(if a.partial.is_some() { "partial" } else { "full" }));
        // indices into the diagrams' arrays where a new range starts after a gap
        if let Value::Object(d) = &mut o["diagrams"] {
            d.insert("breaks".into(), json!(a.diagram_breaks));
        }
        if let Some(c) = &a.cycle {
            o.insert("dead_positions".into(), c.dead.iter().map(|&p| json!({"phi": num(p)})).collect());
            o.insert("kv".into(), num(c.kv));
            o.insert("theta".into(), num(c.theta));
            o.insert("working_angle".into(), num(c.working_angle));
            o.insert("return_angle".into(), num(c.return_angle));
            o.insert("stroke".into(), num(c.stroke));
        }
        if let Some(p) = &a.partial {
            let span = |r: &tmm_linkage::ranges::AssemblyRange| json!({"from": num(r.from), "to": num(r.to)});
            let ranges: Vec<Value> = p
                .ranges
                .iter()
                .map(|r| {
                    json!({"from": num(r.range.from), "to": num(r.range.to),
                        "dead_positions": r.dead.iter().map(|&x| json!({"phi": num(x)})).collect::<Vec<_>>(),
                        "s_min": num(r.s_min), "s_max": num(r.s_max)})
                })
                .collect();
            o.insert("assembly_ranges".into(), Value::Array(ranges));
            o.insert("gaps".into(), p.map.gaps.iter().map(span).collect());
        }
    }
    doc
}
