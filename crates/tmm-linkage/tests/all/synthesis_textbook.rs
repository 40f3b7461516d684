//! The BMSTU textbook's synthesis examples (Chernaya & Timofeev 2019,
//! appendix П1; givens in GIVENS.md): each closed form against a numerical
//! solve of the book's own equations — Newton's method from the book's first
//! guesses, written here — and each synthesised mechanism analysed back by
//! the linkage core (the rocker's extreme angles, the three positions, the
//! cylinder's stroke and pressure angles).

use std::f64::consts::{FRAC_PI_2, PI};

use tmm_geom::Vec2;
use tmm_geom::angle::wrap_pi;
use tmm_linkage::Mechanism;
use tmm_linkage::synthesis::crank_slider::{self, TwoPositionsRequest};
use tmm_linkage::synthesis::cylinder::{self, CylinderRequest, PressureAt};
use tmm_linkage::synthesis::rocker_extremes::{self, Abscissa, ExtremesRequest};
use tmm_linkage::synthesis::three_positions::{self, ThreePositionsRequest};
use tmm_linkage::synthesis::{Drive, Stroke, Synthesis, SynthesisError};

fn rad(d: f64) -> f64 {
    d.to_radians()
}

fn angle(s: &Synthesis, name: &str) -> f64 {
    s.angles.iter().find(|(n, _)| n == name).unwrap().1
}

fn coord(s: &Synthesis, name: &str) -> f64 {
    s.coordinates.iter().find(|(n, _)| n == name).unwrap().1
}

/// Newton's method with a central-difference Jacobian and Gaussian
/// elimination with partial pivoting: the book's `Find` from its guesses.
fn newton(f: impl Fn(&[f64]) -> Vec<f64>, mut x: Vec<f64>) -> Vec<f64> {
    let n = x.len();
    for _ in 0..60 {
        let r = f(&x);
        if r.iter().all(|v| v.abs() < 1e-14) {
            break;
        }
        let mut a = vec![vec![0.0; n + 1]; n];
        for j in 0..n {
            let h = 1e-7 * x[j].abs().max(1.0);
            let (mut xp, mut xm) = (x.clone(), x.clone());
            xp[j] += h;
            xm[j] -= h;
            let (fp, fm) = (f(&xp), f(&xm));
            for i in 0..n {
                a[i][j] = (fp[i] - fm[i]) / (2.0 * h);
            }
        }
        for i in 0..n {
            a[i][n] = -r[i];
        }
        for c in 0..n {
            let p = (c..n).max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs())).unwrap();
            a.swap(c, p);
            let (top, rest) = a.split_at_mut(c + 1);
            let pivot = &top[c];
            for row in rest.iter_mut() {
                let m = row[c] / pivot[c];
                for (x, p) in row[c..].iter_mut().zip(&pivot[c..]) {
                    *x -= m * p;
                }
            }
        }
        let mut dx = vec![0.0; n];
        for i in (0..n).rev() {
            let s: f64 = (i + 1..n).map(|k| a[i][k] * dx[k]).sum();
            dx[i] = (a[i][n] - s) / a[i][i];
        }
        for i in 0..n {
            x[i] += dx[i];
        }
    }
    let r = f(&x);
    assert!(r.iter().all(|v| v.abs() < 1e-12), "Newton did not converge: {r:?}");
    x
}

/// Angle of the rocker D→C at every dead position the core found.
fn rocker_at_dead(s: &Synthesis) -> Vec<f64> {
    s.check
        .dead_positions
        .iter()
        .map(|pos| {
            let p = |n: &str| pos.iter().find(|(m, _)| m == n).unwrap().1;
            (p("C") - p("D")).atan2()
        })
        .collect()
}

fn same_angles(mut got: Vec<f64>, mut want: Vec<f64>, tol: f64) {
    let key = |a: &f64| wrap_pi(*a);
    got.sort_by(|a, b| key(a).total_cmp(&key(b)));
    want.sort_by(|a, b| key(a).total_cmp(&key(b)));
    for (g, w) in got.iter().zip(&want) {
        assert!(wrap_pi(g - w).abs() < tol, "{got:?} vs {want:?}");
    }
}

