//! The four 2K-H schemes of the course (схемы планетарных механизмов 2K-H),
//! their tooth numbers, Willis' ratio and the coaxiality condition.
//!
//! In every scheme the central wheel 1 is the input (or output) member, the
//! carrier H (водило) is the other, and the central wheel 3 is fixed. The
//! ratio is always `u_1H = ω1 / ωH` (передаточное отношение от колеса 1 к водилу).

use serde::{Deserialize, Serialize};

/// One of the four 2K-H schemes of the course (Kudryavtsev's A, B, C, D).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Scheme {
    /// Single-row planets: external mesh 1–2 (sun–planet), internal mesh 2–3
    /// (planet–fixed ring). Teeth `[z1, z2, z3]`.
    SunPlanetRing,
    /// Double planet 2–2′: external mesh 1–2, internal mesh 2′–3 (fixed ring).
    /// Teeth `[z1, z2, z2′, z3]`.
    ExtInt,
    /// Double planet 2–2′: external mesh 1–2, external mesh 2′–3 (fixed
    /// central external wheel). Teeth `[z1, z2, z2′, z3]`.
    ExtExt,
    /// Double planet 2–2′: internal mesh 1–2 (wheel 1 is a ring), internal mesh
    /// 2′–3 (fixed ring). Teeth `[z1, z2, z2′, z3]`.
    IntInt,
}

/// The kind of a mesh (внешнее / внутреннее зацепление).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Mesh {
    /// Two external wheels; the wheels turn in opposite senses (carrier fixed).
    External,
    /// An external wheel inside a ring; both turn in the same sense (carrier fixed).
    Internal,
}

impl Scheme {
    /// All four schemes, in the order of the course.
    pub const ALL: [Scheme; 4] = [Scheme::SunPlanetRing, Scheme::ExtInt, Scheme::ExtExt, Scheme::IntInt];

    /// The name used on the command line and in task files.
    ///
    /// ```
    /// use tmm_planetary::Scheme;
    /// assert_eq!(Scheme::from_name(Scheme::ExtInt.name()), Some(Scheme::ExtInt));
    /// assert_eq!(Scheme::from_name("A"), None);
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Scheme::SunPlanetRing => "sun-planet-ring",
            Scheme::ExtInt => "ext-int",
            Scheme::ExtExt => "ext-ext",
            Scheme::IntInt => "int-int",
        }
    }

    /// The scheme of a name (`sun-planet-ring`, `ext-int`, `ext-ext`, `int-int`).
    pub fn from_name(s: &str) -> Option<Scheme> {
        Scheme::ALL.into_iter().find(|x| x.name() == s)
    }

    /// `true` for the schemes with a double planet (блок сателлитов 2–2′).
    pub fn double_planet(self) -> bool {
        self != Scheme::SunPlanetRing
    }

    /// The kinds of mesh 1–2 (row I) and 2′–3 (row II).
    pub fn meshes(self) -> (Mesh, Mesh) {
        match self {
            Scheme::SunPlanetRing | Scheme::ExtInt => (Mesh::External, Mesh::Internal),
            Scheme::ExtExt => (Mesh::External, Mesh::External),
            Scheme::IntInt => (Mesh::Internal, Mesh::Internal),
        }
    }

    /// The names of the tooth numbers, in the order of [`Teeth::to_vec`]
    /// and of the JSON array `z`.
    ///
    /// ```
    /// use tmm_planetary::Scheme;
    /// assert_eq!(Scheme::SunPlanetRing.teeth_names(), &["z1", "z2", "z3"]);
    /// assert_eq!(Scheme::IntInt.teeth_names(), &["z1", "z2", "z2'", "z3"]);
    /// ```
    pub fn teeth_names(self) -> &'static [&'static str] {
        if self.double_planet() {
            &["z1", "z2", "z2'", "z3"]
        } else {
            &["z1", "z2", "z3"]
        }
    }

    /// The sign `s` in `u_1H = 1 + s·(z2·z3)/(z1·z2′)`: `+1` when the
    /// carrier-fixed ratio `u_13^H` is negative (one external and one internal
    /// mesh), `−1` when it is positive (two meshes of the same kind).
    ///
    /// Source: Willis' method, `u_1H = 1 − u_13^H` with
    /// `u_13^H = (−1)^n_ext · (z2·z3)/(z1·z2′)` (Artobolevsky, ТММ, 1988,
    /// chapter on planetary trains; derivation in docs/planetary.md §1).
    pub fn willis_sign(self) -> i64 {
        match self {
            Scheme::SunPlanetRing | Scheme::ExtInt => 1,
            Scheme::ExtExt | Scheme::IntInt => -1,
        }
    }

    /// The member that usually drives in this scheme: the sun (wheel 1) for
    /// the reducers with `u_1H > 1` (sun-planet-ring, ext-int), the carrier for
    /// the large-ratio schemes with two meshes of one kind (ext-ext, int-int).
    pub fn usual_driver(self) -> Driver {
        match self {
            Scheme::SunPlanetRing | Scheme::ExtInt => Driver::Sun,
            Scheme::ExtExt | Scheme::IntInt => Driver::Carrier,
        }
    }
}

