//! Tooth profiles by simulating generation with the rack cutter (нарезание
//! методом обкатки): every point of the cutter (the straight flank, the tip
//! fillet of radius ρf, the tip line) is carried through the relative motion
//! in which the cutter's machining pitch line rolls without slip on the
//! reference circle; the wheel's profile is the envelope — the point of the
//! cutter whose normal passes through the pole at that instant (the meshing
//! condition, Литвин Ф.Л., Теория зубчатых зацеплений, 1968, ch. 6). The
//! flank envelops the involute, the tip fillet the trochoidal fillet; where the
//! fillet's envelope cuts into the involute (undercut) the profile keeps the
//! deeper cut at every radius, as the machine does.

use std::f64::consts::PI;

use tmm_geom::root::brent;

use crate::{BasicRack, GearError};

/// Which part of the profile a point belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Part {
    /// Root circle (cut by the cutter's tip line).
    Root,
    /// Trochoidal fillet (cut by the cutter's tip rounding).
    Fillet,
    /// Involute (cut by the cutter's straight flank).
    Involute,
    /// The tip circle.
    Tip,
}

impl Part {
    /// Name for CSV/JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Part::Root => "root",
            Part::Fillet => "fillet",
            Part::Involute => "involute",
            Part::Tip => "tip",
        }
    }
}

/// A point of the half profile in polar form about the wheel centre.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProfilePoint {
    /// Radius, m.
    pub r: f64,
    /// Half-thickness angle: from the tooth's centreline to the point, rad.
    pub psi: f64,
    /// The part of the profile.
    pub part: Part,
}

/// One tooth's half profile from the middle of the space (root) to the tip corner.
#[derive(Debug, Clone, PartialEq)]
pub struct ToothProfile {
    /// Tooth number.
    pub z: u32,
    /// `true` for a ring (internal teeth).
    pub ring: bool,
    /// Half profile, from the middle of the tooth space at the root to the tip corner.
    pub half: Vec<ProfilePoint>,
    /// Tip radius, m.
    pub ra: f64,
    /// Root radius, m.
    pub rf: f64,
    /// The cutter's tip fillet radius used, m (0 for a ring): the largest that
    /// fits when the rack's own did not ([`BasicRack::fit_fillet`]).
    pub fillet_radius: f64,
    /// `true` when the rack's fillet did not fit and a smaller one was used.
    pub fillet_reduced: bool,
}

impl ToothProfile {
    /// The outline of one tooth, centred on the +y axis, from the middle of the
    /// space on its left to the middle of the space on its right (x, y in m).
    pub fn tooth_outline(&self) -> Vec<(f64, f64)> {
        let mut out = Vec::with_capacity(2 * self.half.len() + 16);
        for p in &self.half {
            out.push((-p.r * p.psi.sin(), p.r * p.psi.cos()));
        }
        let last = self.half.last().copied();
        if let Some(t) = last {
            let n = 12;
            for k in 1..n {
                let psi = t.psi * (1.0 - 2.0 * k as f64 / n as f64);
                out.push((-t.r * psi.sin(), t.r * psi.cos()));
            }
        }
        for p in self.half.iter().rev() {
            out.push((p.r * p.psi.sin(), p.r * p.psi.cos()));
        }
        out
    }

    /// The whole wheel's outline, closed, turned by `rot` rad (CCW), with a
    /// tooth centred on the direction `π/2 + rot`.
    pub fn wheel_outline(&self, rot: f64) -> Vec<(f64, f64)> {
        let one = self.tooth_outline();
        let mut out = Vec::with_capacity(one.len() * self.z as usize + 1);
        let tau = 2.0 * PI / self.z as f64;
        for k in 0..self.z {
            let a = rot - tau * k as f64;
            let (s, c) = a.sin_cos();
            out.extend(one.iter().map(|&(x, y)| (c * x - s * y, s * x + c * y)));
        }
        if let Some(&f) = out.first() {
            out.push(f);
        }
        out
    }
}

