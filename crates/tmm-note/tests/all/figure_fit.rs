//! No text of a note's figure extends past the figure's `viewBox` (issue
//! 22, point 3: the cam profile's legend was cut off in the Ukrainian
//! note, the meshing drawing's title and the planetary train's angular
//! speeds ran off the A4 page). Every figure the composed note sets, of the
//! default project and of the cam, gear, planetary, six-bar and textbook
//! examples, in ru, uk and en. A text's box is estimated independently of
//! the drawing code, by the project's letter-width estimate: 0.6 of the
//! lettering height per character (`tmm_report::svg::text_width`), 0.85 of
//! it above the baseline and 0.35 below; rotated texts (the axes' names)
//! are left out.

use tmm_note::{Block, Note, Section, compose};
use tmm_report::TaskSource;
use tmm_report::project::Language;
use tmm_report::run::{DEFAULT_TASK, run_task_in};

/// The value of attribute `name` in the tag `tag`.
fn attr<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let i = tag.find(&key)? + key.len();
    Some(&tag[i..i + tag[i..].find('"')?])
}

/// Each text of `svg` not rotated: its shown characters and its box
/// (x0, y0, x1, y1).
fn text_boxes(svg: &str) -> Vec<(String, [f64; 4])> {
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(i) = rest.find("<text") {
        let r = &rest[i..];
        let Some(end) = r.find("</text>") else { break };
        let open_end = r.find('>').unwrap_or(end);
        let (tag, body) = (&r[..open_end], &r[(open_end + 1).min(end)..end]);
        rest = &r[end..];
        if tag.contains("rotate(") {
            continue;
        }
        let mut shown = String::new();
        let mut in_tag = false;
        for c in body.chars() {
            match c {
                '<' => in_tag = true,
                '>' => in_tag = false,
                _ if !in_tag => shown.push(c),
                _ => {}
            }
        }
        let shown = shown.replace("&amp;", "&").replace("&lt;", "<").replace("&gt;", ">");
        let n = |k: &str| attr(tag, k).and_then(|v| v.trim_end_matches("mm").parse::<f64>().ok());
        let (Some(x), Some(y), Some(s)) = (n("x"), n("y"), n("font-size")) else {
            continue;
        };
        let w = 0.6 * s * shown.chars().count() as f64;
        let x0 = match attr(tag, "text-anchor") {
            Some("middle") => x - w / 2.0,
            Some("end") => x - w,
            _ => x,
        };
        out.push((shown, [x0, y - 0.85 * s, x0 + w, y + 0.35 * s]));
    }
    out
}

/// The texts of `svg` whose box leaves the `viewBox` by more than `slack`
/// mm, with how far.
fn outside(svg: &str, slack: f64) -> Vec<(String, f64)> {
    let root = &svg[svg.find("<svg").unwrap_or(0)..];
    let root = &root[..root.find('>').unwrap_or(root.len())];
    let v: Vec<f64> = attr(root, "viewBox")
        .unwrap_or("")
        .split_whitespace()
        .filter_map(|x| x.parse().ok())
        .collect();
    assert_eq!(v.len(), 4, "a figure without its viewBox");
    text_boxes(svg)
        .into_iter()
        .filter_map(|(t, b)| {
            let out = (v[0] - b[0]).max(b[2] - (v[0] + v[2])).max(v[1] - b[1]).max(b[3] - (v[1] + v[3]));
            (out > slack).then_some((t, out))
        })
        .collect()
}

fn figures(note: &Note) -> Vec<(String, String)> {
    fn walk(ss: &[Section], out: &mut Vec<(String, String)>) {
        for s in ss {
            for b in &s.blocks {
                if let Block::Figure { caption, svg, .. } = b {
                    out.push((caption.clone(), svg.clone()));
                }
            }
            walk(&s.subsections, out);
        }
    }
    let mut out = Vec::new();
    walk(&note.sections, &mut out);
    walk(&note.appendices, &mut out);
    out
}

fn example(file: &str) -> String {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples").join(file);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn the_fit_finder_finds_what_it_must() {
    let svg = |x: f64, anchor: &str, text: &str| {
        format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100mm\" height=\"50mm\" viewBox=\"0 0 100 50\"><text x=\"{x}\" y=\"20\" font-size=\"5\" text-anchor=\"{anchor}\">{text}</text></svg>"
        )
    };
    // 10 characters at 5 mm: 30 mm wide
    assert!(outside(&svg(60.0, "start", "0123456789"), 0.5).is_empty());
    assert_eq!(outside(&svg(80.0, "start", "0123456789"), 0.5).len(), 1);
    assert_eq!(outside(&svg(10.0, "middle", "01234<tspan dy=\"1\">56789</tspan>"), 0.5).len(), 1);
    assert!(outside(&svg(100.0, "end", "0123456789"), 0.5).is_empty());
}

#[test]
fn no_text_of_a_note_figure_leaves_its_drawing() {
    let tasks: Vec<(&str, String)> = vec![
        ("default.toml", DEFAULT_TASK.to_string()),
        ("cam-oscillating-roller.toml", example("cam-oscillating-roller.toml")),
        ("cam-seed-001-roller.toml", example("cam-seed-001-roller.toml")),
        ("cam-seed-001-flat.toml", example("cam-seed-001-flat.toml")),
        ("gear-seed001.toml", example("gear-seed001.toml")),
        ("planetary-ext-int.toml", example("planetary-ext-int.toml")),
        ("seed-003-sixbar.toml", example("seed-003-sixbar.toml")),
        ("synth-seed-003-six-bar.toml", example("synth-seed-003-six-bar.toml")),
        ("textbook/p2-engine.toml", example("textbook/p2-engine.toml")),
        (
            "textbook/p5-pneumatic-cylinder.toml",
            example("textbook/p5-pneumatic-cylinder.toml"),
        ),
    ];
    let mut faults = Vec::new();
    let (mut drawn, mut lettering) = (0, 0);
    for (name, text) in &tasks {
        for lang in [Language::Ru, Language::Uk, Language::En] {
            let task = TaskSource::new(*name, text.as_str());
            let run = run_task_in(&task, Some(lang)).unwrap();
            let note = compose(&run, &task).unwrap();
            for (caption, svg) in figures(&note) {
                drawn += 1;
                lettering += text_boxes(&svg).len();
                for (t, by) in outside(&svg, 0.5) {
                    faults.push(format!("{name} {lang:?}, \"{caption}\": \"{t}\" {by:.1} mm outside"));
                }
            }
        }
    }
    println!("note figures: {drawn} drawings, {lettering} texts checked against their viewBox");
    assert!(faults.is_empty(), "{} texts outside:\n{}", faults.len(), faults.join("\n"));
}
