//! DXF drawings for AutoCAD and KOMPAS: a thin layer over the `dxf` crate with
//! named, coloured layers and the entities tmm draws (lines, polylines, circles,
//! arcs, text). Coordinates are in millimetres (the unit CAD users expect);
//! callers convert from SI.

use dxf::entities::{Arc, Circle, Entity, EntityType, Line, LwPolyline, Text};
use dxf::enums::{AcadVersion, Units};
use dxf::tables::Layer;
use dxf::{Color, Drawing, LwPolylineVertex, Point};

/// A DXF document under construction.
pub struct DxfDoc {
    drawing: Drawing,
    layer: String,
}

impl Default for DxfDoc {
    fn default() -> Self {
        Self::new()
    }
}

impl DxfDoc {
    /// An empty AutoCAD 2000 drawing in millimetres.
    pub fn new() -> Self {
        let mut drawing = Drawing::new();
        drawing.header.version = AcadVersion::R2000;
        drawing.header.default_drawing_units = Units::Millimeters;
        DxfDoc {
            drawing,
            layer: "0".to_string(),
        }
    }

    /// Add a layer with an AutoCAD colour index (1 red, 2 yellow, 3 green,
    /// 4 cyan, 5 blue, 6 magenta, 7 white/black) and make it current.
    pub fn layer(&mut self, name: &str, aci: u8) {
        if !self.drawing.layers().any(|l| l.name == name) {
            self.drawing.add_layer(Layer {
                name: name.to_string(),
                color: Color::from_index(aci),
                ..Default::default()
            });
        }
        self.layer = name.to_string();
    }

    fn add(&mut self, t: EntityType) {
        let mut e = Entity::new(t);
        e.common.layer = self.layer.clone();
        self.drawing.add_entity(e);
    }

    /// A line segment (mm).
    pub fn line(&mut self, a: (f64, f64), b: (f64, f64)) {
        if [a.0, a.1, b.0, b.1].iter().all(|v| v.is_finite()) {
            self.add(EntityType::Line(Line::new(Point::new(a.0, a.1, 0.0), Point::new(b.0, b.1, 0.0))));
        }
    }

    /// A polyline through points (mm); non-finite points are dropped.
    pub fn polyline(&mut self, pts: &[(f64, f64)], closed: bool) {
        let mut p = LwPolyline {
            vertices: pts
                .iter()
                .filter(|q| q.0.is_finite() && q.1.is_finite())
                .map(|&(x, y)| LwPolylineVertex {
                    x,
                    y,
                    ..Default::default()
                })
                .collect(),
            ..Default::default()
        };
        if p.vertices.len() < 2 {
            return;
        }
        p.set_is_closed(closed);
        self.add(EntityType::LwPolyline(p));
    }

    /// A circle (mm).
    pub fn circle(&mut self, c: (f64, f64), r: f64) {
        if [c.0, c.1, r].iter().all(|v| v.is_finite()) && r > 0.0 {
            self.add(EntityType::Circle(Circle::new(Point::new(c.0, c.1, 0.0), r)));
        }
    }

    /// An arc (mm) from `a0` to `a1` degrees, counter-clockwise.
    pub fn arc(&mut self, c: (f64, f64), r: f64, a0_deg: f64, a1_deg: f64) {
        if [c.0, c.1, r, a0_deg, a1_deg].iter().all(|v| v.is_finite()) && r > 0.0 {
            self.add(EntityType::Arc(Arc::new(Point::new(c.0, c.1, 0.0), r, a0_deg, a1_deg)));
        }
    }

    /// Text (mm).
    pub fn text(&mut self, at: (f64, f64), height: f64, value: &str) {
        if at.0.is_finite() && at.1.is_finite() {
            let t = Text {
                location: Point::new(at.0, at.1, 0.0),
                text_height: height,
                value: value.to_string(),
                ..Default::default()
            };
            self.add(EntityType::Text(t));
        }
    }

    /// The drawing as DXF text, byte-identical for the same drawing: the
    /// date stamps and GUIDs the `dxf` crate fills from the clock and a
    /// random source are replaced by fixed values (see [`deterministic`]).
    pub fn to_bytes(&self) -> Result<Vec<u8>, crate::Error> {
        let mut buf = Vec::new();
        self.drawing
            .save(&mut buf)
            .map_err(|e| crate::Error::Io(format!("cannot encode a DXF drawing: {e}")))?;
        Ok(deterministic(&String::from_utf8_lossy(&buf)).into_bytes())
    }

    /// The drawing as DXF text (for tests).
    pub fn to_text(&self) -> Result<String, crate::Error> {
        self.to_bytes().map(|b| String::from_utf8_lossy(&b).into_owned())
    }
}

impl DxfDoc {
    /// Text (mm) turned by `rotation_deg` (CCW) about its alignment point
    /// `at`, aligned there at its left (`align` 0), centre (1) or right (2)
    /// end of the baseline.
    pub fn text_aligned(&mut self, at: (f64, f64), height: f64, value: &str, rotation_deg: f64, align: u8) {
        use dxf::enums::HorizontalTextJustification as J;
        if !(at.0.is_finite() && at.1.is_finite() && height.is_finite() && rotation_deg.is_finite()) || height <= 0.0 {
            return;
        }
        let p = Point::new(at.0, at.1, 0.0);
        let t = Text {
            location: p.clone(),
            second_alignment_point: p,
            text_height: height,
            value: value.to_string(),
            rotation: rotation_deg,
            horizontal_text_justification: match align {
                1 => J::Center,
                2 => J::Right,
                _ => J::Left,
            },
            ..Default::default()
        };
        self.add(EntityType::Text(t));
    }
}

/// Header variables that carry the time of writing or a random GUID.
const STAMPS: [&str; 8] = [
    "$TDCREATE",
    "$TDUCREATE",
    "$TDUPDATE",
    "$TDUUPDATE",
    "$TDINDWG",
    "$TDUSRTIMER",
    "$FINGERPRINTGUID",
    "$VERSIONGUID",
];

/// Replace the values of the time and GUID header variables by fixed ones:
/// dates by the Julian date 2451545.0 (1 January 2000, 12:00), durations by
/// zero, GUIDs by a nil-like constant. A DXF file is a sequence of
/// (group code, value) line pairs; a header variable is the pair `9`/name
/// followed by one value pair.
fn deterministic(text: &str) -> String {
    let lines: Vec<&str> = text.split_inclusive('\n').collect();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    while i < lines.len() {
        out.push_str(lines[i]);
        let name = lines[i].trim();
        if STAMPS.contains(&name) && i + 2 < lines.len() {
            let nl = if lines[i + 2].ends_with("\r\n") { "\r\n" } else { "\n" };
            out.push_str(lines[i + 1]);
            let value = match name {
                "$TDINDWG" | "$TDUSRTIMER" => "0.0",
                "$FINGERPRINTGUID" | "$VERSIONGUID" => "{00000000-0000-0000-0000-000000000000}",
                _ => "2451545.0",
            };
            out.push_str(value);
            out.push_str(nl);
            i += 3;
            continue;
        }
        i += 1;
    }
    out
}
