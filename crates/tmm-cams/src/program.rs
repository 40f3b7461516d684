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

/// A phase's own stroke, as written: a length (translating follower) or an
/// angle (oscillating follower), SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Stroke {
    /// m.
    Length(f64),
    /// rad.
    Angle(f64),
}

impl Stroke {
    /// The value in SI (m or rad).
    pub fn value(self) -> f64 {
        match self {
            Stroke::Length(v) | Stroke::Angle(v) => v,
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
    /// The phase's own stroke (None: the program's stroke); rises and
    /// returns of different strokes give intermediate dwell levels.
    pub stroke: Option<Stroke>,
}

impl Phase {
    /// A dwell of `angle` rad.
    pub fn dwell(angle: f64) -> Self {
        Phase {
            kind: PhaseKind::Dwell,
            angle,
            law: None,
            stroke: None,
        }
    }

    /// A rise or return of `angle` rad by `law`, with the program's stroke.
    pub fn moving(kind: PhaseKind, angle: f64, law: Law) -> Self {
        Phase {
            kind,
            angle,
            law: Some(law),
            stroke: None,
        }
    }
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
    heights: Vec<f64>,
}

/// What jumps at a discontinuity of the motion.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum JumpKind {
    /// The velocity analog jumps (constant velocity at a joint): the
    /// acceleration is an impulse Δv·δ(φ − φ₀) — "жёсткий удар", rigid impact.
    Velocity,
    /// The acceleration analog jumps (constant acceleration, cosine, …): the
    /// jerk is an impulse Δa·δ(φ − φ₀) — "мягкий удар", soft impact.
    Acceleration,
}

/// One discontinuity of the follower's motion over the cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jump {
    /// Cam angle, rad, in [0, 2π) (0 is also 360°: the wrap from the last phase).
    pub phi: f64,
    /// Which analog jumps.
    pub kind: JumpKind,
    /// The analog just before φ (ds/dφ or d²s/dφ²).
    pub before: f64,
    /// The analog just after φ.
    pub after: f64,
}

impl Jump {
    /// The size of the jump, `after − before`: the weight of the impulse of
    /// the next higher analog.
    pub fn size(&self) -> f64 {
        self.after - self.before
    }
}

impl Program {
    /// Check and build the cycle: the phases sum to 360° (to 1e-6°), every
    /// phase angle is positive, every rise and return has a law, a phase
    /// without its own [`Phase::stroke`] moves by `stroke`, the follower never
    /// goes below its lowest position, and the rises add up to the returns so
    /// that the cycle closes. Rises and returns of different strokes give
    /// intermediate dwell levels (rise 2, return 1, dwell, return 1).
    ///
    /// ```
    /// use tmm_cams::program::{Phase, PhaseKind, Program};
    /// use tmm_cams::law::{Law, LawKind};
    /// let d = |deg: f64| deg.to_radians();
    /// let law = || Law::new(LawKind::Cosine).unwrap();
    /// let p = Program::new(0.013, vec![
    ///     Phase::moving(PhaseKind::Rise, d(120.0), law()),
    ///     Phase::dwell(d(60.0)),
    ///     Phase::moving(PhaseKind::Return, d(120.0), law()),
    ///     Phase::dwell(d(60.0)),
    /// ]).unwrap();
    /// assert!((p.eval(d(150.0)).s - 0.013).abs() < 1e-15);
    /// assert!((p.eval(d(60.0)).s - 0.0065).abs() < 1e-15);
    /// ```
    pub fn new(stroke: f64, phases: Vec<Phase>) -> Result<Self, CamError> {
        if !positive(stroke) {
            return Err(CamError::Stroke(stroke));
        }
        Self::build(Some(stroke), phases)
    }