#[test]
fn p1_1_crank_slider_by_two_positions_against_the_books_system() {
    let (lam, le, p0, p1, hc) = (2.5, 0.4, rad(60.0), rad(150.0), 0.15);
    let s = crank_slider::by_two_positions(&TwoPositionsRequest {
        lambda: lam,
        lambda_e: le,
        phi_start: p0,
        phi_end: p1,
        travel: hc,
        drive: Drive::default(),
        limits: Default::default(),
    })
    .unwrap();
    // system (1.4): unknowns l1, φ2н, φ2к, X_Cн; guesses 0.2, 0, 0, 0.7
    let x = newton(
        |v| {
            let (l1, a, b, xc) = (v[0], v[1], v[2], v[3]);
            vec![
                l1 * p0.cos() + lam * l1 * a.cos() - xc,
                l1 * p0.sin() + lam * l1 * a.sin() - le * l1,
                l1 * p1.cos() + lam * l1 * b.cos() - (xc - hc),
                l1 * p1.sin() + lam * l1 * b.sin() - le * l1,
            ]
        },
        vec![0.2, 0.0, 0.0, 0.7],
    );
    assert!((s.length("OA").unwrap() - x[0]).abs() < 1e-10);
    assert!(wrap_pi(angle(&s, "phi2_start") - x[1]).abs() < 1e-9);
    assert!(wrap_pi(angle(&s, "phi2_end") - x[2]).abs() < 1e-9);
    assert!((coord(&s, "X_C_start") - x[3]).abs() < 1e-10);
    assert!((s.length("AB").unwrap() - lam * x[0]).abs() < 1e-10);
    assert!((s.length("e").unwrap() - le * x[0]).abs() < 1e-10);
    // analysed back: the slider at the two crank angles, h_C apart, on y = e
    let m = Mechanism::new(&s.def).unwrap();
    let mut sol = m.solution();
    let ib = m.point("B").unwrap();
    m.solve(p0, &mut sol).unwrap();
    let b0 = sol.points[ib].p;
    m.solve(p1, &mut sol).unwrap();
    let b1 = sol.points[ib].p;
    assert!((b0.x - b1.x - hc).abs() < 1e-10 && (b0.x - x[3]).abs() < 1e-10);
    assert!((b0.y - le * x[0]).abs() < 1e-12);
    // the crank turns fully: l2 > l1 + |e|
    assert!(s.check.crank_turns_fully && lam > 1.0 + le);
    assert_eq!(s.shown, vec![p0, p1]);
}

fn p1_2_request(x: f64) -> ExtremesRequest {
    ExtremesRequest {
        abscissa: Abscissa::Given(x),
        frame_y: -0.1,
        rocker: 0.5,
        gamma_start: rad(70.0),
        gamma_end: rad(130.0),
        drive: Drive::default(),
        limits: Default::default(),
    }
}

/// The book's four equations of П1.2/П1.3 with D = (xd, yd).
fn extremes_eqs((l1, l2, p, th): (f64, f64, f64, f64), d: Vec2, l3: f64, (g0, g1): (f64, f64)) -> Vec<f64> {
    vec![
        (l1 + l2) * p.cos() - d.x - l3 * g0.cos(),
        (l1 + l2) * p.sin() - d.y - l3 * g0.sin(),
        (l2 - l1) * (p + th).cos() - d.x - l3 * g1.cos(),
        (l2 - l1) * (p + th).sin() - d.y - l3 * g1.sin(),
    ]
}

