//! Motion laws against their closed forms, boundary conditions, peak
//! coefficients (Norton, Design of Machinery, ch. 8, table of peak factors, and closed forms
//! derived here) and finite differences.

use std::f64::consts::PI;
use tmm_cams::law::{Law, LawKind};
use tmm_cams::program::Program;
use tmm_cams::spec;

fn all() -> Vec<LawKind> {
    vec![
        LawKind::ConstAccel { u: 1.0 / 3.0 },
        LawKind::ConstAccel { u: 0.5 },
        LawKind::Cosine,
        LawKind::Sine,
        LawKind::LinearDecreasing,
        LawKind::Trapezoid,
        LawKind::ModTrapezoid,
        LawKind::ModSine,
        LawKind::Poly345,
        LawKind::Poly4567,
        LawKind::Table(vec![0.0, 2.0, 3.0, 1.0, -1.0, -2.5, -2.0, -0.5, 0.0]),
    ]
}

/// Peak |y′| and |y″| on a fine grid.
fn peaks(l: &Law) -> (f64, f64, f64) {
    let n = 200_000;
    let (mut v, mut a, mut j) = (0.0f64, 0.0f64, 0.0f64);
    for i in 0..=n {
        let [_, y1, y2, y3] = l.eval(i as f64 / n as f64);
        v = v.max(y1.abs());
        a = a.max(y2.abs());
        j = j.max(y3.abs());
    }
    (v, a, j)
}

#[test]
fn every_law_rises_from_rest_to_rest() {
    for k in all() {
        let l = Law::new(k.clone()).unwrap();
        let [y0, v0, ..] = l.eval(0.0);
        let [y1, v1, ..] = l.eval(1.0);
        assert!(y0.abs() < 1e-14, "{k}: y(0) = {y0}");
        assert!((y1 - 1.0).abs() < 1e-12, "{k}: y(1) = {y1}");
        assert!(v0.abs() < 1e-12 && v1.abs() < 1e-12, "{k}: y′ at the ends {v0} {v1}");
        // monotonic rise
        let mut prev = 0.0;
        for i in 1..=1000 {
            let y = l.eval(i as f64 / 1000.0)[0];
            assert!(y >= prev - 1e-13, "{k}: not monotonic at {i}");
            prev = y;
        }
    }
}

#[test]
fn derivatives_match_finite_differences() {
    let h = 1e-5;
    for k in all() {
        let l = Law::new(k.clone()).unwrap();
        let pieces = l.breaks();
        for i in 1..200 {
            let x = i as f64 / 200.0 + 0.00123;
            if x + h >= 1.0 || pieces.iter().any(|b| (x - b).abs() < 3.0 * h) {
                continue;
            }
            let e = |x: f64| l.eval(x);
            let fd = |c: usize| (e(x + h)[c] - e(x - h)[c]) / (2.0 * h);
            let [_, y1, y2, y3] = e(x);
            let sc = |v: f64| 1.0 + v.abs();
            assert!((fd(0) - y1).abs() < 1e-7 * sc(y1), "{k} y′ at {x}: {} vs {y1}", fd(0));
            assert!((fd(1) - y2).abs() < 1e-6 * sc(y2), "{k} y″ at {x}: {} vs {y2}", fd(1));
            assert!((fd(2) - y3).abs() < 1e-5 * sc(y3), "{k} y‴ at {x}: {} vs {y3}", fd(2));
        }
    }
}

#[test]
fn continuity_at_the_ends_is_as_documented() {
    for k in all() {
        let l = Law::new(k.clone()).unwrap();
        let [_, _, a0, j0] = l.eval(0.0);
        let [_, _, a1, j1] = l.eval(1.0);
        match l.continuity() {
            1 => assert!(a0.abs() > 1e-3 || a1.abs() > 1e-3, "{k}: a C1 law should have an acceleration jump"),
            2 => {
                assert!(a0.abs() < 1e-10 && a1.abs() < 1e-10, "{k}: y″ at the ends {a0} {a1}");
                assert!(j0.abs() > 1e-3, "{k}: a C2 law has a jerk jump");
            }
            3 => {
                assert!(a0.abs() < 1e-10 && a1.abs() < 1e-10 && j0.abs() < 1e-9 && j1.abs() < 1e-9, "{k}");
            }
            c => panic!("{k}: continuity {c}"),
        }
    }
}

