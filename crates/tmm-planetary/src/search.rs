//! The search for tooth numbers (подбор чисел зубьев): every set of a scheme
//! that meets the ratio, coaxiality, no undercut, the internal-mesh limits,
//! assembly and the neighbour condition, ranked by radial size and ratio error.
//!
//! Coaxiality is built into the loops (one wheel's tooth number follows from
//! the others), and the ratio window fixes the range of the innermost tooth
//! number, so the search visits only sets close to the ratio; each visited set
//! is then checked exactly. The loop allocates nothing but the pushes of the
//! accepted sets into the caller's buffer.

use std::cmp::Ordering;

use serde::Serialize;

use crate::conditions::{Limits, assembly_positions, internal_limits, neighbours_clear, no_undercut, smallest_gap};
use crate::error::{Condition, PlanetaryError};
use crate::scheme::{Fraction, Mesh, ModuleRatio, Scheme, Teeth, radial_size, standard_module_ratios, willis_ratio};

/// What to search for.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Request {
    /// The scheme.
    pub scheme: Scheme,
    /// The wanted ratio `u_1H = ω1/ωH` (wheel 3 fixed).
    pub ratio: f64,
    /// The number of planets `k` (число сателлитов).
    pub planets: u32,
    /// The relative tolerance of the ratio, `|u − U| ≤ T·|U|` (0: exact).
    pub tolerance: f64,
    /// The limits of the conditions.
    pub limits: Limits,
    /// Allow the two rows of a double planet different standard modules.
    pub two_modules: bool,
}

impl Request {
    /// A request with the default limits, one module, exact ratio.
    ///
    /// ```
    /// let r = tmm_planetary::Request::new(tmm_planetary::Scheme::SunPlanetRing, 4.0, 3);
    /// assert_eq!((r.limits.zmin, r.limits.zmax, r.tolerance), (17, 200, 0.0));
    /// ```
    pub fn new(scheme: Scheme, ratio: f64, planets: u32) -> Request {
        Request {
            scheme,
            ratio,
            planets,
            tolerance: 0.0,
            limits: Limits::default(),
            two_modules: false,
        }
    }

    /// Check every field's range.
    pub fn validate(&self) -> Result<(), PlanetaryError> {
        let bad = |field, message: String, help: &str| {
            Err(PlanetaryError::Invalid {
                field,
                message,
                help: help.to_string(),
            })
        };
        let u = self.ratio;
        if !u.is_finite() || u == 0.0 || u.abs() > 1e6 {
            return bad(
                "ratio",
                format!("{u} is not a usable ratio"),
                "give u_1H = ω1/ωH as a finite non-zero number, e.g. 4 or -12.5 or 0.02",
            );
        }
        if (u - 1.0).abs() < 1e-12 {
            return bad(
                "ratio",
                "u_1H = 1 means the carrier turns with wheel 1: no train is needed".into(),
                "give a ratio other than 1",
            );
        }
        if !self.tolerance.is_finite() || !(0.0..=0.5).contains(&self.tolerance) {
            return bad(
                "tolerance",
                format!("{} is out of range", self.tolerance),
                "a relative tolerance from 0 (exact) to 0.5, e.g. 0.02 for 2 %",
            );
        }
        if !(1..=64).contains(&self.planets) {
            return bad(
                "planets",
                format!("{} planets", self.planets),
                "the number of planets k is 1 to 64 (usually 3)",
            );
        }
        let l = &self.limits;
        if !(1..=2000).contains(&l.zmax) {
            return bad(
                "zmax",
                format!("{} is out of range", l.zmax),
                "the largest tooth number is 1 to 2000 (default 200)",
            );
        }
        if l.zmin > l.zmax {
            return bad(
                "zmax",
                format!("{} is below the smallest tooth number zmin = {}", l.zmax, l.zmin),
                "raise zmax (default 200) or lower zmin",
            );
        }
        if l.zmin < 1 {
            return bad(
                "zmin",
                format!("{} is out of range", l.zmin),
                "the smallest external tooth number is 1 to zmax (17 for ha* = 1, α = 20°)",
            );
        }
        if l.ring_zmin > l.zmax {
            return bad(
                "ring_zmin",
                format!("{} is above zmax = {}", l.ring_zmin, l.zmax),
                "a ring may have at most zmax teeth: raise zmax or lower ring_zmin (85 for ha* = 1)",
            );
        }
        if !l.addendum.is_finite() || !(0.0..=2.0).contains(&l.addendum) || l.addendum == 0.0 {
            return bad(
                "addendum",
                format!("{} is out of range", l.addendum),
                "the addendum coefficient ha* is above 0 and at most 2 (1 is standard)",
            );
        }
        Ok(())
    }

