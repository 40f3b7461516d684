//! The unsteady single stroke end to end (examples/textbook/p4-press.toml,
//! the textbook's П4): every quantity the book asks in the JSON, the printed
//! arrays checked against each other (t(φ) = ∫dφ/ω by the trapezoid rule on
//! the printed ω, ε = dω/dt by central differences of the printed ω and t),
//! `tmm run` with the note and the sheets, the stall located, and every bad
//! input reported with its field, its place in the file and exit code 2.

use std::process::Output;

use serde_json::Value;

use crate::common::{self, json};

const EXAMPLE: &str = "examples/textbook/p4-press.toml";

fn tmm(args: &[&str]) -> Output {
    common::tmm_in(&common::repo(), args)
}

fn arr(v: &Value, p: &str) -> Vec<f64> {
    v.pointer(p)
        .and_then(Value::as_array)
        .unwrap_or_else(|| panic!("no array {p}"))
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

fn f(v: &Value, p: &str) -> f64 {
    common::number(v, p)
}

/// `tmm dynamics` on the example with `from` replaced by `to`: exit code 2,
/// no stdout; the message.
fn bad(name: &str, from: &str, to: &str) -> String {
    bad_in("dynamics", name, from, to)
}

/// As [`bad`] through the subcommand `cmd`.
fn bad_in(cmd: &str, name: &str, from: &str, to: &str) -> String {
    common::refused_edit("single_stroke", EXAMPLE, cmd, name, from, to)
}

#[test]
fn every_asked_quantity_is_in_the_json() {
    let d = json(&tmm(&["dynamics", EXAMPLE, "--json"]));
    assert_eq!(d["motion"], "single-stroke");
    // 2. M_прC(φ), I_прII, I_прΣ; 3. ω(φ), ε(φ), t(φ), M_прДВ over the cycle
    let phi = arr(&d, "/motor_driven/phi");
    assert_eq!(phi.len(), 361);
    for key in [
        "moment_loads",
        "inertia_variable",
        "inertia_total",
        "moment_motor",
        "omega",
        "epsilon",
        "time",
        "travel",
    ] {
        assert_eq!(arr(&d, &format!("/motor_driven/{key}")).len(), 361, "{key}");
    }
    // the cycle time: the event φ = 2π
    let tc = f(&d, "/motor_driven/cycle_time");
    assert!((phi[360] - 2.0 * std::f64::consts::PI).abs() < 1e-12);
    assert_eq!(tc, arr(&d, "/motor_driven/time")[360]);
    // the breakdown speed crossed, with where and when
    let c = &d["motor_driven"]["breakdown_crossings"][0];
    assert_eq!(c["direction"], "below");
    assert!(f(c, "/phi") > 0.0 && f(c, "/time") > 0.0 && f(c, "/time") < tc);
    // 4. the constant moment: A_Σ(φ), ω(φ), ε(φ), t(φ), A_Σ(2π), ω(2π), ε(f), t(2π)
    for key in ["work_total", "omega", "epsilon", "time"] {
        assert_eq!(arr(&d, &format!("/constant_moment/{key}")).len(), 361, "{key}");
    }
    for p in [
        "/constant_moment/work_end",
        "/constant_moment/omega_end",
        "/constant_moment/time_end",
        "/constant_moment/design/epsilon",
    ] {
        assert!(f(&d, p).is_finite(), "{p}");
    }
    // 1. h(f) at the design position f = 120°
    assert!((f(&d, "/motor_driven/design/phi").to_degrees() - 120.0).abs() < 1e-9);
    assert!(f(&d, "/motor_driven/design/travel") > 0.0);
    // the second model is a different one: another cycle time
    assert!((f(&d, "/constant_moment/time_end") - tc).abs() > 0.1);
}

#[test]
fn printed_arrays_agree_with_each_other() {
    let d = json(&tmm(&["dynamics", EXAMPLE, "--json"]));
    for model in ["motor_driven", "constant_moment"] {
        let phi = arr(&d, &format!("/{model}/phi"));
        let w = arr(&d, &format!("/{model}/omega"));
        let t = arr(&d, &format!("/{model}/time"));
        let e = arr(&d, &format!("/{model}/epsilon"));
        // t = ∫dφ/ω by the trapezoid rule on the printed 1° grid
        let mut tt = 0.0;
        for k in 1..phi.len() {
            tt += 0.5 * (phi[k] - phi[k - 1]) * (1.0 / w[k] + 1.0 / w[k - 1]);
            assert!((tt - t[k]).abs() < 2e-4 * t[k], "{model} t at {k}: {tt} {}", t[k]);
        }
        // ε = dω/dt by central differences where ω is smooth (off the
        // deformation's knots and the dead positions)
        for k in (5..80).chain(200..355) {
            let de = (w[k + 1] - w[k - 1]) / (t[k + 1] - t[k - 1]);
            let scale = e.iter().fold(0.0f64, |a, x| a.max(x.abs()));
            assert!((de - e[k]).abs() < 2e-4 * scale, "{model} ε at {k}: {de} {}", e[k]);
        }
    }
}

#[test]
fn runs_whole_with_its_note_and_sheets() {
    let dir = common::tmp("single_stroke", "run");
    let o = tmm(&["run", EXAMPLE, "--out", dir.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for f in [
        "dynamics/dynamics.json",
        "dynamics/dynamics.txt",
        "dynamics/stroke-omega.svg",
        "dynamics/stroke-time.svg",
        "dynamics/stroke-epsilon.svg",
        "dynamics/stroke-moments.svg",
        "note.pdf",
        "sheets/sheet-2.svg",
    ] {
        assert!(dir.join(f).is_file(), "{f}");
    }
    let sheet = std::fs::read_to_string(dir.join("sheets/sheet-2.svg")).unwrap();
    assert!(sheet.contains("stroke") || sheet.len() > 10_000);
    let text = std::fs::read_to_string(dir.join("dynamics/dynamics.txt")).unwrap();
    assert!(
        text.contains("cycle time t_ц") && text.contains("falls below the breakdown speed"),
        "{text}"
    );
}

#[test]
fn a_stall_says_where_it_stops() {
    // twice the deformation force
    let e = bad("stall", "force = [0, 0, 3.5e6, 7e6, 35e6]", "force = [0, 0, 7e6, 14e6, 70e6]");
    assert!(e.contains("stalls in the motor-driven stroke") && e.contains("φ = "), "{e}");
    assert!(e.contains("of its stroke") && e.contains("working stroke"), "{e}");
    assert!(e.contains("crank_shaft"), "the help names what would carry it through: {e}");
}

#[test]
fn bad_inputs_exit_2_naming_the_field() {
    let e = bad("delta", "motion = \"single-stroke\"", "motion = \"single-stroke\"\ndelta = 0.02");
    assert!(e.contains("dynamics.delta"), "{e}");
    let e = bad("motion", "motion = \"single-stroke\"", "motion = \"single\"");
    assert!(e.contains("dynamics.motion") && e.contains("single-stroke"), "{e}");
    let e = bad("breakdown", "breakdown_speed = \"12.3 rev/s\"", "breakdown_speed = \"17 rev/s\"");
    assert!(
        e.contains("dynamics.motor.breakdown_speed") && e.contains("below the synchronous"),
        "{e}"
    );
    let e = bad("no-torque", "breakdown_torque = \"5.24e3 N m\"", "");
    assert!(e.contains("dynamics.motor.breakdown_torque"), "{e}");
    let e = bad("nominal", "ratio = 18.6", "ratio = 18.6\nnominal_speed = \"900 rpm\"");
    assert!(e.contains("dynamics.motor.nominal_speed") && e.contains("Kloss"), "{e}");
    let e = bad(
        "tau",
        "design_angle = \"120 deg\"",
        "design_angle = \"120 deg\"\ntime_constant = \"1e-5 s\"",
    );
    assert!(e.contains("dynamics.stroke.time_constant"), "{e}");
    let e = bad("start", "start_speed = \"synchronous\"", "start_speed = \"-1 rad/s\"");
    assert!(e.contains("dynamics.stroke.start_speed"), "{e}");
    let e = bad("angle", "design_angle = \"120 deg\"", "design_angle = \"400 deg\"");
    assert!(e.contains("dynamics.stroke.design_angle"), "{e}");
    let e = bad("unit", "crank_shaft = \"140e3 kg m^2\"", "crank_shaft = \"140e3 N m\"");
    assert!(e.contains("dynamics.inertia.crank_shaft"), "{e}");
    // the kinetostatics cannot take its crank motion from a single stroke
    let e = bad_in(
        "forces",
        "crank-motion",
        "gravity = \"9.81 m/s^2\"",
        "gravity = \"9.81 m/s^2\"\ncrank_motion = \"dynamics\"",
    );
    assert!(e.contains("dynamics.motion"), "{e}");
}
