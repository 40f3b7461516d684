//! The textbook's machines run whole in memory, as `tmm run` computes them
//! without the note (BMSTU textbook, Chernaya & Timofeev 2019): the П2
//! engine over its 720° cycle (synthesis-free kinematics, the indicator
//! loads, the dynamics with the exact flywheel, the kinetostatics' tables
//! every 1° of the cycle, every drawing and the sheets; target under
//! 0.5 s), the П4 press's single stroke with its drawings, and the П5
//! pneumatic cylinder (the linear coordinate: the motion in s and the
//! kinetostatics) — the section alone and the whole run.

use divan::black_box;
use tmm_report::TaskSource;
use tmm_report::run::{run_section, run_task};

fn main() {
    divan::main();
}

/// A textbook example as a task.
fn task(name: &str) -> TaskSource {
    let path = format!("{}/../../examples/textbook/{name}", env!("CARGO_MANIFEST_DIR"));
    TaskSource::new(name, std::fs::read_to_string(&path).unwrap())
}

/// П2: the whole run of the two-cylinder engine (no note).
#[divan::bench(sample_count = 10)]
fn p2_engine_whole_run(b: divan::Bencher) {
    let t = task("p2-engine.toml");
    b.bench(|| black_box(run_task(&t).unwrap().docs.iter().count()));
}

/// П3: the whole run of the shaper, its synthesis included (no note).
#[divan::bench(sample_count = 10)]
fn p3_shaper_whole_run(b: divan::Bencher) {
    let t = task("p3-shaper.toml");
    b.bench(|| black_box(run_task(&t).unwrap().docs.iter().count()));
}

/// П4: the whole run of the press's single stroke (no note).
#[divan::bench(sample_count = 10)]
fn p4_press_whole_run(b: divan::Bencher) {
    let t = task("p4-press.toml");
    b.bench(|| black_box(run_task(&t).unwrap().docs.iter().count()));
}

/// П5: the `[cylinder]` section alone (synthesis, analogues d/ds, the
/// motion V(s), a(s), t(s), the kinetostatics, its drawings).
#[divan::bench(sample_count = 20)]
fn p5_cylinder_section(b: divan::Bencher) {
    let t = task("p5-pneumatic-cylinder.toml");
    b.bench(|| black_box(run_section("cylinder", &t).unwrap().is_some()));
}

/// П5: the whole run of the pneumatic cylinder (no note).
#[divan::bench(sample_count = 10)]
fn p5_cylinder_whole_run(b: divan::Bencher) {
    let t = task("p5-pneumatic-cylinder.toml");
    b.bench(|| black_box(run_task(&t).unwrap().docs.iter().count()));
}