    fn module_ratios(&self) -> Vec<ModuleRatio> {
        if self.two_modules && self.scheme.double_planet() {
            standard_module_ratios()
        } else {
            vec![ModuleRatio::ONE]
        }
    }
}

/// One tooth-number set that meets every condition.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Candidate {
    /// The tooth numbers.
    pub teeth: Teeth,
    /// `m_II / m_I` (1/1 with one module).
    pub modules: ModuleRatio,
    /// Willis' ratio `u_1H`, exact.
    pub ratio: Fraction,
    /// The relative error `(u − U)/U`.
    pub error: f64,
    /// The overall radial size in modules m_I ([`radial_size`]).
    pub radial_size: f64,
    /// The assembly number `M`: planets can sit at multiples of `2π/M`.
    pub positions: u64,
    /// `true` when `k` planets can be equally spaced (`M % k == 0`).
    pub equal_spacing: bool,
}

impl Candidate {
    /// The ranking: smaller radial size first, then smaller |error|, then
    /// fewer teeth in all, then the tooth numbers themselves (a total order).
    pub fn rank(&self, other: &Candidate) -> Ordering {
        let sum = |c: &Candidate| u64::from(c.teeth.z1) + u64::from(c.teeth.z2) + u64::from(c.teeth.z2p) + u64::from(c.teeth.z3);
        self.radial_size
            .total_cmp(&other.radial_size)
            .then(self.error.abs().total_cmp(&other.error.abs()))
            .then(sum(self).cmp(&sum(other)))
            .then(self.teeth.cmp(&other.teeth))
            .then((self.modules.num * other.modules.den).cmp(&(other.modules.num * self.modules.den)))
    }
}

/// How many sets passed each condition, in order (for the "fails first" message).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize)]
pub struct Counts {
    /// Sets (any `z ≥ 1`) with the ratio in tolerance and coaxial.
    pub ratio: u64,
    /// … and no undercut.
    pub undercut: u64,
    /// … and within the internal-mesh limits.
    pub internal: u64,
    /// … and with room for `k` planets (`M ≥ k`).
    pub assembly: u64,
    /// … of them with equal spacing possible.
    pub equal: u64,
    /// … equally spaced and clear of each other: the candidates.
    pub neighbour: u64,
    /// Sets that fail only equal spacing and are clear with the most even unequal spacing.
    pub unequal: u64,
}

/// The result of a search.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Synthesis {
    /// The sets, best first. With equally spaced sets available, only those;
    /// otherwise the sets that assemble with unequal spacing.
    pub candidates: Vec<Candidate>,
    /// `true` when the candidates are equally spaced.
    pub equal_spacing: bool,
    /// The counts of the stages.
    pub counts: Counts,
}

impl Synthesis {
    /// The best-ranked set.
    pub fn best(&self) -> &Candidate {
        &self.candidates[0]
    }
}

/// Search, rank, and explain a failure.
///
/// ```
/// use tmm_planetary::{synthesize, Scheme};
/// let s = synthesize(&tmm_planetary::Request::new(Scheme::SunPlanetRing, 4.0, 3)).unwrap();
/// let b = s.best();
/// assert_eq!((b.teeth.z1, b.teeth.z2, b.teeth.z3), (30, 30, 90));
/// let e = synthesize(&tmm_planetary::Request::new(Scheme::SunPlanetRing, 1.01, 3)).unwrap_err();
/// assert!(e.to_string().starts_with("ratio and coaxiality"));
/// ```
pub fn synthesize(req: &Request) -> Result<Synthesis, PlanetaryError> {
    let mut candidates = Vec::new();
    let counts = enumerate_into(req, &mut candidates)?;
    let equal_spacing = counts.neighbour > 0;
    if equal_spacing {
        candidates.retain(|c| c.equal_spacing);
    }
    if candidates.is_empty() {
        return Err(no_solution(req, &counts));
    }
    candidates.sort_unstable_by(Candidate::rank);
    Ok(Synthesis {
        candidates,
        equal_spacing,
        counts,
    })
}

/// The bounds of the wanted ratio `[U − T|U|, U + T|U|]`, widened by a hair so
/// that an exact ratio written in decimals (4.2 = 21/5) is found.
fn ratio_window(req: &Request) -> (f64, f64) {
    let u = req.ratio;
    let w = req.tolerance * u.abs() + 1e-9 * u.abs().max(1.0);
    (u - w, u + w)
}

