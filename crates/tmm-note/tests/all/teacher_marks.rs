//! What a teacher marks red on reading the examples' notes page by page:
//! a given angle printed in millimetres (the crank-rocker's frame angle),
//! the slotted lever's coupler ratio printed as a length, the
//! kinetostatics of the engine (whose crank turns at the true ω1(φ) of the
//! dynamics) said to turn uniformly, the engine's constant moment called a
//! driving torque, the task's keys `R30`, `R21` printed raw in captions and
//! the centres of mass `S1`, `S2` raw in the plan's table, the masses the
//! task gives link by link repeated in a table of computed values
//! («0,3400» for the given 0.34 kg). Each test reads the composed note
//! against the task file's givens.

use tmm_note::notation::{MATH_OPEN, runs, strip};
use tmm_note::{Block, Cell, Note, Section, Span, compose};
use tmm_report::project::Language;
use tmm_report::run::run_task_in;

use super::fixtures::task;

const LANGS: [Language; 3] = [Language::Ru, Language::Uk, Language::En];

fn note(name: &str, lang: Language) -> Note {
    let t = task(name);
    let run = run_task_in(&t, Some(lang)).unwrap();
    compose(&run, &t).unwrap()
}

/// Every block of the note: the assignment's, the sections' (depth first)
/// and the appendices'.
fn blocks(note: &Note) -> Vec<&Block> {
    fn walk<'a>(ss: &'a [Section], out: &mut Vec<&'a Block>) {
        for s in ss {
            out.extend(s.blocks.iter());
            walk(&s.subsections, out);
        }
    }
    let mut out: Vec<&Block> = note.assignment.iter().collect();
    walk(&note.sections, &mut out);
    walk(&note.appendices, &mut out);
    out
}

/// A cell's text as printed (math markers and spans flattened).
fn cell_text(c: &Cell) -> String {
    match c {
        Cell::Text(t) => {
            t.0.iter()
                .map(|s| match s {
                    Span::Plain(x) | Span::Strong(x) | Span::Emph(x) | Span::Math(x) => strip(x),
                    _ => String::new(),
                })
                .collect()
        }
        _ => String::new(),
    }
}

/// The (name, value) rows of the two-column tables.
fn pairs(note: &Note) -> Vec<(String, String)> {
    let mut out = Vec::new();
    for b in blocks(note) {
        if let Block::Table { rows, .. } = b {
            for r in rows.iter().filter(|r| r.len() == 2) {
                out.push((cell_text(&r[0]), cell_text(&r[1])));
            }
        }
    }
    out
}

/// The paragraphs' texts, markers removed.
fn paragraphs(note: &Note) -> Vec<String> {
    blocks(note)
        .into_iter()
        .filter_map(|b| match b {
            Block::Paragraph(t) => Some(
                t.0.iter()
                    .map(|s| match s {
                        Span::Plain(x) | Span::Strong(x) | Span::Emph(x) | Span::Math(x) => strip(x),
                        _ => String::new(),
                    })
                    .collect::<String>(),
            ),
            _ => None,
        })
        .collect()
}

/// A printed number in either decimal separator.
fn number(s: &str) -> Option<f64> {
    let t: String = s
        .chars()
        .take_while(|c| c.is_ascii_digit() || matches!(c, ',' | '.' | '-' | '−'))
        .collect();
    t.replace(',', ".").replace('−', "-").parse().ok()
}

#[test]
fn the_crank_rockers_frame_angle_is_printed_in_degrees() {
    // examples/synth-seed-002-ex1-crank-rocker.toml: frame_angle = "90 deg"
    for lang in LANGS {
        let n = note("synth-seed-002-ex1-crank-rocker.toml", lang);
        let rows = pairs(&n);
        let angles: Vec<&(String, String)> = rows
            .iter()
            .filter(|(k, _)| {
                k.to_lowercase()
                    .split(|c: char| !c.is_alphabetic())
                    .any(|w| matches!(w, "угол" | "кут" | "angle"))
            })
            .collect();
        for (k, v) in &angles {
            assert!(v.ends_with('°'), "{lang:?}: «{k}» printed as «{v}»");
        }
        let frame: Vec<_> = angles
            .iter()
            .filter(|(k, _)| k.contains("стойки") || k.contains("стояка") || k.to_lowercase().contains("frame"))
            .collect();
        // δ of the synthesis (tmm-linkage's `FrameAngle`, docs/synthesis.md
        // § 4): the angle from the frame line to the bisector of the
        // rocker's swing, not an angle from the vertical
        for (k, _) in &frame {
            assert!(
                ["биссектрис", "бісектрис", "bisector"].iter().any(|w| k.contains(w)) && !k.contains("вертикал") && !k.contains("vertical"),
                "{lang:?}: «{k}» does not name the angle the synthesis takes"
            );
        }
        assert_eq!(
            frame.len(),
            2,
            "{lang:?}: the frame angle in the assignment and in table 1.1: {angles:?}"
        );
        for (k, v) in frame {
            let x = number(v).unwrap_or(f64::NAN);
            assert!((x - 90.0).abs() < 1e-9, "{lang:?}: «{k}» = «{v}», the task gives 90°");
        }
    }
}

