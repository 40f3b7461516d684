//! One title per figure (issue 21 point 6, issue 22 point 8): GOST 2.105
//! names a figure in its caption under it, so a figure of the note does
//! not print its name again inside its paper; a drawing on an A1 sheet has
//! no caption and keeps its name there. Measured from the output, for the
//! default project and every example, in Russian, Ukrainian and English:
//!
//! - a note figure: none of its SVG's texts (the index markup dropped,
//!   letters and digits only, lower case) contains its caption, nor the
//!   name its drawing (found by `note_figures`' SVG) prints on the sheets;
//! - a sheet: each drawing nested in a sheet's SVG (`<svg class="drawing"
//!   data-source=…>`) whose run's drawing has a name prints that name
//!   among its texts, and every drawing the note sets has one (the
//!   structural scheme, the cam profile, its motion diagrams and the
//!   generated teeth too: a name over their panels or legend).
//!
//! That each figure still prints its scale and μ, and that they measure,
//! is `scales_pdf`'s: it reads them back from the note's PDF.

use std::collections::BTreeSet;

use tmm_note::{Block, compose};

use crate::figure_numbers::svg_texts;
use tmm_report::TaskSource;
use tmm_report::project::Language;
use tmm_report::run::{DEFAULT_TASK, note_figures, run_task_in};

/// Letters and digits only, lower case, words one space apart (`_`, `^`,
/// braces, punctuation dropped): "План скоростей, φ_1" → "план скоростей φ1".
fn norm(s: &str) -> String {
    let kept: String = s
        .chars()
        .filter(|c| !matches!(c, '_' | '^' | '{' | '}'))
        .map(|c| if c.is_alphanumeric() { c } else { ' ' })
        .collect();
    kept.split_whitespace().collect::<Vec<_>>().join(" ").to_lowercase()
}

/// The nested drawings of a sheet's SVG: (source path, its texts).
fn sheet_drawings(svg: &str) -> Vec<(String, Vec<String>)> {
    let mark = "<svg class=\"drawing\" data-source=\"";
    let mut out = Vec::new();
    let starts: Vec<usize> = svg.match_indices(mark).map(|(i, _)| i).collect();
    for (k, &i) in starts.iter().enumerate() {
        let end = starts.get(k + 1).copied().unwrap_or(svg.len());
        let part = &svg[i..end];
        let path = part[mark.len()..].split('"').next().unwrap_or("").to_string();
        out.push((path, svg_texts(part)));
    }
    out
}

/// The examples under examples/ (with textbook/), by name.
fn examples() -> Vec<(String, String)> {
    let root = format!("{}/../../examples", env!("CARGO_MANIFEST_DIR"));
    let mut out = Vec::new();
    for dir in [root.clone(), format!("{root}/textbook")] {
        let mut names: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .filter_map(|e| e.ok())
            .map(|e| e.path())
            .filter(|p| p.extension().is_some_and(|x| x == "toml"))
            .collect();
        names.sort();
        for p in names {
            let name = p.strip_prefix(&root).unwrap().to_string_lossy().trim_start_matches('/').to_string();
            out.push((name, std::fs::read_to_string(&p).unwrap()));
        }
    }
    out
}

/// What one note showed: figures checked, sheet drawings with a name, the
/// sheet drawings without one (none the note sets may be), faults.
#[derive(Default)]
struct Counts {
    figures: usize,
    named: usize,
    unnamed: BTreeSet<String>,
    faults: Vec<String>,
}

