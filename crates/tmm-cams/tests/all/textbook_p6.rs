//! The textbook's cams (BMSTU 2019, appendix П6): the law of П6.1–П6.3 as an
//! `accel(…)` law against its closed form written out here from GIVENS.md
//! and against finite differences; the tangent methods of П6.4 against a
//! dense scan of the same closed form and the book's own equations; the
//! level-line method of П6.5 against the book's formulas written literally
//! (slopes k, intercepts b, X_V on a grid) and the pressure angle of its
//! centre against a brute-force scan of the pitch curve by central
//! differences; tmm's exact sizing against a brute-force grid.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use tmm_cams::design::{CamTask, FollowerSpec};
use tmm_cams::mechanism::{Rotation, rotate};
use tmm_cams::program::{PhaseKind, Program};
use tmm_cams::spec::{self, Limits};
use tmm_cams::{levels, tangents, textbook};
use tmm_geom::Vec2;

const PHASES: &str = "rise 120 accel(sine 1, sine -3); dwell 30; return 180 accel(const -1, const 2.5); dwell 30";
const H: f64 = 0.08;

fn d(x: f64) -> f64 {
    x.to_radians()
}

fn program(h: f64) -> Program {
    Program::new(h, spec::parse_phases(PHASES).unwrap()).unwrap()
}

fn limits() -> Limits {
    Limits {
        rise: d(30.0),
        ret: d(50.0),
    }
}

/// The book's law (GIVENS.md П6.1–П6.3) in closed form: `[S, v_q, a_q]` at φ.
/// Rise: a = (π/f₁) sin(πφ/f₁), then −(π/L₂) sin(π(f₂ − φ)/L₂), integrated
/// twice by hand (v = 1 − cos, S = φ − (f₁/π) sin; then v = 1 + cos(πt/L₂),
/// S = f₁ + t + (L₂/π) sin(πt/L₂)), so H_у = f₂ and the scale is h/ψ_у.
/// Return: −a₃ on L₃, +a₄ = ν·a₃ on L₄; its drop a₃L₃ψ_с/2 = h gives
/// a₃ = 2h/(L₃ψ_с).
fn book(h: f64, phi: f64) -> [f64; 3] {
    let (psu, psc, psr) = (d(120.0), d(180.0), d(330.0));
    let f1 = 3.0 * psu / 4.0;
    let (f2, f3) = (psu, psr - psc);
    let f4 = f3 + 2.5 * psc / 3.5;
    let f5 = psr;
    let (l1, l2, l3) = (f1, f2 - f1, f4 - f3);
    let k = h / psu;
    let a3 = 2.0 * h / (l3 * psc);
    let a4 = 2.5 * a3;
    let p = phi.rem_euclid(TAU);
    if p < f1 {
        let x = PI * p / l1;
        [k * (p - l1 / PI * x.sin()), k * (1.0 - x.cos()), k * PI / l1 * x.sin()]
    } else if p < f2 {
        let t = p - f1;
        let x = PI * t / l2;
        [k * (f1 + t + l2 / PI * x.sin()), k * (1.0 + x.cos()), -k * PI / l2 * x.sin()]
    } else if p < f3 {
        [h, 0.0, 0.0]
    } else if p < f4 {
        let t = p - f3;
        [h - a3 * t * t / 2.0, -a3 * t, -a3]
    } else if p < f5 {
        let t = p - f4;
        [h - a3 * l3 * l3 / 2.0 - a3 * l3 * t + a4 * t * t / 2.0, -a3 * l3 + a4 * t, a4]
    } else {
        [0.0, 0.0, 0.0]
    }
}

#[test]
fn the_p6_law_is_the_books_closed_form() {
    let p = program(H);
    for i in 0..3600 {
        let phi = TAU * (i as f64 + 0.37) / 3600.0;
        let m = p.eval(phi);
        let b = book(H, phi);
        assert!((m.s - b[0]).abs() < 1e-12, "S at {}°: {} vs {}", phi.to_degrees(), m.s, b[0]);
        assert!((m.v - b[1]).abs() < 1e-12, "v at {}°", phi.to_degrees());
        assert!((m.a - b[2]).abs() < 1e-11, "a at {}°: {} vs {}", phi.to_degrees(), m.a, b[2]);
    }
    // phase boundaries f₁ = 90°, f₄ = 278.571°: the return's split a₄ψ_с/(a₃ + a₄)
    let joints: Vec<f64> = p.jumps().iter().map(|j| j.phi.to_degrees()).collect();
    assert!(joints.iter().any(|&j| (j - (150.0 + 2.5 * 180.0 / 3.5)).abs() < 1e-9), "{joints:?}");
}

