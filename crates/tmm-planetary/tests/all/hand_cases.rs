//! One case per scheme worked by hand (the derivation is in the comments),
//! and the impossible requests.
//!
//! Module m = 1 mm, ω1 = 1 rad/s, ha* = 1, basic rack α = 20°.

use approx::assert_relative_eq;
use tmm_planetary::conditions::{
    assembly_positions, equal_spacing, internal_limits, neighbours_clear, no_undercut, planet_positions, smallest_gap,
};
use tmm_planetary::efficiency::{carrier_fixed, train_efficiency};
use tmm_planetary::picture::{angular_diagram, velocity_picture};
use tmm_planetary::scheme::{coaxial, radial_size, willis_ratio};
use tmm_planetary::{Condition, Driver, Limits, MeshEfficiency, ModuleRatio, PlanetaryError, Request, Scheme, Teeth, synthesize};

const PI: f64 = std::f64::consts::PI;

/// Efficiency by a torque balance, independent of the closed forms: with the
/// carrier fixed the mesh losses take a share (1 − η^H) of the power of the
/// member that drives in the relative motion. Try both hypotheses (wheel 1 or
/// wheel 3 drives relatively) and keep the one whose relative power of wheel 1
/// has the assumed sign.
fn efficiency_by_balance(u: f64, eta_h: f64, driver: Driver) -> f64 {
    let wh = 1.0;
    let w1 = u * wh;
    let (x1, x3) = (w1 - wh, -wh); // relative angular velocities of 1 and 3
    for one_drives in [true, false] {
        // Input torque 1 on the driving member; unknowns T1 (or TH), T3.
        // Relative power: P1r + P3r + loss = 0, loss = (1 − η^H)·(driving relative power).
        // Linear in the unknown torques: solve the 2×2 system by Cramer.
        // Unknowns a = T1, b = T3, c = TH with T1 + T3 + TH = 0 and one input fixed.
        let (t1, t3, th) = match driver {
            Driver::Sun => {
                let t1 = 1.0;
                // one_drives: T3·x3 = −η·T1·x1; else T1·x1 = −η·T3·x3
                let t3 = if one_drives {
                    -eta_h * t1 * x1 / x3
                } else {
                    -t1 * x1 / (eta_h * x3)
                };
                (t1, t3, -t1 - t3)
            }
            Driver::Carrier => {
                let th = 1.0;
                // T1 + T3 = −TH and the relative balance give T1, T3.
                // one_drives: T3·x3 = −η·T1·x1 → T3 = −η·x1/x3·T1
                let k = if one_drives { -eta_h * x1 / x3 } else { -x1 / (eta_h * x3) };
                let t1 = -th / (1.0 + k);
                (t1, k * t1, th)
            }
        };
        let p1r = t1 * x1;
        if (p1r > 0.0) == one_drives {
            return match driver {
                Driver::Sun => -th * wh / (t1 * w1),
                Driver::Carrier => -t1 * w1 / (th * wh),
            };
        }
        let _ = t3;
    }
    panic!("no consistent hypothesis");
}

