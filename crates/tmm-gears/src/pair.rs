//! The geometry of one pair (геометрический расчёт): GOST 16532-70 table 1–4
//! for external pairs; the internal pair by the same relations with the ring's
//! signs (GOST 19274-73 conventions, docs/gears.md §Internal).

use std::f64::consts::PI;

use tmm_geom::involute::{inv, inv_inverse};

use crate::spec::xmin;
use crate::{GearError, Kind, PairSpec};

/// One wheel of a pair (SI: m, rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wheel {
    /// Tooth number z.
    pub z: u32,
    /// Profile shift coefficient x.
    pub x: f64,
    /// Reference (pitch) diameter d = z·m (делительный диаметр).
    pub d: f64,
    /// Base diameter db = d·cos α (основной диаметр).
    pub db: f64,
    /// Operating pitch diameter dw (начальный диаметр).
    pub dw: f64,
    /// Tip diameter da (диаметр вершин).
    pub da: f64,
    /// Root diameter df (диаметр впадин).
    pub df: f64,
    /// Tooth depth h = |da − df| / 2 (высота зуба).
    pub h: f64,
    /// Tooth thickness on the reference circle s (окружная толщина).
    pub s: f64,
    /// Tip thickness sa (толщина зуба по окружности вершин).
    pub sa: f64,
    /// Profile angle at the tip αa (угол профиля на окружности вершин).
    pub alpha_a: f64,
    /// Radius of curvature of the involute at the tip, ρa = √(ra² − rb²).
    pub rho_a: f64,
    /// Radius of curvature at the lower point of the active profile ρp
    /// (for a ring: at its contact with the pinion tip).
    pub rho_p: f64,
    /// Radius of curvature at the boundary point of the generated involute ρl
    /// (граничная точка).
    pub rho_l: f64,
    /// Least shift against undercut xmin (None for a ring).
    pub xmin: Option<f64>,
}

/// The computed pair: geometry, contact ratio and the active line of action.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pair {
    /// The data it was computed from.
    pub spec: PairSpec,
    /// Reference centre distance a (делительное межосевое расстояние).
    pub a: f64,
    /// inv αw.
    pub inv_alpha_w: f64,
    /// Operating pressure angle αw (угол зацепления).
    pub alpha_w: f64,
    /// Operating centre distance aw (межосевое расстояние).
    pub aw: f64,
    /// Centre distance coefficient y (коэффициент воспринимаемого смещения).
    pub y: f64,
    /// Tip shortening coefficient Δy (коэффициент уравнительного смещения).
    pub dy: f64,
    /// Gear ratio u = z2 / z1 (передаточное число).
    pub u: f64,
    /// Reference pitch p = π·m.
    pub p: f64,
    /// Base pitch pb = π·m·cos α (шаг зацепления).
    pub pb: f64,
    /// Length of the line of action N1N2, g = aw·sin αw.
    pub g: f64,
    /// Start of the real active line, measured from N1 along N1N2: ρp1, but
    /// never before N1 nor below the pinion's generated involute,
    /// `max(ρp1, ρl1, 0)` (docs/gears.md §Active line).
    pub s_start: f64,
    /// End of the real active line, measured from N1: ρa1, but never past N2
    /// nor above wheel 2's generated involute (docs/gears.md §Active line).
    pub s_end: f64,
    /// Transverse contact ratio εα (коэффициент торцового перекрытия) over the
    /// real active line, `(s_end − s_start)/pb`; equal to
    /// [`Pair::eps_alpha_gost`] whenever the pair has no interference.
    pub eps_alpha: f64,
    /// εα by the GOST 16532-70 tan formula, `[z1 tg αa1 ± z2 tg αa2 ∓ zΣ tg αw]/2π`:
    /// the whole theoretical line from ρp1 to ρa1, past N1 or into a fillet
    /// when there is interference.
    pub eps_alpha_gost: f64,
    /// Tip-interference margin of an internal pair (≥ 0 runs), `None` for an external pair.
    pub tip_interference: Option<f64>,
    /// Trimming (radial-assembly) margin of an internal pair (≥ 0: the pinion
    /// can be moved into mesh along the line of centres), `None` for an
    /// external pair (docs/gears.md §Trimming).
    pub trimming: Option<f64>,
    /// The pinion.
    pub w1: Wheel,
    /// The wheel (or ring).
    pub w2: Wheel,
}

