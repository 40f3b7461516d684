//! The kinematics section's vector equations fit the mechanism: read back
//! against the report's own structure (`linkage.structure.groups` and
//! `.pairs`), the velocity formula has one line for the input link and one
//! per Assur group, each line's point letters are points of that group or
//! of the pairs of its links (the input link's for the first line); a group
//! with a sliding pair on a turning guide has a Coriolis term
//! (Артоболевский 1988, § 15: a^k = 2 ω v_r), one whose guides do not turn
//! (the frame, a ram sliding on it) has none; the line under each formula
//! names every symbol it uses and no other; no link is called a coupler;
//! a slider driving the mechanism has its own line (v_B = v, a_B = a, no
//! ω·l). Failed before for the slider-driven linkage: its note had no
//! vector equations at all.

use std::collections::BTreeSet;

use serde_json::Value;
use tmm_note::{Block, Note, Section, Span, compose};
use tmm_report::project::Language;
use tmm_report::run::run_task_in;

use super::fixtures::task;

/// The mechanisms: the four-bar (RRR), seed 003's six-bar (RRR + RRP,
/// crank OA), the engine (two RRP), the shaper with the rocking guide
/// (RPR + RRP), the shaper with the ram (RRR + RPP), the knee press, the
/// oscillating cylinder (RPR), the moving guides (PRP) and the linkage
/// driven by a slider on a fixed guide (slider 1, RRR).
const TASKS: [&str; 9] = [
    "default",
    "seed-003-sixbar.toml",
    "textbook/p2-engine.toml",
    "seed-002-shaper.toml",
    "textbook/p3-shaper.toml",
    "seed-002-knee-press.toml",
    "textbook/p1-5-oscillating-cylinder-v1.toml",
    "prp-moving-guides.toml",
    "slider-input.toml",
];

struct Pair {
    point: String,
    links: Vec<String>,
    sliding: bool,
}

fn pairs(report: &Value) -> Vec<Pair> {
    report
        .pointer("/linkage/structure/pairs")
        .and_then(Value::as_array)
        .unwrap()
        .iter()
        .map(|p| Pair {
            point: p["point"].as_str().unwrap().to_string(),
            links: p["links"]
                .as_array()
                .unwrap()
                .iter()
                .map(|l| l.as_str().unwrap().to_string())
                .collect(),
            sliding: p["kind"] == "P",
        })
        .collect()
}

/// The links that cannot turn: the frame and whatever slides on a link
/// that cannot turn.
fn still(pairs: &[Pair]) -> BTreeSet<String> {
    let mut s: BTreeSet<String> = ["frame".to_string()].into();
    for _ in 0..pairs.len() {
        for p in pairs.iter().filter(|p| p.sliding) {
            if p.links.iter().any(|l| s.contains(l)) {
                s.extend(p.links.iter().cloned());
            }
        }
    }
    s
}

/// The formulas of the note, each with the paragraph after it.
fn formulas(note: &Note) -> Vec<(String, String)> {
    fn walk(ss: &[Section], out: &mut Vec<(String, String)>) {
        for s in ss {
            for w in s.blocks.windows(2) {
                if let (Block::Formula { typst_math, .. }, Block::Paragraph(t)) = (&w[0], &w[1]) {
                    let text: String =
                        t.0.iter()
                            .map(|s| match s {
                                Span::Plain(x) | Span::Strong(x) | Span::Emph(x) => x.clone(),
                                _ => String::new(),
                            })
                            .collect();
                    out.push((typst_math.clone(), text));
                }
            }
            walk(&s.subsections, out);
        }
    }
    let mut out = Vec::new();
    walk(&note.sections, &mut out);
    out
}

/// The upper-case point letters of a line of typst math.
fn letters(line: &str) -> BTreeSet<String> {
    line.chars().filter(char::is_ascii_uppercase).map(String::from).collect()
}

/// The symbols of a formula: `v_(B A)`, `a^k_(B_3 B_2)`, `omega_1`,
/// `l_(O A)`, the vector arrows taken off.
fn symbols(math: &str) -> BTreeSet<String> {
    let m = math.replace("arrow(v)", "v").replace("arrow(a)", "a");
    let mut out = BTreeSet::new();
    let chars: Vec<char> = m.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        let rest: String = chars[i..].iter().collect();
        let start = i == 0 || !chars[i - 1].is_ascii_alphanumeric();
        let head = ["a^n_(", "a^tau_(", "a^k_(", "a^r_(", "v_(", "a_(", "l_("]
            .into_iter()
            .find(|h| rest.starts_with(h));
        if let (true, Some(_)) = (start, head) {
            let end = rest.find(')').unwrap();
            out.insert(rest[..=end].to_string());
            i += end + 1;
            continue;
        }
        for g in ["omega_", "epsilon_"] {
            if start && rest.starts_with(g) {
                let n: String = rest[g.len()..].chars().take_while(char::is_ascii_digit).collect();
                out.insert(format!("{g}{n}"));
            }
        }
        i += 1;
    }
    out
}

