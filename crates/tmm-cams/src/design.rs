//! The whole cam design from a task: sizing, roller choice, profile, checks.
//! This is the one entry point the report and the command line call.

use crate::mechanism::{Mechanism, Rotation};
use crate::profile::{Profile, flat_rho, over_pieces, pitch_curvature, pressure_extremes};
use crate::program::{JumpKind, Program, Stroke};
use crate::sizing;
use crate::spec::Limits;
use crate::{CamError, positive};
use tmm_geom::Vec2;

/// The follower and what is given about it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FollowerSpec {
    /// Translating roller (a knife edge is `roller = Some(0)`).
    TranslatingRoller {
        /// Offset e (None: the best offset).
        offset: Option<f64>,
        /// Roller radius (None: by the course's rules).
        roller: Option<f64>,
    },
    /// Translating flat face perpendicular to its axis.
    TranslatingFlat {
        /// Offset of the axis (does not change the profile; moves the face).
        offset: f64,
    },
    /// Oscillating roller follower.
    OscillatingRoller {
        /// Arm length l.
        arm: f64,
        /// Pivot distance a = OA (None: the one giving the smallest r₀).
        pivot: Option<f64>,
        /// Roller radius (None: by the course's rules).
        roller: Option<f64>,
    },
    /// Oscillating flat face through the pivot.
    OscillatingFlat {
        /// Pivot distance a = OA.
        pivot: f64,
    },
}

impl FollowerSpec {
    /// `translating-roller`, `translating-flat`, `oscillating-roller`, `oscillating-flat`.
    pub fn name(&self) -> &'static str {
        match self {
            FollowerSpec::TranslatingRoller { .. } => "translating-roller",
            FollowerSpec::TranslatingFlat { .. } => "translating-flat",
            FollowerSpec::OscillatingRoller { .. } => "oscillating-roller",
            FollowerSpec::OscillatingFlat { .. } => "oscillating-flat",
        }
    }
    /// `true` for an oscillating follower (the stroke is an angle).
    pub fn oscillating(&self) -> bool {
        matches!(self, FollowerSpec::OscillatingRoller { .. } | FollowerSpec::OscillatingFlat { .. })
    }
}

/// A cam task.
#[derive(Debug, Clone, PartialEq)]
pub struct CamTask {
    /// The follower's motion over the cycle.
    pub program: Program,
    /// The follower.
    pub follower: FollowerSpec,
    /// The cam's sense of rotation.
    pub rotation: Rotation,
    /// Allowed pressure angles (roller followers).
    pub limits: Limits,
    /// Smallest allowed radius of curvature of the working profile (flat faces:
    /// Geronimus' ρ_min; rollers: an extra bound on the roller).
    pub min_curvature: Option<f64>,
    /// Margin added to the contact extremes for the face width.
    pub face_margin: f64,
    /// The cam's angular speed |ω|, rad/s.
    pub omega: f64,
    /// Profile points over one turn.
    pub points: usize,
}

/// The default smallest radius of curvature of a flat-faced cam's working
/// profile: the lower end of the 10…20 mm recommended in seed 001 (MADI,
/// sheet 1, "Rкр min = (10 … 20)·10⁻³ м").
pub const DEFAULT_MIN_CURVATURE: f64 = 0.010;

/// Positions per moving phase whose cones cut the admissible region of an
/// oscillating roller follower's centre (the envelope error falls as the
/// square of the step: about 10⁻⁵ of r₀ here).
pub const OSC_SAMPLES: usize = 1440;

/// The extent of a flat face.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Face {
    /// Nearest contact point along the face from its reference (the
    /// follower axis, or the pivot), m.
    pub contact_min: f64,
    /// Farthest contact point, m.
    pub contact_max: f64,
    /// Face width: a disc symmetric about the axis for a translating face,
    /// `2·(max |contact| + margin)`; for an oscillating face the length
    /// `contact_max − contact_min + 2·margin`.
    pub width: f64,
}