#[test]
fn cycloidal_peaks_are_2_and_2pi() {
    // s = h(x − sin 2πx / 2π): ds/dφ max = 2h/β, d²s/dφ² max = 2πh/β²
    let h = 0.013;
    let beta = 108f64.to_radians();
    let p = Program::new(h, spec::parse_phases("rise 108 sine; dwell 72; return 108 sine; dwell 72").unwrap()).unwrap();
    let (mut v, mut a) = (0.0f64, 0.0f64);
    for i in 0..=100_000 {
        let m = p.eval_in(0, beta * i as f64 / 100_000.0);
        v = v.max(m.v);
        a = a.max(m.a);
    }
    assert!((v - 2.0 * h / beta).abs() < 1e-12);
    assert!((a - 2.0 * PI * h / (beta * beta)).abs() < 1e-9);
    assert!((p.eval_in(0, beta).s - h).abs() < 1e-15);
}

#[test]
fn peak_coefficients_match_closed_forms_and_nortons_table() {
    // closed forms derived here (docs/cams.md §2) and Norton's table of peak factors (3 decimals)
    let cases: Vec<(LawKind, f64, f64)> = vec![
        // constant acceleration u: y′max = 2 (at x = u), y″ = 2/u then −2/(1−u)
        (LawKind::ConstAccel { u: 0.5 }, 2.0, 4.0),
        (LawKind::ConstAccel { u: 1.0 / 3.0 }, 2.0, 6.0),
        // harmonic: π/2 and π²/2
        (LawKind::Cosine, PI / 2.0, PI * PI / 2.0),
        (LawKind::Sine, 2.0, 2.0 * PI),
        // 3-4-5: y′(1/2) = 15/8; y″ max at x = 1/2 − √3/6: 10/√3
        (LawKind::Poly345, 15.0 / 8.0, 10.0 / 3f64.sqrt()),
        // linearly decreasing (cubic 3x² − 2x³): y′max 3/2 at 1/2, y″ = 6 at the ends
        (LawKind::LinearDecreasing, 1.5, 6.0),
        // 4-5-6-7: y′(1/2) = 35/16
        (LawKind::Poly4567, 35.0 / 16.0, f64::NAN),
        // trapezoid with 1/8 ramps: y(1/2) = 3/32 per unit amplitude, so Ca = 16/3
        // (derived here, docs/cams.md §2)
        (LawKind::Trapezoid, 2.0, 16.0 / 3.0),
    ];
    for (k, cv, ca) in cases {
        let (v, a, _) = peaks(&Law::new(k.clone()).unwrap());
        // a 5·10⁻⁶ grid misses a kinked peak by at most slope × step
        assert!((v - cv).abs() < 5e-5, "{k}: Cv {v} vs {cv}");
        if ca.is_finite() {
            assert!((a - ca).abs() < 5e-5 * ca, "{k}: Ca {a} vs {ca}");
        }
    }
    // Norton's table of peak factors, to three decimals
    for (k, cv, ca) in [
        (LawKind::ModTrapezoid, 2.000, 4.888),
        (LawKind::ModSine, 1.760, 5.528),
        (LawKind::Poly4567, 2.188, 7.513),
    ] {
        let (v, a, _) = peaks(&Law::new(k.clone()).unwrap());
        assert!((v - cv).abs() < 1.5e-3, "{k}: Cv {v} vs {cv}");
        assert!((a - ca).abs() < 1.5e-3, "{k}: Ca {a} vs {ca}");
    }
}

