//! The unsteady single stroke of the П4 press (Chernaya & Timofeev 2019,
//! p. 137–142; examples/textbook/p4-press.toml): the motor-driven stroke
//! against a second, different integrator (RK4 on the energy equation in
//! the crank angle), against the energy balance with the deformation and
//! gravity work and the reduced inertia in closed form (the book's
//! kinematics written out here and differentiated numerically), Kloss's
//! curve at its breakdown point, the constant-moment model against its
//! closed form, the dynamic characteristic, and the stall located.

use std::f64::consts::PI;

use tmm_linkage::dynamics::single_stroke::by_angle;
use tmm_linkage::dynamics::{DynamicsError, KlossMotor, SingleStroke, StrokeSpec};
use tmm_linkage::forces::stroke::Working;

use crate::common::{press, press_loads};

const R: f64 = 0.2;
const L: f64 = 0.94;
const M2: f64 = 30e3;
const J2: f64 = 5e3;
const M3: f64 = 50e3;
const G: f64 = 9.81;
const F_MAX: f64 = 35e6;
const I_I: f64 = 140e3;

fn motor() -> KlossMotor {
    KlossMotor {
        synchronous_speed: 2.0 * PI * 16.7,
        breakdown_speed: 2.0 * PI * 12.3,
        breakdown_torque: 5.24e3,
        ratio: 18.6,
    }
}

fn spec() -> StrokeSpec {
    let mut s = StrokeSpec::new(motor(), I_I);
    s.working = Working::Decreasing;
    s.design_angle = Some(120f64.to_radians());
    s
}

/// The book's kinematics at cycle angle φ (crank angle π/2 − φ): the rod's
/// centre S2, its angle, and the ram's height Y_B.
fn closed(phi: f64) -> ((f64, f64), f64, f64) {
    let th = PI / 2.0 - phi;
    let (xa, ya) = (R * th.cos(), R * th.sin());
    let yb = ya - (L * L - xa * xa).sqrt();
    let s2 = (xa + 2.0 / 3.0 * (0.0 - xa), ya + 2.0 / 3.0 * (yb - ya));
    let phi2 = (yb - ya).atan2(-xa);
    (s2, phi2, yb)
}

/// I_II by central differences of the closed-form positions.
fn inertia_variable(phi: f64) -> f64 {
    let h = 1e-5;
    let (a, b) = (closed(phi - h), closed(phi + h));
    let vs = ((b.0.0 - a.0.0) / (2.0 * h), (b.0.1 - a.0.1) / (2.0 * h));
    let mut dphi2 = b.1 - a.1;
    if dphi2 > PI {
        dphi2 -= 2.0 * PI;
    } else if dphi2 < -PI {
        dphi2 += 2.0 * PI;
    }
    let w2 = dphi2 / (2.0 * h);
    let vb = (b.2 - a.2) / (2.0 * h);
    M2 * (vs.0 * vs.0 + vs.1 * vs.1) + J2 * w2 * w2 + M3 * vb * vb
}

/// ∫₀^h F dh of the piecewise-linear table, exactly.
fn deformation_work(h: f64) -> f64 {
    let knots = [(0.0, 0.0), (0.6, 0.0), (0.62, 0.1), (0.75, 0.2), (1.0, 1.0)];
    let x = (h / 0.4).clamp(0.0, 1.0);
    let mut w = 0.0;
    for k in 1..knots.len() {
        let (x0, f0) = knots[k - 1];
        let (x1, f1) = knots[k];
        if x <= x0 {
            break;
        }
        let xe = x.min(x1);
        let fe = f0 + (f1 - f0) * (xe - x0) / (x1 - x0);
        w += 0.5 * (f0 + fe) * (xe - x0);
    }
    w * 0.4 * F_MAX
}

/// The work of the loads from the start to φ: gravity on links 2, 3 and the
/// deformation force on the down-stroke (φ ≤ π).
fn loads_work(phi: f64) -> f64 {
    let (s0, _, yb0) = closed(0.0);
    let (s, _, yb) = closed(phi);
    let gravity = -G * (M2 * (s.1 - s0.1) + M3 * (yb - yb0));
    let h = if phi <= PI { yb0 - yb } else { 0.4 };
    gravity - deformation_work(h)
}

