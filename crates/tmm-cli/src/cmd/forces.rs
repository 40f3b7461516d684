//! `tmm forces FILE.toml`: kinetostatics of the `[linkage]` mechanism under
//! the loads of the `[forces]` section — reactions in every pair group by
//! group, the balancing torque and force, Zhukovsky's lever, the strength of
//! a link.

use std::path::PathBuf;

use tmm_geom::units::Dim;
use tmm_report::Error;
use tmm_report::forces::{analyse, drawings, json_document, load, text_report};
use tmm_report::task::arg_qty;

use super::common::{checked, json_text, print, read_task, write_dir, written};

/// Kinetostatics (force analysis) of the `[linkage]` mechanism under the
/// loads of the `[forces]` section of a task file.
#[derive(clap::Args)]
pub struct Args {
    /// The task file (TOML) with [linkage] and [forces] sections
    pub file: Option<PathBuf>,
    /// The crank angle shown in detail: absolute, from the x-axis, counter-clockwise (e.g. 15, "15 deg", "0.26 rad")
    #[arg(long, value_name = "DEG", allow_hyphen_values = true)]
    pub at: Option<String>,
    /// Print one JSON document (SI, angles in radians) instead of the tables
    #[arg(long)]
    pub json: bool,
    /// Write the drawings (free bodies with force polygons, Zhukovsky's lever, the balancing torque, N/Q/M) as SVG into this folder
    #[arg(long, value_name = "DIR")]
    pub svg: Option<PathBuf>,
}

/// Run the command.
pub fn run(a: &Args) -> Result<(), Error> {
    let file = a
        .file
        .as_ref()
        .ok_or_else(|| Error::input("FILE", "a task file is needed").with_help("tmm forces examples/seed-001-fourbar.toml"))?;
    let task = read_task(file)?;
    // [synthesis] without [linkage]: the synthesised [linkage] is analysed
    let task = tmm_report::synthesis::with_linkage(&task)?.into_owned();
    let (l, t) = load(&task)?.ok_or_else(|| {
        task.missing("forces", "the file has no [forces] section")
            .with_help("see examples/seed-001-fourbar.toml")
    })?;
    let at = match &a.at {
        Some(s) => Some(arg_qty("--at", s, Dim::Angle)?),
        None => None,
    };
    let an = analyse(&task, &l, &t, at)?;
    let out = if a.json {
        json_text(&json_document(&l, &t, &an))?
    } else {
        checked(text_report(&l, &t, &an))?
    };
    let files = match &a.svg {
        Some(dir) => write_dir(dir, &drawings(&l, &t, &an, &task)?)?,
        None => Vec::new(),
    };
    print(&if a.json { out } else { out + &written(&files) })
}
