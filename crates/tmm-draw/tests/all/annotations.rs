//! Dimensions, arrows and hatches checked against their GOST geometry.

use kurbo::{Point, Vec2};
use tmm_draw::{Arrow, Dimension, Geom, HALF_ANGLE_DEG, Hatch, OVERSHOOT, Rich, Shape, TEXT_GAP, TextHeight, Thickness, arrow_length};

#[test]
fn a_linear_dimension_has_overshooting_extensions_touching_arrows_and_its_number_above() {
    let (a, b) = (Point::new(0.0, 0.0), Point::new(60.0, 0.0));
    let d = Dimension::Linear {
        a,
        b,
        offset: 15.0,
        text: Rich::plain_text("120"),
        height: TextHeight::H3_5,
    };
    let parts = d.parts(Thickness::A1);
    let lines: Vec<(Point, Point)> = parts
        .iter()
        .filter_map(|p| match p {
            Shape::Stroke {
                geom: Geom::Line(p, q), ..
            } => Some((*p, *q)),
            _ => None,
        })
        .collect();
    // extension lines from the measured points to 2 mm past the dimension line
    assert!(lines.contains(&(a, Point::new(0.0, 15.0 + OVERSHOOT))));
    assert!(lines.contains(&(b, Point::new(60.0, 15.0 + OVERSHOOT))));
    // the dimension line between the extension lines, arrows' tips on them, pointing out
    assert!(lines.contains(&(Point::new(0.0, 15.0), Point::new(60.0, 15.0))));
    let arrows: Vec<Arrow> = parts
        .iter()
        .filter_map(|p| if let Shape::Arrow(a) = p { Some(*a) } else { None })
        .collect();
    assert_eq!(arrows.len(), 2);
    assert!(arrows.iter().any(|a| a.tip == Point::new(0.0, 15.0) && a.dir.x < 0.0));
    assert!(arrows.iter().any(|a| a.tip == Point::new(60.0, 15.0) && a.dir.x > 0.0));
    // the number over the middle, 1 mm clear, unturned
    let t = parts
        .iter()
        .find_map(|p| if let Shape::Text(t) = p { Some(t) } else { None })
        .unwrap();
    assert_eq!((t.at, t.rotation_deg), (Point::new(30.0, 15.0 + TEXT_GAP), 0.0));
}

#[test]
fn a_vertical_dimension_reads_from_the_right() {
    // GOST 2.307: numbers of vertical dimensions read from the right (turned +90°)
    for (a, b) in [((0.0, 0.0), (0.0, 40.0)), ((0.0, 40.0), (0.0, 0.0))] {
        let d = Dimension::Linear {
            a: Point::new(a.0, a.1),
            b: Point::new(b.0, b.1),
            offset: 10.0,
            text: Rich::plain_text("80"),
            height: TextHeight::H3_5,
        };
        let t = d
            .parts(Thickness::A1)
            .into_iter()
            .find_map(|p| if let Shape::Text(t) = p { Some(t) } else { None })
            .unwrap();
        assert!((t.rotation_deg - 90.0).abs() < 1e-9, "{}", t.rotation_deg);
    }
}

#[test]
fn an_arrow_is_a_narrow_triangle_of_the_stated_size() {
    let a = Arrow {
        tip: Point::new(10.0, 5.0),
        dir: Vec2::new(3.0, 4.0),
    };
    let c = a.corners(Thickness::A1);
    let len = arrow_length(Thickness::A1);
    let base = c[1].midpoint(c[2]);
    assert!(((c[0] - base).hypot() - len).abs() < 1e-12);
    // the base points back along the direction
    let u = Vec2::new(0.6, 0.8);
    assert!(((c[0] - base).normalize() - u).hypot() < 1e-12);
    // the whole angle at the tip is 2 × HALF_ANGLE_DEG
    let (v1, v2) = (c[1] - c[0], c[2] - c[0]);
    let ang = (v1.dot(v2) / (v1.hypot() * v2.hypot())).acos().to_degrees();
    assert!((ang - 2.0 * HALF_ANGLE_DEG).abs() < 1e-9);
}

#[test]
fn hatch_lines_are_at_45_degrees_spacing_apart_and_end_on_the_boundary() {
    let sq = vec![
        Point::new(0.0, 0.0),
        Point::new(20.0, 0.0),
        Point::new(20.0, 10.0),
        Point::new(0.0, 10.0),
    ];
    let h = Hatch::gost(vec![sq], 2.0, false).unwrap();
    let lines = h.lines();
    // lines x − y = c through the rectangle for c in (−10, 20), 2√2 apart along x
    let cs: Vec<f64> = lines.iter().map(|(p, _)| p.x - p.y).collect();
    let expected = ((-10.0 / (2.0 * 2f64.sqrt())).ceil() as i64..=(20.0 / (2.0 * 2f64.sqrt())).floor() as i64).count();
    assert_eq!(lines.len(), expected);
    for w in cs.windows(2) {
        // neighbours are spacing apart, measured perpendicular to the lines
        assert!(((w[0] - w[1]).abs() / 2f64.sqrt() - 2.0).abs() < 1e-9, "{cs:?}");
    }
    let on_edge = |p: Point| {
        let e = 1e-9;
        (p.x.abs() < e || (p.x - 20.0).abs() < e || p.y.abs() < e || (p.y - 10.0).abs() < e)
            && (-e..=20.0 + e).contains(&p.x)
            && (-e..=10.0 + e).contains(&p.y)
    };
    for (p, q) in &lines {
        let d = *q - *p;
        assert!((d.x - d.y).abs() < 1e-9 && d.x > 0.0, "45°: {d:?}");
        assert!(on_edge(*p) && on_edge(*q));
    }
    // a hole is left unhatched (even-odd)
    let outer = vec![
        Point::new(0.0, 0.0),
        Point::new(20.0, 0.0),
        Point::new(20.0, 20.0),
        Point::new(0.0, 20.0),
    ];
    let hole = vec![
        Point::new(5.0, 5.0),
        Point::new(15.0, 5.0),
        Point::new(15.0, 15.0),
        Point::new(5.0, 15.0),
    ];
    let h = Hatch::gost(vec![outer, hole], 2.0, false).unwrap();
    for (p, q) in h.lines() {
        let m = p.midpoint(q);
        assert!(
            !(m.x > 5.0 + 1e-9 && m.x < 15.0 - 1e-9 && m.y > 5.0 + 1e-9 && m.y < 15.0 - 1e-9),
            "{m:?}"
        );
    }
}
