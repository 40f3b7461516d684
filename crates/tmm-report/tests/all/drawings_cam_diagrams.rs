//! The cam's motion and sizing diagrams read back from the drawn SVG and
//! checked against independent numbers: the slots of the A1 and A2 sheets,
//! the JSON report's stroke and largest velocity analogue over the round
//! scale factor μ written on the drawing, the phase boundaries of the task at
//! μ_φ, the language of the words and the decimal comma, labels clear of
//! each other.

use serde_json::Value;

use crate::svg_read::{attr_s, paper, run_example as run, shown};
use tmm_report::paper::{Slot, slot_mm};
use tmm_report::project::SheetFormat;
use tmm_report::run::Run;
use tmm_testkit::svg::num;

const FILES: [&str; 4] = ["cam-analogs.svg", "cam-motion.svg", "cam-pressure.svg", "cam-sizing.svg"];
const EXAMPLES: [&str; 3] = ["cam-seed-001-roller.toml", "cam-seed-001-flat.toml", "cam-oscillating-roller.toml"];

fn svg<'a>(r: &'a Run, file: &str) -> &'a str {
    let path = format!("cam/{file}");
    r.docs.get(&path).unwrap_or_else(|| panic!("{path}")).as_text().unwrap()
}

fn json(r: &Run) -> Value {
    serde_json::from_str(r.docs.get("cam/cam.json").unwrap().as_text().unwrap()).unwrap()
}

/// The elements starting with `tag` (`<g class="diagram"`), each up to its `>`.
fn elements<'a>(s: &'a str, tag: &str) -> Vec<&'a str> {
    s.match_indices(tag).map(|(i, _)| &s[i..i + s[i..].find('>').unwrap()]).collect()
}

/// The panels: (the `<g class="diagram">` element, the curve's points).
fn panels(s: &str) -> Vec<(&str, Vec<(f64, f64)>)> {
    let gs: Vec<usize> = s.match_indices("<g class=\"diagram\"").map(|(i, _)| i).collect();
    gs.iter()
        .enumerate()
        .map(|(k, &i)| {
            let end = gs.get(k + 1).copied().unwrap_or(s.len());
            let body = &s[i..end];
            let g = &body[..body.find('>').unwrap()];
            let path = elements(body, "<path class=\"curve\"")[0];
            let d = attr_s(path, "d").unwrap();
            let pts = d
                .split_whitespace()
                .map(|t| {
                    let (x, y) = t[1..].split_once(',').unwrap();
                    (x.parse().unwrap(), y.parse().unwrap())
                })
                .collect();
            (g, pts)
        })
        .collect()
}

/// The texts' visible words.
fn texts(s: &str) -> Vec<String> {
    s.match_indices("<text")
        .map(|(i, _)| {
            let inner = &s[i..i + s[i..].find("</text>").unwrap()];
            // the first '>' closes the opening tag
            shown(&inner[inner.find('>').unwrap() + 1..])
        })
        .collect()
}

#[test]
fn every_diagram_fits_its_slot_on_a1_and_a2() {
    for sheet in ["A1", "A2"] {
        let f = if sheet == "A1" { SheetFormat::A1 } else { SheetFormat::A2 };
        let (dw, dh) = slot_mm(Slot::Diagram, f);
        let (pw, ph) = slot_mm(Slot::Plan, f);
        for ex in EXAMPLES {
            let r = run(ex, sheet, "ru");
            for file in FILES {
                let s = svg(&r, file);
                let (w, h, _) = paper(s);
                if file == "cam-sizing.svg" {
                    assert!(w <= pw + 1e-9 && h <= ph + 1e-9, "{ex} {sheet} {file}: {w}×{h}");
                } else {
                    let n = panels(s).len() as f64;
                    assert!(n >= 1.0, "{ex} {file}");
                    // each panel is one diagram slot
                    assert!(w <= dw + 1e-9 && h / n <= dh + 1e-9, "{ex} {sheet} {file}: {w}×{h}");
                }
            }
        }
    }
}

#[test]
fn stroke_and_velocity_analogue_are_drawn_at_their_round_scale() {
    for ex in ["cam-seed-001-roller.toml", "cam-seed-001-flat.toml"] {
        for sheet in ["A1", "A2"] {
            let r = run(ex, sheet, "en");
            let j = json(&r);
            let stroke_mm = j["stroke"].as_f64().unwrap() * 1e3;
            // the largest velocity analogue of the phases, mm
            let v_max = j["phases"]
                .as_array()
                .unwrap()
                .iter()
                .filter_map(|p| p["ds_dphi_max"].as_f64())
                .fold(0.0f64, |m, v| m.max(v.abs()))
                * 1e3;
            assert!(v_max > 0.0);
            let s = svg(&r, "cam-analogs.svg");
            let ps = panels(s);
            assert_eq!(ps.len(), 3);
            for (k, want) in [(0usize, stroke_mm), (1, v_max)] {
                let (g, pts) = &ps[k];
                let mu = num(g, "data-mu-y").unwrap();
                let yz = num(g, "data-y-zero").unwrap();
                let got = pts.iter().map(|p| (yz - p.1).abs()).fold(0.0f64, f64::max);
                assert!(
                    (got - want / mu).abs() < 0.05,
                    "{ex} {sheet} panel {k}: {got} vs {} (μ {mu})",
                    want / mu
                );
                // μ is round: 1, 2, 2.5, 4 or 5 × 10^k
                let m = mu / 10f64.powf(mu.log10().floor());
                assert!([1.0, 2.0, 2.5, 4.0, 5.0, 10.0].iter().any(|r| (m - r).abs() < 1e-9), "{mu}");
            }
            // the displacement over time: the same stroke
            let (g, pts) = &panels(svg(&r, "cam-motion.svg"))[0];
            let mu = num(g, "data-mu-y").unwrap();
            let yz = num(g, "data-y-zero").unwrap();
            let got = pts.iter().map(|p| yz - p.1).fold(0.0f64, f64::max);
            assert!((got - stroke_mm / mu).abs() < 0.05, "{ex} motion: {got}");
        }
    }
}

