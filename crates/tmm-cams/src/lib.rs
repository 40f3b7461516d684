//! Cam mechanisms (кулачковые механизмы): motion laws, the smallest cam for a
//! pressure-angle limit or for convexity, and the profile by kinematic
//! inversion, with its curvature and pressure angle. No I/O.
//!
//! | module | concept |
//! | --- | --- |
//! | [`law`] | one normalized motion law per phase, closed form |
//! | [`segments`] | piecewise acceleration analogs integrated exactly |
//! | [`program`] | the cycle: rise, dwell, return phases over 360° |
//! | [`spec`] | the compact text forms: phase lists, pressure limits |
//! | [`mechanism`] | a sized mechanism: pitch point, face line, pressure angle |
//! | [`sizing`] | smallest r₀ (s–ds/dφ region; Geronimus' convexity) |
//! | [`halfplane`] | half-plane regions and their nearest points |
//! | [`extreme`] | extremes of smooth functions on an interval |
//! | [`profile`] | pitch and working profiles, curvature, pressure angle |
//! | [`design`] | the whole design from a task |
//! | [`tangents`] | the textbook's tangent methods for a translating follower (П6.4) |
//! | [`levels`] | the textbook's level-line method for an oscillating follower (П6.5) |
//! | [`roller_rules`] | the textbook's roller-radius rules (p. 111) |
//! | [`textbook`] | the textbook's constructions beside the design, checked |
//!
//! ```
//! use tmm_cams::{design::{CamTask, FollowerSpec}, mechanism::Rotation, program::Program, spec};
//! let program = Program::new(0.013, spec::parse_phases("rise 108 const-accel(u=1/3); dwell 15; return 108 const-accel(u=1/3); dwell 129").unwrap()).unwrap();
//! let task = CamTask {
//!     program,
//!     follower: FollowerSpec::TranslatingRoller { offset: None, roller: None },
//!     rotation: Rotation::Ccw,
//!     limits: spec::parse_limits("rise 75, return 60", true).unwrap(),
//!     min_curvature: None,
//!     face_margin: 0.005,
//!     omega: 200.0,
//!     points: 720,
//! };
//! let d = task.solve().unwrap();
//! assert!(d.pressure_max_rise <= 15f64.to_radians() + 1e-9);
//! assert!(d.pressure_max_return <= 30f64.to_radians() + 1e-9);
//! assert!(d.roller <= 0.4 * d.r0 + 1e-15);
//! ```

pub mod design;
pub mod error;
pub mod extreme;
pub mod halfplane;
pub mod law;
pub mod levels;
pub mod mechanism;
pub mod profile;
pub mod program;
pub mod roller_rules;
pub mod segments;
pub mod sizing;
pub mod spec;
pub mod tangents;
pub mod textbook;

pub use error::CamError;

/// `true` for a finite number above zero (NaN and infinities are not).
///
/// ```
/// assert!(tmm_cams::positive(1e-300) && !tmm_cams::positive(0.0) && !tmm_cams::positive(f64::NAN));
/// ```
#[inline]
pub fn positive(x: f64) -> bool {
    x.is_finite() && x > 0.0
}