/// Generate an external wheel's tooth with the rack cutter of `rack`, module
/// `m`, shift `x`, tip radius `ra`; `samples` points per cutter part (8 …
/// 100 000). When the rack's tip fillet does not fit on the cutter's tooth
/// (e.g. α = 25° with hl* = 2) the largest that fits is used
/// ([`BasicRack::fit_fillet`]) and reported in [`ToothProfile::fillet_radius`].
///
/// ```
/// use tmm_gears::{BasicRack, generate::{generate, Part}};
/// let m = 0.005;
/// let t = generate(20, m, 0.0, &BasicRack::default(), 0.055, 60).unwrap();
/// // The root point lies on the root circle r = m(z/2 − ha* − c* + x).
/// assert!((t.half[0].r - m * (10.0 - 1.25)).abs() < 1e-12);
/// assert!(t.half.iter().any(|p| p.part == Part::Involute));
/// ```
pub fn generate(z: u32, m: f64, x: f64, rack: &BasicRack, ra: f64, samples: usize) -> Result<ToothProfile, GearError> {
    crate::spec::check_module(m)?;
    // The largest fillet that fits on the cutter's tip (docs/gears.md §Rack).
    let fit = rack.fit_fillet()?;
    let rack = &fit.rack;
    let n = samples.clamp(8, 100_000);
    let r = z as f64 * m / 2.0;
    let al = rack.alpha;
    let (sa, ca, ta) = (al.sin(), al.cos(), al.tan());
    let rho = rack.fillet_radius() * m;
    let tip = -(rack.ha + rack.c) * m;
    let eta_c = tip + rho;
    let xi_c = PI * m / 4.0 + eta_c * ta - rho / ca;
    if xi_c < -1e-12 * m || rho < 0.0 {
        return Err(GearError::Rack {
            param: "hl",
            msg: "the cutter's tip fillet does not fit on its tip (check hl*, c*)",
        });
    }
    let xi_c = xi_c.max(0.0);
    let rf = r + x * m + tip;
    if ra <= rf {
        return Err(GearError::TipBelowRoot {
            wheel: 0,
            da: 2.0 * ra,
            df: 2.0 * rf,
        });
    }
    // Envelope point of a cutter point (xi, eta) with outward normal (nx, ny):
    // the rack is displaced by −rφ while the wheel turns by φ; the normal passes
    // through the pole (0, r) when rφ = ξ − nξ(xm + η)/nη. Returns (radius, angle
    // from the space centreline).
    let env = |xi: f64, eta: f64, nx: f64, ny: f64| -> (f64, f64) {
        let phi = (xi - nx * (x * m + eta) / ny) / r;
        let (px, py) = (xi - r * phi, r + x * m + eta);
        // rotate by −φ into the wheel's frame
        let (s, c) = phi.sin_cos();
        let (gx, gy) = (c * px + s * py, -s * px + c * py);
        ((gx * gx + gy * gy).sqrt(), gx.atan2(gy))
    };
    let half_tau = PI / z as f64;
    let mut root = Vec::with_capacity(n);
    let mut fillet = Vec::with_capacity(2 * n);
    let mut flank = Vec::with_capacity(2 * n);
    for k in 0..n {
        let xi = xi_c * k as f64 / n as f64;
        let (rr, th) = env(xi, tip, 0.0, -1.0);
        root.push((rr, th));
    }
    let nf = 2 * n;
    for k in 0..=nf {
        let b = -PI / 2.0 + (PI / 2.0 - al) * k as f64 / nf as f64;
        let (nb, cb) = (b.sin(), b.cos());
        if nb.abs() < 1e-12 {
            continue;
        }
        fillet.push(env(xi_c + rho * cb, eta_c + rho * nb, cb, nb));
    }
    let flank_at = |eta: f64| env(PI * m / 4.0 + eta * ta, eta, ca, -sa);
    let eta0 = -rack.flank_depth() * m;
    let eta_top = brent(|e| flank_at(e).0 - ra, eta0, eta0 + 20.0 * m, 1e-15 * m.max(1e-300));
    let eta1 = match eta_top {
        Some(e) => e,
        None => {
            // The flank's lowest point already envelops a radius above the tip
            // (the tooth is all fillet), or the tip is inside the base circle.
            let r_form = flank_at(eta0).0;
            let form = r_form >= ra && r_form > r * ca;
            return Err(GearError::TipInsideBase {
                wheel: 0,
                da: 2.0 * ra,
                db: if form { 2.0 * r_form } else { 2.0 * r * ca },
                form,
            });
        }
    };
    for k in 0..=2 * n {
        let e = eta0 + (eta1 - eta0) * k as f64 / (2 * n) as f64;
        flank.push(flank_at(e));
    }
    // Keep, at every radius, the deepest cut (the largest space angle).
    let max_at = |curve: &[(f64, f64)], rr: f64| -> f64 {
        let mut best = f64::NEG_INFINITY;
        for w in curve.windows(2) {
            let ((r0, t0), (r1, t1)) = (w[0], w[1]);
            if (r0 - rr) * (r1 - rr) <= 0.0 && r0 != r1 {
                let t = t0 + (t1 - t0) * (rr - r0) / (r1 - r0);
                best = best.max(t);
            }
        }
        best
    };
    let tol = 1e-12;
    let mut half = Vec::with_capacity(root.len() + fillet.len() + flank.len());
    for &(rr, th) in &root {
        half.push(ProfilePoint {
            r: rr,
            psi: half_tau - th,
            part: Part::Root,
        });
    }
    for &(rr, th) in &fillet {
        if th + tol >= max_at(&flank, rr) && th + tol >= max_at(&fillet, rr) {
            half.push(ProfilePoint {
                r: rr,
                psi: half_tau - th,
                part: Part::Fillet,
            });
        }
    }
    for &(rr, th) in &flank {
        if th + tol >= max_at(&fillet, rr) {
            half.push(ProfilePoint {
                r: rr,
                psi: half_tau - th,
                part: Part::Involute,
            });
        }
    }
    if let Some(last) = half.last_mut() {
        last.part = Part::Tip;
    }
    if half.iter().any(|p| !(p.r.is_finite() && p.psi.is_finite())) {
        return Err(GearError::NonFinite("generated profile"));
    }
    Ok(ToothProfile {
        z,
        ring: false,
        half,
        ra,
        rf,
        fillet_radius: rho,
        fillet_reduced: fit.reduced,
    })
}