#[test]
fn kloss_curve_peaks_at_its_breakdown_point() {
    let m = motor();
    let (w0, wk, mk) = (m.synchronous_speed, m.breakdown_speed, m.breakdown_torque);
    let sk = 1.0 - wk / w0;
    // the first form of the formula, 2·M_K/(S/S_K + S_K/S)
    for w in [0.0, 20.0, 50.0, wk, 90.0, 100.0, 104.0] {
        let s = 1.0 - w / w0;
        let closed = 2.0 * mk / (s / sk + sk / s);
        assert!((m.torque(w) - closed).abs() <= 1e-9 * mk, "{w}");
    }
    assert!((m.torque(wk) - mk).abs() < 1e-9 * mk);
    assert_eq!(m.torque(w0), 0.0);
    // a maximum: zero slope there, and nothing larger on a fine grid
    let h = 1e-4;
    let slope = (m.torque(wk + h) - m.torque(wk - h)) / (2.0 * h);
    assert!(slope.abs() < 1e-6 * mk / wk, "{slope}");
    let best = (0..=100_000)
        .map(|k| w0 * k as f64 / 100_000.0)
        .max_by(|a, b| m.torque(*a).total_cmp(&m.torque(*b)))
        .unwrap();
    assert!((best - wk).abs() <= w0 / 100_000.0, "{best} {wk}");
    // reduced to the crank: u·M at ω = ω_K/u
    assert!((m.crank_moment(wk / m.ratio) - m.ratio * mk).abs() < 1e-9 * m.ratio * mk);
}

#[test]
fn press_stroke_agrees_with_rk4_in_the_crank_angle() {
    let m = press();
    let l = press_loads(&m, F_MAX);
    let s = SingleStroke::compute(&m, &l, &spec()).unwrap();
    let mut sol = s.reducer.solution();
    // RK4's error with 160 000 steps is some 1e-8 here (the load table's
    // knots fall between its steps)
    let c = by_angle(&s.reducer, &s.spec, 160_000, &mut sol).unwrap();
    let mo = &s.motor;
    assert!(
        (c.cycle_time / mo.cycle_time - 1.0).abs() < 3e-8,
        "{} {}",
        c.cycle_time,
        mo.cycle_time
    );
    assert!((c.omega_end / mo.omega_end - 1.0).abs() < 3e-8, "{} {}", c.omega_end, mo.omega_end);
    assert!((c.motor_work / mo.balance.motor_work - 1.0).abs() < 1e-7);
    // the event is the end of the cycle, not the end of a window
    assert!((mo.rows.last().unwrap().phi - 2.0 * PI).abs() < 1e-12);
    assert!(mo.cycle_time > 2.0 && mo.cycle_time < 4.0);
}

#[test]
fn press_stroke_keeps_the_energy_balance_at_every_row() {
    let m = press();
    let l = press_loads(&m, F_MAX);
    let s = SingleStroke::compute(&m, &l, &spec()).unwrap();
    let w0 = s.spec.start_speed;
    let t0 = 0.5 * (I_I + inertia_variable(0.0)) * w0 * w0;
    for r in &s.motor.rows {
        let i = I_I + inertia_variable(r.phi);
        assert!((r.inertia_total / i - 1.0).abs() < 1e-8, "I at {}", r.phi);
        let de = 0.5 * i * r.omega * r.omega - t0;
        let work = r.motor_work + loads_work(r.phi);
        assert!(
            (de - work).abs() < 1e-7 * t0,
            "φ = {}°: ΔT {de} against W {work}",
            r.phi.to_degrees()
        );
        // the ram's travel
        let h = closed(0.0).2 - closed(r.phi).2;
        assert!((r.travel - h).abs() < 1e-9);
    }
    // over the cycle: motor work − deformation work (gravity does none) = ΔT
    let b = &s.motor.balance;
    let w_def = deformation_work(0.4);
    assert!((b.loads_work + w_def).abs() < 1e-8 * w_def, "{} {}", b.loads_work, w_def);
    assert!((b.motor_work - w_def - (b.kinetic_end - b.kinetic_start)).abs() < 1e-7 * t0);
    assert!(b.residual.abs() < 1e-8, "{}", b.residual);
}

#[test]
fn breakdown_speed_crossing_is_where_the_speed_passes_it() {
    let m = press();
    let s = SingleStroke::compute(&m, &press_loads(&m, F_MAX), &spec()).unwrap();
    let wk = motor().crank_breakdown_speed();
    let mo = &s.motor;
    assert_eq!(mo.crossings.len(), 1, "{:?}", mo.crossings);
    let c = mo.crossings[0];
    assert!(c.falling);
    for r in &mo.rows {
        if r.phi < c.phi - 1e-9 {
            assert!(r.omega > wk, "{} {}", r.phi, r.omega);
        } else if r.phi > c.phi + 1e-9 {
            assert!(r.omega < wk, "{} {}", r.phi, r.omega);
        }
    }
    // it is crossed in the deformation (h > 0.6·H), on the down-stroke
    assert!(c.travel > 0.6 * 0.4 && c.phi < PI);
    assert!((mo.time_below_breakdown - (mo.cycle_time - c.time)).abs() < 1e-12);
}

