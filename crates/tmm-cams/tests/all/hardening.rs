//! Regression tests for the cam defects: jumps of the analogs (and the wrap at
//! 360°), constant velocity, strokes per phase, analysing a given cam, and
//! absurd cam speeds — each against closed forms or geometry written here.

use std::f64::consts::{PI, TAU};

use tmm_cams::CamError;
use tmm_cams::design::{CamTask, FollowerSpec};
use tmm_cams::mechanism::{Mechanism, Rotation};
use tmm_cams::program::{JumpKind, Program};
use tmm_cams::spec;

fn program(h: f64, phases: &str) -> Program {
    Program::new(h, spec::parse_phases(phases).unwrap()).unwrap()
}

fn deg(d: f64) -> f64 {
    d.to_radians()
}

fn task(program: Program, follower: FollowerSpec) -> CamTask {
    CamTask {
        program,
        follower,
        rotation: Rotation::Ccw,
        limits: spec::parse_limits("30", false).unwrap(),
        min_curvature: None,
        face_margin: 0.005,
        omega: 10.0,
        points: 720,
    }
}

/// Constant acceleration (u = 1/2): s″ = ±4h/β² on the halves of a rise, ∓ on a
/// return; the acceleration jumps at the start, middle and end of each moving
/// phase, including the wrap at 360° → 0°.
#[test]
fn acceleration_jumps_of_constant_acceleration() {
    let h = 0.012;
    let p = program(h, "rise 90 const-accel; dwell 90; return 90 const-accel; dwell 90");
    let a = 4.0 * h / (deg(90.0) * deg(90.0));
    let want = [
        (0.0, 0.0, a),
        (45.0, a, -a),
        (90.0, -a, 0.0),
        (180.0, 0.0, -a),
        (225.0, -a, a),
        (270.0, a, 0.0),
    ];
    let j = p.jumps();
    assert_eq!(j.len(), want.len(), "{j:?}");
    for (got, &(phi, before, after)) in j.iter().zip(&want) {
        assert_eq!(got.kind, JumpKind::Acceleration);
        assert!((got.phi - deg(phi)).abs() < 1e-12, "{got:?}");
        assert!(
            (got.before - before).abs() < 1e-9 * a && (got.after - after).abs() < 1e-9 * a,
            "{got:?}"
        );
    }
    // u = 1/3 (seed 001): y″ = 2/u on [0, u], −2/(1 − u) after
    let p = program(h, "rise 108 const-accel(u=1/3); dwell 15; return 108 const-accel(u=1/3); dwell 129");
    let b2 = deg(108.0).powi(2);
    let j = p.jumps();
    assert!((j[0].size() - 6.0 * h / b2).abs() < 1e-9);
    assert!((j[1].phi - deg(36.0)).abs() < 1e-12 && (j[1].size() + (6.0 + 3.0) * h / b2).abs() < 1e-9);
    assert!((j[2].phi - deg(108.0)).abs() < 1e-12 && (j[2].size() - 3.0 * h / b2).abs() < 1e-9);
    // a law continuous in acceleration has no jumps at all
    assert!(
        program(h, "rise 120 sine; dwell 60; return 120 poly345; dwell 60")
            .jumps()
            .is_empty()
    );
}

/// The diagram over [0°, 360°] has no slanted spike: between two samples at
/// different angles the acceleration changes by at most max|s‴|·Δφ (cosine:
/// |s‴| ≤ hπ³/(2β³)); every jump appears as two points at one angle; the last
/// point is the end of the last phase (a dwell, s″ = 0), not the value at 0°.
#[test]
fn diagram_has_no_false_spike_at_the_wrap() {
    let h = 0.02;
    let p = program(h, "rise 120 cosine; return 120 cosine; dwell 120");
    let jmax = h * PI.powi(3) / (2.0 * deg(120.0).powi(3));
    let d = p.diagram(360);
    assert_eq!(d[0].0, 0.0);
    let (last_phi, last) = d[d.len() - 1];
    assert!((last_phi - TAU).abs() < 1e-15 && last.a == 0.0 && last.s == 0.0);
    assert!((d[0].1.a - h * PI * PI / (2.0 * deg(120.0).powi(2))).abs() < 1e-12);
    for w in d.windows(2) {
        let ((p0, m0), (p1, m1)) = (w[0], w[1]);
        assert!(p1 >= p0);
        if p1 > p0 {
            assert!(
                (m1.a - m0.a).abs() <= jmax * (p1 - p0) * 1.0001 + 1e-15,
                "spike between {p0} and {p1}"
            );
        }
    }
    // the jumps of this program: 0° (dwell → rise), 120° (rise → return: −hπ²/2β² to −hπ²/2β², none), 240°
    let j = p.jumps();
    let phis: Vec<f64> = j.iter().map(|j| j.phi.to_degrees().round()).collect();
    assert_eq!(phis, vec![0.0, 240.0]);
}

