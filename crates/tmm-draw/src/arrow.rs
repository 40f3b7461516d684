//! Arrowheads (стрелки), GOST 2.307-2011: a filled narrow triangle whose
//! tip touches the line it points at. The standard sizes the arrow by the
//! main line's thickness and shows it with an angle of about 20° at the
//! tip; tmm takes a length of 5·s, at least 2.5 mm (3.5 mm at s = 0.7),
//! the range drafting textbooks give (2.5 … 5 mm).

use kurbo::{Point, Vec2};

use crate::{DrawError, Thickness};

/// The half-angle at the tip, degrees (GOST 2.307's drawing: about 20° whole).
pub const HALF_ANGLE_DEG: f64 = 10.0;

/// The arrow's length for main-line thickness `s`, mm.
///
/// ```
/// use tmm_draw::{arrow_length, Thickness};
/// assert_eq!(arrow_length(Thickness::A1), 3.5);
/// assert_eq!(arrow_length(Thickness::A4), 2.5);
/// ```
pub fn arrow_length(s: Thickness) -> f64 {
    (5.0 * s.mm()).clamp(2.5, 5.0)
}

/// An arrowhead: its tip and the direction it points (from tail to tip).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Arrow {
    /// The tip, paper mm.
    pub tip: Point,
    /// The direction it points; need not be unit length.
    pub dir: Vec2,
}

impl Arrow {
    pub(crate) fn check(&self) -> Result<(), DrawError> {
        if ![self.tip.x, self.tip.y, self.dir.x, self.dir.y].iter().all(|v| v.is_finite()) {
            return Err(DrawError::NotFinite("an arrow's tip or direction"));
        }
        if self.dir.hypot() < 1e-12 {
            return Err(DrawError::Degenerate("an arrow needs a direction"));
        }
        Ok(())
    }

    /// The triangle's corners (tip first) for thickness `s`.
    pub fn corners(&self, s: Thickness) -> [Point; 3] {
        let len = arrow_length(s);
        let u = self.dir / self.dir.hypot();
        let n = Vec2::new(-u.y, u.x);
        let half = len * HALF_ANGLE_DEG.to_radians().tan();
        let base = self.tip - u * len;
        [self.tip, base + n * half, base - n * half]
    }
}
