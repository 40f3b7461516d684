//! Errors of metric synthesis (метрический синтез): a request that is not
//! well formed, and a well-formed request that no mechanism of the kind can
//! meet — with the condition that fails and the nearest value that would work.

use crate::error::LinkageError;

/// Why a synthesis request has no answer.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SynthesisError {
    /// A given value is out of its domain (not finite, not positive, …).
    #[error("{field}: {message}")]
    Input {
        /// The field of the request (`k`, `stroke`, `lambda`, …).
        field: String,
        /// What is wrong and what would be valid.
        message: String,
    },
    /// The request is well formed but no mechanism of this kind meets it.
    /// `nearest` is the closest value of `field` for which one exists (with
    /// everything else unchanged), when there is such a value.
    #[error("{field}: {condition}{}", nearest_text(*.nearest))]
    Infeasible {
        /// The field whose value cannot be met.
        field: String,
        /// The condition that fails, in words with the numbers.
        condition: String,
        /// Nearest feasible value of `field` (SI, angles in rad).
        nearest: Option<f64>,
    },
    /// The synthesised mechanism failed its independent check over the cycle
    /// (the analysis disagrees with the request beyond the tolerance).
    #[error("check of the result: {0}")]
    Check(String),
    /// The linkage core rejected the synthesised mechanism.
    #[error("analysis of the result: {0}")]
    Linkage(#[from] LinkageError),
}

fn nearest_text(n: Option<f64>) -> String {
    match n {
        Some(v) => format!(" (nearest feasible value: {v:.6})"),
        None => String::new(),
    }
}

impl SynthesisError {
    /// An input error.
    pub fn input(field: impl Into<String>, message: impl Into<String>) -> Self {
        SynthesisError::Input {
            field: field.into(),
            message: message.into(),
        }
    }

    /// An infeasibility error.
    pub fn infeasible(field: impl Into<String>, condition: impl Into<String>, nearest: Option<f64>) -> Self {
        SynthesisError::Infeasible {
            field: field.into(),
            condition: condition.into(),
            nearest: nearest.filter(|v| v.is_finite()),
        }
    }
}

/// `Ok(x)` when `x` is finite and > 0, else an input error naming `field`.
pub fn positive(field: &str, x: f64) -> Result<f64, SynthesisError> {
    if x.is_finite() && x > 0.0 {
        Ok(x)
    } else {
        Err(SynthesisError::input(field, format!("must be a finite positive number, got {x}")))
    }
}

/// `Ok(x)` when `x` is finite, else an input error naming `field`.
pub fn finite(field: &str, x: f64) -> Result<f64, SynthesisError> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(SynthesisError::input(field, format!("must be a finite number, got {x}")))
    }
}
