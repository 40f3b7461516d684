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

/// Every number a drawing prints — the plots' ticks, the legends' values
/// ("T_I max = −49,302 Дж" of seed 003's Mertsalov figure), the labels —
/// writes a negative value with the minus sign − (U+2212), as GOST
/// 2.304's characters have it, never the hyphen-minus: every text of every
/// drawing of the default project and of every example (with textbook/),
/// in Russian, Ukrainian and English, on the sheets' paper, and of the
/// default project's note figures. A hyphen is a sign where a digit
/// follows it and it opens the text or a word (after a space, a bracket,
/// `=`, `;`, `:`); the blocking contour's x₂ axis runs down to −0,6 in the
/// default project, seed 003's Mertsalov legend to −1060,509 Дж.
#[test]
fn plot_numbers_print_the_minus_sign() {
    fn signs(text: &str) -> (usize, Vec<String>) {
        let chars: Vec<char> = text.chars().collect();
        let (mut minus, mut hyphens) = (0, Vec::new());
        for (i, &c) in chars.iter().enumerate() {
            let digit = chars.get(i + 1).is_some_and(char::is_ascii_digit);
            let opens = i == 0 || matches!(chars[i - 1], ' ' | '(' | '[' | '=' | ';' | ':');
            if digit && opens && c == '\u{2212}' {
                minus += 1;
            }
            if digit && opens && c == '-' {
                hyphens.push(text.to_string());
            }
        }
        (minus, hyphens)
    }
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut tasks = vec![("default".to_string(), DEFAULT_TASK.to_string())];
    for dir in [root.clone(), root.join("textbook")] {
        let mut files: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "toml"))
            .collect();
        files.sort();
        for f in files {
            tasks.push((f.display().to_string(), std::fs::read_to_string(&f).unwrap()));
        }
    }
    let jobs: Vec<(&str, &str, Language)> = tasks
        .iter()
        .flat_map(|(n, t)| [Language::Ru, Language::Uk, Language::En].map(|l| (n.as_str(), t.as_str(), l)))
        .collect();
    let results: Vec<(usize, usize, Vec<String>, bool)> = std::thread::scope(|s| {
        let handles: Vec<_> = jobs
            .chunks(jobs.len().div_ceil(2))
            .map(|chunk| {
                s.spawn(move || {
                    chunk
                        .iter()
                        .map(|(name, text, lang)| {
                            let t = TaskSource::new(*name, *text).with_lang(*lang);
                            let mut docs = vec![tmm_report::run::run_task_in(&t, Some(*lang)).unwrap().docs];
                            if *name == "default" {
                                docs.push(note_figures(&t, Some(*lang)).unwrap());
                            }
                            let (mut minus, mut texts, mut bad) = (0, 0, Vec::new());
                            let mut mertsalov = false;
                            for d in &docs {
                                for doc in d.iter().filter(|x| x.path.ends_with(".svg") && !x.path.starts_with("sheets/")) {
                                    let Some(pic) = d.picture(&doc.path) else { continue };
                                    for b in crate::label_ink::texts(pic) {
                                        texts += 1;
                                        let (m, h) = signs(&b.text);
                                        minus += m;
                                        if name.ends_with("seed-003-sixbar.toml") && b.text.contains("\u{2212}1060,509") {
                                            mertsalov = true;
                                        }
                                        bad.extend(h.into_iter().map(|h| format!("{name} {lang:?} {}: \"{h}\"", doc.path)));
                                    }
                                }
                            }
                            (minus, texts, bad, mertsalov)
                        })
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        handles.into_iter().flat_map(|h| h.join().unwrap()).collect()
    });
    let minus: usize = results.iter().map(|r| r.0).sum();
    let texts: usize = results.iter().map(|r| r.1).sum();
    let bad: Vec<&String> = results.iter().flat_map(|r| &r.2).collect();
    println!("{} runs, {texts} texts, {minus} negative numbers with −", results.len());
    assert!(
        bad.is_empty(),
        "{} hyphens as a sign:\n{}",
        bad.len(),
        bad.iter().map(|s| s.as_str()).collect::<Vec<_>>().join("\n")
    );
    assert!(minus >= 1000, "the drawings' negative numbers were found: {minus}");
    assert!(results.iter().any(|r| r.3), "seed 003's Mertsalov legend prints −1060,509");
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

/// The П2 engine's drawings in ru, uk and en, each on the A1 sheet and on
/// the note's page: (language, "A1" or "A4", the run's documents).
fn engine_drawings() -> Vec<(Language, &'static str, tmm_report::output::Documents)> {
    let text = examples::text("textbook/p2-engine.toml");
    let mut out = Vec::new();
    for lang in [Language::Ru, Language::Uk, Language::En] {
        let t = TaskSource::new("textbook/p2-engine.toml", text.clone()).with_lang(lang);
        out.push((lang, "A1", run_task(&t).unwrap().docs));
        out.push((lang, "A4", note_figures(&t, None).unwrap()));
    }
    out
}

/// The scheme in 12 positions keeps its scale line clear: no link number
/// or other label prints into "М 1:4, μ_l = 0,004 м/мм" (the engine's short
/// crank once put its number 1 between "1:4," and "μ_l" on the note's
/// page), on the A1 sheet and the note's page, in ru, uk and en.
#[test]
fn positions_scheme_labels_keep_off_the_scale_line() {
    let mut bad = Vec::new();
    for (lang, what, docs) in engine_drawings() {
        let pic = docs.picture("linkage/positions.svg").unwrap();
        let all = crate::label_ink::texts(pic);
        let scale: Vec<_> = all.iter().filter(|b| b.text.contains("μ")).collect();
        assert_eq!(scale.len(), 1, "{lang:?} {what}: one scale line among {all:?}");
        for b in all.iter().filter(|b| !b.text.contains("μ")) {
            if b.gap(scale[0]) < 0.3 {
                bad.push(format!("{lang:?} {what}: «{}» on the scale line «{}»", b.text, scale[0].text));
            }
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

/// The structural scheme letters a slider on the fixed guide apart: the
/// frame's 0 beyond the guide's hatching, not in one row with the point's
/// letter and the slider's number ("3 B 0", "0 F 5" of the engine): the
/// nearest 0 to each slider's letter B, F lies at least 3 mm above or
/// below it, on the A1 sheet and the note's page, in ru, uk and en.
#[test]
fn structure_scheme_puts_the_guides_0_beyond_its_hatching() {
    let mut bad = Vec::new();
    for (lang, what, docs) in engine_drawings() {
        let pic = docs.picture("linkage/structure.svg").unwrap();
        let all = crate::label_ink::texts(pic);
        let centre = |b: &crate::label_ink::InkBox| (0.5 * (b.x0 + b.x1), 0.5 * (b.y0 + b.y1));
        let zeros: Vec<_> = all.iter().filter(|b| b.text == "0").map(centre).collect();
        assert!(zeros.len() >= 3, "{lang:?} {what}: the frame's 0 at O and at both guides");
        for letter in all.iter().filter(|b| b.text == "B" || b.text == "F") {
            let (x, y) = centre(letter);
            let near = zeros
                .iter()
                .min_by(|a, b| (a.0 - x).hypot(a.1 - y).total_cmp(&(b.0 - x).hypot(b.1 - y)))
                .unwrap();
            if (near.1 - y).abs() < 3.0 {
                bad.push(format!(
                    "{lang:?} {what}: 0 in one row with {} ({near:?} by ({x}, {y}))",
                    letter.text
                ));
            }
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