/// Which member drives (ведущее звено).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Driver {
    /// Central wheel 1 drives, the carrier is driven.
    Sun,
    /// The carrier drives, wheel 1 is driven.
    Carrier,
}

/// Tooth numbers (числа зубьев) of a 2K-H train. For the single-row scheme
/// `z2p == z2` (the planet is one wheel).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub struct Teeth {
    /// Central wheel 1 (the sun, or a ring in `int-int`).
    pub z1: u32,
    /// Planet wheel 2, meshing with wheel 1.
    pub z2: u32,
    /// Planet wheel 2′ on the same block, meshing with wheel 3 (equal to `z2`
    /// in the single-row scheme).
    pub z2p: u32,
    /// Fixed central wheel 3 (a ring, or an external wheel in `ext-ext`).
    pub z3: u32,
}

impl Teeth {
    /// Tooth numbers of a single-row train `[z1, z2, z3]`.
    pub fn single(z1: u32, z2: u32, z3: u32) -> Teeth {
        Teeth { z1, z2, z2p: z2, z3 }
    }

    /// Tooth numbers of a double-planet train `[z1, z2, z2′, z3]`.
    pub fn double(z1: u32, z2: u32, z2p: u32, z3: u32) -> Teeth {
        Teeth { z1, z2, z2p, z3 }
    }

    /// The tooth numbers in the documented order of the scheme:
    /// `[z1, z2, z3]` for `sun-planet-ring`, `[z1, z2, z2′, z3]` otherwise.
    ///
    /// ```
    /// use tmm_planetary::{Scheme, Teeth};
    /// assert_eq!(Teeth::single(30, 30, 90).to_vec(Scheme::SunPlanetRing), vec![30, 30, 90]);
    /// ```
    pub fn to_vec(&self, scheme: Scheme) -> Vec<u32> {
        if scheme.double_planet() {
            vec![self.z1, self.z2, self.z2p, self.z3]
        } else {
            vec![self.z1, self.z2, self.z3]
        }
    }
}

/// The ratio of the modules of the two rows, `m_II / m_I = num / den`
/// (row I: mesh 1–2, row II: mesh 2′–3). `1/1` when both rows share one module.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub struct ModuleRatio {
    /// Numerator.
    pub num: u32,
    /// Denominator.
    pub den: u32,
}

impl ModuleRatio {
    /// One module for both rows.
    pub const ONE: ModuleRatio = ModuleRatio { num: 1, den: 1 };

    /// `m_II / m_I` as a number.
    pub fn value(self) -> f64 {
        f64::from(self.num) / f64::from(self.den)
    }
}

/// Standard modules of GOST 9563-60, first series (mm), 1 … 20: the ratios
/// of two of them are the module ratios allowed when the rows may differ.
pub const GOST_9563_FIRST_SERIES: [f64; 14] = [1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0, 12.0, 16.0, 20.0];

