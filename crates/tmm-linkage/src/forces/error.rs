//! Errors of kinetostatics: loads that do not fit the mechanism, a load
//! diagram that does not cover the stroke, a group whose reactions are not
//! determined (a dead centre), a beam that cannot be built.

use crate::LinkageError;

/// What is wrong with a force calculation.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ForceError {
    /// A load does not fit the mechanism or is not physical. `field` names
    /// the load (`links.2.mass`, `resistance.table`).
    #[error("{field}: {message}")]
    Load {
        /// Which load.
        field: String,
        /// What is wrong and what would be valid.
        message: String,
    },
    /// The kinematics failed at a crank angle.
    #[error(transparent)]
    Kinematics(#[from] LinkageError),
    /// The equilibrium equations of a group are singular (the group is at a
    /// dead centre: its reactions are not determined by statics).
    #[error("the reactions of group {group} are not determined at φ = {phi_deg:.4}° (its links are aligned: a dead centre)")]
    Singular {
        /// Crank angle, degrees.
        phi_deg: f64,
        /// The group label.
        group: String,
    },
    /// A result is not a finite number.
    #[error("{what} is not finite at φ = {phi_deg:.4}°")]
    NonFinite {
        /// Crank angle, degrees.
        phi_deg: f64,
        /// Which quantity.
        what: String,
    },
}

impl ForceError {
    /// A load error.
    pub fn load(field: impl Into<String>, message: impl Into<String>) -> Self {
        ForceError::Load {
            field: field.into(),
            message: message.into(),
        }
    }
}
