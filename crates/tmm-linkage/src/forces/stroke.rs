//! The stroke of the output link (ход выходного звена): its two dead
//! positions (крайние положения), which of the two strokes is the working one,
//! and, at any crank angle, the phase of the cycle — working or return, the
//! travel from the start of the working stroke, and the crank angle since then.
//!
//! The output coordinate is the slider's position along its guide (m) for a
//! slider on the frame, otherwise the link's angle (rad). Dead positions are
//! the zeros of its rate: sampled at 0.5° steps of the crank and refined by
//! Brent's method (tmm-geom `root::brent`).
//!
//! The working stroke is by default the slower one — the one taking the larger
//! crank angle, 180° + θ (Kv = (180° + θ)/(180° − θ) ≥ 1, seed 002 §1) — or the
//! one in which the output coordinate increases / decreases when asked.

use std::f64::consts::PI;

use tmm_geom::{Vec2, angle::wrap_2pi, cross};

use super::error::ForceError;
use crate::mechanism::Pair;
use crate::state::LinkState;
use crate::{Mechanism, Solution};

/// Which stroke of the output is the working one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Working {
    /// The stroke taking the larger crank angle (the slower one).
    Slower,
    /// The stroke in which the output coordinate increases.
    Increasing,
    /// The stroke in which the output coordinate decreases.
    Decreasing,
}

/// The phase of the cycle at one crank angle.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Phase {
    /// `true` on the working stroke.
    pub working: bool,
    /// Travel from the start of the working stroke, m or rad, ≥ 0.
    pub travel: f64,
    /// The stroke H, m or rad.
    pub travel_max: f64,
    /// Crank angle since the start of the working stroke, rad in [0, 2π).
    pub angle: f64,
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Coord {
    /// Slider on a frame guide: point (slider-local), guide point and direction (global).
    Slider { ps: Vec2, q: Vec2, d: Vec2 },
    /// Rotation of the link.
    Rotation,
}

/// The dead positions and stroke of the output link.
#[derive(Debug, Clone, PartialEq)]
pub struct Stroke {
    /// The output link.
    pub output: usize,
    /// `true` when the travel is an angle (a rocker), `false` for a slider.
    pub angular: bool,
    /// Crank angle at the start of the working stroke, rad.
    pub phi_start: f64,
    /// Crank angle at the end of the working stroke, rad.
    pub phi_end: f64,
    /// Crank angle turned during the working stroke, rad.
    pub work_span: f64,
    /// The stroke H (m or rad).
    pub travel: f64,
    coord: Coord,
    /// The output's state at the start of the working stroke.
    start: LinkState,
    dir: f64,
}

impl Stroke {
    /// Find the dead positions of the output link `output` and the working stroke.
    pub fn find(m: &Mechanism, output: usize, working: Working) -> Result<Self, ForceError> {
        let coord = m
            .pairs
            .iter()
            .find_map(|p| match *p {
                Pair::P {
                    slider,
                    guide: 0,
                    ps,
                    q,
                    d,
                    ..
                } if slider == output => Some(Coord::Slider { ps, q, d }),
                _ => None,
            })
            .unwrap_or(Coord::Rotation);
        let dir = m.crank.omega.signum();
        let mut sol = m.solution();
        let rate = |sol: &mut Solution, phi: f64| -> Result<f64, ForceError> {
            m.solve(phi, sol)?;
            Ok(coord_rate(coord, &sol.links[output]))
        };
        // a position that does not solve is an error here, not a gap
        let mut failed = None;
        let dead = crate::cycle::periodic_roots(m.assembly_angle, dir, 720, |x| match rate(&mut sol, x) {
            Ok(v) => v,
            Err(e) => {
                failed.get_or_insert(e);
                f64::NAN
            }
        });
        if let Some(e) = failed {
            return Err(e);
        }
        let name = &m.link_names[output];
        if dead.len() != 2 {
            return Err(ForceError::load(
                "resistance",
                format!(
                    "the output link `{name}` has {} dead positions over a turn of the crank, not 2: its working stroke is not defined; give the resistance as a constant",
                    dead.len()
                ),
            ));
        }
        let mut states = [LinkState::default(); 2];
        for (i, &p) in dead.iter().enumerate() {
            m.solve(p, &mut sol)?;
            states[i] = sol.links[output];
        }
        let q = |s: &LinkState, r: &LinkState| coord_delta(coord, r, s);
        // q(1) − q(0): > 0 when the output coordinate grows from dead 0 to dead 1
        let grow01 = q(&states[1], &states[0]);
        let span01 = wrap_2pi((dead[1] - dead[0]) * dir);
        let span10 = 2.0 * PI - span01;
        let first = match working {
            Working::Slower => {
                if (span01 - span10).abs() <= crate::cycle::KV_TIE * 2.0 * PI {
                    return Err(crate::cycle::kv_tie(span01, span10).into());
                }
                span01 >= span10
            }
            Working::Increasing => grow01 > 0.0,
            Working::Decreasing => grow01 < 0.0,
        };
        let (s, e, span, st) = if first {
            (dead[0], dead[1], span01, states[0])
        } else {
            (dead[1], dead[0], span10, states[1])
        };
        Ok(Stroke {
            output,
            angular: coord == Coord::Rotation,
            phi_start: s,
            phi_end: e,
            work_span: span,
            travel: grow01.abs(),
            coord,
            start: st,
            dir,
        })
    }

