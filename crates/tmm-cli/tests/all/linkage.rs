//! `tmm linkage` and `tmm run` from the outside: one JSON document with the
//! contract's keys, drawings written, and every kind of bad input answered
//! with a message naming the field and exit code 2.

use std::path::PathBuf;

use crate::common::{self, tmm};

fn root() -> PathBuf {
    common::repo()
}

fn tmp(name: &str) -> PathBuf {
    common::tmp("linkage", name)
}

const FOURBAR: &str = r#"
[linkage]
fixed = { A = [0, 0], D = ["510 mm", 0] }
input = { link = "1", speed = "900 rpm" }
assembly = ["C below AD"]
[[linkage.links]]
name = "1"
joints = ["A", "B"]
length = "120 mm"
[[linkage.links]]
name = "2"
joints = ["B", "C"]
length = "480 mm"
[[linkage.links]]
name = "3"
joints = ["D", "C"]
length = "380 mm"
"#;

fn run_text(name: &str, text: &str) -> (i32, String, String) {
    let f = tmp(name).join("task.toml");
    std::fs::write(&f, text).unwrap();
    let o = tmm().arg("linkage").arg(&f).output().unwrap();
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

#[test]
fn json_is_one_document_with_the_contract() {
    let o = tmm()
        .args(["linkage", "--json", "--at", "15"])
        .arg(root().join("examples/seed-001-fourbar.toml"))
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("exactly one JSON document");
    assert_eq!(v["units"], "SI");
    let s = &v["structure"];
    assert_eq!(s["dof"], 1);
    assert_eq!((s["n"].as_i64(), s["p5"].as_i64(), s["p4"].as_i64()), (Some(3), Some(4), Some(0)));
    assert_eq!(s["formula"], "I(0,1) → II(2,3)");
    assert_eq!(s["groups"][0]["class"], 2);
    assert_eq!(s["groups"][0]["order"], 2);
    assert_eq!(s["groups"][0]["kind"], "RRR");
    let p = &v["positions"][0];
    let phi = p["phi"].as_f64().unwrap();
    assert!((phi - 15f64.to_radians()).abs() < 1e-12);
    // ω3 · |DC| = |V_C| read from the same document
    let c = &p["points"]["C"];
    let vc = (c["vx"].as_f64().unwrap().powi(2) + c["vy"].as_f64().unwrap().powi(2)).sqrt();
    let w3 = p["links"]["3"]["omega"].as_f64().unwrap();
    assert!((vc - w3.abs() * 0.38).abs() < 1e-9);
    assert!(p["links"]["2"]["epsilon"].is_f64());
    assert_eq!(v["dead_positions"].as_array().unwrap().len(), 2);
    assert!(v["kv"].as_f64().unwrap() > 1.0);
}

#[test]
fn svg_drawings_are_written() {
    let d = tmp("svg");
    let o = tmm()
        .args(["linkage", "--svg"])
        .arg(&d)
        .arg(root().join("examples/seed-003-sixbar.toml"))
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    for f in [
        "positions.svg",
        "diagram-s.svg",
        "diagram-ds.svg",
        "diagram-dds.svg",
        "diagram-v.svg",
        "diagram-a.svg",
        "velocity-plan.svg",
        "acceleration-plan.svg",
    ] {
        let t = std::fs::read_to_string(d.join(f)).unwrap_or_else(|_| panic!("{f} missing"));
        assert!(t.starts_with("<?xml") && t.contains("</svg>") && !t.contains("NaN"), "{f}");
    }
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("I(0,1) → II(2,3) → II(4,5)"));
    assert!(
        text.lines()
            .filter(|l| l.trim_start().starts_with(|c: char| c.is_ascii_digit()))
            .count()
            >= 12
    );
}