#[test]
fn phase_marks_stand_at_the_task_angles() {
    for sheet in ["A1", "A2"] {
        let r = run("cam-seed-001-roller.toml", sheet, "uk");
        // seed 001: rise 108, dwell 15, return 108, dwell 129 (the task file)
        let want = [0.0, 108.0, 123.0, 231.0, 360.0];
        for file in ["cam-analogs.svg", "cam-motion.svg", "cam-pressure.svg"] {
            let s = svg(&r, file);
            for (g, pts) in panels(s) {
                let mu_phi = num(g, "data-mu-phi").unwrap();
                let x0 = num(g, "data-x0").unwrap();
                // the curve spans exactly 0 … 360°
                let xmin = pts.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
                let xmax = pts.iter().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max);
                assert!((xmin - x0).abs() < 1e-3 && (xmax - (x0 + 360.0 / mu_phi)).abs() < 1e-3, "{file}");
            }
            let marks = elements(s, "<g class=\"phase-mark\"");
            let lines = elements(s, "<g class=\"phase-mark\"");
            assert_eq!(marks.len() % want.len(), 0, "{file}");
            for (i, m) in marks.iter().enumerate() {
                assert!((num(m, "data-phi").unwrap() - want[i % want.len()]).abs() < 1e-9, "{file} {m}");
            }
            // the mark's line at x0 + φ/μ_φ
            for (k, (g, _)) in panels(s).iter().enumerate() {
                let mu_phi = num(g, "data-mu-phi").unwrap();
                let x0 = num(g, "data-x0").unwrap();
                for (i, &phi) in want.iter().enumerate() {
                    let m = lines[k * want.len() + i];
                    let at = s.find(m).unwrap();
                    let line = elements(&s[at..], "<line")[0];
                    let x = num(line, "x1").unwrap();
                    assert!((x - (x0 + phi / mu_phi)).abs() < 1e-3, "{file} φ = {phi}: {x}");
                }
            }
        }
    }
}

#[test]
fn russian_diagrams_have_no_english_and_a_decimal_comma() {
    for ex in EXAMPLES {
        let r = run(ex, "A1", "ru");
        for file in FILES {
            let s = svg(&r, file);
            for t in texts(s) {
                // only the course's symbols may be Latin: s, ds/dφ, v, a, j, t, r_0, ρ_min, O, B_0, K, A
                let allowed = ["s", "d", "ds", "v", "a", "j", "t", "r", "min", "O", "B", "K", "A"];
                for w in t.split(|c: char| !c.is_ascii_alphabetic()).filter(|w| !w.is_empty()) {
                    assert!(allowed.contains(&w), "{ex} {file}: {w:?} in {t:?}");
                }
                let b = t.as_bytes();
                for i in 1..b.len().saturating_sub(1) {
                    assert!(
                        !(b[i] == b'.' && b[i - 1].is_ascii_digit() && b[i + 1].is_ascii_digit()),
                        "{ex} {file}: {t:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn labels_do_not_overlap() {
    for ex in EXAMPLES {
        for (sheet, lang) in [("A1", "ru"), ("A2", "uk"), ("A2", "en")] {
            let r = run(ex, sheet, lang);
            for file in ["cam-analogs.svg", "cam-motion.svg", "cam-pressure.svg"] {
                let s = svg(&r, file);
                let (w, h, _) = paper(s);
                let boxes: Vec<(f64, f64, f64, f64, &str)> = elements(s, "<text class=\"label\"")
                    .into_iter()
                    .map(|e| {
                        let (x, y, fs, n) = (
                            num(e, "x").unwrap(),
                            num(e, "y").unwrap(),
                            num(e, "font-size").unwrap(),
                            num(e, "data-chars").unwrap(),
                        );
                        // tmm's lettering box: 0.62 h per character, 1.2 h tall
                        let bw = 0.62 * fs * n;
                        let x0 = if attr_s(e, "text-anchor") == Some("start") {
                            x
                        } else {
                            x - 0.5 * bw
                        };
                        let yc = y - 0.35 * fs;
                        (x0, yc - 0.6 * fs, x0 + bw, yc + 0.6 * fs, e)
                    })
                    .collect();
                assert!(boxes.len() > 5);
                for (i, a) in boxes.iter().enumerate() {
                    assert!(a.0 >= 0.0 && a.1 >= 0.0 && a.2 <= w && a.3 <= h, "{ex} {file}: {}", a.4);
                    for b in &boxes[..i] {
                        let hit = a.0 < b.2 && b.0 < a.2 && a.1 < b.3 && b.1 < a.3;
                        assert!(!hit, "{ex} {sheet} {file}: {} / {}", a.4, b.4);
                    }
                }
            }
        }
    }
}
