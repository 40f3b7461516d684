//! The cylinder-driven mechanism with the piston's travel s as its
//! coordinate (BMSTU textbook П5), checked independently: the analogues
//! against finite differences of the positions, the reduced mass against
//! the kinetic energy from finite differences, the reduced force against
//! the potential energy, the control force's zero work against the change
//! of potential energy, V(s) and t(s) against a time integration of the
//! equation of motion, the kinetostatics' balancing force against virtual
//! power and the equation of motion.

use tmm_geom::Vec2;
use tmm_linkage::dynamics::DynamicsError;
use tmm_linkage::dynamics::rk::Adaptive;
use tmm_linkage::linear::{CylinderDrive, CylinderMasses, CylinderMotion, CylinderState, EndReached, kinetostatics, reduced::reduce};
use tmm_linkage::synthesis::cylinder::{CylinderRequest, PressureAt, synthesize};

/// П5's mechanism: the synthesis of П1.5 variant 1, the load at l_AK =
/// 0.2 m, α = 150°, l_CS2 = l_шт/2, and its masses.
fn p5() -> (CylinderDrive, CylinderMasses) {
    let s = synthesize(&CylinderRequest {
        h_min: 0.05,
        h_max: 0.3,
        rod: 0.39,
        swing: 60f64.to_radians(),
        pressure: PressureAt::End(50f64.to_radians()),
        frame_y: Some(0.05),
        drive: Default::default(),
        limits: Default::default(),
    })
    .unwrap();
    let d = s.frame.iter().find(|(n, _)| n == "D").unwrap().1;
    let phi1 = s.angles.iter().find(|(n, _)| n == "phi1").unwrap().1;
    let drive = CylinderDrive::new(d, s.length("OB").unwrap(), 0.05, 0.3, 0.39, phi1)
        .unwrap()
        .with_rod_center(0.195)
        .with_load(0.2, 150f64.to_radians());
    let m = CylinderMasses {
        lever_mass: 10.0,
        lever_inertia: 1.0,
        piston_mass: 10.0,
        piston_inertia: 0.5,
        cylinder_mass: 10.0,
        cylinder_inertia: 2.0,
        load_mass: 100.0,
        gravity: 9.81,
    };
    (drive, m)
}

fn state(d: &CylinderDrive, s: f64) -> CylinderState {
    let mut st = CylinderState::default();
    d.solve(s, &mut st).unwrap();
    st
}

#[test]
fn p5_starts_at_the_synthesis_position_and_ends_turned_by_beta() {
    let (d, _) = p5();
    let (a, b) = (state(&d, 0.0), state(&d, d.travel()));
    let turn = (b.phi1 - a.phi1).to_degrees();
    assert!((turn - 60.0).abs() < 1e-9, "{turn}");
    assert!((b.pressure_angle.to_degrees() - 50.0).abs() < 1e-9);
    // the lever's pin is at l_AB from A, |DB| = h + s + l_шт
    assert!(((b.b.p - d.d).hypot() - 0.69).abs() < 1e-12);
}

#[test]
fn analogues_are_the_derivatives_of_the_positions() {
    let (d, _) = p5();
    let h = 1e-4;
    for k in 1..10 {
        let s = d.travel() * k as f64 / 10.0;
        let (m, c, p) = (state(&d, s - h), state(&d, s), state(&d, s + h));
        let fd1 = |a: f64, b: f64| (b - a) / (2.0 * h);
        let fd2 = |a: f64, x: f64, b: f64| (a - 2.0 * x + b) / (h * h);
        assert!((c.omega_q1 - fd1(m.phi1, p.phi1)).abs() < 1e-6, "ω_q1 at {s}");
        assert!((c.omega_q3 - fd1(m.phi3, p.phi3)).abs() < 1e-6, "ω_q3 at {s}");
        assert!((c.eps_q1 - fd2(m.phi1, c.phi1, p.phi1)).abs() < 1e-4, "ε_q1 at {s}");
        assert!((c.eps_q3 - fd2(m.phi3, c.phi3, p.phi3)).abs() < 1e-4, "ε_q3 at {s}");
        for (pm, pc, pp) in [(m.b, c.b, p.b), (m.c, c.c, p.c), (m.s2, c.s2, p.s2), (m.k, c.k, p.k)] {
            let v = (pp.p - pm.p) / (2.0 * h);
            let a = (pm.p - pc.p * 2.0 + pp.p) / (h * h);
            assert!((pc.v - v).hypot() < 1e-6, "V_q at {s}");
            assert!((pc.a - a).hypot() < 1e-4, "a_q at {s}");
        }
    }
}

