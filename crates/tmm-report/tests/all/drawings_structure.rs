//! The structural scheme (`linkage/structure.svg`) read back: every link
//! numbered (the frame 0), every pair lettered, each Assur group titled
//! with its class and order, no two texts overlapping, no letter under
//! 2.5 mm, the paper within the drawing's slot on A1 and A2 — for the
//! default project, the six-bar of seed 003 and the synthesised six-bar.

use crate::svg_read::{attr, num, paper, run_example, texts};
use tmm_report::TaskSource;
use tmm_report::paper::{Slot, slot_mm};
use tmm_report::project::SheetFormat;
use tmm_report::run::{DEFAULT_TASK, Run, run_task};

fn runs(sheet: &str, lang: &str) -> Vec<(String, Run)> {
    // the default project with the sheet and the language asked
    let default = DEFAULT_TASK.replacen("lang = \"ru\"", &format!("lang = \"{lang}\""), 1).replacen(
        "sheet = \"A1\"",
        &format!("sheet = \"{sheet}\""),
        1,
    );
    let mut v = vec![("default".to_string(), run_task(&TaskSource::new("default", default)).unwrap())];
    for name in ["seed-003-sixbar.toml", "synth-seed-003-six-bar.toml"] {
        v.push((name.to_string(), run_example(name, sheet, lang)));
    }
    v
}

fn overlap(a: &[f64; 4], b: &[f64; 4]) -> bool {
    a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]
}

#[test]
fn links_numbered_pairs_lettered_groups_titled_labels_apart_inside_the_slot() {
    for (sheet, format) in [("A1", SheetFormat::A1), ("A2", SheetFormat::A2)] {
        for lang in ["ru", "en"] {
            for (name, run) in runs(sheet, lang) {
                let svg = run
                    .docs
                    .get("linkage/structure.svg")
                    .unwrap_or_else(|| panic!("{name}: linkage/structure.svg"))
                    .as_text()
                    .unwrap();
                let (w, h, _) = paper(svg);
                let (sw, sh) = slot_mm(Slot::Diagram, format);
                assert!(w <= sw + 1e-9 && h <= sh + 1e-9, "{name} {sheet}: {w}×{h} in {sw}×{sh}");
                let t = texts(svg, false);
                let shown: Vec<&str> = t.iter().map(|x| x.0.as_str()).collect();
                // the structure as the report gives it, independently of the drawing
                let st = run
                    .report
                    .pointer("/linkage/structure")
                    .unwrap_or_else(|| panic!("{name}: structure"));
                let n = st["n"].as_u64().unwrap();
                for k in 0..=n {
                    assert!(
                        shown.contains(&k.to_string().as_str()),
                        "{name} {sheet}: link {k} not numbered in {shown:?}"
                    );
                }
                for p in st["pairs"].as_array().unwrap() {
                    let letter = p["point"].as_str().unwrap();
                    // a name with an index is shown without its underscore (O1 → O1)
                    assert!(shown.contains(&letter), "{name} {sheet}: pair {letter} not lettered in {shown:?}");
                }
                let (class, order) = if lang == "ru" {
                    ("класс", "порядок")
                } else {
                    ("class", "order")
                };
                for g in st["groups"].as_array().unwrap() {
                    let links: Vec<&str> = g["links"].as_array().unwrap().iter().map(|x| x.as_str().unwrap()).collect();
                    let roman = ["", "I", "II", "III", "IV"][g["class"].as_u64().unwrap() as usize];
                    let head = format!("{roman}({})", links.join(", "));
                    let sub = format!("{class} {roman}, {order} {}", g["order"]);
                    assert!(shown.iter().any(|s| s.starts_with(&head)), "{name}: {head} in {shown:?}");
                    assert!(shown.contains(&sub.as_str()), "{name}: {sub} in {shown:?}");
                }
                for i in 0..t.len() {
                    for j in i + 1..t.len() {
                        assert!(
                            !overlap(&t[i].1, &t[j].1),
                            "{name} {sheet} {lang}: \"{}\" and \"{}\" overlap",
                            t[i].0,
                            t[j].0
                        );
                    }
                    let b = t[i].1;
                    assert!(
                        b[0] >= 0.0 && b[1] >= 0.0 && b[2] <= w && b[3] <= h,
                        "{name} {sheet}: \"{}\" {b:?} leaves the paper {w}×{h}",
                        t[i].0
                    );
                }
                for l in svg.lines().filter(|l| l.starts_with("<text")) {
                    let size = num(l, "font-size");
                    assert!(size >= 2.5 - 1e-9, "{name} {sheet}: letters of {size} mm in {l}");
                }
                assert!(attr(svg.lines().find(|l| l.starts_with("<svg")).unwrap(), "data-mu-l").is_some());
            }
        }
    }
}
