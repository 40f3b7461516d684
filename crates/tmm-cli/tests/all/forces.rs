//! `tmm forces` and the `[forces]` section end to end: one JSON document, the
//! whole mechanism in equilibrium from the printed numbers alone, files
//! written, `tmm run`, and bad loads reported with the field, its place and
//! exit code 2.

use std::path::PathBuf;
use std::process::Output;

use crate::common::{self, json};

fn tmm(args: &[&str]) -> Output {
    common::tmm_in(&common::repo(), args)
}

fn tmp(name: &str) -> PathBuf {
    common::tmp("forces", name)
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// The whole mechanism is in equilibrium under its loads, the frame's
/// reactions and the balancing torque: Σ F = 0 and Σ M about the origin = 0,
/// from the JSON numbers alone.
fn check_equilibrium(p: &serde_json::Value) {
    let (mut fx, mut fy, mut m, mut scale) = (0.0, 0.0, 0.0, 0.0);
    for (_, l) in p["loads"].as_object().unwrap() {
        let (x, y, mm) = (f(&l["fx"]), f(&l["fy"]), f(&l["m"]));
        let (sx, sy) = (f(&l["s"][0]), f(&l["s"][1]));
        fx += x;
        fy += y;
        m += mm + sx * y - sy * x;
        scale += x.abs() + y.abs() + mm.abs();
    }
    for r in p["reactions"].as_array().unwrap() {
        if r["from"] == "frame" {
            let (x, y) = (f(&r["fx"]), f(&r["fy"]));
            let (ax, ay) = (f(&r["at"][0]), f(&r["at"][1]));
            fx += x;
            fy += y;
            m += ax * y - ay * x;
            scale += x.abs() + y.abs();
        }
    }
    m += f(&p["balancing_moment"]);
    assert!(
        fx.abs() < 1e-9 * scale && fy.abs() < 1e-9 * scale && m.abs() < 1e-9 * scale,
        "Σ = ({fx}, {fy}, {m}) vs {scale}"
    );
    let (mb, mz) = (f(&p["balancing_moment"]), f(&p["zhukovsky_moment"]));
    assert!((mb - mz).abs() <= 1e-9 * mb.abs().max(1e-9));
}

#[test]
fn seed001_json_is_one_document_in_equilibrium() {
    let d = json(&tmm(&["forces", "examples/seed-001-fourbar.toml", "--json"]));
    assert_eq!(d["units"], "SI");
    let det = &d["detail"];
    assert!((f(&det["phi"]) - 15f64.to_radians()).abs() < 1e-12);
    check_equilibrium(det);
    for p in d["positions"].as_array().unwrap() {
        check_equilibrium(p);
    }
    // 10 kg/m: 1.2, 4.8, 3.8 kg; J_S = 0.1·m·l²
    for (name, l) in [("1", 0.12), ("2", 0.48), ("3", 0.38)] {
        assert!((f(&d["links"][name]["mass"]) - 10.0 * l).abs() < 1e-12);
        assert!((f(&d["links"][name]["inertia"]) - 0.1 * 10.0 * l * l * l).abs() < 1e-12);
    }
    // P_b·l1 = M_b, and every reaction has its magnitude
    assert!((f(&det["balancing_force"]) * 0.12 - f(&det["balancing_moment"])).abs() < 1e-9);
    for r in det["reactions"].as_array().unwrap() {
        assert!((f(&r["magnitude"]) - f(&r["fx"]).hypot(f(&r["fy"]))).abs() < 1e-9);
    }
    assert!(d["strength"]["round"]["d"].as_f64().unwrap() > 0.0);
}

#[test]
fn at_option_and_svg_files() {
    let dir = tmp("svg");
    let o = tmm(&[
        "forces",
        "examples/seed-004-two-sliders.toml",
        "--at",
        "40 deg",
        "--svg",
        dir.to_str().unwrap(),
        "--json",
    ]);
    let d = json(&o);
    assert!((f(&d["detail"]["phi"]) - 40f64.to_radians()).abs() < 1e-12);
    check_equilibrium(&d["detail"]);
    for name in [
        "group-1.svg",
        "group-2.svg",
        "input-link.svg",
        "zhukovsky-lever.svg",
        "balancing-torque.svg",
        "strength-M.svg",
    ] {
        let s = std::fs::read_to_string(dir.join(name)).unwrap_or_else(|_| panic!("{name} missing"));
        assert!(s.contains("<svg") && !s.contains("NaN"));
    }
}

#[test]
fn seed003_sixbar_with_gravity_and_sine_resistance() {
    let d = json(&tmm(&["forces", "examples/seed-003-sixbar.toml", "--json"]));
    for p in d["positions"].as_array().unwrap() {
        check_equilibrium(p);
        // no resistance on the return stroke
        if p["working_stroke"] == false {
            assert_eq!(f(&p["resistance"][0]), 0.0);
        }
    }
}

#[test]
fn tmm_run_has_the_forces_section() {
    let dir = tmp("run");
    let o = tmm(&["run", "--no-pdf", "examples/seed-001-fourbar.toml", "-o", dir.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let rep: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(dir.join("report.json")).unwrap()).unwrap();
    check_equilibrium(&rep["forces"]["detail"]);
    assert!(dir.join("forces/forces.json").exists() && dir.join("forces/zhukovsky-lever.svg").exists());
}

fn bad(name: &str, forces: &str) -> String {
    let base = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/seed-003-sixbar.toml")).unwrap();
    let cut = base.find("\n[forces]").unwrap();
    let text = format!("{}\n{forces}", &base[..cut]);
    let dir = tmp(name);
    let p = dir.join("task.toml");
    std::fs::write(&p, text).unwrap();
    let o = tmm(&["forces", p.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2), "{name}: stdout {}", String::from_utf8_lossy(&o.stdout));
    assert!(o.stdout.is_empty());
    String::from_utf8_lossy(&o.stderr).to_string()
}

#[test]
fn bad_loads_exit_2_naming_the_field() {
    let e = bad("neg", "[forces]\n[forces.links.2]\nmass = \"-4 kg\"\n");
    assert!(e.contains("forces.links.2.mass") && e.contains("≥ 0"), "{e}");
    let e = bad("unknown-link", "[forces]\n[forces.links.9]\nmass = \"4 kg\"\n");
    assert!(e.contains("unknown link `9`"), "{e}");
    let e = bad(
        "unknown-point",
        "[forces]\n[forces.links.2]\nforces = [{ point = \"Z\", force = [\"1 N\", \"0 N\"] }]\n",
    );
    assert!(e.contains("unknown point `Z`"), "{e}");
    let e = bad(
        "malformed",
        "[forces]\n[[forces.resistance]]\nlink = \"5\"\nforce = \"3 kN\"\nlaw = \"table\"\ntable = [[\"0 mm\"], [\"10 mm\", \"1 kN\"]]\n",
    );
    assert!(e.contains("table[0]"), "{e}");
    let e = bad(
        "short",
        "[forces]\n[[forces.resistance]]\nlink = \"5\"\nforce = \"3 kN\"\nlaw = \"table\"\ntable = [[\"0 mm\", \"3 kN\"], [\"10 mm\", \"3 kN\"]]\n",
    );
    assert!(e.contains("covers travel") && e.contains("forces.resistance[0].table"), "{e}");
    let e = bad("unknown-key", "[forces]\nmas = 3\n");
    assert!(e.contains("mas"), "{e}");
    let e = bad("units", "[forces]\n[forces.links.2]\nmass = \"4 m\"\n");
    assert!(e.contains("forces.links.2.mass"), "{e}");
}
