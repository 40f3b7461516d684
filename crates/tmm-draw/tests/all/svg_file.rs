//! The SVG rendering: widths, dash arrays, indices as tspans, determinism.

use tmm_draw::{LineType, Thickness, sample, svg};

#[test]
fn svg_is_deterministic_and_carries_gost_lines() {
    let scene = sample::scene();
    let a = svg::render(&scene);
    assert_eq!(a, svg::render(&scene));
    let s = Thickness::A1;
    let axis: Vec<String> = LineType::Axis.dashes(s).iter().map(|&v| svg::num(v)).collect();
    assert!(a.contains(&format!("stroke-dasharray=\"{}\"", axis.join(" "))));
    assert!(a.contains("stroke-width=\"0.7\"") && a.contains("stroke-width=\"0.25\""));
    assert!(a.contains("width=\"200mm\"") && a.contains("viewBox=\"0 0 200 120\""));
    assert!(a.contains("font-family=\"osifont"));
    assert!(!a.contains("NaN") && !a.contains("inf"));
}

#[test]
fn indices_are_tspans_with_a_baseline_shift() {
    let a = svg::render(&sample::scene());
    // K_v at 3.5 mm: "v" is a 2.5 mm index lowered by a third of 3.5 mm
    let k = a.find(">K</tspan>").expect("K is a run of its own");
    let v = &a[k..k + 200];
    assert!(
        v.contains("><tspan font-size=\"3.876\" ") && v.contains("baseline-shift=\"-1.167\">v</tspan>"),
        "{v}"
    );
    // every run narrowed by one factor: K's and v's lengths stand as their
    // advances in osifont (K 1393, v 1192 units, fontTools) at their sizes,
    // so usvg, which scales each run about the anchor, opens no gap
    let num = |t: &str| t[..t.find('"').unwrap()].parse::<f64>().unwrap();
    let lk = num(a[..k].rsplit("textLength=\"").next().unwrap());
    let lv = num(v.split("textLength=\"").nth(1).unwrap());
    let ratio = (1393.0 * 5.426) / (1192.0 * 3.876);
    assert!((lk / lv - ratio).abs() < 2e-3 * ratio, "K {lk}, v {lv}: {} vs {ratio}", lk / lv);
    assert!(a.contains(">ур</tspan>"));
    // a 3.5 mm text's font size gives capitals of at least 3.5 mm in the
    // lowest-capped face that may print it, Libertinus Serif Italic
    // (OS/2 sCapHeight 645 of 1000 units), and more in the others
    assert!(a.contains("font-size=\"5.426\""));
    assert!((5.426_f64 * 0.645 - 3.5).abs() < 1e-3);
    for cap_per_em in [1510.0 / 2048.0, 0.729, 0.683, 0.658, 0.645] {
        assert!(5.426 * cap_per_em >= 3.5 - 1e-3);
    }
}

/// With `TMM_DRAW_DUMP=DIR`, the sample scene is written there as SVG and
/// DXF, to render and look at (`rsvg-convert`, `scripts/dxf-audit.py --png`).
#[test]
fn dump_the_sample_when_asked() {
    let Ok(dir) = std::env::var("TMM_DRAW_DUMP") else { return };
    let scene = sample::scene();
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(format!("{dir}/sample.svg"), svg::render(&scene)).unwrap();
    std::fs::write(format!("{dir}/sample.dxf"), tmm_draw::dxf::render(&scene)).unwrap();
}

/// osifont 0.1.20220224 draws Э э Ё ё as boxes: the SVG keeps the letters
/// and sets each run of them in tmm's supplement, the rest in osifont.
#[test]
fn boxed_letters_are_set_in_the_supplement() {
    use kurbo::Point;
    use tmm_draw::{Scale, Scene, Text, TextHeight};
    let mut s = Scene::new(60.0, 20.0, Scale::NATURAL, Thickness::A4).unwrap();
    s.text("TEXT", Text::new(Point::new(1.0, 5.0), TextHeight::H3_5, "Расчёт Эпюра").unwrap())
        .unwrap();
    let a = svg::render(&s);
    let sup = format!("font-family=\"{}\">", svg::SUPPLEMENT_FONT_FAMILY);
    assert!(
        a.contains(&format!("{sup}ё</tspan>")) && a.contains(&format!("{sup}Э</tspan>")),
        "{a}"
    );
    assert!(
        a.contains(">Расч</tspan>") && a.contains(">т </tspan>") && a.contains(">пюра</tspan>"),
        "{a}"
    );
    // the runs share the text's type B width: the lengths add up to it
    let total: f64 = "Расчёт Эпюра".chars().map(|c| TextHeight::H3_5.advance(c)).sum();
    let sum: f64 = a
        .split("textLength=\"")
        .skip(1)
        .map(|t| t[..t.find('"').unwrap()].parse::<f64>().unwrap())
        .sum();
    assert!((sum - total).abs() < 5e-3, "{sum} vs {total}");
    // the supplement's family is the one the font file names
    assert_eq!(svg::SUPPLEMENT_FAMILY, "tmm GOST supplement");
    assert!(tmm_draw::dxf::render(&s).contains("Расчёт Эпюра"));
}
