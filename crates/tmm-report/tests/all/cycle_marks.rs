//! The positions numbered under a diagram over the cycle: a four-stroke
//! engine's cycle of two turns (П2, examples/textbook/p2-engine.toml, 24
//! positions over 720°) numbers them 0 … 24 in order along the φ axis, as
//! many numbers as positions plus the cycle's end — once printed all 13 …
//! 23 as "24", everything past the first turn taken for its end. On the
//! note's A4 page, where 30° is 3 mm, every other number is written (the
//! two-digit ones would run together), still in order. The reactions over
//! that cycle and their hodographs name the task's `R30`, `R21` as the
//! course writes them, the index lowered.

use tmm_report::TaskSource;
use tmm_report::project::Language;
use tmm_report::run::{note_figures, run_task_in};
use tmm_testkit::examples::text as example;
use tmm_testkit::svg::{attr, num, shown};

/// The integers written under or over the φ axis of `svg`, in order of x:
/// the position numbers, centred on their ticks (the y ticks' values end
/// left of the y axis).
fn numbers(svg: &str) -> Vec<(f64, u32)> {
    let mut out: Vec<(f64, u32)> = svg
        .split("<text")
        .skip(1)
        .filter_map(|t| {
            let tag = &t[..t.find('>')?];
            let inner = &t[t.find('>')? + 1..t.find("</text>")?];
            let x = num(tag, "x")?;
            let n: u32 = shown(inner).trim().parse().ok()?;
            (attr(tag, "text-anchor") == Some("middle")).then_some((x, n))
        })
        .collect();
    out.sort_by(|a, b| a.0.total_cmp(&b.0));
    out
}

#[test]
fn an_engines_720_degree_cycle_numbers_its_24_positions_in_order() {
    let task = TaskSource::new("p2-engine.toml", example("textbook/p2-engine.toml"));
    let run = run_task_in(&task, Some(Language::Ru)).expect("П2 runs");
    let svg = run
        .docs
        .get("forces/balancing-torque.svg")
        .and_then(|d| d.as_text())
        .expect("the diagram");
    let got: Vec<u32> = numbers(svg).into_iter().map(|p| p.1).collect();
    let want: Vec<u32> = (0..=24).collect();
    assert_eq!(got, want, "the sheet's diagram numbers its positions 0 … 24 in order");

    let figs = note_figures(&task, Some(Language::Ru)).expect("the note's figures");
    let p = figs.picture("forces/balancing-torque.svg").expect("the note's diagram");
    let got: Vec<u32> = numbers(p.svg()).into_iter().map(|p| p.1).collect();
    let want: Vec<u32> = (0..=24).step_by(2).collect();
    assert_eq!(got, want, "the note's diagram numbers every other position, in order");
}

/// П2's reactions over the cycle and the hodograph write the task's names
/// `R30`, `R21` in the course's notation, R₃₀ₓ, R₂₁ᵧ: the index lowered in
/// the legends, the titles and the hodograph's axes, never the raw key.
#[test]
fn the_reactions_over_the_cycle_are_named_in_the_courses_notation() {
    let task = TaskSource::new("p2-engine.toml", example("textbook/p2-engine.toml"));
    let run = run_task_in(&task, Some(Language::Ru)).expect("П2 runs");
    for (path, name, want) in [
        ("forces/reaction-R30.svg", "R30", &["30x", "30y", "30"][..]),
        ("forces/reaction-R50.svg", "R50", &["50x", "50y", "50"][..]),
        ("forces/hodograph-R21.svg", "R21", &["21x", "21y", "21"][..]),
    ] {
        let svg = run.docs.get(path).and_then(|d| d.as_text()).expect("the drawing");
        let texts: Vec<String> = svg
            .split("<text")
            .skip(1)
            .filter_map(|t| Some(t[t.find('>')? + 1..t.find("</text>")?].to_string()))
            .collect();
        // written as R<tspan …>30x</tspan>: the name never whole in a text
        assert!(!texts.iter().any(|t| t.contains(name)), "{path}: the raw name {name} in {texts:?}");
        for w in want {
            assert!(svg.contains(&format!(">{w}</tspan>")), "{path}: no lowered index {w}");
        }
    }
}
