//! Loads on sliders as the course gives them, along the slider's frame
//! guide through its joint:
//!
//! - the gas force on a piston (сила давления газов), F = p·πd²/4 with the
//!   gauge pressure p of the cylinder's indicator diagram ([`Indicator`]),
//!   directed from the outer dead centre toward the inner one: a positive
//!   pressure pushes the piston away from the cylinder head (П2:
//!   F_3X = +(πd²/4)·p₃ for the left piston, F_5X = −(πd²/4)·p₅ for the
//!   right one);
//! - a force by travel acting on one stroke only, against the slider's
//!   motion on that stroke, and only within a window of the stroke (the
//!   shaper's cutting force with overrun, перебег: none in the first and
//!   last 5 % — П3);
//! - a friction force (сила трения) of constant magnitude against the
//!   slider's velocity on both strokes, zero where the slider stands (П3:
//!   F_трX = −F_тр·sign V_S5X).
//!
//! Travel is measured from a dead position of the slider (its outer dead
//! centre for a piston, the start of the acting stroke for a stroke force),
//! found once by [`Stroke::find`].

use std::f64::consts::PI;

use tmm_geom::Vec2;

use super::error::ForceError;
use super::indicator::{Indicator, TravelScale};
use super::spline::Curve;
use super::stroke::{Stroke, Working};
use crate::mechanism::Pair;
use crate::{Mechanism, Solution};

/// What a slider load is.
#[derive(Debug, Clone, PartialEq)]
pub enum SliderLoadKind {
    /// Gas pressure on a piston of bore `bore` (m).
    Gas {
        /// Bore d, m (> 0).
        bore: f64,
        /// The indicator diagram.
        indicator: Indicator,
    },
    /// A force by travel on one stroke, opposing the motion there.
    StrokeForce {
        /// Force (N) against travel from the start of the acting stroke.
        table: Curve,
        /// How the travel is given.
        travel: TravelScale,
        /// Which stroke it acts on.
        working: Working,
        /// The window of the stroke where it acts, fractions of H: from, to.
        window: (f64, f64),
        /// The arm l_p of the force's line of action (m): the line is
        /// parallel to the guide, placed so that the force's moment about
        /// the slider's point is F·l_p, F the force's component along the
        /// guide's direction (П3: the cutting force's couple
        /// M_5 = F_резX·l_p about S₅, Chernaya & Timofeev 2019, p. 131).
        /// The line is the guide's line shifted by −l_p along the guide's
        /// normal n (the direction turned +90°): (−l_p·n) × F·d = F·l_p.
        arm: f64,
    },
    /// Friction of constant magnitude (N, ≥ 0) against the velocity.
    Friction {
        /// |F|, N.
        force: f64,
    },
}

/// A load on a slider.
#[derive(Debug, Clone, PartialEq)]
pub struct SliderLoad {
    /// The slider (index into [`Mechanism::link_names`]).
    pub link: usize,
    /// What it is.
    pub kind: SliderLoadKind,
}

/// A slider load prepared for one mechanism: its guide and stroke found.
#[derive(Debug, Clone, PartialEq)]
pub struct ActiveSliderLoad {
    /// The load.
    pub load: SliderLoad,
    /// The slider's point on the guide, slider-local.
    pub local: Vec2,
    /// Unit direction of the guide, global.
    pub dir: Vec2,
    /// The slider's stroke (dead positions), measured in the direction
    /// given by the load: for a gas force from the outer dead centre.
    pub stroke: Stroke,
    /// For a gas force: the unit vector of the force for a positive
    /// pressure, from the outer dead centre (travel 0) to the inner one.
    pub push: Vec2,
    /// For a stroke force: the unit vector of the motion on the acting stroke.
    pub motion: Vec2,
    /// Piston area πd²/4, m² (gas force), else 0.
    pub area: f64,
    /// The absolute crank angles (rad) where a stroke force's window opens
    /// and closes on its acting stroke: the load jumps there.
    pub edges: Vec<f64>,
}