/// Constant velocity: s′ = ±h/β inside, so the velocity jumps at both ends of
/// each moving phase (acceleration impulses). A central knife edge on the
/// prime circle r₀ has tan ϑ = (h/β)/(r₀ + s), largest just after the start.
#[test]
fn constant_velocity_law() {
    let (h, r0) = (0.01, 0.04);
    let p = program(h, "rise 90 const-velocity; dwell 90; return 90 const-velocity; dwell 90");
    let v = h / deg(90.0);
    let j = p.jumps();
    let want = [(0.0, 0.0, v), (90.0, v, 0.0), (180.0, 0.0, -v), (270.0, -v, 0.0)];
    assert_eq!(j.len(), 4, "{j:?}");
    for (got, &(phi, b, a)) in j.iter().zip(&want) {
        assert_eq!(got.kind, JumpKind::Velocity);
        assert!((got.phi - deg(phi)).abs() < 1e-12 && (got.before - b).abs() < 1e-12 && (got.after - a).abs() < 1e-12);
    }
    assert!((p.eval(deg(45.0)).s - h / 2.0).abs() < 1e-15);
    let t = task(
        p.clone(),
        FollowerSpec::TranslatingRoller {
            offset: None,
            roller: Some(0.0),
        },
    );
    let d = t.solve_with_r0(r0).unwrap();
    assert!((d.pressure_max_rise - (v / r0).atan()).abs() < 1e-9, "{}", d.pressure_max_rise);
    assert!((d.pressure_max_return - (v / r0).atan()).abs() < 1e-9);
    // a flat face cannot follow a velocity jump
    let t = task(p, FollowerSpec::TranslatingFlat { offset: 0.0 });
    assert!(matches!(t.solve(), Err(CamError::Infeasible(_))));
}

/// Strokes per phase: rise 20 mm, return 10 mm, dwell, return 10 mm; the
/// levels follow from the cosine law s = level ± h(1 − cos πx)/2.
#[test]
fn strokes_per_phase() {
    let text = "rise 90 cosine 20mm; dwell 30; return 60 cosine 10mm; dwell 20; return 60 cosine 10mm; dwell 100";
    let p = Program::from_phases(spec::parse_phases(text).unwrap()).unwrap();
    let cosine = |x: f64| (1.0 - (PI * x).cos()) / 2.0;
    for (phi, s) in [
        (45.0, 0.020 * cosine(0.5)),
        (100.0, 0.020),
        (130.0, 0.020 - 0.010 * cosine(10.0 / 60.0)),
        (190.0, 0.010),
        (230.0, 0.010 - 0.010 * cosine(30.0 / 60.0)),
        (300.0, 0.0),
    ] {
        assert!((p.eval(deg(phi)).s - s).abs() < 1e-15, "φ = {phi}: {} vs {s}", p.eval(deg(phi)).s);
    }
    assert_eq!(p.stroke(), 0.020);
    // with a program stroke, phases without their own take it
    let q = Program::new(
        0.010,
        spec::parse_phases("rise 90 cosine 20mm; return 90 cosine; return 90 cosine; dwell 90").unwrap(),
    )
    .unwrap();
    assert!((q.eval(deg(270.0)).s).abs() < 1e-15 && (q.eval(deg(90.0)).s - 0.020).abs() < 1e-15);
    // the rises must add up to the returns
    let e = Program::from_phases(spec::parse_phases("rise 90 cosine 20mm; return 90 cosine 10mm; dwell 180").unwrap()).unwrap_err();
    assert!(matches!(&e, CamError::Sequence(m) if m.contains("add up")), "{e}");
    // and no return may go below the lowest position
    let e = Program::from_phases(spec::parse_phases("rise 90 cosine 10mm; return 90 cosine 20mm; rise 90 cosine 10mm; dwell 90").unwrap())
        .unwrap_err();
    assert!(matches!(&e, CamError::Sequence(m) if m.contains("below")), "{e}");
    // a stroke without a unit is ambiguous; an angle stroke for a translating follower is refused
    assert!(spec::parse_phases("rise 90 cosine 20; return 90 cosine 20mm; dwell 180").is_err());
    let p = Program::from_phases(spec::parse_phases("rise 180 sine 15°; return 180 sine 15°").unwrap()).unwrap();
    let t = task(
        p,
        FollowerSpec::TranslatingRoller {
            offset: None,
            roller: None,
        },
    );
    assert!(matches!(t.solve(), Err(CamError::Dimension { field: "stroke", .. })));
}

