//! The useful resistance (сила / момент полезного сопротивления): what it
//! acts on, and its law over the cycle — the load diagram of the assignment
//! (диаграмма нагрузки) as a table over the output's travel or the crank
//! angle, constant on the working stroke and zero on the return, a sine of
//! travel (seed 003: F = F_max·sin(π·s/H)), or simply constant.
//!
//! Travel s is measured from the dead position that begins the working stroke
//! (seed 002, §2), in metres for a slider and radians for a rocker; H is the
//! stroke. The crank angle of an angle table is measured from the same dead
//! position in the direction of rotation, 0…2π.

use tmm_geom::Vec2;

use super::error::ForceError;
use super::stroke::{Phase, Stroke};
use crate::state::LinkState;

/// How the resistance acts on its link.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Action {
    /// A force at a point of the link (local coordinates). With a global unit
    /// direction `dir` the force is `value·dir`; without, it opposes the
    /// velocity of the point (zero while the point stands).
    Force {
        /// The point, link-local, m.
        local: Vec2,
        /// Fixed global direction (unit), or `None` to oppose the motion.
        dir: Option<Vec2>,
    },
    /// A moment on the link. With `sign` = ±1 the moment is `value·sign`
    /// (counter-clockwise positive); without, it opposes the link's rotation.
    Moment {
        /// ±1, or `None` to oppose the rotation.
        sign: Option<f64>,
    },
}

/// The magnitude of the resistance over the cycle.
#[derive(Debug, Clone, PartialEq)]
pub enum Law {
    /// The same value at every crank angle.
    Constant(f64),
    /// The value on the working stroke, zero on the return.
    WorkingStroke(f64),
    /// `F_max·sin(π·s/H)` on the working stroke, zero on the return (seed 003, §10).
    SineOfTravel(f64),
    /// A load diagram: value at travel s (m or rad) from the start of the working
    /// stroke, linear between points, zero on the return. Must cover 0…H.
    TravelTable(Vec<(f64, f64)>),
    /// A load diagram over the crank angle (rad) from the start of the working
    /// stroke, linear between points. Must cover 0…2π.
    AngleTable(Vec<(f64, f64)>),
}

/// The useful resistance on one link.
#[derive(Debug, Clone, PartialEq)]
pub struct Resistance {
    /// The link it acts on (index into [`crate::Mechanism::link_names`]).
    pub link: usize,
    /// How it acts.
    pub action: Action,
    /// Its law.
    pub law: Law,
}

impl Law {
    /// `true` when the law needs the dead positions of the output.
    pub fn needs_stroke(&self) -> bool {
        !matches!(self, Law::Constant(_))
    }

    /// Check the law's own numbers (`field` names it in messages).
    pub fn check(&self, field: &str) -> Result<(), ForceError> {
        let finite = |v: f64, what: &str| {
            if v.is_finite() {
                Ok(())
            } else {
                Err(ForceError::load(format!("{field}.{what}"), "must be finite"))
            }
        };
        match self {
            Law::Constant(v) | Law::WorkingStroke(v) | Law::SineOfTravel(v) => finite(*v, "value"),
            Law::TravelTable(t) | Law::AngleTable(t) => {
                if t.len() < 2 {
                    return Err(ForceError::load(
                        format!("{field}.table"),
                        "a load diagram needs at least two points [x, value]",
                    ));
                }
                for (i, &(x, v)) in t.iter().enumerate() {
                    finite(x, &format!("table[{i}]"))?;
                    finite(v, &format!("table[{i}]"))?;
                    if i > 0 && x <= t[i - 1].0 {
                        return Err(ForceError::load(
                            format!("{field}.table[{i}]"),
                            format!("the abscissae must increase: {} after {}", x, t[i - 1].0),
                        ));
                    }
                }
                Ok(())
            }
        }
    }

