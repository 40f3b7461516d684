//! The `[linkage]` section: read the mechanism, analyse its structure and its
//! cycle, and write the tables, the JSON document and the drawings.

pub(crate) mod draw;
mod json;
mod structure;
pub mod task;
mod text;
pub mod travel;

use std::f64::consts::TAU;

use tmm_linkage::cycle::{self, Cycle, Output, Position};
use tmm_linkage::plans::{self, Plans};
use tmm_linkage::ranges::PartialCycle;
use tmm_linkage::{LinkageError, Mechanism, MechanismDef, Solution};

use crate::output::{Documents, SectionOutput};
use crate::{Error, TaskSource};

pub use task::{LinkageTask, RangeMode, Travel};

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
        None => match e {
            // a slider input that does not assemble at some s: its travel
            LinkageError::AssemblyAtTravel { .. } | LinkageError::SingularAtTravel { .. } => {
                ("linkage.travel".to_string(), t.spans.get("travel").cloned())
            }
            _ => ("linkage".to_string(), None),
        },
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
                .map(|g| format!("{g}; or set range = \"partial\" in [linkage] to analyse it over the crank angles where it assembles"))
                .unwrap_or_else(|| "check the link lengths and the fixed points; a crank must be able to turn a full revolution, or set range = \"partial\" in [linkage] to analyse it over the crank angles where it assembles".into()),
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

/// How the output's displacement and its analogs are read: from `s0`, along
/// `sign`, per unit of crank travel ψ (the same measure as
/// [`Cycle::analogs`]: ds/dψ = v/|ω1|, d²s/dψ² = (a − ds/dψ·ε1·sgn ω1)/ω1²).
#[derive(Debug, Clone, Copy)]
pub struct Reading {
    /// The output coordinate.
    pub output: Output,
    /// The coordinate where s = 0, m or rad.
    pub s0: f64,
    /// +1 or −1: the direction s is counted in.
    pub sign: f64,
}

impl Reading {
    /// The reading of a full-turn cycle (from the start of the working stroke).
    pub fn of_cycle(c: &Cycle) -> Self {
        Reading {
            output: c.output,
            s0: c.s_start,
            sign: c.work_sign,
        }
    }

    /// s, ds/dψ, d²s/dψ² at a solved position.
    pub fn analogs(&self, m: &Mechanism, sol: &Solution) -> (f64, f64, f64) {
        let o = self.output.read(sol, self.s0);
        let w = m.crank.omega.abs();
        let s = self.sign * (o.s - self.s0);
        let ds = self.sign * o.v / w;
        let dds = (self.sign * o.a - ds * m.crank.eps * m.crank.omega.signum()) / (w * w);
        (s, ds, dds)
    }
}

/// Everything the section reports.
#[derive(Debug, Clone)]
pub struct Analysis {
    /// The full-turn cycle (dead positions, Kv, stroke); `None` when the
    /// mechanism is analysed over its assembly ranges (`range = "partial"`).
    pub cycle: Option<Cycle>,
    /// The assembly ranges and gaps; `None` for a full turn.
    pub partial: Option<PartialCycle>,
    /// The travel of a slider input; `None` for a crank. Then each row's
    /// `pos.phi` is the slider's s (m), `pos.psi` is s from the travel's
    /// start, the analogues are d/ds and the diagrams' first column is s
    /// from the start (m); `start` is the travel's first s.
    pub travel: Option<Travel>,
    /// How the output is read.
    pub reading: Reading,
    /// The crank angle where ψ = 0, rad.
    pub start: f64,
    /// The table's positions.
    pub rows: Vec<Row>,
    /// Indices into `rows` where a new assembly range starts (empty for a full turn).
    pub row_breaks: Vec<usize>,
    /// Diagram samples: ψ, s, ds/dψ, d²s/dψ².
    pub diagram: Vec<[f64; 4]>,
    /// Indices into `diagram` where a new assembly range starts, after a
    /// gap (empty for a full turn).
    pub diagram_breaks: Vec<usize>,
    /// The gaps in ψ (from, to), rad, where the mechanism does not assemble
    /// (empty for a full turn).
    pub diagram_gaps: Vec<(f64, f64)>,
    /// The position the plans are drawn for.
    pub plan_row: Row,
    /// The plans there.
    pub plans: Plans,
    /// Maximum pressure angle over the cycle per inner joint: (point, ϑmax, φ).
    pub pressure_max: Vec<(usize, f64, f64)>,
}