/// A ring's tooth profile (internal teeth): the involute from the tip circle
/// out to the form radius `r_form`, then the root circle. A ring is cut by a
/// shaper cutter, not a rack, so it is drawn from the involute's closed form
/// `ψ(r) = s/d − inv α + inv α_r` (docs/gears.md §Internal).
///
/// Invalid input (z = 0, a module outside [`crate::spec::check_module`], a
/// radius that is not finite and positive, a non-finite result) gives an
/// empty profile; [`ring_profile_checked`] says why.
#[allow(clippy::too_many_arguments)]
pub fn ring_profile(z: u32, m: f64, s: f64, rack: &BasicRack, ra: f64, rf: f64, r_form: f64, samples: usize) -> ToothProfile {
    ring_profile_checked(z, m, s, rack, ra, rf, r_form, samples).unwrap_or(ToothProfile {
        z,
        ring: true,
        half: Vec::new(),
        ra,
        rf,
        fillet_radius: 0.0,
        fillet_reduced: false,
    })
}

/// [`ring_profile`] with the reason when the input is invalid.
///
/// ```
/// use tmm_gears::{BasicRack, generate::ring_profile_checked};
/// let r = BasicRack::default();
/// assert!(ring_profile_checked(0, 0.002, 0.003, &r, 0.05, 0.06, 0.058, 16).is_err());
/// assert!(ring_profile_checked(60, 0.002, 0.003, &r, 0.058, 0.0625, 0.062, 16).is_ok());
/// ```
#[allow(clippy::too_many_arguments)]
pub fn ring_profile_checked(
    z: u32,
    m: f64,
    s: f64,
    rack: &BasicRack,
    ra: f64,
    rf: f64,
    r_form: f64,
    samples: usize,
) -> Result<ToothProfile, GearError> {
    rack.validate()?;
    crate::spec::check_module(m)?;
    if z == 0 {
        return Err(GearError::TooFewTeeth { wheel: 2, z, min: 1 });
    }
    let pos = |v: f64| v.is_finite() && v > 0.0;
    if !(pos(ra) && pos(rf) && pos(r_form) && s.is_finite()) {
        return Err(GearError::NonFinite("ring radius or tooth thickness"));
    }
    let p = ring_profile_raw(z, m, s, rack, ra, rf, r_form, samples.clamp(8, 100_000));
    if p.half.iter().any(|q| !(q.r.is_finite() && q.psi.is_finite())) {
        return Err(GearError::NonFinite("ring profile"));
    }
    Ok(p)
}

#[allow(clippy::too_many_arguments)]
fn ring_profile_raw(z: u32, m: f64, s: f64, rack: &BasicRack, ra: f64, rf: f64, r_form: f64, samples: usize) -> ToothProfile {
    let n = samples.max(8);
    let d = z as f64 * m;
    let rb = d / 2.0 * rack.alpha.cos();
    let inv = |a: f64| a.tan() - a;
    let psi = |r: f64| s / d - inv(rack.alpha) + inv((rb / r).min(1.0).acos());
    let half_tau = PI / z as f64;
    let r_top = r_form.min(rf);
    let mut half = Vec::with_capacity(2 * n + 2);
    // root first (middle of the space at the root, outside), then the involute inward to the tip
    let psi_root = psi(r_top);
    for k in 0..n / 2 {
        let p = half_tau - (half_tau - psi_root) * k as f64 / (n / 2) as f64;
        half.push(ProfilePoint {
            r: rf,
            psi: p,
            part: Part::Root,
        });
    }
    if r_top < rf {
        half.push(ProfilePoint {
            r: rf,
            psi: psi_root,
            part: Part::Fillet,
        });
    }
    for k in 0..=2 * n {
        let r = r_top + (ra - r_top) * k as f64 / (2 * n) as f64;
        half.push(ProfilePoint {
            r,
            psi: psi(r),
            part: Part::Involute,
        });
    }
    if let Some(last) = half.last_mut() {
        last.part = Part::Tip;
    }
    ToothProfile {
        z,
        ring: true,
        half,
        ra,
        rf,
        fillet_radius: 0.0,
        fillet_reduced: false,
    }
}