/// The designed cam.
#[derive(Debug, Clone, PartialEq)]
pub struct CamDesign {
    /// The sized mechanism.
    pub mechanism: Mechanism,
    /// Smallest radius of the theoretical profile (roller centre's lowest
    /// circle; base circle for a flat face), m.
    pub r0: f64,
    /// Smallest radius of the working profile, m.
    pub rb: f64,
    /// Roller radius, m (0 for a knife edge or a flat face).
    pub roller: f64,
    /// The roller radius bound by the course's rules `min(0.4·r₀, 0.7·ρ_p)`.
    pub roller_rule: Option<f64>,
    /// Largest pressure angle on the rise, rad.
    pub pressure_max_rise: f64,
    /// Largest pressure angle on the return, rad.
    pub pressure_max_return: f64,
    /// Smallest convex radius of curvature of the pitch curve (rollers), m.
    pub rho_min_pitch: Option<f64>,
    /// Radius of curvature of the working profile where it is sharpest, signed
    /// (positive convex, negative concave), m.
    pub rho_min: f64,
    /// Smallest convex radius of the working profile, m.
    pub rho_min_convex: f64,
    /// Smallest concave radius of the working profile (None if it is convex everywhere), m.
    pub rho_min_concave: Option<f64>,
    /// Flat face extent.
    pub face: Option<Face>,
    /// The dense profile.
    pub profile: Profile,
}

fn check_len(field: &'static str, v: f64, allow_zero: bool) -> Result<(), CamError> {
    if !v.is_finite() || v < 0.0 || (!allow_zero && v == 0.0) {
        return Err(CamError::Dimension {
            field,
            reason: format!(
                "must be a {} finite length, got {v}",
                if allow_zero { "non-negative" } else { "positive" }
            ),
        });
    }
    Ok(())
}

impl CamTask {
    /// Check what every solution needs: ω, margins, points, the strokes' kind
    /// (lengths for a translating follower, angles for an oscillating one),
    /// and that ω, ω², ω³ times the analogs stay finite.
    fn check_common(&self) -> Result<Limits, CamError> {
        let prog = &self.program;
        let limits = self.limits.check()?;
        if !positive(self.omega) {
            return Err(CamError::Dimension {
                field: "omega",
                reason: format!("the cam speed must be positive, got {}", self.omega),
            });
        }
        if !(self.face_margin.is_finite() && self.face_margin >= 0.0) {
            return Err(CamError::Dimension {
                field: "face-margin",
                reason: "must be a non-negative length".into(),
            });
        }
        if let Some(r) = self.min_curvature {
            check_len("min-curvature", r, true)?;
        }
        if !(16..=1_000_000).contains(&self.points) {
            return Err(CamError::Dimension {
                field: "points",
                reason: format!("give between 16 and 1000000 profile points, got {}", self.points),
            });
        }
        if self.follower.oscillating() && prog.stroke() >= std::f64::consts::PI {
            return Err(CamError::Dimension {
                field: "stroke",
                reason: "an oscillating follower's stroke is its swing angle, below 180°".into(),
            });
        }
        let osc = self.follower.oscillating();
        for (i, ph) in prog.phases().iter().enumerate() {
            match (ph.stroke, osc) {
                (Some(Stroke::Length(_)), true) => {
                    return Err(CamError::Dimension {
                        field: "stroke",
                        reason: format!("phase {}: an oscillating follower's stroke is an angle, write e.g. `15°`", i + 1),
                    });
                }
                (Some(Stroke::Angle(_)), false) => {
                    return Err(CamError::Dimension {
                        field: "stroke",
                        reason: format!("phase {}: a translating follower's stroke is a length, write e.g. `20mm`", i + 1),
                    });
                }
                _ => {}
            }
        }
        // v = ω s′, a = ω² s″, j = ω³ s‴ must stay finite (and the analogs themselves)
        let w = self.omega;
        let finite = prog
            .diagram(720)
            .iter()
            .all(|(_, m)| (m.v * w).is_finite() && (m.a * w * w).is_finite() && (m.j * w * w * w).is_finite());
        if !finite {
            return Err(CamError::Dimension {
                field: "omega",
                reason: format!(
                    "ω = {} rad/s makes the follower's velocity, acceleration or jerk (ω·s′, ω²·s″, ω³·s‴) overflow; give a realistic cam speed",
                    self.omega
                ),
            });
        }
        Ok(limits)
    }