/// The distinct ratios `m_II / m_I` of two standard modules (GOST 9563-60,
/// first series) between 1/2 and 2, as reduced fractions, `1/1` first.
///
/// ```
/// let r = tmm_planetary::scheme::standard_module_ratios();
/// assert_eq!(r[0], tmm_planetary::ModuleRatio::ONE);
/// assert!(r.iter().any(|q| q.num == 5 && q.den == 4)); // 2.5 / 2
/// ```
pub fn standard_module_ratios() -> Vec<ModuleRatio> {
    let mut out = vec![ModuleRatio::ONE];
    for a in GOST_9563_FIRST_SERIES {
        for b in GOST_9563_FIRST_SERIES {
            // Modules are multiples of 0.25 mm: work in quarters to stay exact.
            let (n, d) = ((a * 4.0).round() as u32, (b * 4.0).round() as u32);
            let g = gcd(u64::from(n), u64::from(d)) as u32;
            let q = ModuleRatio { num: n / g, den: d / g };
            if 2 * q.num >= q.den && q.num <= 2 * q.den && !out.contains(&q) {
                out.push(q);
            }
        }
    }
    out
}

/// Greatest common divisor (Euclid).
///
/// ```
/// assert_eq!(tmm_planetary::scheme::gcd(84, 36), 12);
/// ```
pub fn gcd(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// An exact ratio `num / den` (`den > 0`), reduced.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct Fraction {
    /// Numerator (may be negative).
    pub num: i64,
    /// Denominator, positive.
    pub den: i64,
}

impl Fraction {
    /// The value as a number.
    pub fn value(self) -> f64 {
        self.num as f64 / self.den as f64
    }
}

/// Willis' ratio `u_1H = ω1/ωH` with wheel 3 fixed, exact.
///
/// `u_1H = 1 − u_13^H`, `u_13^H = (ω1 − ωH)/(ω3 − ωH) = (−1)^n_ext·(z2·z3)/(z1·z2′)`,
/// so `u_1H = (z1·z2′ + s·z2·z3) / (z1·z2′)` with `s` = [`Scheme::willis_sign`].
/// Source: Willis' formula (метод Виллиса, обращённое движение), Artobolevsky
/// I.I., ТММ, 1988, chapter on planetary trains; docs/planetary.md §1.
///
/// ```
/// use tmm_planetary::{scheme::willis_ratio, Scheme, Teeth};
/// // u_1H = 1 + z3/z1 = 1 + 90/30 = 4
/// assert_eq!(willis_ratio(Scheme::SunPlanetRing, &Teeth::single(30, 30, 90)).value(), 4.0);
/// // u_1H = 1 − (z2·z3)/(z1·z2′) = 1 − (99·101)/(100·100) = 1/10000
/// let u = willis_ratio(Scheme::ExtExt, &Teeth::double(100, 99, 100, 101));
/// assert_eq!((u.num, u.den), (1, 10000));
/// ```
pub fn willis_ratio(scheme: Scheme, t: &Teeth) -> Fraction {
    let den = i64::from(t.z1) * i64::from(t.z2p);
    let num = den + scheme.willis_sign() * i64::from(t.z2) * i64::from(t.z3);
    let g = gcd(num.unsigned_abs(), den.unsigned_abs()).max(1) as i64;
    Fraction {
        num: num / g,
        den: den / g,
    }
}

/// Row I's span `z1 ± z2` (twice the centre distance in modules m_I): `z1 + z2`
/// for an external mesh 1–2, `z1 − z2` for an internal one (may be ≤ 0 for a
/// set that cannot exist).
pub fn span_row1(scheme: Scheme, t: &Teeth) -> i64 {
    match scheme.meshes().0 {
        Mesh::External => i64::from(t.z1) + i64::from(t.z2),
        Mesh::Internal => i64::from(t.z1) - i64::from(t.z2),
    }
}

/// Row II's span `z3 ± z2′` (twice the centre distance in modules m_II):
/// `z3 + z2′` for an external mesh 2′–3, `z3 − z2′` for an internal one.
pub fn span_row2(scheme: Scheme, t: &Teeth) -> i64 {
    match scheme.meshes().1 {
        Mesh::External => i64::from(t.z3) + i64::from(t.z2p),
        Mesh::Internal => i64::from(t.z3) - i64::from(t.z2p),
    }
}