#[test]
fn constant_moment_model_is_its_closed_form() {
    let m = press();
    let s = SingleStroke::compute(&m, &press_loads(&m, F_MAX), &spec()).unwrap();
    let e = &s.energy;
    let md = 18.6 * 5.24e3;
    assert!((e.driving_moment - md).abs() < 1e-9 * md);
    let w0 = s.spec.start_speed;
    let i0 = I_I + inertia_variable(0.0);
    for r in &e.rows {
        let a = md * r.phi + loads_work(r.phi);
        let w = ((2.0 * a + w0 * w0 * i0) / (I_I + inertia_variable(r.phi))).sqrt();
        assert!((r.omega / w - 1.0).abs() < 1e-8, "φ = {}°: {} {}", r.phi.to_degrees(), r.omega, w);
        assert!((r.work_total - a).abs() < 1e-8 * md * 2.0 * PI);
    }
    // t(2π) = ∫dφ/ω by Simpson's rule on the closed form, 20 000 intervals
    // over each half-turn (1/ω is smooth on each, kinked only by the table)
    let om = |phi: f64| {
        let a = md * phi + loads_work(phi);
        ((2.0 * a + w0 * w0 * i0) / (I_I + inertia_variable(phi))).sqrt()
    };
    let n = 200_000;
    let h = 2.0 * PI / n as f64;
    let t: f64 = (0..n)
        .map(|k| {
            let a = k as f64 * h;
            h / 6.0 * (1.0 / om(a) + 4.0 / om(a + 0.5 * h) + 1.0 / om(a + h))
        })
        .sum();
    assert!((e.time_end / t - 1.0).abs() < 1e-7, "{} {t}", e.time_end);
}

#[test]
fn dynamic_characteristic_against_rk4_and_the_static_limit() {
    let m = press();
    let l = press_loads(&m, F_MAX);
    let mut sp = spec();
    sp.time_constant = 0.05;
    let s = SingleStroke::compute(&m, &l, &sp).unwrap();
    let mut sol = s.reducer.solution();
    let c = by_angle(&s.reducer, &sp, 160_000, &mut sol).unwrap();
    assert!(
        (c.cycle_time / s.motor.cycle_time - 1.0).abs() < 3e-8,
        "{} {}",
        c.cycle_time,
        s.motor.cycle_time
    );
    assert!(
        (c.omega_end / s.motor.omega_end - 1.0).abs() < 3e-8,
        "{} {}",
        c.omega_end,
        s.motor.omega_end
    );
    // the lag changes the stroke; a tiny lag does not
    let stat = SingleStroke::compute(&m, &l, &spec()).unwrap();
    assert!((s.motor.cycle_time - stat.motor.cycle_time).abs() > 1e-3);
    sp.time_constant = 1e-3;
    let tiny = SingleStroke::compute(&m, &l, &sp).unwrap();
    assert!((tiny.motor.cycle_time / stat.motor.cycle_time - 1.0).abs() < 2e-3);
    assert!(tiny.check.is_some());
}

#[test]
fn a_stall_is_located_where_the_energy_runs_out() {
    let m = press();
    // twice the deformation force: the flywheel's energy (2.2 MJ) and the
    // motor cannot forge 4.8 MJ
    let l = press_loads(&m, 2.0 * F_MAX);
    let err = SingleStroke::compute(&m, &l, &spec()).unwrap_err();
    let DynamicsError::Spec { field, message } = &err else {
        panic!("{err:?}")
    };
    assert_eq!(field, "dynamics");
    assert!(message.contains("stalls in the motor-driven stroke"), "{message}");
    assert!(message.contains("working stroke") && message.contains("`3`"), "{message}");
    // the angle where it stops: in the deformation zone, before the bottom
    let at = message
        .split("φ = ")
        .nth(1)
        .unwrap()
        .split('°')
        .next()
        .unwrap()
        .parse::<f64>()
        .unwrap();
    let h_at = closed(0.0).2 - closed(at.to_radians()).2;
    assert!(h_at > 0.6 * 0.4 && at < 180.0, "{at}° h = {h_at}");
    // there the energy is spent: the kinetic energy of the start and the
    // motor's work (at most u·M_K per radian) fall short of the loads' work
    let w_max = 18.6 * 5.24e3 * at.to_radians();
    let t0 = 0.5 * (I_I + inertia_variable(0.0)) * motor().crank_synchronous_speed().powi(2);
    let load = -(-G * (M2 * (closed(at.to_radians()).0.1 - closed(0.0).0.1) + M3 * (-h_at)) - 2.0 * deformation_work(h_at));
    assert!(load > t0 && load < t0 + w_max, "{load} {t0} {w_max}");
    // the constant-moment model stalls too, and says so
    let mut sp = spec();
    sp.start_speed = 2.0;
    let err = SingleStroke::compute(&m, &press_loads(&m, F_MAX), &sp).unwrap_err();
    assert!(err.to_string().contains("stalls"), "{err}");
}
