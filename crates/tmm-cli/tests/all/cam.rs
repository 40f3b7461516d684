//! `tmm cam` and the `[cam]` section end to end: exit codes, one JSON
//! document, files written, errors naming the option or field.

use std::path::{Path, PathBuf};
use std::process::Output;

use crate::common::{self, json};

const SEED_PHASES: &str = "rise 108 const-accel(u=1/3); dwell 15; return 108 const-accel(u=1/3); dwell 129";

fn tmm(args: &[&str]) -> Output {
    common::tmm_in(Path::new(env!("CARGO_MANIFEST_DIR")), args)
}

fn tmp(name: &str) -> PathBuf {
    common::tmp("cam", name)
}

fn seed(extra: &[&str]) -> Vec<String> {
    let mut v: Vec<String> = [
        "cam",
        "--follower",
        "translating-roller",
        "--stroke",
        "13 mm",
        "--phases",
        SEED_PHASES,
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    v.extend(extra.iter().map(|s| s.to_string()));
    v
}

fn run(args: &[String]) -> Output {
    tmm(&args.iter().map(String::as_str).collect::<Vec<_>>())
}

fn f(v: &serde_json::Value, k: &str) -> f64 {
    v[k].as_f64().unwrap_or_else(|| panic!("{k} is not a number: {}", v[k]))
}

#[test]
fn seed_roller_cam_prints_tables() {
    let o = run(&seed(&["--min-transmission", "rise 75, return 60", "--omega", "200 rad/s"]));
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let s = String::from_utf8_lossy(&o.stdout);
    assert!(s.contains("r0") && s.contains("offset") && s.contains("pressure angle"));
}

#[test]
fn json_is_one_document_with_the_promised_keys() {
    let v = json(&run(&seed(&[
        "--min-transmission",
        "rise 75, return 60",
        "--omega",
        "200 rad/s",
        "--json",
        "--points",
        "360",
    ])));
    assert_eq!(v["units"], "SI");
    for k in [
        "r0",
        "rb",
        "e",
        "roller_radius",
        "pressure_angle_max_rise",
        "pressure_angle_max_return",
        "rho_min",
    ] {
        assert!(v[k].is_number(), "{k}");
    }
    let (r0, rb, roller) = (f(&v, "r0"), f(&v, "rb"), f(&v, "roller_radius"));
    assert!((rb - (r0 - roller)).abs() < 1e-12);
    // the course's rule for the roller
    assert!(roller <= 0.4 * r0 + 1e-12);
    // the limits, in radians
    assert!(f(&v, "pressure_angle_max_rise") <= 15f64.to_radians() + 1e-6);
    assert!(f(&v, "pressure_angle_max_return") <= 30f64.to_radians() + 1e-6);
    // r0 is the smallest radius of the pitch curve, rb of the working profile
    let (px, py) = (v["pitch_x"].as_array().unwrap(), v["pitch_y"].as_array().unwrap());
    assert_eq!(px.len(), 360);
    let min_r = px
        .iter()
        .zip(py)
        .map(|(x, y)| x.as_f64().unwrap().hypot(y.as_f64().unwrap()))
        .fold(f64::INFINITY, f64::min);
    assert!((min_r - r0).abs() < 1e-9);
    // v = ω·ds/dφ
    let (ds, vel) = (v["ds_dphi"].as_array().unwrap(), v["velocity"].as_array().unwrap());
    assert!((vel[30].as_f64().unwrap() - 200.0 * ds[30].as_f64().unwrap()).abs() < 1e-12);
}

#[test]
fn pressure_and_transmission_limits_are_the_same_limit() {
    let a = json(&run(&seed(&["--max-pressure", "30", "--json", "--points", "64"])));
    let b = json(&run(&seed(&["--min-transmission", "60", "--json", "--points", "64"])));
    // 90° − 60° and 30° differ in the last bit only
    assert!((f(&a, "r0") - f(&b, "r0")).abs() < 1e-12);
    assert!((f(&a, "e") - f(&b, "e")).abs() < 1e-12);
    let c = json(&run(&seed(&["--max-pressure", "30", "--offset", "0", "--json", "--points", "64"])));
    assert_eq!(f(&c, "e"), 0.0);
    assert!(f(&c, "r0") >= f(&a, "r0"), "the best offset is never worse than e = 0");
}

#[test]
fn flat_face_reports_its_width() {
    let o = tmm(&[
        "cam",
        "--follower",
        "translating-flat",
        "--stroke",
        "13 mm",
        "--phases",
        SEED_PHASES,
        "--json",
        "--points",
        "64",
    ]);
    let v = json(&o);
    assert_eq!(f(&v, "rb"), f(&v, "r0"));
    assert!(f(&v, "face_width") > 2.0 * 0.005);
    assert!((f(&v, "rho_min") - 0.010).abs() < 1e-9);
}

#[test]
fn oscillating_followers_run() {
    let v = json(&tmm(&[
        "cam",
        "--follower",
        "oscillating-roller",
        "--stroke",
        "20 deg",
        "--arm",
        "100 mm",
        "--phases",
        "rise 120 sine; dwell 30; return 120 sine; dwell 90",
        "--max-pressure",
        "35",
        "--json",
        "--points",
        "64",
    ]));
    assert!(f(&v, "pivot_distance") > 0.0);
    let v = json(&tmm(&[
        "cam",
        "--follower",
        "oscillating-flat",
        "--stroke",
        "15 deg",
        "--pivot",
        "120 mm",
        "--phases",
        "rise 120 poly345; dwell 30; return 120 poly345; dwell 90",
        "--json",
        "--points",
        "64",
    ]));
    assert!(f(&v, "face_width") > 0.0);
}

#[test]
fn drawings_dxf_and_csv_are_written() {
    let d = tmp("files");
    let dxf = d.join("profile.dxf");
    let csv = d.join("profile.csv");
    let o = run(&seed(&[
        "--max-pressure",
        "rise 15, return 30",
        "--points",
        "100",
        "--svg",
        d.to_str().unwrap(),
        "--dxf",
        dxf.to_str().unwrap(),
        "--csv",
        csv.to_str().unwrap(),
    ]));
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for n in ["cam.svg", "cam-analogs.svg", "cam-motion.svg", "cam-pressure.svg", "cam-sizing.svg"] {
        let s = std::fs::read_to_string(d.join(n)).unwrap();
        assert!(s.starts_with("<?xml") && s.contains("</svg>") && !s.contains("NaN"), "{n}");
    }
    let c = std::fs::read_to_string(&csv).unwrap();
    assert_eq!(c.lines().count(), 101);
    assert!(
        c.lines()
            .skip(1)
            .all(|l| l.split(',').count() == 7 && l.split(',').all(|x| x.parse::<f64>().is_ok()))
    );
    let x = std::fs::read_to_string(&dxf).unwrap();
    assert!(x.contains("LWPOLYLINE") && x.contains("PROFILE"));
    let _ = std::fs::remove_dir_all(&d);
}

fn fails_naming(args: &[String], what: &[&str]) {
    let o = run(args);
    assert_eq!(
        o.status.code(),
        Some(2),
        "stdout {} stderr {}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    let e = String::from_utf8_lossy(&o.stderr);
    for w in what {
        assert!(e.contains(w), "`{w}` not in: {e}");
    }
    assert!(o.stdout.is_empty());
}

#[test]
fn bad_inputs_exit_2_and_name_the_option() {
    let p = |ph: &str, extra: &[&str]| {
        let mut v: Vec<String> = ["cam", "--follower", "translating-roller", "--stroke", "13 mm", "--phases", ph]
            .iter()
            .map(|s| s.to_string())
            .collect();
        v.extend(extra.iter().map(|s| s.to_string()));
        v
    };
    fails_naming(
        &p("rise 108 cosine; dwell 15; return 108 cosine; dwell 100", &["--max-pressure", "30"]),
        &["--phases", "360"],
    );
    fails_naming(
        &p("rise 108 wobble; dwell 15; return 108 cosine; dwell 129", &["--max-pressure", "30"]),
        &["--phases", "unknown motion law", "wobble"],
    );
    fails_naming(&seed(&["--max-pressure", "90"]), &["--max-pressure", "90"]);
    fails_naming(&seed(&["--min-transmission", "rise 0, return 60"]), &["--min-transmission"]);
    fails_naming(&seed(&["--max-pressure", "30", "--roller", "40 mm"]), &["--roller", "undercut"]);
    fails_naming(&seed(&["--max-pressure", "30", "--roller", "3 kg"]), &["--roller"]);
    fails_naming(&seed(&["--max-pressure", "30", "--rotation", "sideways"]), &["--rotation"]);
    fails_naming(&seed(&[]), &["--max-pressure"]);
    let zero = [
        "cam",
        "--follower",
        "translating-roller",
        "--stroke",
        "0 mm",
        "--phases",
        SEED_PHASES,
        "--max-pressure",
        "30",
    ]
    .map(String::from);
    fails_naming(&zero, &["--stroke"]);
    let neg = [
        "cam",
        "--follower",
        "translating-roller",
        "--stroke",
        "-5 mm",
        "--phases",
        SEED_PHASES,
        "--max-pressure",
        "30",
    ]
    .map(String::from);
    fails_naming(&neg, &["--stroke"]);
    let kind = ["cam", "--follower", "wobbly", "--stroke", "5 mm", "--phases", SEED_PHASES].map(String::from);
    fails_naming(&kind, &["--follower", "translating-roller"]);
}

#[test]
fn task_file_section_runs_and_errors_point_into_the_file() {
    let ex = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/cam-seed-001-roller.toml");
    let v = json(&tmm(&["cam", ex, "--json"]));
    assert_eq!(v["units"], "SI");
    assert!(f(&v, "r0") > 0.0);

    let d = tmp("file");
    let bad = d.join("bad.toml");
    std::fs::write(&bad, "[cam]\nfollower = \"translating-roller\"\nstroke = \"13 mm\"\nphases = \"rise 108 sine; dwell 15; return 108 sine; dwell 120\"\nmax_pressure = 30\n").unwrap();
    let o = tmm(&["cam", bad.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(e.contains("cam.phases") && e.contains("bad.toml:4:"), "{e}");

    std::fs::write(&bad, "[cam]\nfollower = \"translating-roller\"\nstroke = \"13 mm\"\nphases = \"rise 180 sine; return 180 sine\"\nmax_pressure = 30\nwobble = 1\n").unwrap();
    let o = tmm(&["cam", bad.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("wobble"));

    // tmm run writes the section's files
    let out = d.join("out");
    let v = json(&tmm(&["run", "--no-pdf", ex, "-o", out.to_str().unwrap(), "--json"]));
    assert!(v["cam"]["r0"].is_number());
    for n in ["cam.svg", "cam-sizing.svg", "cam-profile.dxf", "cam-profile.csv", "cam.json"] {
        assert!(out.join("cam").join(n).exists(), "{n}");
    }
    let _ = std::fs::remove_dir_all(&d);
}