    /// Analyse a given cam instead of sizing one (the textbook problem "the
    /// prime circle r₀ is given, find the pressure angle"): `r0` is the
    /// smallest radius of the theoretical profile (the lowest roller centre,
    /// or the base circle of a flat face). The rest comes from the follower:
    /// the offset e of a translating follower (None: 0), the pivot distance a
    /// and the arm l of an oscillating roller, the pivot distance of an
    /// oscillating flat face. The pressure angles are computed, not enforced:
    /// compare [`CamDesign::pressure_max_rise`] with the limits. The roller is
    /// chosen or checked as in [`CamTask::solve`].
    ///
    /// Placement (derived here, docs/cams.md §3a): a translating roller has
    /// s₀ = √(r₀² − e²); an oscillating roller has its pivot at A = (a, 0) and
    /// cos ψ₀ = (r₀² − a² − l²)/(2al), the roller moving outward on the rise;
    /// of the two mirror placements (ψ₀ above or below OA) the one with the
    /// smaller largest pressure angle relative to its limit is kept.
    ///
    /// ```
    /// use tmm_cams::{design::{CamTask, FollowerSpec}, mechanism::Rotation, program::Program, spec};
    /// let task = CamTask {
    ///     program: Program::new(0.02, spec::parse_phases("rise 120 cosine; dwell 60; return 120 cosine; dwell 60").unwrap()).unwrap(),
    ///     follower: FollowerSpec::TranslatingRoller { offset: None, roller: Some(0.0) },
    ///     rotation: Rotation::Ccw,
    ///     limits: spec::parse_limits("30", false).unwrap(),
    ///     min_curvature: None, face_margin: 0.005, omega: 10.0, points: 720,
    /// };
    /// let d = task.solve_with_r0(0.05).unwrap();
    /// // central follower, cosine law: tan ϑ = s′/(r₀ + s); s′ = (h/2)(π/β) sin(πφ/β)
    /// let b = 120f64.to_radians();
    /// let best = (0..=2000).map(|i| {
    ///     let x = std::f64::consts::PI * i as f64 / 2000.0;
    ///     (0.01 * std::f64::consts::PI / b * x.sin()).atan2(0.05 + 0.01 * (1.0 - x.cos()))
    /// }).fold(0.0f64, f64::max);
    /// assert!((d.pressure_max_rise - best).abs() < 1e-6);
    /// ```
    pub fn solve_with_r0(&self, r0: f64) -> Result<CamDesign, CamError> {
        let prog = &self.program;
        let sigma = self.rotation.sign();
        let limits = self.check_common()?;
        check_len("r0", r0, false)?;
        let (mech, given_roller) = match self.follower {
            FollowerSpec::TranslatingRoller { offset, roller } => {
                let e = offset.unwrap_or(0.0);
                if !e.is_finite() {
                    return Err(CamError::Dimension {
                        field: "offset",
                        reason: "must be a finite length".into(),
                    });
                }
                if e.abs() >= r0 {
                    return Err(CamError::Dimension {
                        field: "offset",
                        reason: format!(
                            "the offset |e| = {:.3} mm must be smaller than r0 = {:.3} mm",
                            e.abs() * 1e3,
                            r0 * 1e3
                        ),
                    });
                }
                if let Some(r) = roller {
                    check_len("roller", r, true)?;
                }
                let s0 = (r0 - e.abs()).sqrt() * (r0 + e.abs()).sqrt();
                (Mechanism::TranslatingRoller { e, s0, roller: 0.0 }, roller)
            }
            FollowerSpec::OscillatingRoller { arm, pivot, roller } => {
                check_len("arm", arm, false)?;
                if let Some(r) = roller {
                    check_len("roller", r, true)?;
                }
                let a = pivot.ok_or_else(|| CamError::Dimension {
                    field: "pivot",
                    reason: "a given oscillating cam needs the pivot distance a = OA".into(),
                })?;
                check_len("pivot", a, false)?;
                let c = (r0 * r0 - a * a - arm * arm) / (2.0 * a * arm);
                if !(c.is_finite() && c.abs() < 1.0) {
                    return Err(CamError::Dimension {
                        field: "r0",
                        reason: format!(
                            "r0 = {:.3} mm cannot be reached by an arm of {:.3} mm from a pivot {:.3} mm away: it must lie between |a − l| and a + l",
                            r0 * 1e3,
                            arm * 1e3,
                            a * 1e3
                        ),
                    });
                }
                let psi = c.acos();
                let pivot_v = Vec2::new(a, 0.0);
                // the roller moves outward on the rise: d|OB|²/ds = −2al·κ·sin ψ₀ > 0
                let pick = |psi0: f64, kappa: f64| Mechanism::OscillatingRoller {
                    pivot: pivot_v,
                    arm,
                    psi0,
                    kappa,
                    roller: 0.0,
                };
                let score = |m: &Mechanism| {
                    let (r, t) = pressure_extremes(prog, m, sigma);
                    (r / limits.rise).max(t / limits.ret)
                };
                let (m1, m2) = (pick(psi, -1.0), pick(-psi, 1.0));
                let best = if score(&m2) < score(&m1) { m2 } else { m1 };
                (best, roller)
            }
            FollowerSpec::TranslatingFlat { offset } => {
                if !offset.is_finite() {
                    return Err(CamError::Dimension {
                        field: "offset",
                        reason: "must be a finite length".into(),
                    });
                }
                (Mechanism::TranslatingFlat { e: offset, r0 }, None)
            }
            FollowerSpec::OscillatingFlat { pivot } => {
                check_len("pivot", pivot, false)?;
                if r0 >= pivot {
                    return Err(CamError::Dimension {
                        field: "r0",
                        reason: format!(
                            "the base circle r0 = {:.3} mm must be smaller than the pivot distance {:.3} mm",
                            r0 * 1e3,
                            pivot * 1e3
                        ),
                    });
                }
                (
                    Mechanism::OscillatingFlat {
                        a: pivot,
                        delta0: (r0 / pivot).asin(),
                    },
                    None,
                )
            }
        };
        self.finish(mech, given_roller)
    }

