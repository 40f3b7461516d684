//! Every worked formula of the composed note checks: the right side, with
//! the run's numbers as printed, evaluates to the printed result within the
//! rounding of its inputs (`Calculation::check`). The numbers come from
//! independent parts of the report (K and θ of the synthesis; n, p5, p4 and
//! W of the structure; the plan's v_B and the crank's length; the lever's
//! forces and their points' velocities against the kinetostatic M_b; the
//! cycle's work against M_d; the gear's given shifts against the computed
//! α_w and a_w), so a formula typeset with a wrong sign, factor or term
//! fails. That the check can fail is tested too: every formula with its
//! right side negated must fail.

use tmm_note::calc::{Calculation, Expr};
use tmm_note::{Block, Lang, Note, Section, compose, typeset_with_warnings};
use tmm_report::TaskSource;
use tmm_report::project::Language;
use tmm_report::run::{DEFAULT_TASK, run_task_in};
use tmm_testkit::examples;

fn calculations(note: &Note) -> Vec<Calculation> {
    fn walk(ss: &[Section], out: &mut Vec<Calculation>) {
        for s in ss {
            for b in &s.blocks {
                if let Block::Calculation(c) = b {
                    out.push(c.clone());
                }
            }
            walk(&s.subsections, out);
        }
    }
    let mut out = Vec::new();
    for b in &note.assignment {
        if let Block::Calculation(c) = b {
            out.push(c.clone());
        }
    }
    walk(&note.sections, &mut out);
    walk(&note.appendices, &mut out);
    out
}

fn note_of(name: &str, text: &str, lang: Language) -> Note {
    let task = TaskSource::new(name, text);
    let run = run_task_in(&task, Some(lang)).unwrap();
    compose(&run, &task).unwrap()
}

/// Checks every calculation, requires at least the `expected` symbols, and
/// that each negated right side fails.
fn check_all(note: &Note, expected: &[&str]) {
    let calcs = calculations(note);
    for s in expected {
        assert!(
            calcs.iter().any(|c| c.result.symbol == *s),
            "no worked formula for {s}: {:?}",
            calcs.iter().map(|c| &c.result.symbol).collect::<Vec<_>>()
        );
    }
    for c in &calcs {
        c.check().unwrap_or_else(|e| panic!("{e}"));
        let mut wrong = c.clone();
        wrong.rhs = Expr::Neg(Box::new(wrong.rhs));
        if c.result.value.abs() > 1e-9 {
            assert!(wrong.check().is_err(), "{}: the negated formula passes", c.result.symbol);
        }
    }
}

#[test]
fn the_default_projects_formulas_check_in_every_language() {
    for (lang, mb, mzh, md, ifl) in [
        (Language::Ru, "M_\"ур\"", "M_\"Ж\"", "M_\"д\"", "I_\"мах\""),
        (Language::Uk, "M_\"зр\"", "M_\"Ж\"", "M_\"р\"", "I_\"мах\""),
        (Language::En, "M_b", "M_\"Zh\"", "M_d", "I_\"fl\""),
    ] {
        let note = note_of("default.toml", DEFAULT_TASK, lang);
        check_all(
            &note,
            &[
                "theta",
                "W",
                "v_(B)",
                mb,
                "P",
                mzh,
                md,
                "I_\"M\"",
                ifl,
                "\"inv\" alpha_w",
                "a_w",
                "u_(1 H)",
            ],
        );
    }
}

#[test]
fn zhukovskys_lever_with_the_runs_numbers_gives_the_kinetostatic_torque() {
    // the lever's power sum, recomputed here from the report's lever forces
    // (image = velocity turned by +90°): M_Zh·ω1 = −Σ F·v, and it equals the
    // balancing torque of the kinetostatics (489.5 N·m at 15°, issue 22's
    // +46 130 W) — the sign of formula (3.4) as typeset
    let task = TaskSource::new("default.toml", DEFAULT_TASK);
    let run = run_task_in(&task, Some(Language::Ru)).unwrap();
    let r = &run.report;
    let mut power = 0.0;
    for e in r.pointer("/forces/lever").and_then(|l| l.as_array()).unwrap() {
        if e["label"] == "Pb" {
            continue;
        }
        let f = |k: &str, i: usize| e[k][i].as_f64().unwrap();
        // v = (image_y, −image_x)
        power += f("force", 0) * f("image", 1) - f("force", 1) * f("image", 0);
    }
    let omega = r.pointer("/forces/omega1").and_then(|v| v.as_f64()).unwrap();
    let mb = r.pointer("/forces/detail/balancing_moment").and_then(|v| v.as_f64()).unwrap();
    assert!((-power / omega - mb).abs() < 1e-6 * mb.abs(), "{power} W, {mb} N·m");
    assert!(power < 0.0 && mb > 0.0);
    let note = compose(&run, &task).unwrap();
    let c = calculations(&note).into_iter().find(|c| c.result.symbol == "P").unwrap();
    assert!((c.result.value - power).abs() < 1e-6 * power.abs());
}

#[test]
fn the_engine_and_six_bar_examples_formulas_check() {
    for (file, expected) in [
        ("compressor-two-stage.toml", &["W", "v_(A)"][..]),
        ("seed-003-sixbar.toml", &["W", "v_(A)"][..]),
        // the engine's cycle is two turns: its constant moment is −A_c(4π)/4π
        ("textbook/p2-engine.toml", &["W", "v_(A)", "M_\"сопр\"", "I_\"M\""][..]),
    ] {
        let note = note_of(file, &examples::text(file), Language::Ru);
        check_all(&note, expected);
        assert!(!calculations(&note).is_empty(), "{file}");
    }
}

#[test]
fn the_worked_formulas_typeset_without_a_warning() {
    let note = note_of("default.toml", DEFAULT_TASK, Language::Ru);
    assert_eq!(note.lang, Lang::Ru);
    let t = typeset_with_warnings(&note).unwrap();
    assert!(t.warnings.is_empty(), "{:#?}", t.warnings);
}

#[test]
fn the_cam_sections_worked_speed_and_acceleration_check() {
    // v = ω·ds/dφ and a = ω²·d²s/dφ² with the report's ω and analogues
    // against the report's speed and acceleration at their largest
    for (file, text) in [
        ("default.toml", DEFAULT_TASK.to_string()),
        ("cam-seed-001-roller.toml", examples::text("cam-seed-001-roller.toml")),
    ] {
        for lang in [Language::Ru, Language::En] {
            let note = note_of(file, &text, lang);
            check_all(&note, &["v_max", "a_max"]);
        }
    }
}
