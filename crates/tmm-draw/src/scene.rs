//! The scene (сцена чертежа): one drawing as typed elements in paper
//! millimetres (x right, y up, origin at the bottom-left corner of the
//! drawing's area), on named layers, at one declared GOST 2.302 scale and
//! one main-line thickness s. Renderers ([`crate::svg`], [`crate::dxf`])
//! read it; nothing is parsed back.

use kurbo::Point;

use crate::{Arrow, Dimension, DrawError, Hatch, LineType, Scale, Text, Thickness};

/// A layer (слой): a name, an AutoCAD colour index and the line type its
/// elements usually have (which gives its DXF linetype and lineweight).
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Layer {
    /// The layer's name (ASCII, as CAD programs list it).
    pub name: String,
    /// AutoCAD colour index: 1 red, 2 yellow, 3 green, 4 cyan, 5 blue,
    /// 6 magenta, 7 black on white paper, 8 grey.
    pub aci: u8,
    /// The usual line type of the layer.
    pub line: LineType,
}

/// The layers every scene starts with.
pub const STANDARD_LAYERS: [(&str, u8, LineType); 8] = [
    ("MAIN", 7, LineType::Main),
    ("THIN", 7, LineType::Thin),
    ("AXIS", 1, LineType::Axis),
    ("HIDDEN", 6, LineType::Dashed),
    ("HATCH", 8, LineType::Thin),
    ("DIM", 3, LineType::Thin),
    ("TEXT", 7, LineType::Thin),
    ("FRAME", 7, LineType::Main),
];

/// A stroked geometry in paper mm.
#[derive(Clone, Debug, PartialEq)]
pub enum Geom {
    /// A segment.
    Line(Point, Point),
    /// A polyline, closed or open.
    Polyline {
        /// The vertices.
        points: Vec<Point>,
        /// Whether the last vertex joins the first.
        closed: bool,
    },
    /// A circle.
    Circle {
        /// Centre.
        center: Point,
        /// Radius, mm.
        radius: f64,
    },
    /// A circular arc counter-clockwise from `start_deg` to `end_deg`.
    Arc {
        /// Centre.
        center: Point,
        /// Radius, mm.
        radius: f64,
        /// Start angle, degrees from +x.
        start_deg: f64,
        /// End angle, degrees from +x (reached counter-clockwise).
        end_deg: f64,
    },
    /// Cubic Bézier pieces joined end to end.
    Curve(Vec<kurbo::CubicBez>),
}

impl Geom {
    fn finite(&self) -> bool {
        let p = |q: &Point| q.x.is_finite() && q.y.is_finite();
        match self {
            Geom::Line(a, b) => p(a) && p(b),
            Geom::Polyline { points, .. } => points.iter().all(p),
            Geom::Circle { center, radius } => p(center) && radius.is_finite(),
            Geom::Arc {
                center,
                radius,
                start_deg,
                end_deg,
            } => p(center) && radius.is_finite() && start_deg.is_finite() && end_deg.is_finite(),
            Geom::Curve(c) => c.iter().all(|b| [b.p0, b.p1, b.p2, b.p3].iter().all(p)),
        }
    }

    fn check(&self) -> Result<(), DrawError> {
        if !self.finite() {
            return Err(DrawError::NotFinite("a point or radius"));
        }
        match self {
            Geom::Polyline { points, .. } if points.len() < 2 => Err(DrawError::Degenerate("a polyline needs two points")),
            Geom::Circle { radius, .. } | Geom::Arc { radius, .. } if *radius <= 0.0 => {
                Err(DrawError::Degenerate("a circle or arc needs a positive radius"))
            }
            Geom::Curve(c) if c.is_empty() => Err(DrawError::Degenerate("a curve needs one piece")),
            _ => Ok(()),
        }
    }

    /// The geometry as points (arcs and curves flattened to within
    /// `tolerance` mm), for renderers without the primitive.
    pub fn flatten(&self, tolerance: f64) -> Vec<Point> {
        match self {
            Geom::Line(a, b) => vec![*a, *b],
            Geom::Polyline { points, closed } => {
                let mut v = points.clone();
                if *closed {
                    v.push(points[0]);
                }
                v
            }
            Geom::Circle { center, radius } => arc_points(*center, *radius, 0.0, 360.0, tolerance),
            Geom::Arc {
                center,
                radius,
                start_deg,
                end_deg,
            } => arc_points(*center, *radius, *start_deg, *end_deg, tolerance),
            Geom::Curve(c) => {
                let mut v = vec![c[0].p0];
                for b in c {
                    kurbo::flatten(kurbo::Shape::path_elements(b, tolerance), tolerance, |el| {
                        if let kurbo::PathEl::LineTo(p) = el {
                            v.push(p);
                        }
                    });
                }
                v
            }
        }
    }
}

/// The sweep of an arc from `a0` to `a1` counter-clockwise, degrees in (0, 360].
pub fn sweep_deg(a0: f64, a1: f64) -> f64 {
    let d = (a1 - a0).rem_euclid(360.0);
    if d < 1e-9 { 360.0 } else { d }
}

