//! The seed-001 four-bar against closed forms derived here, independently of
//! the solver: the Freudenstein position solution (Norton, *Design of
//! Machinery*, eq. 4.10), and velocities and accelerations from the complex
//! loop equation `a·e^{iθ2} + b·e^{iθ3} − c·e^{iθ4} − d = 0` differentiated once
//! and twice and solved by Cramer's rule. Also the seed's graphical values
//! (within 3 %) and the dead positions (crank and coupler collinear).

use std::f64::consts::PI;

use tmm_geom::Vec2;
use tmm_linkage::cycle::{Cycle, Working};
use tmm_linkage::{AssemblyHint, HintKind, InputDef, LinkDef, Mechanism, MechanismDef};

const A: f64 = 0.12;
const B: f64 = 0.48;
const C: f64 = 0.38;
const D: f64 = 0.51;

fn fourbar(above: bool, omega: f64) -> Mechanism {
    let def = MechanismDef {
        fixed: vec![("A".into(), Vec2::new(0.0, 0.0)), ("D".into(), Vec2::new(D, 0.0))],
        links: vec![
            LinkDef::bar("1", "A", "B", A),
            LinkDef::bar("2", "B", "C", B),
            LinkDef::bar("3", "D", "C", C),
        ],
        input: Some(InputDef {
            link: "1".into(),
            pivot: "A".into(),
            pin: "B".into(),
            omega,
            epsilon: 0.0,
        }),
        hints: vec![AssemblyHint {
            point: "C".into(),
            kind: if above {
                HintKind::Above("A".into(), "D".into())
            } else {
                HintKind::Below("A".into(), "D".into())
            },
        }],
        ..Default::default()
    };
    Mechanism::new(&def).unwrap()
}

/// Closed form: (θ3, θ4, ω3, ω4, α3, α4) for crank angle θ2, ω2, α2 = 0.
/// `open`: the sign of the square root in Freudenstein's solution.
fn closed(t2: f64, w2: f64, sign: f64) -> (f64, f64, f64, f64, f64, f64) {
    let (a, b, c, d) = (A, B, C, D);
    // Norton eq. 4.10a–c: K1 = d/a, K2 = d/c, K3 = (a² − b² + c² + d²)/(2ac)
    let k1 = d / a;
    let k2 = d / c;
    let k3 = (a * a - b * b + c * c + d * d) / (2.0 * a * c);
    let aa = t2.cos() - k1 - k2 * t2.cos() + k3;
    let bb = -2.0 * t2.sin();
    let cc = k1 - (k2 + 1.0) * t2.cos() + k3;
    let t4 = 2.0 * ((-bb + sign * (bb * bb - 4.0 * aa * cc).sqrt()) / (2.0 * aa)).atan();
    // θ3 from the loop: b·e^{iθ3} = d + c·e^{iθ4} − a·e^{iθ2}
    let x = d + c * t4.cos() - a * t2.cos();
    let y = c * t4.sin() - a * t2.sin();
    let t3 = y.atan2(x);
    // velocities: a ω2 i e^{iθ2} + b ω3 i e^{iθ3} − c ω4 i e^{iθ4} = 0
    // real: −a ω2 sinθ2 − b ω3 sinθ3 + c ω4 sinθ4 = 0
    // imag:  a ω2 cosθ2 + b ω3 cosθ3 − c ω4 cosθ4 = 0
    let m = [[-b * t3.sin(), c * t4.sin()], [b * t3.cos(), -c * t4.cos()]];
    let r = [a * w2 * t2.sin(), -a * w2 * t2.cos()];
    let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    let w3 = (r[0] * m[1][1] - m[0][1] * r[1]) / det;
    let w4 = (m[0][0] * r[1] - r[0] * m[1][0]) / det;
    // accelerations: a(−ω2²)e^{iθ2} + b(iα3 − ω3²)e^{iθ3} − c(iα4 − ω4²)e^{iθ4} = 0
    // real: −a ω2² cosθ2 − b α3 sinθ3 − b ω3² cosθ3 + c α4 sinθ4 + c ω4² cosθ4 = 0
    // imag: −a ω2² sinθ2 + b α3 cosθ3 − b ω3² sinθ3 − c α4 cosθ4 + c ω4² sinθ4 = 0
    let ra = [
        a * w2 * w2 * t2.cos() + b * w3 * w3 * t3.cos() - c * w4 * w4 * t4.cos(),
        a * w2 * w2 * t2.sin() + b * w3 * w3 * t3.sin() - c * w4 * w4 * t4.sin(),
    ];
    let a3 = (ra[0] * m[1][1] - m[0][1] * ra[1]) / det;
    let a4 = (m[0][0] * ra[1] - ra[0] * m[1][0]) / det;
    (t3, t4, w3, w4, a3, a4)
}

fn wrap(a: f64) -> f64 {
    tmm_geom::angle::wrap_pi(a)
}

