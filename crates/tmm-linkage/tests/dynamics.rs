//! Dynamics of the machine: the reduction checked against kinetic energy and
//! kinetostatics, the flywheel by three methods against each other, a
//! closed form and the time integration, and bad input.

mod common;

use common::*;
use tmm_linkage::Mechanism;
use tmm_linkage::dynamics::*;
use tmm_linkage::forces::{Action, Law, Loads, Resistance};

/// Seed 001 loads: 10 kg/m, J_S = 0.1·m·l², S mid-link, no gravity, 380 N·m
/// on the rocker against its rotation.
fn seed001_loads(m: &Mechanism) -> Loads {
    let lens = [0.12, 0.48, 0.38];
    let mut loads = Loads::new(m);
    for i in 1..=3 {
        let mass = 10.0 * lens[i - 1];
        loads.links[i].mass = mass;
        loads.links[i].inertia = 0.1 * mass * lens[i - 1] * lens[i - 1];
    }
    loads.resistance.push(Resistance {
        link: 3,
        action: Action::Moment { sign: None },
        law: Law::Constant(380.0),
    });
    loads
}

#[test]
fn explore_seed001() {
    let m = seed001();
    let loads = seed001_loads(&m);
    let t = std::time::Instant::now();
    let d = Dynamics::compute(&m, &loads, &DynamicsSpec::new(0.02)).unwrap();
    eprintln!("time {:?}", t.elapsed());
    eprintln!("md {} given {:?}", d.cycle.driving_moment, d.inertia_given);
    eprintln!("req {:?}", d.required);
    eprintln!("exact {:?}", d.exact);
    eprintln!("fw {} {:?}", d.flywheel_inertia, d.flywheel);
    eprintln!(
        "motion {} {} {} {} T={}",
        d.motion.omega_max, d.motion.omega_min, d.motion.omega_mean, d.motion.delta, d.motion.cycle_time
    );
    eprintln!("sim {:?}", d.simulated);
    for p in &d.positions {
        eprintln!("{:?}", p);
    }
}