    /// Size the cam, choose or check the roller, build the profile.
    pub fn solve(&self) -> Result<CamDesign, CamError> {
        let prog = &self.program;
        let sigma = self.rotation.sign();
        let limits = self.check_common()?;
        let (mech, given_roller) = match self.follower {
            FollowerSpec::TranslatingRoller { offset, roller } => {
                if let Some(r) = roller {
                    check_len("roller", r, true)?;
                }
                let (e, s0) = sizing::translating_roller(prog, sigma, limits, offset)?;
                (Mechanism::TranslatingRoller { e, s0, roller: 0.0 }, roller)
            }
            FollowerSpec::OscillatingRoller { arm, pivot, roller } => {
                if let Some(r) = roller {
                    check_len("roller", r, true)?;
                }
                (sizing::oscillating_roller(prog, sigma, limits, arm, pivot, OSC_SAMPLES)?, roller)
            }
            FollowerSpec::TranslatingFlat { offset } => {
                if !offset.is_finite() {
                    return Err(CamError::Dimension {
                        field: "offset",
                        reason: "must be a finite length".into(),
                    });
                }
                let r0 = sizing::translating_flat(prog, self.min_curvature.unwrap_or(DEFAULT_MIN_CURVATURE));
                (Mechanism::TranslatingFlat { e: offset, r0 }, None)
            }
            FollowerSpec::OscillatingFlat { pivot } => {
                let r0 = sizing::oscillating_flat(prog, sigma, pivot, self.min_curvature.unwrap_or(DEFAULT_MIN_CURVATURE))?;
                (
                    Mechanism::OscillatingFlat {
                        a: pivot,
                        delta0: (r0 / pivot).asin(),
                    },
                    None,
                )
            }
        };
        self.finish(mech, given_roller)
    }

