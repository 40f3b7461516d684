//! The geometry of the gear, planetary and cam drawings read back from the
//! drawn SVG and checked against independent numbers: the JSON report, the
//! task's data, GOST 2.302 scales, GOST 2.304 lettering, the slots of the
//! A1 and A2 sheets.

use crate::svg_read::{attr_s, paper, run_example as run};
use tmm_report::run::Run;
use tmm_testkit::plane::Rect;
use tmm_testkit::svg::num;

fn svg<'a>(r: &'a Run, path: &str) -> &'a str {
    r.docs.get(path).unwrap_or_else(|| panic!("{path}")).as_text().unwrap()
}

/// The scale written on the root: `2,5:1` → 2.5, `1:2` → 0.5.
fn data_scale(s: &str) -> f64 {
    let root = &s[s.find("<svg").unwrap()..];
    let t = attr_s(&root[..root.find('>').unwrap()], "data-scale").expect("data-scale on the root");
    let (a, b) = t.split_once(':').unwrap();
    let f = |x: &str| x.replace(',', ".").parse::<f64>().unwrap();
    f(a) / f(b)
}

/// GOST 2.302 scales, written independently of the code's table.
const GOST: [f64; 19] = [
    1.0, 2.0, 2.5, 4.0, 5.0, 10.0, 20.0, 40.0, 50.0, 100.0, 0.5, 0.4, 0.25, 0.2, 0.1, 0.05, 0.04, 0.025, 0.02,
];

fn is_standard(f: f64) -> bool {
    GOST.iter().any(|g| (g - f).abs() < 1e-12) || (f - 1.0 / 15.0).abs() < 1e-12 || (f - 0.01).abs() < 1e-12
}

/// The lines of one group `<g id="…">` … `</g>`.
fn group<'a>(s: &'a str, id: &str) -> Vec<&'a str> {
    let open = format!("<g id=\"{id}\">");
    let i = s.find(&open).unwrap_or_else(|| panic!("group {id}")) + open.len();
    let j = i + s[i..].find("</g>").unwrap();
    s[i..j].lines().filter(|l| !l.trim().is_empty()).collect()
}

/// The vertices of a `<polyline>` or `<polygon>`.
fn points(el: &str) -> Vec<(f64, f64)> {
    tmm_testkit::svg::points(attr_s(el, "points").unwrap())
}

/// A label's box: font size × visible characters (with the lettering's
/// advance 0.62) by 1.2 × font size, about its middle.
#[derive(Debug, Clone, Copy)]
struct Boxed {
    x0: f64,
    y0: f64,
    x1: f64,
    y1: f64,
    h: f64,
}

fn label_boxes(s: &str) -> Vec<(Boxed, String)> {
    s.lines()
        .filter(|l| l.starts_with("<text class=\"label\""))
        .map(|l| {
            let (x, y, h) = (num(l, "x").unwrap(), num(l, "y").unwrap(), num(l, "font-size").unwrap());
            let mut text = String::new();
            let mut inside = false;
            for ch in l[l.find('>').unwrap() + 1..].chars() {
                match ch {
                    '<' => inside = true,
                    '>' => inside = false,
                    c if !inside => text.push(c),
                    _ => {}
                }
            }
            let n = text.chars().count() as f64;
            let w = 0.62 * h * n;
            let xc = if attr_s(l, "text-anchor") == Some("start") {
                x + 0.5 * w
            } else {
                x
            };
            let yc = y - 0.35 * h;
            (
                Boxed {
                    x0: xc - 0.5 * w,
                    y0: yc - 0.6 * h,
                    x1: xc + 0.5 * w,
                    y1: yc + 0.6 * h,
                    h,
                },
                text,
            )
        })
        .collect()
}

fn labels_apart_and_inside(s: &str, what: &str) {
    let (w, h, _) = paper(s);
    let b = label_boxes(s);
    assert!(!b.is_empty(), "{what}: no labels");
    for (i, (bi, ti)) in b.iter().enumerate() {
        assert!(
            bi.x0 >= 0.0 && bi.y0 >= 0.0 && bi.x1 <= w && bi.y1 <= h,
            "{what}: {ti} outside the paper {bi:?}"
        );
        assert!(bi.h >= 2.5 - 1e-9, "{what}: {ti} lettering {} mm < 2.5 (GOST 2.304)", bi.h);
        for (bj, tj) in &b[..i] {
            let hit = bi.x0 < bj.x1 && bj.x0 < bi.x1 && bi.y0 < bj.y1 && bj.y0 < bi.y1;
            assert!(!hit, "{what}: «{ti}» overlaps «{tj}»");
        }
    }
}