/// The math runs of a where-line that are symbols (not a point's letter).
fn named(line: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let mut rest = line;
    while let Some(a) = rest.find('\u{E000}') {
        let b = rest[a..].find('\u{E001}').unwrap() + a;
        let run = &rest[a + '\u{E000}'.len_utf8()..b];
        out.extend(symbols(run));
        rest = &rest[b..];
    }
    out
}

#[test]
fn each_mechanism_has_its_own_group_equations() {
    for name in TASKS {
        for lang in [Language::Ru, Language::Uk, Language::En] {
            let t = task(name);
            let run = run_task_in(&t, Some(lang)).unwrap();
            let note = compose(&run, &t).unwrap();
            let report = &run.report;
            let pairs = pairs(report);
            let still = still(&pairs);
            let groups = report.pointer("/linkage/structure/groups").and_then(Value::as_array).unwrap();
            let input = report.pointer("/linkage/input/link").and_then(Value::as_str).unwrap();
            let fs = formulas(&note);
            let at = |needle: &str| {
                fs.iter()
                    .find(|(m, _)| m.contains(needle))
                    .unwrap_or_else(|| panic!("{name}: no formula with {needle}"))
            };
            let (velocity, v_where) = at("arrow(v)");
            let (acceleration, a_where) = at("arrow(a)");
            let v_lines: Vec<&str> = velocity.split(" \\ ").collect();
            let a_lines: Vec<&str> = acceleration.split(" \\ ").collect();
            assert_eq!(v_lines.len(), groups.len() + 1, "{name} {lang:?}: {velocity}");
            assert_eq!(a_lines.len(), groups.len() + 1, "{name} {lang:?}: {acceleration}");
            // the input link's line: its own pairs' points
            let own: BTreeSet<String> = pairs
                .iter()
                .filter(|p| p.links.iter().any(|l| l == input))
                .map(|p| p.point.clone())
                .collect();
            assert!(letters(v_lines[0]).is_subset(&own), "{name}: {} against {own:?}", v_lines[0]);
            assert!(!letters(v_lines[0]).is_empty(), "{name}: {}", v_lines[0]);
            // a slider on a fixed guide does not turn: each of its points
            // moves with the slider's given v and a (v_B = v, a_B = a), no ω·l
            if report.pointer("/linkage/input/kind").and_then(Value::as_str) == Some("slider") {
                for (line, given) in [(v_lines[0], "= v"), (a_lines[0], "= a")] {
                    assert!(line.contains(given), "{name} {lang:?}: {line}");
                    assert!(!line.contains("omega") && !line.contains("l_("), "{name} {lang:?}: {line}");
                }
            }
            for (k, g) in groups.iter().enumerate() {
                let links: Vec<&str> = g["links"].as_array().unwrap().iter().map(|l| l.as_str().unwrap()).collect();
                let mine: Vec<&Pair> = pairs
                    .iter()
                    .filter(|p| p.links.iter().any(|l| links.contains(&l.as_str())))
                    .collect();
                let points: BTreeSet<String> = mine.iter().map(|p| p.point.clone()).collect();
                // the inner pairs' points: the points the group's equation solves for
                let inner: BTreeSet<String> = mine
                    .iter()
                    .filter(|p| p.links.iter().all(|l| links.contains(&l.as_str())))
                    .map(|p| p.point.clone())
                    .collect();
                for line in [v_lines[k + 1], a_lines[k + 1]] {
                    let l = letters(line);
                    assert!(l.is_subset(&points), "{name} group {k}: {line} against {points:?}");
                    assert!(!inner.is_empty() && inner.is_subset(&l), "{name} group {k}: {line} lacks {inner:?}");
                }
                // a sliding pair of the group on a guide that turns
                // (the group's own pairs: a point of its list, a link of it)
                let points_of: BTreeSet<&str> = g["pairs"].as_array().unwrap().iter().map(|p| p.as_str().unwrap()).collect();
                let group_pairs: Vec<&&Pair> = mine.iter().filter(|p| points_of.contains(p.point.as_str())).collect();
                let turning_guide = group_pairs.iter().any(|p| p.sliding && p.links.iter().all(|l| !still.contains(l)));
                assert_eq!(
                    a_lines[k + 1].contains("^k"),
                    turning_guide,
                    "{name} group {k}: Coriolis term in {}",
                    a_lines[k + 1]
                );
                let sliding = group_pairs.iter().any(|p| p.sliding);
                assert_eq!(a_lines[k + 1].contains("^r"), sliding, "{name} group {k}: {}", a_lines[k + 1]);
            }
            // every formula of the kinematics with its where-line: every
            // symbol named, no other
            let mags = fs.iter().find(|(m, _)| m.contains("a^n_") && !m.contains("arrow"));
            for (math, line) in [(velocity, v_where), (acceleration, a_where)]
                .into_iter()
                .chain(mags.map(|(m, w)| (m, w)))
            {
                let prefix = ["где ", "де ", "where "].iter().any(|p| line.starts_with(p));
                assert!(prefix, "{name} {lang:?}: no where-line under {math}: {line}");
                assert_eq!(symbols(math), named(line), "{name} {lang:?}: {math}\n{line}");
                for word in ["шатун", "coupler"] {
                    assert!(!line.contains(word), "{name} {lang:?}: {line}");
                }
            }
        }
    }
}
