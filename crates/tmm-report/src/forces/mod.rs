//! The `[forces]` section: kinetostatics of the `[linkage]` mechanism under
//! the loads given here — inertia loads, reactions in every pair group by
//! group, the balancing torque and force, Zhukovsky's lever, the balancing
//! torque over the cycle and the strength of a chosen link — as tables, one
//! JSON document and SVG drawings.

// the shared `Error` carries the task file for located messages

mod draw;
mod json;
pub mod reaction_cycle;
mod slider_task;
pub mod task;
mod text;

use std::f64::consts::TAU;

use tmm_linkage::Solution;
use tmm_linkage::cycle::{self, Cycle, Position};
use tmm_linkage::dynamics::{DynamicsError, FlywheelPlace, with_crank_motion};
use tmm_linkage::forces::stroke::Working;
use tmm_linkage::forces::zhukovsky::{LeverForce, lever_forces};
use tmm_linkage::forces::{Beam, BeamSample, ForceError, ForceSolution, Kinetostatics, PointForce, SectionSizes, size_sections};

use crate::linkage::{self, Loaded};
use crate::output::{Documents, SectionOutput};
use crate::{Error, TaskSource};

pub use task::{CrankMotion, ForcesTask};

/// One solved position: kinematics and forces.
#[derive(Debug, Clone)]
pub struct Row {
    /// Label (`0`…`11`, `7'`, `at`).
    pub label: String,
    /// Crank angle φ (absolute), rad.
    pub phi: f64,
    /// Crank travel from the start of the working stroke, rad; over a
    /// cycle of several turns, the angle of the machine's cycle.
    pub psi: f64,
    /// `psi` is the angle of the machine's cycle (a cycle of several turns).
    pub machine_cycle: bool,
    /// Kinematics.
    pub sol: Solution,
    /// Forces.
    pub fs: ForceSolution,
}

/// A link as a beam at the detailed position.
#[derive(Debug, Clone)]
pub struct BeamResult {
    /// The beam.
    pub beam: Beam,
    /// Its diagrams N, Q, M.
    pub samples: Vec<BeamSample>,
    /// The section sizes.
    pub sizes: SectionSizes,
    /// Names of the axis points.
    pub names: (String, String),
    /// Allowed stress, Pa.
    pub allowed: f64,
    /// h/b.
    pub k: f64,
}

/// Everything the section computes.
#[derive(Debug, Clone)]
pub struct Analysis {
    /// The cycle of the output (dead positions, working stroke).
    pub cycle: Cycle,
    /// The equally spaced positions.
    pub rows: Vec<Row>,
    /// The position shown in detail (free bodies, lever, beam).
    pub detail: Row,
    /// The forces on Zhukovsky's lever at the detailed position.
    pub lever: Vec<LeverForce>,
    /// Balancing torque over the cycle: (ψ, φ, M_b, M_Zh), 361 samples.
    pub curve: Vec<[f64; 4]>,
    /// The strength of a link, if asked.
    pub beam: Option<BeamResult>,
    /// The reactions at every step of the cycle, if asked (`[forces.cycle] step`).
    pub reaction_cycle: Option<reaction_cycle::ReactionCycle>,
    /// Each windowed stroke force's angles, if any.
    pub windows: Vec<WindowAngles>,
    /// The weight of the flywheel on the crank shaft, m·g, N, when the
    /// crank moves as the dynamics finds it, a flywheel is needed there and
    /// gravity is given: a force at the crank's pivot, in the frame's
    /// reaction on the crank (П2: the book's G_1Y = −m_M·g at O in R_10).
    pub flywheel_weight: Option<f64>,
}

