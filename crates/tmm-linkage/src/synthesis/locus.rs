//! The inscribed-angle locus of crank pivots (геометрическое место центров
//! вращения кривошипа): the crank pivot O of a mechanism whose driven joint
//! has the extreme positions C1, C2 must see the chord C1C2 at the angle θ,
//! since at the dead positions the crank and the coupler are collinear, the
//! extended one |OC| = l2 + l1 and the folded one |OC| = l2 − l1, and the
//! crank turns by π ± θ between them. By the inscribed-angle theorem the
//! locus is an arc of the circle whose centre O* sees the chord at 2θ
//! (seed 002 § 1 and examples 1, 2, 4; Artobolevsky, ТММ, 1988, § 26).
//!
//! Parametrisation (derived here, docs/synthesis.md § 2): on the arc on side
//! `s` of the chord, the triangle O C1 C2 has the angle θ at O and the angles
//! A ± w at C1 and C2 with A = (π − θ)/2, w ∈ (−A, A). By the law of sines,
//! with h = |C1C2|/2 and R = h / sin θ,
//!
//! - |OC1| = 2R sin(A − w), |OC2| = 2R sin(A + w),
//! - l1 = (|OC2| − |OC1|)/2 = h·sin w / cos(θ/2) (in absolute value),
//! - l2 = (|OC2| + |OC1|)/2 = h·cos w / sin(θ/2).
//!
//! For θ = 0 (K = 1) the locus is the line C1C2 outside the chord: the pivot
//! at distance t beyond C2 (or C1) has l1 = h, l2 = h + t; t = h·tan w,
//! w ∈ (0, π/2).

use std::f64::consts::{FRAC_PI_2, PI};

use tmm_geom::{Vec2, cross, perp};

use super::error::SynthesisError;
use super::result::LocusCircle;

/// The locus of crank pivots for the chord C1C2 seen at θ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Locus {
    /// First extreme position.
    pub c1: Vec2,
    /// Second extreme position.
    pub c2: Vec2,
    /// θ, rad, in [0, π).
    pub theta: f64,
    /// Half the chord, m.
    pub h: f64,
    u: Vec2,
}

fn rot(v: Vec2, a: f64) -> Vec2 {
    let (s, c) = a.sin_cos();
    Vec2::new(c * v.x - s * v.y, s * v.x + c * v.y)
}

impl Locus {
    /// The locus for the extreme positions `c1`, `c2` and θ.
    pub fn new(c1: Vec2, c2: Vec2, theta: f64) -> Result<Self, SynthesisError> {
        let h = 0.5 * (c2 - c1).hypot();
        if !(h.is_finite() && h > 1e-12) {
            return Err(SynthesisError::input(
                "extreme positions",
                "the two extreme positions coincide: the output would not move",
            ));
        }
        if !(theta.is_finite() && (0.0..PI).contains(&theta)) {
            return Err(SynthesisError::input("theta", "θ must lie in [0, π)"));
        }
        Ok(Locus {
            c1,
            c2,
            theta,
            h,
            u: (c2 - c1) * (0.5 / h),
        })
    }

    /// The parameter domain (open interval) of `point`.
    pub fn domain(&self) -> (f64, f64) {
        if self.theta == 0.0 {
            (0.0, FRAC_PI_2)
        } else {
            let a = 0.5 * (PI - self.theta);
            (-a, a)
        }
    }

    /// The pivot on side `side` (±1: left or right of C1→C2) at parameter `w`.
    pub fn point(&self, side: f64, w: f64) -> Vec2 {
        if self.theta == 0.0 {
            let t = self.h * w.tan();
            return if side > 0.0 { self.c2 + self.u * t } else { self.c1 - self.u * t };
        }
        let a = 0.5 * (PI - self.theta);
        let r = self.h / self.theta.sin();
        let d1 = 2.0 * r * (a - w).sin();
        self.c1 + rot(self.u, side * (a + w)) * d1
    }

    /// Crank and coupler lengths (l1, l2) of the pivot `o`: from the distances
    /// to the extreme positions (extended |OC| = l2 + l1, folded l2 − l1).
    pub fn lengths(&self, o: Vec2) -> (f64, f64) {
        let (a, b) = ((o - self.c1).hypot(), (o - self.c2).hypot());
        (0.5 * (a - b).abs(), 0.5 * (a + b))
    }

    /// Whether `o` sees the chord at θ (to 1e-9 rad), i.e. lies on the locus.
    pub fn sees(&self, o: Vec2) -> bool {
        let (a, b) = (self.c1 - o, self.c2 - o);
        if a.hypot() < 1e-12 || b.hypot() < 1e-12 {
            return false;
        }
        let ang = cross(a, b).abs().atan2(a.dot(b));
        (ang - self.theta).abs() < 1e-9
    }

