//! `tmm dynamics FILE.toml`: the dynamics of the machine — the mechanism of
//! `[linkage]` under the loads of `[forces]` reduced to its crank, the
//! flywheel for the coefficient of speed fluctuation of `[dynamics]` by
//! Mertsalov's method, Wittenbauer's diagram and exactly, its size, the true
//! ω1(φ), ε1(φ) and, with a motor, the run-up; with `motion =
//! "single-stroke"` the unsteady single stroke driven by a motor by Kloss's
//! formula and the constant-moment stroke beside it.

use std::path::PathBuf;

use tmm_report::Error;
use tmm_report::dynamics::{analyse, drawings, json_document, load, text_report};

use super::common::{checked, json_text, print, read_task, write_dir, written};

/// Dynamics of the machine: reduced inertia and moments, the flywheel, the
/// true crank speed, the run-up with a motor.
#[derive(clap::Args)]
pub struct Args {
    /// The task file (TOML) with [linkage], [forces] and [dynamics] sections
    pub file: Option<PathBuf>,
    /// Print one JSON document (SI, angles in radians) instead of the tables
    #[arg(long)]
    pub json: bool,
    /// Write the diagrams (moments, work, I_II, T_I, Wittenbauer's diagram, ω1, ε1, the run-up) as SVG into this folder
    #[arg(long, value_name = "DIR")]
    pub svg: Option<PathBuf>,
}

/// Run the command.
pub fn run(a: &Args) -> Result<(), Error> {
    let file = a
        .file
        .as_ref()
        .ok_or_else(|| Error::input("FILE", "a task file is needed").with_help("tmm dynamics examples/seed-001-fourbar.toml"))?;
    let task = read_task(file)?;
    // [synthesis] without [linkage]: the synthesised [linkage] is analysed
    let task = tmm_report::synthesis::with_linkage(&task)?.into_owned();
    if tmm_report::dynamics::stroke_task::is_single_stroke(&task)? {
        return single_stroke(a, &task);
    }
    let (l, ft, dt) = load(&task)?.ok_or_else(|| {
        task.missing("dynamics", "the file has no [dynamics] section")
            .with_help("add [dynamics] with delta = 0.02 (the coefficient of speed fluctuation); see examples/seed-001-fourbar.toml")
    })?;
    let d = analyse(&task, &l, &ft, &dt)?;
    let out = if a.json {
        json_text(&json_document(&l, &d))?
    } else {
        checked(text_report(&l, &d))?
    };
    let files = match &a.svg {
        Some(dir) => write_dir(dir, &drawings(&d, task.lang, task.sheet)?)?,
        None => Vec::new(),
    };
    print(&if a.json { out } else { out + &written(&files) })
}

/// `motion = "single-stroke"`: the unsteady single stroke.
fn single_stroke(a: &Args, task: &tmm_report::TaskSource) -> Result<(), Error> {
    use tmm_report::dynamics::stroke;
    let (l, ft, st) = stroke::load(task)?;
    let s = stroke::analyse(task, &l, &ft, &st)?;
    let out = if a.json {
        json_text(&stroke::json_document(&l, &s))?
    } else {
        checked(stroke::text_report(&l, &s))?
    };
    let files = match &a.svg {
        Some(dir) => write_dir(dir, &stroke::drawings(&s, task.lang, task.sheet)?)?,
        None => Vec::new(),
    };
    print(&if a.json { out } else { out + &written(&files) })
}
