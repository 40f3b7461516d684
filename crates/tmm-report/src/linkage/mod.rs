//! The `[linkage]` section: read the mechanism, analyse its structure and its
//! cycle, and write the tables, the JSON document and the drawings.

mod draw;
mod json;
pub mod task;
mod text;

use std::f64::consts::TAU;

use tmm_linkage::cycle::{self, Cycle, Position};
use tmm_linkage::plans::{self, Plans};
use tmm_linkage::{LinkageError, Mechanism, MechanismDef, Solution};

use crate::output::{Documents, SectionOutput};
use crate::{Error, TaskSource};

pub use task::LinkageTask;

/// A mechanism read from a task file and compiled.
#[derive(Debug, Clone)]
pub struct Loaded {
    /// The section as read.
    pub task: LinkageTask,
    /// The description.
    pub def: MechanismDef,
    /// The compiled mechanism.
    pub mech: Mechanism,
}

/// Turn a core error into a located input error.
pub fn locate(src: &TaskSource, t: &LinkageTask, e: &LinkageError) -> Error {
    // The core names the field of a description or range error; find where
    // the user wrote it (the field, the field without `.length`, or its
    // first two parts).
    let core_field = match e {
        LinkageError::Description { field, .. } | LinkageError::Range { field, .. } => Some(field.as_str()),
        _ => None,
    };
    let (field, span) = match core_field {
        Some(field) => {
            let key = field.trim_end_matches(".length");
            let span = t
                .spans
                .get(field)
                .or_else(|| t.spans.get(key))
                .or_else(|| t.spans.get(field.split('.').take(2).collect::<Vec<_>>().join(".").as_str()))
                .cloned();
            (format!("linkage.{field}"), span)
        }
        None => ("linkage".to_string(), None),
    };
    let msg = match e {
        LinkageError::Description { message, .. } => message.clone(),
        LinkageError::Range { value, range, why, .. } => format!("{value} is outside the accepted range {range}{why}"),
        other => other.to_string(),
    };
    let err = Error::at(src, span.unwrap_or(t.section.clone()), &field, msg);
    match e {
        LinkageError::AssemblyRanges { .. } | LinkageError::Assembly { .. } => err.with_help(
            grashof_help(&t.def)
                .unwrap_or_else(|| "check the link lengths and the fixed points; a crank must be able to turn a full revolution".into()),
        ),
        LinkageError::Mobility { .. } => {
            err.with_help("check that every joint is shared by the right links and every slider has one guide")
        }
        _ => err,
    }
}

/// For a four-bar: the Grashof sums, which say whether the crank can turn.
fn grashof_help(def: &MechanismDef) -> Option<String> {
    if def.links.len() != 3 || !def.sliders.is_empty() || def.fixed.len() != 2 {
        return None;
    }
    let mut l: Vec<f64> = def
        .links
        .iter()
        .map(|l| (l.points.get(1)?.1 - l.points[0].1).hypot().into())
        .collect::<Option<Vec<f64>>>()?;
    l.push((def.fixed[1].1 - def.fixed[0].1).hypot());
    l.sort_by(f64::total_cmp);
    let (s, p, q, g) = (l[0], l[1], l[2], l[3]);
    Some(format!(
        "Grashof: shortest + longest = {:.4} m {} other two = {:.4} m; {}",
        s + g,
        if s + g <= p + q { "≤" } else { ">" },
        p + q,
        if s + g <= p + q {
            "the shortest link turns fully only if it is the crank next to the frame"
        } else {
            "no link can turn fully: the crank cannot make a full revolution"
        }
    ))
}

/// Read and compile the `[linkage]` section; `None` when there is none.
pub fn load(src: &TaskSource) -> Result<Option<Loaded>, Error> {
    let Some(t) = task::read(src)? else { return Ok(None) };
    let mech = Mechanism::new(&t.def).map_err(|e| locate(src, &t, &e))?;
    Ok(Some(Loaded {
        def: t.def.clone(),
        task: t,
        mech,
    }))
}

/// One solved position of the table.
#[derive(Debug, Clone)]
pub struct Row {
    /// The position.
    pub pos: Position,
    /// Its solution.
    pub sol: Solution,
    /// s, ds/dψ, d²s/dψ².
    pub analogs: (f64, f64, f64),
    /// Pressure angles (point index, rad).
    pub pressure: Vec<(usize, f64)>,
}

/// Everything the section reports.
#[derive(Debug, Clone)]
pub struct Analysis {
    /// The cycle (dead positions, Kv, stroke).
    pub cycle: Cycle,
    /// The table's positions.
    pub rows: Vec<Row>,
    /// Diagram samples: ψ, s, ds/dψ, d²s/dψ².
    pub diagram: Vec<[f64; 4]>,
    /// The position the plans are drawn for.
    pub plan_row: Row,
    /// The plans there.
    pub plans: Plans,
    /// Maximum pressure angle over the cycle per inner joint: (point, ϑmax, φ).
    pub pressure_max: Vec<(usize, f64, f64)>,
}

/// Solve one position into a row.
pub fn row(m: &Mechanism, c: &Cycle, pos: Position) -> Result<Row, LinkageError> {
    let mut sol = m.solution();
    m.solve(pos.phi, &mut sol)?;
    let analogs = c.analogs(m, &sol);
    let mut pressure = Vec::new();
    cycle::pressure_angles(m, &sol, &mut pressure);
    Ok(Row {
        pos,
        sol,
        analogs,
        pressure,
    })
}

