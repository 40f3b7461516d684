//! The dynamics diagrams and the synthesis construction read back as a
//! teacher checks them: each within its slot on A1 and A2, at round scale
//! factors written under the title, the φ axis over 0…360° marked with the
//! positions 0…12, the construction at a GOST 2.302 scale whose drawn chord
//! measures the JSON length × scale, labels' boxes apart, and no English
//! word or decimal point on a Russian drawing.

use std::path::Path;

use tmm_report::TaskSource;

use crate::svg_read::{attr, num, paper, texts};
use tmm_report::output::Documents;
use tmm_report::paper::{STANDARD_SCALES, Slot, round_mu, slot_mm};
use tmm_report::project::{Language, SheetFormat};

fn examples() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

fn dynamics_tasks() -> Vec<(String, String)> {
    let mut v = vec![("default".to_string(), tmm_report::run::DEFAULT_TASK.to_string())];
    for name in ["seed-003-sixbar.toml", "seed-001-fourbar.toml"] {
        v.push((name.to_string(), std::fs::read_to_string(examples().join(name)).unwrap()));
    }
    v
}

fn synthesis_tasks() -> Vec<(String, String)> {
    let mut v = Vec::new();
    let mut names: Vec<_> = std::fs::read_dir(examples())
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|n| n.starts_with("synth-") && n.ends_with(".toml"))
        .collect();
    names.sort();
    assert!(names.len() >= 3);
    for name in names {
        v.push((name.clone(), std::fs::read_to_string(examples().join(&name)).unwrap()));
    }
    v
}

fn overlap(a: &[f64; 4], b: &[f64; 4]) -> bool {
    a[0] < b[2] - 1e-6 && b[0] < a[2] - 1e-6 && a[1] < b[3] - 1e-6 && b[1] < a[3] - 1e-6
}

fn dynamics(name: &str, text: &str, lang: Language, sheet: SheetFormat) -> Documents {
    let task = TaskSource::new(name, text).with_lang(lang).with_sheet(sheet);
    tmm_report::dynamics::run_section(&task).unwrap().unwrap().docs
}

fn synthesis(name: &str, text: &str, lang: Language, sheet: SheetFormat) -> (Documents, serde_json::Value) {
    let task = TaskSource::new(name, text).with_lang(lang).with_sheet(sheet);
    let s = tmm_report::synthesis::run_section(&task).unwrap().unwrap();
    (s.docs, s.json)
}

fn svgs(docs: &Documents) -> Vec<(String, String)> {
    docs.iter()
        .filter(|d| d.path.ends_with(".svg"))
        .map(|d| (d.path.clone(), d.as_text().unwrap().to_string()))
        .collect()
}

fn dynamics_slot(path: &str) -> Slot {
    if path.ends_with("wittenbauer.svg") {
        Slot::Small
    } else {
        Slot::Diagram
    }
}

fn synthesis_slot(path: &str) -> Slot {
    if path.ends_with("construction.svg") {
        Slot::Small
    } else {
        Slot::Diagram
    }
}

/// Every drawing's paper is within its slot and every text inside the paper.
fn check_fits(name: &str, path: &str, svg: &str, slot: Slot, sheet: SheetFormat) {
    let (w, h, _) = paper(svg);
    let (sw, sh) = slot_mm(slot, sheet);
    assert!(w <= sw + 1e-9 && h <= sh + 1e-9, "{name} {path} {sheet:?}: {w}×{h} over {sw}×{sh}");
    for (t, b) in texts(svg, true) {
        assert!(
            b[0] >= -1e-6 && b[1] >= -1e-6 && b[2] <= w + 1e-6 && b[3] <= h + 1e-6,
            "{name} {path} {sheet:?}: \"{t}\" {b:?} off the {w}×{h} paper"
        );
    }
}

/// No two texts' boxes overlap.
fn check_apart(name: &str, path: &str, svg: &str) {
    let t = texts(svg, true);
    for i in 0..t.len() {
        for j in i + 1..t.len() {
            assert!(
                !overlap(&t[i].1, &t[j].1),
                "{name} {path}: \"{}\" {:?} and \"{}\" {:?} overlap",
                t[i].0,
                t[i].1,
                t[j].0,
                t[j].1
            );
        }
    }
}