#[test]
fn p1_2_four_bar_by_extreme_positions_against_the_books_system() {
    let s = rocker_extremes::synthesize(&p1_2_request(0.8)).unwrap();
    let d = Vec2::new(0.8, -0.1);
    let x = newton(
        |v| extremes_eqs((v[0], v[1], v[2], v[3]), d, 0.5, (rad(70.0), rad(130.0))),
        vec![0.2, 0.5, rad(30.0), rad(30.0)],
    );
    assert!((s.length("AB").unwrap() - x[0]).abs() < 1e-10);
    assert!((s.length("BC").unwrap() - x[1]).abs() < 1e-10);
    assert!(wrap_pi(angle(&s, "phi1_start") - x[2]).abs() < 1e-9);
    assert!(wrap_pi(angle(&s, "theta") - x[3]).abs() < 1e-9);
    // analysed back: the rocker's extreme angles over the whole cycle, the
    // swing, and K from θ
    same_angles(rocker_at_dead(&s), vec![rad(70.0), rad(130.0)], 1e-9);
    assert!(matches!(s.check.stroke, Some(Stroke::Angular(p)) if (p - rad(60.0)).abs() < 1e-9));
    let th = x[3].abs();
    assert!((s.check.k.unwrap() - (PI + th) / (PI - th)).abs() < 1e-9);
    // Grashof: the crank is the shortest and s + l < p + q
    let mut l = [x[0], x[1], 0.5, d.hypot()];
    l.sort_by(f64::total_cmp);
    assert!(l[0] == x[0] && l[0] + l[3] < l[1] + l[2]);
}

#[test]
fn p1_2_refuses_a_frame_point_whose_first_position_is_folded() {
    // D far to the left: C_н is nearer to A than C_к
    let e = rocker_extremes::synthesize(&p1_2_request(-0.8)).unwrap_err();
    assert!(
        matches!(e, SynthesisError::Infeasible { ref field, .. } if field == "frame_x"),
        "{e}"
    );
}

#[test]
fn p1_3_frame_abscissa_by_k_against_the_books_system() {
    let (k, yd, l3, g0, g1) = (1.2, -0.1, 0.5, rad(50.0), rad(110.0));
    let theta = PI * (k - 1.0) / (k + 1.0);
    let s = rocker_extremes::synthesize(&ExtremesRequest {
        abscissa: Abscissa::ByK(k),
        frame_y: yd,
        rocker: l3,
        gamma_start: g0,
        gamma_end: g1,
        drive: Drive::default(),
        limits: Default::default(),
    })
    .unwrap();
    // the book's system with unknowns (l1, l2, φ1н, X_D), guesses 0.2, 0.5, 30°, 0.5
    let x = newton(
        |v| extremes_eqs((v[0], v[1], v[2], theta), Vec2::new(v[3], yd), l3, (g0, g1)),
        vec![0.2, 0.5, rad(30.0), 0.5],
    );
    assert!((coord(&s, "X_D") - x[3]).abs() < 1e-10, "{} vs {}", coord(&s, "X_D"), x[3]);
    assert!((s.length("AB").unwrap() - x[0]).abs() < 1e-10);
    assert!((s.length("BC").unwrap() - x[1]).abs() < 1e-10);
    assert!(wrap_pi(angle(&s, "phi1_start") - x[2]).abs() < 1e-9);
    // analysed back: K and the extreme angles by the core
    assert!((s.check.k.unwrap() - k).abs() < 1e-9);
    same_angles(rocker_at_dead(&s), vec![g0, g1], 1e-9);
    // every root in the range: a scan of the one equation, independent of
    // the code's (20 000 steps over ±10 m), finds the same roots
    let g = |x: f64| {
        let d = Vec2::new(x, yd);
        let (c0, c1) = (d + Vec2::new(g0.cos(), g0.sin()) * l3, d + Vec2::new(g1.cos(), g1.sin()) * l3);
        wrap_pi(c1.atan2() - c0.atan2()) - theta
    };
    let mut signs = 0;
    for i in 0..20_000 {
        let (a, b) = (-10.0 + 1e-3 * i as f64, -10.0 + 1e-3 * (i + 1) as f64);
        if (g(a) > 0.0) != (g(b) > 0.0) && (g(a) - g(b)).abs() < 1.0 {
            signs += 1;
        }
    }
    let roots = rocker_extremes::frame_abscissae(yd, l3, g0, g1, theta);
    assert_eq!(roots.len(), signs);
    assert_eq!(roots.len(), 2);
    let reason = &s.free_parameter.as_ref().unwrap().reason;
    assert!(reason.contains("2 root(s)") && reason.contains("rejected"), "{reason}");
}