#[test]
fn poly4567_peak_acceleration_from_its_jerk_root() {
    // y‴ = 840x(1 − 6x + 10x² − 5x³) = 0 → the peak of y″ is at the root in (0, 1/2)
    let g = |x: f64| 1.0 - 6.0 * x + 10.0 * x * x - 5.0 * x * x * x;
    let (mut lo, mut hi) = (0.0, 0.5);
    for _ in 0..200 {
        let m = 0.5 * (lo + hi);
        if g(lo) * g(m) <= 0.0 { hi = m } else { lo = m }
    }
    let x = 0.5 * (lo + hi);
    let ypp = 420.0 * x.powi(2) - 1680.0 * x.powi(3) + 2100.0 * x.powi(4) - 840.0 * x.powi(5);
    let (_, a, _) = peaks(&Law::new(LawKind::Poly4567).unwrap());
    assert!((a - ypp).abs() < 1e-6, "{a} vs {ypp}");
}

#[test]
fn const_accel_has_the_seed_amplitude_ratio() {
    // seed 001: A2/A1 = u/(1 − u) for u = 1/3 (A1 = 110 → A2 = 55)
    let l = Law::new(LawKind::ConstAccel { u: 1.0 / 3.0 }).unwrap();
    let a1 = l.eval(0.1)[2];
    let a2 = l.eval(0.9)[2];
    assert!(a1 > 0.0 && a2 < 0.0);
    assert!((-a2 / a1 - 0.5).abs() < 1e-12);
    // the switch is at x = u
    assert!(l.eval(1.0 / 3.0 - 1e-9)[2] > 0.0 && l.eval(1.0 / 3.0 + 1e-9)[2] < 0.0);
}

#[test]
fn tables_reproduce_the_piecewise_linear_laws() {
    let pairs = [
        (LawKind::Table(vec![1.0, 0.0, -1.0]), LawKind::LinearDecreasing),
        (
            LawKind::Table(vec![0.0, 1.0, 1.0, 1.0, 0.0, -1.0, -1.0, -1.0, 0.0]),
            LawKind::Trapezoid,
        ),
    ];
    for (t, k) in pairs {
        let (a, b) = (Law::new(t).unwrap(), Law::new(k.clone()).unwrap());
        for i in 0..=100 {
            let x = i as f64 / 100.0;
            let (p, q) = (a.eval(x), b.eval(x));
            for c in 0..3 {
                assert!((p[c] - q[c]).abs() < 1e-12 * (1.0 + q[c].abs()), "{k} at {x}: {p:?} vs {q:?}");
            }
        }
    }
}

#[test]
fn unbalanced_table_is_refused() {
    assert!(Law::new(LawKind::Table(vec![1.0, 1.0, -0.5])).is_err());
    assert!(Law::new(LawKind::Table(vec![1.0])).is_err());
}

#[test]
fn program_is_continuous_at_the_phase_joints() {
    let text = "rise 100 LAW; dwell 20; return 110 LAW; dwell 130";
    for k in all() {
        let name = match &k {
            LawKind::ConstAccel { u } => format!("const-accel(u={u})"),
            LawKind::Table(v) => format!("table({})", v.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(", ")),
            k => k.name().to_string(),
        };
        let law = Law::new(k.clone()).unwrap();
        let p = Program::new(0.02, spec::parse_phases(&text.replace("LAW", &name)).unwrap()).unwrap();
        // s(end of the rise) = h, s(end of the return) = 0
        assert!((p.eval_in(0, p.phases()[0].angle).s - 0.02).abs() < 1e-14, "{k}");
        assert!(p.eval_in(2, p.phases()[2].angle).s.abs() < 1e-14, "{k}");
        for j in 0..p.phases().len() {
            let next = (j + 1) % p.phases().len();
            let end = p.eval_in(j, p.phases()[j].angle);
            let start = p.eval_in(next, 0.0);
            assert!((end.s - start.s).abs() < 1e-14, "{k}: s jumps at joint {j}");
            assert!((end.v - start.v).abs() < 1e-12, "{k}: v jumps at joint {j}");
            if law.continuity() >= 2 {
                assert!((end.a - start.a).abs() < 1e-9, "{k}: a jumps at joint {j}");
            }
        }
    }
}
