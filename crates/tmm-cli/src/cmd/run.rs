//! `tmm run [FILE]`: every section of a task file into an output folder.

use std::path::PathBuf;

use tmm_report::run::{DEFAULT_TASK, DEFAULT_TASK_NAME, run_task};
use tmm_report::{Error, TaskSource};

use super::common::{print_json, read_task};

/// Run every section of a task file.
#[derive(clap::Args)]
pub struct Args {
    /// The task file (TOML); without it, the embedded default course project
    pub file: Option<PathBuf>,
    /// Output folder for drawings, tables and report.json
    #[arg(short, long, default_value = "tmm-out")]
    pub out: PathBuf,
    /// Print the combined JSON report instead of the tables
    #[arg(long)]
    pub json: bool,
    /// Print the embedded default task file and exit
    #[arg(long)]
    pub print_default: bool,
}

/// Run the command.
pub fn run(a: &Args) -> Result<(), Error> {
    if a.print_default {
        print!("{DEFAULT_TASK}");
        return Ok(());
    }
    let task = match &a.file {
        Some(p) => read_task(p)?,
        None => TaskSource::new(DEFAULT_TASK_NAME, DEFAULT_TASK),
    };
    let outs = run_task(&task, &a.out)?;
    if a.json {
        let mut doc = serde_json::Map::new();
        doc.insert("units".into(), "SI".into());
        for o in &outs {
            doc.insert(o.section.into(), o.json.clone());
        }
        return print_json(&serde_json::Value::Object(doc));
    }
    for o in &outs {
        println!("{}", o.text);
    }
    println!("Files written under {}:", a.out.display());
    println!("  {}", a.out.join("report.json").display());
    for o in &outs {
        for f in &o.files {
            println!("  {}", f.display());
        }
    }
    Ok(())
}
