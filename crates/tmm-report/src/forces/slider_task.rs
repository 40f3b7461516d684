//! Reading the machine's cycle and the loads on sliders of `[forces]`: the
//! cylinders' indicator diagrams, forces by travel on one stroke, and
//! friction (docs/forces.md, "Engines, compressors, shapers").
//!
//! ```toml
//! [forces.cycle]
//! turns = 2                      # 1 (360°) or 2 (720°, a four-stroke engine)
//! start = "180 deg"              # crank angle where the cycle starts
//!
//! [[forces.cylinders]]
//! link = "3"                     # the piston, a slider on a frame guide
//! bore = "78 mm"
//! p_max = "1.1 MPa"              # with pressure_unit = "p_max"
//! pressure_unit = "p_max"        # Pa | kPa | bar | MPa | p_max
//! travel_unit = "H"              # H (fractions of the stroke) | m | mm
//! processes = ["intake", "compression", "expansion", "exhaust"]
//! shift = "0 deg"                # where the first process starts in the cycle
//! # bounds = ["0 deg", "180 deg", "360 deg", "540 deg", "720 deg"]  (default: equal shares)
//! [forces.cylinders.tables.expansion]
//! interpolation = "spline"       # spline (not-a-knot, Mathcad cspline) | natural | linear
//! travel = [0, 0.025, 0.05, 0.1]
//! pressure = [0.29, 1, 0.9, 0.71]
//!
//! [[forces.stroke_forces]]
//! link = "5"
//! stroke = "working"             # working (the slower) | increasing | decreasing
//! window = [0.05, 0.95]          # fractions of the stroke where it acts
//! arm = "0.09 m"                 # the couple F·arm about the slider's point (П3's l_p)
//! travel_unit = "m"
//! travel = [0, 0.3]
//! force = [400, 600]             # N, against the motion on that stroke
//!
//! [[forces.friction]]
//! link = "5"
//! force = "100 N"
//! ```

use std::collections::BTreeMap;
use std::ops::Range;

use serde::Deserialize;
use tmm_geom::units::Dim;
use tmm_linkage::Mechanism;
use tmm_linkage::forces::stroke::Working;
use tmm_linkage::forces::{Curve, ForceError, Indicator, Interpolation, MachineCycle, Process, SliderLoad, SliderLoadKind, TravelScale};

use crate::task::{Qty, qty};
use crate::{Error, TaskSource};

type S<T> = toml::Spanned<T>;

/// `[forces.cycle]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct CycleSec {
    turns: Option<S<i64>>,
    start: Option<Qty>,
    step: Option<Qty>,
    diagrams: Option<S<Vec<S<String>>>>,
    hodographs: Option<S<Vec<S<String>>>>,
}

/// The reactions over the whole cycle (`[forces.cycle] step`, `diagrams`,
/// `hodographs`): every reaction at every `step` of the machine's cycle,
/// the chosen ones drawn against the cycle angle and as hodographs.
#[derive(Debug, Clone, PartialEq)]
pub struct ReactionCycleSpec {
    /// The step of the cycle angle, rad (it divides the cycle).
    pub step: f64,
    /// The reactions (`R50`) and guide couples (`M50`) to draw over the cycle, with their spans.
    pub diagrams: Vec<(String, Range<usize>)>,
    /// The reactions whose hodographs to draw, with their spans.
    pub hodographs: Vec<(String, Range<usize>)>,
}

/// The most steps of the reaction table over a cycle (0.1° on a 720° cycle).
pub const MAX_REACTION_STEPS: usize = 7200;

/// Read `step`, `diagrams` and `hodographs` of `[forces.cycle]`: `None`
/// when none is given; the step defaults to 1°.
pub(crate) fn reaction_cycle(task: &TaskSource, cycle_sec: Option<&S<CycleSec>>, turns: u32) -> Result<Option<ReactionCycleSpec>, Error> {
    let Some(c) = cycle_sec else { return Ok(None) };
    let cr = c.get_ref();
    if cr.step.is_none() && cr.diagrams.is_none() && cr.hodographs.is_none() {
        return Ok(None);
    }
    let period = std::f64::consts::TAU * f64::from(turns.max(1));
    let step = match &cr.step {
        None => 1f64.to_radians(),
        Some(q) => {
            let v = qty(task, "forces.cycle.step", q, Dim::Angle)?;
            let n = period / v;
            if !(v.is_finite()
                && v > 0.0
                && (n - n.round()).abs() <= 1e-6 * n
                && n.round() >= 12.0
                && n.round() <= MAX_REACTION_STEPS as f64)
            {
                return Err(Error::at(
                    task,
                    q.span(),
                    "forces.cycle.step",
                    format!(
                        "the step must divide the cycle of {}° into 12 to {MAX_REACTION_STEPS} equal parts, not {}°",
                        period.to_degrees(),
                        v.to_degrees()
                    ),
                )
                .with_help("step = \"1 deg\" (or 0.5, 2, 5, 10, 15, 30 deg)"));
            }
            period / n.round()
        }
    };
    let names = |v: &Option<S<Vec<S<String>>>>| -> Vec<(String, Range<usize>)> {
        v.as_ref()
            .map(|v| v.get_ref().iter().map(|s| (s.get_ref().clone(), s.span())).collect())
            .unwrap_or_default()
    };
    Ok(Some(ReactionCycleSpec {
        step,
        diagrams: names(&cr.diagrams),
        hodographs: names(&cr.hodographs),
    }))
}

