//! `tmm cylinder FILE.toml`: a lever driven by an oscillating cylinder with
//! the piston's travel s as the generalized coordinate (the textbook's П5)
//! — the `[cylinder]` section: the synthesis, the analogues d/ds, the
//! reduced mass and forces, the zero-work control force, V(s), a(s), t(s)
//! and the kinetostatics at one s.

use std::path::PathBuf;

use tmm_report::Error;
use tmm_report::cylinder::{analyse, drawings, input, json, text};

use super::common::{checked, json_text, print, read_task, write_dir, written};

/// A mechanism driven by a cylinder: the piston's travel as its coordinate.
#[derive(clap::Args)]
pub struct Args {
    /// The task file (TOML) with a [cylinder] section
    pub file: Option<PathBuf>,
    /// Print one JSON document (SI, angles in radians) instead of the tables
    #[arg(long)]
    pub json: bool,
    /// Write the drawings (the mechanism, m_пр(s), V(s), a(s), t(s), the forces against s) as SVG into this folder
    #[arg(long, value_name = "DIR")]
    pub svg: Option<PathBuf>,
}

/// Run the command.
pub fn run(a: &Args) -> Result<(), Error> {
    let file = a.file.as_ref().ok_or_else(|| {
        Error::input("FILE", "a task file is needed").with_help("tmm cylinder examples/textbook/p5-pneumatic-cylinder.toml")
    })?;
    let task = read_task(file)?;
    task.check_sections()?;
    let t = input::read(&task)?.ok_or_else(|| {
        task.missing("cylinder", "the file has no [cylinder] section")
            .with_help("add [cylinder] with h_min, h_max, rod, the synthesis' swing, pressure_end and frame_y, switch and the masses; see examples/textbook/p5-pneumatic-cylinder.toml")
    })?;
    let an = analyse(&task, t)?;
    let out = if a.json {
        json_text(&json::document(&an))?
    } else {
        checked(text::report(&an))?
    };
    let files = match &a.svg {
        Some(dir) => write_dir(dir, &drawings(&an, "", task.lang, task.sheet)?)?,
        None => Vec::new(),
    };
    print(&if a.json { out } else { out + &written(&files) })
}
