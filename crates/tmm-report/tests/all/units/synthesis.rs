//! Tests of `tmm_report::synthesis`, kept outside the library so that the
//! test command compiles it once.

use tmm_linkage::cycle::{Cycle, Working};
use tmm_report::TaskSource;
use tmm_report::synthesis::*;

fn fields(text: &str) -> Fields {
    Fields::section(&TaskSource::new("t.toml", text)).unwrap().unwrap()
}

/// The seed-001 four-bar analysed by the linkage core gives K and the
/// swing; a crank-rocker synthesis by those, the rocker and the frame
/// must give back its crank and coupler (120 mm, 480 mm).
#[test]
fn seed_001_four_bar_is_synthesised_back_from_its_own_k_and_swing() {
    let src = TaskSource::new(
        "seed-001-fourbar.toml",
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/seed-001-fourbar.toml")).unwrap(),
    );
    let l = tmm_report::linkage::load(&src).unwrap().unwrap();
    let c = Cycle::new(&l.mech, Working::Slower).unwrap();
    let f = fields(&format!(
        "[synthesis]\nkind = \"crank-rocker\"\nk = {:?}\nswing = \"{:?} rad\"\nrocker = \"380 mm\"\nframe = \"510 mm\"\n",
        c.kv, c.stroke
    ));
    let s = solve(&f).unwrap();
    assert!((s.syn.length("OA").unwrap() - 0.12).abs() < 1e-9);
    assert!((s.syn.length("AB").unwrap() - 0.48).abs() < 1e-9);
}

#[test]
fn a_task_without_linkage_runs_every_section_on_the_synthesised_one() {
    let text = "[synthesis]\nkind = \"crank-slider\"\nstroke = \"300 mm\"\nk = 1.2\nlambda = 3.5\nspeed = \"600 rpm\"\n\n[forces]\nmass_per_length = \"10 kg/m\"\n\n[[forces.resistance]]\nlink = \"3\"\nforce = \"1 kN\"\nlaw = \"working\"\n";
    let task = TaskSource::new("t.toml", text);
    let run = tmm_report::run::run_task(&task).unwrap();
    let r = &run.report;
    assert!((r["linkage"]["kv"].as_f64().unwrap() - 1.2).abs() < 1e-9);
    assert!((r["linkage"]["stroke"].as_f64().unwrap() - 0.3).abs() < 1e-9);
    assert!(r.get("forces").is_some());
    assert!(r["synthesis"].get("given_linkage").is_none());
    // an error in the user's own lines keeps its place
    let bad = TaskSource::new("t.toml", text.replace("lambda = 3.5", "lambda = 0.5"));
    let e = tmm_report::run::run_task(&bad).unwrap_err().to_string();
    assert!(e.starts_with("t.toml:5:10: synthesis.lambda"), "{e}");
}

#[test]
fn unknown_and_conflicting_fields_are_named() {
    let e = solve(&fields(
        "[synthesis]\nkind = \"crank-rocker\"\nk = 1.2\nswing = 40\nrocker = 0.3\noptimum = true\nstroke = 1\n",
    ))
    .unwrap_err()
    .to_string();
    assert!(e.contains("t.toml:7:10: synthesis.stroke: not a field of a crank-rocker"), "{e}");
    let e = solve(&fields("[synthesis]\nkind = \"four-bar\"\n")).unwrap_err().to_string();
    assert!(e.contains("synthesis.kind: unknown kind"), "{e}");
}
