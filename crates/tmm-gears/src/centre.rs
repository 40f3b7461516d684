//! A required centre distance instead of the shifts (заданное межосевое
//! расстояние): the shift sum that gives it.

use tmm_geom::involute::inv;

use crate::{BasicRack, GearError, Kind};

/// The shift sum `xΣ` (x1 + x2 external, x2 − x1 internal) that gives the
/// centre distance `aw`: `cos αw = a cos α / aw`, then
/// `xΣ = (inv αw − inv α)(z2 ± z1) / (2 tg α)` (GOST 16532-70 t.2, the
/// inverse of t.1 items 3–4; seed 003 §14 rounds aw to 560 mm and recomputes).
///
/// ```
/// use tmm_gears::{centre::shift_sum_for_aw, BasicRack, Kind};
/// // The unshifted centre distance needs no shift.
/// let xs = shift_sum_for_aw(20, 40, 0.002, 0.060, &BasicRack::default(), Kind::External).unwrap();
/// assert!(xs.abs() < 1e-12);
/// ```
pub fn shift_sum_for_aw(z1: u32, z2: u32, m: f64, aw: f64, rack: &BasicRack, kind: Kind) -> Result<f64, GearError> {
    rack.validate()?;
    crate::spec::check_module(m)?;
    let zs = match kind {
        Kind::External => z1 as f64 + z2 as f64,
        Kind::Internal => z2 as f64 - z1 as f64,
    };
    if zs <= 0.0 {
        return Err(GearError::InternalAssembly(format!(
            "the ring needs more teeth than the pinion (z2 = {z2} ≤ z1 = {z1})"
        )));
    }
    let a = zs * m / 2.0;
    let min = a * rack.alpha.cos();
    if !(aw.is_finite() && aw > min) {
        return Err(GearError::CentreDistance { aw, min });
    }
    let aw_angle = (min / aw).acos();
    let sum = (inv(aw_angle) - inv(rack.alpha)) * zs / (2.0 * rack.alpha.tan());
    // an αw of 90° (aw far beyond a·cos α) has no finite involute
    if !sum.is_finite() {
        return Err(GearError::NonFinite("shift sum for this centre distance"));
    }
    Ok(sum)
}