/// sun-planet-ring, u_1H = 4, k = 3 — the optimum found by hand.
///
/// Willis: u_1H = 1 + z3/z1 = 4 → z3 = 3·z1. Coaxiality z3 = z1 + 2·z2 → z2 = z1.
/// Ring limit z3 ≥ 85 → z1 ≥ 85/3 = 28.3 → z1 ≥ 29. Assembly (z1 + z3)/k = 4·z1/3
/// integer → z1 a multiple of 3 → the smallest is z1 = 30: z = [30, 30, 90].
/// Neighbour: (z1 + z2)·sin(π/3) = 60·0.8660 = 51.96 > z2 + 2 = 32.
/// Every exact set is z1·[1, 1, 3], so the radial size z3 = 3·z1 grows with z1:
/// [30, 30, 90] is the best, [33, 33, 99] the second.
/// Efficiency: η^H = 0.99·0.995 = 0.98505; η_1H = 1 − (1 − 0.98505)·(4 − 1)/4 = 0.9887875.
/// Picture: r1 = 15 mm, r3 = 45 mm, a_w = 30 mm; v_a = 15 mm/s; the planet line
/// from (15, 15) to (0, 45) gives v_b = 15·(45 − 30)/(45 − 15) = 7.5 mm/s;
/// ωH = 7.5/30 = 0.25 rad/s, u = 1/0.25 = 4; ω2 = 15/(15 − 45) = −0.5 rad/s.
#[test]
fn sun_planet_ring_u4_k3() {
    let s = synthesize(&Request::new(Scheme::SunPlanetRing, 4.0, 3)).unwrap();
    assert!(s.equal_spacing);
    assert_eq!(s.candidates[0].teeth, Teeth::single(30, 30, 90));
    assert_eq!(s.candidates[1].teeth, Teeth::single(33, 33, 99));
    assert_eq!(s.candidates[0].radial_size, 90.0);
    assert_eq!(s.candidates[0].error, 0.0);
    let t = Teeth::single(30, 30, 90);
    assert_eq!(assembly_positions(Scheme::SunPlanetRing, &t), 120);
    let eta = train_efficiency(4.0, carrier_fixed(Scheme::SunPlanetRing, MeshEfficiency::default()), Driver::Sun);
    assert_relative_eq!(eta, 1.0 - (1.0 - 0.99 * 0.995) * 3.0 / 4.0, max_relative = 1e-14);
    assert_relative_eq!(eta, 0.9887875, max_relative = 1e-12);
    let p = velocity_picture(Scheme::SunPlanetRing, &t, ModuleRatio::ONE, 1e-3, 1.0);
    assert_relative_eq!(p.a.v, 0.015, max_relative = 1e-14);
    assert_relative_eq!(p.b.v, 0.0075, max_relative = 1e-14);
    assert_relative_eq!(p.omega_h, 0.25, max_relative = 1e-14);
    assert_relative_eq!(p.omega_planet, -0.5, max_relative = 1e-14);
    assert_relative_eq!(p.ratio, 4.0, max_relative = 1e-14);
    assert_relative_eq!(angular_diagram(&p, 40.0).ratio, 4.0, max_relative = 1e-14);
}

/// ext-int, z = [24, 48, 24, 96], k = 3.
///
/// Willis: u_13^H = −(z2/z1)·(z3/z2′) = −(48/24)·(96/24) = −8, u_1H = 1 + 8 = 9.
/// Coaxiality z1 + z2 = 72 = z3 − z2′ = 96 − 24. No undercut: 24, 48, 24 ≥ 17.
/// Ring 96 ≥ 85, 96 − 24 = 72 ≥ 8. Assembly: (z1·z2′ + z2·z3)/gcd(z2, z2′)
/// = (576 + 4608)/24 = 216 = 3·72. Neighbour: 2·a_w·sin 60° = 72·0.8660 = 62.35,
/// above max(48 + 2, 24 + 2) = 50. Radial size: max(z3, z1 + 2·z2) = max(96, 120) = 120.
/// Efficiency (sun drives, u > 1): 1 − 0.01495·8/9 = 0.986711…
/// Picture: v_a = 12 at r = 12, zero at r3 = 48: v_b(36) = 12·(36 − 48)/(12 − 48) = 4,
/// ωH = 4/36 = 1/9 → u = 9.
#[test]
fn ext_int_24_48_24_96() {
    let (sc, t, q) = (Scheme::ExtInt, Teeth::double(24, 48, 24, 96), ModuleRatio::ONE);
    let u = willis_ratio(sc, &t);
    assert_eq!((u.num, u.den), (9, 1));
    assert!(coaxial(sc, &t, q));
    assert!(no_undercut(sc, &t, 17));
    assert!(internal_limits(sc, &t, &Limits::default()));
    assert_eq!(assembly_positions(sc, &t), 216);
    assert!(equal_spacing(sc, &t, 3));
    assert!(neighbours_clear(sc, &t, q, 2.0 * PI / 3.0, 1.0));
    assert_eq!(radial_size(sc, &t, q), 120.0);
    let eta = train_efficiency(9.0, carrier_fixed(sc, MeshEfficiency::default()), Driver::Sun);
    assert_relative_eq!(eta, 1.0 - 0.01495 * 8.0 / 9.0, max_relative = 1e-12);
    assert_relative_eq!(eta, efficiency_by_balance(9.0, 0.98505, Driver::Sun), max_relative = 1e-12);
    let p = velocity_picture(sc, &t, q, 1e-3, 1.0);
    assert_relative_eq!(p.b.v, 0.004, max_relative = 1e-12);
    assert_relative_eq!(p.ratio, 9.0, max_relative = 1e-12);
    // The search for u = 9 lists it, and the best is no larger.
    let s = synthesize(&Request::new(sc, 9.0, 3)).unwrap();
    assert!(s.candidates.iter().any(|c| c.teeth == t));
    assert!(s.best().radial_size <= 120.0);
}

