//! Engines: the textbook's П2 (Chernaya & Timofeev 2019, a two-cylinder
//! opposed four-stroke engine over 720°) checked against its own closed-form
//! kinematics written here from the book's formulas, finite differences of
//! the positions, integrals by Simpson's rule, the kinetic energy summed
//! link by link, and the splines against their end conditions and a case
//! worked by hand.

use std::f64::consts::PI;

use tmm_geom::Vec2;
use tmm_linkage::dynamics::{DrivingMoment, Dynamics, DynamicsSpec, kinetic_energy, with_crank_motion};
use tmm_linkage::forces::{
    Curve, Indicator, Interpolation, Kinetostatics, Loads, MachineCycle, Process, SliderLoad, SliderLoadKind, TravelScale,
};
use tmm_linkage::{AssemblyHint, HintKind, InputDef, LinkDef, Mechanism, MechanismDef, SliderDef};

// --- П2 givens (GIVENS.md, П2)
const N1: f64 = 1300.0;
const BORE: f64 = 0.078;
const P_MAX: f64 = 11e5;
const M_ROD: f64 = 0.34;
const M_PISTON: f64 = 0.36;
const I_ROD: f64 = 0.002;
const G: f64 = 9.81;

fn lengths() -> (f64, f64, f64, f64) {
    let t = 60.0 / N1;
    let h = 5.0 * t / 2.0;
    let l1 = h / 2.0;
    let l2 = 3.8 * l1;
    (h, l1, l2, 0.3 * l2)
}

const H_EXP: [f64; 13] = [0.0, 0.025, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0];
const P_EXP: [f64; 13] = [0.29, 1.0, 0.9, 0.71, 0.5, 0.36, 0.29, 0.24, 0.19, 0.165, 0.135, 0.115, 0.05];
const P_COMP: [f64; 13] = [
    0.29, 0.23, 0.2, 0.157, 0.097, 0.064, 0.043, 0.029, 0.014, 0.007, 0.0, -0.004, -0.008,
];

fn pts(x: &[f64], y: &[f64]) -> Vec<(f64, f64)> {
    x.iter().copied().zip(y.iter().copied()).collect()
}

/// The four tables: intake, compression, expansion, exhaust (p/p_max by h/H).
fn tables() -> Vec<Curve> {
    vec![
        Curve::new(
            &pts(&[0.0, 0.025, 0.05, 1.0], &[0.08, 0.0, -0.008, -0.008]),
            Interpolation::Linear,
            "intake",
        )
        .unwrap(),
        Curve::new(&pts(&H_EXP, &P_COMP), Interpolation::NotAKnot, "compression").unwrap(),
        Curve::new(&pts(&H_EXP, &P_EXP), Interpolation::NotAKnot, "expansion").unwrap(),
        Curve::new(&pts(&[0.0, 0.9, 1.0], &[0.08, 0.08, 0.05]), Interpolation::Linear, "exhaust").unwrap(),
    ]
}

/// The processes of a cylinder: `order[k]` (a table index) on [kπ, (k+1)π).
fn indicator(order: [usize; 4]) -> Indicator {
    let names = ["intake", "compression", "expansion", "exhaust"];
    Indicator {
        tables: tables(),
        names: names.iter().map(|s| s.to_string()).collect(),
        travel: TravelScale::Stroke,
        pressure_scale: P_MAX,
        processes: order
            .iter()
            .enumerate()
            .map(|(k, &t)| Process {
                name: names[t].into(),
                from: k as f64 * PI,
                to: (k + 1) as f64 * PI,
                table: t,
            })
            .collect(),
    }
}

const LEFT: [usize; 4] = [0, 1, 2, 3];
const RIGHT: [usize; 4] = [2, 3, 0, 1];