    /// Build a cycle in which every rise and return gives its own stroke
    /// (no program stroke); otherwise as [`Program::new`].
    ///
    /// ```
    /// let p = tmm_cams::program::Program::from_phases(tmm_cams::spec::parse_phases(
    ///     "rise 90 cosine 20mm; dwell 30; return 60 cosine 10mm; dwell 20; return 60 cosine 10mm; dwell 100",
    /// ).unwrap()).unwrap();
    /// assert!((p.stroke() - 0.020).abs() < 1e-15);
    /// assert!((p.eval(105f64.to_radians()).s - 0.020).abs() < 1e-15);
    /// assert!((p.eval(190f64.to_radians()).s - 0.010).abs() < 1e-15); // the intermediate dwell
    /// ```
    pub fn from_phases(phases: Vec<Phase>) -> Result<Self, CamError> {
        Self::build(None, phases)
    }

    fn build(default: Option<f64>, phases: Vec<Phase>) -> Result<Self, CamError> {
        if phases.is_empty() {
            return Err(CamError::Sequence("the cycle has no phases".into()));
        }
        let n = phases.len();
        let mut starts = Vec::with_capacity(n);
        let mut levels = Vec::with_capacity(n);
        let mut heights = Vec::with_capacity(n);
        let (mut sum, mut level, mut top) = (0.0, 0.0f64, 0.0f64);
        let (mut rises, mut returns) = (0.0, 0.0);
        for (i, ph) in phases.iter().enumerate() {
            let name = || format!("phase {} ({})", i + 1, ph.kind.name());
            if !positive(ph.angle) {
                return Err(CamError::Phase {
                    text: name(),
                    reason: "the phase angle must be positive".into(),
                });
            }
            let h = match ph.kind {
                PhaseKind::Dwell => 0.0,
                PhaseKind::Rise | PhaseKind::Return => {
                    if ph.law.is_none() {
                        return Err(CamError::Phase {
                            text: name(),
                            reason: "a rise or return needs a motion law".into(),
                        });
                    }
                    let h = match (ph.stroke, default) {
                        (Some(st), _) => st.value(),
                        (None, Some(h)) => h,
                        (None, None) => {
                            return Err(CamError::Phase {
                                text: name(),
                                reason: "give the phase its stroke, e.g. `rise 90 cosine 20mm`".into(),
                            });
                        }
                    };
                    if !positive(h) {
                        return Err(CamError::Phase {
                            text: name(),
                            reason: format!("the stroke must be positive, got {h}"),
                        });
                    }
                    h
                }
            };
            starts.push(sum);
            levels.push(level);
            heights.push(h);
            match ph.kind {
                PhaseKind::Rise => {
                    level += h;
                    rises += h;
                }
                PhaseKind::Return => {
                    if h > level * (1.0 + 1e-9) {
                        return Err(CamError::Sequence(if level <= 0.0 {
                            format!("phase {}: a return must follow a rise (the follower is at the bottom)", i + 1)
                        } else {
                            format!(
                                "phase {}: the return of {h} would take the follower {} below its lowest position (it is {level} up); shorten the return or raise an earlier rise",
                                i + 1,
                                h - level
                            )
                        }));
                    }
                    level = (level - h).max(0.0);
                    returns += h;
                }
                PhaseKind::Dwell => {}
            }
            top = top.max(level);
            sum += ph.angle;
        }
        if (sum - TAU).abs() > 1e-6f64.to_radians() {
            return Err(CamError::PhaseSum { sum_deg: sum.to_degrees() });
        }
        if rises <= 0.0 {
            return Err(CamError::Sequence("the cycle has no rise".into()));
        }
        if (rises - returns).abs() > 1e-9 * rises {
            return Err(CamError::Sequence(format!(
                "the rises add up to {rises} but the returns to {returns} (m, or rad for an oscillating follower): the follower must come back to its lowest position, so the sums must be equal"
            )));
        }
        let prog = Program {
            stroke: default.filter(|_| top <= 0.0).unwrap_or(top),
            phases,
            starts,
            levels,
            heights,
        };
        // s′ = h·y′/β, s″ = h·y″/β², s‴ = h·y‴/β³ must be finite numbers
        for (k, ph) in prog.phases.iter().enumerate() {
            let ok = (0..=32).all(|i| {
                let m = prog.eval_phase(k, ph.angle * i as f64 / 32.0, false);
                let l = prog.eval_phase(k, ph.angle * i as f64 / 32.0, true);
                [m.s, m.v, m.a, m.j, l.v, l.a, l.j].iter().all(|v| v.is_finite())
            });
            if !ok || !prog.stroke.is_finite() {
                return Err(CamError::Phase {
                    text: format!("phase {} ({})", k + 1, ph.kind.name()),
                    reason: format!(
                        "its stroke {} over its angle {:.4}° gives analogs (h/β, h/β², h/β³) that are not finite numbers; give a realistic stroke",
                        prog.heights[k],
                        ph.angle.to_degrees()
                    ),
                });
            }
        }
        Ok(prog)
    }

