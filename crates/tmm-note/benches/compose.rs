//! The whole of `tmm run` for the embedded default task once built: compute
//! every section, compose and typeset the note, typeset every sheet the run
//! has (`sheets/sheet-N.svg`). The target is under 3 s on one core
//! (issue: "tmm run of the default task with the note and four sheets").
//!
//! The engines' family (the textbook's П2 engine over 720°, П3 shaper with
//! its reactions every degree, П4 press's single stroke, the two-stage
//! compressor) is measured the same way, with and without the note: the
//! targets are 0.5 s for the computation and drawings and 1.5 s with the
//! note and sheets, on one core (`taskset -c 0 cargo bench …`).

use tmm_report::TaskSource;
use tmm_report::run::{DEFAULT_TASK, run_task};

fn main() {
    divan::main();
}

/// The machines of the engines' family, by their example files.
const MACHINES: &[&str] = &["p2-engine", "p3-shaper", "p4-press", "compressor-two-stage"];

fn machine(name: &str) -> TaskSource {
    let text = match name {
        "p2-engine" => include_str!("../../../examples/textbook/p2-engine.toml"),
        "p3-shaper" => include_str!("../../../examples/textbook/p3-shaper.toml"),
        "p4-press" => include_str!("../../../examples/textbook/p4-press.toml"),
        "compressor-two-stage" => include_str!("../../../examples/compressor-two-stage.toml"),
        _ => unreachable!("not a machine of the list"),
    };
    TaskSource::new(format!("{name}.toml"), text)
}

/// Every section of the task computed and drawn, in memory (no note).
#[divan::bench(args = MACHINES, sample_count = 5, sample_size = 1)]
fn machine_run(bencher: divan::Bencher, name: &str) {
    let task = machine(name);
    bencher.bench(|| divan::black_box(run_task(divan::black_box(&task)).expect("the example runs").docs.len()));
}

/// The whole `tmm run` of the machine: sections, note and sheets.
#[divan::bench(args = MACHINES, sample_count = 5, sample_size = 1)]
fn machine_run_note_and_sheets(bencher: divan::Bencher, name: &str) {
    let task = machine(name);
    bencher.bench(|| {
        typst::comemo::evict(0);
        divan::black_box(whole(&task))
    });
}

/// Sections, the note's PDF and every sheet's PDF: their sizes in bytes.
fn whole(task: &TaskSource) -> (usize, usize) {
    let run = run_task(task).expect("the task runs");
    let note = tmm_note::compose(&run, task).expect("the note composes");
    let pdf = tmm_note::typeset(&note).expect("the note typesets");
    let mut sheets = 0;
    for d in run
        .docs
        .iter()
        .filter(|d| d.path.starts_with("sheets/") && d.path.ends_with(".svg"))
    {
        let svg = d.as_text().expect("an SVG is text");
        sheets += tmm_note::sheet_pdf(svg).expect("the sheet typesets").len();
    }
    (pdf.len(), sheets)
}

#[divan::bench(sample_count = 5, sample_size = 1)]
fn default_task_run_note_and_sheets(bencher: divan::Bencher) {
    let task = TaskSource::new("default.toml", DEFAULT_TASK);
    bencher.bench(|| {
        // Forget typst's memoized results: each run compiles from scratch, as
        // a one-shot `tmm run` does.
        typst::comemo::evict(0);
        divan::black_box(whole(divan::black_box(&task)))
    });
}