/// Enumerate every set of `req` that meets all conditions (equally spaced,
/// or, failing only that, unequally spaced) into `out` (cleared first), in
/// no particular order. Returns the stage counts.
pub fn enumerate_into(req: &Request, out: &mut Vec<Candidate>) -> Result<Counts, PlanetaryError> {
    req.validate()?;
    out.clear();
    let mut counts = Counts::default();
    let (ulo, uhi) = ratio_window(req);
    let s = req.scheme.willis_sign() as f64;
    // Q = z2·z3/(z1·z2′) = s·(u − 1)
    let (qlo, qhi) = if s > 0.0 { (ulo - 1.0, uhi - 1.0) } else { (1.0 - uhi, 1.0 - ulo) };
    if qhi <= 0.0 {
        return Err(no_solution(req, &counts));
    }
    let zmax = req.limits.zmax;
    let zmaxf = f64::from(zmax);
    let clamp = |x: f64| x.clamp(-1.0, zmaxf + 2.0);
    let mut visit = |t: Teeth, q: ModuleRatio| visit_set(req, t, q, (ulo, uhi), &mut counts, out);
    if !req.scheme.double_planet() {
        // z3 = z1 + 2·z2 and u = 1 + z3/z1: z3 ∈ [qlo·z1, qhi·z1].
        for z1 in 1..=zmax {
            let z1f = f64::from(z1);
            let lo = (clamp(qlo * z1f).floor() as i64 - 1).max(i64::from(z1) + 2);
            let hi = (clamp(qhi * z1f).ceil() as i64 + 1).min(i64::from(zmax));
            for z3 in lo..=hi {
                if (z3 - i64::from(z1)) % 2 == 0 {
                    let z2 = ((z3 - i64::from(z1)) / 2) as u32;
                    visit(Teeth::single(z1, z2, z3 as u32), ModuleRatio::ONE);
                }
            }
        }
        return Ok(counts);
    }
    let row2_internal = req.scheme.meshes().1 == Mesh::Internal;
    for q in req.module_ratios() {
        for z1 in 1..=zmax {
            for z2 in 1..=zmax {
                let Some(span2) = row2_span(req.scheme, z1, z2, q) else { continue };
                // Q(z2′) = (z2/z1)·(1 ± span2/z2′), decreasing in z2′.
                let c = f64::from(z1) / f64::from(z2);
                let sf = span2 as f64;
                let (lo, hi) = if row2_internal {
                    // z3 = z2′ + span2, z2′ = span2/(Q·z1/z2 − 1)
                    let dhi = qhi * c - 1.0;
                    if dhi <= 0.0 {
                        continue;
                    }
                    let dlo = qlo * c - 1.0;
                    let hi = if dlo <= 0.0 { zmaxf + 2.0 } else { clamp(sf / dlo) };
                    (clamp(sf / dhi), hi.min(zmaxf - sf))
                } else {
                    // z3 = span2 − z2′, z2′ = span2/(Q·z1/z2 + 1)
                    let hi = if qlo <= 0.0 { sf - 1.0 } else { clamp(sf / (qlo * c + 1.0)) };
                    (clamp(sf / (qhi * c + 1.0)), hi.min(sf - 1.0))
                };
                let lo = (lo.floor() as i64 - 1).max(1);
                let hi = (hi.ceil() as i64 + 1).min(i64::from(zmax));
                for z2p in lo..=hi {
                    let z3 = if row2_internal { z2p + span2 } else { span2 - z2p };
                    if (1..=i64::from(zmax)).contains(&z3) {
                        visit(Teeth::double(z1, z2, z2p as u32, z3 as u32), q);
                    }
                }
            }
        }
    }
    Ok(counts)
}

/// Row II's span `z3 ± z2′` that coaxiality demands of `z1`, `z2` and the
/// module ratio: `m_I·span1 = m_II·span2`; `None` when it is not a positive integer.
fn row2_span(scheme: Scheme, z1: u32, z2: u32, q: ModuleRatio) -> Option<i64> {
    let span1 = match scheme.meshes().0 {
        Mesh::External => i64::from(z1) + i64::from(z2),
        Mesh::Internal => i64::from(z1) - i64::from(z2),
    };
    let n = span1 * i64::from(q.den);
    (span1 > 0 && n % i64::from(q.num) == 0).then(|| n / i64::from(q.num))
}

