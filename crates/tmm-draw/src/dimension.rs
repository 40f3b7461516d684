//! Dimensions (размеры), GOST 2.307-2011: a linear, angular or radius
//! dimension kept as one element and drawn as thin lines, arrows and its
//! number ([`Dimension::parts`]), the same way in every renderer.
//!
//! The rules drawn: extension lines run 2 mm past the dimension line (the
//! standard allows 1 … 5 mm); arrows touch the extension lines (or the arc)
//! from inside, and go outside when the space between them is shorter than
//! two arrows and a gap; the number stands over the dimension line near its
//! middle, parallel to it, 1 mm clear of it, and is turned so that it reads
//! from below or from the right; an angular number stands over the arc,
//! along its tangent; a radius number carries the sign "R" and stands over
//! the line from the centre to the arc, which has one arrow at the arc.

use kurbo::{Point, Vec2};

use crate::{Anchor, Arrow, DrawError, Geom, LineType, Rich, Shape, Text, TextHeight, Thickness, arrow_length};

/// How far extension lines run past the dimension line, mm (GOST 2.307: 1 … 5).
pub const OVERSHOOT: f64 = 2.0;
/// The clearance between a dimension line and its number, mm.
pub const TEXT_GAP: f64 = 1.0;

/// A dimension.
#[derive(Clone, Debug, PartialEq)]
pub enum Dimension {
    /// The distance between `a` and `b`, its line parallel to a–b at
    /// `offset` mm to the left of the direction a → b (negative: right).
    Linear {
        /// First measured point.
        a: Point,
        /// Second measured point.
        b: Point,
        /// Signed distance of the dimension line from a–b, mm.
        offset: f64,
        /// The number (and sign) written.
        text: Rich,
        /// Its height.
        height: TextHeight,
    },
    /// An angle at `center` from `start_deg` counter-clockwise to `end_deg`,
    /// its arc at `radius`.
    Angular {
        /// The vertex.
        center: Point,
        /// Radius of the dimension arc, mm.
        radius: f64,
        /// Start direction, degrees.
        start_deg: f64,
        /// End direction, degrees.
        end_deg: f64,
        /// The number written.
        text: Rich,
        /// Its height.
        height: TextHeight,
    },
    /// The radius of an arc: a line from `center` to the arc in direction
    /// `angle_deg`, an arrow at the arc.
    Radius {
        /// The arc's centre.
        center: Point,
        /// The arc's radius, paper mm.
        radius: f64,
        /// Direction of the dimension line, degrees.
        angle_deg: f64,
        /// The number written (with "R").
        text: Rich,
        /// Its height.
        height: TextHeight,
    },
}

fn finite(p: Point) -> bool {
    p.x.is_finite() && p.y.is_finite()
}

/// The rotation, degrees, that makes text along `dir` read from below or
/// from the right (GOST 2.307's zones), and whether the text was flipped.
fn readable(dir: Vec2) -> f64 {
    let a = dir.y.atan2(dir.x).to_degrees();
    // keep in (−90°, 90°]; a vertical line reads from the right (90°)
    if a > 90.0 + 1e-9 {
        a - 180.0
    } else if a <= -90.0 + 1e-9 {
        a + 180.0
    } else {
        a
    }
}

impl Dimension {
    pub(crate) fn check(&self) -> Result<(), DrawError> {
        let ok = match self {
            Dimension::Linear { a, b, offset, .. } => finite(*a) && finite(*b) && offset.is_finite(),
            Dimension::Angular {
                center,
                radius,
                start_deg,
                end_deg,
                ..
            } => finite(*center) && radius.is_finite() && start_deg.is_finite() && end_deg.is_finite(),
            Dimension::Radius {
                center, radius, angle_deg, ..
            } => finite(*center) && radius.is_finite() && angle_deg.is_finite(),
        };
        if !ok {
            return Err(DrawError::NotFinite("a dimension's point or size"));
        }
        match self {
            Dimension::Linear { a, b, .. } if (*b - *a).hypot() < 1e-9 => {
                Err(DrawError::Degenerate("a linear dimension needs two distinct points"))
            }
            Dimension::Angular { radius, .. } | Dimension::Radius { radius, .. } if *radius <= 0.0 => {
                Err(DrawError::Degenerate("an angular or radius dimension needs a positive radius"))
            }
            _ => Ok(()),
        }
    }

