//! The dynamics diagrams read back from the SVG as a teacher checks them:
//! on Wittenbauer's energy–mass diagram both lines are supporting lines of
//! the drawn curve (the whole curve on one side, touching it); on ω₁(φ) the
//! levels ω_max, ω_m, ω_min are where the curve's extremes are; T_I carries
//! ΔT_I between its drawn extremes; the run-up ends on the steady speed.

use tmm_report::TaskSource;
use tmm_report::output::Documents;
use tmm_report::project::{Language, SheetFormat};
use tmm_testkit::examples;

fn docs(name: &str) -> Documents {
    let task = TaskSource::new(name, examples::text(name))
        .with_lang(Language::En)
        .with_sheet(SheetFormat::A1);
    tmm_report::dynamics::run_section(&task).unwrap().unwrap().docs
}

fn svg(d: &Documents, file: &str) -> String {
    d.get(&format!("dynamics/{file}")).unwrap().as_text().unwrap().to_string()
}

/// The points of every `<path class="curve" …>` in drawing order, paper mm
/// (y down), with the path's stroke colour.
fn curves(svg: &str) -> Vec<(String, Vec<(f64, f64)>)> {
    let mut out = Vec::new();
    for tag in svg.split('<').filter(|t| t.starts_with("path class=\"curve\"")) {
        let get = |key: &str| {
            let k = format!(" {key}=\"");
            let i = tag.find(&k).unwrap() + k.len();
            tag[i..i + tag[i..].find('"').unwrap()].to_string()
        };
        let pts = get("d")
            .split(['M', 'L', ' '])
            .filter(|s| !s.is_empty())
            .map(|p| {
                let (x, y) = p.split_once(',').unwrap();
                (x.parse().unwrap(), y.parse().unwrap())
            })
            .collect();
        out.push((get("stroke"), pts));
    }
    out
}

/// Paper y of the straight line through `a` and `b` at paper x.
fn line_y(a: (f64, f64), b: (f64, f64), x: f64) -> f64 {
    a.1 + (b.1 - a.1) * (x - a.0) / (b.0 - a.0)
}

#[test]
fn wittenbauer_lines_support_the_curve_from_above_and_below() {
    for name in ["seed-001-fourbar.toml", "seed-003-sixbar.toml", "seed-004-two-sliders.toml"] {
        let s = svg(&docs(name), "wittenbauer.svg");
        let c = curves(&s);
        assert_eq!(c.len(), 3, "{name}: the curve and two lines");
        let curve = &c[0].1;
        // a curve (the vertices Douglas–Peucker keeps at 0.01 mm of the
        // densely sampled cycle, tmm_draw::simplify), not a few points joined
        assert!(curve.len() > 24, "{name}: {} vertices", curve.len());
        for (k, above) in [(1, true), (2, false)] {
            let l = &c[k].1;
            assert_eq!(l.len(), 2, "{name}: a line is one segment");
            // signed gap, positive when the curve point is on the side the
            // line must leave it (below the upper line: larger paper y)
            let gaps: Vec<f64> = curve
                .iter()
                .map(|&(x, y)| {
                    let g = y - line_y(l[0], l[1], x);
                    if above { g } else { -g }
                })
                .collect();
            let min = gaps.iter().fold(f64::INFINITY, |a, &b| a.min(b));
            // the whole curve on one side (to the 0.001 mm the path is written
            // in) and touching: the nearest drawn point within 0.02 mm
            assert!(min > -0.005, "{name}: line {k} crosses the curve by {min} mm");
            assert!(min < 0.02, "{name}: line {k} misses the curve by {min} mm");
        }
        // the upper line is the steeper one (ω_max² > ω_min²): in paper
        // coordinates its slope is the more negative
        let slope = |l: &Vec<(f64, f64)>| (l[1].1 - l[0].1) / (l[1].0 - l[0].0);
        assert!(slope(&c[1].1) < slope(&c[2].1), "{name}");
        for w in ["ω", "max", "min", "I<tspan", "φ = "] {
            assert!(s.contains(w), "{name}: {w}");
        }
    }
}