/// Check one coaxial set against every condition, counting and keeping it.
fn visit_set(req: &Request, t: Teeth, q: ModuleRatio, (ulo, uhi): (f64, f64), counts: &mut Counts, out: &mut Vec<Candidate>) {
    let zmax = req.limits.zmax;
    if [t.z1, t.z2, t.z2p, t.z3].iter().any(|&z| z == 0 || z > zmax) {
        return;
    }
    let ratio = willis_ratio(req.scheme, &t);
    let u = ratio.value();
    if !(ulo..=uhi).contains(&u) || ratio.num == 0 {
        return;
    }
    debug_assert!(crate::scheme::coaxial(req.scheme, &t, q));
    counts.ratio += 1;
    if !no_undercut(req.scheme, &t, req.limits.zmin) {
        return;
    }
    counts.undercut += 1;
    if !internal_limits(req.scheme, &t, &req.limits) {
        return;
    }
    counts.internal += 1;
    let k = req.planets;
    let m = assembly_positions(req.scheme, &t);
    if m < u64::from(k) {
        return;
    }
    counts.assembly += 1;
    let equal = m % u64::from(k) == 0;
    counts.equal += u64::from(equal);
    // A single planet has no neighbour.
    if k > 1 && !neighbours_clear(req.scheme, &t, q, smallest_gap(m, k), req.limits.addendum) {
        return;
    }
    if equal {
        counts.neighbour += 1;
    } else {
        counts.unequal += 1;
    }
    let error = (u - req.ratio) / req.ratio + 0.0; // + 0.0: no "-0" in outputs
    out.push(Candidate {
        teeth: t,
        modules: q,
        ratio,
        error,
        radial_size: radial_size(req.scheme, &t, q),
        positions: m,
        equal_spacing: equal,
    });
}

/// The range of ratios a scheme can give, in words, with the bound that the
/// tooth-number limits put on it: z3 ≤ zmax and z1 ≥ zmin give
/// u_1H = 1 + z3/z1 ≤ 1 + zmax/zmin for sun-planet-ring, and
/// u_1H = 1 + z2·z3/(z1·z2') ≤ 1 + (zmax/zmin)² for ext-int.
fn reach(scheme: Scheme, l: &Limits) -> String {
    let q = l.zmax as f64 / l.zmin.max(1) as f64;
    match scheme {
        Scheme::SunPlanetRing => format!(
            "u_1H = 1 + z3/z1 with z3 = z1 + 2·z2, so 2 < u_1H ≤ 1 + zmax/zmin = {:.4} with z from {} to {}",
            1.0 + q,
            l.zmin,
            l.zmax
        ),
        Scheme::ExtInt => format!(
            "u_1H = 1 + z2·z3/(z1·z2'), so 1 < u_1H ≤ 1 + (zmax/zmin)² = {:.4} with z from {} to {}",
            1.0 + q * q,
            l.zmin,
            l.zmax
        ),
        Scheme::ExtExt => "u_1H = 1 − z2·z3/(z1·z2'), so u_1H < 1 (u_1H ≠ 0; with the carrier driving, u_H1 = 1/u_1H)".into(),
        Scheme::IntInt => "u_1H = 1 − z2·z3/(z1·z2'), so u_1H < 1 (u_1H ≠ 0; with the carrier driving, u_H1 = 1/u_1H)".into(),
    }
}

/// The error for a search that found nothing: the first condition after
/// which no set was left.
fn no_solution(req: &Request, c: &Counts) -> PlanetaryError {
    let (u, k, l) = (req.ratio, req.planets, &req.limits);
    let within = if req.tolerance > 0.0 {
        format!("within {} %", req.tolerance * 100.0)
    } else {
        "exactly".to_string()
    };
    let (condition, message, help) = if c.ratio == 0 {
        (
            Condition::RatioCoaxiality,
            format!(
                "no coaxial set of tooth numbers up to zmax = {} gives u_1H = {u} {within}: the scheme {} has {}",
                l.zmax,
                req.scheme.name(),
                reach(req.scheme, l)
            ),
            "choose a ratio the scheme can give, another scheme, or allow a tolerance (e.g. 0.02)".to_string(),
        )
    } else if c.undercut == 0 {
        (
            Condition::Undercut,
            format!(
                "all {} coaxial sets with u_1H = {u} {within} have an external wheel with fewer than zmin = {} teeth",
                c.ratio, l.zmin
            ),
            "raise zmax, allow a tolerance, or lower zmin (wheels below 17 teeth need profile shift)".to_string(),
        )
    } else if c.internal == 0 {
        (
            Condition::InternalMesh,
            format!(
                "all {} sets without undercut have a ring with fewer than {} teeth or a ring–planet difference below {}",
                c.undercut, l.ring_zmin, l.min_difference
            ),
            "raise zmax, allow a tolerance, or relax ring_zmin / min_difference".to_string(),
        )
    } else if c.assembly == 0 {
        (
            Condition::Assembly,
            format!(
                "none of the {} sets can hold {k} planets: the assembly number M = |z1·z2'·u_1H|/gcd(z2, z2') is below {k}",
                c.internal
            ),
            "use fewer planets".to_string(),
        )
    } else {
        (
            Condition::Neighbour,
            format!(
                "with {k} planets the tip circles of adjacent planets overlap in all {} sets that meet the other conditions: 2·a_w·sin(π/k) ≤ d_a",
                c.assembly
            ),
            "use fewer planets, or a ratio that gives smaller planets".to_string(),
        )
    };
    PlanetaryError::NoSolution { condition, message, help }
}