#[test]
fn p1_4_three_positions_against_the_books_six_equations() {
    let (d, l3) = (Vec2::new(0.5, -0.1), 0.5);
    let g = [70.0, 80.0, 120.0].map(rad);
    let dphi = [0.0, 30.0, 120.0].map(rad);
    let s = three_positions::synthesize(&ThreePositionsRequest {
        frame: d,
        rocker: l3,
        gammas: g,
        crank_turns: [dphi[1], dphi[2]],
        drive: Drive::default(),
        limits: Default::default(),
    })
    .unwrap();
    // unknowns l1, l2, φ1н, φ21, φ22, φ23; guesses 0.2, 0.5, 30°, 10°, 20°, 30°
    let x = newton(
        |v| {
            let mut r = Vec::new();
            for j in 0..3 {
                r.push(v[0] * (v[2] + dphi[j]).cos() + v[1] * v[3 + j].cos() - d.x - l3 * g[j].cos());
                r.push(v[0] * (v[2] + dphi[j]).sin() + v[1] * v[3 + j].sin() - d.y - l3 * g[j].sin());
            }
            r
        },
        vec![0.2, 0.5, rad(30.0), rad(10.0), rad(20.0), rad(30.0)],
    );
    assert!((s.length("AB").unwrap() - x[0]).abs() < 1e-10);
    assert!((s.length("BC").unwrap() - x[1]).abs() < 1e-10);
    assert!(wrap_pi(angle(&s, "phi1_start") - x[2]).abs() < 1e-9);
    for j in 0..3 {
        assert!(wrap_pi(angle(&s, &format!("phi2_{}", j + 1)) - x[3 + j]).abs() < 1e-9);
    }
    // analysed back: the core, moving the crank from position 1, puts the
    // rocker at γj
    let m = Mechanism::new(&s.def).unwrap();
    let mut sol = m.solution();
    let (ic, id) = (m.point("C").unwrap(), m.point("D").unwrap());
    for step in 0..=120 {
        let t = dphi[2] * step as f64 / 120.0;
        m.solve(x[2] + t, &mut sol).unwrap();
        if let Some(j) = dphi.iter().position(|p| (p - t).abs() < 1e-12) {
            let got = (sol.points[ic].p - sol.points[id].p).atan2();
            assert!(wrap_pi(got - g[j]).abs() < 1e-9, "position {j}: {got} vs {}", g[j]);
        }
    }
    assert_eq!(s.shown.len(), 3);
}

#[test]
fn p1_4_refuses_rotations_of_two_senses() {
    let e = three_positions::synthesize(&ThreePositionsRequest {
        frame: Vec2::new(0.5, -0.1),
        rocker: 0.5,
        gammas: [70.0, 80.0, 120.0].map(rad),
        crank_turns: [rad(30.0), rad(-40.0)],
        drive: Drive::default(),
        limits: Default::default(),
    })
    .unwrap_err();
    assert!(matches!(e, SynthesisError::Input { ref field, .. } if field == "phi13"), "{e}");
}

fn cyl(pressure: PressureAt, frame_y: Option<f64>) -> CylinderRequest {
    CylinderRequest {
        h_min: 0.05,
        h_max: 0.3,
        rod: 1.3 * 0.3,
        swing: rad(60.0),
        pressure,
        frame_y,
        drive: Drive::default(),
        limits: Default::default(),
    }
}