impl Pair {
    /// Compute the pair, validating the data first.
    ///
    /// ```
    /// let p = tmm_gears::Pair::new(&tmm_gears::PairSpec::external(20, 40, 0.002, 0.0, 0.0)).unwrap();
    /// assert!((p.aw - 0.060).abs() < 1e-15);         // a = m(z1 + z2)/2 without shifts
    /// assert!((p.alpha_w - 20f64.to_radians()).abs() < 1e-12);
    /// ```
    pub fn new(spec: &PairSpec) -> Result<Pair, GearError> {
        spec.validate()?;
        let pair = Self::compute(spec)?;
        if let Some(t) = pair.tip_interference
            && t < 0.0
        {
            return Err(GearError::InternalAssembly(format!(
                "the tips of the pinion and the ring interfere on leaving the mesh (margin {t:.4} < 0); raise z2 − z1 or the shifts"
            )));
        }
        Ok(pair)
    }

    /// Compute without [`PairSpec::validate`] and without rejecting tip
    /// interference (the caller validated `spec` apart from the shifts); used in
    /// the inner loops of the blocking contour.
    pub fn compute(spec: &PairSpec) -> Result<Pair, GearError> {
        let r = &spec.rack;
        let m = spec.m;
        let (al, ta, ca) = (r.alpha, r.alpha.tan(), r.alpha.cos());
        let internal = spec.kind == Kind::Internal;
        let (z1, z2) = (spec.z1 as f64, spec.z2 as f64);
        // GOST 16532-70 t.1 items 1–4; GOST 19274-73 for internal (z2 − z1, x2 − x1).
        let (zs, xs) = if internal {
            (z2 - z1, spec.x2 - spec.x1)
        } else {
            (z1 + z2, spec.x1 + spec.x2)
        };
        let a = zs * m / 2.0;
        let inv_aw = 2.0 * xs * ta / zs + inv(al);
        let alpha_w = inv_inverse(inv_aw).ok_or(GearError::ShiftSum { x_sum: xs, inv_aw })?;
        let cw = alpha_w.cos();
        if cw <= 1e-9 {
            return Err(GearError::ShiftSum { x_sum: xs, inv_aw });
        }
        let aw = a * ca / cw;
        let y = (aw - a) / m;
        let dy = xs - y;
        let u = z2 / z1;
        // Tip and root diameters (GOST 16532-70 t.1 items 9–10; ring: derived, docs §Internal).
        let d1 = z1 * m;
        let d2 = z2 * m;
        let da1 = if internal {
            d1 + 2.0 * (r.ha + spec.x1) * m
        } else {
            d1 + 2.0 * (r.ha + spec.x1 - dy) * m
        };
        let df1 = d1 - 2.0 * (r.ha + r.c - spec.x1) * m;
        let (da2, df2) = if internal {
            (d2 - 2.0 * (r.ha - spec.x2) * m, d2 + 2.0 * (r.ha + r.c + spec.x2) * m)
        } else {
            (d2 + 2.0 * (r.ha + spec.x2 - dy) * m, d2 - 2.0 * (r.ha + r.c - spec.x2) * m)
        };
        if da1 <= df1 {
            return Err(GearError::TipBelowRoot {
                wheel: 1,
                da: da1,
                df: df1,
            });
        }
        if !internal && da2 <= df2 {
            return Err(GearError::TipBelowRoot {
                wheel: 2,
                da: da2,
                df: df2,
            });
        }
        let (db1, db2) = (d1 * ca, d2 * ca);
        let (rb1, rb2) = (db1 / 2.0, db2 / 2.0);
        // Boundary point of the generated involute (seed 001 §IV.2; GOST 16532-70 t.4):
        // ρl = r sin α − (hl* − ha* − x) m / sin α. Ring: docs §Internal.
        let sn = al.sin();
        let rho_l1 = d1 / 2.0 * sn - (r.flank_depth() - spec.x1) * m / sn;
        let rho_l2 = if internal {
            let rl = d2 / 2.0 + (r.flank_depth() + spec.x2) * m;
            (rl * rl - rb2 * rb2).max(0.0).sqrt()
        } else {
            d2 / 2.0 * sn - (r.flank_depth() - spec.x2) * m / sn
        };
        // A rack-cut tooth has an involute only between the form circle (where the
        // cutter's straight flank ends, radius √(rb² + ρl²), or the base circle when
        // ρl ≤ 0) and its tip: the tip must lie outside that circle (docs §Tip and form circle).
        let form_check = |wheel: u8, da: f64, db: f64, rho_l: f64| -> Result<(), GearError> {
            let rb = db / 2.0;
            let dl = if rho_l > 0.0 { 2.0 * rb.hypot(rho_l) } else { db };
            if da <= dl {
                Err(GearError::TipInsideBase {
                    wheel,
                    da,
                    db: dl,
                    form: rho_l > 0.0,
                })
            } else {
                Ok(())
            }
        };
        form_check(1, da1, db1, rho_l1)?;
        if internal {
            if da2 <= db2 {
                // da2 = d2 − 2(ha* − x2)m > d2 cos α ⇔ z2 > 2(ha* − x2)/(1 − cos α) ⇔ x2 > ha* − z2(1 − cos α)/2.
                let zneed = 2.0 * (r.ha - spec.x2) / (1.0 - ca);
                let xneed = r.ha - z2 * (1.0 - ca) / 2.0;
                return Err(GearError::InternalAssembly(format!(
                    "the ring's tip circle (d = {:.4} mm) lies inside its base circle (d = {:.4} mm), so its teeth have no involute; a ring needs z2 > 2(ha* − x2)/(1 − cos α) = {zneed:.2} (z2 ≥ {} with x2 = {}) or, with z2 = {}, x2 > ha* − z2(1 − cos α)/2 = {xneed:.4}",
                    da2 * 1e3,
                    db2 * 1e3,
                    zneed.floor() + 1.0,
                    spec.x2,
                    spec.z2
                )));
            }
        } else {
            form_check(2, da2, db2, rho_l2)?;
        }
        // dw1 = 2aw/(u ± 1), dw2 = 2aw·u/(u ± 1) (GOST 16532-70 t.1 item 7).
        let (dw1, dw2) = (2.0 * aw * z1 / zs, 2.0 * aw * z2 / zs);
        // Tooth thickness on the reference circle (GOST 16532-70 t.4); the ring's
        // tooth is the complement of an external tooth space.
        let s1 = (PI / 2.0 + 2.0 * spec.x1 * ta) * m;
        let s2 = if internal {
            (PI / 2.0 - 2.0 * spec.x2 * ta) * m
        } else {
            (PI / 2.0 + 2.0 * spec.x2 * ta) * m
        };
        let aa1 = (db1 / da1).acos();
        let aa2 = (db2 / da2).acos();
        // Tip thickness sa = da (s/d + inv α − inv αa) (GOST 16532-70 t.4);
        // ring: sa = da (s/d − inv α + inv αa) (derived, docs §Internal).
        let sa1 = da1 * (s1 / d1 + inv(al) - inv(aa1));
        let sa2 = if internal {
            da2 * (s2 / d2 - inv(al) + inv(aa2))
        } else {
            da2 * (s2 / d2 + inv(al) - inv(aa2))
        };
        // Line of action N1N2 and its active part (GOST 16532-70 t.4).
        let g = aw * alpha_w.sin();
        let rho_a1 = (da1 / 2.0 - rb1).sqrt() * (da1 / 2.0 + rb1).sqrt();
        let rho_a2 = (da2 / 2.0 - rb2).sqrt() * (da2 / 2.0 + rb2).sqrt();
        let (rho_p1, rho_p2) = if internal {
            (rho_a2 - g, rho_a1 + g)
        } else {
            (g - rho_a2, g - rho_a1)
        };
        // Contact ratio (GOST 16532-70 t.4): εα = [z1 tg αa1 ± z2 tg αa2 ∓ (z2 ± z1) tg αw] / 2π.
        let tw = alpha_w.tan();
        let eps_alpha_gost = if internal {
            (z1 * aa1.tan() - z2 * aa2.tan() + zs * tw) / (2.0 * PI)
        } else {
            (z1 * aa1.tan() + z2 * aa2.tan() - zs * tw) / (2.0 * PI)
        };
        // The real active line: the involutes touch only where both exist, so the
        // line from ρp1 to ρa1 is cut at N1 (ρ1 = 0), at the pinion's form point ρl1,
        // and likewise for wheel 2 (docs §Active line).
        let s_start = rho_p1.max(rho_l1).max(0.0);
        let s_end = if internal {
            // ρ2 = s + g must stay inside the ring's involute, ρ2 ≤ ρl2.
            rho_a1.min(rho_l2 - g)
        } else {
            // ρ2 = g − s ≥ max(ρl2, 0).
            rho_a1.min(g - rho_l2.max(0.0))
        };
        let pb = PI * m * ca;
        let eps_alpha = ((s_end - s_start) / pb).max(0.0);
        let (tip_interference, trimming) = if internal {
            (
                Some(tip_interference_margin(z1, z2, da1 / 2.0, da2 / 2.0, aw, aa1, aa2, inv_aw)),
                Some(trimming_margin(z1, z2, aa1, aa2, inv_aw)),
            )
        } else {
            (None, None)
        };
        let wheel = |z: u32,
                     x: f64,
                     d: f64,
                     db: f64,
                     dw: f64,
                     da: f64,
                     df: f64,
                     s: f64,
                     sa: f64,
                     aa: f64,
                     ra: f64,
                     rp: f64,
                     rl: f64,
                     ring: bool| Wheel {
            z,
            x,
            d,
            db,
            dw,
            da,
            df,
            h: (da - df).abs() / 2.0,
            s,
            sa,
            alpha_a: aa,
            rho_a: ra,
            rho_p: rp,
            rho_l: rl,
            xmin: if ring { None } else { Some(xmin(z, &spec.rack)) },
        };
        let pair = Pair {
            spec: *spec,
            a,
            inv_alpha_w: inv_aw,
            alpha_w,
            aw,
            y,
            dy,
            u,
            p: PI * m,
            pb,
            g,
            s_start,
            s_end,
            eps_alpha,
            eps_alpha_gost,
            tip_interference,
            trimming,
            w1: wheel(
                spec.z1, spec.x1, d1, db1, dw1, da1, df1, s1, sa1, aa1, rho_a1, rho_p1, rho_l1, false,
            ),
            w2: wheel(
                spec.z2, spec.x2, d2, db2, dw2, da2, df2, s2, sa2, aa2, rho_a2, rho_p2, rho_l2, internal,
            ),
        };
        pair.check_finite()?;
        Ok(pair)
    }