/// One `[[forces.cylinders]]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct CylinderSec {
    link: S<String>,
    bore: Qty,
    p_max: Option<Qty>,
    pressure_unit: Option<S<String>>,
    travel_unit: Option<S<String>>,
    processes: S<Vec<String>>,
    shift: Option<Qty>,
    bounds: Option<S<Vec<Qty>>>,
    tables: S<BTreeMap<String, S<TableSec>>>,
}

/// A pressure table.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct TableSec {
    interpolation: Option<S<String>>,
    travel: S<Vec<f64>>,
    pressure: S<Vec<f64>>,
}

/// One `[[forces.stroke_forces]]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct StrokeForceSec {
    link: S<String>,
    stroke: Option<S<String>>,
    window: Option<S<Vec<f64>>>,
    arm: Option<Qty>,
    travel_unit: Option<S<String>>,
    interpolation: Option<S<String>>,
    travel: S<Vec<f64>>,
    force: S<Vec<f64>>,
}

/// One `[[forces.friction]]`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct FrictionSec {
    link: S<String>,
    force: Qty,
}

fn slider_link(task: &TaskSource, m: &Mechanism, field: &str, name: &S<String>) -> Result<usize, Error> {
    match m.link(name.get_ref()) {
        Some(i) if i > 0 => Ok(i),
        _ => Err(
            Error::at(task, name.span(), field, format!("unknown or fixed link `{}`", name.get_ref())).with_help(format!(
                "name a slider on a frame guide; the links are {}",
                m.link_names[1..].join(", ")
            )),
        ),
    }
}

fn interpolation(task: &TaskSource, field: &str, s: Option<&S<String>>, default: Interpolation) -> Result<Interpolation, Error> {
    match s.map(|s| (s.get_ref().as_str(), s.span())) {
        None => Ok(default),
        Some(("spline", _)) => Ok(Interpolation::NotAKnot),
        Some(("natural", _)) => Ok(Interpolation::Natural),
        Some(("linear", _)) => Ok(Interpolation::Linear),
        Some((other, sp)) => Err(Error::at(task, sp, field, format!("unknown interpolation `{other}`")).with_help(
            "interpolation = \"spline\" (cubic, not-a-knot ends: Mathcad cspline) | \"natural\" (cubic, S″ = 0 at the ends: Mathcad lspline) | \"linear\"",
        )),
    }
}

/// The travel unit: a scale for the core and a factor to metres.
fn travel_unit(task: &TaskSource, field: &str, s: Option<&S<String>>) -> Result<(TravelScale, f64), Error> {
    match s.map(|s| (s.get_ref().as_str(), s.span())) {
        None | Some(("H", _)) => Ok((TravelScale::Stroke, 1.0)),
        Some(("m", _)) => Ok((TravelScale::Metres, 1.0)),
        Some(("mm", _)) => Ok((TravelScale::Metres, 1e-3)),
        Some((other, sp)) => Err(Error::at(task, sp, field, format!("unknown travel unit `{other}`"))
            .with_help("travel_unit = \"H\" (fractions of the stroke, 0…1; the default) | \"m\" | \"mm\"")),
    }
}