impl SliderLoad {
    /// Find the slider's guide and stroke in `m`; check the tables against
    /// the stroke and the machine's cycle `period` (rad). `field` names the
    /// load in messages (`sliders[0]`).
    pub fn prepare(&self, m: &Mechanism, period: f64, field: &str) -> Result<ActiveSliderLoad, ForceError> {
        let Some((ps, d)) = m.pairs.iter().find_map(|p| match *p {
            Pair::P {
                slider, guide: 0, ps, d, ..
            } if slider == self.link => Some((ps, d)),
            _ => None,
        }) else {
            return Err(ForceError::load(
                format!("{field}.link"),
                format!(
                    "link `{}` is not a slider on a frame guide; a piston, cutting or friction force acts on one",
                    m.link_names.get(self.link).map_or("?", |s| s.as_str())
                ),
            ));
        };
        let dir = d * (1.0 / d.hypot());
        let mut sol = m.solution();
        let pos_at = |sol: &mut Solution, phi: f64| -> Result<Vec2, ForceError> {
            m.solve(phi, sol)?;
            Ok(sol.links[self.link].pos(ps))
        };
        let mut edges = Vec::new();
        let (stroke, push, motion, area) = match &self.kind {
            SliderLoadKind::Gas { bore, indicator } => {
                if !(bore.is_finite() && *bore > 0.0) {
                    return Err(ForceError::load(
                        format!("{field}.bore"),
                        format!("the bore must be > 0 m, not {bore}"),
                    ));
                }
                // the outer dead centre is the one farther from the crank's pivot
                let inc = Stroke::find(m, self.link, Working::Increasing)?;
                let pivot = m.crank.pivot;
                let a = (pos_at(&mut sol, inc.phi_start)? - pivot).hypot();
                let b = (pos_at(&mut sol, inc.phi_end)? - pivot).hypot();
                let (stroke, push) = if a >= b {
                    (inc, dir)
                } else {
                    (Stroke::find(m, self.link, Working::Decreasing)?, -dir)
                };
                indicator.check(period, stroke.travel, field)?;
                (stroke, push, Vec2::ZERO, 0.25 * PI * bore * bore)
            }
            SliderLoadKind::StrokeForce {
                table,
                travel,
                working,
                window,
                arm,
            } => {
                if !(arm.is_finite() && arm.abs() <= crate::limits::MAX_LENGTH) {
                    return Err(ForceError::load(
                        format!("{field}.arm"),
                        format!("the arm must be a length within ±{} m, not {arm}", crate::limits::MAX_LENGTH),
                    ));
                }
                let s = Stroke::find(m, self.link, *working)?;
                let end = travel.end(s.travel);
                let tol = 1e-9 * end;
                if table.first() > tol || table.last() < end - tol {
                    return Err(ForceError::load(
                        format!("{field}.table"),
                        format!(
                            "the force table covers travel {}…{} but the stroke is 0…{end}{}; give forces over the whole stroke",
                            table.first(),
                            table.last(),
                            if *travel == TravelScale::Stroke { "·H" } else { " m" }
                        ),
                    ));
                }
                let (w0, w1) = *window;
                if !(w0.is_finite() && w1.is_finite() && 0.0 <= w0 && w0 < w1 && w1 <= 1.0) {
                    return Err(ForceError::load(
                        format!("{field}.window"),
                        format!("the window must be fractions of the stroke with 0 ≤ from < to ≤ 1, not {w0}…{w1}"),
                    ));
                }
                let mv = pos_at(&mut sol, s.phi_end)? - pos_at(&mut sol, s.phi_start)?;
                let motion = if mv.dot(dir) >= 0.0 { dir } else { -dir };
                for w in [w0, w1] {
                    if w > 0.0 && w < 1.0 {
                        let a = s.angle_at_travel(m, &mut sol, w * s.travel, true)?;
                        edges.push(s.phi_start + m.crank.omega.signum() * a);
                    }
                }
                (s, Vec2::ZERO, motion, 0.0)
            }
            SliderLoadKind::Friction { force } => {
                if !(force.is_finite() && *force >= 0.0) {
                    return Err(ForceError::load(
                        format!("{field}.force"),
                        format!("the friction force must be ≥ 0 N, not {force}"),
                    ));
                }
                (Stroke::find(m, self.link, Working::Increasing)?, Vec2::ZERO, Vec2::ZERO, 0.0)
            }
        };
        Ok(ActiveSliderLoad {
            load: self.clone(),
            local: ps,
            dir,
            stroke,
            push,
            motion,
            area,
            edges,
        })
    }
}

impl ActiveSliderLoad {
    /// The force on the slider (global, N) and its point (global) in the
    /// solved position `sol` at cycle angle `psi` (rad, in [0, period]).
    /// Allocates nothing.
    #[inline]
    pub fn force(&self, sol: &Solution, psi: f64) -> (Vec2, Vec2) {
        let st = &sol.links[self.load.link];
        let p = st.pos(self.local);
        let mut at = p;
        let f = match &self.load.kind {
            SliderLoadKind::Gas { indicator, .. } => {
                let h = self.stroke.travel;
                let s = self.stroke.travel_at(st).clamp(0.0, h);
                self.push * (self.area * indicator.pressure(psi, s, h))
            }
            SliderLoadKind::StrokeForce {
                table,
                travel,
                window,
                arm,
                ..
            } => {
                // the line of action l_p off the guide (see `arm`)
                at = p - Vec2::new(-self.dir.y, self.dir.x) * *arm;
                let ph = self.stroke.phase(sol);
                let h = self.stroke.travel;
                let s = ph.travel.clamp(0.0, h);
                let moving = st.kin_at(p).0.dot(self.motion) > 0.0;
                if ph.working && moving && s >= window.0 * h && s <= window.1 * h {
                    self.motion * -table.eval(travel.abscissa(s, h))
                } else {
                    Vec2::ZERO
                }
            }
            SliderLoadKind::Friction { force } => {
                let v = st.kin_at(p).0.dot(self.dir);
                if v.abs() > 1e-12 {
                    self.dir * (-force * v.signum())
                } else {
                    Vec2::ZERO
                }
            }
        };
        (f, at)
    }

    /// The crank angles (absolute, rad) where the load may jump or kink:
    /// the slider's dead positions, and the edges of a stroke force's window.
    pub fn dead_positions(&self) -> impl Iterator<Item = f64> + '_ {
        [self.stroke.phi_start, self.stroke.phi_end]
            .into_iter()
            .chain(self.edges.iter().copied())
    }

    /// The cycle angles (rad from its start) where the process changes.
    pub fn process_bounds(&self) -> impl Iterator<Item = f64> + '_ {
        let procs: &[super::indicator::Process] = match &self.load.kind {
            SliderLoadKind::Gas { indicator, .. } => &indicator.processes,
            _ => &[],
        };
        procs.iter().map(|p| p.from)
    }
}
