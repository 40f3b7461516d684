//! Typed errors of the gear calculations (ошибки исходных данных).

/// Why a gear pair cannot be computed as given.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum GearError {
    /// A tooth number below the smallest that can be cut.
    #[error("z{wheel} = {z} is below the smallest tooth number that can be cut without undercut and without a pointed tip ({min})")]
    TooFewTeeth {
        /// 1 (pinion) or 2 (wheel).
        wheel: u8,
        /// The tooth number given.
        z: u32,
        /// The smallest tooth number that can be cut.
        min: u32,
    },
    /// The module is not a positive finite length.
    #[error("the module must be a positive length, got {} mm", .0 * 1e3)]
    Module(f64),
    /// A basic-rack parameter is out of range.
    #[error("basic rack: {msg}")]
    Rack {
        /// Which parameter: `alpha`, `ha`, `c` or `hl`.
        param: &'static str,
        /// What is wrong.
        msg: &'static str,
    },
    /// A profile shift is not a finite number.
    #[error("the shift x{wheel} must be a finite number")]
    Shift {
        /// 1 or 2.
        wheel: u8,
    },
    /// The shifts give a tip circle at or below the root circle.
    #[error("wheel {wheel}: the tip diameter {:.4} mm is not above the root diameter {:.4} mm (the tip shortening Δy of a large shift sum eats the whole tooth)", .da * 1e3, .df * 1e3)]
    TipBelowRoot {
        /// 1 or 2.
        wheel: u8,
        /// Tip diameter, m.
        da: f64,
        /// Root diameter, m.
        df: f64,
    },
    /// The tip circle is inside the base circle: no involute at the tip.
    #[error("wheel {wheel}: the tip circle (d = {:.4} mm) lies inside the base circle (d = {:.4} mm), so the tip has no involute", .da * 1e3, .db * 1e3)]
    TipInsideBase {
        /// 1 or 2.
        wheel: u8,
        /// Tip diameter, m.
        da: f64,
        /// Base diameter, m.
        db: f64,
    },
    /// The shift sum gives no operating pressure angle (inv αw < 0).
    #[error("the shift sum {x_sum:.4} is too negative: inv αw = {inv_aw:.6} < 0 has no operating pressure angle")]
    ShiftSum {
        /// x1 + x2 (external) or x2 − x1 (internal).
        x_sum: f64,
        /// The involute of the operating pressure angle.
        inv_aw: f64,
    },
    /// A centre distance that no shift sum can reach.
    #[error("the centre distance {:.4} mm cannot be reached by any shift sum: it must exceed a·cos α = {:.4} mm", .aw * 1e3, .min * 1e3)]
    CentreDistance {
        /// The centre distance given, m.
        aw: f64,
        /// The exclusive lower bound, m.
        min: f64,
    },
    /// An internal pair that cannot be assembled or run.
    #[error("the internal pair cannot be assembled: {0}")]
    InternalAssembly(String),
    /// No shift split satisfies every check.
    #[error("no x1, x2 inside the blocking contour satisfies every check{0}")]
    NoFeasibleSplit(String),
    /// A result is not finite (guard against NaN and infinity).
    #[error("the calculation gave a non-finite {0}")]
    NonFinite(&'static str),
}
