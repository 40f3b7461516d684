//! The oscillating cylinder's note (the textbook's П1.5, variants 1–3) as
//! a teacher reads it: the kinematic analysis' conclusion names the
//! pressure angle that matters — the rod's force on the lever against the
//! velocity of the lever's point B — with its values over the lever's
//! working turn, not the analysed group's identically zero angle; the
//! synthesis' tables name every given and every unknown in words and
//! symbols, never by the task's keys (`h_min`, `rod`, `phi3_start`).

use tmm_note::{Block, Cell, Note, Section, Span, compose};
use tmm_report::TaskSource;
use tmm_report::project::Language;
use tmm_report::run::run_task_in;

use super::fixtures::{outside_math, section_blocks, task};

const VARIANTS: [&str; 3] = [
    "textbook/p1-5-oscillating-cylinder-v1.toml",
    "textbook/p1-5-oscillating-cylinder-v2.toml",
    "textbook/p1-5-oscillating-cylinder-v3.toml",
];

/// The words that open the conclusion's sentence on the pair's pressure angle.
fn pair_words(lang: Language) -> &'static str {
    match lang {
        Language::Ru => "в паре штока и рычага",
        Language::Uk => "в парі штока й важеля",
        Language::En => "rod–lever pair",
    }
}

/// A given of the task's `[synthesis]` in SI units: "50 mm" → 0.05, "60 deg"
/// → π/3 (the units the examples use).
fn given(task: &TaskSource, key: &str) -> Option<f64> {
    let table: toml::Table = task.text.parse().unwrap();
    let s = table.get("synthesis")?.get(key)?.as_str()?.to_string();
    let (v, unit) = s.split_once(' ')?;
    let v: f64 = v.parse().ok()?;
    Some(match unit {
        "mm" => v / 1000.0,
        "m" => v,
        "deg" => v.to_radians(),
        _ => return None,
    })
}

/// The text of a paragraph: its plain spans, the numbers as the note
/// prints them, a math span as written.
fn plain(t: &tmm_note::Text, lang: Language) -> String {
    let comma = lang != Language::En;
    t.0.iter()
        .map(|s| match s {
            Span::Plain(p) | Span::Strong(p) | Span::Emph(p) | Span::Math(p) => p.clone(),
            Span::Number { value, .. } => {
                let s = format!("{value}");
                if comma { s.replace('.', ",") } else { s }
            }
            _ => String::new(),
        })
        .collect()
}

fn paragraphs(s: &Section, lang: Language, out: &mut Vec<String>) {
    for b in section_blocks(s) {
        if let Block::Paragraph(t) = b {
            out.push(plain(t, lang));
        }
    }
}

/// The numbers before a degree sign in `s`, in order ("2,435°" → 2.435).
fn degrees(s: &str) -> Vec<f64> {
    let mut out = Vec::new();
    let chars: Vec<char> = s.chars().collect();
    for (i, c) in chars.iter().enumerate() {
        if *c != '°' {
            continue;
        }
        let mut j = i;
        while j > 0 && (chars[j - 1].is_ascii_digit() || chars[j - 1] == ',' || chars[j - 1] == '.') {
            j -= 1;
        }
        let n: String = chars[j..i].iter().collect::<String>().replace(',', ".");
        if let Ok(v) = n.parse() {
            out.push(v);
        }
    }
    out
}

/// The pressure angle of the rod on the lever by the triangle O–B–D, in
/// degrees: with |OB| = l, |OD| = d, |DB| = L the angle at B is
/// arccos((l² + L² − d²)/(2 l L)) (the law of cosines), and the pressure
/// angle — between DB and B's velocity, which is across OB — is its
/// difference from 90°.
fn pressure_by_triangle(l: f64, d: f64, big_l: f64) -> f64 {
    let at_b = ((l * l + big_l * big_l - d * d) / (2.0 * l * big_l)).clamp(-1.0, 1.0).acos();
    (90.0 - at_b.to_degrees()).abs()
}

/// The pressure angle over the lever's turn from the task's givens and the
/// synthesised |OB|, |OD|: L runs from h_min + l_шт to h_max + l_шт; the
/// angle ∠BOD at the start by the law of cosines, then turned by β towards
/// the end position (whose |DB| must come out as h_max + l_шт — checked).
/// Returns (start, end, largest) in degrees.
fn pressure_over_turn(task: &TaskSource, l: f64, d: f64) -> (f64, f64, f64) {
    let rod = given(task, "rod").unwrap();
    let (ln, lk) = (given(task, "h_min").unwrap() + rod, given(task, "h_max").unwrap() + rod);
    let beta = given(task, "swing").unwrap();
    let alpha_n = ((l * l + d * d - ln * ln) / (2.0 * l * d)).clamp(-1.0, 1.0).acos();
    // the lever turns by β with |DB| growing: ∠BOD grows (or, past π, wraps)
    let len = |alpha: f64| (l * l + d * d - 2.0 * l * d * alpha.cos()).sqrt();
    let sense = if (len(alpha_n + beta) - lk).abs() < (len(alpha_n - beta) - lk).abs() {
        1.0
    } else {
        -1.0
    };
    assert!(
        (len(alpha_n + sense * beta) - lk).abs() < 1e-6,
        "{}: the lever's turn β does not bring |DB| to h_max + l_шт",
        task.name
    );
    let mut max = 0.0_f64;
    for k in 0..=2000 {
        let alpha = alpha_n + sense * beta * f64::from(k) / 2000.0;
        max = max.max(pressure_by_triangle(l, d, len(alpha)));
    }
    (pressure_by_triangle(l, d, ln), pressure_by_triangle(l, d, lk), max)
}

