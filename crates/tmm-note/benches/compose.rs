//! The whole of `tmm run` for the embedded default task once built: compute
//! every section, compose and typeset the note, typeset every sheet the run
//! has (`sheets/sheet-N.svg`). The target is under 3 s on one core
//! (issue: "tmm run of the default task with the note and four sheets").

use tmm_report::TaskSource;
use tmm_report::run::{DEFAULT_TASK, run_task};

fn main() {
    divan::main();
}

#[divan::bench(sample_count = 5, sample_size = 1)]
fn default_task_run_note_and_sheets(bencher: divan::Bencher) {
    let task = TaskSource::new("default.toml", DEFAULT_TASK);
    bencher.bench(|| {
        // Forget typst's memoized results: each run compiles from scratch, as
        // a one-shot `tmm run` does.
        typst::comemo::evict(0);
        let run = run_task(divan::black_box(&task)).expect("the default task runs");
        let note = tmm_note::compose(&run, &task).expect("the note composes");
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
        divan::black_box((pdf.len(), sheets))
    });
}