/// ext-ext, z = [40, 20, 21, 39], k = 3: a carrier-driven reducer u_H1 = 14.
///
/// Willis: u_13^H = (+)(z2·z3)/(z1·z2′) = (20·39)/(40·21) = 780/840 = 13/14,
/// u_1H = 1 − 13/14 = 1/14, u_H1 = 14. Coaxiality 40 + 20 = 60 = 21 + 39.
/// Assembly |z1·z2′ − z2·z3|/gcd(20, 21) = |840 − 780|/1 = 60 = 3·20.
/// Neighbour: a_w = 30, 60·sin 60° = 51.96 > max(22, 23).
/// Radial size: max(z1, z3, 60 + 20, 60 + 21) = 81.
/// Efficiency, carrier driving, η^H = 0.99² = 0.9801, 0 < u < 1 so wheel 1
/// drives in the relative motion: η_H1 = u/(1 + η^H·(u − 1))
/// = (1/14)/(1 − 0.9801·13/14) = 0.0714286/0.0899071 = 0.79447.
#[test]
fn ext_ext_40_20_21_39() {
    let (sc, t, q) = (Scheme::ExtExt, Teeth::double(40, 20, 21, 39), ModuleRatio::ONE);
    let u = willis_ratio(sc, &t);
    assert_eq!((u.num, u.den), (1, 14));
    assert!(coaxial(sc, &t, q));
    assert!(no_undercut(sc, &t, 17));
    assert_eq!(assembly_positions(sc, &t), 60);
    assert!(neighbours_clear(sc, &t, q, 2.0 * PI / 3.0, 1.0));
    assert_eq!(radial_size(sc, &t, q), 81.0);
    let eta = train_efficiency(1.0 / 14.0, carrier_fixed(sc, MeshEfficiency::default()), Driver::Carrier);
    assert_relative_eq!(eta, 0.794_470, max_relative = 1e-5);
    assert_relative_eq!(
        eta,
        efficiency_by_balance(1.0 / 14.0, 0.9801, Driver::Carrier),
        max_relative = 1e-12
    );
    // Driven from the sun (a speed increaser ×14) wheel 3 drives in the relative
    // motion: η_1H = (1 + (u − 1)/η^H)/u = 14·(1 − (13/14)/0.9801) = 0.73606.
    let up = train_efficiency(1.0 / 14.0, 0.9801, Driver::Sun);
    assert_relative_eq!(up, 14.0 * (1.0 - (13.0 / 14.0) / 0.9801), max_relative = 1e-12);
    assert_relative_eq!(up, efficiency_by_balance(1.0 / 14.0, 0.9801, Driver::Sun), max_relative = 1e-12);
    let p = velocity_picture(sc, &t, q, 1e-3, 1.0);
    assert_relative_eq!(p.ratio, 1.0 / 14.0, max_relative = 1e-12);
    let s = synthesize(&Request::new(sc, 1.0 / 14.0, 3)).unwrap();
    assert!(s.candidates.iter().any(|c| c.teeth == t));
}