    /// The dimension as thin lines, arrows and text, paper mm.
    pub fn parts(&self, s: Thickness) -> Vec<Shape> {
        let thin = |geom| Shape::Stroke {
            line: LineType::Thin,
            geom,
        };
        let al = arrow_length(s);
        let mut out = Vec::new();
        match self {
            Dimension::Linear {
                a,
                b,
                offset,
                text,
                height,
            } => {
                let ab = *b - *a;
                let len = ab.hypot();
                let u = ab / len;
                let n = Vec2::new(-u.y, u.x);
                let off = n * *offset;
                let (pa, pb) = (*a + off, *b + off);
                let sign = if *offset >= 0.0 { 1.0 } else { -1.0 };
                if offset.abs() > 1e-9 {
                    out.push(thin(Geom::Line(*a, pa + n * (OVERSHOOT * sign))));
                    out.push(thin(Geom::Line(*b, pb + n * (OVERSHOOT * sign))));
                }
                let inside = len >= 2.0 * al + 2.0;
                if inside {
                    out.push(thin(Geom::Line(pa, pb)));
                    out.push(Shape::Arrow(Arrow { tip: pa, dir: -u }));
                    out.push(Shape::Arrow(Arrow { tip: pb, dir: u }));
                } else {
                    // arrows outside, pointing in, the line carried past them
                    out.push(thin(Geom::Line(pa - u * (al + 2.0), pb + u * (al + 2.0))));
                    out.push(Shape::Arrow(Arrow { tip: pa, dir: u }));
                    out.push(Shape::Arrow(Arrow { tip: pb, dir: -u }));
                }
                let rot = readable(u);
                let (sr, cr) = rot.to_radians().sin_cos();
                let up = Vec2::new(-sr, cr); // "above" for the turned text
                let mid = pa.midpoint(pb) + up * TEXT_GAP;
                out.push(Shape::Text(Text {
                    at: mid,
                    height: *height,
                    rich: text.clone(),
                    anchor: Anchor::Middle,
                    rotation_deg: rot,
                    width_factor: 1.0,
                }));
            }
            Dimension::Angular {
                center,
                radius,
                start_deg,
                end_deg,
                text,
                height,
            } => {
                out.push(thin(Geom::Arc {
                    center: *center,
                    radius: *radius,
                    start_deg: *start_deg,
                    end_deg: *end_deg,
                }));
                let at = |deg: f64| {
                    let (s, c) = deg.to_radians().sin_cos();
                    (*center + Vec2::new(c, s) * *radius, Vec2::new(-s, c))
                };
                let (p0, t0) = at(*start_deg);
                let (p1, t1) = at(*end_deg);
                out.push(Shape::Arrow(Arrow { tip: p0, dir: -t0 }));
                out.push(Shape::Arrow(Arrow { tip: p1, dir: t1 }));
                let mid = start_deg + crate::scene::sweep_deg(*start_deg, *end_deg) / 2.0;
                let (pm, tm) = at(mid);
                let rot = readable(tm);
                let radial = (pm - *center) / *radius;
                out.push(Shape::Text(Text {
                    at: pm + radial * TEXT_GAP,
                    height: *height,
                    rich: text.clone(),
                    anchor: Anchor::Middle,
                    rotation_deg: rot,
                    width_factor: 1.0,
                }));
            }
            Dimension::Radius {
                center,
                radius,
                angle_deg,
                text,
                height,
            } => {
                let (s_, c) = angle_deg.to_radians().sin_cos();
                let u = Vec2::new(c, s_);
                let tip = *center + u * *radius;
                out.push(thin(Geom::Line(*center, tip)));
                out.push(Shape::Arrow(Arrow { tip, dir: u }));
                let rot = readable(u);
                let (sr, cr) = rot.to_radians().sin_cos();
                let up = Vec2::new(-sr, cr);
                out.push(Shape::Text(Text {
                    at: center.midpoint(tip) + up * TEXT_GAP,
                    height: *height,
                    rich: text.clone(),
                    anchor: Anchor::Middle,
                    rotation_deg: rot,
                    width_factor: 1.0,
                }));
            }
        }
        out
    }
}