/// The book's five equations of П1.5 with Y_D fixed: unknowns X_D, l1, φ1,
/// φ3н, φ3к.
fn cylinder_eqs(v: &[f64], yd: f64, at: PressureAt) -> Vec<f64> {
    let (xd, l1, p1, f0, f1) = (v[0], v[1], v[2], v[3], v[4]);
    let (beta, s0, s1) = (rad(60.0), 0.05 + 0.39, 0.3 + 0.39);
    vec![
        l1 * (p1 + beta).cos() - xd - s1 * f1.cos(),
        l1 * (p1 + beta).sin() - yd - s1 * f1.sin(),
        l1 * p1.cos() - xd - s0 * f0.cos(),
        l1 * p1.sin() - yd - s0 * f0.sin(),
        match at {
            PressureAt::End(t) => p1 + beta + FRAC_PI_2 - f1 - t,
            PressureAt::Start(t) => p1 + FRAC_PI_2 - f0 - t,
        },
    ]
}

/// The synthesis against Newton on the book's equations, and the mechanism
/// analysed back by the core: |DB| = h + l_шт at both ends, monotonic
/// between, the given pressure angle, and the other one. From the book's
/// guesses (X_D = 2 h_max, l1 = h_max, φ1 = 90°, φ3н = 120°, φ3к = 150°)
/// Newton reaches, for θк given, the longer root of the quadratic in l1,
/// whose θн exceeds 90° (the rod would first draw the lever back below
/// h_min): the synthesis lists that root as rejected, and a start with
/// φ1 = 60° reaches the one taken.
fn cylinder_case(at: PressureAt, yd: f64) {
    let s = cylinder::synthesize(&cyl(at, Some(yd))).unwrap();
    let book = newton(|v| cylinder_eqs(v, yd, at), vec![0.6, 0.3, rad(90.0), rad(120.0), rad(150.0)]);
    let roots = cylinder::solutions(0.44, 0.69, rad(60.0), at, |_| Some(0.0));
    assert!(roots.iter().any(|p| (p.l1 - book[1]).abs() < 1e-10), "{book:?} vs {roots:?}");
    let x = if (s.length("OB").unwrap() - book[1]).abs() < 1e-9 {
        book
    } else {
        // the book's start reached the other root: a pressure angle > 90°
        let th_start = wrap_pi(book[2] + FRAC_PI_2 - book[3]);
        assert!(th_start.abs() > FRAC_PI_2, "{}", th_start.to_degrees());
        let why = &s.free_parameter.as_ref().unwrap().reason;
        assert!(why.contains("rejected: a pressure angle"), "{why}");
        newton(|v| cylinder_eqs(v, yd, at), vec![0.6, 0.3, rad(60.0), rad(120.0), rad(150.0)])
    };
    assert!((coord(&s, "X_D") - x[0]).abs() < 1e-10, "X_D {} vs {}", coord(&s, "X_D"), x[0]);
    assert!((s.length("OB").unwrap() - x[1]).abs() < 1e-10);
    assert!(wrap_pi(angle(&s, "phi1") - x[2]).abs() < 1e-9);
    assert!(wrap_pi(angle(&s, "phi3_start") - x[3]).abs() < 1e-9);
    assert!(wrap_pi(angle(&s, "phi3_end") - x[4]).abs() < 1e-9);
    let m = Mechanism::new(&s.def).unwrap();
    let mut sol = m.solution();
    let (ib, id) = (m.point("B").unwrap(), m.point("D").unwrap());
    let mut prev = 0.0;
    let mut ends = vec![];
    for k in 0..=60 {
        let phi = x[2] + rad(60.0) * k as f64 / 60.0;
        m.solve(phi, &mut sol).unwrap();
        let v = sol.points[ib].p - sol.points[id].p;
        assert!(v.hypot() > prev);
        prev = v.hypot();
        if k == 0 || k == 60 {
            ends.push((v.hypot(), wrap_pi(phi + FRAC_PI_2 - v.atan2())));
        }
    }
    assert!((ends[0].0 - 0.44).abs() < 1e-10 && (ends[1].0 - 0.69).abs() < 1e-10);
    assert!((ends[0].1 - angle(&s, "theta_start")).abs() < 1e-9);
    assert!((ends[1].1 - angle(&s, "theta_end")).abs() < 1e-9);
    match at {
        PressureAt::End(t) => assert!((ends[1].1 - t).abs() < 1e-9),
        PressureAt::Start(t) => assert!((ends[0].1 - t).abs() < 1e-9),
    }
    assert!((s.frame[1].1.y - yd).abs() < 1e-12);
}

