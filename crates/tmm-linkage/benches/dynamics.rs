//! The whole dynamics of the seed-001 four-bar (10 kg/m, J_S = 0.1·m·l²,
//! 380 N·m on the rocker, δ = 0.02): the reduced model on 3600 intervals,
//! the work, the three flywheel methods, the motion and the steady cycle
//! re-integrated in time; and the same driven by an induction motor, with
//! the run-up from rest to the steady cycle.

use divan::black_box;
use tmm_linkage::dynamics::{DrivingMoment, Dynamics, DynamicsSpec, Motor};

#[path = "../tests/common/mod.rs"]
mod common;

fn main() {
    divan::main();
}

/// Constant driving moment (the course's assumption).
#[divan::bench]
fn seed001_constant_moment(b: divan::Bencher) {
    let m = common::seed001();
    let l = common::seed001_loads(&m);
    let spec = DynamicsSpec::new(0.02);
    b.bench(|| black_box(Dynamics::compute(black_box(&m), &l, &spec).unwrap().required.exact));
}

/// An induction motor (1500 rpm synchronous, 1400 rpm nominal, 60 N·m,
/// ratio 1.55) with the run-up from rest.
#[divan::bench]
fn seed001_motor_runup(b: divan::Bencher) {
    let m = common::seed001();
    let l = common::seed001_loads(&m);
    let mut spec = DynamicsSpec::new(0.02);
    spec.driving = DrivingMoment::Motor(Motor {
        synchronous_speed: 157.08,
        nominal_speed: 146.6,
        nominal_torque: 60.0,
        ratio: 1.55,
    });
    b.bench(|| black_box(Dynamics::compute(black_box(&m), &l, &spec).unwrap().runup.map(|r| r.time)));
}