fn arc_points(c: Point, r: f64, a0: f64, a1: f64, tol: f64) -> Vec<Point> {
    let sweep = sweep_deg(a0, a1).to_radians();
    // chord error r(1 − cos(θ/2)) ≤ tol
    let step = 2.0 * (1.0 - (tol / r).min(1.0)).acos();
    let n = ((sweep / step.max(1e-3)).ceil() as usize).clamp(4, 720);
    (0..=n)
        .map(|i| {
            let t = a0.to_radians() + sweep * i as f64 / n as f64;
            Point::new(c.x + r * t.cos(), c.y + r * t.sin())
        })
        .collect()
}

/// What an element is.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// A line of a GOST 2.303 type.
    Stroke {
        /// The line type.
        line: LineType,
        /// The geometry.
        geom: Geom,
    },
    /// A filled arrowhead.
    Arrow(Arrow),
    /// A hatched region.
    Hatch(Hatch),
    /// Lettering.
    Text(Text),
    /// A dimension (its lines, arrows and number).
    Dimension(Dimension),
}

/// An element: a shape on a layer (by index into the scene's layers).
#[derive(Clone, Debug, PartialEq)]
pub struct Item {
    /// Index of the layer in [`Scene::layers`].
    pub layer: usize,
    /// The shape.
    pub shape: Shape,
}

/// A drawing: its paper size, scale, line thickness, layers and elements.
///
/// ```
/// use tmm_draw::{LineType, Scale, Scene, Thickness};
/// use kurbo::Point;
/// let mut s = Scene::new(100.0, 50.0, Scale::NATURAL, Thickness::A4).unwrap();
/// s.stroke("MAIN", LineType::Main, tmm_draw::Geom::Line(Point::new(0.0, 0.0), Point::new(10.0, 0.0))).unwrap();
/// assert_eq!(s.items().len(), 1);
/// assert!(s.stroke("NOPE", LineType::Main, tmm_draw::Geom::Line(Point::ZERO, Point::new(1.0, 1.0))).is_err());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// Width of the drawing's area, paper mm.
    pub width: f64,
    /// Height of the drawing's area, paper mm.
    pub height: f64,
    /// The declared scale: model lengths × factor = paper lengths.
    pub scale: Scale,
    /// The main line's thickness.
    pub s: Thickness,
    layers: Vec<Layer>,
    items: Vec<Item>,
}

impl Scene {
    /// An empty scene with the [`STANDARD_LAYERS`].
    pub fn new(width: f64, height: f64, scale: Scale, s: Thickness) -> Result<Scene, DrawError> {
        if !(width.is_finite() && height.is_finite() && width > 0.0 && height > 0.0) {
            return Err(DrawError::Degenerate("a scene needs a positive finite size"));
        }
        Ok(Scene {
            width,
            height,
            scale,
            s,
            layers: STANDARD_LAYERS
                .iter()
                .map(|&(name, aci, line)| Layer {
                    name: name.to_string(),
                    aci,
                    line,
                })
                .collect(),
            items: Vec::new(),
        })
    }

    /// Declare another layer (or change a declared one's colour and line).
    pub fn layer(&mut self, name: &str, aci: u8, line: LineType) {
        match self.layers.iter_mut().find(|l| l.name == name) {
            Some(l) => {
                l.aci = aci;
                l.line = line;
            }
            None => self.layers.push(Layer {
                name: name.to_string(),
                aci,
                line,
            }),
        }
    }

    /// The declared layers.
    pub fn layers(&self) -> &[Layer] {
        &self.layers
    }

    /// The elements in drawing order.
    pub fn items(&self) -> &[Item] {
        &self.items
    }

    fn layer_index(&self, name: &str) -> Result<usize, DrawError> {
        self.layers
            .iter()
            .position(|l| l.name == name)
            .ok_or_else(|| DrawError::UnknownLayer(name.to_string()))
    }

    /// A model point (mm on the object, relative to the model origin) on
    /// the paper, with the model origin at paper point `origin`.
    pub fn place(&self, origin: Point, model_mm: Point) -> Point {
        Point::new(
            origin.x + self.scale.to_paper(model_mm.x),
            origin.y + self.scale.to_paper(model_mm.y),
        )
    }

    /// Add a shape on a layer, checked (finite, not degenerate).
    pub fn add(&mut self, layer: &str, shape: Shape) -> Result<(), DrawError> {
        let layer = self.layer_index(layer)?;
        match &shape {
            Shape::Stroke { geom, .. } => geom.check()?,
            Shape::Arrow(a) => a.check()?,
            Shape::Hatch(h) => h.check()?,
            Shape::Text(t) => {
                if !(t.at.x.is_finite() && t.at.y.is_finite()) {
                    return Err(DrawError::NotFinite("text position"));
                }
            }
            Shape::Dimension(d) => d.check()?,
        }
        self.items.push(Item { layer, shape });
        Ok(())
    }

