//! The conditions a tooth-number set must meet (условия подбора чисел зубьев):
//! no undercut, the internal-mesh limits, assembly and neighbour. The ratio
//! and coaxiality are in [`crate::scheme`].

use std::f64::consts::PI;

use serde::Serialize;

use crate::scheme::{Mesh, ModuleRatio, Scheme, Teeth, centre_distance, gcd};

/// The limits of the conditions, for the basic rack `α = 20°`, `c* = 0.25`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Limits {
    /// Smallest tooth number of an external wheel cut by a rack without
    /// undercut (z_min, default 17 for `ha* = 1`, `α = 20°`).
    pub zmin: u32,
    /// Largest tooth number of any wheel considered (default 200).
    pub zmax: u32,
    /// Smallest tooth number of a ring (internal wheel), default 85 for `ha* = 1`.
    pub ring_zmin: u32,
    /// Smallest difference of tooth numbers ring − planet in an internal mesh,
    /// default 8 for `ha* = 1`.
    pub min_difference: u32,
    /// Addendum coefficient `ha*` (коэффициент высоты головки), default 1.
    pub addendum: f64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            zmin: 17,
            zmax: 200,
            ring_zmin: 85,
            min_difference: 8,
            addendum: 1.0,
        }
    }
}

/// No undercut of the external wheels (отсутствие подрезания): every external
/// wheel has `z ≥ z_min`; `z_min = 2·ha*/sin²α = 17.1 → 17` for `ha* = 1`,
/// `α = 20°` (the course allows 17 — a slight undercut that does not harm).
/// The external wheels are the planets 2 and 2′, wheel 1 unless it is a ring
/// (`int-int`), and wheel 3 in `ext-ext`.
///
/// Source: GOST 16532-70 / Artobolevsky, ТММ, 1988, undercut by a rack.
///
/// ```
/// use tmm_planetary::{conditions::no_undercut, Scheme, Teeth};
/// assert!(no_undercut(Scheme::SunPlanetRing, &Teeth::single(17, 34, 85), 17));
/// assert!(!no_undercut(Scheme::SunPlanetRing, &Teeth::single(16, 34, 84), 17));
/// // int-int: wheel 1 is a ring, only the planets count
/// assert!(no_undercut(Scheme::IntInt, &Teeth::double(100, 20, 18, 98), 17));
/// ```
pub fn no_undercut(scheme: Scheme, t: &Teeth, zmin: u32) -> bool {
    let (m1, m2) = scheme.meshes();
    let planets = t.z2 >= zmin && t.z2p >= zmin;
    let w1 = m1 == Mesh::Internal || t.z1 >= zmin;
    let w3 = m2 == Mesh::Internal || t.z3 >= zmin;
    planets && w1 && w3
}

/// The internal-mesh limits for zero-shift wheels with `ha* = 1`, `α = 20°`
/// (отсутствие интерференции во внутреннем зацеплении): every ring has
/// `z ≥ 85` and in every internal mesh `z_ring − z_planet ≥ 8`.
///
/// Source: the rule of the MGTU course for zero-shift internal gearing cut by a
/// shaper cutter (Popov S.A., Timofeev G.A., Курсовое проектирование по
/// теории механизмов и механике машин, 2002, planetary trains); both numbers
/// are options (`Limits::ring_zmin`, `Limits::min_difference`), see
/// docs/planetary.md §4.
///
/// ```
/// use tmm_planetary::{conditions::{internal_limits, Limits}, Scheme, Teeth};
/// let l = Limits::default();
/// assert!(internal_limits(Scheme::SunPlanetRing, &Teeth::single(30, 30, 90), &l));
/// assert!(!internal_limits(Scheme::SunPlanetRing, &Teeth::single(28, 28, 84), &l)); // ring 84 < 85
/// assert!(!internal_limits(Scheme::IntInt, &Teeth::double(90, 84, 20, 26), &l)); // 90 − 84 < 8
/// ```
pub fn internal_limits(scheme: Scheme, t: &Teeth, l: &Limits) -> bool {
    let ok = |ring: u32, planet: u32| ring >= l.ring_zmin && ring >= planet + l.min_difference;
    let (m1, m2) = scheme.meshes();
    (m1 == Mesh::External || ok(t.z1, t.z2)) && (m2 == Mesh::External || ok(t.z3, t.z2p))
}