/// The kinematic analysis' conclusion gives the pressure angle in the rod–lever
/// pair at the start and the end of the lever's working turn and its
/// largest value, each equal (to the note's four digits) to the angle by
/// the triangle O–B–D over the turn; the given angle (θ_к = 50° in
/// variants 1 and 2, θ_н = 10° in variant 3) is among them, and no
/// "largest pressure angle 0°" is left in the conclusions. Failed before:
/// the conclusion printed the analysed group's 0°.
#[test]
fn the_cylinder_notes_conclusion_gives_the_rods_pressure_angle_on_the_lever() {
    let mut checked = 0;
    for name in VARIANTS {
        let task = task(name);
        for lang in [Language::Ru, Language::Uk, Language::En] {
            let run = run_task_in(&task, Some(lang)).unwrap();
            let note = compose(&run, &task).unwrap();
            let l = run.report.pointer("/synthesis/lengths/OB").and_then(|v| v.as_f64()).unwrap();
            let d = run.report.pointer("/synthesis/lengths/OD").and_then(|v| v.as_f64()).unwrap();
            let (start, end, max) = pressure_over_turn(&task, l, d);
            // the task's given angle is the one the synthesis reproduced
            if let Some(te) = given(&task, "pressure_end") {
                assert!((end - te.to_degrees()).abs() < 1e-6, "{name}: θ_к {end} against the given");
            }
            if let Some(ts) = given(&task, "pressure_start") {
                assert!((start - ts.to_degrees()).abs() < 1e-6, "{name}: θ_н {start} against the given");
            }
            let mut texts = Vec::new();
            for s in &note.sections {
                paragraphs(s, lang, &mut texts);
            }
            let words = pair_words(lang);
            let Some(p) = texts.iter().find(|t| t.contains(words)) else {
                panic!("{name} {lang:?}: no conclusion on the pressure angle {words:?}");
            };
            let tail = &p[p.find(words).unwrap()..];
            let got = degrees(tail);
            assert_eq!(got.len(), 3, "{name} {lang:?}: {tail}");
            for (g, want) in got.iter().zip([start, end, max]) {
                // four significant digits
                assert!(
                    (g - want).abs() <= 5e-4 * want.abs().max(1.0),
                    "{name} {lang:?}: {g} against {want} in {tail}"
                );
            }
            for zero in [
                "наибольший угол давления 0°",
                "найбільший кут тиску 0°",
                "largest pressure angle 0°",
            ] {
                assert!(!texts.iter().any(|t| t.contains(zero)), "{name} {lang:?}: «{zero}»");
            }
            checked += 1;
        }
    }
    assert_eq!(checked, 9);
}

/// A table cell's text outside its math runs.
fn words_outside_math(c: &Cell) -> String {
    let Cell::Text(t) = c else { return String::new() };
    t.0.iter()
        .map(|span| match span {
            Span::Plain(p) => outside_math(p),
            _ => String::new(),
        })
        .collect()
}

/// The tables of the note's first section (the synthesis).
fn synthesis_tables(note: &Note) -> Vec<&Block> {
    let first = note.sections.first().map(section_blocks).unwrap_or_default();
    first.into_iter().filter(|b| matches!(b, Block::Table { .. })).collect()
}

/// Every synthesis by positions (the textbook's П1.1–П1.5): the names in
/// the first column of the synthesis section's tables are words and
/// typeset symbols — no task key (`h_min`, `rod`, `frame_y`, `phi3_start`,
/// `gamma_start`, `X_C_start`) and no raw `_` outside the math. Failed
/// before: the given and found tables printed the keys.
#[test]
fn the_position_synthesis_tables_name_no_task_keys() {
    let names = [
        "textbook/p1-1-crank-slider-two-positions.toml",
        "textbook/p1-2-four-bar-extreme-positions.toml",
        "textbook/p1-3-four-bar-extreme-positions-k.toml",
        "textbook/p1-4-four-bar-three-positions.toml",
        "textbook/p1-5-oscillating-cylinder-v1.toml",
        "textbook/p1-5-oscillating-cylinder-v3.toml",
    ];
    let mut faults = Vec::new();
    let mut rows = 0;
    for name in names {
        let task = task(name);
        let table: toml::Table = task.text.parse().unwrap();
        let keys: Vec<String> = table["synthesis"].as_table().unwrap().keys().cloned().collect();
        for lang in [Language::Ru, Language::Uk, Language::En] {
            let run = run_task_in(&task, Some(lang)).unwrap();
            let mut found_keys: Vec<String> = Vec::new();
            for p in ["/synthesis/angles", "/synthesis/coordinates"] {
                if let Some(o) = run.report.pointer(p).and_then(|v| v.as_object()) {
                    found_keys.extend(o.keys().cloned());
                }
            }
            let note = compose(&run, &task).unwrap();
            for t in synthesis_tables(&note) {
                let Block::Table { rows: r, caption, .. } = t else { continue };
                for row in r {
                    let Some(first) = row.first() else { continue };
                    rows += 1;
                    let w = words_outside_math(first);
                    let bare = w.trim();
                    if w.contains('_') || keys.iter().chain(&found_keys).any(|k| k == bare) {
                        faults.push(format!("{name} {lang:?}: «{bare}» in «{caption}»"));
                    }
                }
            }
        }
    }
    assert!(rows > 100, "only {rows} rows read");
    assert!(faults.is_empty(), "{}", faults.join("\n"));
}