#[test]
fn the_p6_law_matches_its_finite_differences_and_ends() {
    let p = program(H);
    let hstep = 1e-5;
    for i in 1..720 {
        let phi = TAU * (i as f64 + 0.21) / 720.0;
        let (l, m, r) = (p.eval(phi - hstep), p.eval(phi), p.eval(phi + hstep));
        let v_fd = (r.s - l.s) / (2.0 * hstep);
        let a_fd = (r.v - l.v) / (2.0 * hstep);
        assert!((m.v - v_fd).abs() < 1e-9, "ds/dφ at {}°", phi.to_degrees());
        assert!((m.a - a_fd).abs() < 1e-8, "d²s/dφ² at {}°", phi.to_degrees());
    }
    // the ends: S(f₂) = h at rest, S(f₅) = 0 at rest
    let top = p.eval_left(d(120.0));
    assert!((top.s - H).abs() < 1e-15 && top.v.abs() < 1e-15);
    let bottom = p.eval_left(d(330.0));
    assert!(bottom.s.abs() < 1e-15 && bottom.v.abs() < 1e-15);
    // s and s′ continuous over the whole cycle; s″ continuous at the rise's
    // joints (half sines end at 0), jumping at the return's three
    for j in p.jumps() {
        let (l, r) = (p.eval_left(j.phi), p.eval(j.phi));
        assert!((l.s - r.s).abs() < 1e-15 && (l.v - r.v).abs() < 1e-15, "at {}°", j.phi.to_degrees());
        assert!(j.phi > d(149.0), "the rise is C2, jump at {}°", j.phi.to_degrees());
    }
    assert_eq!(p.jumps().len(), 3);
    let law = p.phases()[0].law.as_ref().unwrap();
    assert_eq!(law.continuity(), 2);
    assert_eq!(p.phases()[2].law.as_ref().unwrap().continuity(), 1);
}

#[test]
fn accel_pieces_with_angles_must_fill_the_phase() {
    assert!(spec::parse_phases("rise 120 accel(sine 1 90°, sine -3 30°); dwell 240").is_ok());
    let e = spec::parse_phases("rise 120 accel(sine 1 90°, sine -3 20°); dwell 240")
        .unwrap_err()
        .to_string();
    assert!(e.contains("add up to 110") && e.contains("120"), "{e}");
    // unbalanced areas: the velocity would not come back to zero
    let e = spec::parse_phases("rise 120 accel(sine 1 60°, sine -3 60°); dwell 240")
        .unwrap_err()
        .to_string();
    assert!(e.contains("areas"), "{e}");
    // a return written as a rise: no lift
    let e = spec::parse_phases("rise 60 cosine; return 120 accel(const 1, const -2.5); dwell 180")
        .unwrap_err()
        .to_string();
    assert!(e.contains("return with a negative"), "{e}");
    // one piece without an angle takes the rest
    let p = spec::parse_phases("rise 120 accel(const 2 30°, const -0.5, const -1 30°); dwell 240");
    assert!(p.is_ok(), "{p:?}");
}

/// Dense scan of `|s′| − t·s` over a phase of the closed form: (φ, value).
fn scan_max(lo: f64, hi: f64, f: impl Fn(f64) -> f64) -> (f64, f64) {
    let n = 400_000;
    (0..=n)
        .map(|i| lo + (hi - lo) * i as f64 / n as f64)
        .map(|p| (p, f(p)))
        .fold((0.0, f64::NEG_INFINITY), |a, b| if b.1 > a.1 { b } else { a })
}