/// Analyse: the cycle, `n` positions (or the one at `at`), diagrams, plans.
pub fn analyse(l: &Loaded, src: &TaskSource, at: Option<f64>, n: usize) -> Result<Analysis, Error> {
    let m = &l.mech;
    let loc = |e: LinkageError| locate(src, &l.task, &e);
    let c = Cycle::new(m, l.task.working).map_err(loc)?;
    let sg = m.crank.omega.signum();
    let psi_of = |phi: f64| (sg * (phi - c.start)).rem_euclid(TAU);
    let positions: Vec<Position> = match at {
        Some(phi) => vec![Position {
            label: "at".into(),
            phi,
            psi: psi_of(phi),
        }],
        None => c.positions(m, n),
    };
    let rows = positions
        .into_iter()
        .map(|p| row(m, &c, p))
        .collect::<Result<Vec<_>, _>>()
        .map_err(loc)?;
    let plan_phi = at.or(l.task.at).unwrap_or_else(|| rows.get(1).map_or(c.start, |r| r.pos.phi));
    let plan_row = row(
        m,
        &c,
        Position {
            label: "plan".into(),
            phi: plan_phi,
            psi: psi_of(plan_phi),
        },
    )
    .map_err(loc)?;
    let plans = plans::plans(m, &plan_row.sol);
    let mut sol = m.solution();
    let samples = 360;
    let mut diagram = Vec::with_capacity(samples + 1);
    let mut pressure_max: Vec<(usize, f64, f64)> = Vec::new();
    let mut pa = Vec::new();
    for k in 0..=samples {
        let psi = TAU * k as f64 / samples as f64;
        let phi = c.start + sg * psi;
        m.solve(phi, &mut sol).map_err(loc)?;
        let (s, ds, dds) = c.analogs(m, &sol);
        diagram.push([psi, s, ds, dds]);
        cycle::pressure_angles(m, &sol, &mut pa);
        for &(p, v) in &pa {
            match pressure_max.iter_mut().find(|x| x.0 == p) {
                Some(x) => {
                    if v > x.1 {
                        x.1 = v;
                        x.2 = tmm_geom::angle::wrap_2pi(phi);
                    }
                }
                None => pressure_max.push((p, v, tmm_geom::angle::wrap_2pi(phi))),
            }
        }
    }
    Ok(Analysis {
        cycle: c,
        rows,
        diagram,
        plan_row,
        plans,
        pressure_max,
    })
}

/// Run the `[linkage]` section of a task: documents under `linkage/`.
pub fn run_section(task: &TaskSource) -> Result<Option<SectionOutput>, Error> {
    let Some(l) = load(task)? else { return Ok(None) };
    let a = analyse(&l, task, None, l.task.positions)?;
    let mut docs = Documents::new();
    draw::draw_all(&l, &a, task, "linkage/", &mut docs)?;
    let json = json::document(&l, &a);
    docs.add_json("linkage/linkage.json", &json)?;
    let text = text::report(&l, &a);
    docs.add_text("linkage/linkage.txt", text.clone())?;
    Ok(Some(SectionOutput {
        section: "linkage",
        text,
        json,
        docs,
    }))
}

/// [`run_section`] in two stages: the tables and the JSON now, the
/// drawings when [`crate::run::Staged::drawings`] is called (the same
/// documents as [`run_section`]'s).
pub fn run_staged(task: &TaskSource) -> Result<Option<crate::run::Staged>, Error> {
    let Some(l) = load(task)? else { return Ok(None) };
    let a = analyse(&l, task, None, l.task.positions)?;
    let mut docs = Documents::new();
    let json = json::document(&l, &a);
    docs.add_json("linkage/linkage.json", &json)?;
    let text = text::report(&l, &a);
    docs.add_text("linkage/linkage.txt", text.clone())?;
    let task = task.clone();
    Ok(Some(crate::run::Staged {
        output: SectionOutput {
            section: "linkage",
            text,
            json,
            docs,
        },
        draw: Box::new(move || {
            let mut docs = Documents::new();
            draw::draw_all(&l, &a, &task, "linkage/", &mut docs)?;
            Ok(docs)
        }),
    }))
}

/// The velocity and acceleration plans (SVG) of the position `sol` solved
/// at the crank angle `phi` (rad): the same drawings as `velocity-plan.svg`
/// and `acceleration-plan.svg`, with nothing else of the section computed.
///
/// ```
/// use tmm_report::{TaskSource, run::DEFAULT_TASK, linkage};
/// let l = linkage::load(&TaskSource::new("t.toml", DEFAULT_TASK)).unwrap().unwrap();
/// let mut sol = l.mech.solution();
/// l.mech.solve(1.0, &mut sol).unwrap();
/// let (v, a) = linkage::plan_drawings(&l, &sol, 1.0, &TaskSource::new("t.toml", DEFAULT_TASK));
/// assert!(v.starts_with("<?xml") || v.starts_with("<svg"));
/// assert_ne!(v, a);
/// ```
pub fn plan_drawings(l: &Loaded, sol: &Solution, phi: f64, task: &TaskSource) -> (String, String) {
    draw::plans_at(l, sol, phi, task)
}

/// The human report.
pub fn text_report(l: &Loaded, a: &Analysis) -> String {
    text::report(l, a)
}

/// The JSON document.
pub fn json_document(l: &Loaded, a: &Analysis) -> serde_json::Value {
    json::document(l, a)
}

/// The drawings, as documents named by file name only (`positions.svg`, …),
/// in the task's language and for its sheet format; with `all_plans` also
/// the plans of every position (`plan-velocity-1.svg`, …).
pub fn drawings(l: &Loaded, a: &Analysis, task: &TaskSource, all_plans: bool) -> Result<Documents, Error> {
    let mut docs = Documents::new();
    let which = if all_plans { draw::PlansAt::All } else { draw::PlansAt::One };
    draw::draw_with(l, a, task, "", which, &mut docs)?;
    Ok(docs)
}
