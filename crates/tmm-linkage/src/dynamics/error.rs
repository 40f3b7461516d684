//! Errors of the dynamics of the machine: a specification that is not
//! physical, loads that need no drive, a motor that cannot turn the crank at
//! its speed, and failures of the kinematics or of an iteration.

use crate::LinkageError;
use crate::forces::ForceError;

/// What is wrong with a dynamics calculation.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DynamicsError {
    /// A field of the specification is out of range. `field` names it
    /// (`dynamics.delta`, `dynamics.motor.ratio`).
    #[error("{field}: {message}")]
    Spec {
        /// Which field.
        field: String,
        /// What is wrong and what would be valid.
        message: String,
    },
    /// The loads do no resisting work over a cycle, so no driving moment is
    /// needed and the flywheel problem has no meaning.
    #[error(
        "the loads do no resisting work over a cycle (work of the loads {work:.6e} J per turn of the crank); the dynamics needs a useful resistance or other loads that the drive must overcome (give them in [forces])"
    )]
    NoResistance {
        /// The work of all loads over one cycle, J (≥ 0, or negative only by
        /// rounding: within 1e-9 of ∫|M_c|dφ).
        work: f64,
    },
    /// An engine whose loads do no driving work over its cycle.
    #[error(
        "the loads do no driving work over the machine's cycle (work of the loads {work:.6e} J per cycle): an engine needs gas forces that drive (give the cylinders' indicator diagrams in [forces])"
    )]
    NoDrive {
        /// The work of all loads over one cycle, J.
        work: f64,
    },
    /// The loads are wrong for the mechanism.
    #[error(transparent)]
    Force(#[from] ForceError),
    /// The kinematics failed at a crank angle.
    #[error(transparent)]
    Kinematics(#[from] LinkageError),
    /// A result is not a finite number.
    #[error("{what} is not finite")]
    NonFinite {
        /// Which quantity.
        what: String,
    },
    /// An iteration did not converge.
    #[error("{what} did not converge")]
    NoConvergence {
        /// Which iteration.
        what: String,
    },
    /// The crank stopped or turned back during a time integration.
    #[error(
        "the crank stops at t = {time:.6} s (φ = {phi_deg:.3}° from the start of the cycle): the driving moment cannot overcome the loads there"
    )]
    Stall {
        /// Time, s.
        time: f64,
        /// Crank angle from the start of the cycle, degrees.
        phi_deg: f64,
    },
}

impl DynamicsError {
    /// A specification error.
    pub fn spec(field: impl Into<String>, message: impl Into<String>) -> Self {
        DynamicsError::Spec {
            field: field.into(),
            message: message.into(),
        }
    }
}

/// A number for a message: as Rust writes it when it is of a usual size
/// (`0.02`, `157.08`), in scientific notation otherwise (`1e300`, not three
/// hundred digits).
///
/// ```
/// use tmm_linkage::dynamics::error::show;
/// assert_eq!(show(0.02), "0.02");
/// assert_eq!(show(1e300), "1e300");
/// assert_eq!(show(-2.5e-9), "-2.5e-9");
/// assert_eq!(show(0.0), "0");
/// ```
pub fn show(x: f64) -> String {
    if x == 0.0 || !x.is_finite() || (1e-4..1e7).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}
