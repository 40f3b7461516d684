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
    /// The module is not a positive length inside the plausible range
    /// [`crate::spec::MODULE_MIN`] … [`crate::spec::MODULE_MAX`] (0.05 … 100 mm,
    /// the span of GOST 9563-60's series).
    #[error("the module must be a length between 0.05 mm and 100 mm (the span of the GOST 9563-60 series), got {} mm{}", .0 * 1e3, crate::error::unit_hint(*.0))]
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
    /// The tip circle does not reach the involute: it lies inside the base
    /// circle, or (for a wheel cut by the rack) at or below the circle where the
    /// generated involute begins, so the whole tooth is the cutter's fillet.
    #[error("{}", crate::error::tip_inside_text(*.wheel, *.da, *.db, *.form))]
    TipInsideBase {
        /// 1 or 2 (0: a lone wheel generated outside a pair).
        wheel: u8,
        /// Tip diameter, m.
        da: f64,
        /// Diameter where the involute begins, m: the base circle, or with
        /// `form` the form circle of the rack's straight flank.
        db: f64,
        /// `true` when `db` is the form circle (the tip lies below the start of
        /// the generated involute: lower the shift); `false` for the base
        /// circle (raise the shift).
        form: bool,
    },
    /// The shift sum gives no operating pressure angle: inv αw < 0 (too
    /// negative), or αw practically 90° (too large).
    #[error("{}", crate::error::shift_sum_text(*.x_sum, *.inv_aw))]
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
    /// A result is not finite (guard against NaN and infinity): names the quantity.
    #[error("the calculation gave a non-finite {0}; the input is out of any practical range")]
    NonFinite(&'static str),
}

impl GearError {
    /// What the user can do about it, in words (for the edge to print under
    /// the message).
    ///
    /// ```
    /// use tmm_gears::GearError;
    /// let e = GearError::TipInsideBase { wheel: 1, da: 0.115, db: 0.159, form: true };
    /// assert!(e.help().contains("lower x1"));
    /// ```
    pub fn help(&self) -> String {
        match self {
            GearError::TooFewTeeth { min, .. } => {
                format!("use at least {min} teeth (fewer cannot be cut by the rack without undercut or a pointed tip)")
            }
            GearError::Module(m) => format!(
                "give the module with its unit, e.g. \"5 mm\"; the GOST 9563-60 series spans 0.05 mm to 100 mm{}",
                unit_hint(*m)
            ),
            GearError::Rack { .. } => "the default rack is α = 20°, ha* = 1, c* = 0.25, hl* = 2 (GOST 13755-81)".into(),
            GearError::Shift { .. } => "a shift is a plain number such as 0.3".into(),
            GearError::TipBelowRoot { wheel, .. } => format!(
                "lower the shift sum (its tip shortening Δy eats the tooth) or x{wheel}; `tmm gear contour` shows the allowed region"
            ),
            GearError::TipInsideBase { wheel, form: true, .. } => format!(
                "lower x{wheel} (or the shift sum): the rack's straight flank then cuts the involute below the tip; `tmm gear contour` shows the allowed region"
            ),
            GearError::TipInsideBase { wheel, form: false, .. } => {
                format!("raise x{wheel}: the tip circle then moves out past the base circle")
            }
            GearError::ShiftSum { .. } => "raise x1 + x2 (x2 − x1 for an internal pair)".into(),
            GearError::CentreDistance { min, .. } => format!("give aw above {:.4} mm", min * 1e3),
            GearError::InternalAssembly(_) => "see the message for the condition that fails and what to change".into(),
            GearError::NoFeasibleSplit(_) => "try another criterion, relax sa_min or eps_min, or change the tooth numbers".into(),
            GearError::NonFinite(_) => "check the magnitudes of the input (module, shifts, tooth numbers)".into(),
        }
    }
}

/// A hint when a module looks like a length given in the wrong unit.
pub(crate) fn unit_hint(m: f64) -> String {
    if (0.05..=100.0).contains(&m) {
        format!(" — did you mean {} mm? (a number without a unit is read in metres)", m)
    } else {
        String::new()
    }
}

/// The message of [`GearError::ShiftSum`]: which way the sum is out.
pub(crate) fn shift_sum_text(x_sum: f64, inv_aw: f64) -> String {
    if inv_aw < 0.0 {
        format!("the shift sum {x_sum:.4} is too negative: inv αw = {inv_aw:.6} < 0 has no operating pressure angle")
    } else {
        format!(
            "the shift sum {x_sum:.4} is too large: inv αw = {inv_aw:.6} puts the operating pressure angle at practically 90°, where the teeth cannot transmit motion"
        )
    }
}

/// The message of [`GearError::TipInsideBase`].
pub(crate) fn tip_inside_text(wheel: u8, da: f64, db: f64, form: bool) -> String {
    let who = if wheel == 0 {
        "the wheel".to_string()
    } else {
        format!("wheel {wheel}")
    };
    if form {
        format!(
            "{who}: the tip circle (d = {:.4} mm) lies inside the circle where the involute cut by the rack's straight flank begins (d = {:.4} mm): the tooth has no involute, it is all fillet",
            da * 1e3,
            db * 1e3
        )
    } else {
        format!(
            "{who}: the tip circle (d = {:.4} mm) lies inside the base circle (d = {:.4} mm), so the tip has no involute",
            da * 1e3,
            db * 1e3
        )
    }
}
