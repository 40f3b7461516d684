//! The typed errors of the planetary core: a request that is malformed, or one
//! that no tooth-number set can meet (naming the condition that fails first).

use std::fmt;

/// A condition of the tooth-number search, in the order they are applied.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Condition {
    /// The ratio within the tolerance together with coaxiality.
    RatioCoaxiality,
    /// No undercut of the external wheels.
    Undercut,
    /// The internal-mesh limits (smallest ring, smallest tooth difference).
    InternalMesh,
    /// Assembly: room for `k` planets at all.
    Assembly,
    /// The neighbour condition (tip circles of adjacent planets).
    Neighbour,
}

impl Condition {
    /// A short name for messages and JSON.
    pub fn name(self) -> &'static str {
        match self {
            Condition::RatioCoaxiality => "ratio and coaxiality",
            Condition::Undercut => "no-undercut",
            Condition::InternalMesh => "internal-mesh",
            Condition::Assembly => "assembly",
            Condition::Neighbour => "neighbour",
        }
    }
}

impl fmt::Display for Condition {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// What can go wrong in a tooth-number search.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PlanetaryError {
    /// A request field is out of its range.
    #[error("{field}: {message}")]
    Invalid {
        /// The request field (`ratio`, `planets`, `tolerance`, `zmin`, `zmax`,
        /// `ring_zmin`, `min_difference`, `addendum`, `efficiency`, `module`, `omega1`).
        field: &'static str,
        /// What is wrong.
        message: String,
        /// What would be valid.
        help: String,
    },
    /// No tooth-number set meets every condition.
    #[error("{condition}: {message}")]
    NoSolution {
        /// The first condition after which no set was left.
        condition: Condition,
        /// What happened.
        message: String,
        /// What the user can change.
        help: String,
    },
}

impl PlanetaryError {
    /// What would be valid, or what to change.
    pub fn help(&self) -> &str {
        match self {
            PlanetaryError::Invalid { help, .. } | PlanetaryError::NoSolution { help, .. } => help,
        }
    }
}
