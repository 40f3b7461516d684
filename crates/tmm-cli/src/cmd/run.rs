//! `tmm run [FILE]`: every section of a task file into an output folder,
//! all or nothing.

use std::path::PathBuf;

use tmm_report::run::{DEFAULT_TASK, DEFAULT_TASK_NAME, run_task};
use tmm_report::{Error, TaskSource};

use super::common::{json_text, print, read_task, written};
use crate::write::{Existing, write_folder};

/// Run every section of a task file.
#[derive(clap::Args)]
pub struct Args {
    /// The task file (TOML); without it, the embedded default course project
    pub file: Option<PathBuf>,
    /// Output folder for drawings, tables and report.json. It is written whole
    /// or not at all; a folder an earlier run made is replaced, a folder with
    /// other files is refused
    #[arg(short, long, default_value = "tmm-out")]
    pub out: PathBuf,
    /// Print the combined JSON report (the same as report.json) instead of the tables
    #[arg(long)]
    pub json: bool,
    /// Print the embedded default task file and exit
    #[arg(long)]
    pub print_default: bool,
}

/// Run the command.
pub fn run(a: &Args) -> Result<(), Error> {
    if a.print_default {
        return print(DEFAULT_TASK);
    }
    let task = match &a.file {
        Some(p) => read_task(p)?,
        None => TaskSource::new(DEFAULT_TASK_NAME, DEFAULT_TASK),
    };
    let run = run_task(&task)?;
    let out = if a.json {
        json_text(&run.report)?
    } else {
        let mut s = String::new();
        for o in &run.sections {
            s.push_str(&o.text);
            s.push('\n');
        }
        s
    };
    let files = write_folder(&a.out, &run.docs, Existing::Refuse)?;
    print(&if a.json { out } else { out + &written(&files) })
}
