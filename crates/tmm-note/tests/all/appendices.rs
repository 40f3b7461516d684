//! The appendices print one angle under one heading (issue 22, point 1):
//! the crank's angle φ of each position in appendix В (the machine's
//! reduced parameters) is the one appendices А and Б print for the same
//! position — the crank's absolute angle, not the angle from the start of
//! the working stroke. Checked for the default project (the crank turning
//! counter-clockwise from 131.9°) and the seed-003 six-bar (clockwise from
//! 208.0°), the angles read back from the composed tables.

use tmm_note::{Block, Cell, Note, Span, compose};
use tmm_report::project::Language;
use tmm_report::run::run_task_in;

use super::fixtures::task;

/// (label, φ) of the rows of the appendix `k`'s first table.
fn angles(note: &Note, k: usize) -> Vec<(String, f64)> {
    let Some(Block::Table { rows, .. }) = note.appendices[k].blocks.iter().find(|b| matches!(b, Block::Table { .. })) else {
        panic!("appendix {k} has no table");
    };
    rows.iter()
        .map(|r| {
            let label = match &r[0] {
                Cell::Text(t) => t.0.iter().map(|s| if let Span::Plain(p) = s { p.as_str() } else { "" }).collect(),
                _ => String::new(),
            };
            let Cell::Number { value, .. } = r[1] else {
                panic!("no angle in {r:?}")
            };
            (label, value)
        })
        .collect()
}

#[test]
fn every_appendix_gives_a_position_the_same_crank_angle() {
    for (name, first) in [("default", 131.9), ("seed-003-sixbar.toml", 208.0)] {
        let src = task(name);
        let run = run_task_in(&src, Some(Language::Ru)).unwrap();
        let note = compose(&run, &src).unwrap();
        assert_eq!(note.appendices.len(), 3, "{name}");
        let kinematics = angles(&note, 0);
        assert!((kinematics[0].1 - first).abs() < 0.05, "{name}: {kinematics:?}");
        for k in [1, 2] {
            let other = angles(&note, k);
            let mut matched = 0;
            for (label, phi) in &other {
                if let Some((_, a)) = kinematics.iter().find(|(l, _)| l == label) {
                    assert!((phi - a).abs() < 1e-3, "{name}, appendix {k}, position {label}: {phi} against {a}");
                    matched += 1;
                }
            }
            assert!(matched >= 12, "{name}, appendix {k}: {matched} positions matched");
        }
    }
}