#[test]
fn reduced_mass_is_twice_the_kinetic_energy_at_unit_speed() {
    let (d, m) = p5();
    let h = 1e-5;
    let mut st = CylinderState::default();
    for k in 0..=10 {
        let s = (d.travel() * k as f64 / 10.0).clamp(h, d.travel() - h);
        let (a, b) = (state(&d, s - h), state(&d, s + h));
        // velocities at ds/dt = 1 from positions alone
        let v = |pa: Vec2, pb: Vec2| (pb - pa) / (2.0 * h);
        let (w1, w3) = ((b.phi1 - a.phi1) / (2.0 * h), (b.phi3 - a.phi3) / (2.0 * h));
        let t2 = m.lever_inertia * w1 * w1
            + (m.piston_inertia + m.cylinder_inertia) * w3 * w3
            + m.piston_mass * v(a.s2.p, b.s2.p).hypot2()
            + m.load_mass * v(a.k.p, b.k.p).hypot2();
        let r = reduce(&d, &m, s, &mut st).unwrap();
        assert!((r.mass - t2).abs() < 1e-7 * t2, "m_пр at {s}: {} vs {t2}", r.mass);
        // m′ and F_C against differences of the model itself and of the potential energy
        let (ra, rb) = (reduce(&d, &m, s - h, &mut st).unwrap(), reduce(&d, &m, s + h, &mut st).unwrap());
        assert!((r.mass_derivative - (rb.mass - ra.mass) / (2.0 * h)).abs() < 1e-5 * r.mass.max(1.0));
        let pot = |x: &CylinderState| m.gravity * (m.piston_mass * x.s2.p.y + m.load_mass * x.k.p.y);
        let f = -(pot(&b) - pot(&a)) / (2.0 * h);
        assert!((r.force - f).abs() < 1e-6 * f.abs().max(1.0), "F_прC at {s}");
    }
}

#[test]
fn control_force_does_the_work_the_load_takes() {
    let (d, m) = p5();
    let mo = CylinderMotion::compute(&d, &m, 0.18, 200).unwrap();
    let (a, b) = (state(&d, 0.0), state(&d, d.travel()));
    // A_C is the loss of potential energy of the rod and the load
    let dpot = m.gravity * (m.piston_mass * (b.s2.p.y - a.s2.p.y) + m.load_mass * (b.k.p.y - a.k.p.y));
    assert!(
        (mo.resistance_work + dpot).abs() < 1e-10 * dpot.abs(),
        "{} {dpot}",
        mo.resistance_work
    );
    // the control force's work returns it: F_H s_c + (F_H + F_K)(s_max − s_c)/2
    let c = mo.control;
    let w = c.start * c.switch + 0.5 * (c.start + c.end) * (c.travel - c.switch);
    assert!((w - dpot).abs() < 1e-10 * dpot);
    // F_K holds the load: the gravity's reduced force at s_max, by potential differences
    let h = 1e-6;
    let (p, q) = (state(&d, d.travel() - 2.0 * h), state(&d, d.travel()));
    let pot = |x: &CylinderState| m.gravity * (m.piston_mass * x.s2.p.y + m.load_mass * x.k.p.y);
    assert!((c.end - (pot(&q) - pot(&p)) / (2.0 * h)).abs() < 1e-3 * c.end);
    assert!(matches!(mo.end, EndReached::Asymptotic { time_constant: Some(_) }));
    let last = mo.rows.last().unwrap();
    assert_eq!(last.time, None);
    assert!(last.speed.abs() < 1e-6 && last.total.abs() < 1e-9 * c.end);
}

