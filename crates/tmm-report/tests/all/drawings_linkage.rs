//! The lever mechanism's drawings read back as a teacher checks them: the
//! scheme at a GOST 2.302 scale whose links measure length × scale, plan
//! arrows of |v|/μ at a round μ, labels clear of each other and of the lines
//! of the plans and of the synthesis constructions, everything inside the
//! paper, the paper within its slot on A1 and A2, no English word on a
//! Russian drawing.

use std::path::Path;

use tmm_report::TaskSource;

use crate::svg_read::{attr, num, paper, texts};
use tmm_report::linkage::{analyse, drawings, json_document, load};
use tmm_report::paper::{STANDARD_SCALES, Slot, slot_mm};
use tmm_report::project::{Language, SheetFormat};

fn tasks() -> Vec<(String, String)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut v = vec![("default".to_string(), tmm_report::run::DEFAULT_TASK.to_string())];
    for name in ["seed-003-sixbar.toml", "crank-slider-offset.toml"] {
        v.push((name.to_string(), std::fs::read_to_string(dir.join(name)).unwrap()));
    }
    v
}

/// Straight segments of the `<line>` elements and polylines.
fn segments(svg: &str) -> Vec<[f64; 4]> {
    let mut out = Vec::new();
    for l in svg.lines() {
        if l.starts_with("<line") {
            out.push([num(l, "x1"), num(l, "y1"), num(l, "x2"), num(l, "y2")]);
        } else if l.starts_with("<polyline") {
            let pts: Vec<(f64, f64)> = attr(l, "points")
                .unwrap()
                .split_whitespace()
                .map(|p| {
                    let (a, b) = p.split_once(',').unwrap();
                    (a.parse().unwrap(), b.parse().unwrap())
                })
                .collect();
            for w in pts.windows(2) {
                out.push([w[0].0, w[0].1, w[1].0, w[1].1]);
            }
        }
    }
    out
}

fn overlap(a: &[f64; 4], b: &[f64; 4]) -> bool {
    a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]
}

/// Whether a segment passes through a box: sampled every 0.05 mm.
fn crosses(s: &[f64; 4], b: &[f64; 4]) -> bool {
    let len = ((s[2] - s[0]).powi(2) + (s[3] - s[1]).powi(2)).sqrt();
    let n = (len / 0.05).ceil().max(1.0) as usize;
    (0..=n).any(|i| {
        let t = i as f64 / n as f64;
        let (x, y) = (s[0] + t * (s[2] - s[0]), s[1] + t * (s[3] - s[1]));
        x > b[0] + 1e-6 && x < b[2] - 1e-6 && y > b[1] + 1e-6 && y < b[3] - 1e-6
    })
}

fn slot_of(file: &str) -> Slot {
    if file == "positions.svg" {
        Slot::Scheme
    } else if file.contains("plan") {
        Slot::Plan
    } else {
        Slot::Diagram
    }
}

fn run(name: &str, text: &str, lang: Language, sheet: SheetFormat) -> (tmm_report::output::Documents, serde_json::Value, f64, f64) {
    let task = TaskSource::new(name, text).with_lang(lang).with_sheet(sheet);
    let l = load(&task).unwrap().unwrap();
    let a = analyse(&l, &task, None, l.task.positions).unwrap();
    let docs = drawings(&l, &a, &task, true).unwrap();
    let json = json_document(&l, &a);
    (docs, json, l.mech.crank.omega.abs(), l.mech.crank.radius)
}