/// Solve one position into a row.
pub fn row(m: &Mechanism, r: &Reading, pos: Position) -> Result<Row, LinkageError> {
    row_with(m, pos, |sol| r.analogs(m, sol))
}

/// A row of the table at `pos` with the output's analogues given by
/// `analogs` of the solved position (the crank's over ψ, a slider input's
/// over s).
pub(crate) fn row_with(m: &Mechanism, pos: Position, analogs: impl FnOnce(&Solution) -> (f64, f64, f64)) -> Result<Row, LinkageError> {
    let mut sol = m.solution();
    m.solve(pos.phi, &mut sol)?;
    let analogs = analogs(&sol);
    let mut pressure = Vec::new();
    cycle::pressure_angles(m, &sol, &mut pressure);
    Ok(Row {
        pos,
        sol,
        analogs,
        pressure,
    })
}

/// Refuse a section that needs a crank (the forces over the cycle, the
/// machine's dynamics and flywheel, Zhukovsky's lever) when the linkage is
/// driven by a slider.
pub fn require_crank(src: &TaskSource, l: &Loaded, section: &str) -> Result<(), Error> {
    if let Some(d) = &l.mech.drive {
        let span = l.task.spans.get("input.slider").cloned().unwrap_or(l.task.section.clone());
        return Err(Error::at(
            src,
            span,
            "linkage.input.slider",
            format!(
                "[{section}] needs a crank that turns as the input; this linkage is driven by the slider `{}`",
                l.mech.link_names[d.link]
            ),
        )
        .with_help(format!(
            "drive the linkage by a crank (input.link and input.speed in rpm) or remove [{section}]"
        )));
    }
    Ok(())
}

/// Refuse a section that needs the steady cycle of a full turn when the
/// linkage is analysed over its assembly ranges only.
pub fn require_full_turn(src: &TaskSource, l: &Loaded, section: &str) -> Result<(), Error> {
    require_crank(src, l, section)?;
    if l.task.range == RangeMode::Partial {
        return Err(Error::at(
            src,
            l.task.range_span.clone().unwrap_or(l.task.section.clone()),
            "linkage.range",
            format!("[{section}] needs a crank that turns a full revolution; range = \"partial\" analyses only the ranges where the mechanism assembles"),
        )
        .with_help("the forces and the steady motion of a machine are found over a full turn of the crank: remove range = \"partial\" and choose link lengths for which the crank turns fully"));
    }
    Ok(())
}

/// The assembly range that holds `phi` (any turn), or the error naming the nearest one.
fn inside_range(p: &PartialCycle, phi: f64) -> Result<f64, String> {
    let mut best: Option<(f64, &tmm_linkage::ranges::AssemblyRange)> = None;
    for rc in &p.ranges {
        let r = &rc.range;
        // the representative of phi in [from, from + 2π)
        let x = r.from + (phi - r.from).rem_euclid(TAU);
        if x <= r.to + 1e-12 {
            return Ok(x.min(r.to));
        }
        let d = (x - r.to).min(r.from + TAU - x);
        if best.is_none_or(|b| d < b.0) {
            best = Some((d, r));
        }
    }
    let ranges: Vec<String> = p
        .ranges
        .iter()
        .map(|r| format!("{:.4}°…{:.4}°", r.range.from.to_degrees(), r.range.to.to_degrees()))
        .collect();
    Err(match best {
        Some((_, r)) => format!(
            "the mechanism does not assemble at φ = {:.4}°; the nearest range where it does is {:.4}°…{:.4}° (all ranges: {})",
            phi.to_degrees(),
            r.from.to_degrees(),
            r.to.to_degrees(),
            ranges.join(", ")
        ),
        None => format!("the mechanism does not assemble at φ = {:.4}°", phi.to_degrees()),
    })
}

