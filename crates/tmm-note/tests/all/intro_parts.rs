//! The introduction and the conclusion name only the parts the note has
//! (issue 22, point 7): composed for every task under examples/ in Russian
//! and English, their paragraphs (the lists of the sections' titles aside)
//! must not speak of a part whose section the note lacks — seed 003's
//! six-bar, with no synthesis section, once read "методы … синтеза
//! механизмов … определить размеры механизмов".
//!
//! Which parts a note has is read from its sections' titles; what betrays
//! a part in a paragraph is a list of word stems written here, not the
//! words files' sentences.

use tmm_note::{Block, Section, Span, compose};
use tmm_report::project::Language;
use tmm_report::run::run_task_in;

/// A part: a stem of its section's title in ru and en, and the stems that
/// name it in a paragraph.
struct Part {
    title: (&'static str, &'static str),
    stems: (&'static [&'static str], &'static [&'static str]),
}

const PARTS: [Part; 7] = [
    Part {
        title: ("Метрический синтез", "Metric synthesis"),
        stems: (&["синтез", "размеры рычажного"], &["synthesis", "sizes the linkage"]),
    },
    Part {
        title: ("кинематический анализ", "kinematics of the linkage"),
        stems: (
            &["кинематическ", "планы скоростей"],
            &["kinematics of the linkage", "velocity and acceleration plans"],
        ),
    },
    Part {
        title: ("Кинетостатический", "Kinetostatics"),
        stems: (&["реакци", "Жуковск", "силового"], &["reactions", "Zhukovsky", "force analysis"]),
    },
    Part {
        title: ("Расчёт маховика", "The flywheel"),
        stems: (&["маховик", "равномерност"], &["flywheel", "fluctuation"]),
    },
    Part {
        title: ("зубчатого", "gear pair"),
        stems: (&["зубчат", "зацеплен"], &["gear pair", "gear mesh"]),
    },
    Part {
        title: ("планетарной", "planetary"),
        stems: (&["планетарн"], &["planetary"]),
    },
    Part {
        title: ("кулачкового", "cam mechanism"),
        stems: (&["кулачк"], &["cam mechanism"]),
    },
];

/// The plain text of a section's paragraphs (not its lists).
fn paragraphs(s: &Section) -> String {
    let mut out = String::new();
    for b in &s.blocks {
        if let Block::Paragraph(t) = b {
            for span in &t.0 {
                if let Span::Plain(p) = span {
                    out.push_str(p);
                }
            }
            out.push(' ');
        }
    }
    out
}

/// Every task file under examples/ (and examples/textbook/).
fn examples() -> Vec<std::path::PathBuf> {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut out = Vec::new();
    for dir in [root.clone(), root.join("textbook")] {
        for e in std::fs::read_dir(&dir).unwrap() {
            let p = e.unwrap().path();
            if p.extension().is_some_and(|x| x == "toml") {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

#[test]
fn the_introduction_and_conclusion_name_only_the_notes_parts() {
    let files = examples();
    assert!(files.len() >= 30, "{} examples", files.len());
    let mut faults = Vec::new();
    let mut checked = 0;
    for path in &files {
        let text = std::fs::read_to_string(path).unwrap();
        let task = tmm_report::TaskSource::new(path.display().to_string(), text);
        for lang in [Language::Ru, Language::En] {
            let run = run_task_in(&task, Some(lang)).unwrap();
            let note = compose(&run, &task).unwrap();
            let titles: Vec<&str> = note.sections.iter().map(|s| s.title.as_str()).collect();
            for (what, s) in [("introduction", &note.introduction), ("conclusion", &note.conclusion)] {
                let Some(s) = s else { continue };
                let text = paragraphs(s).to_lowercase();
                for part in &PARTS {
                    let (title, stems) = match lang {
                        Language::En => (part.title.1, part.stems.1),
                        _ => (part.title.0, part.stems.0),
                    };
                    if titles.iter().any(|t| t.contains(title)) {
                        continue;
                    }
                    for stem in stems {
                        if text.contains(&stem.to_lowercase()) {
                            faults.push(format!(
                                "{} {lang:?}: the {what} names \"{stem}\", the note has no section \"{title}…\" ({titles:?})",
                                path.file_name().unwrap().to_string_lossy()
                            ));
                        }
                    }
                }
                checked += 1;
            }
        }
    }
    println!("{} examples, {checked} introductions and conclusions checked", files.len());
    assert!(faults.is_empty(), "{} faults:\n{}", faults.len(), faults.join("\n"));
}

/// A note never says the crank "does not turn a full revolution" of a
/// mechanism the report assembles over the whole turn (the oscillating
/// cylinder's lever, П1.5: assembled from 0 to 2π, K_v undefined because
/// the lever only swings in use); where the report's ranges leave a gap it
/// may. Every example, ru/uk/en, every section's paragraphs and the
/// conclusion.
#[test]
fn no_crank_is_said_to_stop_short_of_a_turn_it_makes() {
    let mut faults = Vec::new();
    let mut full = 0;
    for path in &examples() {
        let text = std::fs::read_to_string(path).unwrap();
        let task = tmm_report::TaskSource::new(path.display().to_string(), text);
        let run = run_task_in(&task, Some(Language::Ru)).unwrap();
        let Some(ranges) = run.report.pointer("/linkage/assembly_ranges").and_then(|v| v.as_array()) else {
            continue;
        };
        let whole = ranges.len() == 1
            && ranges[0]["to"].as_f64().unwrap_or(0.0) - ranges[0]["from"].as_f64().unwrap_or(0.0) >= std::f64::consts::TAU - 1e-9;
        if !whole {
            continue;
        }
        for lang in [Language::Ru, Language::Uk, Language::En] {
            let run = run_task_in(&task, Some(lang)).unwrap();
            let note = compose(&run, &task).unwrap();
            full += 1;
            let mut text: String = note
                .sections
                .iter()
                .map(|s| paragraphs(s) + &s.subsections.iter().map(paragraphs).collect::<String>())
                .collect();
            if let Some(c) = &note.conclusion {
                text += &paragraphs(c);
            }
            for stop in ["не проворачивается", "не провертається", "does not turn a full"] {
                if text.contains(stop) {
                    faults.push(format!(
                        "{} {lang:?}: «{stop}» of a crank assembled over the whole turn",
                        path.display()
                    ));
                }
            }
        }
    }
    assert!(full >= 3, "only {full} notes of a whole-turn assembly");
    assert!(faults.is_empty(), "{}", faults.join("\n"));
}