#[test]
fn every_drawing_fits_its_slot_and_keeps_inside_its_paper() {
    for (name, text) in tasks() {
        for sheet in [SheetFormat::A1, SheetFormat::A2] {
            let (docs, ..) = run(&name, &text, Language::Ru, sheet);
            assert!(docs.iter().count() >= 8 + 2 * 12, "{name}: the plans of every position");
            for d in docs.iter() {
                let svg = d.as_text().unwrap();
                let (w, h, _) = paper(svg);
                let (sw, sh) = slot_mm(slot_of(&d.path), sheet);
                assert!(w <= sw + 1e-9 && h <= sh + 1e-9, "{name} {}: {w}×{h} in {sw}×{sh}", d.path);
                for (t, b) in texts(svg, false) {
                    assert!(
                        b[0] >= 0.0 && b[1] >= 0.0 && b[2] <= w && b[3] <= h,
                        "{name} {}: \"{t}\" {b:?} leaves the paper {w}×{h}",
                        d.path
                    );
                }
                for s in segments(svg) {
                    for (x, y) in [(s[0], s[1]), (s[2], s[3])] {
                        assert!(
                            (-1e-6..=w + 1e-6).contains(&x) && (-1e-6..=h + 1e-6).contains(&y),
                            "{name} {}: a line at ({x}, {y}) outside {w}×{h}",
                            d.path
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn labels_do_not_collide() {
    for (name, text) in tasks() {
        let (docs, ..) = run(&name, &text, Language::Ru, SheetFormat::A1);
        for d in docs.iter() {
            let svg = d.as_text().unwrap();
            let t = texts(svg, false);
            for i in 0..t.len() {
                for j in i + 1..t.len() {
                    assert!(
                        !overlap(&t[i].1, &t[j].1),
                        "{name} {}: \"{}\" and \"{}\" overlap",
                        d.path,
                        t[i].0,
                        t[j].0
                    );
                }
            }
            // on the plans, no label lies on a line
            if d.path.contains("plan") {
                let segs = segments(svg);
                for (txt, b) in &t {
                    for s in &segs {
                        assert!(!crosses(s, b), "{name} {}: \"{txt}\" {b:?} on the line {s:?}", d.path);
                    }
                }
            }
        }
    }
}

#[test]
fn plan_arrows_measure_the_velocity_over_the_round_scale_factor() {
    for (name, text) in tasks() {
        let (docs, json, omega, radius) = run(&name, &text, Language::Ru, SheetFormat::A1);
        for (file, key) in [("velocity-plan.svg", "velocity"), ("acceleration-plan.svg", "acceleration")] {
            let svg = docs.get(file).unwrap().as_text().unwrap();
            let (_, _, root) = paper(svg);
            let mu: f64 = attr(&root, "data-mu").unwrap().parse().unwrap();
            // round: 1, 2, 2.5, 4, 5 × 10^k, and written on the drawing with a decimal comma
            let m = mu / 10f64.powf(mu.log10().floor());
            assert!(
                [1.0, 2.0, 2.5, 4.0, 5.0].iter().any(|r| (m - r).abs() < 1e-9),
                "{name} {file}: μ = {mu}"
            );
            let printed = format!("{mu}").replace('.', ",");
            assert!(svg.contains(&printed), "{name} {file}: μ {printed} not written");
            let lines: Vec<&str> = svg.lines().collect();
            let mut checked = 0;
            for v in json["plans"][key].as_array().unwrap() {
                let label = v["label"].as_str().unwrap();
                let (f, t) = (&v["from"], &v["to"]);
                let len = ((t[0].as_f64().unwrap() - f[0].as_f64().unwrap()).powi(2)
                    + (t[1].as_f64().unwrap() - f[1].as_f64().unwrap()).powi(2))
                .sqrt();
                let Some(i) = lines.iter().position(|l| l.contains(&format!("data-label=\"{label}\""))) else {
                    assert!(len / mu < 0.05, "{name} {file}: {label} of {len} not drawn");
                    continue;
                };
                let l = lines[i + 1];
                let drawn = ((num(l, "x2") - num(l, "x1")).powi(2) + (num(l, "y2") - num(l, "y1")).powi(2)).sqrt();
                assert!((drawn - len / mu).abs() < 0.01, "{name} {file}: {label} {drawn} mm vs {}", len / mu);
                checked += 1;
            }
            assert!(checked >= 3, "{name} {file}");
        }
        // the crank pin's velocity, independently: ω1·l1
        let svg = docs.get("velocity-plan.svg").unwrap().as_text().unwrap();
        let mu: f64 = attr(&paper(svg).2, "data-mu").unwrap().parse().unwrap();
        let lens: Vec<f64> = svg
            .lines()
            .collect::<Vec<_>>()
            .windows(2)
            .filter(|w| w[0].contains("data-kind=\"Absolute\""))
            .map(|w| ((num(w[1], "x2") - num(w[1], "x1")).powi(2) + (num(w[1], "y2") - num(w[1], "y1")).powi(2)).sqrt())
            .collect();
        let want = omega * radius / mu;
        assert!(
            lens.iter().any(|l| (l - want).abs() < 0.01),
            "{name}: no arrow of ω1·l1/μ = {want} mm among {lens:?}"
        );
    }
}

#[test]
fn the_scheme_is_at_a_standard_scale_and_its_links_measure_length_times_scale() {
    for (name, text) in tasks() {
        for sheet in [SheetFormat::A1, SheetFormat::A2] {
            let task = TaskSource::new(&name, text.clone()).with_sheet(sheet);
            let l = load(&task).unwrap().unwrap();
            let (docs, ..) = run(&name, &text, Language::Ru, sheet);
            let svg = docs.get("positions.svg").unwrap().as_text().unwrap();
            let scale = attr(&paper(svg).2, "data-scale").unwrap();
            let &(factor, _) = STANDARD_SCALES
                .iter()
                .find(|s| s.1 == scale)
                .unwrap_or_else(|| panic!("{name}: {scale} is not a GOST 2.302 scale"));
            assert!(svg.contains(&scale), "{name}: the scale is written");
            // the bold position's links
            let bold = &svg[svg.find("<g id=\"bold-position\">").unwrap()..];
            let bold = &bold[..bold.find("</g>").unwrap()];
            let lens: Vec<f64> = bold
                .lines()
                .filter(|l| l.starts_with("<line") && l.contains("stroke-width=\"0.700\""))
                .map(|l| ((num(l, "x2") - num(l, "x1")).powi(2) + (num(l, "y2") - num(l, "y1")).powi(2)).sqrt())
                .collect();
            for link in l.def.links.iter().filter(|k| k.points.len() >= 2) {
                let (a, b) = (link.points[0].1, link.points[1].1);
                let want = (b - a).hypot() * 1e3 * factor;
                assert!(
                    lens.iter().any(|x| (x - want).abs() < 0.01),
                    "{name} {sheet:?}: link {} of {want} mm at {scale} not among {lens:?}",
                    link.name
                );
            }
        }
    }
}

#[test]
fn russian_drawings_have_no_english_words_and_use_the_decimal_comma() {
    for (name, text) in tasks() {
        let (docs, ..) = run(&name, &text, Language::Ru, SheetFormat::A1);
        for d in docs.iter() {
            for (t, _) in texts(d.as_text().unwrap(), false) {
                // Latin letters are the points' and quantities' names (B, CB, s, v):
                // a run of three lower-case Latin letters is a word
                let mut run = 0;
                for ch in t.chars() {
                    run = if ch.is_ascii_lowercase() { run + 1 } else { 0 };
                    assert!(run < 3, "{name} {}: English in \"{t}\"", d.path);
                }
                let b = t.as_bytes();
                for i in 1..b.len().saturating_sub(1) {
                    assert!(
                        !(b[i] == b'.' && b[i - 1].is_ascii_digit() && b[i + 1].is_ascii_digit()),
                        "{name} {}: a decimal point in \"{t}\"",
                        d.path
                    );
                }
            }
        }
        let (docs, ..) = run(&name, &text, Language::En, SheetFormat::A1);
        let svg = docs.get("velocity-plan.svg").unwrap().as_text().unwrap();
        assert!(svg.contains("Velocity plan"), "{name}: the English words come from en.toml");
    }
}

#[test]
fn force_plans_and_the_lever_fit_their_slot_with_labels_apart() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    for name in ["seed-001-fourbar.toml", "seed-003-sixbar.toml", "seed-004-two-sliders.toml"] {
        let text = std::fs::read_to_string(dir.join(name)).unwrap();
        for sheet in [SheetFormat::A1, SheetFormat::A2] {
            let task = TaskSource::new(name, text.clone()).with_sheet(sheet);
            let (l, t) = tmm_report::forces::load(&task).unwrap().unwrap();
            let a = tmm_report::forces::analyse(&task, &l, &t, None).unwrap();
            let docs = tmm_report::forces::drawings(&l, &t, &a, &task).unwrap();
            for d in docs
                .iter()
                .filter(|d| d.path.starts_with("group-") || d.path == "input-link.svg" || d.path == "zhukovsky-lever.svg")
            {
                let svg = d.as_text().unwrap();
                let (w, h, root) = paper(svg);
                let (sw, sh) = slot_mm(Slot::Plan, sheet);
                assert!(w <= sw && h <= sh, "{name} {}: {w}×{h}", d.path);
                let mu: f64 = attr(&root, "data-mu-f")
                    .or_else(|| attr(&root, "data-mu"))
                    .unwrap()
                    .parse()
                    .unwrap();
                let m = mu / 10f64.powf(mu.log10().floor());
                assert!([1.0, 2.0, 2.5, 4.0, 5.0].iter().any(|r| (m - r).abs() < 1e-9), "{name}: μ = {mu}");
                // the lever's labels (its forces numbered "(k) …") are
                // checked by their printed ink, on the paper and apart, in
                // lever_drawing.rs; these boxes of 0.6 em a character
                // overstate them
                if d.path == "zhukovsky-lever.svg" {
                    continue;
                }
                let tx = texts(svg, false);
                for (s, b) in &tx {
                    assert!(
                        b[0] >= 0.0 && b[1] >= 0.0 && b[2] <= w && b[3] <= h,
                        "{name} {}: \"{s}\" outside",
                        d.path
                    );
                }
                for i in 0..tx.len() {
                    for j in i + 1..tx.len() {
                        assert!(
                            !overlap(&tx[i].1, &tx[j].1),
                            "{name} {}: \"{}\" on \"{}\"",
                            d.path,
                            tx[i].0,
                            tx[j].0
                        );
                    }
                }
            }
        }
    }
}

/// The balancing torque over the cycle: the curve by kinetostatics and
/// Zhukovsky's lever as circles at the positions. Each circle sits on the
/// curve (the two methods agree, so a circle off the curve is a misdrawn
/// point), the φ axis runs over one turn (0 … 360°, the positions 0 … 12,
/// not to 400°) and the scale factors are written.
#[test]
fn balancing_torque_circles_sit_on_the_curve() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let text = std::fs::read_to_string(dir.join("seed-001-fourbar.toml")).unwrap();
    let run = tmm_report::run::run_task(&TaskSource::new("seed-001-fourbar.toml", text)).unwrap();
    let svg = run
        .docs
        .iter()
        .find(|d| d.path == "forces/balancing-torque.svg")
        .and_then(|d| d.as_text())
        .unwrap()
        .to_string();
    // the curve's vertices
    let path = svg.lines().find(|l| l.contains("class=\"curve\"")).unwrap();
    let d = attr(path, "d").unwrap();
    let pts: Vec<(f64, f64)> = d
        .split(['M', 'L'])
        .filter_map(|p| {
            let (x, y) = p.trim().split_once(',')?;
            Some((x.parse().ok()?, y.parse().ok()?))
        })
        .collect();
    // a curve, not the positions joined: the vertices Douglas–Peucker keeps
    // at 0.01 mm (tmm_draw::simplify) of the densely sampled cycle
    assert!(pts.len() > 24, "{} vertices", pts.len());
    let (x0, x1) = (pts[0].0, pts[pts.len() - 1].0);
    let dots: Vec<(f64, f64)> = svg
        .lines()
        .filter(|l| l.contains("class=\"dot\""))
        .map(|l| (num(l, "cx"), num(l, "cy")))
        .collect();
    // 12 positions, the extreme one and position 12 (= 0 a turn later)
    assert!(dots.len() >= 13, "{} circles", dots.len());
    for &(cx, cy) in &dots {
        let k = pts.windows(2).position(|w| w[0].0 <= cx && cx <= w[1].0).unwrap();
        let (a, b) = (pts[k], pts[k + 1]);
        let t = if b.0 > a.0 { (cx - a.0) / (b.0 - a.0) } else { 0.0 };
        let y = a.1 + t * (b.1 - a.1);
        assert!((y - cy).abs() < 0.05, "circle at x {cx}: {cy} against the curve's {y}");
    }
    // one turn: the last position mark at the curve's end, 360° from its start
    let shown = texts(&svg, false);
    let twelve = shown.iter().find(|t| t.0 == "12").unwrap().1;
    assert!(
        (0.5 * (twelve[0] + twelve[2]) - x1).abs() < 0.5,
        "12 at {twelve:?}, the curve ends at {x1}"
    );
    let zero = shown.iter().find(|t| t.0 == "0").unwrap().1;
    assert!(
        (0.5 * (zero[0] + zero[2]) - x0).abs() < 0.5,
        "0 at {zero:?}, the curve starts at {x0}"
    );
    assert!(
        shown.iter().any(|t| t.0.starts_with("μM = ") && t.0.contains("μφ = ")),
        "no scale factors"
    );
}

/// The edges of the `<polygon>`s (ground symbols, arrowheads), closed.
fn polygon_segments(svg: &str) -> Vec<[f64; 4]> {
    let mut out = Vec::new();
    for l in svg.lines().filter(|l| l.starts_with("<polygon")) {
        let pts: Vec<(f64, f64)> = attr(l, "points")
            .unwrap()
            .split_whitespace()
            .map(|p| {
                let (a, b) = p.split_once(',').unwrap();
                (a.parse().unwrap(), b.parse().unwrap())
            })
            .collect();
        for i in 0..pts.len() {
            let (a, b) = (pts[i], pts[(i + 1) % pts.len()]);
            out.push([a.0, a.1, b.0, b.1]);
        }
    }
    out
}

#[test]
fn synthesis_constructions_keep_their_labels_off_the_lines() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.file_name().unwrap().to_string_lossy().starts_with("synth-"))
        .collect();
    files.sort();
    assert!(files.len() >= 5, "{files:?}");
    let mut tasks: Vec<(String, String)> = files
        .iter()
        .map(|p| {
            (
                p.file_name().unwrap().to_string_lossy().into_owned(),
                std::fs::read_to_string(p).unwrap(),
            )
        })
        .collect();
    tasks.push(("default".to_string(), tmm_report::run::DEFAULT_TASK.to_string()));
    for (name, text) in tasks {
        for (sheet, lang) in [("A1", Language::Ru), ("A2", Language::Uk), ("A1", Language::En)] {
            let text = if text.contains("[project]") {
                text.replace("sheet = \"A1\"", &format!("sheet = \"{sheet}\""))
            } else {
                format!("{text}\n[project]\nsheet = \"{sheet}\"\n")
            };
            let run = tmm_report::run::run_task_in(&TaskSource::new(&name, text), Some(lang)).unwrap_or_else(|e| panic!("{name}: {e}"));
            let Some(doc) = run.docs.get("synthesis/construction.svg") else {
                panic!("{name}: no construction drawing");
            };
            let svg = doc.as_text().unwrap();
            let (w, h, _) = paper(svg);
            let mut segs = segments(svg);
            segs.extend(polygon_segments(svg));
            assert!(segs.len() > 10, "{name}: {} segments", segs.len());
            let t = texts(svg, false);
            assert!(t.len() >= 5, "{name}: {} texts", t.len());
            for (i, (txt, b)) in t.iter().enumerate() {
                assert!(
                    b[0] >= 0.0 && b[1] >= 0.0 && b[2] <= w && b[3] <= h,
                    "{name} {sheet} {lang:?}: «{txt}» {b:?} leaves the paper"
                );
                for (txt2, b2) in &t[..i] {
                    assert!(!overlap(b, b2), "{name} {sheet} {lang:?}: «{txt}» on «{txt2}»");
                }
                for s in &segs {
                    assert!(!crosses(s, b), "{name} {sheet} {lang:?}: «{txt}» {b:?} on the line {s:?}");
                }
            }
        }
    }
}

/// The position numbers of the scheme (the crank's 0 … 11 and the marked
/// ones, 6′): the texts of digits (and a prime) at the size most of them
/// share (the links' numbers are larger), with their boxes.
fn position_numbers(svg: &str) -> Vec<(String, [f64; 4])> {
    let is_number = |t: &str| {
        let t = t.trim_end_matches(['\'', '′']);
        !t.is_empty() && t.chars().all(|c| c.is_ascii_digit())
    };
    let sized: Vec<(String, [f64; 4], f64)> = texts(svg, false)
        .into_iter()
        .filter(|(t, _)| is_number(t))
        .map(|(t, b)| {
            let h = b[3] - b[1];
            (t, b, h)
        })
        .collect();
    let mut sizes: Vec<f64> = sized.iter().map(|s| (s.2 * 1000.0).round()).collect();
    sizes.sort_by(f64::total_cmp);
    let common = sizes
        .iter()
        .max_by_key(|s| sizes.iter().filter(|t| t == s).count())
        .copied()
        .unwrap_or(0.0);
    sized
        .into_iter()
        .filter(|s| (s.2 * 1000.0).round() == common)
        .map(|(t, b, _)| (t, b))
        .collect()
}

/// On the scheme of the positions, as the note prints it (A4) and as the
/// sheet does (A1): every position has its number, no two numbers' boxes
/// come within 1 mm (`svg::NUMBER_GAP`) and no line of the scheme (a crank, a rod, a rocker, a frame
/// mark) passes through a number.
#[test]
fn position_numbers_keep_apart_and_off_the_links() {
    for (name, text) in tasks() {
        for sheet in [SheetFormat::A4, SheetFormat::A1] {
            let task = TaskSource::new(&name, &text).with_lang(Language::Ru).with_sheet(sheet);
            let l = load(&task).unwrap().unwrap();
            let a = analyse(&l, &task, None, l.task.positions).unwrap();
            let docs = drawings(&l, &a, &task, true).unwrap();
            let svg = docs.get("positions.svg").and_then(|d| d.as_text()).unwrap();
            let nums = position_numbers(svg);
            assert!(
                nums.len() >= a.rows.len(),
                "{name} {sheet:?}: {} numbers for {} positions",
                nums.len(),
                a.rows.len()
            );
            let segs = segments(svg);
            let mut worst = f64::MAX;
            for (i, (t, b)) in nums.iter().enumerate() {
                for (t2, b2) in &nums[i + 1..] {
                    assert!(!overlap(b, b2), "{name} {sheet:?}: the numbers {t} {b:?} and {t2} {b2:?} overlap");
                }
                for s in &segs {
                    assert!(!crosses(s, b), "{name} {sheet:?}: the number {t} {b:?} lies on the line {s:?}");
                }
                for (_, b2) in nums.iter().filter(|(t2, _)| t2 != t) {
                    let gap = (b2[0] - b[2]).max(b[0] - b2[2]).max((b2[1] - b[3]).max(b[1] - b2[3]));
                    worst = worst.min(gap);
                }
            }
            eprintln!(
                "{name} {sheet:?}: {} position numbers, the nearest two {worst:.2} mm apart",
                nums.len()
            );
            assert!(
                worst >= tmm_report::svg::NUMBER_GAP - 1e-6,
                "{name} {sheet:?}: two position numbers {worst:.2} mm apart"
            );
        }
    }
}