    /// Contact ratio by the length of the real active line:
    /// εα = (s_end − s_start) / pb (GOST 16532-70 t.4 as a length over the base
    /// pitch; the same quantity as [`Pair::eps_alpha`]).
    pub fn eps_alpha_by_length(&self) -> f64 {
        ((self.s_end - self.s_start) / self.pb).max(0.0)
    }

    /// The radius of curvature of wheel 2's involute at the contact point that
    /// lies `s` from N1 along the line of action.
    #[inline]
    pub fn rho2_at(&self, s: f64) -> f64 {
        match self.spec.kind {
            Kind::External => self.g - s,
            Kind::Internal => s + self.g,
        }
    }

    /// The first non-finite quantity, named, as an error.
    fn check_finite(&self) -> Result<(), GearError> {
        let named = [
            (self.a, "reference centre distance a"),
            (self.alpha_w, "operating pressure angle αw"),
            (self.aw, "centre distance aw"),
            (self.y, "centre distance coefficient y"),
            (self.dy, "tip shortening Δy"),
            (self.g, "line of action N1N2"),
            (self.s_start, "start of the active line"),
            (self.s_end, "end of the active line"),
            (self.eps_alpha, "contact ratio εα"),
            (self.eps_alpha_gost, "contact ratio εα"),
            (self.tip_interference.unwrap_or(0.0), "tip-interference margin"),
            (self.trimming.unwrap_or(0.0), "trimming margin"),
        ];
        for (v, what) in named {
            if !v.is_finite() {
                return Err(GearError::NonFinite(what));
            }
        }
        for w in [&self.w1, &self.w2] {
            let named = [
                (w.d, "reference diameter d"),
                (w.db, "base diameter db"),
                (w.dw, "operating pitch diameter dw"),
                (w.da, "tip diameter da"),
                (w.df, "root diameter df"),
                (w.h, "tooth depth h"),
                (w.s, "tooth thickness s"),
                (w.sa, "tip thickness sa"),
                (w.alpha_a, "tip profile angle αa"),
                (w.rho_a, "tip radius of curvature ρa"),
                (w.rho_p, "radius of curvature ρp"),
                (w.rho_l, "radius of curvature ρl"),
                (w.xmin.unwrap_or(0.0), "least shift xmin"),
            ];
            for (v, what) in named {
                if !v.is_finite() {
                    return Err(GearError::NonFinite(what));
                }
            }
        }
        Ok(())
    }
}

