//! The cylinder-driven mechanism end to end (examples/textbook/
//! p5-pneumatic-cylinder.toml, the textbook's П5): every quantity the book
//! asks in the JSON; the printed numbers checked against each other and
//! against closed forms derived here (the synthesis' loop equations, the
//! control force's zero work, t(s) = ∫ds/V by the trapezoid rule on the
//! printed V away from the ends, the balancing force equal to the control
//! force); `tmm run` with the note and the sheet; every bad input reported
//! with its field, its place in the file and exit code 2.

use std::process::Output;

use serde_json::Value;

use crate::common::{self, json};

const EXAMPLE: &str = "examples/textbook/p5-pneumatic-cylinder.toml";

fn tmm(args: &[&str]) -> Output {
    common::tmm_in(&common::repo(), args)
}

fn arr(v: &Value, p: &str) -> Vec<Option<f64>> {
    v.pointer(p)
        .and_then(Value::as_array)
        .unwrap_or_else(|| panic!("no array {p}"))
        .iter()
        .map(Value::as_f64)
        .collect()
}

fn f(v: &Value, p: &str) -> f64 {
    common::number(v, p)
}

/// `tmm cylinder` on the example with `from` replaced by `to`: exit code 2,
/// no stdout, the message located in the file.
fn bad(name: &str, from: &str, to: &str) -> String {
    common::refused_edit("cylinder", EXAMPLE, "cylinder", name, from, to)
}

#[test]
fn every_asked_quantity_is_in_the_json() {
    let d = json(&tmm(&["cylinder", EXAMPLE, "--json"]));
    // the synthesis: X_D, l_AB, φ1н, φ3н, φ3к with Y_D given, closing the book's four loop equations
    let (xd, yd, l) = (f(&d, "/synthesis/X_D"), f(&d, "/synthesis/Y_D"), f(&d, "/synthesis/l_AB"));
    let (p1, p3n, p3k) = (
        f(&d, "/synthesis/phi1"),
        f(&d, "/synthesis/phi3_start"),
        f(&d, "/synthesis/phi3_end"),
    );
    let beta = 60f64.to_radians();
    for (h, a1, a3) in [(0.05, p1, p3n), (0.3, p1 + beta, p3k)] {
        assert!((l * a1.cos() - xd - (h + 0.39) * a3.cos()).abs() < 1e-9);
        assert!((l * a1.sin() - yd - (h + 0.39) * a3.sin()).abs() < 1e-9);
    }
    assert!((p1 + beta + std::f64::consts::FRAC_PI_2 - p3k - 50f64.to_radians()).abs() < 1e-9);
    // φ1(f), φ3(f) at f = 0.15 m; the analogues; m_пр, m′_пр; A_C, F_K, F_H; V, a, t; the nine unknowns
    assert_eq!(f(&d, "/position/s"), 0.15);
    for p in ["/position/phi1", "/position/phi3"] {
        f(&d, p);
    }
    for k in ["phi1", "phi3", "omega_q1", "omega_q2", "omega_q3", "eps_q1", "eps_q2", "eps_q3"] {
        assert_eq!(arr(&d, &format!("/analogues/{k}")).len(), 12, "{k}");
    }
    for k in [
        "reduced_mass",
        "reduced_mass_derivative",
        "speed",
        "acceleration",
        "time",
        "force_resistance",
        "force_control",
    ] {
        assert_eq!(arr(&d, &format!("/motion/{k}")).len(), 201, "{k}");
    }
    for k in ["work_resistance", "F_K", "F_H"] {
        f(&d, &format!("/control/{k}"));
    }
    for k in ["R_AX", "R_AY", "R_BX", "R_BY", "R_32", "M_32", "R_DX", "R_DY", "F_balancing"] {
        f(&d, &format!("/kinetostatics/{k}"));
    }
    // the ideal model's end: reached only asymptotically, no finite time printed
    assert_eq!(d["end"]["reached"], "asymptotically");
    assert!(d["end"]["time"].is_null());
    assert_eq!(arr(&d, "/motion/time").last().unwrap(), &None);
}

