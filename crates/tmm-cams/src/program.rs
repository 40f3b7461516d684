//! The follower's motion over a whole cam turn (цикл): phases of rise,
//! dwell and return that start at cam angle 0 and close at 360°.
//!
//! `s(φ)` is the follower displacement from its lowest position (a length for
//! a translating follower, an angle for an oscillating one); derivatives are
//! taken with respect to the cam angle φ (kinematic analogs, аналоги скорости
//! и ускорения).

use crate::law::Law;
use crate::{CamError, positive};
use std::f64::consts::TAU;

/// What the follower does during a phase.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PhaseKind {
    /// Rise (подъём, удаление): from 0 to the stroke.
    Rise,
    /// Dwell (выстой): no motion.
    Dwell,
    /// Return (опускание, возвращение): from the stroke to 0.
    Return,
}

impl PhaseKind {
    /// `rise`, `dwell`, `return`.
    pub fn name(self) -> &'static str {
        match self {
            PhaseKind::Rise => "rise",
            PhaseKind::Dwell => "dwell",
            PhaseKind::Return => "return",
        }
    }
}

/// One phase of the cycle.
#[derive(Debug, Clone, PartialEq)]
pub struct Phase {
    /// Rise, dwell or return.
    pub kind: PhaseKind,
    /// Phase angle β (фазовый угол), rad.
    pub angle: f64,
    /// The law (None for a dwell).
    pub law: Option<Law>,
}

/// Follower displacement and its derivatives with respect to the cam angle.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Motion {
    /// Displacement s.
    pub s: f64,
    /// Velocity analog ds/dφ (аналог скорости).
    pub v: f64,
    /// Acceleration analog d²s/dφ² (аналог ускорения).
    pub a: f64,
    /// Jerk analog d³s/dφ³.
    pub j: f64,
}

/// The whole cycle: stroke and phases with their start angles.
#[derive(Debug, Clone, PartialEq)]
pub struct Program {
    stroke: f64,
    phases: Vec<Phase>,
    starts: Vec<f64>,
    levels: Vec<f64>,
}

impl Program {
    /// Check and build the cycle: the stroke is positive, the phases sum to
    /// 360° (to 1e-6°), every phase angle is positive, and rises and returns
    /// alternate starting from the bottom (a return needs a rise before it).
    ///
    /// ```
    /// use tmm_cams::program::{Phase, PhaseKind, Program};
    /// use tmm_cams::law::{Law, LawKind};
    /// let d = |deg: f64| deg.to_radians();
    /// let law = || Some(Law::new(LawKind::Cosine).unwrap());
    /// let p = Program::new(0.013, vec![
    ///     Phase { kind: PhaseKind::Rise, angle: d(120.0), law: law() },
    ///     Phase { kind: PhaseKind::Dwell, angle: d(60.0), law: None },
    ///     Phase { kind: PhaseKind::Return, angle: d(120.0), law: law() },
    ///     Phase { kind: PhaseKind::Dwell, angle: d(60.0), law: None },
    /// ]).unwrap();
    /// assert!((p.eval(d(150.0)).s - 0.013).abs() < 1e-15);
    /// assert!((p.eval(d(60.0)).s - 0.0065).abs() < 1e-15);
    /// ```
    pub fn new(stroke: f64, phases: Vec<Phase>) -> Result<Self, CamError> {
        if !positive(stroke) {
            return Err(CamError::Stroke(stroke));
        }
        if phases.is_empty() {
            return Err(CamError::Sequence("the cycle has no phases".into()));
        }
        let mut starts = Vec::with_capacity(phases.len());
        let mut levels = Vec::with_capacity(phases.len());
        let mut sum = 0.0;
        let mut top = false;
        for (i, ph) in phases.iter().enumerate() {
            let before = if top { stroke } else { 0.0 };
            if !positive(ph.angle) {
                return Err(CamError::Phase {
                    text: format!("phase {} ({})", i + 1, ph.kind.name()),
                    reason: "the phase angle must be positive".into(),
                });
            }
            match ph.kind {
                PhaseKind::Rise if top => {
                    return Err(CamError::Sequence(format!(
                        "phase {}: a rise must start from the bottom, but the follower is already at the top",
                        i + 1
                    )));
                }
                PhaseKind::Return if !top => {
                    return Err(CamError::Sequence(format!(
                        "phase {}: a return must follow a rise (the follower is at the bottom)",
                        i + 1
                    )));
                }
                PhaseKind::Rise | PhaseKind::Return => {
                    if ph.law.is_none() {
                        return Err(CamError::Phase {
                            text: format!("phase {} ({})", i + 1, ph.kind.name()),
                            reason: "a rise or return needs a motion law".into(),
                        });
                    }
                    top = !top;
                }
                PhaseKind::Dwell => {}
            }
            starts.push(sum);
            levels.push(before);
            sum += ph.angle;
        }
        if (sum - TAU).abs() > 1e-6f64.to_radians() {
            return Err(CamError::PhaseSum { sum_deg: sum.to_degrees() });
        }
        if top {
            return Err(CamError::Sequence(
                "the cycle ends at the top: add a return so that the follower comes back to the bottom".into(),
            ));
        }
        if !phases.iter().any(|p| p.kind == PhaseKind::Rise) {
            return Err(CamError::Sequence("the cycle has no rise".into()));
        }
        Ok(Program {
            stroke,
            phases,
            starts,
            levels,
        })
    }

    /// The stroke h (ход толкателя): m, or rad for an oscillating follower.
    pub fn stroke(&self) -> f64 {
        self.stroke
    }

    /// The phases in order.
    pub fn phases(&self) -> &[Phase] {
        &self.phases
    }

    /// Start angle of phase `i`, rad.
    pub fn start(&self, i: usize) -> f64 {
        self.starts[i]
    }

    /// Index of the phase containing the cam angle φ (wrapped to one turn).
    #[inline]
    pub fn phase_at(&self, phi: f64) -> usize {
        let phi = phi.rem_euclid(TAU);
        let mut k = 0;
        while k + 1 < self.starts.len() && phi >= self.starts[k + 1] {
            k += 1;
        }
        k
    }

    /// Motion at the cam angle φ (rad, any turn).
    #[inline]
    pub fn eval(&self, phi: f64) -> Motion {
        let phi = phi.rem_euclid(TAU);
        let k = self.phase_at(phi);
        self.eval_in(k, phi - self.starts[k])
    }

    /// Motion at the angle `dphi` from the start of phase `k` (no wrapping:
    /// the phase's own law is used even at its ends, so the one-sided values
    /// at a joint are available).
    #[inline]
    pub fn eval_in(&self, k: usize, dphi: f64) -> Motion {
        let ph = &self.phases[k];
        let h = self.stroke;
        let b = ph.angle;
        let level = self.level_before(k);
        match (&ph.law, ph.kind) {
            (Some(law), PhaseKind::Rise) | (Some(law), PhaseKind::Return) => {
                let [y, y1, y2, y3] = law.eval(dphi / b);
                let sg = if ph.kind == PhaseKind::Rise { 1.0 } else { -1.0 };
                let s = if ph.kind == PhaseKind::Rise { h * y } else { h * (1.0 - y) };
                Motion {
                    s,
                    v: sg * h * y1 / b,
                    a: sg * h * y2 / (b * b),
                    j: sg * h * y3 / (b * b * b),
                }
            }
            _ => Motion {
                s: level,
                v: 0.0,
                a: 0.0,
                j: 0.0,
            },
        }
    }

    /// The displacement at the start of phase `k` (0 or the stroke).
    pub fn level_before(&self, k: usize) -> f64 {
        self.levels[k]
    }
}