#[test]
fn the_books_tangent_methods_against_a_scan_and_its_own_equations() {
    let p = program(H);
    let sigma = -1.0; // the book's ω_q1 = −1
    let t = tangents::tangent_sizing(&p, sigma, limits()).unwrap();
    let (tu, tc) = (d(30.0).tan(), d(50.0).tan());
    // largest speeds at f₁ = 90° and f₄ = 278.571°
    assert!((t.speed_rise - d(90.0)).abs() < 1e-7, "{}", t.speed_rise.to_degrees());
    assert!((t.speed_return - d(150.0 + 2.5 * 180.0 / 3.5)).abs() < 1e-7);
    // the book's step 1 with v_q = s′ (ω_q1 = −1): tan θ_п (s₀ + S) = v − e_b,
    // tan θ_л (s₀ + S) = −v + e_b, solved by Cramer's rule
    let solve = |pp: f64, pl: f64| {
        let ([sp, vp, _], [sl, vl, _]) = (book(H, pp), book(H, pl));
        let (b1, b2) = (vp - tu * sp, -vl - tc * sl);
        let det = -tu - tc; // |tu 1; tc −1|
        let s0 = (-b1 - b2) / det;
        let eb = (tu * b2 - b1 * tc) / det;
        (s0, eb)
    };
    let (s0, eb) = solve(d(90.0), d(150.0 + 2.5 * 180.0 / 3.5));
    assert!(
        (t.approximate.s0 - s0).abs() < 1e-9 && (t.approximate.e + eb).abs() < 1e-9,
        "{:?} vs {s0} {eb}",
        t.approximate
    );
    // tangency: the maxima of v − tS (rise) and −v − tS (return) by a dense scan
    let (pr, _) = scan_max(0.0, d(120.0), |x| {
        let b = book(H, x);
        b[1] - tu * b[0]
    });
    let (pl, _) = scan_max(d(150.0), d(330.0), |x| {
        let b = book(H, x);
        -b[1] - tc * b[0]
    });
    assert!(
        (t.tangent_rise - pr).abs() < 1e-5,
        "{} vs {}",
        t.tangent_rise.to_degrees(),
        pr.to_degrees()
    );
    assert!((t.tangent_return - pl).abs() < 1e-5);
    // there the diagram's slope v/a is the ray's tan δ
    let b = book(H, t.tangent_rise);
    assert!((b[1] / b[2] - (FRAC_PI_2 - d(30.0)).tan()).abs() < 1e-6, "{}", b[1] / b[2]);
    let b = book(H, t.tangent_return);
    assert!((b[1] / b[2] - (PI - (FRAC_PI_2 - d(50.0))).tan()).abs() < 1e-6);
    // method 2 from the book's equations at the scanned tangency points;
    // method 1 (the lines intersected) is the same point
    let (s0, eb) = solve(pr, pl);
    assert!((t.method2.s0 - s0).abs() < 1e-9 && (t.method2.e + eb).abs() < 1e-9);
    assert!((t.method1.s0 - t.method2.s0).abs() < 1e-12 && (t.method1.e - t.method2.e).abs() < 1e-12);
    assert!((t.method1_xy.0 - eb).abs() < 1e-9 && (t.method1_xy.1 + s0).abs() < 1e-9);
    // at the book's centre the pressure angle touches +30° on the rise and
    // −50° on the return (tan θ = (v − e_b)/(s₀ + S) on a fine grid)
    let th = |x: f64| {
        let b = book(H, x);
        ((b[1] - eb) / (s0 + b[0])).atan()
    };
    let (_, rise_max) = scan_max(0.0, d(120.0), th);
    let (_, ret_min) = scan_max(d(150.0), d(330.0), |x| -th(x));
    assert!((rise_max - d(30.0)).abs() < 1e-9 && (ret_min - d(50.0)).abs() < 1e-9);
    // … and the rise's other side, at φ = 0 where v = 0, is −atan(e_b/s₀) < −30°
    assert!(th(0.0) < -d(30.0));
    // the book's relative changes
    let (dr, de) = t.deltas();
    let (r1, rp) = (s0.hypot(eb), t.approximate.r0());
    assert!((dr - (r1 - rp) / r1).abs() < 1e-9, "{dr} vs {}", (r1 - rp) / r1);
    assert!((de - (-eb - t.approximate.e) / -eb).abs() < 1e-9, "{de}");
}