fn engine() -> (Mechanism, Loads) {
    let (_, l1, l2, ls) = lengths();
    let mut crank = LinkDef::bar("1", "O", "A", l1);
    crank.points.push(("D".into(), Vec2::new(-l1, 0.0)));
    let mut rod2 = LinkDef::bar("2", "A", "B", l2);
    rod2.mass_center = Vec2::new(ls, 0.0);
    let mut rod4 = LinkDef::bar("4", "D", "F", l2);
    rod4.mass_center = Vec2::new(ls, 0.0);
    let slider = |l: &str, p: &str| SliderDef {
        slider: l.into(),
        point: p.into(),
        guide_link: "frame".into(),
        through: Vec2::ZERO,
        angle: 0.0,
        angle_on_slider: 0.0,
    };
    let hint = |p: &str, x: f64| AssemblyHint {
        point: p.into(),
        kind: HintKind::Near(Vec2::new(x, 0.0)),
    };
    let def = MechanismDef {
        fixed: vec![("O".into(), Vec2::ZERO)],
        links: vec![crank, rod2, LinkDef::block("3", "B"), rod4, LinkDef::block("5", "F")],
        sliders: vec![slider("3", "B"), slider("5", "F")],
        input: Some(InputDef {
            link: "1".into(),
            pivot: "O".into(),
            pin: "A".into(),
            omega: -N1 * PI / 30.0,
            epsilon: 0.0,
        }),
        hints: vec![hint("B", -0.3), hint("F", 0.3)],
        ..Default::default()
    };
    let m = Mechanism::new(&def).unwrap();
    let mut loads = Loads::new(&m);
    for (name, mass, inertia) in [("2", M_ROD, I_ROD), ("4", M_ROD, I_ROD), ("3", M_PISTON, 0.0), ("5", M_PISTON, 0.0)] {
        let l = m.link(name).unwrap();
        loads.links[l].mass = mass;
        loads.links[l].inertia = inertia;
    }
    loads.gravity = Vec2::new(0.0, -G);
    loads.cycle = MachineCycle { turns: 2, start: Some(PI) };
    for (name, order) in [("3", LEFT), ("5", RIGHT)] {
        loads.sliders.push(SliderLoad {
            link: m.link(name).unwrap(),
            kind: SliderLoadKind::Gas {
                bore: BORE,
                indicator: indicator(order),
            },
        });
    }
    (m, loads)
}

/// The book's kinematics in closed form at φ (φ₁ = π − φ): X_B, X_F, S₂, S₄, φ₂, φ₄.
fn book_positions(phi: f64) -> (f64, f64, Vec2, Vec2, f64, f64) {
    let (_, l1, l2, ls) = lengths();
    let p1 = PI - phi;
    let a = Vec2::new(l1 * p1.cos(), l1 * p1.sin());
    let d = -a;
    let p2 = (a.y / l2).asin(); // sin φ₂ = (Y_A − Y_B)/l_AB, cos φ₂ > 0
    let xb = a.x - l2 * p2.cos();
    let s2 = a - Vec2::new(p2.cos(), p2.sin()) * ls;
    let p4 = (-d.y / l2).asin(); // sin φ₄ = (Y_F − Y_D)/l_DF
    let xf = d.x + l2 * p4.cos();
    let s4 = d + Vec2::new(p4.cos(), p4.sin()) * ls;
    (xb, xf, s2, s4, p2, p4)
}

/// M_прДВ(φ) and I_прII(φ) by the book's formulas (GIVENS.md П2, asked 4),
/// the analogues by central differences of the closed-form positions.
fn book_reduced(phi: f64, curves: &[Curve]) -> (f64, f64) {
    let (h_stroke, ..) = lengths();
    let e = 1e-6;
    let (xb0, xf0, ..) = book_positions(0.0);
    let (xbp, xfp, s2p, s4p, p2p, p4p) = book_positions(phi + e);
    let (xbm, xfm, s2m, s4m, p2m, p4m) = book_positions(phi - e);
    let (xb, xf, ..) = book_positions(phi);
    let d = |p: f64, m: f64| (p - m) / (2.0 * e);
    let (vb, vf) = (d(xbp, xbm), d(xfp, xfm));
    let (vs2, vs4) = (
        Vec2::new(d(s2p.x, s2m.x), d(s2p.y, s2m.y)),
        Vec2::new(d(s4p.x, s4m.x), d(s4p.y, s4m.y)),
    );
    let (w2, w4) = (d(p2p, p2m), d(p4p, p4m));
    let k = ((phi / PI).floor() as usize).min(3);
    let area = PI * BORE * BORE / 4.0;
    let p3 = curves[LEFT[k]].eval((xb - xb0) / h_stroke) * P_MAX;
    let p5 = curves[RIGHT[k]].eval((xf0 - xf) / h_stroke) * P_MAX;
    let f3 = area * p3;
    let f5 = -area * p5;
    let g = -M_ROD * G;
    let moment = g * vs2.y + g * vs4.y + f3 * vb + f5 * vf;
    let inertia = I_ROD * (w2 * w2 + w4 * w4) + M_ROD * (vs2.hypot2() + vs4.hypot2()) + M_PISTON * (vb * vb + vf * vf);
    (moment, inertia)
}

