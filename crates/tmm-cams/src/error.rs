//! The typed errors of cam design: what in the input is wrong or what cannot
//! be built, with the numbers a user needs to fix it.

/// Why a cam cannot be designed as asked.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CamError {
    /// The phase list could not be read (`rise 108 cosine; dwell 15; …`).
    #[error("cannot read the phase `{text}`: {reason}")]
    Phase {
        /// The offending piece of the list.
        text: String,
        /// What is wrong with it.
        reason: String,
    },
    /// Pressure or transmission limits that could not be read (`rise 15, return 30`).
    #[error("cannot read the limits `{text}`: {reason}")]
    Limits {
        /// The text as written.
        text: String,
        /// What is wrong with it.
        reason: String,
    },
    /// A motion law name that tmm does not know.
    #[error("unknown motion law `{name}`")]
    UnknownLaw {
        /// The name as written.
        name: String,
    },
    /// A motion-law parameter out of range (e.g. `const-accel(u=1.2)`).
    #[error("motion law `{law}`: {reason}")]
    LawParameter {
        /// The law as written.
        law: String,
        /// What would be valid.
        reason: String,
    },
    /// The phase angles do not close the cycle.
    #[error("the phase angles sum to {sum_deg:.4}°, but a cam turn is 360°")]
    PhaseSum {
        /// The sum, degrees.
        sum_deg: f64,
    },
    /// Rises and returns do not alternate (a return from the bottom, two rises…).
    #[error("{0}")]
    Sequence(String),
    /// The stroke is zero, negative or not finite.
    #[error("the stroke must be positive, got {0}")]
    Stroke(f64),
    /// A pressure-angle limit outside (0°, 90°).
    #[error("the allowed pressure angle on the {phase} must lie strictly between 0° and 90°, got {deg:.3}°")]
    PressureLimit {
        /// `rise` or `return`.
        phase: &'static str,
        /// The limit, degrees.
        deg: f64,
    },
    /// A length or other dimension out of range.
    #[error("{field}: {reason}")]
    Dimension {
        /// The quantity (`roller`, `arm`, `offset`, …).
        field: &'static str,
        /// What is wrong and what would be valid.
        reason: String,
    },
    /// The roller is larger than the smallest radius of curvature of the convex
    /// part of the pitch curve: the working profile would be undercut.
    #[error(
        "the roller radius {roller_mm:.3} mm exceeds the allowed {allowed_mm:.3} mm: the pitch curve's smallest convex radius of curvature is {rho_mm:.3} mm, so the working profile would be undercut"
    )]
    RollerTooLarge {
        /// The roller radius, mm.
        roller_mm: f64,
        /// The largest roller that keeps the required working curvature, mm.
        allowed_mm: f64,
        /// The smallest convex radius of curvature of the pitch curve, mm.
        rho_mm: f64,
    },
    /// No cam centre satisfies the limits (or the design degenerates).
    #[error("{0}")]
    Infeasible(String),
}