/// How far inside each end of an assembly range the table's positions and
/// the diagrams start and end, rad (0.5°, at most a tenth of the range).
pub const INSET: f64 = 0.5 * std::f64::consts::PI / 180.0;

/// Samples of the diagrams over a full turn of the crank.
const SAMPLES_PER_TURN: f64 = 360.0;

/// Analyse: the cycle, `n` positions (or the one at `at`), diagrams, plans.
pub fn analyse(l: &Loaded, src: &TaskSource, at: Option<f64>, n: usize) -> Result<Analysis, Error> {
    if let Some(t) = l.task.travel {
        return travel::analyse(l, src, t, at, n);
    }
    let m = &l.mech;
    let loc = |e: LinkageError| locate(src, &l.task, &e);
    let sg = m.crank.omega.signum();
    let (cycle, partial, reading, start) = match l.task.range {
        RangeMode::Full => {
            let c = Cycle::new(m, l.task.working).map_err(loc)?;
            let (r, st) = (Reading::of_cycle(&c), c.start);
            (Some(c), None, r, st)
        }
        RangeMode::Partial => {
            let p = PartialCycle::new(m).map_err(loc)?;
            // ψ runs in the direction of rotation from the first range's first angle
            let first = if sg > 0.0 { p.ranges.first() } else { p.ranges.last() };
            let start = first.map_or(0.0, |r| if sg > 0.0 { r.range.from } else { r.range.to });
            let mut sol = m.solution();
            m.solve(start, &mut sol).map_err(loc)?;
            let s0 = p.output.read(&sol, 0.0).s;
            let r = Reading {
                output: p.output,
                s0,
                sign: 1.0,
            };
            (None, Some(p), r, start)
        }
    };
    let psi_of = |phi: f64| (sg * (phi - start)).rem_euclid(TAU);
    // the assembly ranges in order of crank travel (first, last), and the
    // pieces swept for the table and the diagrams
    let ends: Vec<(f64, f64)> = match &partial {
        None => vec![(start, start + sg * TAU)],
        Some(p) => {
            let mut v: Vec<(f64, f64)> = p.ranges.iter().map(|r| (r.range.from, r.range.to)).collect();
            if sg < 0.0 {
                v.reverse();
                for x in &mut v {
                    *x = (x.1, x.0);
                }
            }
            v
        }
    };
    // a range ends at a group's dead centre, where the velocities grow
    // without bound: the table and the diagrams keep INSET inside it
    let pieces: Vec<(f64, f64)> = match &partial {
        None => ends.clone(),
        Some(_) => ends
            .iter()
            .map(|&(a, b)| {
                let d = sg * INSET.min(0.1 * (b - a).abs());
                (a + d, b - d)
            })
            .collect(),
    };
    // an `at` given to the command (`--at`) or written in the file (`linkage.at`)
    let at_checked = |phi: f64, in_file: bool| -> Result<f64, Error> {
        match &partial {
            None => Ok(phi),
            Some(p) => inside_range(p, phi).map_err(|msg| {
                let help = "choose an angle inside one of the ranges where the mechanism assembles";
                if in_file {
                    let span = l.task.spans.get("at").cloned().unwrap_or(l.task.section.clone());
                    Error::at(src, span, "linkage.at", msg).with_help(help)
                } else {
                    Error::input("--at", msg).with_help(help)
                }
            }),
        }
    };
    let at = at.map(|a| at_checked(a, false)).transpose()?;
    let mut row_breaks = Vec::new();
    let positions: Vec<Position> = match (at, &cycle) {
        (Some(phi), _) => vec![Position {
            label: "at".into(),
            phi,
            psi: psi_of(phi),
        }],
        (None, Some(c)) => c.positions(m, n),
        (None, None) => {
            // n positions over each range, its ends included: numbered
            // 0 … n − 1 as the course numbers a crank's positions when the
            // mechanism assembles over one range (a lever driven by a
            // cylinder over its swing), "range.k" over several
            let k_max = n.max(2);
            let single = pieces.len() == 1;
            let mut out = Vec::new();
            for (i, &(a, b)) in pieces.iter().enumerate() {
                if i > 0 {
                    row_breaks.push(out.len());
                }
                for k in 0..k_max {
                    let phi = a + (b - a) * k as f64 / (k_max - 1) as f64;
                    out.push(Position {
                        label: if single { k.to_string() } else { format!("{}.{k}", i + 1) },
                        phi: tmm_geom::angle::wrap_2pi(phi),
                        psi: psi_of(phi),
                    });
                }
            }
            out
        }
    };
    let rows = positions
        .into_iter()
        .map(|p| row(m, &reading, p))
        .collect::<Result<Vec<_>, _>>()
        .map_err(loc)?;
    let plan_phi = match (at, l.task.at) {
        (Some(a), _) => a,
        (None, Some(a)) => at_checked(a, true)?,
        (None, None) => match &partial {
            None => rows.get(1).map_or(start, |r| r.pos.phi),
            // the middle of the first range
            Some(_) => pieces.first().map_or(start, |&(a, b)| tmm_geom::angle::wrap_2pi(0.5 * (a + b))),
        },
    };
    let plan_row = row(
        m,
        &reading,
        Position {
            label: "plan".into(),
            phi: plan_phi,
            psi: psi_of(plan_phi),
        },
    )
    .map_err(loc)?;
    let plans = plans::plans(m, &plan_row.sol);
    let mut sol = m.solution();
    let mut diagram = Vec::new();
    let mut diagram_breaks = Vec::new();
    let mut pressure_max: Vec<(usize, f64, f64)> = Vec::new();
    let mut pa = Vec::new();
    for (i, &(a, b)) in pieces.iter().enumerate() {
        if i > 0 {
            diagram_breaks.push(diagram.len());
        }
        let samples = ((b - a).abs() / TAU * SAMPLES_PER_TURN).ceil().max(2.0) as usize;
        for k in 0..=samples {
            let phi = a + (b - a) * k as f64 / samples as f64;
            m.solve(phi, &mut sol).map_err(loc)?;
            let (s, ds, dds) = reading.analogs(m, &sol);
            // ψ unwrapped over the pieces: the full turn ends at 2π
            let psi = sg * (phi - start);
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
    }
    let diagram_gaps: Vec<(f64, f64)> = match &partial {
        None => Vec::new(),
        Some(_) => (0..ends.len())
            .map(|i| {
                let end = sg * (ends[i].1 - start);
                let next = ends.get(i + 1).map_or(TAU, |p| sg * (p.0 - start));
                (end, next)
            })
            .filter(|g| g.1 - g.0 > 1e-9)
            .collect(),
    };
    Ok(Analysis {
        cycle,
        travel: None,
        diagram_gaps,
        partial,
        reading,
        start,
        rows,
        row_breaks,
        diagram,
        diagram_breaks,
        plan_row,
        plans,
        pressure_max,
    })
}

/// Run the `[linkage]` section of a task: documents under `linkage/`.
pub fn run_section(task: &TaskSource) -> Result<Option<SectionOutput>, Error> {
    let Some(l) = load(task)? else { return Ok(None) };
    let a = analyse(&l, task, None, l.task.positions)?;
    let mut docs = Documents::for_task(task);
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
    let mut docs = Documents::for_task(task);
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
            let mut docs = Documents::for_task(&task);
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
    let mut docs = Documents::for_task(task);
    let which = if all_plans { draw::PlansAt::All } else { draw::PlansAt::One };
    draw::draw_with(l, a, task, "", which, &mut docs)?;
    Ok(docs)
}

/// The structural scheme and the Assur groups drawn apart
/// (`structure.svg`): see [`structure::structure_scheme`].
pub fn structure_drawing(l: &Loaded, a: &Analysis, task: &TaskSource) -> crate::picture::Picture {
    structure::structure_scheme(l, a, task)
}