    /// A line of type `line` on `layer`.
    pub fn stroke(&mut self, layer: &str, line: LineType, geom: Geom) -> Result<(), DrawError> {
        self.add(layer, Shape::Stroke { line, geom })
    }

    /// Text on `layer`.
    pub fn text(&mut self, layer: &str, text: Text) -> Result<(), DrawError> {
        self.add(layer, Shape::Text(text))
    }

    /// Place every element of `other` into this scene moved by `offset`
    /// (paper mm), each on the layer of the same name (declared here, with
    /// `other`'s colour and line type, when it is not yet). A sheet places
    /// its drawings this way: each keeps its own scale, written in its
    /// caption.
    ///
    /// ```
    /// use tmm_draw::{Geom, LineType, Scale, Scene, Thickness};
    /// use kurbo::{Point, Vec2};
    /// let mut d = Scene::new(50.0, 50.0, Scale::NATURAL, Thickness::A1).unwrap();
    /// d.layer("C_0050C0", 5, LineType::Thin);
    /// d.stroke("C_0050C0", LineType::Thin, Geom::Line(Point::new(0.0, 0.0), Point::new(10.0, 0.0))).unwrap();
    /// let mut sheet = Scene::new(841.0, 594.0, Scale::NATURAL, Thickness::A1).unwrap();
    /// sheet.insert(&d, Vec2::new(100.0, 200.0));
    /// assert!(sheet.layers().iter().any(|l| l.name == "C_0050C0" && l.aci == 5));
    /// match &sheet.items()[0].shape {
    ///     tmm_draw::Shape::Stroke { geom: Geom::Line(a, _), .. } => assert_eq!(*a, Point::new(100.0, 200.0)),
    ///     _ => unreachable!(),
    /// }
    /// ```
    pub fn insert(&mut self, other: &Scene, offset: kurbo::Vec2) {
        let map: Vec<usize> = other
            .layers
            .iter()
            .map(|l| match self.layers.iter().position(|m| m.name == l.name) {
                Some(i) => i,
                None => {
                    self.layers.push(l.clone());
                    self.layers.len() - 1
                }
            })
            .collect();
        for it in &other.items {
            self.items.push(Item {
                layer: map[it.layer],
                shape: translated(&it.shape, offset),
            });
        }
    }

    /// The scale's caption with the "М" prefix (масштаб), as written under
    /// a view or in the title block: "М 1:2,5".
    pub fn scale_caption(&self, decimal: char) -> String {
        format!("М {}", self.scale.caption(decimal))
    }
}

fn moved_geom(g: &Geom, v: kurbo::Vec2) -> Geom {
    match g {
        Geom::Line(a, b) => Geom::Line(*a + v, *b + v),
        Geom::Polyline { points, closed } => Geom::Polyline {
            points: points.iter().map(|&p| p + v).collect(),
            closed: *closed,
        },
        Geom::Circle { center, radius } => Geom::Circle {
            center: *center + v,
            radius: *radius,
        },
        Geom::Arc {
            center,
            radius,
            start_deg,
            end_deg,
        } => Geom::Arc {
            center: *center + v,
            radius: *radius,
            start_deg: *start_deg,
            end_deg: *end_deg,
        },
        Geom::Curve(c) => Geom::Curve(
            c.iter()
                .map(|b| kurbo::CubicBez::new(b.p0 + v, b.p1 + v, b.p2 + v, b.p3 + v))
                .collect(),
        ),
    }
}

/// A shape moved by `v` on the paper.
fn translated(s: &Shape, v: kurbo::Vec2) -> Shape {
    match s {
        Shape::Stroke { line, geom } => Shape::Stroke {
            line: *line,
            geom: moved_geom(geom, v),
        },
        Shape::Arrow(a) => Shape::Arrow(Arrow {
            tip: a.tip + v,
            dir: a.dir,
        }),
        Shape::Hatch(h) => Shape::Hatch(Hatch {
            loops: h.loops.iter().map(|l| l.iter().map(|&p| p + v).collect()).collect(),
            ..h.clone()
        }),
        Shape::Text(t) => Shape::Text(Text { at: t.at + v, ..t.clone() }),
        Shape::Dimension(d) => Shape::Dimension(match d {
            Dimension::Linear {
                a,
                b,
                offset,
                text,
                height,
            } => Dimension::Linear {
                a: *a + v,
                b: *b + v,
                offset: *offset,
                text: text.clone(),
                height: *height,
            },
            Dimension::Angular {
                center,
                radius,
                start_deg,
                end_deg,
                text,
                height,
            } => Dimension::Angular {
                center: *center + v,
                radius: *radius,
                start_deg: *start_deg,
                end_deg: *end_deg,
                text: text.clone(),
                height: *height,
            },
            Dimension::Radius {
                center,
                radius,
                angle_deg,
                text,
                height,
            } => Dimension::Radius {
                center: *center + v,
                radius: *radius,
                angle_deg: *angle_deg,
                text: text.clone(),
                height: *height,
            },
        }),
    }
}