/// Where a force on one stroke with a window (the shaper's overrun) starts
/// and stops acting, as cycle angles from the start of its acting stroke
/// (rad, in the direction of rotation): the book's φ′ and φ″ (П3, p. 131).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WindowAngles {
    /// The load's index in [`tmm_linkage::forces::Loads::sliders`].
    pub load: usize,
    /// The window, fractions of the stroke.
    pub window: (f64, f64),
    /// The stroke H, m.
    pub stroke: f64,
    /// The acting stroke's start, absolute crank angle, rad.
    pub phi_start: f64,
    /// Where the slider enters the window on the acting stroke (φ′).
    pub on: f64,
    /// Where it leaves the window on the acting stroke.
    pub off: f64,
    /// Where, returning, it passes the window's start again (φ″).
    pub back: f64,
    /// The crank's turn with the slider within the first overrun, φ′ + (2π − φ″).
    pub overrun: f64,
}

/// Turn a core force error into a located input error.
pub fn locate(src: &TaskSource, l: &Loaded, t: &ForcesTask, e: &ForceError) -> Error {
    match e {
        ForceError::Kinematics(k) => linkage::locate(src, &l.task, k),
        ForceError::Load { field, message } => {
            // the longest named prefix of the field
            let mut f = field.as_str();
            let span = loop {
                if let Some(s) = t.spans.get(f) {
                    break s.clone();
                }
                match f.rsplit_once('.') {
                    Some((head, _)) => f = head,
                    None => break t.section.clone(),
                }
            };
            // a slider load is named as the task names it
            let shown = match field.strip_prefix("sliders[").and_then(|r| r.split_once(']')) {
                Some((i, rest)) => match i.parse::<usize>().ok().and_then(|i| t.slider_fields.get(i)) {
                    Some(name) => format!("{name}{rest}"),
                    None => field.clone(),
                },
                None => field.clone(),
            };
            Error::at(src, span, &format!("forces.{shown}"), message)
        }
        other => Error::at(src, t.section.clone(), "forces", other.to_string()),
    }
}

/// Read the `[linkage]` and `[forces]` sections; `None` when there is no `[forces]`.
pub fn load(src: &TaskSource) -> Result<Option<(Loaded, ForcesTask)>, Error> {
    let has_forces = task_has_forces(src)?;
    if !has_forces {
        return Ok(None);
    }
    let l = linkage::load(src)?.ok_or_else(|| {
        Error::input(&src.name, "the [forces] section needs a [linkage] section describing the mechanism")
            .with_help("see examples/seed-001-fourbar.toml")
    })?;
    let t = task::read(src, &l.def, &l.mech)?.ok_or_else(|| Error::input(&src.name, "no [forces] section"))?;
    Ok(Some((l, t)))
}

fn task_has_forces(src: &TaskSource) -> Result<bool, Error> {
    #[derive(serde::Deserialize)]
    struct Probe {
        forces: Option<toml::Value>,
    }
    let p: Probe = src.parse("forces")?;
    Ok(p.forces.is_some())
}

/// The core's working stroke for the linkage's choice.
pub(crate) fn working(w: cycle::Working) -> Working {
    match w {
        cycle::Working::Slower => Working::Slower,
        cycle::Working::Increasing => Working::Increasing,
        cycle::Working::Decreasing => Working::Decreasing,
    }
}

