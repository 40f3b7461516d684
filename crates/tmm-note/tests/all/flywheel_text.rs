//! The flywheel as the task makes it and the δ reached as given (issue 22,
//! point 5): the dynamics section's sentence names the task's shape (a disc
//! or a rim) and its material by the task's density, the table of the
//! flywheel's size gives a rim's radial thickness, and the table of the
//! results writes the δ reached as the task writes δ (0,02, not 0,02000).
//!
//! The expectations come from the task files themselves (the shape, the
//! density, the rim's ratio, δ as written), not from the report: seed 003's
//! flywheel is a cast-iron rim (7200 kg/m³), П3's a steel rim given by its
//! inner diameter, the default project's and seed 001's a steel disc.

use tmm_note::{Block, Cell, Note, Section, Span, Text, compose, notation};
use tmm_report::TaskSource;
use tmm_report::project::Language;
use tmm_report::run::{DEFAULT_TASK, run_task_in};

/// The words a language writes for the shapes and the materials.
struct Words {
    disc: &'static str,
    rim: &'static str,
    steel: &'static str,
    cast_iron: &'static str,
    flywheel: &'static str,
    thickness: &'static str,
    diameter: &'static str,
}

fn words(lang: Language) -> Words {
    match lang {
        Language::Ru => Words {
            disc: "диск",
            rim: "обод",
            steel: "стальн",
            cast_iron: "чугун",
            flywheel: "Маховик —",
            thickness: "Толщина",
            diameter: "Диаметр маховика",
        },
        Language::Uk => Words {
            disc: "диск",
            rim: "обід",
            steel: "сталев",
            cast_iron: "чавун",
            flywheel: "Маховик —",
            thickness: "Товщина",
            diameter: "Діаметр маховика",
        },
        Language::En => Words {
            disc: "disc",
            rim: "rim",
            steel: "steel",
            cast_iron: "cast-iron",
            flywheel: "The flywheel is",
            thickness: "thickness",
            diameter: "Flywheel diameter",
        },
    }
}

/// A text's characters without the notation's markers.
fn flat(t: &Text) -> String {
    t.0.iter()
        .map(|s| match s {
            Span::Plain(p) | Span::Strong(p) | Span::Emph(p) => notation::strip(p),
            Span::Math(m) => m.clone(),
            _ => String::new(),
        })
        .collect()
}

fn cell(c: &Cell) -> String {
    match c {
        Cell::Text(t) => flat(t),
        _ => String::new(),
    }
}

/// Every paragraph and every two-column table row of a section.
fn read(s: &Section, paras: &mut Vec<String>, rows: &mut Vec<(String, String)>) {
    for b in &s.blocks {
        match b {
            Block::Paragraph(t) => paras.push(flat(t)),
            Block::Table { rows: r, .. } => {
                rows.extend(r.iter().filter(|r| r.len() == 2).map(|r| (cell(&r[0]), cell(&r[1]))));
            }
            _ => {}
        }
    }
    for ss in &s.subsections {
        read(ss, paras, rows);
    }
}

/// The leading number of a cell ("40,09 мм" → 40.09).
fn number(s: &str) -> f64 {
    let n: String = s
        .trim()
        .chars()
        .take_while(|c| c.is_ascii_digit() || matches!(c, ',' | '.'))
        .collect();
    n.replace(',', ".").parse().unwrap_or_else(|_| panic!("no number in {s:?}"))
}

/// The task's flywheel: (shape, density in kg/m³, a rim's h/D, δ as
/// written in the file).
fn task_flywheel(text: &str) -> (String, f64, Option<f64>, String) {
    let t: toml::Table = text.parse().unwrap();
    let dy = t["dynamics"].as_table().unwrap();
    let delta = dy["delta"].to_string();
    let fw = dy.get("flywheel").and_then(toml::Value::as_table).cloned().unwrap_or_default();
    let shape = fw.get("shape").and_then(toml::Value::as_str).unwrap_or("disc").to_string();
    // the default material is steel (docs: dynamics.flywheel.density)
    let density = fw
        .get("density")
        .and_then(toml::Value::as_str)
        .map_or(7850.0, |d| d.split_whitespace().next().unwrap().parse().unwrap());
    let ratio = |k: &str| fw.get(k).and_then(|v| v.as_float().or_else(|| v.as_integer().map(|i| i as f64)));
    // a rim by its inner diameter D₁ = k·D: h = (1 − k)·D/2
    let h = ratio("thickness_ratio").or_else(|| ratio("inner_ratio").map(|k| (1.0 - k) / 2.0));
    (shape, density, h, delta)
}

