//! A whole `tmm run` on one thread, in memory: the task computed, then its
//! note and its sheets typeset to PDF — what the command does before it
//! writes the files. Targets: the default course project with the note and
//! the sheets under 1 s on one core (issue "Drawings to ESKD", item 8); the
//! textbook's two-cylinder engine (П2) under 0.5 s without and 1.5 s with
//! them. Each case is also timed without the PDFs, for the ratio.
//!
//! Run with `cargo bench --profile release -p tmm-note --bench run` (the
//! release profile shares the build of `cargo build --release`; the default
//! bench profile would compile the typesetter again). Pin one core with
//! `taskset -c 0` for the one-core figure.

use tmm_report::TaskSource;
use tmm_report::run::{DEFAULT_TASK, run_task_in};

fn main() {
    divan::main();
}

const ENGINE: &str = include_str!("../../../examples/textbook/p2-engine.toml");

fn task(name: &str) -> TaskSource {
    match name {
        "default" => TaskSource::new("default.toml", DEFAULT_TASK),
        _ => TaskSource::new("p2-engine.toml", ENGINE),
    }
}

/// Compute, then typeset the note and every sheet; the PDFs' total bytes.
fn whole(task: &TaskSource) -> usize {
    // forget typst's memoized results: every run starts cold, as the command
    typst::comemo::evict(0);
    let run = run_task_in(task, None).expect("the task runs");
    let note = tmm_note::compose(&run, task).expect("the note composes");
    let mut bytes = tmm_note::typeset(&note).expect("the note typesets").len();
    for d in run
        .docs
        .iter()
        .filter(|d| d.path.starts_with("sheets/") && d.path.ends_with(".svg"))
    {
        let svg = d.as_text().expect("a sheet is text");
        bytes += tmm_note::sheet_pdf(svg).expect("the sheet typesets").len();
    }
    bytes
}

#[divan::bench(args = ["default", "p2-engine"], sample_count = 5, sample_size = 1)]
fn with_note_and_sheets(bencher: divan::Bencher, name: &str) {
    let t = task(name);
    bencher.bench(|| divan::black_box(whole(divan::black_box(&t))));
}

#[divan::bench(args = ["default", "p2-engine"], sample_count = 5, sample_size = 1)]
fn without_pdfs(bencher: divan::Bencher, name: &str) {
    let t = task(name);
    bencher.bench(|| divan::black_box(run_task_in(divan::black_box(&t), None).map(|r| r.docs.iter().count()).ok()));
}