    /// Everything after the mechanism is placed: the roller, the pressure
    /// angles, the curvature, the flat face's extent, the profile.
    fn finish(&self, mut mech: Mechanism, given_roller: Option<f64>) -> Result<CamDesign, CamError> {
        let prog = &self.program;
        let sigma = self.rotation.sign();
        if let Some(r) = self.min_curvature {
            check_len("min-curvature", r, true)?;
        }
        if mech.is_flat() && prog.jumps().iter().any(|j| j.kind == JumpKind::Velocity) {
            return Err(CamError::Infeasible(
                "a flat face cannot follow a jump of velocity (constant velocity at a joint): its profile radius r₀ + s + s″ would have an infinite negative impulse; use a roller follower or a law without velocity jumps".into(),
            ));
        }
        let r0 = match mech {
            Mechanism::TranslatingRoller { e, s0, .. } => e.hypot(s0),
            Mechanism::TranslatingFlat { r0, .. } => r0,
            Mechanism::OscillatingRoller { pivot, arm, psi0, .. } => (pivot + Vec2::new(psi0.cos(), psi0.sin()) * arm).hypot(),
            Mechanism::OscillatingFlat { a, delta0 } => a * delta0.sin(),
        };
        let scan = 256;
        let (mut roller, mut roller_rule, mut rho_min_pitch) = (0.0, None, None);
        if !mech.is_flat() {
            let kmax = over_pieces(prog, scan, |m| pitch_curvature(&mech, m, sigma), true);
            let rho_p = if kmax > 0.0 { 1.0 / kmax } else { f64::INFINITY };
            rho_min_pitch = Some(rho_p);
            let need = self.min_curvature.unwrap_or(0.0);
            // the course's rule (seed 001, sheet 1): r_roller ≤ 0.4·r₀ and ≤ 0.7·ρ_min
            let rule = (0.4 * r0).min(0.7 * rho_p).min(rho_p - need);
            roller_rule = Some(rule.max(0.0));
            roller = match given_roller {
                Some(r) => {
                    let allowed = rho_p - need;
                    if r >= allowed {
                        return Err(CamError::RollerTooLarge {
                            roller_mm: r * 1e3,
                            allowed_mm: allowed * 1e3,
                            rho_mm: rho_p * 1e3,
                        });
                    }
                    if r >= r0 {
                        return Err(CamError::Dimension {
                            field: "roller",
                            reason: format!("the roller radius {:.3} mm is not smaller than r0 = {:.3} mm", r * 1e3, r0 * 1e3),
                        });
                    }
                    r
                }
                None => {
                    if rule <= 0.0 {
                        return Err(CamError::Infeasible(format!(
                            "the pitch curve's smallest radius of curvature {:.3} mm leaves no room for a roller with ρ ≥ {:.3} mm",
                            rho_p * 1e3,
                            need * 1e3
                        )));
                    }
                    rule
                }
            };
            match &mut mech {
                Mechanism::TranslatingRoller { roller: r, .. } | Mechanism::OscillatingRoller { roller: r, .. } => *r = roller,
                _ => {}
            }
        }
        let (pressure_max_rise, pressure_max_return) = pressure_extremes(prog, &mech, sigma);
        // working-profile curvature extremes
        let curv = |m: &crate::program::Motion| {
            if mech.is_flat() {
                1.0 / flat_rho(&mech, m, sigma)
            } else {
                let k = pitch_curvature(&mech, m, sigma);
                k / (1.0 - roller * k)
            }
        };
        let kmax = over_pieces(prog, scan, curv, true);
        let kmin = over_pieces(prog, scan, curv, false);
        if mech.is_flat() {
            let rmin = over_pieces(prog, scan, |m| flat_rho(&mech, m, sigma), false);
            if !positive(rmin) {
                return Err(CamError::Infeasible(format!(
                    "the flat-faced cam is not convex (ρ_min = {:.3} mm)",
                    rmin * 1e3
                )));
            }
        }
        let rho_min_convex = if kmax > 0.0 { 1.0 / kmax } else { f64::INFINITY };
        let rho_min_concave = if kmin < 0.0 { Some(1.0 / kmin) } else { None };
        let rho_min = match rho_min_concave {
            Some(c) if c.abs() < rho_min_convex => c,
            _ => rho_min_convex,
        };
        let face = match mech {
            Mechanism::TranslatingFlat { e, .. } => {
                let lo = over_pieces(prog, scan, |m| sigma * m.v - e, false);
                let hi = over_pieces(prog, scan, |m| sigma * m.v - e, true);
                Some(Face {
                    contact_min: lo,
                    contact_max: hi,
                    width: 2.0 * (lo.abs().max(hi.abs()) + self.face_margin),
                })
            }
            Mechanism::OscillatingFlat { a, .. } => {
                let along = |m: &crate::program::Motion| {
                    let c = mech.contact_frame(m, sigma);
                    let d = m.s
                        + match mech {
                            Mechanism::OscillatingFlat { delta0, .. } => delta0,
                            _ => 0.0,
                        };
                    (c - Vec2::new(a, 0.0)).dot(Vec2::new(-d.cos(), -d.sin()))
                };
                let lo = over_pieces(prog, scan, along, false);
                let hi = over_pieces(prog, scan, along, true);
                if lo <= 0.0 {
                    return Err(CamError::Infeasible(format!(
                        "the contact point passes the pivot ({:.3} mm from it): increase the pivot distance",
                        lo * 1e3
                    )));
                }
                Some(Face {
                    contact_min: lo,
                    contact_max: hi,
                    width: hi - lo + 2.0 * self.face_margin,
                })
            }
            _ => None,
        };
        let profile = Profile::new(prog, &mech, sigma, self.points);
        let rb = if mech.is_flat() { r0 } else { r0 - roller };
        let d = CamDesign {
            mechanism: mech,
            r0,
            rb,
            roller,
            roller_rule,
            pressure_max_rise,
            pressure_max_return,
            rho_min_pitch,
            rho_min,
            rho_min_convex,
            rho_min_concave,
            face,
            profile,
        };
        d.check_finite()?;
        Ok(d)
    }
}

impl CamDesign {
    /// Offset e of a translating follower.
    pub fn offset(&self) -> Option<f64> {
        match self.mechanism {
            Mechanism::TranslatingRoller { e, .. } | Mechanism::TranslatingFlat { e, .. } => Some(e),
            _ => None,
        }
    }

    /// Pivot distance OA of an oscillating follower.
    pub fn pivot_distance(&self) -> Option<f64> {
        self.mechanism.pivot().map(|p| p.hypot())
    }

    fn check_finite(&self) -> Result<(), CamError> {
        let scalars = [
            self.r0,
            self.rb,
            self.roller,
            self.pressure_max_rise,
            self.pressure_max_return,
            self.rho_min,
        ];
        let arrays_ok = self
            .profile
            .pitch
            .iter()
            .chain(&self.profile.working)
            .all(|p| p.x.is_finite() && p.y.is_finite())
            && self.profile.curvature.iter().chain(&self.profile.pressure).all(|x| x.is_finite());
        if scalars.iter().all(|x| x.is_finite()) && arrays_ok {
            Ok(())
        } else {
            Err(CamError::Infeasible(
                "the design degenerates (a non-finite value appeared); check the dimensions and the limits".into(),
            ))
        }
    }
}
