//! The unsteady single stroke of the П4 press (Chernaya & Timofeev 2019,
//! p. 137–142): the motor-driven stroke against a second integrator (RK4 in
//! the crank angle) and against the energy balance with the deformation and
//! gravity work in closed form, Kloss's curve at its breakdown point, the
//! constant-moment model against its closed form, the stall located.

use std::f64::consts::PI;

use tmm_linkage::dynamics::single_stroke::by_angle;
use tmm_linkage::dynamics::{KlossMotor, SingleStroke, StrokeSpec};
use tmm_linkage::forces::stroke::Working;

use crate::common::{press, press_loads};

fn motor() -> KlossMotor {
    KlossMotor {
        synchronous_speed: 2.0 * PI * 16.7,
        breakdown_speed: 2.0 * PI * 12.3,
        breakdown_torque: 5.24e3,
        ratio: 18.6,
    }
}

fn spec() -> StrokeSpec {
    let mut s = StrokeSpec::new(motor(), 140e3);
    s.working = Working::Decreasing;
    s.design_angle = Some(120f64.to_radians());
    s
}

#[test]
fn explore() {
    let m = press();
    let l = press_loads(&m, 35e6);
    let t = std::time::Instant::now();
    let s = SingleStroke::compute(&m, &l, &spec()).unwrap();
    eprintln!("{:?}", t.elapsed());
    for r in s.motor.rows.iter().step_by(15) {
        eprintln!("{:7.2} h={:.4} I={:.1} Mc={:.1} Md={:.1} w={:.5} e={:.4} t={:.5}", r.phi.to_degrees(), r.travel, r.inertia_total, r.moment_loads, r.moment_motor, r.omega, r.epsilon, r.time);
    }
    eprintln!("tc {} wend {} wmin {} at {} crossings {:?} bal {:?} steps {:?}", s.motor.cycle_time, s.motor.omega_end, s.motor.omega_min, s.motor.phi_omega_min.to_degrees(), s.motor.crossings, s.motor.balance, s.motor.steps);
    eprintln!("check {:?}", s.check);
    eprintln!("energy: A {} w {} t {} wmin {} design {:?}", s.energy.work_end, s.energy.omega_end, s.energy.time_end, s.energy.omega_min, s.energy.design);
}
