//! The human-readable report of a planetary run: the request, the stage
//! counts, the best set with every condition's numbers, and the table of the
//! first candidates.

use std::f64::consts::PI;
use std::fmt::Write as _;

use tmm_planetary::scheme::span_row1;
use tmm_planetary::{Candidate, Driver, Scheme, Teeth};

use super::analysis::Analysis;

/// `z1 = 30, z2 = 30, z3 = 90`.
pub fn teeth_text(scheme: Scheme, c: &Candidate) -> String {
    let v = c.teeth.to_vec(scheme);
    scheme
        .teeth_names()
        .iter()
        .zip(v)
        .map(|(n, z)| format!("{n} = {z}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Willis' formula for the set, in the drawings' index markup, with its
/// numbers: `1 + z_3/z_1 = 1 + 85/17` for one planet per row,
/// `1 − z_2·z_3/(z_1·z_2′) = 1 − 99·101/(100·100)` for a double planet.
///
/// Source: `u_1H = 1 − u_13^H`, `u_13^H = (−1)^n_ext·(z2·z3)/(z1·z2′)`
/// (Artobolevsky, ТММ, 1988; `tmm_planetary::scheme::willis_ratio`, whose
/// sign this takes); with one planet z2′ = z2 cancels.
///
/// ```
/// use tmm_planetary::{Scheme, Teeth};
/// use tmm_report::planetary::text::willis_text;
/// assert_eq!(willis_text(Scheme::SunPlanetRing, &Teeth::single(17, 34, 85)), "1 + z_3/z_1 = 1 + 85/17");
/// assert_eq!(
///     willis_text(Scheme::ExtExt, &Teeth::double(100, 99, 100, 101)),
///     "1 − z_2·z_3/(z_1·z_{2′}) = 1 − 99·101/(100·100)"
/// );
/// ```
pub fn willis_text(scheme: Scheme, t: &Teeth) -> String {
    let sign = if scheme.willis_sign() > 0 { '+' } else { '−' };
    let Teeth { z1, z2, z2p, z3 } = *t;
    if scheme.double_planet() {
        format!("1 {sign} z_2·z_3/(z_1·z_{{2′}}) = 1 {sign} {z2}·{z3}/({z1}·{z2p})")
    } else {
        format!("1 {sign} z_3/z_1 = 1 {sign} {z3}/{z1}")
    }
}

/// The ratio as a fraction, or a whole number.
pub fn fraction_text(c: &Candidate) -> String {
    if c.ratio.den == 1 {
        format!("{}", c.ratio.num)
    } else {
        format!("{}/{}", c.ratio.num, c.ratio.den)
    }
}

fn g(x: f64) -> String {
    if !x.is_finite() {
        return crate::output::NONFINITE.to_string();
    }
    let x = x + 0.0; // no "-0"
    let a = x.abs();
    if a != 0.0 && !(1e-3..1e6).contains(&a) {
        format!("{x:.4e}")
    } else {
        format!("{:.6}", x).trim_end_matches('0').trim_end_matches('.').to_string()
    }
}

/// The report.
pub fn report(a: &Analysis) -> String {
    let r = &a.params.request;
    let l = &r.limits;
    let b = &a.best;
    let sc = r.scheme;
    let mut s = String::new();
    let _ = writeln!(
        s,
        "Planetary train 2K-H, scheme {} (wheel 3 fixed), u_1H = ω1/ωH = {}, k = {} planets",
        sc.name(),
        g(r.ratio),
        r.planets
    );
    let _ = writeln!(
        s,
        "Search: z ≤ {}, external z ≥ {} (no undercut, ha* = {}, α = 20°), ring z ≥ {}, ring − planet ≥ {}, ratio tolerance {} %, {}",
        l.zmax,
        l.zmin,
        g(l.addendum),
        l.ring_zmin,
        l.min_difference,
        g(r.tolerance * 100.0),
        if r.two_modules && sc.double_planet() {
            "two modules allowed (GOST 9563)"
        } else {
            "one module"
        }
    );
    let c = &a.synthesis.counts;
    let _ = writeln!(
        s,
        "Sets passing, in order: ratio & coaxiality {} → no undercut {} → internal-mesh limits {} → assembly {} (equal spacing {}) → neighbour {}",
        c.ratio,
        c.undercut,
        c.internal,
        c.assembly,
        c.equal,
        if a.synthesis.equal_spacing { c.neighbour } else { c.unequal }
    );
    if !a.synthesis.equal_spacing {
        let _ = writeln!(
            s,
            "No set assembles with {} equally spaced planets: the sets below need UNEQUAL spacing (the carrier is then unbalanced).",
            r.planets
        );
    }
    let _ = writeln!(s);
    let m = a.params.module;
    let _ = writeln!(
        s,
        "Best: {}{}",
        teeth_text(sc, b),
        if b.modules.num != b.modules.den {
            format!("  (m_II/m_I = {}/{})", b.modules.num, b.modules.den)
        } else {
            String::new()
        }
    );
    let _ = writeln!(
        s,
        "  u_1H by Willis               = {}{} = {}   (error {} %)",
        willis_text(sc, &b.teeth).replace(['_', '{', '}'], ""),
        if b.ratio.den == 1 {
            String::new()
        } else {
            format!(" = {}", fraction_text(b))
        },
        g(b.ratio.value()),
        g(b.error * 100.0)
    );
    let _ = writeln!(s, "  u_1H read off the picture    = tan ψ1 / tan ψH = {}", g(a.picture.ratio));
    let _ = writeln!(s, "  u_1H read off the ω diagram  = 0–1 / 0–H = {}", g(a.diagram.ratio));
    if sc.usual_driver() == Driver::Carrier {
        let _ = writeln!(s, "  u_H1 = 1/u_1H                = {}", g(1.0 / b.ratio.value()));
    }
    let _ = writeln!(
        s,
        "  radial size                  = {} modules = {} mm at m = {} mm",
        g(b.radial_size),
        g(b.radial_size * m * 1e3),
        g(m * 1e3)
    );
    let _ = writeln!(
        s,
        "  centre distance a_w          = {} modules = {} mm",
        g(0.5 * span_row1(sc, &b.teeth) as f64),
        g(a.centre_distance * 1e3)
    );
    if b.equal_spacing {
        let _ = writeln!(
            s,
            "  assembly: M = {} is divisible by k = {} → planets every {}°",
            b.positions,
            r.planets,
            g(360.0 / f64::from(r.planets))
        );
    } else {
        let deg: Vec<String> = a.planet_angles.iter().map(|x| g(x * 180.0 / PI)).collect();
        let _ = writeln!(
            s,
            "  assembly: M = {} is not divisible by k = {} → planets at {}° (multiples of 360°/{})",
            b.positions,
            r.planets,
            deg.join("°, "),
            b.positions
        );
    }
    let gap = if a.planet_angles.len() > 1 {
        a.planet_angles[1] - a.planet_angles[0]
    } else {
        2.0 * PI
    };
    let gap = a.planet_angles.windows(2).map(|w| w[1] - w[0]).fold(gap, f64::min);
    let aw = 0.5 * span_row1(sc, &b.teeth) as f64;
    let q = b.modules.value();
    let da = (f64::from(b.teeth.z2) + 2.0 * l.addendum).max(q * (f64::from(b.teeth.z2p) + 2.0 * l.addendum));
    if r.planets > 1 {
        let chord = g(2.0 * aw * (0.5 * gap).sin());
        let _ = writeln!(
            s,
            "  neighbour: 2·a_w·sin(γ/2) = {chord} > d_a,max = {} (modules), γ = {}°",
            g(da),
            g(gap * 180.0 / PI)
        );
    } else {
        let _ = writeln!(s, "  neighbour: one planet, no neighbour");
    }
    let (dn, rn) = match a.driver {
        Driver::Sun => ("η_1H (wheel 1 drives)", "η_H1 (carrier drives)"),
        Driver::Carrier => ("η_H1 (carrier drives)", "η_1H (wheel 1 drives)"),
    };
    let lock = |e: f64| if e <= 0.0 { " — self-locking".to_string() } else { String::new() };
    let _ = writeln!(
        s,
        "  efficiency: η^H = {} (meshes {} ext, {} int); {dn} = {}{}; {rn} = {}{}",
        g(a.eta_h),
        g(a.params.efficiency.external),
        g(a.params.efficiency.internal),
        g(a.efficiency),
        lock(a.efficiency),
        g(a.efficiency_reverse),
        lock(a.efficiency_reverse)
    );
    let p = &a.picture;
    let _ = writeln!(
        s,
        "  speeds at ω1 = {} rad/s: ωH = {} rad/s, ω planet = {} rad/s; v_a = {} m/s, v_b = {} m/s",
        g(p.omega1),
        g(p.omega_h),
        g(p.omega_planet),
        g(p.a.v),
        g(p.b.v)
    );
    let _ = writeln!(s);
    let n = a.synthesis.candidates.len();
    let shown = n.min(a.params.top);
    let _ = writeln!(s, "Candidates (first {shown} of {n}, ranked by radial size, then ratio error):");
    let mut head = String::from("   #");
    for name in sc.teeth_names() {
        let _ = write!(head, " {name:>5}");
    }
    if r.two_modules && sc.double_planet() {
        head.push_str("  m_II/m_I");
    }
    let _ = writeln!(s, "{head}  {:>14}  {:>10}  {:>7}  {:>6}  spacing", "u_1H", "error %", "size", "M");
    for (i, c) in a.synthesis.candidates.iter().take(shown).enumerate() {
        let mut row = format!("{:>4}", i + 1);
        for z in c.teeth.to_vec(sc) {
            let _ = write!(row, " {z:>5}");
        }
        if r.two_modules && sc.double_planet() {
            let _ = write!(row, "  {:>8}", format!("{}/{}", c.modules.num, c.modules.den));
        }
        let _ = writeln!(
            s,
            "{row}  {:>14}  {:>10}  {:>7}  {:>6}  {}",
            fraction_text(c),
            g(c.error * 100.0),
            g(c.radial_size),
            c.positions,
            if c.equal_spacing { "equal" } else { "unequal" }
        );
    }
    s
}
