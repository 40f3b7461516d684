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
        Some(v) => format!(" (nearest feasible value: {})", show(v)),
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

/// A number for a message: six significant digits, in exponent form when it
/// is very large or very small (a request may hold 1e300).
///
/// ```
/// use tmm_linkage::synthesis::error::show;
/// assert_eq!(show(1.2), "1.2");
/// assert_eq!(show(0.30000000000000004), "0.3");
/// assert_eq!(show(1e300), "1e300");
/// assert_eq!(show(-2.5e-9), "-2.5e-9");
/// ```
pub fn show(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{}", if x == 0.0 { 0.0 } else { x });
    }
    let e = x.abs().log10().floor();
    if !(-4.0..6.0).contains(&e) {
        let t = format!("{x:.5e}");
        let (m, ex) = t.split_once('e').unwrap_or((&t, "0"));
        let m = if m.contains('.') {
            m.trim_end_matches('0').trim_end_matches('.')
        } else {
            m
        };
        return format!("{m}e{ex}");
    }
    let d = (5.0 - e).max(0.0) as usize;
    let t = format!("{x:.d$}");
    if t.contains('.') {
        t.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        t
    }
}

/// `Ok(x)` when `x` is finite and > 0, else an input error naming `field`.
pub fn positive(field: &str, x: f64) -> Result<f64, SynthesisError> {
    if x.is_finite() && x > 0.0 {
        Ok(x)
    } else {
        Err(SynthesisError::input(
            field,
            format!("must be a finite positive number, got {}", show(x)),
        ))
    }
}

/// `Ok(x)` when `x` is finite, else an input error naming `field`.
pub fn finite(field: &str, x: f64) -> Result<f64, SynthesisError> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(SynthesisError::input(field, format!("must be a finite number, got {}", show(x))))
    }
}