    /// The circle of the locus on side `side` (`None` for θ = 0).
    pub fn circle(&self, side: f64) -> Option<LocusCircle> {
        if self.theta == 0.0 {
            return None;
        }
        let m = (self.c1 + self.c2) * 0.5;
        let n = perp(self.u) * side;
        let center = m + n * (self.h / self.theta.tan());
        let radius = self.h / self.theta.sin();
        let a1 = (self.c1 - center).atan2();
        let a2 = (self.c2 - center).atan2();
        // the arc on the side `n` of the chord: from C2 round to C1 through the
        // point centre + n·R
        let top = n.atan2();
        let mut s1 = tmm_geom::angle::wrap_pi(a1 - top);
        let mut s2 = tmm_geom::angle::wrap_pi(a2 - top);
        if s1 < s2 {
            std::mem::swap(&mut s1, &mut s2);
        }
        Some(LocusCircle {
            center,
            radius,
            arc_start: top + s2,
            arc_sweep: s1 - s2,
        })
    }

    /// Intersections of the locus (side `side`) with the line through `p`
    /// along `dir`, that see the chord at θ.
    pub fn meet_line(&self, side: f64, p: Vec2, dir: Vec2) -> Vec<Vec2> {
        let dl = dir.hypot();
        if dl < 1e-300 || !dl.is_finite() {
            return vec![];
        }
        let d = dir * (1.0 / dl);
        let mut out = Vec::with_capacity(2);
        match self.circle(side) {
            Some(c) => {
                // |p + t d − c|² = R²
                let q = p - c.center;
                let b = q.dot(d);
                let disc = b * b - (q.hypot2() - c.radius * c.radius);
                if disc >= 0.0 {
                    let s = disc.sqrt();
                    out.push(p + d * (-b - s));
                    out.push(p + d * (-b + s));
                }
            }
            None => {
                // line C1C2 meets the given line
                let den = cross(self.u, d);
                if den.abs() > 1e-12 {
                    let t = cross(p - self.c1, d) / den;
                    out.push(self.c1 + self.u * t);
                }
            }
        }
        out.retain(|o| self.sees(*o) && self.on_side(side, *o));
        out
    }

    /// Intersections of the locus (side `side`) with the circle about `q` of
    /// radius `r`, that see the chord at θ.
    pub fn meet_circle(&self, side: f64, q: Vec2, r: f64) -> Vec<Vec2> {
        let mut out = Vec::with_capacity(2);
        match self.circle(side) {
            Some(c) => {
                let dv = c.center - q;
                let dd = dv.hypot();
                if dd > 1e-15 && dd <= r + c.radius && dd >= (r - c.radius).abs() {
                    let a = (r * r - c.radius * c.radius + dd * dd) / (2.0 * dd);
                    let hh = (r * r - a * a).max(0.0).sqrt();
                    let e = dv * (1.0 / dd);
                    let base = q + e * a;
                    out.push(base + perp(e) * hh);
                    out.push(base - perp(e) * hh);
                }
            }
            None => {
                let qq = q - self.c1;
                let b = qq.dot(self.u);
                let disc = b * b - (qq.hypot2() - r * r);
                if disc >= 0.0 {
                    let s = disc.sqrt();
                    out.push(self.c1 + self.u * (b - s));
                    out.push(self.c1 + self.u * (b + s));
                }
            }
        }
        out.retain(|o| self.sees(*o) && self.on_side(side, *o));
        out
    }

    /// Whether `o` is on side `side` of the chord (θ > 0) or beyond the end
    /// of side `side` (θ = 0).
    fn on_side(&self, side: f64, o: Vec2) -> bool {
        if self.theta == 0.0 {
            let t = (o - self.c1).dot(self.u);
            if side > 0.0 { t > 2.0 * self.h } else { t < 0.0 }
        } else {
            cross(self.u, o - self.c1) * side > 0.0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points_see_the_chord_at_theta_and_lengths_match_the_closed_form() {
        let l = Locus::new(Vec2::new(0.1, 0.3), Vec2::new(0.4, 0.2), 0.5).unwrap();
        let (lo, hi) = l.domain();
        for k in 1..50 {
            let w = lo + (hi - lo) * k as f64 / 50.0;
            for side in [1.0, -1.0] {
                let o = l.point(side, w);
                assert!(l.sees(o), "w = {w}");
                let (l1, l2) = l.lengths(o);
                let t2 = 0.5 * l.theta;
                assert!((l1 - l.h * w.sin().abs() / t2.cos()).abs() < 1e-12);
                assert!((l2 - l.h * w.cos() / t2.sin()).abs() < 1e-12);
            }
        }
    }
}