#[test]
fn matches_closed_form_on_both_branches() {
    let w2 = 900.0 * PI / 30.0;
    for (above, sign) in [(true, -1.0), (false, 1.0)] {
        let m = fourbar(above, w2);
        let mut sol = m.solution();
        for k in 0..72 {
            let t2 = k as f64 * 5f64.to_radians() + 0.01;
            m.solve(t2, &mut sol).unwrap();
            let (t3, t4, w3, w4, a3, a4) = closed(t2, w2, sign);
            let l2 = &sol.links[2];
            let l3 = &sol.links[3];
            assert!(wrap(l2.angle() - t3).abs() < 1e-9, "θ3 at {t2}: {} vs {t3}", l2.angle());
            assert!(wrap(l3.angle() - t4).abs() < 1e-9, "θ4 at {t2}: {} vs {t4}", l3.angle());
            assert!((l2.omega - w3).abs() < 1e-9 * w2, "ω3 {} vs {w3}", l2.omega);
            assert!((l3.omega - w4).abs() < 1e-9 * w2, "ω4 {} vs {w4}", l3.omega);
            assert!((l2.eps - a3).abs() < 1e-9 * w2 * w2, "α3 {} vs {a3}", l2.eps);
            assert!((l3.eps - a4).abs() < 1e-9 * w2 * w2, "α4 {} vs {a4}", l3.eps);
        }
    }
}

#[test]
fn seed_001_graphical_values_within_3_percent() {
    // Seed 001, sheet 3: V_C = 13.23 m/s, ω2 = 24.61, ω3 = 34.82 rad/s,
    // ε2 = 2221, ε3 = 1262 rad/s² at φ ≈ 15° with C below AD.
    let w2 = 900.0 * PI / 30.0;
    let m = fourbar(false, w2);
    let mut sol = m.solution();
    m.solve(15f64.to_radians(), &mut sol).unwrap();
    let c = sol.points[m.point("C").unwrap()];
    let rel = |x: f64, seed: f64| (x.abs() - seed).abs() / seed;
    assert!(rel(c.v.hypot(), 13.23) < 0.03, "V_C = {}", c.v.hypot());
    assert!(rel(sol.links[2].omega, 24.61) < 0.03, "ω2 = {}", sol.links[2].omega);
    assert!(rel(sol.links[3].omega, 34.82) < 0.03, "ω3 = {}", sol.links[3].omega);
    assert!(rel(sol.links[2].eps, 2221.0) < 0.03, "ε2 = {}", sol.links[2].eps);
    assert!(rel(sol.links[3].eps, 1262.0) < 0.03, "ε3 = {}", sol.links[3].eps);
    // and exactly the closed form
    let (_, _, w3, w4, a3, a4) = closed(15f64.to_radians(), w2, 1.0);
    assert!((sol.links[2].omega - w3).abs() < 1e-9 && (sol.links[3].omega - w4).abs() < 1e-9);
    assert!((sol.links[2].eps - a3).abs() < 1e-7 && (sol.links[3].eps - a4).abs() < 1e-7);
    // V_C = ω4 · c
    assert!((c.v.hypot() - (w4 * C).abs()).abs() < 1e-9);
}

#[test]
fn dead_positions_where_crank_and_coupler_are_collinear() {
    // Extreme positions of the rocker: |AC| = b + a (extended) or b − a
    // (folded). C lies on the circle about D of radius c; by the law of
    // cosines at A: cos∠CAD = (AC² + d² − c²)/(2·AC·d); C below AD.
    let m = fourbar(false, 10.0);
    let c = Cycle::new(&m, Working::Slower).unwrap();
    let ang = |ac: f64| -((ac * ac + D * D - C * C) / (2.0 * ac * D)).acos();
    let ext = tmm_geom::angle::wrap_2pi(ang(B + A));
    let fold = tmm_geom::angle::wrap_2pi(ang(B - A) + PI);
    let mut got = c.dead.clone();
    got.sort_by(f64::total_cmp);
    let mut want = [ext, fold];
    want.sort_by(f64::total_cmp);
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() < 1e-9, "dead position {g} vs {w}");
    }
    // θ = the angle between the two crank positions minus 180°; Kv = (180 + θ)/(180 − θ)
    let theta = (c.working_angle - PI).abs();
    assert!((c.kv - (PI + theta) / (PI - theta)).abs() < 1e-12);
    // the rocker swing equals the angle CDC' between the two extreme positions
    let cpos = |ac: f64, a: f64| Vec2::new(ac * a.cos(), ac * a.sin());
    let c1 = cpos(B + A, ang(B + A));
    let c2 = cpos(B - A, ang(B - A));
    let dvec = Vec2::new(D, 0.0);
    let swing = ((c1 - dvec).atan2() - (c2 - dvec).atan2()).abs();
    assert!((c.stroke - swing).abs() < 1e-9, "{} vs {swing}", c.stroke);
}