fn check(name: &str, text: &str, lang: Language) -> Counts {
    let mut n = Counts::default();
    let task = TaskSource::new(name, text);
    let run = run_task_in(&task, Some(lang)).unwrap();
    let note = compose(&run, &task).unwrap();
    // the note's figures as note_figures makes them: each figure's drawing
    // (its path) found by its SVG, and the name that drawing prints on the
    // sheets
    let figs = note_figures(&task, Some(lang)).unwrap();
    let path_of = |svg: &str| {
        figs.iter()
            .find(|d| d.path.ends_with(".svg") && figs.picture(&d.path).is_some_and(|p| p.svg() == svg))
            .map(|d| d.path.clone())
    };
    let mut noted = BTreeSet::new();
    for b in crate::fixtures::note_figures(&note) {
        let Block::Figure { caption, svg, .. } = b else { continue };
        n.figures += 1;
        let normed: Vec<String> = svg_texts(svg).iter().map(|t| norm(t)).collect();
        let cap = norm(caption);
        if let Some(t) = normed.iter().find(|t| !cap.is_empty() && t.contains(&cap)) {
            n.faults
                .push(format!("{name} {lang:?}: figure \"{caption}\" prints its caption: \"{t}\""));
        }
        let Some(path) = path_of(svg) else {
            n.faults
                .push(format!("{name} {lang:?}: figure \"{caption}\" is none of the run's drawings"));
            continue;
        };
        let Some(title) = run.docs.picture(&path).and_then(|p| p.title()) else {
            continue;
        };
        let t1 = norm(&title);
        if let Some(t) = normed.iter().find(|t| t.contains(&t1)) {
            n.faults.push(format!(
                "{name} {lang:?}: figure \"{caption}\" ({path}) prints its name \"{title}\": \"{t}\""
            ));
        }
        noted.insert(path);
    }
    // the sheets: each placed drawing's name among its texts
    for d in run
        .docs
        .iter()
        .filter(|d| d.path.starts_with("sheets/") && d.path.ends_with(".svg"))
    {
        let sheet = d.as_text().unwrap();
        for (src, texts) in sheet_drawings(sheet) {
            let Some(pic) = run.docs.picture(&src) else { continue };
            match pic.title() {
                Some(title) => {
                    let t1 = norm(&title);
                    let joined = texts.iter().map(|t| norm(t)).collect::<Vec<_>>().join(" ");
                    if joined.contains(&t1) {
                        n.named += 1;
                    } else {
                        n.faults
                            .push(format!("{name} {lang:?}: {} {src} lost its name \"{title}\"", d.path));
                    }
                }
                None => {
                    if noted.contains(&src) {
                        n.faults
                            .push(format!("{name} {lang:?}: {} {src}, a figure of the note, has no name", d.path));
                    }
                    n.unnamed.insert(src);
                }
            }
        }
    }
    n
}

#[test]
fn a_note_figure_leaves_its_name_to_the_caption_a_sheet_drawing_keeps_it() {
    let mut tasks: Vec<(String, String)> = vec![("default.toml".into(), DEFAULT_TASK.to_string())];
    tasks.extend(examples());
    let langs = [Language::Ru, Language::Uk, Language::En];
    let jobs: Vec<(&str, &str, Language)> = tasks
        .iter()
        .flat_map(|(n, t)| langs.iter().map(move |l| (n.as_str(), t.as_str(), *l)))
        .collect();
    let results: Vec<Counts> = std::thread::scope(|s| {
        let handles: Vec<_> = jobs
            .chunks(jobs.len().div_ceil(2))
            .map(|chunk| s.spawn(move || chunk.iter().map(|(n, t, l)| check(n, t, *l)).collect::<Vec<_>>()))
            .collect();
        handles.into_iter().flat_map(|h| h.join().unwrap()).collect()
    });
    let figures: usize = results.iter().map(|c| c.figures).sum();
    let named: usize = results.iter().map(|c| c.named).sum();
    let unnamed: BTreeSet<&String> = results.iter().flat_map(|c| &c.unnamed).collect();
    let faults: Vec<&String> = results.iter().flat_map(|c| &c.faults).collect();
    println!(
        "{} notes: {figures} figures checked; {named} sheet drawings print their name; drawn without one: {unnamed:?}",
        results.len()
    );
    assert!(figures > 300 && named > 300, "{figures} figures, {named} named sheet drawings");
    assert!(
        faults.is_empty(),
        "{} faults:\n{}",
        faults.len(),
        faults.iter().map(|s| s.as_str()).collect::<Vec<_>>().join("\n")
    );
}

/// The comparison finds what it must: the old velocity plan's title line
/// holds its caption, its μ line does not; a sheet's drawings are found
/// with their texts.
#[test]
fn the_title_finders_find_what_they_must() {
    let old = "<svg><text x=\"1\">План скоростей, φ<tspan>1</tspan> = 15°</text><text>μ<tspan>v</tspan> = 0,1 (м/с)/мм</text></svg>";
    let texts = svg_texts(old);
    assert_eq!(texts.len(), 2);
    assert!(norm(&texts[0]).contains(&norm("План скоростей")));
    assert!(!norm(&texts[1]).contains(&norm("План скоростей")));
    let sheet = "<svg><svg class=\"drawing\" data-source=\"a/b.svg\" x=\"1\"><text>Name</text></svg><svg class=\"drawing\" data-source=\"c.svg\"><text>x</text></svg></svg>";
    let d = sheet_drawings(sheet);
    assert_eq!(d.len(), 2);
    assert_eq!((d[0].0.as_str(), d[0].1[0].as_str()), ("a/b.svg", "Name"));
}