    /// The output coordinate's travel from the start of the working stroke, ≥ 0.
    #[inline]
    pub fn travel_at(&self, s: &LinkState) -> f64 {
        coord_delta(self.coord, &self.start, s).abs()
    }

    /// The crank angle from the start of the working stroke (rad, in the
    /// direction of rotation) where the output's travel from the start of the
    /// working stroke is `target` (0…H): on the working stroke when `working`,
    /// else on the return. The travel is monotonic on each stroke between the
    /// two dead positions, so bisection on the angle brackets it (derived
    /// here; П3's φ′ and φ″, the crank angles where the cutting starts and
    /// where the returning ram passes the overrun, Chernaya & Timofeev 2019,
    /// p. 131).
    ///
    /// ```
    /// use tmm_geom::Vec2;
    /// use tmm_linkage::forces::stroke::{Stroke, Working};
    /// use tmm_linkage::{AssemblyHint, HintKind, InputDef, LinkDef, Mechanism, MechanismDef, SliderDef};
    /// // an axial crank-slider, r = 0.1, l = 0.4: the slider's x is r·cos φ + √(l² − r²·sin² φ);
    /// // its decreasing stroke starts at the outer dead centre φ = 0
    /// let def = MechanismDef {
    ///     fixed: vec![("O".into(), Vec2::new(0.0, 0.0))],
    ///     links: vec![LinkDef::bar("1", "O", "A", 0.1), LinkDef::bar("2", "A", "B", 0.4), LinkDef::block("3", "B")],
    ///     sliders: vec![SliderDef { slider: "3".into(), point: "B".into(), guide_link: "frame".into(),
    ///                               through: Vec2::new(0.0, 0.0), angle: 0.0, angle_on_slider: 0.0 }],
    ///     input: Some(InputDef { link: "1".into(), pivot: "O".into(), pin: "A".into(), omega: 1.0, epsilon: 0.0 }),
    ///     hints: vec![AssemblyHint { point: "B".into(), kind: HintKind::Near(Vec2::new(0.5, 0.0)) }],
    ///     ..Default::default()
    /// };
    /// let m = Mechanism::new(&def).unwrap();
    /// let s = Stroke::find(&m, m.link("3").unwrap(), Working::Decreasing).unwrap();
    /// let mut sol = m.solution();
    /// let a = s.angle_at_travel(&m, &mut sol, 0.05, true).unwrap();
    /// let (r, l) = (0.1f64, 0.4f64);
    /// let x = |f: f64| r * f.cos() + (l * l - (r * f.sin()).powi(2)).sqrt();
    /// assert!((x(0.0) - x(a) - 0.05).abs() < 1e-9);
    /// ```
    pub fn angle_at_travel(&self, m: &Mechanism, sol: &mut Solution, target: f64, working: bool) -> Result<f64, ForceError> {
        let (mut lo, mut hi) = if working {
            (0.0, self.work_span)
        } else {
            (self.work_span, 2.0 * PI)
        };
        // g(angle) = travel − target grows on the working stroke and falls on the return
        let sign = if working { 1.0 } else { -1.0 };
        let mut g = |a: f64| -> Result<f64, ForceError> {
            m.solve(self.phi_start + self.dir * a, sol)?;
            Ok(sign * (self.travel_at(&sol.links[self.output]) - target))
        };
        for _ in 0..64 {
            let mid = 0.5 * (lo + hi);
            if g(mid)? < 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Ok(0.5 * (lo + hi))
    }

    /// The phase of the cycle of a solved position.
    #[inline]
    pub fn phase(&self, sol: &Solution) -> Phase {
        let a = (sol.phi - self.phi_start) * self.dir;
        // φ and φ_start lie in [0, 2π) as a rule: one shift instead of a
        // remainder (the same value as wrap_2pi there)
        let angle = if (0.0..2.0 * PI).contains(&a) {
            a
        } else if (-2.0 * PI..0.0).contains(&a) && a + 2.0 * PI < 2.0 * PI {
            a + 2.0 * PI
        } else {
            wrap_2pi(a)
        };
        let angle = if angle >= 2.0 * PI - 1e-12 { 0.0 } else { angle };
        Phase {
            working: angle <= self.work_span + 1e-12,
            travel: self.travel_at(&sol.links[self.output]),
            travel_max: self.travel,
            angle,
        }
    }
}

/// The rate of the output coordinate: slider speed along its guide, or ω.
#[inline]
fn coord_rate(c: Coord, s: &LinkState) -> f64 {
    match c {
        Coord::Slider { ps, d, .. } => s.point(ps).v.dot(d),
        Coord::Rotation => s.omega,
    }
}

/// Coordinate of state `s` minus that of `r`.
#[inline]
fn coord_delta(c: Coord, r: &LinkState, s: &LinkState) -> f64 {
    match c {
        Coord::Slider { ps, q, d } => (s.pos(ps) - q).dot(d) - (r.pos(ps) - q).dot(d),
        Coord::Rotation => cross(r.u, s.u).atan2(r.u.dot(s.u)),
    }
}
