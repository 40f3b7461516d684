//! The words of the synthesis construction and of the planetary train's
//! drawing read without their colours and without ambiguity, in ru, uk and
//! en, on the A1 sheet and on the note's page: every extreme position is
//! named by its point (B′, not a prime alone), the chosen pivot by its
//! letter (not "red:"); the angular-velocity picture's point 0 of the fixed
//! wheel is not written "0,3" (a decimal number with the decimal comma);
//! Willis' ratio is written as a formula with its tooth numbers; no
//! "name = value" pair is broken across two lines.

use crate::svg_read::texts;
use tmm_report::TaskSource;
use tmm_report::project::Language;
use tmm_report::run::{DEFAULT_TASK, note_figures, run_task_in};
use tmm_testkit::examples::text as example;

fn runs(name: &str, text: &str) -> Vec<(String, tmm_report::output::Documents)> {
    let mut out = Vec::new();
    for lang in [Language::Ru, Language::Uk, Language::En] {
        let src = TaskSource::new(name, text);
        out.push((format!("{name} {lang:?} A1"), run_task_in(&src, Some(lang)).unwrap().docs));
        out.push((format!("{name} {lang:?} A4"), note_figures(&src, Some(lang)).unwrap()));
    }
    out
}

#[test]
fn synthesis_legend_names_positions_and_pivot() {
    let mut bad = Vec::new();
    let mut seen = 0;
    for (name, text) in [
        ("default", DEFAULT_TASK.to_string()),
        (
            "synth-seed-002-ex1-crank-rocker.toml",
            example("synth-seed-002-ex1-crank-rocker.toml"),
        ),
    ] {
        for (what, docs) in runs(name, &text) {
            let Some(svg) = docs.get("synthesis/construction.svg").and_then(|d| d.as_text()) else {
                bad.push(format!("{what}: no construction"));
                continue;
            };
            let words: Vec<String> = texts(svg, false).into_iter().map(|t| t.0).collect();
            let all = words.join(" | ");
            for w in &words {
                if w.contains(" ′") || w.contains(" ″") {
                    bad.push(format!("{what}: a prime without its point: «{w}»"));
                }
                for colour in ["красным", "червоним", "red:"] {
                    if w.contains(colour) {
                        bad.push(format!("{what}: the legend relies on colour: «{w}»"));
                    }
                }
            }
            if all.contains("′ (") && all.contains("″") && all.contains("опора") | all.contains("pivot") {
                seen += 1;
            } else {
                bad.push(format!("{what}: legend incomplete: {all}"));
            }
        }
    }
    assert!(seen >= 12, "{seen}");
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

#[test]
fn planetary_drawing_writes_its_numbers_unambiguously() {
    let mut bad = Vec::new();
    for (what, docs) in runs("default", DEFAULT_TASK) {
        let svg = docs
            .get("planetary/planetary.svg")
            .and_then(|d| d.as_text())
            .expect("planetary drawing");
        let words: Vec<String> = texts(svg, false).into_iter().map(|t| t.0).collect();
        for w in &words {
            if w.trim() == "0,3" {
                bad.push(format!("{what}: «0,3» reads as a decimal number"));
            }
            if w.trim_end().ends_with('=') {
                bad.push(format!("{what}: a pair broken after «=»: «{w}»"));
            }
        }
        // the default project's set: z1 = 17, z3 = 85, u_1H = 1 + 85/17 = 6
        if !words.iter().any(|w| w.contains("1 + 85/17 = 6")) {
            bad.push(format!("{what}: Willis' ratio not written with its numbers: {words:?}"));
        }
        if !words.iter().any(|w| w.trim() == "0; 3") {
            bad.push(format!("{what}: the point 0 of the fixed wheel 3 is not named"));
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