/// int-int, z = [100, 30, 28, 98], k = 2: u_H1 = −20.
///
/// Willis: u_13^H = (z2/z1)·(z3/z2′) = (30·98)/(100·28) = 2940/2800 = 21/20,
/// u_1H = 1 − 21/20 = −1/20. Coaxiality 100 − 30 = 70 = 98 − 28.
/// Rings 100, 98 ≥ 85; differences 70, 70 ≥ 8. Assembly |2800 − 2940|/gcd(30, 28)
/// = 140/2 = 70: two planets (35 each side) but not three (70/3 is not whole):
/// three planets need unequal spacing, positions 0, 23, 46 of 70, the
/// smallest gap 23·360°/70 = 118.29°; 2·35·sin 59.14° = 60.07 > 32 still clears.
/// Neighbour k = 2: 70·sin 90° = 70 > 32. Radial size max(100, 98, 70 + 30) = 100.
#[test]
fn int_int_100_30_28_98() {
    let (sc, t, q) = (Scheme::IntInt, Teeth::double(100, 30, 28, 98), ModuleRatio::ONE);
    let u = willis_ratio(sc, &t);
    assert_eq!((u.num, u.den), (-1, 20));
    assert!(coaxial(sc, &t, q));
    assert!(no_undercut(sc, &t, 17));
    assert!(internal_limits(sc, &t, &Limits::default()));
    assert_eq!(assembly_positions(sc, &t), 70);
    assert!(equal_spacing(sc, &t, 2));
    assert!(!equal_spacing(sc, &t, 3));
    assert_eq!(planet_positions(70, 3), Some(vec![0, 23, 46]));
    assert_relative_eq!(smallest_gap(70, 3), 23.0 * 2.0 * PI / 70.0, max_relative = 1e-15);
    assert!(neighbours_clear(sc, &t, q, smallest_gap(70, 3), 1.0));
    assert!(neighbours_clear(sc, &t, q, PI, 1.0));
    assert_eq!(radial_size(sc, &t, q), 100.0);
    let eta = train_efficiency(-0.05, carrier_fixed(sc, MeshEfficiency::default()), Driver::Carrier);
    assert_relative_eq!(
        eta,
        efficiency_by_balance(-0.05, 0.995 * 0.995, Driver::Carrier),
        max_relative = 1e-12
    );
    let p = velocity_picture(sc, &t, q, 1e-3, 1.0);
    assert_relative_eq!(p.ratio, -0.05, max_relative = 1e-12);
    let s = synthesize(&Request::new(sc, -0.05, 2)).unwrap();
    assert!(s.candidates.iter().any(|c| c.teeth == t));
}

/// u = 1.01 is out of reach of sun-planet-ring (u_1H = 1 + z3/z1 > 2): the
/// ratio-and-coaxiality condition fails first, and the message gives the
/// reachable range, 2 < u_1H ≤ 1 + zmax/zmin = 1 + 200/17 with the default limits.
#[test]
fn impossible_ratio() {
    match synthesize(&Request::new(Scheme::SunPlanetRing, 1.01, 3)) {
        Err(PlanetaryError::NoSolution { condition, message, .. }) => {
            assert_eq!(condition, Condition::RatioCoaxiality);
            assert!(message.contains("2 < u_1H"), "{message}");
            assert!(message.contains(&format!("{:.4}", 1.0 + 200.0 / 17.0)), "{message}");
        }
        other => panic!("{other:?}"),
    }
}

