//! The basic rack profile (исходный контур) that generates the wheels.

use crate::GearError;

/// The basic rack (исходный контур, GOST 13755-81 / ISO 53): profile angle α,
/// addendum coefficient ha*, clearance coefficient c*, boundary-height
/// coefficient hl* (коэффициент граничной высоты: the straight flank spans
/// hl*·m in all).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BasicRack {
    /// Profile angle α, rad (угол профиля).
    pub alpha: f64,
    /// Addendum coefficient ha* (коэффициент высоты головки).
    pub ha: f64,
    /// Clearance coefficient c* (коэффициент радиального зазора).
    pub c: f64,
    /// Boundary-height coefficient hl* (коэффициент граничной высоты).
    pub hl: f64,
}

impl Default for BasicRack {
    /// GOST 13755-81: α = 20°, ha* = 1, c* = 0.25, hl* = 2.
    fn default() -> Self {
        BasicRack {
            alpha: 20f64.to_radians(),
            ha: 1.0,
            c: 0.25,
            hl: 2.0,
        }
    }
}

impl BasicRack {
    /// Check the ranges: 5° < α < 45°, ha* > 0, c* ≥ 0, ha* ≤ hl* − ha* + … such
    /// that the cutter's tip fillet has a non-negative radius.
    pub fn validate(&self) -> Result<(), GearError> {
        if !(self.alpha.is_finite() && self.alpha > 5f64.to_radians() && self.alpha < 45f64.to_radians()) {
            return Err(GearError::Rack {
                param: "alpha",
                msg: "the profile angle α must lie between 5° and 45°",
            });
        }
        if !(self.ha.is_finite() && self.ha > 0.0 && self.ha <= 3.0) {
            return Err(GearError::Rack {
                param: "ha",
                msg: "ha* must lie in (0, 3]",
            });
        }
        if !(self.c.is_finite() && self.c >= 0.0 && self.c <= 1.0) {
            return Err(GearError::Rack {
                param: "c",
                msg: "c* must lie in [0, 1]",
            });
        }
        if !(self.hl.is_finite() && self.hl > self.ha && self.hl <= 2.0 * self.ha + self.c) {
            return Err(GearError::Rack {
                param: "hl",
                msg: "hl* must lie in (ha*, 2·ha* + c*] so that the cutter's straight flank ends above its tip fillet",
            });
        }
        Ok(())
    }

    /// Height of the cutter's straight flank above its reference line, in
    /// modules: `hl* − ha*` (the part that cuts the dedendum involute).
    ///
    /// ```
    /// assert_eq!(tmm_gears::BasicRack::default().flank_depth(), 1.0);
    /// ```
    #[inline]
    pub fn flank_depth(&self) -> f64 {
        self.hl - self.ha
    }

    /// Cutter tip fillet radius in modules, ρf* = (ha* + c* − (hl* − ha*)) / (1 − sin α):
    /// the circle tangent to the tip line at depth (ha* + c*)·m and to the flank
    /// where the straight part ends (derived here, docs/gears.md §Rack; gives
    /// GOST 13755-81's ρf* = 0.38 for the default rack).
    ///
    /// ```
    /// let r = tmm_gears::BasicRack::default().fillet_radius();
    /// assert!((r - 0.38).abs() < 0.001);
    /// ```
    #[inline]
    pub fn fillet_radius(&self) -> f64 {
        (2.0 * self.ha + self.c - self.hl) / (1.0 - self.alpha.sin())
    }

    /// The largest tip fillet, in modules, that fits on the cutter's tooth:
    /// the two fillets of one tooth meet on its centreline (a full-round tip),
    /// `ρf,max* = (π/4 − (ha* + c*) tg α)·cos α / (1 − sin α)` (derived here,
    /// docs/gears.md §Rack). Negative when the cutter's tooth is pointed before
    /// its tip line.
    ///
    /// ```
    /// let r = tmm_gears::BasicRack::default();
    /// assert!(r.max_fillet_radius() > r.fillet_radius()); // 0.38 fits on the 20° rack
    /// ```
    #[inline]
    pub fn max_fillet_radius(&self) -> f64 {
        let (s, c) = self.alpha.sin_cos();
        (std::f64::consts::FRAC_PI_4 - (self.ha + self.c) * self.alpha.tan()) * c / (1.0 - s)
    }

    /// The rack with the largest tip fillet that fits: unchanged when the
    /// fillet that ends the straight flank at hl* fits on the cutter's tip;
    /// otherwise the fillet is reduced to [`BasicRack::max_fillet_radius`]
    /// and the straight flank runs deeper, `hl* = 2ha* + c* − ρf*(1 − sin α)`
    /// (e.g. α = 25°: ρf* 0.433 → 0.318, hl* 2 → 2.066). Use the returned rack
    /// for the whole pair, so the checks (ρl, xmin) and the generated teeth
    /// agree; an error when even a sharp tip does not fit.
    ///
    /// ```
    /// use tmm_gears::BasicRack;
    /// let r = BasicRack { alpha: 25f64.to_radians(), ..BasicRack::default() };
    /// let f = r.fit_fillet().unwrap();
    /// assert!(f.reduced && f.rho_f < f.rho_f_nominal && f.rack.hl > r.hl);
    /// assert!(!BasicRack::default().fit_fillet().unwrap().reduced);
    /// ```
    pub fn fit_fillet(&self) -> Result<FilletFit, GearError> {
        self.validate()?;
        let nominal = self.fillet_radius();
        let max = self.max_fillet_radius();
        if max.is_nan() || max <= 0.0 {
            return Err(GearError::Rack {
                param: "alpha",
                msg: "the cutter's tooth is pointed before its tip line ((ha* + c*)·tg α ≥ π/4): lower α, ha* or c*",
            });
        }
        if nominal <= max {
            return Ok(FilletFit {
                rack: *self,
                rho_f: nominal,
                rho_f_nominal: nominal,
                reduced: false,
            });
        }
        let hl = 2.0 * self.ha + self.c - max * (1.0 - self.alpha.sin());
        Ok(FilletFit {
            rack: BasicRack { hl, ..*self },
            rho_f: max,
            rho_f_nominal: nominal,
            reduced: true,
        })
    }
}

/// The cutter's tip fillet chosen by [`BasicRack::fit_fillet`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilletFit {
    /// The rack to use (hl* raised when the fillet was reduced).
    pub rack: BasicRack,
    /// The fillet radius used, in modules (ρf*).
    pub rho_f: f64,
    /// The fillet the given hl* asks for, in modules.
    pub rho_f_nominal: f64,
    /// `true` when the given fillet did not fit and the largest that fits was used.
    pub reduced: bool,
}