#[test]
fn printed_numbers_agree_with_each_other() {
    let d = json(&tmm(&["cylinder", EXAMPLE, "--json"]));
    // zero work of the control force with the resistance
    let (ac, fk, fh, sc, smax) = (
        f(&d, "/control/work_resistance"),
        f(&d, "/control/F_K"),
        f(&d, "/control/F_H"),
        f(&d, "/control/switch"),
        f(&d, "/control/travel"),
    );
    assert!((fh * sc + 0.5 * (fh + fk) * (smax - sc) + ac).abs() < 1e-9 * ac.abs());
    let fc = arr(&d, "/motion/force_resistance");
    assert!((fk + fc.last().unwrap().unwrap()).abs() < 1e-9 * fk);
    // A_C by the trapezoid rule on the printed F_прC
    let s: Vec<f64> = arr(&d, "/motion/s").into_iter().map(Option::unwrap).collect();
    let trap: f64 = (1..s.len())
        .map(|i| 0.5 * (fc[i].unwrap() + fc[i - 1].unwrap()) * (s[i] - s[i - 1]))
        .sum();
    assert!((trap - ac).abs() < 1e-4 * ac.abs(), "{trap} {ac}");
    // t = ∫ds/V on the printed V between 10 % and 90 % of the travel
    let v: Vec<f64> = arr(&d, "/motion/speed").into_iter().map(Option::unwrap).collect();
    let t = arr(&d, "/motion/time");
    let (i0, i1) = (20, 180);
    let dt: f64 = (i0 + 1..=i1).map(|i| 0.5 * (1.0 / v[i] + 1.0 / v[i - 1]) * (s[i] - s[i - 1])).sum();
    let printed = t[i1].unwrap() - t[i0].unwrap();
    assert!((dt - printed).abs() < 1e-3 * printed, "{dt} {printed}");
    // V² m_пр/2 = A_Σ at every node
    let m: Vec<f64> = arr(&d, "/motion/reduced_mass").into_iter().map(Option::unwrap).collect();
    let w = arr(&d, "/motion/work_total");
    for i in 0..s.len() {
        let e = 0.5 * m[i] * v[i] * v[i];
        assert!((e - w[i].unwrap()).abs() < 1e-9 * ac.abs(), "at {}", s[i]);
    }
    // the balancing force is the control force at s_f
    let (fb, fd) = (f(&d, "/kinetostatics/F_balancing"), f(&d, "/kinetostatics/F_control"));
    assert!((fb - fd).abs() < 1e-6 * fd.abs(), "{fb} {fd}");
    assert!((fd - fh).abs() < 1e-9 * fh, "s_f = 0.15 m is before s_c: the level F_H");
}

#[test]
fn runs_whole_with_its_note_and_sheet() {
    let dir = common::tmp("cylinder", "run");
    let o = tmm(&["run", EXAMPLE, "--out", dir.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for f in [
        "cylinder/cylinder.json",
        "cylinder/cylinder.txt",
        "cylinder/mechanism.svg",
        "cylinder/mass.svg",
        "cylinder/speed.svg",
        "cylinder/accel.svg",
        "cylinder/time.svg",
        "cylinder/forces.svg",
        "note.pdf",
        "sheets/sheet-1.svg",
    ] {
        assert!(dir.join(f).is_file(), "{f}");
    }
    let text = std::fs::read_to_string(dir.join("cylinder/cylinder.txt")).unwrap();
    assert!(text.contains("reached only asymptotically") && text.contains("→ ∞"), "{text}");
    let report: Value = serde_json::from_str(&std::fs::read_to_string(dir.join("report.json")).unwrap()).unwrap();
    assert!(report["cylinder"]["kinetostatics"]["R_32"].is_f64());
}

#[test]
fn bad_inputs_exit_2_naming_the_field() {
    let e = bad("lift", "switch = \"0.18 m\"", "switch = \"0.1 m\"");
    assert!(
        e.contains("cylinder.switch: the control force cannot lift the load") && e.contains("from s = 0.12"),
        "{e}"
    );
    let e = bad("switch", "switch = \"0.18 m\"", "switch = \"0.3 m\"");
    assert!(e.contains("cylinder.switch") && e.contains("within the piston's travel"), "{e}");
    let e = bad("at", "at = \"0.15 m\"", "at = \"0.5 m\"");
    assert!(e.contains("cylinder.at"), "{e}");
    let e = bad("points", "points = 200", "points = 3");
    assert!(e.contains("cylinder.points"), "{e}");
    let e = bad("unknown", "gravity = ", "gravitation = ");
    assert!(e.contains("gravitation"), "{e}");
    let e = bad("mass", "mass = \"100 kg\"", "mass = \"-100 kg\"");
    assert!(e.contains("cylinder.load.mass"), "{e}");
    let e = bad("unit", "arm = \"0.2 m\"", "arm = \"0.2 kg\"");
    assert!(e.contains("cylinder.load.arm"), "{e}");
    // a cylinder too short for its travel: the geometry given, the lever cannot follow
    let e = bad(
        "reach",
        "swing = \"60 deg\"\npressure_end = \"50 deg\"\nframe_y = \"0.05 m\"",
        "frame = [\"0.5 m\", \"0 m\"]\nlever_length = \"0.15 m\"\nstart_angle = \"90 deg\"",
    );
    assert!(
        e.contains("cylinder.h_max") && e.contains("too long for the lever") && e.contains("at s = "),
        "{e}"
    );
    let e = bad(
        "short",
        "swing = \"60 deg\"\npressure_end = \"50 deg\"\nframe_y = \"0.05 m\"",
        "frame = [\"0.9 m\", \"0.05 m\"]\nlever_length = \"0.3 m\"\nstart_angle = \"90 deg\"",
    );
    assert!(e.contains("cylinder.h_min") && e.contains("too short for its travel"), "{e}");
    // a synthesis that cannot be met names its field
    let e = bad("theta", "pressure_end = \"50 deg\"", "pressure_end = \"95 deg\"");
    assert!(e.contains("cylinder.pressure_end"), "{e}");
}