/// Tip interference of an internal pair (интерференция вершин), the margin
/// `z1 (inv αa1 + δ1) + (z2 − z1) inv αw − z2 (inv αa2 + δ2)` that must be
/// ≥ 0, with `cos δ1 = (ra2² − ra1² − aw²) / (2 ra1 aw)`,
/// `cos δ2 = (ra2² − ra1² + aw²) / (2 ra2 aw)`: the pinion's tip corner must
/// leave the point where the tip circles cross before the ring's tip corner
/// reaches it. Source: Болотовский И.А. (ред.), Справочник по геометрическому
/// расчёту эвольвентных зубчатых и червячных передач, 1986, internal gearing;
/// the derivation is in docs/gears.md §Internal.
#[allow(clippy::too_many_arguments)]
fn tip_interference_margin(z1: f64, z2: f64, ra1: f64, ra2: f64, aw: f64, aa1: f64, aa2: f64, inv_aw: f64) -> f64 {
    let c1 = (ra2 * ra2 - ra1 * ra1 - aw * aw) / (2.0 * ra1 * aw);
    let c2 = (ra2 * ra2 - ra1 * ra1 + aw * aw) / (2.0 * ra2 * aw);
    if !(-1.0..=1.0).contains(&c1) || !(-1.0..=1.0).contains(&c2) {
        // The tip circles do not cross: the pinion cannot reach the ring tips at all.
        return if ra1 + aw < ra2 { 1.0 } else { -1.0 };
    }
    z1 * (inv(aa1) + c1.acos()) + (z2 - z1) * inv_aw - z2 * (inv(aa2) + c2.acos())
}

