//! The note's words as composed, before typesetting: outside the math runs
//! that `notation` marks, no text of a paragraph, a list, a table or a
//! caption holds raw notation — a `^` (`e^(−t/τ)` printed its hat) or a
//! `_` joining two letters or digits (`h_min`, `I1S` aside, a task key) —
//! in any example or the default project, in ru, uk and en; and every
//! note has a title.

use tmm_note::{Block, Cell, Span, Text, compose};
use tmm_report::project::Language;
use tmm_report::run::run_task_in;

use super::fixtures::{all_tasks, note_blocks, note_sections, outside_math, section_blocks, task};

/// The raw notation of a text: a `^`, or a `_` between letters or digits.
fn raw(s: &str) -> Option<String> {
    let t = outside_math(s);
    let c: Vec<char> = t.chars().collect();
    for i in 0..c.len() {
        let joined = c[i] == '_' && i > 0 && i + 1 < c.len() && c[i - 1].is_alphanumeric() && c[i + 1].is_alphanumeric();
        if c[i] == '^' || joined {
            let from = i.saturating_sub(12);
            let to = (i + 12).min(c.len());
            return Some(c[from..to].iter().collect());
        }
    }
    None
}

fn text_raw(t: &Text, out: &mut Vec<String>) {
    for s in &t.0 {
        if let Span::Plain(p) | Span::Strong(p) | Span::Emph(p) = s
            && let Some(r) = raw(p)
        {
            out.push(r);
        }
    }
}

fn block_raw(b: &Block, out: &mut Vec<String>) {
    match b {
        Block::Paragraph(t) => text_raw(t, out),
        Block::List(items) => items.iter().for_each(|t| text_raw(t, out)),
        Block::Table { caption, header, rows, .. } => {
            out.extend(raw(caption));
            out.extend(header.iter().filter_map(|h| raw(h)));
            for row in rows {
                for c in row {
                    if let Cell::Text(t) = c {
                        text_raw(t, out);
                    }
                }
            }
        }
        Block::Figure { caption, .. } => out.extend(raw(caption)),
        _ => {}
    }
}

/// No raw `^` or `_` outside the math in any composed note, and no empty
/// title. Failed before on the pneumatic cylinder's conclusion
/// (`e^(−t/τ)`), on the position syntheses' tables (`h_min`, `phi3_start`,
/// `l_DB` `_start`) and on the untitled examples (the planetary and gear
/// tasks printed «» on the title page).
#[test]
fn no_note_prints_raw_notation_outside_its_math() {
    let mut faults = Vec::new();
    let mut notes = 0;
    for task in all_tasks() {
        for lang in [Language::Ru, Language::Uk, Language::En] {
            let Ok(run) = run_task_in(&task, Some(lang)) else { continue };
            let Ok(note) = compose(&run, &task) else { continue };
            notes += 1;
            if note.project.title.trim().is_empty() {
                faults.push(format!("{} {lang:?}: an empty title, «» on the title page", task.name));
            }
            let mut found: Vec<String> = note_sections(&note).iter().filter_map(|s| raw(&s.title)).collect();
            for b in note_blocks(&note) {
                block_raw(b, &mut found);
            }
            // the caller's own strings stay literal (a title "m = 30 мм, a_w = 560 мм")
            let title = note.project.title.as_str();
            found.retain(|f| title.is_empty() || !title.contains(f.trim_matches(|c: char| c == '«' || c == '»' || c == '“' || c == '”')));
            for f in found {
                faults.push(format!("{} {lang:?}: «{f}»", task.name));
            }
        }
    }
    assert!(notes > 60, "only {notes} notes composed");
    assert!(faults.is_empty(), "{} raw:\n{}", faults.len(), faults.join("\n"));
}

/// An oscillating follower's note speaks of the arm's swing ψ_max and its
/// angular speed ω_2 = ω·dψ/dφ, not of a translating follower's stroke h
/// and speed v = ω·ds/dφ. Failed before: "хід h = 20,00°" and v, a in m/s.
#[test]
fn an_oscillating_followers_note_gives_its_swing_and_angular_analogues() {
    let task = task("cam-oscillating-roller.toml");
    for lang in [Language::Ru, Language::Uk, Language::En] {
        let run = run_task_in(&task, Some(lang)).unwrap();
        let note = compose(&run, &task).unwrap();
        let cam = &note.sections[0];
        let mut text = String::new();
        let mut formulas = Vec::new();
        for b in section_blocks(cam) {
            match b {
                Block::Paragraph(t) => {
                    for s in &t.0 {
                        if let Span::Plain(p) = s {
                            text.push_str(&outside_math(p));
                        }
                    }
                }
                Block::Formula { typst_math, .. } => formulas.push(typst_math.clone()),
                _ => {}
            }
        }
        for stroke in [" ход ", " хід ", " stroke "] {
            assert!(!text.contains(stroke), "{lang:?}: «{stroke}» of a swinging arm in {text}");
        }
        assert!(
            formulas
                .iter()
                .any(|f| f.contains("(dif psi) / (dif phi)") && f.contains("omega_2")),
            "{lang:?}: no ω_2 = ω dψ/dφ among {formulas:?}"
        );
    }
}

/// The dynamics' results keep its tables before its six diagrams, so that
/// the conclusions' paragraphs, not the tables kept whole, follow the
/// floating diagrams and fill the pages under them (the default project's
/// pages 25 and 26 had their lower third empty, Table 4.1 of nine rows not
/// fitting under two diagrams). Failed before: the diagrams were moved
/// ahead of the tables.
#[test]
fn the_dynamics_tables_come_before_its_diagrams() {
    let task = task("default");
    for lang in [Language::Ru, Language::Uk, Language::En] {
        let run = run_task_in(&task, Some(lang)).unwrap();
        let note = compose(&run, &task).unwrap();
        let dynamics = &note.sections[3];
        let results = &dynamics.subsections[2];
        let last_table = results.blocks.iter().rposition(|b| matches!(b, Block::Table { .. }));
        let first_figure = results.blocks.iter().position(|b| matches!(b, Block::Figure { .. }));
        let (Some(t), Some(f)) = (last_table, first_figure) else {
            panic!("{lang:?}: the dynamics' results have no tables or no figures")
        };
        assert!(t < f, "{lang:?}: a diagram (block {f}) before the dynamics' table (block {t})");
    }
}
