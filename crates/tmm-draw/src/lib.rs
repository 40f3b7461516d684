//! The drawing model of tmm (модель чертежа): every drawing is built once as
//! a [`Scene`] — typed elements in paper millimetres at a declared GOST 2.302
//! [`Scale`] — and rendered to SVG ([`svg`]) and DXF ([`dxf`]) from it, so
//! what a line *is* (a main outline, an axis, a dimension) reaches every
//! format.
//!
//! The GOST rules are enforced by construction: a [`Scale`] exists only for
//! GOST 2.302's ratios, a [`TextHeight`] only for GOST 2.304's series (no
//! lettering under 2.5 mm), a [`Thickness`] only in GOST 2.303's 0.5 … 1.4 mm,
//! and every [`LineType`] has its width and dash pattern as a function of s.
//! Like the other core crates it does no I/O and builds for wasm32: renderers
//! return strings. docs/drawing.md has the rules and their sources.
//!
//! ```
//! use kurbo::Point;
//! use tmm_draw::{Geom, LineType, Scale, Scene, Text, TextHeight, Thickness};
//! let mut scene = Scene::new(120.0, 80.0, Scale::reduction(2.0).unwrap(), Thickness::A4).unwrap();
//! // a 100 mm rod drawn at 1:2 is 50 mm on paper
//! let a = scene.place(Point::new(10.0, 10.0), Point::new(0.0, 0.0));
//! let b = scene.place(Point::new(10.0, 10.0), Point::new(100.0, 0.0));
//! assert_eq!(b.x - a.x, 50.0);
//! scene.stroke("MAIN", LineType::Main, Geom::Line(a, b)).unwrap();
//! scene.text("TEXT", Text::new(Point::new(10.0, 20.0), TextHeight::H3_5, "M_{ур}").unwrap()).unwrap();
//! let svg = tmm_draw::svg::render(&scene);
//! assert!(svg.contains("baseline-shift"));
//! let dxf = tmm_draw::dxf::render(&scene);
//! assert!(dxf.contains("GOST_DASHDOT"));
//! ```

mod arrow;
mod dimension;
mod error;
pub mod eskd;
pub mod face;
pub mod fixed;
mod hatch;
mod line;
pub mod sample;
mod scale;
pub mod scene;
pub mod simplify;
mod text;

pub mod dxf;
pub mod svg;

pub use arrow::{Arrow, HALF_ANGLE_DEG, arrow_length};
pub use dimension::{Dimension, OVERSHOOT, TEXT_GAP};
pub use error::DrawError;
pub use hatch::Hatch;
pub use line::{LegendStyle, LineType, Marker, Thickness};
pub use scale::Scale;
pub use scene::{Geom, Item, Layer, STANDARD_LAYERS, Scene, Shape};
pub use text::{Anchor, Rich, Span, Text, TextHeight, wrap};