/// ∫ M_прДВ over [a, b] by Simpson's rule, `n` (even) pieces.
fn simpson(a: f64, b: f64, n: usize, f: impl Fn(f64) -> f64) -> f64 {
    let h = (b - a) / n as f64;
    let mut s = f(a) + f(b);
    for i in 1..n {
        s += f(a + h * i as f64) * if i % 2 == 1 { 4.0 } else { 2.0 };
    }
    s * h / 3.0
}

/// Work of the loads from 0 to φ, piecewise over the processes' half-turns.
fn book_work(phi: f64, curves: &[Curve]) -> f64 {
    let mut a = 0.0;
    let mut lo = 0.0;
    while lo < phi - 1e-15 {
        let hi = ((lo / PI).floor() + 1.0) * PI;
        let hi = hi.min(phi);
        a += simpson(lo, hi, 4000, |x| book_reduced(x.clamp(lo + 1e-9, hi - 1e-9), curves).0);
        lo = hi;
    }
    a
}

#[test]
fn spline_end_conditions_and_a_hand_case() {
    // natural spline through (0,0), (1,1), (2,0), worked by hand: the one
    // interior equation 1·M₀ + 2·(1 + 1)·M₁ + 1·M₂ = 6·((0 − 1) − (1 − 0))
    // with M₀ = M₂ = 0 gives M₁ = −3; at x = 0.5 (t = u = 0.5, h = 1)
    // S = (M₀u³ + M₁t³)/6 + (y₀ − M₀/6)·u + (y₁ − M₁/6)·t
    //   = −3·0.125/6 + 0 + 1.5·0.5 = 0.6875.
    let c = Curve::new(&[(0.0, 0.0), (1.0, 1.0), (2.0, 0.0)], Interpolation::Natural, "t").unwrap();
    assert!((c.eval(0.5) - 0.6875).abs() < 1e-14, "{}", c.eval(0.5));
    assert!((c.node_second_derivative(1) + 3.0).abs() < 1e-14);
    // the same three points not-a-knot: the parabola y = x·(2 − x)
    let p = Curve::new(&[(0.0, 0.0), (1.0, 1.0), (2.0, 0.0)], Interpolation::NotAKnot, "t").unwrap();
    assert!((p.eval(0.5) - 0.75).abs() < 1e-14);
    // П2's expansion table: natural ends S″ = 0, not-a-knot ends S‴ equal on
    // both sides of the second and the last-but-one node (by differences of
    // S″ measured with the spline's own values, four points a side)
    let pts = pts(&H_EXP, &P_EXP);
    let nat = Curve::new(&pts, Interpolation::Natural, "t").unwrap();
    let nak = Curve::new(&pts, Interpolation::NotAKnot, "t").unwrap();
    let e = 1e-4;
    let d2 = |c: &Curve, x: f64| (c.eval(x + e) - 2.0 * c.eval(x) + c.eval(x - e)) / (e * e);
    // S″ is linear on an end interval: extrapolated to the end from two
    // inner points it must vanish (against the largest S″ on the table)
    let end2 = |c: &Curve, x1: f64, x2: f64, x0: f64| {
        let (a1, a2) = (d2(c, x1), d2(c, x2));
        a1 + (x0 - x1) * (a2 - a1) / (x2 - x1)
    };
    let big = (1..400).map(|i| d2(&nat, i as f64 / 400.0).abs()).fold(0.0, f64::max);
    assert!(
        end2(&nat, 0.005, 0.01, 0.0).abs() < 1e-5 * big,
        "{} of {big}",
        end2(&nat, 0.005, 0.01, 0.0)
    );
    assert!(
        end2(&nat, 0.99, 0.95, 1.0).abs() < 1e-5 * big,
        "{} of {big}",
        end2(&nat, 0.99, 0.95, 1.0)
    );
    // the not-a-knot spline's S″ does not vanish at the ends here
    assert!(end2(&nak, 0.005, 0.01, 0.0).abs() > 1e-2 * big);
    for (a, b, c) in [(0.0, 0.025, 0.05), (0.8, 0.9, 1.0)] {
        // S‴ on each side from S″ at two inner points of each interval
        let third = |x0: f64, x1: f64| {
            let (p, q) = (x0 + 0.25 * (x1 - x0), x0 + 0.75 * (x1 - x0));
            (d2(&nak, q) - d2(&nak, p)) / (q - p)
        };
        let (l, r) = (third(a, b), third(b, c));
        assert!((l - r).abs() < 1e-3 * l.abs().max(r.abs()), "S‴ jumps at {b}: {l} vs {r}");
        let (ln, rn) = {
            let third_n = |x0: f64, x1: f64| {
                let (p, q) = (x0 + 0.25 * (x1 - x0), x0 + 0.75 * (x1 - x0));
                (d2(&nat, q) - d2(&nat, p)) / (q - p)
            };
            (third_n(a, b), third_n(b, c))
        };
        // the natural spline's S‴ does jump there: the test tells them apart
        assert!((ln - rn).abs() > 1e-2 * ln.abs().max(rn.abs()), "{ln} {rn}");
    }
    // every spline goes through its nodes
    for &(x, y) in &pts {
        assert!((nak.eval(x) - y).abs() < 1e-14 && (nat.eval(x) - y).abs() < 1e-14);
    }
}