/// No English word (three Latin lower-case letters in a row; the indices
/// max and min of ω_max, ω_min are notation) and no decimal point.
fn check_russian(name: &str, path: &str, svg: &str) {
    for (t, _) in texts(svg, true) {
        let mut run = 0;
        for ch in t.replace("max", "").replace("min", "").chars() {
            run = if ch.is_ascii_lowercase() { run + 1 } else { 0 };
            assert!(run < 3, "{name} {path}: English in \"{t}\"");
        }
        let b: Vec<char> = t.chars().collect();
        for i in 1..b.len().saturating_sub(1) {
            assert!(
                !(b[i] == '.' && b[i - 1].is_ascii_digit() && b[i + 1].is_ascii_digit()),
                "{name} {path}: a decimal point in \"{t}\""
            );
        }
    }
}

#[test]
fn dynamics_diagrams_fit_their_slots_with_labels_apart() {
    for (name, text) in dynamics_tasks() {
        for sheet in [SheetFormat::A1, SheetFormat::A2] {
            for lang in [Language::Ru, Language::En] {
                let docs = dynamics(&name, &text, lang, sheet);
                let all = svgs(&docs);
                dump(&name, lang, sheet, &all);
                assert!(all.len() >= 7, "{name}: {} drawings", all.len());
                for (path, svg) in &all {
                    check_fits(&name, path, svg, dynamics_slot(path), sheet);
                    check_apart(&name, path, svg);
                    if lang == Language::Ru {
                        check_russian(&name, path, svg);
                    }
                }
            }
        }
    }
}

/// The φ axis of a cycle diagram: the positions 0…12 under it, evenly
/// 360°/12 apart at the written round μ_φ, and the scale factors' line
/// under the title.
#[test]
fn cycle_diagrams_mark_the_positions_at_a_round_mu() {
    let (name, text) = &dynamics_tasks()[0];
    for sheet in [SheetFormat::A1, SheetFormat::A2] {
        let docs = dynamics(name, text, Language::Ru, sheet);
        for file in [
            "moments.svg",
            "work.svg",
            "inertia.svg",
            "energy-constant.svg",
            "omega.svg",
            "epsilon.svg",
        ] {
            let svg = docs.get(&format!("dynamics/{file}")).unwrap().as_text().unwrap();
            let t = texts(svg, true);
            // the scale factors: "μ_φ = 2 °/мм" and μ of the quantity, both round
            let line = t
                .iter()
                .find(|(s, _)| s.contains("μφ"))
                .unwrap_or_else(|| panic!("{file}: no μ_φ"))
                .0
                .clone();
            let mus: Vec<f64> = line
                .split('=')
                .skip(1)
                .map(|p| p.trim().split(' ').next().unwrap().replace(',', ".").parse::<f64>().unwrap())
                .collect();
            assert_eq!(mus.len(), 2, "{file}: {line}");
            for mu in &mus {
                assert_eq!(*mu, round_mu(*mu), "{file}: μ {mu} is not round");
            }
            let mu_phi = mus[1];
            // the position numbers 0…12, left to right, 30°/μ_φ apart
            let mut xs = Vec::new();
            for k in 0..=12 {
                let label = k.to_string();
                let b = t
                    .iter()
                    .filter(|(s, _)| *s == label)
                    .map(|(_, b)| *b)
                    .max_by(|a, b| a[1].total_cmp(&b[1]))
                    .unwrap_or_else(|| panic!("{file}: no position {k}"));
                xs.push(0.5 * (b[0] + b[2]));
            }
            for w in xs.windows(2) {
                assert!(
                    (w[1] - w[0] - 30.0 / mu_phi).abs() < 1e-3,
                    "{file} {sheet:?}: positions {xs:?} at μ_φ {mu_phi}"
                );
            }
        }
        let omega = docs.get("dynamics/omega.svg").unwrap().as_text().unwrap();
        for s in ["ω<tspan", ">max<", ">min<"] {
            assert!(omega.contains(s), "ω_max, ω_min, ω_m marked: {s}");
        }
        let w = docs.get("dynamics/wittenbauer.svg").unwrap().as_text().unwrap();
        assert!(w.matches("class=\"curve\"").count() >= 3, "the curve and both tangents");
    }
}

