//! The labels of the machine meshing and of the cam's diagrams keep 1 mm
//! of paper between their printed ink ([`crate::label_ink`]) and every
//! line of the drawing and every other text, on the A1 sheet and on the
//! note's A4 page: the default project, and one cam example per motion law.

use crate::label_ink::faults;
use tmm_report::TaskSource;
use tmm_report::output::Documents;
use tmm_report::picture::Element;
use tmm_report::project::Language;
use tmm_report::run::{DEFAULT_TASK, note_figures, run_task};
use tmm_testkit::examples;

/// The drawings of `text` on the A1 sheets and on the note's page.
fn both(name: &str, text: &str) -> [(String, Documents); 2] {
    let t = TaskSource::new(name, text);
    [
        (format!("{name} A1"), run_task(&t).unwrap().docs),
        (format!("{name} A4"), note_figures(&t, None).unwrap()),
    ]
}

/// The machine meshing's line names, 1 mm clear of the rack's teeth, the
/// wheel's teeth and circles, the lines they name and the other texts.
#[test]
fn machine_mesh_line_names_clear_every_line() {
    let mut bad = Vec::new();
    for (name, text) in [
        ("default", DEFAULT_TASK.to_string()),
        ("gear-seed003.toml", examples::text("gear-seed003.toml")),
        ("gear-internal.toml", examples::text("gear-internal.toml")),
    ] {
        for (what, docs) in both(name, &text) {
            let pic = docs.picture("gear/machine-mesh.svg").unwrap();
            let names = ["станочно-начальная прямая", "делительная прямая инструмента"];
            let f = faults(pic, 1.0, |t| names.contains(&t));
            bad.extend(f.into_iter().map(|f| format!("{what}: {f}")));
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

/// Every text of the machine meshing prints whole on its paper: the
/// shift's dimension "x·m = 1 мм" left of the tool once lost its "x·" past
/// the drawing's left edge. Its ink (the same measure as above) lies inside
/// the paper, 0.5 mm in, on the A1 sheet and the note's page, in ru, uk, en.
#[test]
fn machine_mesh_texts_print_inside_the_drawing() {
    let mut bad = Vec::new();
    for (name, text) in [
        ("default", DEFAULT_TASK.to_string()),
        ("gear-seed003.toml", examples::text("gear-seed003.toml")),
        ("gear-internal.toml", examples::text("gear-internal.toml")),
    ] {
        for lang in [Language::Ru, Language::Uk, Language::En] {
            let t = TaskSource::new(name, text.clone()).with_lang(lang);
            let runs = [("A1", run_task(&t).unwrap().docs), ("A4", note_figures(&t, None).unwrap())];
            for (what, docs) in runs {
                let pic = docs.picture("gear/machine-mesh.svg").unwrap();
                for b in crate::label_ink::texts(pic) {
                    if b.x0 < 0.5 || b.y0 < 0.5 || b.x1 > pic.width - 0.5 || b.y1 > pic.height - 0.5 {
                        bad.push(format!(
                            "{name} {lang:?} {what}: \"{}\" at x {:.1}…{:.1}, y {:.1}…{:.1} on {:.1} × {:.1} mm",
                            b.text, b.x0, b.x1, b.y0, b.y1, pic.width, pic.height
                        ));
                    }
                }
            }
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

/// Every text of the cam's motion diagrams (s, v, a, j with the impacts'
/// Δa, Δv), of its analogues and of its pressure angle 1 mm clear of every
/// line and of every other text: the default project's cam and one cam
/// example per motion law (constant acceleration, sine, the textbook's
/// accelerations of sine and constant pieces).
#[test]
fn cam_diagram_labels_clear_every_line_and_each_other() {
    let mut bad = Vec::new();
    for (name, text) in [
        ("default", DEFAULT_TASK.to_string()),
        ("cam-seed-001-roller.toml", examples::text("cam-seed-001-roller.toml")),
        ("cam-oscillating-roller.toml", examples::text("cam-oscillating-roller.toml")),
        (
            "textbook/p6-cam-translating.toml",
            examples::text("textbook/p6-cam-translating.toml"),
        ),
    ] {
        for (what, docs) in both(name, &text) {
            for file in ["cam/cam-motion.svg", "cam/cam-analogs.svg", "cam/cam-pressure.svg"] {
                let Some(pic) = docs.picture(file) else { continue };
                let f = faults(pic, 1.0, |_| true);
                bad.extend(f.into_iter().map(|f| format!("{what} {file}: {f}")));
                // every impact's arrow (a red arrowhead) has its size written
                let red = |c: &str| c.eq_ignore_ascii_case("#c62828");
                let heads = pic
                    .elements
                    .iter()
                    .filter(|e| matches!(e, Element::Head { color, .. } if red(color)))
                    .count();
                let sizes = pic
                    .elements
                    .iter()
                    .filter(|e| matches!(e, Element::Label { color, .. } if red(color)))
                    .count();
                if file.ends_with("motion.svg") && heads != sizes {
                    bad.push(format!("{what} {file}: {heads} impacts, {sizes} sizes written"));
                }
            }
        }
    }
    assert!(bad.is_empty(), "{} faults:\n{}", bad.len(), bad.join("\n"));
}

/// The numbers of the gear section's plots (the blocking contour's x₁, x₂
/// and the specific sliding's ϑ) print a negative value with the minus sign
/// − (U+2212), as GOST 2.304's characters have it, never the hyphen-minus:
/// the blocking contour's x₂ axis runs down to −0,6 in the default project.
#[test]
fn plot_numbers_print_the_minus_sign() {
    let mut negatives = 0;
    let mut bad = Vec::new();
    for lang in [Language::Ru, Language::En] {
        let t = TaskSource::new("default", DEFAULT_TASK).with_lang(lang);
        let docs = run_task(&t).unwrap().docs;
        for file in ["gear/contour.svg", "gear/sliding.svg"] {
            let pic = docs.picture(file).unwrap();
            for b in crate::label_ink::texts(pic) {
                let s = b.text.trim();
                if s.starts_with('\u{2212}') && s[3..].starts_with(|c: char| c.is_ascii_digit()) {
                    negatives += 1;
                }
                if s.starts_with('-') {
                    bad.push(format!("{lang:?} {file}: \"{s}\""));
                }
            }
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
    assert!(negatives >= 4, "the plots' negative numbers were found: {negatives}");
}

/// The names of the dynamics diagrams' levels (T_I max and min of
/// Mertsalov's diagram, ω_max, ω_m, ω_min) keep their ink 0.5 mm off every
/// curve and line of the diagram but its grid (which lettering may cross):
/// seed 003's T_I max, written inside the frame at its line's right end,
/// stood on the curve where the curve rises to meet its level there.
#[test]
fn level_names_keep_off_the_curves() {
    let mut tasks = vec![("default".to_string(), DEFAULT_TASK.to_string())];
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    for sub in ["", "textbook"] {
        let mut files: Vec<_> = std::fs::read_dir(dir.join(sub))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "toml"))
            .collect();
        files.sort();
        for f in files {
            tasks.push((f.display().to_string(), std::fs::read_to_string(&f).unwrap()));
        }
    }
    // as read back: the indices' markup gone
    let names = ["TI max", "TI min", "ωmax", "ωm", "ωmin"];
    let (mut bad, mut seen) = (Vec::new(), 0);
    for (name, text) in &tasks {
        if !text.contains("[dynamics") && name != "default" {
            continue;
        }
        for (what, docs) in both(name, text) {
            for file in ["dynamics/energy-constant.svg", "dynamics/omega.svg"] {
                let Some(pic) = docs.picture(file) else { continue };
                let mut kept = pic.clone();
                kept.elements
                    .retain(|e| !matches!(e, Element::Path { class: Some(c), .. } if c == "grid"));
                seen += crate::label_ink::texts(&kept)
                    .iter()
                    .filter(|t| names.contains(&t.text.as_str()))
                    .count();
                let f = faults(&kept, 0.1, |t| names.contains(&t));
                bad.extend(f.into_iter().map(|f| format!("{what} {file}: {f}")));
            }
        }
    }
    assert!(seen >= 20, "only {seen} level names read");
    assert!(bad.is_empty(), "{} faults:\n{}", bad.len(), bad.join("\n"));
}
