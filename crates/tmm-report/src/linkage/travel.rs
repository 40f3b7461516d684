//! A linkage driven by a slider on a fixed guide (ведущий ползун), analysed
//! over its travel s: the positions 0 … n at equal steps of s, the output's
//! coordinate x and its analogues dx/ds and d²x/ds², the diagrams over s,
//! the plans at one s, and the section's tables and JSON.
//!
//! The core solves each position with the slider placed at `Q + s·d`
//! moving at v (and a): every velocity and acceleration comes from the same
//! linear systems as for a crank, with the slider's velocity and
//! acceleration on the right side. The analogues follow from the chain
//! rule: ẋ = x′·v, ẍ = x″·v² + x′·a, so x′ = ẋ/v and x″ = (ẍ − x′·a)/v²
//! (derived in docs/linkage.md, "A slider as the input").

use std::fmt::Write as _;

use serde_json::{Map, Value, json};
use tmm_linkage::cycle::{self, Output, OutputKind, Position};
use tmm_linkage::{LinkageError, Mechanism, Solution};

use super::task::Travel;
use super::{Analysis, Loaded, Reading, Row, locate};
use crate::output::num;
use crate::{Error, TaskSource};

/// Samples of the diagrams over the travel.
const SAMPLES: usize = 360;

/// The output's coordinate x and its analogues dx/ds, d²x/ds² at a solved
/// position of a slider-driven mechanism (x from `x0`; an angle continuous
/// near it).
///
/// ```
/// // ẋ = x′·v and ẍ = x″·v² + x′·a: with x′ = 2, x″ = 3, v = 0.5, a = 4
/// let (xp, xpp) = tmm_report::linkage::travel::analogues(2.0 * 0.5, 3.0 * 0.25 + 2.0 * 4.0, 0.5, 4.0);
/// assert!((xp - 2.0).abs() < 1e-15 && (xpp - 3.0).abs() < 1e-15);
/// ```
pub fn analogues(xdot: f64, xddot: f64, v: f64, a: f64) -> (f64, f64) {
    let xp = xdot / v;
    (xp, (xddot - xp * a) / (v * v))
}

fn row_analogs(m: &Mechanism, out: &Output, x0: f64, sol: &Solution) -> (f64, f64, f64) {
    let o = out.read(sol, x0);
    let (xp, xpp) = analogues(o.v, o.a, m.crank.omega, m.crank.eps);
    (o.s - x0, xp, xpp)
}

/// Solve one s into a row.
fn row(m: &Mechanism, out: &Output, x0: f64, pos: Position) -> Result<Row, LinkageError> {
    super::row_with(m, pos, |sol| row_analogs(m, out, x0, sol))
}