/// Every straight piece drawn: `<line>`s and the edges of `<polyline>`s
/// and `<polygon>`s (circles, teeth, arrowheads, arcs), paper mm.
fn drawn_segments(s: &str) -> Vec<[f64; 4]> {
    let mut out = Vec::new();
    for l in s.lines() {
        if l.starts_with("<line") {
            out.push([
                num(l, "x1").unwrap(),
                num(l, "y1").unwrap(),
                num(l, "x2").unwrap(),
                num(l, "y2").unwrap(),
            ]);
        } else if l.starts_with("<polyline") || l.starts_with("<polygon") {
            let p = points(l);
            for w in p.windows(2) {
                out.push([w[0].0, w[0].1, w[1].0, w[1].1]);
            }
            if l.starts_with("<polygon") && p.len() > 2 {
                let (a, b) = (p[p.len() - 1], p[0]);
                out.push([a.0, a.1, b.0, b.1]);
            }
        }
    }
    out
}

/// No label's box is crossed by a drawn line (a teacher marks a label that
/// touches a line).
fn labels_off_the_lines(s: &str, what: &str) {
    let segs = drawn_segments(s);
    assert!(segs.len() > 100, "{what}: {} segments", segs.len());
    for (b, t) in label_boxes(s) {
        for g in &segs {
            assert!(
                !Rect::from([b.x0, b.y0, b.x1, b.y1]).enters((g[0], g[1]), (g[2], g[3])),
                "{what}: «{t}» {b:?} touches the line {g:?}"
            );
        }
    }
}

/// Every coordinate of every element lies inside the viewBox.
fn everything_inside(s: &str, what: &str) {
    let (w, h, _) = paper(s);
    let inside = |x: f64, y: f64| (-0.01..=w + 0.01).contains(&x) && (-0.01..=h + 0.01).contains(&y);
    for l in s.lines() {
        for (xa, ya) in [("x1", "y1"), ("x2", "y2"), ("cx", "cy"), ("x", "y")] {
            if let (Some(x), Some(y)) = (num(l, xa), num(l, ya)) {
                assert!(inside(x, y), "{what}: {l}");
            }
        }
        if l.contains(" points=\"") {
            for (x, y) in points(l) {
                assert!(inside(x, y), "{what}: ({x}, {y}) in {l}");
            }
        }
    }
}

fn dot_centre(s: &str, id: &str) -> (f64, f64) {
    let g = group(s, id);
    let c = g.iter().find(|l| l.starts_with("<circle")).unwrap();
    (num(c, "cx").unwrap(), num(c, "cy").unwrap())
}

fn json_mm(r: &Run, key: &str) -> f64 {
    r.report["gear"][key].as_f64().unwrap_or_else(|| panic!("{key}")) * 1e3
}

#[test]
fn meshing_drawing_at_a_standard_scale_with_both_centres_and_true_circles() {
    for (ex, sheet) in [
        ("gear-seed001.toml", "A1"),
        ("gear-seed001.toml", "A2"),
        ("gear-internal.toml", "A1"),
        ("gear-seed003.toml", "A2"),
    ] {
        let r = run(ex, sheet, "ru");
        let s = svg(&r, "gear/mesh.svg");
        let what = format!("{ex} {sheet}");
        let k = data_scale(s);
        assert!(is_standard(k), "{what}: scale {k} is not GOST 2.302");
        // the scale is written on the drawing too
        assert!(s.contains(&format!("Масштаб {}", attr_s(s, "data-scale").unwrap())), "{what}");
        let (w, h, _) = paper(s);
        let o1 = dot_centre(s, "centre-O1");
        let o2 = dot_centre(s, "centre-O2");
        for o in [o1, o2] {
            assert!(o.0 > 0.0 && o.0 < w && o.1 > 0.0 && o.1 < h, "{what}: centre {o:?} off the paper");
        }
        let aw = json_mm(&r, "aw");
        let drawn = (o1.0 - o2.0).hypot(o1.1 - o2.1);
        assert!((drawn - aw * k).abs() < 2e-3, "{what}: O1O2 {drawn} vs aw·scale {}", aw * k);
        // every drawn vertex of every circle lies at d/2·scale from its centre
        for (i, o) in [(1, o1), (2, o2)] {
            for name in ["d", "db", "da", "df", "dw"] {
                let key = format!("{name}{i}");
                let g = group(s, &format!("circle-{key}"));
                let want = json_mm(&r, &key) / 2.0 * k;
                let pts: Vec<(f64, f64)> = g.iter().flat_map(|l| points(l)).collect();
                assert!(pts.len() > 10, "{what}: {key} not drawn");
                for p in pts {
                    let rr = (p.0 - o.0).hypot(p.1 - o.1);
                    assert!((rr - want).abs() < 3e-3, "{what}: {key} drawn at r {rr}, want {want}");
                }
            }
        }
        // the circles' labels are all there, 3.5 mm high (raised to the
        // lettering floor where that is more)
        let labels = label_boxes(s);
        for i in [1, 2] {
            for name in ["d", "db", "da", "df", "dw"] {
                let t = format!("{name}{i}");
                let b = labels
                    .iter()
                    .find(|(_, x)| *x == t)
                    .unwrap_or_else(|| panic!("{what}: no label {t}"));
                let want = tmm_report::picture::em(3.5);
                assert!((b.0.h - want).abs() < 0.006, "{what}: {t} lettering {}", b.0.h);
            }
        }
        for t in ["P", "N1", "N2", "A", "B", "O1", "O2"] {
            assert!(labels.iter().any(|(_, x)| x == t), "{what}: no label {t}");
        }
        // a_w and α_w dimensioned with the report's values
        let aw_t = format!("aw = {}", format!("{aw:.2}").replace('.', ","));
        assert!(labels.iter().any(|(_, x)| *x == aw_t), "{what}: no «{aw_t}»");
        let al = r.report["gear"]["alpha_w"].as_f64().unwrap().to_degrees();
        let al_t = format!("αw = {}°", format!("{al:.2}").replace('.', ","));
        assert!(labels.iter().any(|(_, x)| *x == al_t), "{what}: no «{al_t}»");
        labels_apart_and_inside(s, &what);
        labels_off_the_lines(s, &what);
        everything_inside(s, &what);
    }
}