/// Ten planets of sun-planet-ring with u = 4: z2 = z1, and the neighbour
/// condition (z1 + z2)·sin 18° > z2 + 2 would need 0.618·z1 > z1 + 2 — never.
#[test]
fn ten_planets_do_not_fit() {
    match synthesize(&Request::new(Scheme::SunPlanetRing, 4.0, 10)) {
        Err(PlanetaryError::NoSolution { condition, .. }) => assert_eq!(condition, Condition::Neighbour),
        other => panic!("{other:?}"),
    }
}

/// Malformed requests name their field.
#[test]
fn invalid_fields() {
    let field = |r: Request| match synthesize(&r) {
        Err(PlanetaryError::Invalid { field, .. }) => field,
        other => panic!("{other:?}"),
    };
    assert_eq!(field(Request::new(Scheme::ExtInt, f64::NAN, 3)), "ratio");
    assert_eq!(field(Request::new(Scheme::ExtInt, 1.0, 3)), "ratio");
    assert_eq!(field(Request::new(Scheme::ExtInt, 5.0, 0)), "planets");
    assert_eq!(
        field(Request {
            tolerance: -0.1,
            ..Request::new(Scheme::ExtInt, 5.0, 3)
        }),
        "tolerance"
    );
}

/// One planet: assembly is trivial (M ≥ 1) and there is no neighbour, so
/// for u = 4 the smallest ring z3 = 3·z1 ≥ 85 gives z1 = 29: [29, 29, 87].
#[test]
fn single_planet_has_no_neighbour() {
    let s = synthesize(&Request::new(Scheme::SunPlanetRing, 4.0, 1)).unwrap();
    assert_eq!(s.best().teeth, Teeth::single(29, 29, 87));
}

/// Two sets of the same radial size reached through different module ratios
/// are ranked by their ratio error, not by the rounding of the size.
///
/// Ext-int, U = 3.434 ± 2 %, two modules. [8, 7, 10, 28] with m_II/m_I = 5/6:
/// 2a_w = 8 + 7 = 15, planet 5/6·10 = 25/3, ring 5/6·28 = 70/3, so the size is
/// max(8, 70/3, 15 + 25/3) = 70/3; u = 1 + 7·28/(8·10) = 3.45, error +0.47 %.
/// [9, 7, 11, 35] with 2/3: 2a_w = 16, planet 7, ring 70/3: size 70/3 too;
/// u = 1 + 7·35/(9·11) = 3.4747, error +1.19 %. The first must rank first.
#[test]
fn equal_sizes_are_ranked_by_ratio_error() {
    let r = Request {
        tolerance: 0.02,
        limits: Limits {
            zmin: 7,
            zmax: 35,
            ring_zmin: 12,
            min_difference: 1,
            addendum: 1.0,
        },
        two_modules: true,
        ..Request::new(Scheme::ExtInt, 3.434, 2)
    };
    let s = synthesize(&r).unwrap();
    let a = (Teeth::double(8, 7, 10, 28), ModuleRatio { num: 5, den: 6 });
    let b = (Teeth::double(9, 7, 11, 35), ModuleRatio { num: 2, den: 3 });
    let at = |x: (Teeth, ModuleRatio)| {
        s.candidates
            .iter()
            .position(|c| c.teeth == x.0 && c.modules == x.1)
            .unwrap_or_else(|| panic!("{x:?} is not among the candidates"))
    };
    let (ia, ib) = (at(a), at(b));
    assert!(ia < ib, "{ia} {ib}");
    assert_eq!(s.candidates[ia].radial_size, s.candidates[ib].radial_size);
    assert_relative_eq!(s.candidates[ia].radial_size, 70.0 / 3.0, max_relative = 1e-15);
    assert_relative_eq!(s.candidates[ia].error, 3.45 / 3.434 - 1.0, max_relative = 1e-12);
    assert_relative_eq!(s.candidates[ib].error, (1.0 + 245.0 / 99.0) / 3.434 - 1.0, max_relative = 1e-12);
    // nothing smaller exists (the property test's brute force checks this in general)
    assert!(s.candidates.iter().all(|c| c.radial_size >= 70.0 / 3.0 - 1e-12));
}