/// The error of a travel that goes past where the mechanism assembles: the
/// core's reason, and where it stops assembling, found by bisection between
/// the last s that solved and the first that did not (to 1e-9 of the size).
fn beyond(l: &Loaded, src: &TaskSource, t: Travel, ok: f64, bad: f64, e: &LinkageError) -> Error {
    let m = &l.mech;
    let mut sol = m.solution();
    let (mut lo, mut hi) = (ok, bad);
    let tol = 1e-9 * (t.to - t.from).abs().max(1e-3);
    while hi - lo > tol {
        let mid = 0.5 * (lo + hi);
        if m.solve(mid, &mut sol).is_ok() {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let span = l.task.spans.get("travel").cloned().unwrap_or(l.task.section.clone());
    Error::at(
        src,
        span,
        "linkage.travel",
        format!(
            "the mechanism does not assemble over the whole travel; it moves from s = {:.3} mm only up to s = {:.4} mm: {}",
            t.from * 1e3,
            lo * 1e3,
            e
        ),
    )
    .with_help(format!("end the travel before s = {:.3} mm", lo * 1e3))
}

/// Analyse a slider-driven mechanism over its travel: `n` equal steps (n + 1
/// positions, both ends included) or the one position `at` (s, m).
pub fn analyse(l: &Loaded, src: &TaskSource, t: Travel, at: Option<f64>, n: usize) -> Result<Analysis, Error> {
    let m = &l.mech;
    let loc = |e: LinkageError| locate(src, &l.task, &e);
    let out = Output::of(m);
    let mut sol = m.solution();
    m.solve(t.from, &mut sol).map_err(loc)?;
    let x0 = out.read(&sol, 0.0).s;
    let reading = Reading {
        output: out,
        s0: x0,
        sign: 1.0,
    };
    // the diagrams first: a travel past the assembly is found here and
    // refused with where it ends
    let mut diagram = Vec::with_capacity(SAMPLES + 1);
    let mut pressure_max: Vec<(usize, f64, f64)> = Vec::new();
    let mut pa = Vec::new();
    let mut last_ok = t.from;
    for k in 0..=SAMPLES {
        let s = t.from + (t.to - t.from) * k as f64 / SAMPLES as f64;
        if let Err(e) = m.solve(s, &mut sol) {
            return Err(beyond(l, src, t, last_ok, s, &e));
        }
        last_ok = s;
        let (x, xp, xpp) = row_analogs(m, &out, x0, &sol);
        diagram.push([s - t.from, x, xp, xpp]);
        cycle::pressure_angles(m, &sol, &mut pa);
        for &(p, v) in &pa {
            match pressure_max.iter_mut().find(|x| x.0 == p) {
                Some(x) => {
                    if v > x.1 {
                        x.1 = v;
                        x.2 = s;
                    }
                }
                None => pressure_max.push((p, v, s)),
            }
        }
    }
    let pos = |label: String, s: f64| Position {
        label,
        phi: s,
        psi: s - t.from,
    };
    let positions: Vec<Position> = match at {
        Some(s) => {
            if !(t.from..=t.to).contains(&s) {
                return Err(Error::input(
                    "--at",
                    format!(
                        "s = {:.3} mm is outside the travel {:.3} … {:.3} mm",
                        s * 1e3,
                        t.from * 1e3,
                        t.to * 1e3
                    ),
                )
                .with_help("for a slider input --at is the slider's s in mm inside `travel`"));
            }
            vec![pos("at".into(), s)]
        }
        None => {
            let n = n.max(1);
            (0..=n)
                .map(|k| pos(k.to_string(), t.from + (t.to - t.from) * k as f64 / n as f64))
                .collect()
        }
    };
    let rows = positions
        .into_iter()
        .map(|p| row(m, &out, x0, p))
        .collect::<Result<Vec<_>, _>>()
        .map_err(loc)?;
    let plan_s = at.or(l.task.at).unwrap_or_else(|| rows.get(1).map_or(t.from, |r| r.pos.phi));
    let plan_row = row(m, &out, x0, pos("plan".into(), plan_s)).map_err(loc)?;
    let plans = tmm_linkage::plans::plans(m, &plan_row.sol);
    Ok(Analysis {
        cycle: None,
        partial: None,
        travel: Some(t),
        reading,
        start: t.from,
        rows,
        row_breaks: Vec::new(),
        diagram,
        diagram_breaks: Vec::new(),
        diagram_gaps: Vec::new(),
        plan_row,
        plans,
        pressure_max,
    })
}

/// The output's unit in the tables: m for a slider, rad for a link's angle.
fn out_unit(kind: OutputKind) -> &'static str {
    if kind == OutputKind::Linear { "m" } else { "rad" }
}

/// The human tables of a slider-driven mechanism.
pub fn report(l: &Loaded, a: &Analysis, t: Travel) -> String {
    let m = &l.mech;
    let mut o = super::text::structure(l);
    let out = a.reading.output;
    let unit = out_unit(out.kind);
    let _ = writeln!(
        o,
        "\nINPUT — slider `{}` on a fixed guide: v = {:.6} m/s, a = {:.6} m/s², travel s = {:.3} … {:.3} mm ({:.3} mm)",
        m.link_names[m.crank.link],
        m.crank.omega,
        m.crank.eps,
        t.from * 1e3,
        t.to * 1e3,
        (t.to - t.from) * 1e3
    );
    if m.crank.eps == 0.0 {
        let _ = writeln!(o, "  at constant v the travel takes {:.6} s", (t.to - t.from) / m.crank.omega.abs());
    }
    let _ = writeln!(
        o,
        "OUTPUT — link `{}` ({}); x from its value at s = {:.3} mm",
        m.link_names[out.link],
        if out.kind == OutputKind::Linear {
            "travel along its guide"
        } else {
            "angle"
        },
        t.from * 1e3
    );
    for &(p, v, s) in &a.pressure_max {
        let _ = writeln!(
            o,
            "  max pressure angle at {}: ϑ = {:.3}° (γ = {:.3}°) at s = {:.3} mm",
            m.points[p].name,
            v.to_degrees(),
            90.0 - v.to_degrees(),
            s * 1e3
        );
    }
    let _ = writeln!(o, "\nPOSITIONS (s in mm; x in {unit}, dx/ds in {unit}/m, d²x/ds² in {unit}/m²)");
    let mut head = format!("  {:>4} {:>10} {:>11} {:>11} {:>12}", "pos", "s,mm", "x", "dx/ds", "d²x/ds²");
    for nm in m.link_names.iter().skip(1) {
        let _ = write!(head, " {:>10} {:>11}", format!("ω{nm}"), format!("ε{nm}"));
    }
    let _ = writeln!(o, "{head}");
    for r in &a.rows {
        let mut line = format!(
            "  {:>4} {:>10.3} {:>11.6} {:>11.6} {:>12.6}",
            r.pos.label,
            r.pos.phi * 1e3,
            r.analogs.0,
            r.analogs.1,
            r.analogs.2
        );
        for i in 1..m.link_names.len() {
            let _ = write!(line, " {:>10.4} {:>11.3}", r.sol.links[i].omega, r.sol.links[i].eps);
        }
        let _ = writeln!(o, "{line}");
    }
    let r = &a.plan_row;
    let _ = writeln!(o, "\nPOINTS at s = {:.3} mm (m, m/s, m/s²)", r.pos.phi * 1e3);
    super::text::points_table(&mut o, l, r);
    o
}

/// The JSON document of a slider-driven mechanism (SI: s in m).
pub fn document(l: &Loaded, a: &Analysis, t: Travel) -> Value {
    let m = &l.mech;
    let mut doc = super::json::common(l, a);
    let v = m.crank.omega;
    let positions: Vec<Value> = a
        .rows
        .iter()
        .map(|r| {
            let mut j = super::json::row_json(l, r);
            if let Value::Object(o) = &mut j {
                o.remove("phi");
                o.remove("psi");
                o.insert("s".into(), num(r.pos.phi));
                o.insert(
                    "output".into(),
                    json!({"x": num(r.analogs.0), "dx_ds": num(r.analogs.1), "d2x_ds2": num(r.analogs.2)}),
                );
            }
            j
        })
        .collect();
    let pmax: Vec<Value> = a
        .pressure_max
        .iter()
        .map(|&(p, v, s)| json!({"point": m.points[p].name, "max": num(v), "s": num(s)}))
        .collect();
    if let Value::Object(o) = &mut doc {
        o.insert(
            "input".into(),
            json!({"kind": "slider", "link": m.link_names[m.crank.link], "speed": num(v), "acceleration": num(m.crank.eps),
                "travel": {"from": num(t.from), "to": num(t.to)}}),
        );
        o.insert("range".into(), json!("travel"));
        o.insert("positions".into(), Value::Array(positions));
        o.insert("pressure_angle_max".into(), Value::Array(pmax));
        let mut d = Map::new();
        d.insert("s".into(), a.diagram.iter().map(|d| num(t.from + d[0])).collect());
        d.insert("x".into(), a.diagram.iter().map(|d| num(d[1])).collect());
        d.insert("dx_ds".into(), a.diagram.iter().map(|d| num(d[2])).collect());
        d.insert("d2x_ds2".into(), a.diagram.iter().map(|d| num(d[3])).collect());
        if m.crank.eps == 0.0 {
            // time from the start of the travel at constant v
            d.insert("t".into(), a.diagram.iter().map(|d| num(d[0] / v.abs())).collect());
        }
        d.insert("v".into(), a.diagram.iter().map(|d| num(d[2] * v)).collect());
        d.insert(
            "a".into(),
            a.diagram.iter().map(|d| num(d[3] * v * v + d[2] * m.crank.eps)).collect(),
        );
        o.insert("diagrams".into(), Value::Object(d));
        o.insert(
            "plans".into(),
            json!({"s": num(a.plan_row.pos.phi), "velocity": super::json::plan_vectors(&a.plans.velocity), "acceleration": super::json::plan_vectors(&a.plans.acceleration)}),
        );
    }
    doc
}