#[test]
fn omega_levels_sit_on_the_drawn_extremes() {
    for name in ["seed-001-fourbar.toml", "seed-004-two-sliders.toml"] {
        let s = svg(&docs(name), "omega.svg");
        let c = curves(&s);
        let w = &c[0].1;
        let (top, bottom) = w
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(t, b), p| (t.min(p.1), b.max(p.1)));
        // the dashed levels: ω_max at the curve's top, ω_min at its bottom,
        // ω_m half-way (ω_m = (ω_max + ω_min)/2), within a tenth of a mm
        let levels: Vec<f64> = s
            .split('<')
            .filter(|t| t.starts_with("line ") && t.contains("stroke-dasharray"))
            .filter_map(|t| {
                let get = |k: &str| -> Option<f64> {
                    let k = format!(" {k}=\"");
                    let i = t.find(&k)? + k.len();
                    t[i..i + t[i..].find('"')?].trim_end_matches("mm").parse().ok()
                };
                let (y1, y2) = (get("y1")?, get("y2")?);
                ((y1 - y2).abs() < 1e-9).then_some(y1)
            })
            .collect();
        let h = top.max(bottom) - top.min(bottom);
        assert!(h > 5.0, "{name}: the fluctuation is drawn large ({h} mm)");
        for want in [top, bottom, 0.5 * (top + bottom)] {
            assert!(
                levels.iter().any(|y| (y - want).abs() < 0.1),
                "{name}: no level at {want} among {levels:?}"
            );
        }
        for w in ["ω", "max", "min", "δ = "] {
            assert!(s.contains(w), "{name}: {w}");
        }
    }
}

#[test]
fn mertsalov_swing_between_the_drawn_extremes_and_the_run_up_settles() {
    let d = docs("seed-003-sixbar.toml");
    let s = svg(&d, "energy-constant.svg");
    let c = curves(&s);
    let t = &c[0].1;
    let (top, bottom) = t
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.1), b.max(p.1)));
    assert!(s.contains("ΔT") && s.contains("T<tspan"), "ΔT_I and T_I are named");
    // the double arrow of ΔT_I: a vertical segment from T_I min to T_I max
    let arrows: Vec<(f64, f64, f64, f64)> = s
        .split('<')
        .filter(|t| t.starts_with("line ") && t.contains("#c00000"))
        .filter_map(|t| {
            let get = |k: &str| -> Option<f64> {
                let k = format!(" {k}=\"");
                let i = t.find(&k)? + k.len();
                t[i..i + t[i..].find('"')?].trim_end_matches("mm").parse().ok()
            };
            Some((get("x1")?, get("y1")?, get("x2")?, get("y2")?))
        })
        .filter(|l| (l.0 - l.2).abs() < 1e-6 && (l.1 - l.3).abs() > 1.0)
        .collect();
    assert!(
        arrows
            .iter()
            .any(|l| (l.1.min(l.3) - top).abs() < 0.1 && (l.1.max(l.3) - bottom).abs() < 0.1),
        "ΔT_I spans {top}…{bottom}: {arrows:?}"
    );
    // the run-up from rest: starts at ω = 0 and ends near the steady ω_m level
    let r = svg(&d, "runup.svg");
    let c = curves(&r);
    let w = &c[0].1;
    let (first, last) = (w[0], w[w.len() - 1]);
    assert!(last.1 < first.1 - 20.0, "the speed rises on the drawing: {first:?} → {last:?}");
    assert!(r.contains("ω") && r.contains("t, s"), "axes named");
}

/// The legend of Wittenbauer's tangents writes ω²_max/2 as the course
/// does: the square raised right after ω, the index lowered after it (not
/// ω_max with the square after the index). Read from the SVG's text: ω, then
/// a raised "2", then a lowered "max"/"min".
#[test]
fn wittenbauer_legend_squares_omega_before_its_index() {
    let s = svg(&docs("seed-001-fourbar.toml"), "wittenbauer.svg");
    let dy = |run: &str| -> f64 { run.split("dy=\"").nth(1).unwrap().split('"').next().unwrap().parse().unwrap() };
    for index in ["max", "min"] {
        let end = s
            .find(&format!(">{index}</tspan>"))
            .unwrap_or_else(|| panic!("no ω {index} in the legend"));
        let start = s[..end].rfind("<text").unwrap();
        // the text's content up to the index: ω, the raised 2, the index's run
        let content = &s[start + s[start..].find('>').unwrap() + 1..end];
        let runs: Vec<&str> = content.split("<tspan").collect();
        assert_eq!(runs.len(), 3, "ω, the square, the index: {content}");
        assert_eq!(runs[0], "ω", "{content}");
        assert!(
            runs[1].ends_with(">2</tspan>") && dy(runs[1]) < 0.0,
            "the square raised after ω: {content}"
        );
        assert!(dy(runs[2]) > 0.0, "the index lowered after the square: {content}");
    }
}
