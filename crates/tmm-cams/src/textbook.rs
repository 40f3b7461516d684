//! The textbook's own constructions beside tmm's design (appendix П6 of
//! Chernaya, Timofeev, *ТММ. Курсовое проектирование*, BMSTU 2019): the
//! tangent methods for a translating follower ([`crate::tangents`]), the
//! level-line method for an oscillating one ([`crate::levels`]), the pressure
//! angles each resulting centre gives over the cycle (signed: the book bounds
//! one side per phase, tmm both), and the roller rules of p. 111
//! ([`crate::roller_rules`]).

use crate::design::{CamDesign, CamTask, FollowerSpec, OSC_SAMPLES};
use crate::extreme::{maximize, minimize};
use crate::levels::{self, LevelLines};
use crate::mechanism::Mechanism;
use crate::profile::{over_pieces, pitch_curvature};
use crate::program::{PhaseKind, Program};
use crate::roller_rules::RollerCheck;
use crate::sizing;
use crate::tangents::{self, Centre, TangentSizing};
use crate::{CamError, positive};
use tmm_geom::Vec2;

/// The range of the signed pressure angle over the rise and the return at
/// one centre, rad: positive on the rise's driving side.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PressureRange {
    /// (smallest, largest) on the rise.
    pub rise: (f64, f64),
    /// (smallest, largest) on the return.
    pub ret: (f64, f64),
}

impl PressureRange {
    /// Scan `theta(φ)` over each moving phase of `prog` (a scan and
    /// golden-section refinement, both ends included).
    pub fn of(prog: &Program, theta: impl Fn(f64) -> f64) -> Self {
        let (mut rise, mut ret) = ((f64::INFINITY, f64::NEG_INFINITY), (f64::INFINITY, f64::NEG_INFINITY));
        for (k, ph) in prog.phases().iter().enumerate() {
            let r = match ph.kind {
                PhaseKind::Rise => &mut rise,
                PhaseKind::Return => &mut ret,
                PhaseKind::Dwell => continue,
            };
            let a = prog.start(k);
            // just inside the ends, so the phase's own law is used
            let (lo, hi) = (a, a + ph.angle * (1.0 - 1e-12));
            let (_, mn) = minimize(&theta, lo, hi, 512);
            let (_, mx) = maximize(&theta, lo, hi, 512);
            r.0 = r.0.min(mn).min(theta(lo)).min(theta(hi));
            r.1 = r.1.max(mx).max(theta(lo)).max(theta(hi));
        }
        PressureRange { rise, ret }
    }

    /// How far the range goes past the limits, rad (0 when within): on each
    /// phase both sides are measured against that phase's limit.
    pub fn excess(&self, rise_limit: f64, return_limit: f64) -> f64 {
        let r = self.rise.1.max(-self.rise.0) - rise_limit;
        let t = self.ret.1.max(-self.ret.0) - return_limit;
        r.max(t).max(0.0)
    }
}

/// One centre of the comparison with its pressure-angle range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Checked<T> {
    /// The centre.
    pub centre: T,
    /// Its signed pressure angles over the cycle.
    pub pressure: PressureRange,
}

/// The translating follower's comparison.
#[derive(Debug, Clone, PartialEq)]
pub struct TranslatingBook {
    /// The book's steps.
    pub sizing: TangentSizing,
    /// Step 1's centre, checked.
    pub approximate: Checked<Centre>,
    /// Method 1's centre, checked.
    pub method1: Checked<Centre>,
    /// Method 2's centre, checked.
    pub method2: Checked<Centre>,
    /// tmm's design's centre (both sides of each phase bounded), checked.
    pub exact: Checked<Centre>,
    /// The smallest convex radius of curvature of the pitch curve with the
    /// book's centre (method 1) and the design's roller, m.
    pub rho_pitch_book: f64,
}

/// The oscillating follower's comparison (the book's frame: pivot at the
/// origin, the arm along +x at the lowest position, κ = +1).
#[derive(Debug, Clone, PartialEq)]
pub struct OscillatingBook {
    /// The level-line method's points.
    pub levels: LevelLines,
    /// Point 2, checked.
    pub point2: Checked<Vec2>,
    /// The envelopes' vertex, checked.
    pub vertex: Checked<Vec2>,
    /// tmm's smallest cam (both sides of every position bounded) in the
    /// book's frame and arrangement (κ = +1): the design's, or sized again
    /// when the design's arm turns the other way.
    pub exact: Checked<Vec2>,
    /// The arm length l, m.
    pub arm: f64,
}

