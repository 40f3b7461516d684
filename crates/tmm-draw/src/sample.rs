//! A sample scene (образец) with one element of every kind — each line
//! type, an arc, a circle, a curve, a hatch, the three dimensions, plain
//! and indexed Cyrillic and Greek text — for the tests, the DXF audit
//! script and the documentation.

use kurbo::{CubicBez, Point};

use crate::{Dimension, Geom, Hatch, LineType, Rich, Scale, Scene, Shape, Text, TextHeight, Thickness};

/// The sample scene: 200 × 120 mm at 1:2, s = 0.7 mm.
pub fn scene() -> Scene {
    let mut s = match Scene::new(200.0, 120.0, Scale::reduction(2.0).unwrap_or(Scale::NATURAL), Thickness::A1) {
        Ok(s) => s,
        Err(_) => unreachable!("the sample's size is positive"),
    };
    let p = Point::new;
    let mut add = |layer: &str, shape: Shape| {
        let _ = s.add(layer, shape);
    };
    // a 20 × 10 plate (model 40 × 20 mm at 1:2) outlined, hatched, with axes
    let plate = vec![p(20.0, 20.0), p(80.0, 20.0), p(80.0, 50.0), p(20.0, 50.0)];
    add(
        "MAIN",
        Shape::Stroke {
            line: LineType::Main,
            geom: Geom::Polyline {
                points: plate.clone(),
                closed: true,
            },
        },
    );
    if let Ok(h) = Hatch::gost(vec![plate], 2.0, false) {
        add("HATCH", Shape::Hatch(h));
    }
    add(
        "AXIS",
        Shape::Stroke {
            line: LineType::Axis,
            geom: Geom::Line(p(15.0, 35.0), p(85.0, 35.0)),
        },
    );
    add(
        "HIDDEN",
        Shape::Stroke {
            line: LineType::Dashed,
            geom: Geom::Line(p(20.0, 60.0), p(80.0, 60.0)),
        },
    );
    add(
        "THIN",
        Shape::Stroke {
            line: LineType::Phantom,
            geom: Geom::Line(p(20.0, 66.0), p(80.0, 66.0)),
        },
    );
    add(
        "THIN",
        Shape::Stroke {
            line: LineType::Thin,
            geom: Geom::Line(p(20.0, 72.0), p(80.0, 72.0)),
        },
    );
    // a crank circle with its centre lines and an arc
    add(
        "MAIN",
        Shape::Stroke {
            line: LineType::Main,
            geom: Geom::Circle {
                center: p(140.0, 45.0),
                radius: 20.0,
            },
        },
    );
    add(
        "AXIS",
        Shape::Stroke {
            line: LineType::Axis,
            geom: Geom::Line(p(115.0, 45.0), p(165.0, 45.0)),
        },
    );
    add(
        "AXIS",
        Shape::Stroke {
            line: LineType::Axis,
            geom: Geom::Line(p(140.0, 20.0), p(140.0, 70.0)),
        },
    );
    add(
        "MAIN",
        Shape::Stroke {
            line: LineType::Main,
            geom: Geom::Arc {
                center: p(140.0, 45.0),
                radius: 28.0,
                start_deg: 20.0,
                end_deg: 70.0,
            },
        },
    );
    add(
        "THIN",
        Shape::Stroke {
            line: LineType::Thin,
            geom: Geom::Curve(vec![CubicBez::new(
                p(120.0, 100.0),
                p(140.0, 115.0),
                p(160.0, 85.0),
                p(190.0, 105.0),
            )]),
        },
    );
    let t = |x: f64, y: f64, h: TextHeight, m: &str| Text::new(p(x, y), h, m).ok();
    let rich = |m: &str| Rich::parse(m).unwrap_or_default();
    add(
        "DIM",
        Shape::Dimension(Dimension::Linear {
            a: p(20.0, 20.0),
            b: p(80.0, 20.0),
            offset: -10.0,
            text: rich("40"),
            height: TextHeight::H3_5,
        }),
    );
    add(
        "DIM",
        Shape::Dimension(Dimension::Radius {
            center: p(140.0, 45.0),
            radius: 20.0,
            angle_deg: 225.0,
            text: rich("R20"),
            height: TextHeight::H3_5,
        }),
    );
    add(
        "DIM",
        Shape::Dimension(Dimension::Angular {
            center: p(140.0, 45.0),
            radius: 35.0,
            start_deg: 20.0,
            end_deg: 70.0,
            text: rich("50°"),
            height: TextHeight::H3_5,
        }),
    );
    for text in [
        t(20.0, 100.0, TextHeight::H5, "Кривошип ОА"),
        t(20.0, 90.0, TextHeight::H3_5, "K_v = 1,4; R^τ_{12} = 5 кН; M_{ур} = 12 Н·м; ω_1"),
        t(150.0, 10.0, TextHeight::H3_5, "М 1:2"),
    ]
    .into_iter()
    .flatten()
    {
        add("TEXT", Shape::Text(text));
    }
    s
}