#[test]
fn the_slotted_levers_coupler_ratio_is_a_bare_number() {
    // examples/synth-seed-002-ex3-shaper.toml: coupler_ratio = 3 (l_CD/l_EC)
    for lang in LANGS {
        let n = note("synth-seed-002-ex3-shaper.toml", lang);
        let rows = pairs(&n);
        let ratio: Vec<_> = rows.iter().filter(|(k, _)| k.contains("l_(C D)/l_(E C)")).collect();
        assert_eq!(ratio.len(), 2, "{lang:?}: the ratio in the assignment and in table 1.1: {rows:?}");
        for (k, v) in ratio {
            assert!(
                v.chars().all(|c| c.is_ascii_digit() || matches!(c, ',' | '.')),
                "{lang:?}: «{k}» printed with a unit: «{v}»"
            );
            assert!((number(v).unwrap_or(f64::NAN) - 3.0).abs() < 1e-9, "{lang:?}: «{k}» = «{v}»");
        }
        assert!(
            !rows.iter().any(|(_, v)| v.starts_with("3000")),
            "{lang:?}: the ratio 3 printed as 3000 mm: {rows:?}"
        );
    }
}

#[test]
fn the_engines_kinetostatics_and_dynamics_say_what_the_task_gives() {
    // examples/textbook/p2-engine.toml: crank_motion = "dynamics" (the crank
    // turns at the true ω1(φ) of the machine), driving = "engine" (the gas
    // forces drive, the driven machine's resistance is the constant moment)
    let t = task("textbook/p2-engine.toml");
    let given: toml::Table = toml::from_str(&t.text).unwrap();
    assert_eq!(given["forces"]["crank_motion"].as_str(), Some("dynamics"));
    assert_eq!(given["dynamics"]["driving"].as_str(), Some("engine"));
    for (lang, uniform, driving) in [
        (Language::Ru, "равномерно с", "Движущий момент"),
        (Language::Uk, "рівномірно з", "Рушійний момент"),
        (Language::En, "turns uniformly", "driving torque is"),
    ] {
        let n = note("textbook/p2-engine.toml", lang);
        let text = paragraphs(&n).join("\n");
        assert!(!text.contains(uniform), "{lang:?}: the crank said to turn uniformly:\n{text}");
        assert!(!text.contains(driving), "{lang:?}: the engine's resistance called driving:\n{text}");
        assert!(
            !pairs(&n).iter().any(|(k, _)| k.starts_with(driving)),
            "{lang:?}: the engine's resistance called driving in a table"
        );
    }
}

#[test]
fn the_cycles_reactions_and_the_plans_points_are_typeset() {
    let raw = |s: &str| {
        let c: Vec<char> = s.chars().collect();
        (0..c.len()).any(|i| {
            matches!(c[i], 'R' | 'M' | 'S') && (i == 0 || !c[i - 1].is_alphanumeric()) && c.get(i + 1).is_some_and(char::is_ascii_digit)
        })
    };
    for lang in LANGS {
        let n = note("textbook/p2-engine.toml", lang);
        let mut captions = 0;
        for b in blocks(&n) {
            match b {
                Block::Figure { caption, .. } => {
                    for (math, run) in runs(caption) {
                        assert!(math || !raw(&run), "{lang:?}: a raw name in the caption «{}»", strip(caption));
                    }
                    if caption.contains(MATH_OPEN) && ["R_(30)", "R_(50)", "R_(21)"].iter().any(|r| caption.contains(r)) {
                        captions += 1;
                    }
                }
                Block::Table { rows, .. } => {
                    for r in rows {
                        if let Some(Cell::Text(t)) = r.first() {
                            for s in &t.0 {
                                if let Span::Plain(x) = s {
                                    assert!(!raw(x), "{lang:?}: a raw point «{x}» in a table");
                                }
                            }
                        }
                    }
                }
                _ => {}
            }
        }
        // the task's diagrams R30, R50 and the hodographs of R21 (two)
        assert_eq!(captions, 4, "{lang:?}");
    }
}

/// П2 gives every link's mass and inertia («0.34 kg», «0.002 kg m^2»): the
/// assignment prints each as written, and no table repeats them with the
/// digits of a computed value («0,3400», «0,002000»).
#[test]
fn masses_given_link_by_link_are_printed_as_written_once() {
    let text = tmm_testkit::examples::text("textbook/p2-engine.toml");
    let t: toml::Table = toml::from_str(&text).unwrap();
    let links = t["forces"]["links"].as_table().expect("П2 gives its links' masses");
    let mut given = Vec::new();
    for l in links.values() {
        for key in ["mass", "inertia"] {
            let v = l[key].as_str().expect("a quantity with its unit");
            given.push(v.split_whitespace().next().unwrap().to_string());
        }
    }
    for lang in LANGS {
        let n = note("textbook/p2-engine.toml", lang);
        // every cell as printed, a number cell with its digits
        let mut cells = Vec::new();
        for b in &n.assignment {
            if let Block::Table { rows, .. } = b {
                cells.extend(rows.iter().flatten().map(|c| {
                    match c {
                        Cell::Number { value, digits } => tmm_note::number::format_number(*value, *digits, n.lang)
                            .map(|f| f.to_string())
                            .unwrap_or_default(),
                        c => cell_text(c),
                    }
                }));
            }
        }
        for g in &given {
            let want: f64 = g.parse().unwrap();
            let written = if lang == Language::En { g.clone() } else { g.replace('.', ",") };
            for c in &cells {
                let Some(first) = c.split_whitespace().next() else { continue };
                let Some(x) = number(first) else { continue };
                if x == want && want != 0.0 {
                    assert_eq!(first, written, "{lang:?}: the given {g} printed as «{c}»");
                }
            }
            assert!(
                want == 0.0 || cells.iter().any(|c| c.starts_with(&written)),
                "{lang:?}: the given {g} is not in the assignment"
            );
        }
    }
}
