//! No text of a note's figure extends past the figure's `viewBox` (issue
//! 22, point 3: the cam profile's legend was cut off in the Ukrainian
//! note, the meshing drawing's title and the planetary train's angular
//! speeds ran off the A4 page). Every figure the composed note sets, of the
//! default project and of the cam, gear, planetary, six-bar and textbook
//! examples, in ru, uk and en. A text's box is measured from the SVG as
//! printed: each run (the text's own characters and each `tspan`) is as
//! wide as its `textLength` when it has one (the sheets' writer narrows
//! runs to type B), else as the sum of its characters' advances in the
//! drawing face, osifont with tmm's supplement (`tmm_draw::face`, read
//! from the font files; 0.6 em for a character the face lacks), at the
//! run's own font size, plus its `dx`; the 75° slant (`skewX(-15)`) widens
//! the box by tan 15° of the height above the baseline at the right and of
//! the depth below it at the left; 0.85 of the font size above the
//! baseline and 0.35 below; rotated texts (the axes' names) are left out.

use tmm_note::{Block, compose};
use tmm_report::TaskSource;
use tmm_report::project::Language;
use tmm_report::run::{DEFAULT_TASK, run_task_in};
use tmm_testkit::examples;
use tmm_testkit::svg::{attr, num, unescape, view_box};

use super::fixtures::note_figures;

/// The advance of `c` in ems in the drawing face (0.6 em if it lacks it).
fn advance(c: char) -> f64 {
    tmm_draw::face::advance_em(c).unwrap_or(0.6)
}

/// The shown width of a text's body at font size `size`: its runs, each
/// its `textLength` or its characters' advances at its font size, and
/// each `tspan`'s `dx`; and the largest font size shown.
fn body_width(body: &str, size: f64) -> (String, f64, f64) {
    let (mut shown, mut width, mut largest) = (String::new(), 0.0, 0.0_f64);
    // (font size, text length) of the element the characters belong to
    let mut stack: Vec<(f64, Option<f64>)> = vec![(size, None)];
    let mut run = String::new();
    let mut flush = |run: &mut String, top: (f64, Option<f64>), width: &mut f64, largest: &mut f64| {
        let t = unescape(run);
        if !t.is_empty() {
            *width += top.1.unwrap_or_else(|| t.chars().map(advance).sum::<f64>() * top.0);
            *largest = largest.max(top.0);
            shown.push_str(&t);
        }
        run.clear();
    };
    let mut rest = body;
    while !rest.is_empty() {
        if let Some(tag_end) = rest.strip_prefix('<').and_then(|r| r.find('>')) {
            let tag = &rest[..tag_end + 2];
            flush(&mut run, *stack.last().unwrap_or(&(size, None)), &mut width, &mut largest);
            if tag.starts_with("</") {
                if stack.len() > 1 {
                    stack.pop();
                }
            } else {
                let parent = stack.last().map_or(size, |t| t.0);
                let s = num(tag, "font-size").unwrap_or(parent);
                width += num(tag, "dx").unwrap_or(0.0);
                if !tag.ends_with("/>") {
                    stack.push((s, num(tag, "textLength")));
                }
            }
            rest = &rest[tag.len()..];
        } else {
            let c = rest.chars().next().unwrap_or(' ');
            run.push(c);
            rest = &rest[c.len_utf8()..];
        }
    }
    flush(&mut run, *stack.last().unwrap_or(&(size, None)), &mut width, &mut largest);
    (shown, width, largest)
}

/// Each text of `svg` not rotated: its shown characters and its box
/// (x0, y0, x1, y1).
pub(super) fn text_boxes(svg: &str) -> Vec<(String, [f64; 4])> {
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
        // the anchor: x and y, else the frame's translate(x y)
        let translate = attr(tag, "transform")
            .and_then(|t| t.split("translate(").nth(1))
            .and_then(|t| t.split(')').next())
            .map(|t| t.split([' ', ',']).filter_map(|v| v.parse::<f64>().ok()).collect::<Vec<_>>());
        let x = num(tag, "x").or_else(|| translate.as_ref().and_then(|t| t.first().copied()));
        let y = num(tag, "y").or_else(|| translate.as_ref().and_then(|t| t.get(1).copied()));
        let (Some(x), Some(y), Some(s)) = (x, y, num(tag, "font-size")) else {
            continue;
        };
        let (shown, w, largest) = body_width(body, s);
        let x0 = match attr(tag, "text-anchor") {
            Some("middle") => x - w / 2.0,
            Some("end") => x - w,
            _ => x,
        };
        let s = largest.max(s);
        let (up, down) = (0.85 * s, 0.35 * s);
        // the slant leans the top to the right and the foot to the left
        let slant = if tag.contains("skewX(-15)") {
            15f64.to_radians().tan()
        } else {
            0.0
        };
        out.push((shown, [x0 - slant * down, y - up, x0 + w + slant * up, y + down]));
    }
    out
}