#[test]
fn run_default_and_a_file() {
    let d = tmp("run");
    let o = tmm().args(["run", "--no-pdf", "--out"]).arg(&d).output().unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(d.join("report.json").exists() && d.join("linkage/positions.svg").exists());
    let o = tmm()
        .args(["run", "--no-pdf", "--json", "--out"])
        .arg(&d)
        .arg(root().join("examples/seed-002-shaper.toml"))
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["linkage"]["structure"]["groups"][0]["kind"], "RPR");
}

fn bad(name: &str, text: &str, needles: &[&str]) {
    let (code, out, err) = run_text(name, text);
    assert_eq!(code, 2, "{name}: exit {code}\n{out}\n{err}");
    for n in needles {
        assert!(err.contains(n), "{name}: `{n}` not in\n{err}");
    }
    assert!(!err.contains("panicked"), "{name}: {err}");
}

#[test]
fn unknown_point() {
    bad(
        "unknown-point",
        &FOURBAR.replace("\"C below AD\"", "\"X below AD\""),
        &["linkage.assembly[0]", "unknown point `X`"],
    );
    let slider = format!("{FOURBAR}\n[[linkage.sliders]]\nlink = \"3\"\npoint = \"Q\"\nguide = {{ through = [0, 0] }}\n");
    bad("unknown-slider-point", &slider, &["sliders[0].point", "unknown point `Q`"]);
}

#[test]
fn missing_length() {
    bad(
        "missing-length",
        &FOURBAR.replacen("length = \"480 mm\"\n", "", 1),
        &["linkage.links[1] (2).length", "missing length"],
    );
}

#[test]
fn link_too_short_to_assemble() {
    bad(
        "too-short",
        &FOURBAR.replace("\"480 mm\"", "\"200 mm\""),
        &["cannot be assembled", "°"],
    );
}

#[test]
fn crank_cannot_turn_fully_grashof() {
    bad(
        "grashof",
        &FOURBAR.replace("\"120 mm\"", "\"400 mm\""),
        &["cannot be assembled for crank angles", "Grashof"],
    );
}

#[test]
fn zero_length() {
    bad("zero", &FOURBAR.replace("\"380 mm\"", "\"0 mm\""), &["links[2] (3).length", "> 0"]);
}

#[test]
fn duplicate_names() {
    bad(
        "duplicate",
        &FOURBAR.replace("name = \"3\"", "name = \"2\""),
        &["duplicate link name `2`"],
    );
}

#[test]
fn mobility_not_one() {
    // a five-bar: 4 moving links, 5 pairs, W = 12 − 10 = 2
    let five = r#"
[linkage]
fixed = { A = [0, 0], E = ["0.5 m", 0] }
input = { link = "1", speed = "10 rad/s" }
[[linkage.links]]
name = "1"
joints = ["A", "B"]
length = "0.1 m"
[[linkage.links]]
name = "2"
joints = ["B", "C"]
length = "0.4 m"
[[linkage.links]]
name = "3"
joints = ["C", "D"]
length = "0.3 m"
[[linkage.links]]
name = "4"
joints = ["E", "D"]
length = "0.3 m"
"#;
    bad("w2", five, &["degrees of freedom", "W = 3n − 2p5 − p4", "= 2"]);
}

#[test]
fn malformed_units() {
    bad(
        "units",
        &FOURBAR.replace("\"480 mm\"", "\"480 kg\""),
        &["linkage.links[1] (2).length", "`kg` is not a unit of length", "accepted units"],
    );
    bad(
        "speed",
        &FOURBAR.replace("\"900 rpm\"", "\"fast\""),
        &["linkage.input.speed", "does not start with a number"],
    );
    bad("toml", &FOURBAR.replace("length = \"120 mm\"", "length = "), &["task.toml:"]);
}

#[test]
fn bad_command_line() {
    let o = tmm()
        .args(["linkage", "--at", "ten"])
        .arg(root().join("examples/seed-001-fourbar.toml"))
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--at"));
    let o = tmm().args(["linkage", "no-such-file.toml"]).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
}