/// The coaxiality condition (условие соосности) for zero-shift wheels: the
/// centre distances of both rows are equal, `m_I·(z1 ± z2) = m_II·(z3 ± z2′)`;
/// for one module, e.g. `z1 + 2·z2 = z3` (sun-planet-ring).
///
/// Source: Artobolevsky I.I., ТММ, 1988, planetary trains (условие соосности);
/// docs/planetary.md §2.
///
/// ```
/// use tmm_planetary::{scheme::coaxial, ModuleRatio, Scheme, Teeth};
/// assert!(coaxial(Scheme::SunPlanetRing, &Teeth::single(30, 30, 90), ModuleRatio::ONE));
/// assert!(!coaxial(Scheme::SunPlanetRing, &Teeth::single(30, 31, 90), ModuleRatio::ONE));
/// // 2·(20 + 40) = 2.5·(72 − 24)
/// assert!(coaxial(Scheme::ExtInt, &Teeth::double(20, 40, 24, 72), ModuleRatio { num: 5, den: 4 }));
/// ```
pub fn coaxial(scheme: Scheme, t: &Teeth, q: ModuleRatio) -> bool {
    let (s1, s2) = (span_row1(scheme, t), span_row2(scheme, t));
    s1 > 0 && s2 > 0 && s1 * i64::from(q.den) == s2 * i64::from(q.num)
}

/// The centre distance of the planets' axes from the main axis, in modules
/// m_I: `a_w / m_I = (z1 ± z2)/2` (zero-shift wheels).
pub fn centre_distance(scheme: Scheme, t: &Teeth) -> f64 {
    0.5 * span_row1(scheme, t) as f64
}

/// The overall radial size of the train in modules m_I: the diameter of the
/// smallest circle about the main axis that holds every pitch circle,
/// `max(z1, (m_II/m_I)·z3, 2a_w/m_I + z2, 2a_w/m_I + (m_II/m_I)·z2′)`.
/// For the schemes with a ring it is the ring's pitch diameter, the
/// "largest pitch diameter" of the course (docs/planetary.md §5).
///
/// ```
/// use tmm_planetary::{scheme::radial_size, ModuleRatio, Scheme, Teeth};
/// assert_eq!(radial_size(Scheme::SunPlanetRing, &Teeth::single(30, 30, 90), ModuleRatio::ONE), 90.0);
/// // ext-ext: planets stick out beyond both central wheels: 20 + 40 + 40
/// assert_eq!(radial_size(Scheme::ExtExt, &Teeth::double(20, 40, 30, 30), ModuleRatio::ONE), 100.0);
/// // with m_II/m_I = 5/6 and 2/3 two sets have the same size, 70/3, and the
/// // same number: the search then ranks them by their ratio error
/// let a = radial_size(Scheme::ExtInt, &Teeth::double(8, 7, 10, 28), ModuleRatio { num: 5, den: 6 });
/// let b = radial_size(Scheme::ExtInt, &Teeth::double(9, 7, 11, 35), ModuleRatio { num: 2, den: 3 });
/// assert_eq!(a, b);
/// assert_eq!(a, 70.0 / 3.0);
/// ```
///
/// Every term is a whole multiple of `1/den` for `m_II/m_I = num/den`, so the
/// size is computed as the whole number `max(z1·den, num·z3, (2a_w/m_I)·den +
/// max(z2·den, num·z2′))` divided once by `den` (derived here). The result is
/// the correctly rounded value of the exact size: equal sizes give equal
/// numbers, whatever the tooth numbers and module ratio, and the search's
/// ranking by size is exact.
pub fn radial_size(scheme: Scheme, t: &Teeth, q: ModuleRatio) -> f64 {
    let (num, den) = (i64::from(q.num), i64::from(q.den).max(1));
    let two_aw = span_row1(scheme, t);
    let planet = (i64::from(t.z2) * den).max(num * i64::from(t.z2p));
    let size = (i64::from(t.z1) * den).max(num * i64::from(t.z3)).max(two_aw * den + planet);
    size as f64 / den as f64
}