fn note_of(name: &str, text: &str, lang: Language) -> Note {
    let task = TaskSource::new(name, text);
    let run = run_task_in(&task, Some(lang)).unwrap();
    compose(&run, &task).unwrap()
}

fn example(file: &str) -> String {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples").join(file);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn the_flywheel_is_written_as_the_task_makes_it() {
    let tasks = [
        (
            "default.toml",
            DEFAULT_TASK.to_string(),
            vec![Language::Ru, Language::Uk, Language::En],
        ),
        (
            "seed-003-sixbar.toml",
            example("seed-003-sixbar.toml"),
            vec![Language::Ru, Language::Uk, Language::En],
        ),
        ("seed-001-fourbar.toml", example("seed-001-fourbar.toml"), vec![Language::Ru]),
        (
            "textbook/p3-shaper.toml",
            example("textbook/p3-shaper.toml"),
            vec![Language::Ru, Language::En],
        ),
    ];
    let mut faults = Vec::new();
    let mut checked = 0;
    for (name, text, langs) in &tasks {
        let (shape, density, h_ratio, delta) = task_flywheel(text);
        for &lang in langs {
            let w = words(lang);
            let label = format!("{name} {lang:?}");
            let note = note_of(name, text, lang);
            let (mut paras, mut rows) = (Vec::new(), Vec::new());
            for s in &note.sections {
                read(s, &mut paras, &mut rows);
            }
            let sentences: Vec<&String> = paras.iter().filter(|p| p.contains(w.flywheel)).collect();
            if sentences.is_empty() {
                faults.push(format!("{label}: no sentence on the flywheel"));
            }
            let (this, other) = if shape == "rim" { (w.rim, w.disc) } else { (w.disc, w.rim) };
            let material = match density {
                d if (7700.0..=7900.0).contains(&d) => Some(w.steel),
                d if (6800.0..=7400.0).contains(&d) => Some(w.cast_iron),
                _ => None,
            };
            let wrong_material = if material == Some(w.steel) { w.cast_iron } else { w.steel };
            for p in &sentences {
                let at = p.find(w.flywheel).unwrap();
                // the sentence: to its full stop (a decimal point is
                // followed by a digit)
                let s = &p[at..(at + p[at..].find(". ").unwrap_or(p.len() - at))];
                if !s.contains(this) || s.contains(other) {
                    faults.push(format!("{label}: the task's flywheel is a {shape}, the note says {s:?}"));
                }
                if let Some(m) = material
                    && !s.contains(m)
                {
                    faults.push(format!("{label}: density {density} kg/m³ is not named {m:?} in {s:?}"));
                }
                if s.contains(wrong_material) {
                    faults.push(format!("{label}: {s:?} names another material than {density} kg/m³"));
                }
                if !s.contains(&format!("{density:.0}")) {
                    faults.push(format!("{label}: {s:?} does not give the density {density}"));
                }
                checked += 1;
            }
            // the size table: a rim's thickness, h = ratio·D
            let diameter = rows.iter().find(|r| r.0.contains(w.diameter)).map(|r| number(&r.1));
            let thickness = rows.iter().find(|r| r.0.contains(w.thickness)).map(|r| number(&r.1));
            match (shape.as_str(), diameter, thickness, h_ratio) {
                // both printed to four digits
                ("rim", Some(d), Some(h), Some(k)) if (h - k * d).abs() > 1e-3 * h + 0.05 => {
                    faults.push(format!("{label}: the rim's thickness {h} mm is not {k}·D = {} mm", k * d));
                }
                ("rim", _, None, _) => faults.push(format!("{label}: the size table has no rim thickness")),
                ("disc", _, Some(_), _) => faults.push(format!("{label}: a disc given a rim's thickness")),
                _ => {}
            }
            // δ reached, as the task writes δ
            let given = if lang == Language::En {
                delta.clone()
            } else {
                delta.replace('.', ",")
            };
            match rows.iter().find(|r| r.0.ends_with("δ") && !r.1.is_empty()) {
                Some((q, v)) if v.trim() != given => {
                    faults.push(format!("{label}: \"{q}\" is {v:?}, the task writes δ = {given}"));
                }
                None => faults.push(format!("{label}: no row of the δ reached")),
                _ => {}
            }
        }
    }
    println!("{checked} flywheel sentences checked");
    assert!(faults.is_empty(), "{} faults:\n{}", faults.len(), faults.join("\n"));
}
