//! What the user gives for one pair: tooth numbers, module, shifts, rack, kind.

use std::f64::consts::PI;

use tmm_geom::involute::inv;

use crate::{BasicRack, GearError};

/// External pair (внешнее зацепление) or internal pair with wheel 2 a ring
/// (внутреннее зацепление).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Kind {
    /// Two external wheels.
    #[default]
    External,
    /// Wheel 2 is a ring gear (internal teeth).
    Internal,
}

/// The data of one pair (исходные данные).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairSpec {
    /// Pinion tooth number z1 (число зубьев шестерни).
    pub z1: u32,
    /// Wheel tooth number z2 (число зубьев колеса).
    pub z2: u32,
    /// Module m, metres (модуль).
    pub m: f64,
    /// Pinion profile shift coefficient x1 (коэффициент смещения).
    pub x1: f64,
    /// Wheel profile shift coefficient x2. For a ring, positive x2 moves the
    /// cutter away from the ring axis (GOST 19274-73 sign).
    pub x2: f64,
    /// The basic rack.
    pub rack: BasicRack,
    /// External or internal.
    pub kind: Kind,
}

impl PairSpec {
    /// An external pair on the default rack.
    pub fn external(z1: u32, z2: u32, m: f64, x1: f64, x2: f64) -> Self {
        PairSpec {
            z1,
            z2,
            m,
            x1,
            x2,
            rack: BasicRack::default(),
            kind: Kind::External,
        }
    }

    /// Check everything that does not need the geometry (the module by
    /// [`check_module`]).
    pub fn validate(&self) -> Result<(), GearError> {
        self.rack.validate()?;
        check_module(self.m)?;
        if !self.x1.is_finite() {
            return Err(GearError::Shift { wheel: 1 });
        }
        if !self.x2.is_finite() {
            return Err(GearError::Shift { wheel: 2 });
        }
        let zmin = smallest_cuttable(&self.rack);
        if self.z1 < zmin {
            return Err(GearError::TooFewTeeth {
                wheel: 1,
                z: self.z1,
                min: zmin,
            });
        }
        match self.kind {
            Kind::External => {
                if self.z2 < zmin {
                    return Err(GearError::TooFewTeeth {
                        wheel: 2,
                        z: self.z2,
                        min: zmin,
                    });
                }
            }
            Kind::Internal => {
                if self.z2 <= self.z1 {
                    return Err(GearError::InternalAssembly(format!(
                        "the ring needs more teeth than the pinion (z2 = {} ≤ z1 = {})",
                        self.z2, self.z1
                    )));
                }
            }
        }
        Ok(())
    }
}

/// The smallest module accepted, 0.05 mm: the first value of GOST 9563-60's
/// series of modules (Модули, ряды 1 и 2, 0.05 … 100 mm).
pub const MODULE_MIN: f64 = 0.05e-3;

/// The largest module accepted, 100 mm: the last value of GOST 9563-60's
/// series. Anything outside 0.05 … 100 mm is far more likely a unit slip (a
/// module of 5 typed without "mm" and read as 5 m) than a real gear.
pub const MODULE_MAX: f64 = 100e-3;

/// Refuse a module that is not a finite length inside
/// [`MODULE_MIN`] … [`MODULE_MAX`] (the span of GOST 9563-60); the message of
/// [`GearError::Module`] suggests the unit when the number looks like
/// millimetres read as metres.
///
/// ```
/// use tmm_gears::spec::check_module;
/// assert!(check_module(0.005).is_ok());
/// assert!(check_module(5.0).is_err()); // "5" read as 5 m: da would be 88.9 m
/// assert!(check_module(1e-5).is_err() && check_module(f64::NAN).is_err());
/// ```
pub fn check_module(m: f64) -> Result<(), GearError> {
    if m.is_finite() && (MODULE_MIN * (1.0 - 1e-12)..=MODULE_MAX * (1.0 + 1e-12)).contains(&m) {
        Ok(())
    } else {
        Err(GearError::Module(m))
    }
}

/// The least shift that avoids undercut by the rack,
/// `xmin = (hl* − ha*) − z·sin²α / 2` (seed 001, sheet 2, §IV.1; GOST 16532-70
/// writes `ha* − z·sin²α/2` for the standard rack where hl* − ha* = ha*).
///
/// ```
/// let r = tmm_gears::BasicRack::default();
/// // 17 teeth are the classical limit: xmin ≈ 0.
/// assert!(tmm_gears::spec::xmin(17, &r).abs() < 0.01);
/// ```
#[inline]
pub fn xmin(z: u32, rack: &BasicRack) -> f64 {
    let s = rack.alpha.sin();
    rack.flank_depth() - z as f64 * s * s / 2.0
}

/// Tip thickness of a lone external wheel with shift `x` and no tip shortening,
/// in modules: `sa/m = (da/m)·(s/d + inv α − inv αa)` (GOST 16532-70, table 4).
/// Returns `None` when the tip circle is inside the base circle, and for
/// `z = 0` or a result that is not finite.
pub fn lone_tip_thickness(z: u32, x: f64, rack: &BasicRack) -> Option<f64> {
    if z == 0 {
        return None;
    }
    let zf = z as f64;
    let d = zf;
    let da = d + 2.0 * (rack.ha + x);
    let db = d * rack.alpha.cos();
    if da <= db {
        return None;
    }
    let aa = (db / da).acos();
    let s = PI / 2.0 + 2.0 * x * rack.alpha.tan();
    let sa = da * (s / d + inv(rack.alpha) - inv(aa));
    sa.is_finite().then_some(sa)
}

/// The smallest tooth number a rack can cut with neither undercut nor a pointed
/// tip: the least `z` whose tooth at `x = xmin(z)` still has `sa > 0`
/// (defined here; docs/gears.md §Smallest tooth number).
///
/// ```
/// // 20° rack: z = 7 at xmin = 0.591 has αa = 49.75°, sa/m = 10.18·(0.2858 + 0.0149 − 0.3139) < 0;
/// // z = 8 at xmin = 0.532 has αa = 33.96°, sa/m = 9.064·(0.2448 + 0.0149 − 0.0809) > 0.
/// assert_eq!(tmm_gears::spec::smallest_cuttable(&tmm_gears::BasicRack::default()), 8);
/// ```
pub fn smallest_cuttable(rack: &BasicRack) -> u32 {
    (1..200)
        .find(|&z| lone_tip_thickness(z, xmin(z, rack).max(-10.0), rack).is_some_and(|s| s > 0.0))
        .unwrap_or(200)
}