#[test]
fn p1_5_cylinder_variant_1_against_the_books_system() {
    cylinder_case(PressureAt::End(rad(50.0)), 0.05);
}

#[test]
fn p1_5_cylinder_variants_2_and_3_with_their_free_ordinate() {
    cylinder_case(PressureAt::End(rad(50.0)), -0.121);
    cylinder_case(PressureAt::Start(rad(10.0)), -0.193);
}

#[test]
fn p1_5_the_family_keeps_the_lever_the_distance_and_the_pressure_angles() {
    let base = cylinder::synthesize(&cyl(PressureAt::End(rad(50.0)), None)).unwrap();
    for y in [-0.3, -0.121, 0.0, 0.05, 0.2] {
        let s = cylinder::synthesize(&cyl(PressureAt::End(rad(50.0)), Some(y))).unwrap();
        for n in ["OB", "OD"] {
            assert!((s.length(n).unwrap() - base.length(n).unwrap()).abs() < 1e-12);
        }
        for n in ["theta_start", "theta_end"] {
            assert!((angle(&s, n) - angle(&base, n)).abs() < 1e-9);
        }
        // the whole configuration turned about O: φ1 − arg D is invariant
        let turn = |s: &Synthesis| wrap_pi(angle(s, "phi1") - s.frame[1].1.atan2());
        assert!(wrap_pi(turn(&s) - turn(&base)).abs() < 1e-9);
    }
    // |Y_D| beyond |OD| places no cylinder
    let od = base.length("OD").unwrap();
    let e = cylinder::synthesize(&cyl(PressureAt::End(rad(50.0)), Some(1.5 * od))).unwrap_err();
    assert!(
        matches!(e, SynthesisError::Infeasible { ref field, nearest: Some(_), .. } if field == "frame_y"),
        "{e}"
    );
}