    /// Check that a table covers what it must: travel 0…H, or crank angle 0…2π.
    /// `fmt` renders an abscissa for the message (units of the caller).
    pub fn check_cover(&self, field: &str, stroke: Option<&Stroke>, fmt: &dyn Fn(f64, bool) -> String) -> Result<(), ForceError> {
        let tol = 1e-9;
        match self {
            Law::TravelTable(t) => {
                let Some(s) = stroke else {
                    return Err(ForceError::load(
                        field,
                        "a load diagram over travel needs an output that stops and returns (dead positions)",
                    ));
                };
                let (lo, hi) = (t[0].0, t[t.len() - 1].0);
                let h = s.travel;
                if lo > tol * h.max(1e-12) || hi < h * (1.0 - tol) {
                    return Err(ForceError::load(
                        format!("{field}.table"),
                        format!(
                            "the load diagram covers travel {}…{} but the working stroke is 0…{}; give values over the whole stroke",
                            fmt(lo, s.angular),
                            fmt(hi, s.angular),
                            fmt(h, s.angular)
                        ),
                    ));
                }
                Ok(())
            }
            Law::AngleTable(t) => {
                let (lo, hi) = (t[0].0, t[t.len() - 1].0);
                let two_pi = 2.0 * std::f64::consts::PI;
                if lo > tol || hi < two_pi * (1.0 - tol) {
                    return Err(ForceError::load(
                        format!("{field}.table"),
                        format!(
                            "the load diagram covers crank angles {:.3}°…{:.3}° but must cover 0…360° from the start of the working stroke",
                            lo.to_degrees(),
                            hi.to_degrees()
                        ),
                    ));
                }
                Ok(())
            }
            _ => Ok(()),
        }
    }

    /// The magnitude at a phase of the cycle.
    #[inline]
    pub fn value(&self, phase: &Phase) -> f64 {
        match self {
            Law::Constant(v) => *v,
            Law::WorkingStroke(v) => {
                if phase.working {
                    *v
                } else {
                    0.0
                }
            }
            Law::SineOfTravel(v) => {
                if phase.working && phase.travel_max > 0.0 {
                    // seed 003, §10: F_пс = F_max·sin(π·S/h)
                    *v * (std::f64::consts::PI * (phase.travel / phase.travel_max).clamp(0.0, 1.0)).sin()
                } else {
                    0.0
                }
            }
            Law::TravelTable(t) => {
                if phase.working {
                    interp(t, phase.travel)
                } else {
                    0.0
                }
            }
            Law::AngleTable(t) => interp(t, phase.angle),
        }
    }
}

/// Linear interpolation in a table sorted by x, clamped at its ends.
///
/// ```
/// let t = [(0.0, 0.0), (1.0, 10.0), (2.0, 10.0)];
/// assert_eq!(tmm_linkage::forces::resistance::interp(&t, 0.25), 2.5);
/// assert_eq!(tmm_linkage::forces::resistance::interp(&t, 5.0), 10.0);
/// ```
#[inline]
pub fn interp(t: &[(f64, f64)], x: f64) -> f64 {
    if x <= t[0].0 {
        return t[0].1;
    }
    let last = t.len() - 1;
    if x >= t[last].0 {
        return t[last].1;
    }
    // tables are short: a linear scan allocates nothing and is fast enough
    let mut i = 1;
    while t[i].0 < x {
        i += 1;
    }
    let (x0, y0) = t[i - 1];
    let (x1, y1) = t[i];
    y0 + (y1 - y0) * (x - x0) / (x1 - x0)
}

impl Resistance {
    /// The force (at `local`) or the moment this resistance applies to its
    /// link in state `s`, given its magnitude. Returns `(force, point, moment)`
    /// with the point global.
    #[inline]
    pub fn apply(&self, s: &LinkState, value: f64) -> (Vec2, Vec2, f64) {
        match self.action {
            Action::Force { local, dir } => {
                let p = s.pos(local);
                let f = match dir {
                    Some(d) => d * value,
                    None => {
                        let (v, _) = s.kin_at(p);
                        let n = v.hypot();
                        if n > 1e-12 { v * (-value / n) } else { Vec2::ZERO }
                    }
                };
                (f, p, 0.0)
            }
            Action::Moment { sign } => {
                let m = match sign {
                    Some(sg) => value * sg,
                    None => {
                        if s.omega.abs() > 1e-12 {
                            -value * s.omega.signum()
                        } else {
                            0.0
                        }
                    }
                };
                (Vec2::ZERO, s.o, m)
            }
        }
    }
}

/// Unit vector of a global direction angle, rad.
///
/// ```
/// let d = tmm_linkage::forces::resistance::direction(std::f64::consts::FRAC_PI_2);
/// assert!(d.x.abs() < 1e-15 && (d.y - 1.0).abs() < 1e-15);
/// ```
pub fn direction(angle: f64) -> Vec2 {
    let (s, c) = angle.sin_cos();
    Vec2::new(c, s)
}