#[test]
fn tmms_exact_translating_centre_is_the_smallest_on_a_grid() {
    let p = program(H);
    let task = CamTask {
        program: p.clone(),
        follower: FollowerSpec::TranslatingRoller {
            offset: None,
            roller: Some(0.02),
        },
        rotation: Rotation::Cw,
        limits: limits(),
        min_curvature: None,
        face_margin: 0.005,
        omega: 1.0,
        points: 720,
    };
    let dsn = task.solve().unwrap();
    // brute force: for each offset e (tmm's sign: the book's −e_b) the least s₀ with
    // |θ| ≤ limit on both sides of each phase over a grid of the closed form,
    // tan θ = |s′ + e|/(s₀ + S) for a clockwise cam (σ = −1)
    let grid: Vec<(bool, [f64; 3])> = (0..=20000)
        .map(|i| d(330.0) * i as f64 / 20000.0)
        .filter(|&x| x <= d(120.0) || x >= d(150.0))
        .map(|x| (x <= d(120.0), book(H, x)))
        .collect();
    let mut best = f64::INFINITY;
    for i in 0..=4000 {
        let e = -0.04 + 0.04 * i as f64 / 4000.0;
        let s0 = grid
            .iter()
            .map(|(rise, b)| (b[1] + e).abs() / if *rise { d(30.0).tan() } else { d(50.0).tan() } - b[0])
            .fold(0.0f64, f64::max);
        best = best.min(e.hypot(s0));
    }
    assert!(dsn.r0 <= best + 1e-7 && dsn.r0 > best - 2e-5, "tmm {} vs grid {best}", dsn.r0);
    // the comparison: the book's vertex is smaller but breaks the rise's other side
    let b = textbook::compare(&task, &dsn).unwrap();
    let t = b.translating.unwrap();
    assert!(t.method1.centre.r0() < dsn.r0);
    assert!(t.method1.pressure.excess(d(30.0), d(50.0)) > d(1.0));
    assert!(t.exact.pressure.excess(d(30.0), d(50.0)) < 1e-9);
    // the roller rules of p. 111 with r0 and ρ_min of the pitch curve
    let r = b.roller.unwrap();
    assert!((r.high - 0.4 * dsn.r0).abs() < 1e-15 && r.in_range() == (0.02 <= 0.4 * dsn.r0 && 0.02 >= 0.25 * dsn.r0));
    assert!((r.rho_bound - 0.8 * dsn.rho_min_pitch.unwrap()).abs() < 1e-15);
}

/// The book's П6.5 written literally: κ = +1, ω_q1 = +1, v_q = l·s′ (the
/// П6.4 orientation), ρ = l_T − v_q, N = ρ·e(φ₂), k = tan(φ₂ + π/2 ± θ),
/// b = N_y − k·N_x.
fn book_line(p: &Program, l: f64, phi: f64) -> (f64, f64) {
    let m = p.eval(phi);
    let ph2 = m.s;
    let rho = l - l * m.v;
    let n = (rho * ph2.cos(), rho * ph2.sin());
    let ang = if phi <= d(120.0) {
        ph2 + FRAC_PI_2 + d(30.0)
    } else {
        ph2 + FRAC_PI_2 - d(50.0)
    };
    let k = ang.tan();
    (k, n.1 - k * n.0)
}

fn meet(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    let x = (b.1 - a.1) / (a.0 - b.0);
    (x, a.0 * x + a.1)
}