#[test]
fn synthesis_drawings_fit_their_slots_with_labels_apart() {
    for (name, text) in synthesis_tasks() {
        for sheet in [SheetFormat::A1, SheetFormat::A2] {
            for lang in [Language::Ru, Language::En] {
                let (docs, _) = synthesis(&name, &text, lang, sheet);
                let all = svgs(&docs);
                dump(&name, lang, sheet, &all);
                assert!(!all.is_empty(), "{name}");
                for (path, svg) in &all {
                    check_fits(&name, path, svg, synthesis_slot(path), sheet);
                    if path.ends_with("construction.svg") {
                        check_apart(&name, path, svg);
                    }
                    if lang == Language::Ru {
                        check_russian(&name, path, svg);
                    }
                }
            }
        }
    }
}

/// The construction is at a standard scale written as `data-scale`, and
/// its chord between the driven point's extremes measures the JSON
/// stroke × scale.
#[test]
fn the_construction_is_at_a_standard_scale() {
    for (name, text) in synthesis_tasks() {
        for sheet in [SheetFormat::A1, SheetFormat::A2] {
            let (docs, json) = synthesis(&name, &text, Language::Ru, sheet);
            let svg = docs.get("synthesis/construction.svg").unwrap().as_text().unwrap();
            let (_, _, root) = paper(svg);
            let scale = attr(&root, "data-scale").unwrap_or_else(|| panic!("{name}: no data-scale"));
            let factor = STANDARD_SCALES
                .iter()
                .find(|s| s.1 == scale)
                .unwrap_or_else(|| panic!("{name}: {scale} is not a GOST 2.302 scale"))
                .0;
            let chord = svg
                .lines()
                .find(|l| l.contains("class=\"chord\""))
                .unwrap_or_else(|| panic!("{name}: no chord"));
            let drawn = ((num(chord, "x2") - num(chord, "x1")).powi(2) + (num(chord, "y2") - num(chord, "y1")).powi(2)).sqrt();
            let e = &json["construction"]["extremes"];
            let (a, b) = (&e[0], &e[1]);
            let len = ((a[0].as_f64().unwrap() - b[0].as_f64().unwrap()).powi(2)
                + (a[1].as_f64().unwrap() - b[1].as_f64().unwrap()).powi(2))
            .sqrt();
            assert!(
                (drawn - len * 1000.0 * factor).abs() < 2e-3,
                "{name} {sheet:?}: chord {drawn} mm, {len} m at {scale}"
            );
        }
    }
}

fn dump(name: &str, lang: Language, sheet: SheetFormat, all: &[(String, String)]) {
    if let Ok(dir) = std::env::var("DRAW_DUMP") {
        for (p, svg) in all {
            let f = format!("{dir}/{name}-{}-{sheet:?}-{}", lang.code(), p.replace('/', "-"));
            std::fs::write(f, svg).unwrap();
        }
    }
}

/// The shared plot prints its tick labels with the decimal comma in
/// Russian: the balancing torque and the strength diagrams of the default
/// task carry no decimal point, and the English ones no comma in a number
/// (the number printed with the comma: `svg::plot_in`'s doctest).
#[test]
fn plots_use_the_decimal_comma_in_russian() {
    for (lang, bad) in [(Language::Ru, '.'), (Language::En, ',')] {
        let task = TaskSource::new("default", tmm_report::run::DEFAULT_TASK).with_lang(lang);
        let docs = tmm_report::forces::run_section(&task).unwrap().unwrap().docs;
        let plots: Vec<_> = svgs(&docs)
            .into_iter()
            .filter(|(p, _)| p.contains("balancing-torque") || p.contains("strength-"))
            .collect();
        assert!(!plots.is_empty());
        let mut fractional = 0;
        for (path, svg) in &plots {
            for (t, _) in texts(svg, true) {
                let b: Vec<char> = t.chars().collect();
                for i in 1..b.len().saturating_sub(1) {
                    let between = b[i - 1].is_ascii_digit() && b[i + 1].is_ascii_digit();
                    assert!(!(b[i] == bad && between), "{path}: \"{t}\" in {lang:?}");
                    if between && (b[i] == '.' || b[i] == ',') {
                        fractional += 1;
                    }
                }
            }
        }
        // the default task's ticks may all be whole; plot_in's doctest
        // asserts a fractional tick printed with the comma
        let _ = fractional;
    }
}