#[test]
fn reduction_matches_the_book_formulas_by_finite_differences() {
    let (m, loads) = engine();
    let spec = DynamicsSpec::new(1.0 / 18.0);
    let red = tmm_linkage::dynamics::Reducer::new(&m, &loads, spec.working).unwrap();
    assert!((red.period - 4.0 * PI).abs() < 1e-15);
    let mut sol = red.solution();
    let curves = tables();
    let mut worst = (0.0f64, 0.0f64);
    let mut scale = (0.0f64, 0.0f64);
    for i in 0..720 {
        let phi = (i as f64 + 0.37) * PI / 180.0;
        let r = red.eval(phi, &mut sol).unwrap();
        let (mb, ib) = book_reduced(phi, &curves);
        worst = (worst.0.max((r.moment - mb).abs()), worst.1.max((r.inertia - ib).abs()));
        scale = (scale.0.max(mb.abs()), scale.1.max(ib.abs()));
    }
    assert!(worst.0 < 1e-6 * scale.0, "M: {worst:?} of {scale:?}");
    assert!(worst.1 < 1e-6 * scale.1, "I: {worst:?} of {scale:?}");
}

fn p2_dynamics() -> (Mechanism, Loads, Dynamics) {
    let (m, loads) = engine();
    let mut spec = DynamicsSpec::new(1.0 / 18.0);
    spec.driving = DrivingMoment::Engine;
    spec.inertia_crank_shaft = 0.1;
    spec.points = 2880;
    let d = Dynamics::compute(&m, &loads, &spec).unwrap();
    (m, loads, d)
}