/// Trimming of an internal pair (срезание при радиальной сборке, trimming
/// interference): the margin
/// `z1 (θ1 + inv αa1 − inv αw) − z2 (θ2 + inv αa2 − inv αw)` that must be ≥ 0
/// for the pinion to be moved into mesh along the line of centres at any
/// phase of the mesh, with
/// `sin²θ1 = (1 − c²)/(1 − k²)`, `sin θ2 = (k/c) sin θ1`,
/// `c = cos αa1 / cos αa2`, `k = z1/z2` (θ1 = θ2 = 0 when c ≥ 1).
/// θ1, θ2 are the angles (at O1 and O2, from the line of centres) of the two
/// tip-circle points that lie on one line parallel to the line of centres
/// where the pinion's tip corners, followed over the phases of the mesh,
/// come nearest to the ring's tip corners.
///
/// Derived here (docs/gears.md §Trimming); the same condition is printed by
/// KHK, Gear Technical Reference, "Internal gears: trimming interference", and
/// by Болотовский И.А. (ред.), Справочник по геометрическому расчёту
/// эвольвентных зубчатых и червячных передач, 1986 (условие отсутствия
/// срезания при радиальной сборке).
fn trimming_margin(z1: f64, z2: f64, aa1: f64, aa2: f64, inv_aw: f64) -> f64 {
    let k = z1 / z2;
    let c = aa1.cos() / aa2.cos();
    let (th1, th2) = if c < 1.0 {
        let s1 = ((1.0 - c * c) / (1.0 - k * k)).clamp(0.0, 1.0).sqrt();
        let s2 = (k / c * s1).clamp(0.0, 1.0);
        (s1.asin(), s2.asin())
    } else {
        (0.0, 0.0)
    };
    z1 * (th1 + inv(aa1) - inv_aw) - z2 * (th2 + inv(aa2) - inv_aw)
}