/// The assembly number `N = z1·z2′·u_1H = z1·z2′ ± z2·z3` (the sign of
/// [`Scheme::willis_sign`]) divided by `g = gcd(z2, z2′)`, as an absolute
/// value: the number of equally spaced carrier angles `2π·j/M` at which a
/// planet block can be put in mesh with both central wheels once the first one
/// is in place.
///
/// Derived here (docs/planetary.md §3) from the tooth phases of the two
/// meshes; for a single-row train it is `z1 + z3`, the course's
/// `(z1 + z3)/k = integer` (Artobolevsky, ТММ, 1988, условие сборки), and for a
/// double planet it agrees with the course's `z1·u_1H·(1 + k·p)/k = integer`
/// whenever that rule admits a set.
///
/// ```
/// use tmm_planetary::{conditions::assembly_positions, Scheme, Teeth};
/// assert_eq!(assembly_positions(Scheme::SunPlanetRing, &Teeth::single(30, 30, 90)), 120);
/// // ext-int 20, 40, 24, 84: (20·24 + 40·84)/gcd(40, 24) = 3840/8
/// assert_eq!(assembly_positions(Scheme::ExtInt, &Teeth::double(20, 40, 24, 84)), 480);
/// ```
pub fn assembly_positions(scheme: Scheme, t: &Teeth) -> u64 {
    let n = i64::from(t.z1) * i64::from(t.z2p) + scheme.willis_sign() * i64::from(t.z2) * i64::from(t.z3);
    let g = gcd(u64::from(t.z2), u64::from(t.z2p)).max(1);
    n.unsigned_abs() / g
}

/// The assembly condition with `k` equally spaced planets (условие сборки):
/// `M / k` is an integer, `M` = [`assembly_positions`].
///
/// ```
/// use tmm_planetary::{conditions::equal_spacing, Scheme, Teeth};
/// assert!(equal_spacing(Scheme::SunPlanetRing, &Teeth::single(30, 30, 90), 3)); // 120/3
/// assert!(!equal_spacing(Scheme::SunPlanetRing, &Teeth::single(31, 31, 93), 3)); // 124/3
/// ```
pub fn equal_spacing(scheme: Scheme, t: &Teeth, k: u32) -> bool {
    let m = assembly_positions(scheme, t);
    k >= 1 && m >= u64::from(k) && m % u64::from(k) == 0
}

/// The positions (multiples of `2π/M`) of `k` planets spaced as evenly as the
/// assembly allows: planet `i` at `⌊i·M/k⌋`; `None` when `M < k`. With
/// `M % k == 0` they are equally spaced.
///
/// ```
/// use tmm_planetary::conditions::planet_positions;
/// assert_eq!(planet_positions(124, 3), Some(vec![0, 41, 82]));
/// assert_eq!(planet_positions(2, 3), None);
/// ```
pub fn planet_positions(m: u64, k: u32) -> Option<Vec<u64>> {
    (k >= 1 && m >= u64::from(k)).then(|| (0..u64::from(k)).map(|i| i * m / u64::from(k)).collect())
}

/// The smallest angle between adjacent planets of [`planet_positions`]:
/// `2π·⌊M/k⌋/M`, rad; `2π/k` when the spacing is equal.
pub fn smallest_gap(m: u64, k: u32) -> f64 {
    if k <= 1 || m == 0 {
        return 2.0 * PI;
    }
    2.0 * PI * (m / u64::from(k)) as f64 / m as f64
}

/// The neighbour condition (условие соседства) for planets `gap` rad apart:
/// the tip circles of adjacent planets do not touch,
/// `2·a_w·sin(gap/2) > d_a,max` with `d_a2 = m_I·(z2 + 2ha*)`,
/// `d_a2′ = m_II·(z2′ + 2ha*)`; for equal spacing `gap = 2π/k`, the course's
/// `(z1 + z2)·sin(π/k) > z2 + 2ha*`.
///
/// Source: Artobolevsky I.I., ТММ, 1988, условие соседства; docs/planetary.md §3.
///
/// ```
/// use std::f64::consts::PI;
/// use tmm_planetary::{conditions::neighbours_clear, ModuleRatio, Scheme, Teeth};
/// // 60·sin 60° = 51.96 > 32
/// assert!(neighbours_clear(Scheme::SunPlanetRing, &Teeth::single(30, 30, 90), ModuleRatio::ONE, 2.0 * PI / 3.0, 1.0));
/// // 60·sin 30° = 30 < 32
/// assert!(!neighbours_clear(Scheme::SunPlanetRing, &Teeth::single(30, 30, 90), ModuleRatio::ONE, 2.0 * PI / 6.0, 1.0));
/// ```
pub fn neighbours_clear(scheme: Scheme, t: &Teeth, q: ModuleRatio, gap: f64, addendum: f64) -> bool {
    let aw = centre_distance(scheme, t);
    let da = (f64::from(t.z2) + 2.0 * addendum).max(q.value() * (f64::from(t.z2p) + 2.0 * addendum));
    2.0 * aw * (0.5 * gap).sin() - da > 1e-9
}