#[test]
fn drawings_fit_their_slots_on_a1_and_a2() {
    // slots of the sheets (A1; A2 = A1/√2 rounded down to 5 mm)
    let slot = |a1: (f64, f64), sheet: &str| {
        if sheet == "A1" {
            a1
        } else {
            let r = |x: f64| (x / 2f64.sqrt() / 5.0).floor() * 5.0;
            (r(a1.0), r(a1.1))
        }
    };
    let scheme = (400.0, 280.0);
    for sheet in ["A1", "A2"] {
        let g = run("gear-seed001.toml", sheet, "ru");
        let p = run("planetary-ext-ext.toml", sheet, "ru");
        let c = run("cam-seed-001-roller.toml", sheet, "ru");
        for (r, path, box_) in [
            (&g, "gear/mesh.svg", scheme),
            (&g, "gear/contour.svg", (200.0, 150.0)),
            (&g, "gear/sliding.svg", (260.0, 120.0)),
            (&p, "planetary/planetary.svg", scheme),
            (&c, "cam/cam.svg", scheme),
        ] {
            let (w, h, _) = paper(svg(r, path));
            let (sw, sh) = slot(box_, sheet);
            assert!(w <= sw + 1e-9 && h <= sh + 1e-9, "{sheet} {path}: {w}×{h} > slot {sw}×{sh}");
        }
        for (r, path) in [(&p, "planetary/planetary.svg"), (&c, "cam/cam.svg"), (&g, "gear/contour.svg")] {
            let s = svg(r, path);
            labels_apart_and_inside(s, &format!("{sheet} {path}"));
        }
        for (r, path) in [(&p, "planetary/planetary.svg"), (&c, "cam/cam.svg")] {
            let k = data_scale(svg(r, path));
            assert!(is_standard(k), "{sheet} {path}: {k}");
        }
    }
}

#[test]
fn contour_lines_each_have_their_own_style_and_the_legend_matches() {
    let r = run("gear-seed001.toml", "A1", "en");
    let s = svg(&r, "gear/contour.svg");
    let style = |l: &str| {
        (
            attr_s(l, "stroke").unwrap().to_string(),
            attr_s(l, "stroke-dasharray").map(str::to_string),
        )
    };
    let mut drawn = Vec::new();
    let mut rest = s;
    // the line groups in drawing order: ids other than "allowed"
    while let Some(i) = rest.find("<g id=\"") {
        let id_end = rest[i + 7..].find('"').unwrap();
        let id = &rest[i + 7..i + 7 + id_end];
        let body = &rest[i..i + rest[i..].find("</g>").unwrap()];
        if id != "allowed" {
            let first = body.lines().find(|l| l.starts_with("<polyline")).unwrap();
            drawn.push(style(first));
        }
        rest = &rest[i + 7..];
    }
    assert!(drawn.len() >= 6, "{drawn:?}");
    for i in 0..drawn.len() {
        for j in 0..i {
            assert_ne!(drawn[i], drawn[j], "lines {i} and {j} share a style");
        }
    }
    // the legend's sample lines are 9 mm long, in the same order and styles
    let legend: Vec<_> = s
        .lines()
        .filter(|l| l.starts_with("<line") && (num(l, "x2").unwrap() - num(l, "x1").unwrap() - 9.0).abs() < 1e-6)
        .map(style)
        .collect();
    assert_eq!(legend, drawn);
}