/// Seed 002, example 2, with every given: the bell crank B–C–D
/// (l_BC = l_CD = 0.22 m, l_BC/l_BD = 2) drives the knee C–D–F
/// (l_DF = 0.2 m); H_F = 0.09 m, K = 1.12, δ = 5°, l^x_CO = 0.28 m.
#[test]
fn seed_002_knee_press_with_the_bell_crank_uses_every_given() {
    use tmm_linkage::synthesis::Rotation;
    use tmm_linkage::synthesis::knee_bell_crank::{self, BellKneeRequest};
    use tmm_linkage::synthesis::knee_press::KneePivot;
    let s = knee_bell_crank::synthesize(&BellKneeRequest {
        stroke: 0.09,
        k: 1.12,
        knee: 0.22,
        link: 0.2,
        arm: 0.22,
        chord: 0.11,
        delta: rad(5.0),
        pivot: KneePivot::Horizontal(0.28),
        drive: Drive {
            rotation: Rotation::Cw,
            omega: 1.0,
        },
        limits: Default::default(),
    })
    .unwrap();
    let (l1, l2) = (s.length("OA").unwrap(), s.length("AB").unwrap());
    // the seed's graphical lengths (read at 0.005 m/mm): within about 1 %
    assert!((l1 / 0.055 - 1.0).abs() < 0.011, "l_OA = {l1}");
    assert!((l2 / 0.255 - 1.0).abs() < 0.011, "l_AB = {l2}");
    // analysed back: at the core's two dead positions the slide is 0.09 m
    // apart, the knee CD at δ = 5° from the vertical at the bottom, B and D
    // 0.11 m apart, |CB| = |CD| = 0.22 m, and O sees B′B″ at θ
    let theta = PI * 0.12 / 2.12;
    let pos = &s.check.dead_positions;
    let p = |i: usize, n: &str| pos[i].iter().find(|(m, _)| m == n).unwrap().1;
    let (f0, f1) = (p(0, "F"), p(1, "F"));
    assert!(((f0.y - f1.y).abs() - 0.09).abs() < 1e-9);
    let bottom = if f0.y < f1.y { 0 } else { 1 };
    let d = p(bottom, "D");
    assert!(((-d.x).atan2(-d.y) - rad(5.0)).abs() < 1e-9, "{d:?}");
    for i in 0..2 {
        assert!(((p(i, "B") - p(i, "D")).hypot() - 0.11).abs() < 1e-12);
        assert!((p(i, "B").hypot() - 0.22).abs() < 1e-12 && (p(i, "D").hypot() - 0.22).abs() < 1e-12);
        assert!(((p(i, "F") - p(i, "D")).hypot() - 0.2).abs() < 1e-12 && p(i, "F").x.abs() < 1e-12);
    }
    let o = s.frame[1].1;
    assert!((o.x - 0.28).abs() < 1e-12);
    let (r0, r1) = (p(0, "B") - o, p(1, "B") - o);
    let seen = (r0.x * r1.y - r0.y * r1.x).atan2(r0.x * r1.x + r0.y * r1.y).abs();
    assert!((seen - theta).abs() < 1e-9, "{} vs {}", seen.to_degrees(), theta.to_degrees());
    assert!((s.check.k.unwrap() - 1.12).abs() < 1e-9);
}

/// The textbook's П3 shaper request (GIVENS.md: H = 0.3 m, K = 1.4,
/// l_BC = 0.5 m, λ = 1.4, l_OC = 0.3 m), the crank turning `rotation`.
fn p3_request(rotation: tmm_linkage::synthesis::Rotation) -> tmm_linkage::synthesis::shaper::ShaperRequest {
    tmm_linkage::synthesis::shaper::ShaperRequest {
        stroke: 0.3,
        k: 1.4,
        rocker: 0.5,
        lambda: 1.4,
        frame: 0.3,
        ram_center: 0.164,
        drive: Drive { rotation, omega: 6.0 },
        limits: Default::default(),
    }
}

/// The ram's stroke and K measured by brute force on the analysed mechanism:
/// the ram's abscissa at 36 000 crank angles in the crank's sense from 0,
/// its extreme values and the crank's travel from the smallest to the
/// largest — no dead-position search, no synthesis formula; K is the
/// longer of the two strokes' crank travels over the shorter.
fn measured_stroke_and_k(s: &Synthesis) -> (f64, f64) {
    let m = Mechanism::new(&s.def).unwrap();
    let sg = m.crank.omega.signum();
    let mut sol = m.solution();
    let e = m.points.iter().position(|p| p.name == "E").unwrap();
    let n = 36_000;
    let (mut lo, mut hi) = ((f64::INFINITY, 0.0), (f64::NEG_INFINITY, 0.0));
    for i in 0..n {
        let psi = 2.0 * PI * i as f64 / n as f64;
        m.solve(sg * psi, &mut sol).unwrap();
        let x = sol.points[e].p.x;
        if x < lo.0 {
            lo = (x, psi);
        }
        if x > hi.0 {
            hi = (x, psi);
        }
    }
    let one = (hi.1 - lo.1).rem_euclid(2.0 * PI);
    let other = 2.0 * PI - one;
    (hi.0 - lo.0, one.max(other) / one.min(other))
}

