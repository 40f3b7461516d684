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

/// The stages of the default project's run with the note, each alone: the
/// sections computed (`run`), the note's A4 drawings
/// (`note_figures`), the note composed (with its drawings), the note
/// laid out (typst's compilation without the PDF export), the note
/// typeset, the sheets typeset.
#[divan::bench(args = ["run", "note_figures", "compose", "layout_note", "typeset_note", "sheets"], sample_count = 5, sample_size = 1)]
fn stages_of_default(bencher: divan::Bencher, stage: &str) {
    let t = task("default");
    let run = run_task_in(&t, None).expect("the task runs");
    let note = tmm_note::compose(&run, &t).expect("the note composes");
    bencher.bench(|| {
        typst::comemo::evict(0);
        match stage {
            "run" => run_task_in(&t, None).map(|r| r.docs.iter().count()).unwrap_or(0),
            "note_figures" => tmm_report::run::note_figures(&t, None).map(|d| d.iter().count()).unwrap_or(0),
            "compose" => tmm_note::compose(&run, &t).map(|n| n.sections.len()).unwrap_or(0),
            "layout_note" => {
                let tr = tmm_note::Translation::load(note.lang).expect("the words load");
                let g = tmm_note::markup::generate(&note, &tr).expect("the note generates");
                let world = tmm_note::world::NoteWorld::new(g.main, g.figures).expect("the world");
                typst::compile::<typst_layout::PagedDocument>(&world)
                    .output
                    .map(|d| d.pages().len())
                    .unwrap_or(0)
            }
            "typeset_note" => tmm_note::typeset(&note).map(|p| p.len()).unwrap_or(0),
            _ => run
                .docs
                .iter()
                .filter(|d| d.path.starts_with("sheets/") && d.path.ends_with(".svg"))
                .map(|d| tmm_note::sheet_pdf(d.as_text().unwrap_or("")).map(|p| p.len()).unwrap_or(0))
                .sum(),
        }
    });
}