/// Solve the cycle, the equally spaced positions, the detailed position (at
/// `at`, else the section's `at`, else the linkage's, else position 1), the
/// balancing torque over the cycle and the strength of the chosen link.
pub fn analyse(src: &TaskSource, l: &Loaded, t: &ForcesTask, at: Option<f64>) -> Result<Analysis, Error> {
    let m = &l.mech;
    let loc = |e: ForceError| locate(src, l, t, &e);
    linkage::require_full_turn(src, l, "forces")?;
    let c = Cycle::new(m, l.task.working).map_err(|e| linkage::locate(src, &l.task, &e))?;
    // the true motion of the crank, when asked: ω₁, ε₁ at each angle from
    // the dynamics of the machine (docs/dynamics.md, "Kinetostatics with the
    // true motion")
    let dynamics = match t.crank_motion {
        CrankMotion::Constant => None,
        CrankMotion::Dynamics => {
            let span = t.crank_motion_span.clone().unwrap_or(t.section.clone());
            let dt = crate::dynamics::task::read(src, working(l.task.working))?.ok_or_else(|| {
                Error::at(
                    src,
                    span,
                    "forces.crank_motion",
                    "crank_motion = \"dynamics\" needs a [dynamics] section",
                )
            })?;
            let d = crate::dynamics::analyse(src, l, t, &dt)?;
            Some((dt, d))
        }
    };
    // the flywheel on the crank shaft weighs on the crank's pivot: its
    // weight m·g there goes into the frame's reaction on the crank only (a
    // force at a fixed point does no work and has no moment about it)
    let mut loads = t.loads.clone();
    let flywheel_weight = match &dynamics {
        Some((_, d)) if matches!(d.spec.flywheel.place, FlywheelPlace::Crank) && loads.gravity.hypot() > 0.0 => d.flywheel.map(|fw| {
            loads.links[m.crank.link].forces.push(PointForce {
                local: m.crank.pivot_local,
                force: loads.gravity * fw.mass,
            });
            fw.mass * loads.gravity.hypot()
        }),
        _ => None,
    };
    let mut k = Kinetostatics::with_working(m, loads, working(l.task.working)).map_err(loc)?;
    let mut sd = dynamics.as_ref().map(|(_, d)| d.solution());
    let sg = m.crank.omega.signum();
    let psi_of = |phi: f64| (sg * (phi - c.start)).rem_euclid(TAU);
    let mut sol = m.solution();
    let mut fs = k.result();
    // a cycle of several turns (a four-stroke engine) is walked by the
    // machine's cycle angle: the crank angle alone does not tell the turn
    let turns = t.loads.cycle.turns.max(1) as usize;
    let mut solve = |label: String, phi: f64, cyc: Option<f64>, k: &mut Kinetostatics| -> Result<Row, Error> {
        match (&dynamics, sd.as_mut()) {
            (Some((dt, d)), Some(sd)) => {
                let dloc = |e: DynamicsError| crate::dynamics::locate(src, l, t, dt, &e);
                let (w, e) = match cyc {
                    Some(psi) => d.crank_motion_at_cycle(psi, sd).map_err(dloc)?,
                    None => d.crank_motion_at(phi, sd).map_err(dloc)?,
                };
                let mt = with_crank_motion(m, w, e).map_err(dloc)?;
                mt.solve(phi, &mut sol).map_err(|e| linkage::locate(src, &l.task, &e))?;
                if let Some(psi) = cyc {
                    k.set_cycle_angle(psi);
                }
                k.solve(&sol, &mut fs).map_err(loc)?;
            }
            _ => {
                if let Some(psi) = cyc {
                    k.set_cycle_angle(psi);
                }
                k.solve_at(phi, &mut sol, &mut fs).map_err(loc)?
            }
        }
        Ok(Row {
            label,
            phi: if cyc.is_some() { tmm_geom::angle::wrap_2pi(phi) } else { phi },
            psi: cyc.unwrap_or_else(|| psi_of(phi)),
            machine_cycle: cyc.is_some(),
            sol: sol.clone(),
            fs: fs.clone(),
        })
    };
    let mut rows = Vec::new();
    if turns > 1 {
        let n = l.task.positions * turns;
        let period = TAU * turns as f64;
        for i in 0..n {
            let psi = period * i as f64 / n as f64;
            rows.push(solve(i.to_string(), k.cycle_start + sg * psi, Some(psi), &mut k)?);
        }
    } else {
        let positions: Vec<Position> = c.positions(m, l.task.positions);
        for p in positions {
            rows.push(solve(p.label, p.phi, None, &mut k)?);
        }
    }
    let phi_d = at.or(t.at).or(l.task.at).unwrap_or_else(|| rows.get(1).map_or(c.start, |r| r.phi));
    // over a cycle of several turns the angle is the crank's angle counted
    // on through the cycle (420° is the second turn's 60°, with that
    // phase's loads), not folded into the first turn
    let cd = if turns > 1 {
        Some((sg * (phi_d - k.cycle_start)).rem_euclid(TAU * turns as f64))
    } else {
        None
    };
    let detail = solve(if at.is_some() { "at".into() } else { "detail".into() }, phi_d, cd, &mut k)?;
    let mut curve = Vec::with_capacity(360 * turns + 1);
    for i in 0..=360 * turns {
        let psi = TAU * i as f64 / 360.0;
        if turns > 1 {
            let phi = k.cycle_start + sg * psi;
            let r = solve(String::new(), phi, Some(psi), &mut k)?;
            curve.push([psi, tmm_geom::angle::wrap_2pi(phi), r.fs.balancing_moment, r.fs.zhukovsky_moment]);
        } else {
            let phi = c.start + sg * psi;
            let r = solve(String::new(), phi, None, &mut k)?;
            curve.push([psi, tmm_geom::angle::wrap_2pi(phi), r.fs.balancing_moment, r.fs.zhukovsky_moment]);
        }
    }
    let reaction_cycle = match &t.reaction_cycle {
        None => None,
        Some(spec) => {
            let lumped = dynamics.as_ref().map(|(_, d)| reaction_cycle::Lumped {
                inertia: d.motion.inertia_constant - d.inertia_given.crank,
                moment: sg * d.cycle.driving_moment,
            });
            let mut rc = reaction_cycle::ReactionCycle::new(
                spec.step,
                &m.link_names,
                &detail.fs,
                spec.diagrams.iter().map(|d| d.0.clone()).collect(),
                spec.hodographs.iter().map(|d| d.0.clone()).collect(),
                lumped,
            );
            let drawable = rc.drawable();
            for (key, list) in [("diagrams", &spec.diagrams), ("hodographs", &spec.hodographs)] {
                for (i, (name, span)) in list.iter().enumerate() {
                    let ok = if key == "hodographs" {
                        rc.names.contains(name)
                    } else {
                        drawable.contains(name)
                    };
                    if !ok {
                        return Err(Error::at(
                            src,
                            span.clone(),
                            &format!("forces.cycle.{key}[{i}]"),
                            format!("no reaction `{name}` in this mechanism"),
                        )
                        .with_help(format!(
                            "name one of {} (R_ij: the force on link i by link j, 0 the frame{})",
                            if key == "hodographs" {
                                rc.names.join(", ")
                            } else {
                                drawable.join(", ")
                            },
                            if key == "hodographs" {
                                ""
                            } else {
                                "; M_ij: a guide's reaction couple"
                            }
                        )));
                    }
                }
            }
            let period = TAU * turns as f64;
            let n = (period / spec.step).round() as usize;
            for i in 0..=n {
                let psi = period * i as f64 / n as f64;
                let start = if turns > 1 { k.cycle_start } else { c.start };
                let phi = start + sg * psi;
                let r = solve(String::new(), phi, if turns > 1 { Some(psi) } else { None }, &mut k)?;
                rc.push(psi, tmm_geom::angle::wrap_2pi(phi), r.sol.links[m.crank.link].eps, &r.fs);
            }
            Some(rc)
        }
    };
    let mut windows = Vec::new();
    for (j, a) in k.sliders.iter().enumerate() {
        if let tmm_linkage::forces::SliderLoadKind::StrokeForce { window, .. } = a.load.kind {
            if window == (0.0, 1.0) {
                continue;
            }
            let st = &a.stroke;
            let mut s2 = m.solution();
            let h = st.travel;
            let on = st.angle_at_travel(m, &mut s2, window.0 * h, true).map_err(loc)?;
            let off = st.angle_at_travel(m, &mut s2, window.1 * h, true).map_err(loc)?;
            let back = st.angle_at_travel(m, &mut s2, window.0 * h, false).map_err(loc)?;
            windows.push(WindowAngles {
                load: j,
                window,
                stroke: h,
                phi_start: st.phi_start,
                on,
                off,
                back,
                overrun: on + (TAU - back),
            });
        }
    }
    let mut lever = lever_forces(m, &k.loads, &detail.sol, &detail.fs);
    // the slider loads (a cylinder's gas force from its indicator diagram, a
    // stroke force) at the images of their points, `Fc<link>`: the
    // kinetostatics and its virtual power carry them, so the lever does too
    // and its moments sum to zero with P_b
    for (j, a) in k.sliders.iter().enumerate() {
        let force = detail.fs.slider_forces[j];
        if force.hypot() == 0.0 {
            continue;
        }
        let (_, at) = a.force(&detail.sol, detail.psi);
        lever.push(LeverForce {
            label: format!("Fc{}", m.link_names[a.load.link]),
            image: tmm_geom::perp(detail.sol.links[a.load.link].kin_at(at).0),
            force,
        });
    }
    let beam = match &t.strength {
        Some(s) => {
            let beam = Beam::new(m, &k.loads, &detail.sol, &detail.fs, s.link, s.axis.0, s.axis.1).map_err(loc)?;
            let samples = beam.diagrams(200);
            let sizes = size_sections(&samples, s.allowed, s.k).map_err(loc)?;
            Some(BeamResult {
                beam,
                samples,
                sizes,
                names: s.names.clone(),
                allowed: s.allowed,
                k: s.k,
            })
        }
        None => None,
    };
    Ok(Analysis {
        cycle: c,
        rows,
        detail,
        lever,
        curve,
        beam,
        reaction_cycle,
        windows,
        flywheel_weight,
    })
}

