//! `tmm run [FILE]`: every section of a task file into an output folder,
//! all or nothing — the tables, drawings and report, the explanatory note
//! `note.pdf` and the sheets `sheets/sheet-N.pdf` (unless `--no-pdf`).

use std::path::PathBuf;

use tmm_report::Error;
use tmm_report::run::{DEFAULT_TASK, run_task_in};

use super::common::{json_text, print, written};
use super::note::{language, pdf_documents, progress, task_of};
use crate::write::{Existing, write_folder};

/// Run every section of a task file.
#[derive(clap::Args)]
pub struct Args {
    /// The task file (TOML); without it, the embedded default course project
    pub file: Option<PathBuf>,
    /// Output folder for drawings, tables and report.json. It is written whole
    /// or not at all; a folder an earlier run made is replaced, an empty one is
    /// written into in place, a folder with other files is refused
    #[arg(short, long, default_value = "tmm-out")]
    pub out: PathBuf,
    /// Print the combined JSON report (the same as report.json) instead of the tables
    #[arg(long)]
    pub json: bool,
    /// Print the embedded default task file and exit
    #[arg(long)]
    pub print_default: bool,
    /// Do not typeset: write no note.pdf and no sheets/*.pdf
    #[arg(long)]
    pub no_pdf: bool,
    /// The language of the note, the sheets and the drawings (default: the
    /// task's [project] lang, else ru)
    #[arg(long, value_parser = ["ru", "uk", "en"])]
    pub lang: Option<String>,
}

/// Run the command.
pub fn run(a: &Args) -> Result<(), Error> {
    if a.print_default {
        return print(DEFAULT_TASK);
    }
    let task = task_of(a.file.as_ref())?;
    progress("computing");
    let run = run_task_in(&task, language(a.lang.as_deref()))?;
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
    let mut docs = run.docs.clone();
    if !a.no_pdf {
        docs.append(pdf_documents(&run, &task)?);
    }
    progress("writing");
    let files = write_folder(&a.out, &docs, Existing::Refuse, "--out")?;
    print(&if a.json { out } else { out + &written(&files) })
}