/// The largest pressure angle of a given cam, from the geometry of its pitch
/// curve: in the cam frame P(φ) = R(−φ)·B(φ); the angle between the curve's
/// normal and the direction B moves in, by central differences.
fn pressure_by_geometry(t: &CamTask, mech: &Mechanism) -> f64 {
    let p = &t.program;
    let n = 20_000;
    let rot = |(x, y): (f64, f64), a: f64| (x * a.cos() - y * a.sin(), x * a.sin() + y * a.cos());
    let b_of = |phi: f64| -> (f64, (f64, f64)) {
        let s = p.eval(phi).s;
        match *mech {
            Mechanism::TranslatingRoller { e, s0, .. } => (s, (e, s0 + s)),
            Mechanism::OscillatingRoller {
                pivot, arm, psi0, kappa, ..
            } => {
                let psi = psi0 + kappa * s;
                (s, (pivot.x + arm * psi.cos(), pivot.y + arm * psi.sin()))
            }
            _ => unreachable!(),
        }
    };
    let mut best = 0.0f64;
    let hstep = 1e-6;
    for i in 1..n {
        let phi = TAU * i as f64 / n as f64;
        let (_, b) = b_of(phi);
        let (_, bp) = b_of(phi + hstep);
        let (_, bm) = b_of(phi - hstep);
        // direction of B's motion in the frame (dwells have none)
        let (dx, dy) = (bp.0 - bm.0, bp.1 - bm.1);
        if dx.hypot(dy) < 1e-12 {
            continue;
        }
        let pp = rot(bp, -(phi + hstep));
        let pm = rot(bm, -(phi - hstep));
        let (tx, ty) = (pp.0 - pm.0, pp.1 - pm.1);
        let dir = rot((dx, dy), -phi);
        // angle between the normal and the motion = 90° − angle between tangent and motion
        let cos_t = ((tx * dir.0 + ty * dir.1) / (tx.hypot(ty) * dir.0.hypot(dir.1))).abs();
        best = best.max(PI / 2.0 - cos_t.min(1.0).acos());
        let _ = b;
    }
    best
}

/// The textbook problem: a given cam (prime circle r₀, offset e; or pivot
/// distance a, arm l, r₀) and its pressure angles.
#[test]
fn given_cam_is_analysed() {
    let p = program(0.015, "rise 120 sine; dwell 30; return 90 cosine; dwell 120");
    let t = task(
        p.clone(),
        FollowerSpec::TranslatingRoller {
            offset: Some(0.006),
            roller: Some(0.005),
        },
    );
    let d = t.solve_with_r0(0.04).unwrap();
    let Mechanism::TranslatingRoller { e, s0, .. } = d.mechanism else {
        panic!()
    };
    assert!((e - 0.006).abs() < 1e-15 && (e.hypot(s0) - 0.04).abs() < 1e-15 && (d.r0 - 0.04).abs() < 1e-15);
    let geo = pressure_by_geometry(&t, &d.mechanism);
    assert!(
        (d.pressure_max_rise.max(d.pressure_max_return) - geo).abs() < 1e-5,
        "{} {} vs {geo}",
        d.pressure_max_rise,
        d.pressure_max_return
    );
    // oscillating: |OA| = a, |AB0| = l, |OB0| = r0, and the same geometric check
    let po = program(deg(20.0), "rise 120 sine; dwell 30; return 120 cosine; dwell 90");
    let t = task(
        po,
        FollowerSpec::OscillatingRoller {
            arm: 0.1,
            pivot: Some(0.12),
            roller: Some(0.0),
        },
    );
    let d = t.solve_with_r0(0.05).unwrap();
    let Mechanism::OscillatingRoller { pivot, arm, psi0, .. } = d.mechanism else {
        panic!()
    };
    let b0 = (pivot.x + arm * psi0.cos(), pivot.y + arm * psi0.sin());
    assert!((pivot.x.hypot(pivot.y) - 0.12).abs() < 1e-15 && (b0.0.hypot(b0.1) - 0.05).abs() < 1e-12);
    let geo = pressure_by_geometry(&t, &d.mechanism);
    assert!(
        (d.pressure_max_rise.max(d.pressure_max_return) - geo).abs() < 1e-5,
        "{} vs {geo}",
        d.pressure_max_rise
    );
    // impossible dimensions are refused, naming the quantity
    assert!(matches!(t.solve_with_r0(0.5), Err(CamError::Dimension { field: "r0", .. })));
    let tt = task(
        p,
        FollowerSpec::TranslatingRoller {
            offset: Some(0.05),
            roller: None,
        },
    );
    assert!(matches!(tt.solve_with_r0(0.04), Err(CamError::Dimension { field: "offset", .. })));
}

/// ω = 1e110 rad/s: ω³·s‴ overflows; refused as `omega`, not a NaN or an infinity.
#[test]
fn absurd_cam_speed_is_refused() {
    let mut t = task(
        program(0.013, "rise 108 sine; dwell 15; return 108 sine; dwell 129"),
        FollowerSpec::TranslatingRoller {
            offset: None,
            roller: None,
        },
    );
    t.omega = 1e110;
    assert!(matches!(t.solve(), Err(CamError::Dimension { field: "omega", .. })));
    t.omega = 1e3;
    assert!(t.solve().is_ok());
}