/// Run the `[forces]` section of a task: documents under `forces/`.
pub fn run_section(task: &TaskSource) -> Result<Option<SectionOutput>, Error> {
    let Some((l, t)) = load(task)? else { return Ok(None) };
    let a = analyse(task, &l, &t, None)?;
    let mut docs = Documents::for_task(task);
    draw::draw_all(&l, &t, &a, task, "forces/", &mut docs)?;
    let json = json::document(&l, &t, &a);
    docs.add_json("forces/forces.json", &json)?;
    let text = text::report(&l, &t, &a);
    docs.add_text("forces/forces.txt", text.clone())?;
    Ok(Some(SectionOutput {
        section: "forces",
        text,
        json,
        docs,
    }))
}

/// [`run_section`] in two stages: the tables and the JSON now, the
/// drawings when [`crate::run::Staged::drawings`] is called (the same
/// documents as [`run_section`]'s).
pub fn run_staged(task: &TaskSource) -> Result<Option<crate::run::Staged>, Error> {
    let Some((l, t)) = load(task)? else { return Ok(None) };
    let a = analyse(task, &l, &t, None)?;
    let mut docs = Documents::for_task(task);
    let json = json::document(&l, &t, &a);
    docs.add_json("forces/forces.json", &json)?;
    let text = text::report(&l, &t, &a);
    docs.add_text("forces/forces.txt", text.clone())?;
    let task = task.clone();
    Ok(Some(crate::run::Staged {
        output: SectionOutput {
            section: "forces",
            text,
            json,
            docs,
        },
        draw: Box::new(move || {
            let mut docs = Documents::for_task(&task);
            draw::draw_all(&l, &t, &a, &task, "forces/", &mut docs)?;
            Ok(docs)
        }),
    }))
}

/// The human report.
pub fn text_report(l: &Loaded, t: &ForcesTask, a: &Analysis) -> String {
    text::report(l, t, a)
}

/// The JSON document.
pub fn json_document(l: &Loaded, t: &ForcesTask, a: &Analysis) -> serde_json::Value {
    json::document(l, t, a)
}

/// The drawings, as documents named by file name only (`group-1.svg`, …),
/// in the task's language and for its sheet format.
pub fn drawings(l: &Loaded, t: &ForcesTask, a: &Analysis, task: &TaskSource) -> Result<Documents, Error> {
    let mut docs = Documents::for_task(task);
    draw::draw_all(l, t, a, task, "", &mut docs)?;
    Ok(docs)
}