/// The textbook's constructions for a task.
#[derive(Debug, Clone, PartialEq)]
pub struct BookMethods {
    /// Translating roller follower.
    pub translating: Option<TranslatingBook>,
    /// Oscillating roller (or knife-edge) follower.
    pub oscillating: Option<OscillatingBook>,
    /// The roller rules for the design's roller and r₀ (None for a knife
    /// edge or a flat face).
    pub roller: Option<RollerCheck>,
    /// The same rules with the book's centre (translating follower).
    pub roller_book: Option<RollerCheck>,
}

/// The smallest convex radius of curvature of the pitch curve of `mech`, m.
fn rho_pitch(prog: &Program, mech: &Mechanism, sigma: f64) -> f64 {
    let k = over_pieces(prog, 256, |m| pitch_curvature(mech, m, sigma), true);
    if k > 0.0 { 1.0 / k } else { f64::INFINITY }
}

/// The book's constructions for the task and its design: the tangent methods
/// for a translating roller, the level-line method for an oscillating one
/// (with κ = +1, as the book draws it), the pressure angles at each centre,
/// and the roller rules. Flat faces have no book construction here and are
/// refused.
pub fn compare(task: &CamTask, d: &CamDesign) -> Result<BookMethods, CamError> {
    let prog = &task.program;
    let sigma = task.rotation.sign();
    let roller = (d.roller > 0.0).then(|| RollerCheck::new(d.roller, d.r0, d.rho_min_pitch.unwrap_or(f64::INFINITY)));
    match (task.follower, d.mechanism) {
        (FollowerSpec::TranslatingRoller { .. }, Mechanism::TranslatingRoller { e, s0, .. }) => {
            let sizing = tangents::tangent_sizing(prog, sigma, task.limits)?;
            let check = |c: Centre| Checked {
                centre: c,
                pressure: PressureRange::of(prog, |phi| tangents::signed_pressure(prog, sigma, c, phi)),
            };
            let book_mech = sizing.method1.mechanism();
            let rho_pitch_book = rho_pitch(prog, &book_mech, sigma);
            let roller_book = (d.roller > 0.0).then(|| RollerCheck::new(d.roller, sizing.method1.r0(), rho_pitch_book));
            Ok(BookMethods {
                translating: Some(TranslatingBook {
                    approximate: check(sizing.approximate),
                    method1: check(sizing.method1),
                    method2: check(sizing.method2),
                    exact: check(Centre { e, s0 }),
                    sizing,
                    rho_pitch_book,
                }),
                oscillating: None,
                roller,
                roller_book,
            })
        }
        (
            FollowerSpec::OscillatingRoller { arm, .. },
            Mechanism::OscillatingRoller {
                pivot, psi0, kappa: dk, ..
            },
        ) => {
            if !positive(arm) {
                return Err(CamError::Dimension {
                    field: "arm",
                    reason: format!("the arm length must be positive, got {arm}"),
                });
            }
            let kappa = 1.0;
            let lv = levels::level_lines(prog, sigma, kappa, task.limits, arm)?;
            let check = |o: Vec2| Checked {
                centre: o,
                pressure: PressureRange::of(prog, |phi| levels::signed_pressure(prog, sigma, kappa, arm, o, phi)),
            };
            // the design's centre in the book's frame: O − A = −pivot, turned
            // so that the arm's lowest direction is +x; a design whose arm
            // turns clockwise on the rise is sized again with κ = +1
            let (pivot, psi0) = if dk > 0.0 {
                (pivot, psi0)
            } else {
                match sizing::oscillating_roller_senses(prog, sigma, task.limits, arm, None, OSC_SAMPLES, &[1.0])? {
                    Mechanism::OscillatingRoller { pivot, psi0, .. } => (pivot, psi0),
                    _ => {
                        return Err(CamError::Infeasible(
                            "the oscillating sizing gave no oscillating mechanism".into(),
                        ));
                    }
                }
            };
            let (s, c) = (-psi0).sin_cos();
            let v = -pivot;
            let exact = check(Vec2::new(c * v.x - s * v.y, s * v.x + c * v.y));
            Ok(BookMethods {
                translating: None,
                oscillating: Some(OscillatingBook {
                    point2: check(lv.point2),
                    vertex: check(lv.vertex),
                    exact,
                    levels: lv,
                    arm,
                }),
                roller,
                roller_book: None,
            })
        }
        _ => Err(CamError::Infeasible(
            "the book's constructions (П6) are for roller and knife-edge followers: the tangent methods for a translating one, the level lines for an oscillating one".into(),
        )),
    }
}