    /// The stroke h (ход толкателя): the highest displacement over the cycle,
    /// m, or rad for an oscillating follower.
    pub fn stroke(&self) -> f64 {
        self.stroke
    }

    /// The stroke of phase `k` (0 for a dwell).
    pub fn phase_stroke(&self, k: usize) -> f64 {
        self.heights[k]
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
        self.eval_phase(k, dphi, false)
    }

    /// [`Program::eval_in`] with the left-hand value at a joint inside the
    /// law (`left = true`): at a piece boundary of a piecewise law the piece
    /// before it is used.
    #[inline]
    fn eval_phase(&self, k: usize, dphi: f64, left: bool) -> Motion {
        let ph = &self.phases[k];
        let h = self.heights[k];
        let b = ph.angle;
        let level = self.level_before(k);
        match (&ph.law, ph.kind) {
            (Some(law), PhaseKind::Rise) | (Some(law), PhaseKind::Return) => {
                let x = dphi / b;
                let [y, y1, y2, y3] = if left { law.eval_left(x) } else { law.eval(x) };
                let sg = if ph.kind == PhaseKind::Rise { 1.0 } else { -1.0 };
                let s = level + sg * h * y;
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

    /// The displacement at the start of phase `k`.
    pub fn level_before(&self, k: usize) -> f64 {
        self.levels[k]
    }

    /// The motion just before the cam angle φ (the left-hand limit): at a
    /// phase joint the end of the phase before it, at φ = 0 or 360° the end
    /// of the last phase (the wrap of the cycle).
    ///
    /// ```
    /// use tmm_cams::{program::Program, spec::parse_phases};
    /// let p = Program::new(0.01, parse_phases("rise 180 const-accel; return 180 const-accel").unwrap()).unwrap();
    /// let tau = std::f64::consts::TAU;
    /// // the return ends with a = +4h/β², as the rise begins: no jump at the wrap
    /// let (b, a) = (p.eval_left(tau).a, p.eval(0.0).a);
    /// assert!((b - a).abs() < 1e-12 && (a - 4.0 * 0.01 / (std::f64::consts::PI).powi(2)).abs() < 1e-12);
    /// ```
    pub fn eval_left(&self, phi: f64) -> Motion {
        let t = phi.rem_euclid(TAU);
        let k = self.phase_at(t);
        let d = t - self.starts[k];
        if d <= 0.0 {
            let j = if k == 0 { self.phases.len() - 1 } else { k - 1 };
            return self.eval_phase(j, self.phases[j].angle, true);
        }
        self.eval_phase(k, d, true)
    }

    /// Every discontinuity of the velocity or acceleration analog over the
    /// cycle, in order of φ: the joints between phases (φ = 0 included, where
    /// the last phase meets the first), and the joints inside piecewise laws.
    /// A velocity jump means an acceleration impulse of weight Δv (constant
    /// velocity); an acceleration jump a jerk impulse of weight Δa. A drawing
    /// marks these instead of joining the samples across them.
    ///
    /// ```
    /// use tmm_cams::{program::{Program, JumpKind}, spec::parse_phases};
    /// let h = 0.01;
    /// let p = Program::new(h, parse_phases("rise 90 const-accel; dwell 90; return 90 const-accel; dwell 90").unwrap()).unwrap();
    /// let j = p.jumps();
    /// // at the start, the middle and the end of each moving phase: 6 acceleration jumps
    /// assert_eq!(j.len(), 6);
    /// assert!(j.iter().all(|j| j.kind == JumpKind::Acceleration));
    /// // at φ = 0 (the wrap): from the dwell's 0 to +4h/β²
    /// let b = std::f64::consts::FRAC_PI_2;
    /// assert!(j[0].phi == 0.0 && (j[0].size() - 4.0 * h / (b * b)).abs() < 1e-12);
    /// ```
    pub fn jumps(&self) -> Vec<Jump> {
        let mut out = Vec::new();
        let n = self.phases.len();
        let scale_v = self.stroke / TAU;
        let push = |out: &mut Vec<Jump>, phi: f64, l: Motion, r: Motion, scale_a: f64| {
            if (r.v - l.v).abs() > 1e-9 * scale_v.max(l.v.abs()).max(r.v.abs()) {
                out.push(Jump {
                    phi,
                    kind: JumpKind::Velocity,
                    before: l.v,
                    after: r.v,
                });
            }
            if (r.a - l.a).abs() > 1e-9 * scale_a.max(l.a.abs()).max(r.a.abs()) {
                out.push(Jump {
                    phi,
                    kind: JumpKind::Acceleration,
                    before: l.a,
                    after: r.a,
                });
            }
        };
        for k in 0..n {
            let prev = if k == 0 { n - 1 } else { k - 1 };
            let ph = &self.phases[k];
            let scale_a = self.stroke / (ph.angle * ph.angle);
            let l = self.eval_phase(prev, self.phases[prev].angle, true);
            let r = self.eval_phase(k, 0.0, false);
            push(&mut out, self.starts[k], l, r, scale_a);
            if let Some(law) = &ph.law {
                for x in law.breaks() {
                    if x > 0.0 && x < 1.0 {
                        let d = x * ph.angle;
                        let l = self.eval_phase(k, d, true);
                        let r = self.eval_phase(k, d, false);
                        push(&mut out, self.starts[k] + d, l, r, scale_a);
                    }
                }
            }
        }
        out
    }

    /// The motion sampled for a diagram over the closed turn [0, 360°]: `n`
    /// equal steps plus, at every [`Program::jumps`] angle, both one-sided
    /// values at the same φ (so a drawn polyline shows a vertical step, not a
    /// slanted line), and at 360° the end of the last phase — not the value at
    /// 0°, which would draw a false spike where the cycle wraps.
    ///
    /// ```
    /// use tmm_cams::{program::Program, spec::parse_phases};
    /// let p = Program::new(0.01, parse_phases("rise 90 const-accel; return 90 const-accel; dwell 180").unwrap()).unwrap();
    /// let pts = p.diagram(360);
    /// let (phi, m) = pts[pts.len() - 1];
    /// assert!((phi - std::f64::consts::TAU).abs() < 1e-15 && m.a == 0.0); // the dwell, not the rise's start
    /// ```
    pub fn diagram(&self, n: usize) -> Vec<(f64, Motion)> {
        let n = n.clamp(2, 1_000_000);
        let mut angles: Vec<f64> = self.jumps().iter().map(|j| j.phi).filter(|&p| p > 0.0).collect();
        angles.dedup();
        let mut out = Vec::with_capacity(n + 1 + 2 * angles.len());
        let mut k = 0;
        for i in 0..n {
            let phi = TAU * i as f64 / n as f64;
            while k < angles.len() && angles[k] < phi {
                out.push((angles[k], self.eval_left(angles[k])));
                out.push((angles[k], self.eval(angles[k])));
                k += 1;
            }
            if k < angles.len() && angles[k] == phi {
                out.push((phi, self.eval_left(phi)));
                out.push((phi, self.eval(phi)));
                k += 1;
                continue;
            }
            out.push((phi, self.eval(phi)));
        }
        for &a in &angles[k..] {
            out.push((a, self.eval_left(a)));
            out.push((a, self.eval(a)));
        }
        out.push((TAU, self.eval_left(TAU)));
        out
    }
}