/// Points of a table: equal lengths, finite numbers (`xname`, `yname`:
/// the arrays' keys, for the messages).
fn points(
    task: &TaskSource,
    field: &str,
    (xname, x): (&str, &S<Vec<f64>>),
    (yname, y): (&str, &S<Vec<f64>>),
    xs: f64,
    ys: f64,
) -> Result<Vec<(f64, f64)>, Error> {
    if x.get_ref().len() != y.get_ref().len() {
        return Err(Error::at(
            task,
            y.span(),
            field,
            format!(
                "{} travels but {} values; give one value per travel",
                x.get_ref().len(),
                y.get_ref().len()
            ),
        ));
    }
    for (name, v) in [(xname, x), (yname, y)] {
        if let Some(i) = v.get_ref().iter().position(|a| !a.is_finite()) {
            return Err(Error::at(
                task,
                v.span(),
                &format!("{field}.{name}[{i}]"),
                format!("each number of the table must be finite, not {}", v.get_ref()[i]),
            ));
        }
    }
    Ok(x.get_ref().iter().zip(y.get_ref()).map(|(a, b)| (a * xs, b * ys)).collect())
}

/// A core error in building a table, located at the table.
fn table_error(task: &TaskSource, span: Range<usize>, field: &str, e: ForceError) -> Error {
    match e {
        ForceError::Load { field: f, message } => Error::at(task, span, &format!("{field}{}", f.strip_prefix("t").unwrap_or(&f)), message),
        other => Error::at(task, span, field, other.to_string()),
    }
}