#[test]
fn speed_and_time_follow_a_time_integration() {
    let (d, m) = p5();
    let mo = CylinderMotion::compute(&d, &m, 0.18, 200).unwrap();
    let mut st = CylinderState::default();
    let mut rhs = |_t: f64, y: &[f64; 2]| -> Result<[f64; 2], DynamicsError> {
        let r = reduce(&d, &m, y[0], &mut st)?;
        let f = r.force + mo.control.force(y[0]);
        Ok([y[1], (f - 0.5 * r.mass_derivative * y[1] * y[1]) / r.mass])
    };
    let f0 = rhs(0.0, &[0.0, 0.0]).unwrap();
    let mut ode = Adaptive::new(0.0, [0.0, 0.0], f0, 1e-4, 1e-2, 1e-11, [1e-13, 1e-13]);
    let mut checked = 0;
    for row in mo.rows.iter().skip(1) {
        let Some(t) = row.time else { break };
        if row.reduced.s > 0.95 * d.travel() {
            break;
        }
        while ode.t < t {
            ode.step(&mut rhs).unwrap();
        }
        let (y, _) = ode.state_at(t, &mut rhs).unwrap();
        assert!(
            (y[0] - row.reduced.s).abs() < 1e-6 * d.travel(),
            "s at t = {t}: {} vs {}",
            y[0],
            row.reduced.s
        );
        assert!(
            (y[1] - row.speed).abs() < 1e-5 * row.speed.max(0.01),
            "V at s = {}: {} vs {}",
            row.reduced.s,
            y[1],
            row.speed
        );
        checked += 1;
    }
    assert!(checked > 150);
}

#[test]
fn balancing_force_is_the_control_force_with_the_true_motion() {
    let (d, m) = p5();
    let mo = CylinderMotion::compute(&d, &m, 0.18, 200).unwrap();
    let mut st = CylinderState::default();
    for s in [0.02, 0.1, 0.15, 0.2, 0.24] {
        let (v, a) = mo.motion_at(s, &mut st).unwrap();
        let k = kinetostatics(&d, &m, &st, v, a).unwrap();
        let f = mo.control.force(s);
        assert!(
            (k.balancing - f).abs() < 1e-6 * f.abs(),
            "at {s}: F_ур {} vs F_прДВ {f}",
            k.balancing
        );
        // the frame's reactions with gravity and inertia balance the whole machine
        let g = Vec2::new(0.0, -m.gravity);
        let total = k.r_a + k.r_d + g * (m.lever_mass + m.piston_mass + m.cylinder_mass + m.load_mass) + k.inertia_piston + k.inertia_load;
        assert!(total.hypot() < 1e-9 * k.r_a.hypot().max(1.0), "{total:?}");
    }
}

#[test]
fn a_travel_the_lever_cannot_follow_is_located() {
    let e = CylinderDrive::new(Vec2::new(0.6, 0.05), 0.3, 0.05, 0.6, 0.39, 1.6).unwrap_err();
    let t = e.to_string();
    assert!(t.starts_with("cylinder.h_max") && t.contains("at s = "), "{t}");
}

#[test]
fn a_control_force_that_cannot_lift_is_located() {
    let (d, m) = p5();
    // switching at 0.1 m the zero-work level is too low to carry the load on
    let e = CylinderMotion::compute(&d, &m, 0.1, 200).unwrap_err().to_string();
    assert!(e.starts_with("cylinder.switch: the control force cannot lift the load"), "{e}");
    let at: f64 = e.split("from s = ").nth(1).unwrap().split(' ').next().unwrap().parse().unwrap();
    // A_Σ there by the potential energy and the law's trapezoids: zero, positive before
    let (a0, b0) = (state(&d, 0.0), state(&d, d.travel()));
    let pot = |x: &CylinderState| m.gravity * (m.piston_mass * x.s2.p.y + m.load_mass * x.k.p.y);
    let lift = pot(&b0) - pot(&a0);
    let (sc, smax) = (0.1, d.travel());
    let fk = CylinderMotion::compute(&d, &m, 0.18, 50).unwrap().control.end;
    let fh = (lift - fk * 0.5 * (smax - sc)) / (0.5 * (smax + sc));
    let work = |s: f64| {
        let drive = if s <= sc {
            fh * s
        } else {
            fh * sc + (s - sc) * (fh + (fh + (fk - fh) * (s - sc) / (smax - sc))) * 0.5
        };
        drive - (pot(&state(&d, s)) - pot(&a0))
    };
    assert!(work(at).abs() < 1e-5 * lift, "A_Σ({at}) = {}", work(at));
    assert!(work(at - 0.01) > 0.0 && work(at + 0.01) < 0.0);
    // and switching at the end of the travel the end is reached in a finite time
    let mo = CylinderMotion::compute(&d, &m, smax, 200).unwrap();
    assert!(matches!(mo.end, EndReached::Finite { time } if time > 0.0));
}
