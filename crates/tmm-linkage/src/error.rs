//! Errors of the linkage core: a description that is not a mechanism, and a
//! mechanism that cannot be assembled or whose velocities are singular.

/// What is wrong with a mechanism or a solve.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LinkageError {
    /// The description itself is inconsistent (unknown name, duplicate, zero
    /// length…). `field` names the part of the description.
    #[error("{field}: {message}")]
    Description {
        /// The part of the description (`links.2`, `input.link`, …).
        field: String,
        /// What is wrong and what would be valid.
        message: String,
    },
    /// The degree of freedom is not 1.
    #[error("{}", mobility_message(*dof, *w, *n, *p5, *p4, detail))]
    Mobility {
        /// DOF from the rank of the constraint equations.
        dof: i64,
        /// Chebyshev's W.
        w: i64,
        /// Moving links.
        n: usize,
        /// Lower pairs.
        p5: usize,
        /// Higher pairs.
        p4: usize,
        /// Extra explanation.
        detail: String,
    },
    /// The mechanism moves, but some of its constraints repeat others
    /// (redundant constraints, избыточные связи) or its rank-based mobility
    /// differs from Chebyshev's W: found by the rank of the constraint
    /// equations at an assembled position.
    #[error(
        "Chebyshev's W = 3n − 2p5 = 3·{n} − 2·{p5} = {w}, but the rank of the constraint equations at an assembled position gives mobility {dof} with {redundant} redundant constraint(s) (избыточные связи) and {passive} passive freedom(s): the mechanism is statically indeterminate, which the Assur-group solution cannot handle ({detail}); remove the repeated link or pair (e.g. the third crank of a double parallelogram) and analyse the mechanism without it — its motion is the same"
    )]
    Redundant {
        /// Chebyshev's W.
        w: i64,
        /// Moving links.
        n: usize,
        /// Lower pairs.
        p5: usize,
        /// Mobility from the rank.
        dof: i64,
        /// Redundant constraints q.
        redundant: i64,
        /// Passive freedoms.
        passive: i64,
        /// Which links do not form groups.
        detail: String,
    },
    /// The mechanism does not decompose into the input and Assur groups.
    #[error("structure: {0}")]
    Structure(String),
    /// A group cannot be assembled at a crank angle.
    #[error("cannot be assembled at φ = {phi_deg:.4}°: group {group}: {reason}")]
    Assembly {
        /// Crank angle, degrees.
        phi_deg: f64,
        /// The group (`II(2,3) RRR`).
        group: String,
        /// Why (`|BD| = 0.91 m > BC + CD = 0.86 m`).
        reason: String,
    },
    /// A group cannot be assembled at a travel of the input slider.
    #[error("cannot be assembled at s = {s_mm:.4} mm: group {group}: {reason}")]
    AssemblyAtTravel {
        /// The slider's travel, mm.
        s_mm: f64,
        /// The group (`II(2,3) RRR`).
        group: String,
        /// Why.
        reason: String,
    },
    /// The velocity equations of a group are singular at a travel of the
    /// input slider (a dead centre of the group).
    #[error("no finite velocities at s = {s_mm:.6} mm: group {group}: {reason}")]
    SingularAtTravel {
        /// The slider's travel, mm.
        s_mm: f64,
        /// The group.
        group: String,
        /// Why.
        reason: String,
    },
    /// The mechanism cannot be assembled over whole ranges of the crank angle.
    #[error("cannot be assembled for crank angles {ranges}: {reason}")]
    AssemblyRanges {
        /// The ranges, e.g. `102.5°…157.5°`.
        ranges: String,
        /// The first reason met.
        reason: String,
    },
    /// The velocity (or acceleration) equations of a group are singular or
    /// nearly so: the group is at or next to a dead centre (мёртвое положение
    /// группы), where its velocities grow without bound.
    #[error("no finite velocities at φ = {phi_deg:.6}°: group {group}: {reason}")]
    Singular {
        /// Crank angle, degrees.
        phi_deg: f64,
        /// The group.
        group: String,
        /// Why, with the relative measure (the sine of the angle between the
        /// columns of the group's velocity equations).
        reason: String,
    },
    /// A value given to the core lies outside its physically sensible range.
    #[error("{field}: {value} is outside the accepted range {range}{why}")]
    Range {
        /// The quantity (`input.omega`, `links.2.C`, `phi`).
        field: String,
        /// The value as given, with its unit.
        value: String,
        /// The accepted range, with units.
        range: String,
        /// Why the range, or what to do.
        why: String,
    },
    /// A result came out non-finite (an overflow the ranges did not prevent).
    #[error("{what} is not a finite number at φ = {phi_deg:.6}°")]
    NonFinite {
        /// Crank angle, degrees.
        phi_deg: f64,
        /// Which quantity.
        what: String,
    },
}

impl LinkageError {
    /// A description error.
    pub fn desc(field: impl Into<String>, message: impl Into<String>) -> Self {
        LinkageError::Description {
            field: field.into(),
            message: message.into(),
        }
    }
}

/// The text of [`LinkageError::Mobility`]: Chebyshev's count, and the rank's
/// mobility where it differs from it, so the message never states one number
/// and computes another.
///
/// ```
/// use tmm_linkage::LinkageError;
/// let e = LinkageError::Mobility { dof: 0, w: 0, n: 4, p5: 6, p4: 0, detail: String::new() };
/// assert!(e.to_string().starts_with("the mechanism has 0 degrees of freedom (W = 3n − 2p5 − p4 = 3·4 − 2·6 − 0 = 0)"));
/// let e = LinkageError::Mobility { dof: 8, w: 1, n: 3, p5: 4, p4: 0, detail: String::new() };
/// let t = e.to_string();
/// assert!(t.contains("W = 3n − 2p5 − p4 = 3·3 − 2·4 − 0 = 1") && t.contains("mobility 8"), "{t}");
/// assert!(!t.contains("has 8 degrees"), "{t}");
/// ```
fn mobility_message(dof: i64, w: i64, n: usize, p5: usize, p4: usize, detail: &str) -> String {
    let count = format!("W = 3n − 2p5 − p4 = 3·{n} − 2·{p5} − {p4} = {w}");
    if dof == w {
        format!("the mechanism has {dof} degrees of freedom ({count}); a mechanism driven by one crank needs 1{detail}")
    } else {
        format!(
            "Chebyshev's {count}, but the rank of the constraint equations at the assembled position gives mobility {dof}; a mechanism driven by one crank needs 1 — with W = 1 this means the links are too short against the mechanism's extent for their pairs to be told apart (a length under a millionth of the largest?){detail}"
        )
    }
}