/// Read the cycle and the slider loads into `cycle`, `sliders`; spans go
/// into `spans` keyed as the core names the loads (`sliders[0].bore`).
#[allow(clippy::too_many_arguments)]
pub(crate) fn read(
    task: &TaskSource,
    m: &Mechanism,
    cycle_sec: Option<&S<CycleSec>>,
    cylinders: &[S<CylinderSec>],
    strokes: &[S<StrokeForceSec>],
    friction: &[S<FrictionSec>],
    cycle: &mut MachineCycle,
    sliders: &mut Vec<SliderLoad>,
    spans: &mut BTreeMap<String, Range<usize>>,
) -> Result<(), Error> {
    if let Some(c) = cycle_sec {
        spans.insert("cycle".into(), c.span());
        let cr = c.get_ref();
        if let Some(t) = &cr.turns {
            let v = *t.get_ref();
            if v != 1 && v != 2 {
                return Err(Error::at(
                    task,
                    t.span(),
                    "forces.cycle.turns",
                    format!("the machine's cycle is 1 turn of the crank (360°) or 2 (720°, a four-stroke engine), not {v}"),
                )
                .with_help("turns = 2"));
            }
            cycle.turns = v as u32;
        }
        if let Some(s) = &cr.start {
            cycle.start = Some(qty(task, "forces.cycle.start", s, Dim::Angle)?);
        }
    }
    let period = cycle.period();
    for (k, cs) in cylinders.iter().enumerate() {
        let key = format!("sliders[{}]", sliders.len());
        let field = format!("forces.cylinders[{k}]");
        spans.insert(key.clone(), cs.span());
        let c = cs.get_ref();
        let link = slider_link(task, m, &format!("{field}.link"), &c.link)?;
        // one cylinder per piston: the cylinders' phases are their pistons'
        // cranks and shifts, so a second cylinder needs its own piston
        if let Some(j) = cylinders[..k].iter().position(|o| o.get_ref().link.get_ref() == c.link.get_ref()) {
            return Err(Error::at(
                task,
                c.link.span(),
                &format!("{field}.link"),
                format!(
                    "the piston `{}` already has its cylinder (forces.cylinders[{j}]); a piston has one cylinder",
                    c.link.get_ref()
                ),
            )
            .with_help(
                "give each cylinder its own piston: a connecting rod and a slider in [linkage] on its crank (П2: rods 2 and 4 on cranks at 180°, pistons 3 and 5), and its phase by shift",
            ));
        }
        spans.insert(format!("{key}.link"), c.link.span());
        spans.insert(format!("{key}.bore"), c.bore.span());
        let bore = qty(task, &format!("{field}.bore"), &c.bore, Dim::Length)?;
        if !(bore.is_finite() && bore > 0.0) {
            return Err(Error::at(
                task,
                c.bore.span(),
                &format!("{field}.bore"),
                format!("the bore must be > 0, not {bore} m"),
            )
            .with_help("bore = \"78 mm\""));
        }
        let scale = match c.pressure_unit.as_ref().map(|s| (s.get_ref().as_str(), s.span())) {
            None | Some(("Pa", _)) => 1.0,
            Some(("kPa", _)) => 1e3,
            Some(("bar", _)) => 1e5,
            Some(("MPa", _)) => 1e6,
            Some(("p_max", sp)) => {
                let q = c.p_max.as_ref().ok_or_else(|| {
                    Error::at(
                        task,
                        sp,
                        &format!("{field}.p_max"),
                        "pressure_unit = \"p_max\" needs p_max, the largest pressure",
                    )
                    .with_help("p_max = \"1.1 MPa\"")
                })?;
                let p = qty(task, &format!("{field}.p_max"), q, Dim::Stress)?;
                if !(p.is_finite() && p > 0.0) {
                    return Err(Error::at(
                        task,
                        q.span(),
                        &format!("{field}.p_max"),
                        format!("must be > 0, not {p} Pa"),
                    ));
                }
                p
            }
            Some((other, sp)) => {
                return Err(Error::at(
                    task,
                    sp,
                    &format!("{field}.pressure_unit"),
                    format!("unknown pressure unit `{other}`"),
                )
                .with_help("pressure_unit = \"Pa\" | \"kPa\" | \"bar\" | \"MPa\" | \"p_max\" (fractions of p_max)"));
            }
        };
        let (travel, xs) = travel_unit(task, &format!("{field}.travel_unit"), c.travel_unit.as_ref())?;
        let mut names = Vec::new();
        let mut tables = Vec::new();
        spans.insert(format!("{key}.tables"), c.tables.span());
        for (name, ts) in c.tables.get_ref() {
            let tf = format!("{field}.tables.{name}");
            spans.insert(format!("{key}.tables.{name}"), ts.span());
            let t = ts.get_ref();
            let ip = interpolation(
                task,
                &format!("{tf}.interpolation"),
                t.interpolation.as_ref(),
                Interpolation::Linear,
            )?;
            let pts = points(task, &tf, ("travel", &t.travel), ("pressure", &t.pressure), xs, 1.0)?;
            let curve = Curve::new(&pts, ip, "t").map_err(|e| table_error(task, t.travel.span(), &format!("{tf}.travel"), e))?;
            names.push(name.clone());
            tables.push(curve);
        }
        // the processes, each an equal share of the cycle unless bounded
        let procs = c.processes.get_ref();
        spans.insert(format!("{key}.processes"), c.processes.span());
        if procs.is_empty() {
            return Err(Error::at(task, c.processes.span(), &format!("{field}.processes"), "no processes")
                .with_help("processes = [\"intake\", \"compression\", \"expansion\", \"exhaust\"]"));
        }
        let n = procs.len();
        let bounds: Vec<f64> = match &c.bounds {
            None => (0..=n).map(|i| period * i as f64 / n as f64).collect(),
            Some(b) => {
                let bf = format!("{field}.bounds");
                let v = b
                    .get_ref()
                    .iter()
                    .map(|q| qty(task, &bf, q, Dim::Angle))
                    .collect::<Result<Vec<_>, _>>()?;
                let tol = 1e-9 * period;
                let fits = v.len() == n + 1 && v[0].abs() <= tol && (v[n] - period).abs() <= tol && v.windows(2).all(|w| w[1] > w[0]);
                if !fits {
                    return Err(Error::at(
                        task,
                        b.span(),
                        &bf,
                        format!(
                            "the bounds of the {n} processes must be {} angles increasing from 0° to the cycle's {:.0}°",
                            n + 1,
                            period.to_degrees()
                        ),
                    )
                    .with_help("bounds = [\"0 deg\", \"180 deg\", \"360 deg\", \"540 deg\", \"720 deg\"]"));
                }
                v
            }
        };
        let shift = match &c.shift {
            Some(q) => {
                let s = qty(task, &format!("{field}.shift"), q, Dim::Angle)?;
                if !(0.0..period).contains(&s) {
                    return Err(Error::at(
                        task,
                        q.span(),
                        &format!("{field}.shift"),
                        format!(
                            "the shift must be in [0°, {:.0}°), the machine's cycle, not {:.4}°",
                            period.to_degrees(),
                            s.to_degrees()
                        ),
                    ));
                }
                s
            }
            None => 0.0,
        };
        // the cycle angles: each process shifted, split where it wraps
        let mut processes = Vec::new();
        for (i, name) in procs.iter().enumerate() {
            let Some(t) = names.iter().position(|x| x == name) else {
                return Err(Error::at(
                    task,
                    c.processes.span(),
                    &format!("{field}.processes"),
                    format!("the process `{name}` has no pressure table"),
                )
                .with_help(format!(
                    "add [forces.cylinders.tables.{name}] with travel = […] and pressure = […]; the tables given are {}",
                    names.join(", ")
                )));
            };
            let (a, b) = (bounds[i] + shift, bounds[i + 1] + shift);
            let mut push = |from: f64, to: f64| {
                if to - from > 1e-12 {
                    processes.push(Process {
                        name: name.clone(),
                        from,
                        to,
                        table: t,
                    })
                }
            };
            if b <= period + 1e-12 {
                push(a, b.min(period));
            } else if a >= period - 1e-12 {
                push(a - period, b - period);
            } else {
                push(a, period);
                push(0.0, b - period);
            }
        }
        // a table no process names is a misspelt process or a stray table
        if let Some((name, ts)) = c.tables.get_ref().iter().find(|(name, _)| !procs.contains(name)) {
            return Err(Error::at(
                task,
                ts.span(),
                &format!("{field}.tables.{name}"),
                format!(
                    "the table `{name}` is for no process of the cylinder; its processes are {}",
                    procs.join(", ")
                ),
            )
            .with_help(format!(
                "name each table after a process of processes = [{}], or add `{name}` to processes",
                procs.iter().map(|p| format!("\"{p}\"")).collect::<Vec<_>>().join(", ")
            )));
        }
        processes.sort_by(|p, q| p.from.total_cmp(&q.from));
        if let Some(p) = processes.first_mut() {
            p.from = 0.0;
        }
        sliders.push(SliderLoad {
            link,
            kind: SliderLoadKind::Gas {
                bore,
                indicator: Indicator {
                    tables,
                    names,
                    travel,
                    pressure_scale: scale,
                    processes,
                },
            },
        });
    }
    for (k, ss) in strokes.iter().enumerate() {
        let key = format!("sliders[{}]", sliders.len());
        let field = format!("forces.stroke_forces[{k}]");
        spans.insert(key.clone(), ss.span());
        let s = ss.get_ref();
        let link = slider_link(task, m, &format!("{field}.link"), &s.link)?;
        spans.insert(format!("{key}.link"), s.link.span());
        spans.insert(format!("{key}.table"), s.travel.span());
        let working = match s.stroke.as_ref().map(|s| (s.get_ref().as_str(), s.span())) {
            None | Some(("working", _)) => Working::Slower,
            Some(("increasing", _)) => Working::Increasing,
            Some(("decreasing", _)) => Working::Decreasing,
            Some((other, sp)) => {
                return Err(Error::at(task, sp, &format!("{field}.stroke"), format!("unknown stroke `{other}`")).with_help(
                    "stroke = \"working\" (the slower stroke) | \"increasing\" | \"decreasing\" (the slider's coordinate along its guide on the acting stroke)",
                ));
            }
        };
        let window = match &s.window {
            None => (0.0, 1.0),
            Some(w) => {
                spans.insert(format!("{key}.window"), w.span());
                let v = w.get_ref();
                if v.len() != 2 {
                    return Err(Error::at(
                        task,
                        w.span(),
                        &format!("{field}.window"),
                        "expected [from, to], fractions of the stroke",
                    )
                    .with_help("window = [0.05, 0.95]"));
                }
                (v[0], v[1])
            }
        };
        let arm = match &s.arm {
            None => 0.0,
            Some(a) => {
                spans.insert(format!("{key}.arm"), a.span());
                qty(task, &format!("{field}.arm"), a, Dim::Length)?
            }
        };
        let (travel, xs) = travel_unit(task, &format!("{field}.travel_unit"), s.travel_unit.as_ref())?;
        let ip = interpolation(
            task,
            &format!("{field}.interpolation"),
            s.interpolation.as_ref(),
            Interpolation::Linear,
        )?;
        let pts = points(task, &field, ("travel", &s.travel), ("force", &s.force), xs, 1.0)?;
        let table = Curve::new(&pts, ip, "t").map_err(|e| table_error(task, s.travel.span(), &format!("{field}.travel"), e))?;
        sliders.push(SliderLoad {
            link,
            kind: SliderLoadKind::StrokeForce {
                table,
                travel,
                working,
                window,
                arm,
            },
        });
    }
    for (k, fs) in friction.iter().enumerate() {
        let key = format!("sliders[{}]", sliders.len());
        let field = format!("forces.friction[{k}]");
        spans.insert(key.clone(), fs.span());
        let f = fs.get_ref();
        let link = slider_link(task, m, &format!("{field}.link"), &f.link)?;
        spans.insert(format!("{key}.link"), f.link.span());
        spans.insert(format!("{key}.force"), f.force.span());
        let force = qty(task, &format!("{field}.force"), &f.force, Dim::Force)?;
        if !(force.is_finite() && force >= 0.0) {
            return Err(Error::at(
                task,
                f.force.span(),
                &format!("{field}.force"),
                format!("the friction force must be ≥ 0, not {force} N"),
            ));
        }
        sliders.push(SliderLoad {
            link,
            kind: SliderLoadKind::Friction { force },
        });
    }
    Ok(())
}
