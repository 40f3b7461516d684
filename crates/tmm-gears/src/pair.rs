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
    /// Start of the active line, measured from N1 along N1N2 (= ρp1).
    pub s_start: f64,
    /// End of the active line, measured from N1 (= ρa1).
    pub s_end: f64,
    /// Transverse contact ratio εα (коэффициент торцового перекрытия), GOST tan formula.
    pub eps_alpha: f64,
    /// Tip-interference margin of an internal pair (≥ 0 runs), `None` for an external pair.
    pub tip_interference: Option<f64>,
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
        if da1 <= db1 {
            return Err(GearError::TipInsideBase {
                wheel: 1,
                da: da1,
                db: db1,
            });
        }
        if da2 <= db2 {
            return if internal {
                Err(GearError::InternalAssembly(format!(
                    "the ring's tip circle (d = {:.4} mm) lies inside its base circle (d = {:.4} mm); raise x2",
                    da2 * 1e3,
                    db2 * 1e3
                )))
            } else {
                Err(GearError::TipInsideBase {
                    wheel: 2,
                    da: da2,
                    db: db2,
                })
            };
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
        let (rb1, rb2) = (db1 / 2.0, db2 / 2.0);
        let rho_a1 = ((da1 / 2.0).powi(2) - rb1 * rb1).sqrt();
        let rho_a2 = ((da2 / 2.0).powi(2) - rb2 * rb2).sqrt();
        let (rho_p1, rho_p2) = if internal {
            (rho_a2 - g, rho_a1 + g)
        } else {
            (g - rho_a2, g - rho_a1)
        };
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
        // Contact ratio (GOST 16532-70 t.4): εα = [z1 tg αa1 ± z2 tg αa2 ∓ (z2 ± z1) tg αw] / 2π.
        let tw = alpha_w.tan();
        let eps_alpha = if internal {
            (z1 * aa1.tan() - z2 * aa2.tan() + zs * tw) / (2.0 * PI)
        } else {
            (z1 * aa1.tan() + z2 * aa2.tan() - zs * tw) / (2.0 * PI)
        };
        let tip_interference = if internal {
            Some(tip_interference_margin(z1, z2, da1 / 2.0, da2 / 2.0, aw, aa1, aa2, inv_aw))
        } else {
            None
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
            pb: PI * m * ca,
            g,
            s_start: rho_p1,
            s_end: rho_a1,
            eps_alpha,
            tip_interference,
            w1: wheel(
                spec.z1, spec.x1, d1, db1, dw1, da1, df1, s1, sa1, aa1, rho_a1, rho_p1, rho_l1, false,
            ),
            w2: wheel(
                spec.z2, spec.x2, d2, db2, dw2, da2, df2, s2, sa2, aa2, rho_a2, rho_p2, rho_l2, internal,
            ),
        };
        if !pair.all_finite() {
            return Err(GearError::NonFinite("pair geometry"));
        }
        Ok(pair)
    }

    /// Contact ratio by the length of the active line: εα = (ρa1 − ρp1) / pb
    /// (GOST 16532-70 t.4, the same quantity as [`Pair::eps_alpha`] written as
    /// a length over the base pitch).
    pub fn eps_alpha_by_length(&self) -> f64 {
        (self.s_end - self.s_start) / self.pb
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

    fn all_finite(&self) -> bool {
        let w = |w: &Wheel| tmm_geom::all_finite(&[w.d, w.db, w.dw, w.da, w.df, w.h, w.s, w.sa, w.alpha_a, w.rho_a, w.rho_p, w.rho_l]);
        tmm_geom::all_finite(&[self.a, self.alpha_w, self.aw, self.y, self.dy, self.g, self.eps_alpha]) && w(&self.w1) && w(&self.w2)
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