#[test]
fn the_level_line_method_against_the_books_formulas_and_a_pressure_scan() {
    let l = 0.15;
    // the stroke is the arc 80 mm of the tip: φ₂ = S/l_T
    let p = program(H / l);
    let lv = levels::level_lines(&p, 1.0, 1.0, limits(), l).unwrap();
    let (f1, f4) = (d(90.0), d(150.0 + 2.5 * 180.0 / 3.5));
    let (x1, y1) = meet(book_line(&p, l, f1), book_line(&p, l, f4));
    assert!(
        (lv.point1.x - x1).abs() < 1e-12 && (lv.point1.y - y1).abs() < 1e-12,
        "{:?} vs {x1} {y1}",
        lv.point1
    );
    // X_V = (Y₁ − b)/k − X₁ on the book's windows (rise ≤ 120°, return 220…320°)
    let xv = |phi: f64| {
        let (k, b) = book_line(&p, l, phi);
        (y1 - b) / k - x1
    };
    let n = 200_000;
    let (mut vmin, mut vmax) = ((0.0, f64::INFINITY), (0.0, f64::NEG_INFINITY));
    for i in 0..=n {
        let a = d(60.0) + d(60.0) * i as f64 / n as f64;
        if xv(a) < vmin.1 {
            vmin = (a, xv(a));
        }
        let b = d(220.0) + d(100.0) * i as f64 / n as f64;
        if xv(b) > vmax.1 {
            vmax = (b, xv(b));
        }
    }
    assert!(
        (lv.level_rise - vmin.0).abs() < 2e-5,
        "{} vs {}",
        lv.level_rise.to_degrees(),
        vmin.0.to_degrees()
    );
    assert!((lv.level_return - vmax.0).abs() < 2e-5);
    assert!((lv.level_values.0 - vmin.1).abs() < 1e-9, "{} vs {}", lv.level_values.0, vmin.1);
    // the return's maximum is at the corner f₄, which the grid may miss by half a step
    assert!((lv.level_values.1 - vmax.1).abs() < 1e-7, "{} vs {}", lv.level_values.1, vmax.1);
    let (x2, y2) = meet(book_line(&p, l, vmin.0), book_line(&p, l, vmax.0));
    assert!(
        (lv.point2.x - x2).abs() < 1e-7 && (lv.point2.y - y2).abs() < 1e-7,
        "{:?} vs {x2} {y2}",
        lv.point2
    );
    let (aw, f20) = levels::distance_and_angle(lv.point2);
    assert!((aw - x2.hypot(y2)).abs() < 1e-7 && (f20 - (y2 / x2).abs().atan()).abs() < 1e-6);

    // brute force: the knife edge's pitch curve seen from the cam, its normal
    // by central differences, the angle to the tip's velocity (⊥ the arm)
    let pressure_scan = |o: Vec2| {
        let tip = |phi: f64| {
            let s = p.eval(phi).s;
            // frame with the cam centre at the origin; the cam turns ccw by φ
            rotate(Vec2::new(l * s.cos(), l * s.sin()) - o, -phi)
        };
        let (mut rise, mut ret) = (f64::NEG_INFINITY, f64::NEG_INFINITY);
        let n = 40_000;
        // a grid, and the law's inner joints f₁, f₄ where s″ jumps and θ has a kink
        let joints = [d(90.0), d(150.0 + 2.5 * 180.0 / 3.5)];
        for phi in (1..n).map(|i| d(330.0) * i as f64 / n as f64).chain(joints) {
            let kind = p.phases()[p.phase_at(phi)].kind;
            if kind == PhaseKind::Dwell {
                continue;
            }
            let hh = 1e-6;
            let tang = tip(phi + hh) - tip(phi - hh);
            let nrm = Vec2::new(-tang.y, tang.x);
            let s = p.eval(phi).s;
            // the tip's velocity in the frame, perpendicular to the arm, turned into the cam frame
            let vel = rotate(Vec2::new(-s.sin(), s.cos()), -phi);
            let c = (nrm.dot(vel) / (nrm.hypot() * vel.hypot())).abs().min(1.0);
            let theta = c.acos();
            if kind == PhaseKind::Rise {
                rise = rise.max(theta);
            } else {
                ret = ret.max(theta);
            }
        }
        (rise, ret)
    };
    // at point 2 the rise's limit is passed a little: the level line ranks the
    // lines at the height of point 1 only
    let (rise, ret) = pressure_scan(lv.point2);
    let c2 = textbook::PressureRange::of(&p, |phi| levels::signed_pressure(&p, 1.0, 1.0, l, lv.point2, phi));
    assert!(
        (c2.rise.1 - rise).abs() < 1e-5,
        "{} vs {}",
        c2.rise.1.to_degrees(),
        rise.to_degrees()
    );
    assert!((-c2.ret.0 - ret).abs() < 1e-5, "{} vs {}", -c2.ret.0, ret);
    assert!(rise > d(30.0) + d(0.05) && rise < d(30.0) + d(0.2), "{}", rise.to_degrees());
    // at the vertex both limits are met exactly
    let (rise, ret) = pressure_scan(lv.vertex);
    assert!(
        (rise - d(30.0)).abs() < 1e-6 && (ret - d(50.0)).abs() < 1e-6,
        "{} {}",
        rise.to_degrees(),
        ret.to_degrees()
    );
    // and the book's own θ formula gives the same angles at point 2
    let book_theta = |phi: f64| {
        let m = p.eval(phi);
        let ph2 = m.s;
        ((l * m.v + aw * (f20 + ph2).cos() - l) / (aw * (f20 + ph2).sin())).atan()
    };
    for i in 0..=330 {
        let phi = d(i as f64);
        let ours = levels::signed_pressure(&p, 1.0, 1.0, l, lv.point2, phi);
        assert!((ours - book_theta(phi)).abs() < 1e-12, "θ at {i}°");
    }
}

#[test]
fn bad_pressure_limits_are_refused() {
    let p = program(H);
    for (rise, ret) in [(0.0, 50.0), (30.0, 90.0), (95.0, 30.0)] {
        let lim = Limits {
            rise: d(rise),
            ret: d(ret),
        };
        assert!(tangents::tangent_sizing(&p, -1.0, lim).is_err());
        assert!(levels::level_lines(&p, 1.0, 1.0, lim, 0.15).is_err());
    }
    // two rises: the book's construction has one ray per phase kind
    let two = Program::from_phases(
        spec::parse_phases("rise 60 cosine 10mm; dwell 30; rise 60 cosine 10mm; return 120 cosine 20mm; dwell 90").unwrap(),
    )
    .unwrap();
    let e = tangents::tangent_sizing(&two, 1.0, limits()).unwrap_err().to_string();
    assert!(e.contains("2 rises"), "{e}");
}
