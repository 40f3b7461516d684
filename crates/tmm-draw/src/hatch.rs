//! Hatching of sections (штриховка), GOST 2.306-68: parallel thin lines at
//! 45° to the frame, 1 … 10 mm apart depending on the hatched area (the
//! same spacing and direction for every section of one part). A hatch is
//! kept as a region and a pattern, so the DXF gets a HATCH entity; SVG and
//! PDF draw its lines ([`Hatch::lines`]).

use kurbo::{Point, Vec2};

use crate::DrawError;

/// A hatched region: closed boundary loops (the even-odd rule: a loop inside
/// another is a hole) and the line pattern.
#[derive(Clone, Debug, PartialEq)]
pub struct Hatch {
    /// Closed loops of paper points (the last joins the first).
    pub loops: Vec<Vec<Point>>,
    /// Angle of the lines, degrees from +x (45 or 135 by GOST 2.306).
    pub angle_deg: f64,
    /// Distance between the lines, mm.
    pub spacing: f64,
}

impl Hatch {
    /// A GOST 2.306 hatch: lines at 45° (or 135° when `mirrored`, for an
    /// adjacent part), `spacing` 1 … 10 mm.
    ///
    /// ```
    /// use tmm_draw::Hatch;
    /// use kurbo::Point;
    /// let sq = vec![Point::new(0.0, 0.0), Point::new(10.0, 0.0), Point::new(10.0, 10.0), Point::new(0.0, 10.0)];
    /// assert!(Hatch::gost(vec![sq.clone()], 2.0, false).is_ok());
    /// assert!(Hatch::gost(vec![sq], 0.5, false).is_err());
    /// ```
    pub fn gost(loops: Vec<Vec<Point>>, spacing: f64, mirrored: bool) -> Result<Hatch, DrawError> {
        if !(spacing.is_finite() && (1.0..=10.0).contains(&spacing)) {
            return Err(DrawError::Degenerate("GOST 2.306 hatch lines are 1 … 10 mm apart"));
        }
        let h = Hatch {
            loops,
            angle_deg: if mirrored { 135.0 } else { 45.0 },
            spacing,
        };
        h.check()?;
        Ok(h)
    }

    pub(crate) fn check(&self) -> Result<(), DrawError> {
        if self.loops.is_empty() || self.loops.iter().any(|l| l.len() < 3) {
            return Err(DrawError::Degenerate("a hatch needs closed loops of three points or more"));
        }
        if !self.loops.iter().flatten().all(|p| p.x.is_finite() && p.y.is_finite()) {
            return Err(DrawError::NotFinite("a hatch boundary point"));
        }
        Ok(())
    }

    /// The hatch lines clipped to the region (even-odd), paper mm. Lines
    /// pass through the points k·spacing along the normal from the origin,
    /// so neighbouring regions with the same pattern line up.
    pub fn lines(&self) -> Vec<(Point, Point)> {
        let (s, c) = self.angle_deg.to_radians().sin_cos();
        let u = Vec2::new(c, s);
        let n = Vec2::new(-s, c);
        let pts = self.loops.iter().flatten();
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for p in pts {
            let d = p.to_vec2().dot(n);
            lo = lo.min(d);
            hi = hi.max(d);
        }
        let mut out = Vec::new();
        let mut k = (lo / self.spacing).ceil() as i64;
        while (k as f64) * self.spacing <= hi {
            let d = k as f64 * self.spacing;
            // crossings of the line {x·n = d} with every edge, as positions along u
            let mut ts: Vec<f64> = Vec::new();
            for l in &self.loops {
                for i in 0..l.len() {
                    let (a, b) = (l[i], l[(i + 1) % l.len()]);
                    let (da, db) = (a.to_vec2().dot(n) - d, b.to_vec2().dot(n) - d);
                    if (da < 0.0) != (db < 0.0) {
                        let t = da / (da - db);
                        ts.push((a + (b - a) * t).to_vec2().dot(u));
                    }
                }
            }
            ts.sort_by(f64::total_cmp);
            for w in ts.chunks_exact(2) {
                let base = n * d;
                out.push(((base + u * w[0]).to_point(), (base + u * w[1]).to_point()));
            }
            k += 1;
        }
        out
    }
}