/// The texts of `svg` whose box leaves the `viewBox` by more than `slack`
/// mm, with how far.
fn outside(svg: &str, slack: f64) -> Vec<(String, f64)> {
    let v = view_box(svg).expect("a figure without its viewBox");
    text_boxes(svg)
        .into_iter()
        .filter_map(|(t, b)| {
            let out = (v[0] - b[0]).max(b[2] - (v[0] + v[2])).max(v[1] - b[1]).max(b[3] - (v[1] + v[3]));
            (out > slack).then_some((t, out))
        })
        .collect()
}

#[test]
fn the_fit_finder_finds_what_it_must() {
    let svg = |x: f64, anchor: &str, text: &str| {
        format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100mm\" height=\"50mm\" viewBox=\"0 0 100 50\"><text x=\"{x}\" y=\"20\" font-size=\"5\" text-anchor=\"{anchor}\">{text}</text></svg>"
        )
    };
    // ten digits at 5 mm: their advances in osifont (about 0.57 em each)
    let em = |c: char| tmm_draw::face::advance_em(c).unwrap();
    let digits = 5.0 * "0123456789".chars().map(em).sum::<f64>();
    assert!((25.0..32.0).contains(&digits), "{digits}");
    assert!((text_boxes(&svg(60.0, "start", "0123456789"))[0].1[2] - 60.0 - digits).abs() < 1e-9);
    assert!(outside(&svg(100.4 - digits, "start", "0123456789"), 0.5).is_empty());
    assert_eq!(outside(&svg(100.6 - digits, "start", "0123456789"), 0.5).len(), 1);
    assert_eq!(outside(&svg(10.0, "middle", "01234<tspan dy=\"1\">56789</tspan>"), 0.5).len(), 1);
    assert!(outside(&svg(100.0, "end", "0123456789"), 0.5).is_empty());
    // a run narrowed by textLength is as wide as that, a tspan's font size is its own
    let narrowed = svg(
        0.0,
        "start",
        "0123<tspan textLength=\"2\">456789</tspan><tspan font-size=\"2\">ab</tspan>",
    );
    let w = 5.0 * "0123".chars().map(em).sum::<f64>() + 2.0 + 2.0 * (em('a') + em('b'));
    assert!((text_boxes(&narrowed)[0].1[2] - w).abs() < 1e-9, "{:?}", text_boxes(&narrowed));
    // the sheets' frame: the anchor in translate(), the slant widening the box
    let sheared = "<svg viewBox=\"0 0 100 50\"><text transform=\"translate(10 20) skewX(-15)\" font-size=\"5\">0</text></svg>";
    let b = text_boxes(sheared)[0].1;
    assert!(
        (b[0] - (10.0 - 15f64.to_radians().tan() * 0.35 * 5.0)).abs() < 1e-9 && (b[1] - (20.0 - 0.85 * 5.0)).abs() < 1e-9,
        "{b:?}"
    );
}

#[test]
fn no_text_of_a_note_figure_leaves_its_drawing() {
    let tasks: Vec<(&str, String)> = vec![
        ("default.toml", DEFAULT_TASK.to_string()),
        ("cam-oscillating-roller.toml", examples::text("cam-oscillating-roller.toml")),
        ("cam-seed-001-roller.toml", examples::text("cam-seed-001-roller.toml")),
        ("cam-seed-001-flat.toml", examples::text("cam-seed-001-flat.toml")),
        ("gear-seed001.toml", examples::text("gear-seed001.toml")),
        ("planetary-ext-int.toml", examples::text("planetary-ext-int.toml")),
        ("seed-003-sixbar.toml", examples::text("seed-003-sixbar.toml")),
        ("synth-seed-003-six-bar.toml", examples::text("synth-seed-003-six-bar.toml")),
        ("textbook/p2-engine.toml", examples::text("textbook/p2-engine.toml")),
        (
            "textbook/p5-pneumatic-cylinder.toml",
            examples::text("textbook/p5-pneumatic-cylinder.toml"),
        ),
    ];
    let mut faults = Vec::new();
    let (mut drawn, mut lettering) = (0, 0);
    for (name, text) in &tasks {
        for lang in [Language::Ru, Language::Uk, Language::En] {
            let task = TaskSource::new(*name, text.as_str());
            let run = run_task_in(&task, Some(lang)).unwrap();
            let note = compose(&run, &task).unwrap();
            for b in note_figures(&note) {
                let Block::Figure { caption, svg, .. } = b else { continue };
                drawn += 1;
                lettering += text_boxes(svg).len();
                for (t, by) in outside(svg, 0.5) {
                    faults.push(format!("{name} {lang:?}, \"{caption}\": \"{t}\" {by:.1} mm outside"));
                }
            }
        }
    }
    println!("note figures: {drawn} drawings, {lettering} texts checked against their viewBox");
    assert!(faults.is_empty(), "{} texts outside:\n{}", faults.len(), faults.join("\n"));
}