#[test]
fn cam_profile_has_the_rotation_arrow_and_rays_at_the_phase_boundaries() {
    // examples/cam-seed-001-roller.toml: rise 108°, dwell 15°, return 108°,
    // dwell 129°, counter-clockwise
    for sheet in ["A1", "A2"] {
        let r = run("cam-seed-001-roller.toml", sheet, "ru");
        let s = svg(&r, "cam/cam.svg");
        let rot = group(s, "rotation");
        assert!(rot.iter().any(|l| l.starts_with("<polygon")), "no arrowhead");
        let labels = label_boxes(s);
        assert!(labels.iter().any(|(_, t)| t == "ω1"));
        for t in ["φу = 108,0°", "φдс = 15,0°", "φв = 108,0°", "φбс = 129,0°"] {
            assert!(
                labels.iter().any(|(_, x)| x == t),
                "no «{t}»: {:?}",
                labels.iter().map(|l| &l.1).collect::<Vec<_>>()
            );
        }
        let rays = group(s, "phase-rays");
        assert_eq!(rays.len(), 4);
        // the rays start at O; the first passes through the follower's
        // contact point at φ = 0 (B0, the roller's centre on the pitch profile)
        let o = (num(rays[0], "x1").unwrap(), num(rays[0], "y1").unwrap());
        let ang = |l: &str| {
            let (x, y) = (num(l, "x2").unwrap(), num(l, "y2").unwrap());
            (-(y - o.1)).atan2(x - o.0)
        };
        let theta0 = ang(rays[0]);
        // B0: the white joint of radius 0.8 that is not O
        let b0 = s
            .lines()
            .filter(|l| l.starts_with("<circle") && num(l, "r") == Some(0.8) && l.contains("#ffffff"))
            .map(|l| (num(l, "cx").unwrap(), num(l, "cy").unwrap()))
            .next()
            .unwrap();
        let tb = (-(b0.1 - o.1)).atan2(b0.0 - o.0);
        let wrap = |a: f64| (a + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI;
        assert!(wrap(theta0 - tb).abs() < 1e-3, "{theta0} vs B0 at {tb}");
        let mut cum = 0.0f64;
        for (k, deg) in [0.0, 108.0, 15.0, 108.0].iter().enumerate() {
            cum += deg;
            // counter-clockwise cam: the follower meets the profile at θ0 − φ
            let want = theta0 - cum.to_radians();
            assert!(wrap(ang(rays[k]) - want).abs() < 1e-3, "ray {k}: {} vs {want}", ang(rays[k]));
        }
        for l in &rays {
            assert!((num(l, "x1").unwrap() - o.0).abs() < 1e-9 && (num(l, "y1").unwrap() - o.1).abs() < 1e-9);
        }
    }
}

#[test]
fn russian_drawings_have_no_english_words() {
    let runs = [
        run("gear-internal.toml", "A1", "ru"),
        run("gear-seed003.toml", "A1", "ru"),
        run("planetary-sun-planet-ring.toml", "A1", "ru"),
        run("cam-oscillating-roller.toml", "A1", "ru"),
    ];
    // every drawing of the runs, the sheets' copies aside
    let all: Vec<(&Run, String)> = runs
        .iter()
        .flat_map(|r| {
            r.docs
                .iter()
                .filter(|d| d.path.ends_with(".svg") && !d.path.starts_with("sheets/"))
                .map(move |d| (r, d.path.clone()))
        })
        .collect();
    assert!(all.len() >= 10, "{} drawings", all.len());
    for (r, path) in &all {
        let path = path.as_str();
        let s = svg(r, path);
        for l in s.lines().filter(|l| l.starts_with("<text")) {
            let mut text = String::new();
            let mut inside = false;
            for ch in l.chars() {
                match ch {
                    '<' => inside = true,
                    '>' => {
                        inside = false;
                        text.push(' ');
                    }
                    c if !inside => text.push(c),
                    _ => {}
                }
            }
            for w in text.split(|c: char| !c.is_ascii_alphabetic()) {
                // min and max are the notation's subscripts (ρ_min, ϑ_1max)
                assert!(w.len() < 3 || w == "min" || w == "max", "{path}: English «{w}» in «{text}»");
            }
            // the decimal comma: no digit.digit
            let b = text.as_bytes();
            for i in 1..b.len().saturating_sub(1) {
                assert!(
                    !(b[i] == b'.' && b[i - 1].is_ascii_digit() && b[i + 1].is_ascii_digit()),
                    "{path}: decimal point in «{text}»"
                );
            }
        }
    }
}
