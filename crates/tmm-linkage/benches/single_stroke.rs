//! The unsteady single stroke of the textbook's П4 press (Chernaya &
//! Timofeev 2019, p. 137–142): the motor-driven stroke integrated in time
//! to the event φ = 2π (target: under 50 ms), the constant-moment stroke by
//! the energy method, and everything (both and the check by RK4 in φ).

use divan::black_box;
use tmm_linkage::dynamics::single_stroke::integrate;
use tmm_linkage::dynamics::{EnergyStroke, KlossMotor, Reducer, SingleStroke, StrokeSpec};
use tmm_linkage::forces::stroke::Working;

#[path = "../tests/common/mod.rs"]
mod common;

fn main() {
    divan::main();
}

fn spec() -> StrokeSpec {
    let tau = 2.0 * std::f64::consts::PI;
    let mut s = StrokeSpec::new(
        KlossMotor {
            synchronous_speed: tau * 16.7,
            breakdown_speed: tau * 12.3,
            breakdown_torque: 5.24e3,
            ratio: 18.6,
        },
        140e3,
    );
    s.working = Working::Decreasing;
    s.design_angle = Some(120f64.to_radians());
    s
}

/// The motor-driven stroke alone, 360 output intervals.
#[divan::bench]
fn p4_motor_stroke(b: divan::Bencher) {
    let m = common::press();
    let l = common::press_loads(&m, 35e6);
    let sp = spec();
    let red = Reducer::new(&m, &l, sp.working).unwrap();
    let mut sol = red.solution();
    b.bench_local(|| black_box(integrate(&red, &sp, &mut sol).unwrap().cycle_time));
}

/// The constant-moment stroke by the energy method.
#[divan::bench]
fn p4_constant_moment(b: divan::Bencher) {
    let m = common::press();
    let l = common::press_loads(&m, 35e6);
    let sp = spec();
    let red = Reducer::new(&m, &l, sp.working).unwrap();
    let mut sol = red.solution();
    b.bench_local(|| black_box(EnergyStroke::compute(&red, &sp, &mut sol).unwrap().time_end));
}

/// Both models and the check (what `tmm run` computes).
#[divan::bench]
fn p4_whole(b: divan::Bencher) {
    let m = common::press();
    let l = common::press_loads(&m, 35e6);
    let sp = spec();
    b.bench(|| black_box(SingleStroke::compute(&m, &l, &sp).unwrap().motor.cycle_time));
}
