//! Tests of `tmm_report::dynamics::task`, kept outside the library so that the
//! test command compiles it once.

use tmm_linkage::dynamics::{DynamicsSpec, FlywheelPlace, FlywheelShape};
use tmm_linkage::forces::stroke::Working;
use tmm_report::TaskSource;
use tmm_report::dynamics::task::*;

fn err(body: &str) -> String {
    let t = TaskSource::new("task.toml", format!("[dynamics]\n{body}"));
    match read(&t, Working::Slower) {
        Ok(_) => panic!("accepted: {body}"),
        Err(e) => {
            assert_eq!(e.exit_code(), 2);
            e.to_string()
        }
    }
}

#[test]
fn reads_every_key() {
    let t = TaskSource::new(
        "task.toml",
        "[dynamics]\ndelta = 0.05\npoints = 720\n[dynamics.motor]\nsynchronous_speed = \"1500 rpm\"\nnominal_speed = \"1400 rpm\"\nnominal_torque = \"40 N m\"\nratio = 2\n[dynamics.inertia]\ncrank_shaft = \"0.5 kg m^2\"\nmotor_shaft = \"0.01 kg m^2\"\n[dynamics.flywheel]\nplace = \"motor\"\ndensity = \"7.2 g/cm^3\"\nshape = \"rim\"\nwidth_ratio = 0.25\nthickness_ratio = 0.1\n",
    );
    let d = read(&t, Working::Slower).unwrap().unwrap();
    let s = &d.spec;
    assert_eq!((s.delta, s.points), (0.05, 720));
    let m = s.motor().unwrap();
    // 1500 rpm = 1500·2π/60 rad/s, written out here
    assert!((m.synchronous_speed - 1500.0 * std::f64::consts::PI / 30.0).abs() < 1e-12);
    assert_eq!((m.nominal_torque, m.ratio), (40.0, 2.0));
    assert_eq!((s.inertia_crank_shaft, s.inertia_motor_shaft), (0.5, 0.01));
    assert_eq!(s.flywheel.place, FlywheelPlace::Motor);
    assert!((s.flywheel.density - 7200.0).abs() < 1e-9);
    assert_eq!(
        s.flywheel.shape,
        FlywheelShape::Rim {
            width_ratio: 0.25,
            thickness_ratio: 0.1
        }
    );
}

#[test]
fn defaults() {
    let t = TaskSource::new("task.toml", "[dynamics]\ndelta = 0.02\n");
    let d = read(&t, Working::Slower).unwrap().unwrap();
    assert_eq!(d.spec, DynamicsSpec::new(0.02));
    assert!(
        read(&TaskSource::new("t.toml", "title = \"x\"\n"), Working::Slower)
            .unwrap()
            .is_none()
    );
}

#[test]
fn bad_values_are_located_and_named() {
    assert!(err("delta = 0\n").starts_with("task.toml:2:9: dynamics.delta:"));
    assert!(err("delta = 1.5\n").contains("dynamics.delta"));
    assert!(err("points = 360\n").contains("dynamics.delta"));
    assert!(err("delta = 0.02\npoints = 100\n").contains("task.toml:3:10: dynamics.points"));
    assert!(err("delta = 0.02\ncolour = 1\n").contains("colour"));
    assert!(err("delta = 0.02\ndriving = \"motor\"\n").contains("dynamics.driving"));
    assert!(err("delta = 0.02\ndriving = \"diesel\"\n").contains("dynamics.driving"));
    let m = "[dynamics.motor]\nsynchronous_speed = \"1500 rpm\"\nnominal_speed = \"1600 rpm\"\nnominal_torque = \"40 N m\"\n";
    assert!(err(&format!("delta = 0.02\n{m}")).contains("task.toml:5:17: dynamics.motor.nominal_speed"));
    assert!(err("delta = 0.02\n[dynamics.inertia]\nmotor_shaft = 0.1\n").contains("task.toml:4:15: dynamics.inertia.motor_shaft"));
    assert!(err("delta = 0.02\n[dynamics.inertia]\ncrank_shaft = -0.1\n").contains("dynamics.inertia.crank_shaft"));
    assert!(err("delta = 0.02\n[dynamics.flywheel]\nplace = \"motor\"\n").contains("dynamics.flywheel.place"));
    assert!(err("delta = 0.02\n[dynamics.flywheel]\ndensity = \"7 kg/l\"\n").contains("dynamics.flywheel.density"));
    assert!(err("delta = 0.02\n[dynamics.flywheel]\ndensity = 0\n").contains("dynamics.flywheel.density"));
    assert!(err("delta = 0.02\n[dynamics.flywheel]\nshape = \"rim\"\n").contains("dynamics.flywheel.thickness_ratio"));
    assert!(
        err("delta = 0.02\n[dynamics.flywheel]\nshape = \"rim\"\nthickness_ratio = 0.5\n")
            .contains("task.toml:5:19: dynamics.flywheel.thickness_ratio")
    );
    assert!(err("delta = 0.02\n[dynamics.flywheel]\nshape = \"cube\"\n").contains("dynamics.flywheel.shape"));
    assert!(err("delta = 0.02\n[dynamics.flywheel]\nwidth_ratio = 0\n").contains("dynamics.flywheel.width_ratio"));
}