#[test]
fn constant_resistance_gives_zero_work_over_720_degrees() {
    let (_, _, d) = p2_dynamics();
    let curves = tables();
    let a = book_work(4.0 * PI, &curves);
    let mc = -a / (4.0 * PI);
    let got = d.cycle.driving_moment;
    assert!(mc < 0.0 && got < 0.0, "an engine's constant moment resists: {mc} {got}");
    assert!((got - mc).abs() < 1e-6 * mc.abs(), "M_прC = {got} vs {mc} by Simpson");
    // the cycle's own work closes
    let n = d.cycle.len();
    assert!((d.cycle.work_loads[n] + got * 4.0 * PI).abs() < 1e-9 * a.abs());
    // the summed loads of the symmetric engine are 2π-periodic (the book's remark)
    let half = book_work(2.0 * PI, &curves);
    assert!((half - 0.5 * a).abs() < 1e-6 * a.abs(), "{half} vs {a}/2");
    eprintln!("P2: M_C = {got:.6} N·m, A_loads(4π) = {a:.6} J");
}

#[test]
fn energy_balance_and_balancing_moment_over_the_cycle() {
    let (m, loads, d) = p2_dynamics();
    let curves = tables();
    let mc = d.cycle.driving_moment;
    let ii = d.motion.inertia_constant;
    let n = d.cycle.len();
    let dir = -1.0;
    let mut loads_k = loads.clone();
    let c = m.crank.link;
    let t_of = |k: usize| -> f64 {
        let w = d.motion.omega[k];
        let mm = with_crank_motion(&m, dir * w, dir * d.motion.epsilon[k]).unwrap();
        let mut s = mm.solution();
        mm.solve(PI + dir * d.cycle.phi[k], &mut s).unwrap();
        kinetic_energy(&mm, &loads, &s) + 0.5 * ii * w * w
    };
    let t0 = t_of(0);
    for k in (0..=n).step_by(n / 24) {
        let phi = d.cycle.phi[k];
        let a = mc * phi + book_work(phi, &curves);
        let t = t_of(k);
        assert!(
            (t - t0 - a).abs() < 2e-6 * t0,
            "φ = {:.1}°: T − T₀ = {} vs A = {a}",
            phi.to_degrees(),
            t - t0
        );
    }
    // kinetostatics with the true motion, the whole constant inertia lumped
    // on the crank: the balancing moment is the constant resistance
    loads_k.links[c].inertia = ii;
    for k in (0..=n).step_by(n / 12) {
        let (w, e) = (d.motion.omega[k], d.motion.epsilon[k]);
        let mm = with_crank_motion(&m, dir * w, dir * e).unwrap();
        let mut ks = Kinetostatics::new(&mm, loads_k.clone()).unwrap();
        let mut s = mm.solution();
        let mut f = ks.result();
        ks.solve_at_cycle(d.cycle.phi[k].min(4.0 * PI - 1e-12), &mut s, &mut f).unwrap();
        assert!(
            (f.balancing_moment - dir * mc).abs() < 1e-5 * mc.abs(),
            "φ = {:.0}°: M_b = {} vs {}",
            d.cycle.phi[k].to_degrees(),
            f.balancing_moment,
            dir * mc
        );
    }
}

#[test]
fn p2_values() {
    let (h, l1, l2, ls) = lengths();
    let (_, _, d) = p2_dynamics();
    eprintln!(
        "P2: T = {:.6} s, H = {h:.6} m, l_OA = {l1:.6} m, l_AB = {l2:.6} m, l_AS2 = {ls:.6} m",
        60.0 / N1
    );
    eprintln!(
        "P2: M_C = {:.6} N·m; I_I Mertsalov = {:.6}, Wittenbauer = {:.6}, exact = {:.6} kg·m²; flywheel {:.6} kg·m²",
        d.cycle.driving_moment, d.required.mertsalov, d.required.wittenbauer, d.required.exact, d.flywheel_inertia
    );
    eprintln!(
        "P2: ω(0) = {:.6} rad/s, ω_max at {:.3}°, ω_min at {:.3}°; ε(60°) = {:.6} rad/s²",
        d.motion.omega[0],
        d.exact.phi_max.to_degrees(),
        d.exact.phi_min.to_degrees(),
        d.motion.epsilon[d.cycle.len() / 12]
    );
    // the time integration reproduces δ
    assert!((d.simulated.delta - 1.0 / 18.0).abs() < 1e-4, "{}", d.simulated.delta);
}
