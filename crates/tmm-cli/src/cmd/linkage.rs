//! `tmm linkage FILE.toml`: structure and kinematics of a lever mechanism.

use std::path::PathBuf;

use tmm_geom::units::Dim;
use tmm_report::Error;
use tmm_report::linkage::{analyse, drawings, json_document, load, text_report};
use tmm_report::task::arg_qty;

use super::common::{checked, json_text, print, read_task, write_dir, written};

/// Structure (Assur groups, formula) and kinematics (dead positions, Kv, the
/// 12-position table, diagrams, velocity and acceleration plans) of the
/// `[linkage]` section of a task file. The input is a crank, or a slider on
/// a fixed guide driven at a given speed over a travel
/// (`input = { slider = "1", speed = "0.5 m/s" }`, `travel = ["0 mm", "120 mm"]`):
/// then the positions are equal steps of the slider's s and the analogues are d/ds.
#[derive(clap::Args)]
pub struct Args {
    /// The task file (TOML) with a [linkage] section
    pub file: PathBuf,
    /// One crank angle only: the absolute angle of the crank from the x-axis, counter-clockwise (e.g. 15, "15 deg", "0.26 rad"); for a slider input the slider's s inside the travel (e.g. "40 mm"); or "all": the table of every position and, with --svg, the velocity and acceleration plans of each (plan-velocity-N.svg, plan-acceleration-N.svg)
    #[arg(long, value_name = "DEG|MM", allow_hyphen_values = true)]
    pub at: Option<String>,
    /// Number of equally spaced positions from the dead position that starts the working stroke; for a slider input the number of equal steps over the travel (default: the file's, else 12)
    #[arg(long, value_name = "N")]
    pub positions: Option<usize>,
    /// Print one JSON document (SI, angles in radians) instead of the tables
    #[arg(long)]
    pub json: bool,
    /// Write the drawings (positions, diagrams, velocity and acceleration plans) as SVG into this folder
    #[arg(long, value_name = "DIR")]
    pub svg: Option<PathBuf>,
}

/// Run the command.
pub fn run(a: &Args) -> Result<(), Error> {
    let task = read_task(&a.file)?;
    // [synthesis] without [linkage]: the synthesised [linkage] is analysed
    let task = tmm_report::synthesis::with_linkage(&task)?.into_owned();
    let l = load(&task)?.ok_or_else(|| {
        task.missing("linkage", "the file has no [linkage] section")
            .with_help("see examples/seed-001-fourbar.toml")
    })?;
    let all = a.at.as_deref().is_some_and(|t| t.trim().eq_ignore_ascii_case("all"));
    let at = match &a.at {
        Some(_) if all => None,
        Some(t) if l.task.travel.is_some() => Some(arg_qty("--at", t, Dim::Length)?),
        Some(t) => Some(arg_qty("--at", t, Dim::Angle)?),
        None => None,
    };
    if a.positions == Some(0) || a.positions.is_some_and(|n| n > tmm_report::linkage::task::MAX_POSITIONS) {
        return Err(Error::input(
            "--positions",
            format!("must be from 1 to {} (0.1° apart)", tmm_report::linkage::task::MAX_POSITIONS),
        ));
    }
    let n = a.positions.unwrap_or(l.task.positions);
    let an = analyse(&l, &task, at, n)?;
    let out = if a.json {
        json_text(&json_document(&l, &an))?
    } else {
        checked(text_report(&l, &an))?
    };
    let files = match &a.svg {
        Some(dir) => write_dir(dir, &drawings(&l, &an, &task, all)?)?,
        None => Vec::new(),
    };
    print(&if a.json { out } else { out + &written(&files) })
}