#[test]
fn p3_shaper_against_the_books_four_equations_and_measured_back() {
    use tmm_linkage::synthesis::Rotation;
    use tmm_linkage::synthesis::shaper;
    let s = shaper::synthesize(&p3_request(Rotation::Cw)).unwrap();
    // the book's four equations, Newton from its guesses 0.1, 0.3, 45°, −45°
    let (h, k, l_bc, l_cd, l_oc): (f64, f64, f64, f64, f64) = (0.3, 1.4, 0.5, 0.7, 0.3);
    let g = (h / (2.0 * l_cd)).asin();
    let d_px = 2.0 * PI - 2.0 * PI / (k + 1.0);
    let x = newton(
        |v| {
            let c = Vec2::new(l_oc * v[3].cos(), l_oc * v[3].sin());
            let b1 = c + Vec2::new((FRAC_PI_2 - g).cos(), (FRAC_PI_2 - g).sin()) * l_bc;
            let b2 = c + Vec2::new((FRAC_PI_2 + g).cos(), (FRAC_PI_2 + g).sin()) * l_bc;
            vec![
                (v[0] + v[1]) * v[2].cos() - b1.x,
                (v[0] + v[1]) * v[2].sin() - b1.y,
                (v[0] - v[1]) * (v[2] + d_px).cos() - b2.x,
                (v[0] - v[1]) * (v[2] + d_px).sin() - b2.y,
            ]
        },
        vec![0.1, 0.3, rad(45.0), rad(-45.0)],
    );
    assert!(
        (s.length("OA").unwrap() - x[0]).abs() < 1e-12,
        "{} {}",
        s.length("OA").unwrap(),
        x[0]
    );
    assert!((s.length("AB").unwrap() - x[1]).abs() < 1e-12);
    assert!(wrap_pi(angle(&s, "phi0") - x[2]).abs() < 1e-11);
    assert!(wrap_pi(angle(&s, "beta") - x[3]).abs() < 1e-11);
    assert!((coord(&s, "X_C") - l_oc * x[3].cos()).abs() < 1e-12);
    let y_c = l_oc * x[3].sin();
    assert!((coord(&s, "Y_C") - y_c).abs() < 1e-12);
    assert!((coord(&s, "Y_S5") - (y_c + l_cd - l_cd * (1.0 - g.cos()) / 2.0)).abs() < 1e-12);
    assert!(wrap_pi(angle(&s, "phi_start") - (x[2] + d_px)).abs() < 1e-11);
    // measured back on the written mechanism, both senses of the crank
    for rot in [Rotation::Cw, Rotation::Ccw] {
        let s = shaper::synthesize(&p3_request(rot)).unwrap();
        let (stroke, kk) = measured_stroke_and_k(&s);
        assert!((stroke - h).abs() < 1e-7, "{rot:?}: stroke {stroke}");
        // K from a 0.01° grid: the travel between the extremes to ±0.01°
        assert!((kk - k).abs() < 1e-3, "{rot:?}: K {kk}");
        assert!(s.check.crank_turns_fully);
    }
}

#[test]
fn p3_shaper_refuses_what_it_cannot_build() {
    use tmm_linkage::synthesis::Rotation;
    use tmm_linkage::synthesis::shaper;
    let field = |e: SynthesisError| match e {
        SynthesisError::Input { field, .. } | SynthesisError::Infeasible { field, .. } => field,
        other => panic!("{other}"),
    };
    // H ≥ 2·l_CD: the rocker cannot swing the ram so far
    let mut r = p3_request(Rotation::Cw);
    r.stroke = 1.5;
    assert_eq!(field(shaper::synthesize(&r).unwrap_err()), "stroke");
    // K < 1
    let mut r = p3_request(Rotation::Cw);
    r.k = 0.9;
    assert_eq!(field(shaper::synthesize(&r).unwrap_err()), "k");
    // λ ≤ 0
    let mut r = p3_request(Rotation::Cw);
    r.lambda = 0.0;
    assert_eq!(field(shaper::synthesize(&r).unwrap_err()), "lambda");
    // O so far from C that it cannot see the chord at θ = 30°
    let mut r = p3_request(Rotation::Cw);
    r.frame = 50.0;
    assert_eq!(field(shaper::synthesize(&r).unwrap_err()), "frame");
}
