//! Regression tests for the defects found by trying tmm as a new user, a
//! teacher and an adversary would: each test reproduces one reported case
//! through the `tmm` binary and checks what the user sees.

use std::path::{Path, PathBuf};
use std::process::Stdio;

use crate::common::{self, longest_number, repo, run, tmm};

fn example(name: &str) -> String {
    repo().join("examples").join(name).to_string_lossy().into_owned()
}

fn tempdir(tag: &str) -> PathBuf {
    common::tmp("hardening", tag)
}

/// Item 8: a closed pipe ends quietly with exit code 0, not a panic.
#[cfg(unix)]
#[test]
fn closed_pipe_is_quiet() {
    let mut child = tmm()
        .args(["linkage", &example("seed-001-fourbar.toml"), "--json"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // read one line, then close the pipe
    let mut out = child.stdout.take().unwrap();
    let mut first = [0u8; 2];
    std::io::Read::read_exact(&mut out, &mut first).unwrap();
    drop(out);
    let o = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!err.contains("panicked"), "{err}");
    assert_eq!(o.status.code(), Some(0), "{err}");
}

/// Item 8: a failed write (a full disk) exits 1 with the message.
#[cfg(target_os = "linux")]
#[test]
fn full_disk_exits_1() {
    let full = std::fs::File::create("/dev/full").unwrap();
    let o = tmm()
        .args(["linkage", &example("seed-001-fourbar.toml"), "--json"])
        .stdout(full)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("No space left") && !err.contains("panicked"), "{err}");
}

/// Item 12: a section that fails after another succeeded writes nothing, and
/// leaves an earlier run's folder as it was.
#[test]
fn a_failed_run_writes_nothing() {
    let dir = tempdir("allornothing");
    let good = std::fs::read_to_string(example("seed-001-fourbar.toml")).unwrap();
    std::fs::write(dir.join("good.toml"), &good).unwrap();
    let (c, _, e) = run(&[
        "run",
        dir.join("good.toml").to_str().unwrap(),
        "--out",
        dir.join("out").to_str().unwrap(),
    ]);
    assert_eq!(c, 0, "{e}");
    let before: Vec<_> = std::fs::read_dir(dir.join("out/linkage"))
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    // a [forces] error after a [linkage] that works
    let bad = good.replace("[forces]", "[forces]\nk = -5");
    std::fs::write(dir.join("bad.toml"), bad).unwrap();
    let (c, _, e) = run(&[
        "run",
        dir.join("bad.toml").to_str().unwrap(),
        "--out",
        dir.join("out2").to_str().unwrap(),
    ]);
    assert_eq!(c, 2, "{e}");
    assert!(!dir.join("out2").exists(), "a failed run left files");
    let (c, _, _) = run(&[
        "run",
        dir.join("bad.toml").to_str().unwrap(),
        "--out",
        dir.join("out").to_str().unwrap(),
    ]);
    assert_eq!(c, 2);
    let after: Vec<_> = std::fs::read_dir(dir.join("out/linkage"))
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(before, after);
    // nothing left beside the folders
    let beside: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert!(
        beside.iter().all(|n| !n.contains("tmm-tmp") && !n.contains("tmm-old")),
        "{beside:?}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Item 12: a run replaces the files of an earlier run; the same input gives
/// byte-identical files (DXF included).
#[test]
fn runs_are_deterministic_and_replace_the_old() {
    let dir = tempdir("determinism");
    let out = dir.join("out");
    let (c, _, e) = run(&["run", "--out", out.to_str().unwrap()]);
    assert_eq!(c, 0, "{e}");
    let read_all = |root: &Path| -> Vec<(String, Vec<u8>)> {
        let mut v = Vec::new();
        let mut stack = vec![root.to_path_buf()];
        while let Some(d) = stack.pop() {
            for e in std::fs::read_dir(&d).unwrap() {
                let p = e.unwrap().path();
                if p.is_dir() {
                    stack.push(p);
                } else {
                    v.push((
                        p.strip_prefix(root).unwrap().to_string_lossy().into_owned(),
                        std::fs::read(&p).unwrap(),
                    ));
                }
            }
        }
        v.sort();
        v
    };
    let first = read_all(&out);
    assert!(first.iter().any(|(n, _)| n.ends_with(".dxf")));
    std::fs::write(out.join("gear/stale.svg"), "x").unwrap();
    let (c, _, e) = run(&["run", "--out", out.to_str().unwrap()]);
    // the planted file is not tmm's: the run refuses rather than delete it
    assert_eq!(c, 2, "{e}");
    assert!(e.contains("did not write"), "{e}");
    std::fs::remove_file(out.join("gear/stale.svg")).unwrap();
    let (c, _, e) = run(&["run", "--out", out.to_str().unwrap()]);
    assert_eq!(c, 0, "{e}");
    let second = read_all(&out);
    assert_eq!(first.len(), second.len());
    for (a, b) in first.iter().zip(&second) {
        assert_eq!(a.0, b.0);
        assert!(a.1 == b.1, "{} differs between two runs", a.0);
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Item 17: `"units": "SI"` is the first key, and `tmm run --json` has the title.
#[test]
fn json_starts_with_units_and_has_the_title() {
    let dir = tempdir("json");
    let (c, out, e) = run(&["run", "--json", "--out", dir.join("o").to_str().unwrap()]);
    assert_eq!(c, 0, "{e}");
    let first_key = out.lines().nth(1).unwrap().trim();
    assert!(first_key.starts_with("\"units\": \"SI\""), "{first_key}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert!(v["title"].as_str().is_some_and(|t| !t.is_empty()));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Item 10: a plain module is metres; 5 m is refused with "did you mean 5 mm?".
#[test]
fn module_unit_slip() {
    let (c, _, e) = run(&[
        "gear", "pair", "--z1", "15", "--z2", "20", "--module", "5", "--x1", "0", "--x2", "0",
    ]);
    assert_eq!(c, 2);
    assert!(e.contains("--module") && e.contains("did you mean 5 mm"), "{e}");
    let (c, _, e) = run(&[
        "planetary",
        "--scheme",
        "sun-planet-ring",
        "--ratio",
        "6",
        "--planets",
        "3",
        "--module",
        "1e160 mm",
    ]);
    assert_eq!(c, 2, "{e}");
    assert!(e.contains("--module"), "{e}");
}

/// Item 14: the message names wheel 1 and gives the right advice.
#[test]
fn pointed_wheel_message() {
    let (c, _, e) = run(&[
        "gear", "pair", "--z1", "15", "--z2", "20", "--module", "5 mm", "--x1", "5", "--x2", "0",
    ]);
    assert_eq!(c, 2);
    assert!(!e.contains("wheel 0"), "{e}");
    assert!(e.contains("--x1") && e.contains("lower x1"), "{e}");
}

/// Item 3: the undercut pinion of 10/60 fails the interference check.
#[test]
fn undercut_pinion_interferes() {
    let (c, out, e) = run(&[
        "gear", "pair", "--z1", "10", "--z2", "60", "--module", "1 mm", "--x1", "0", "--x2", "0", "--json",
    ]);
    assert_eq!(c, 0, "{e}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["checks"]["interference1"]["pass"], false, "{}", v["checks"]);
}

/// Item 17: α = 25° works with the largest fillet that fits, and says so;
/// --sa-min's default is GOST's 0.3.
#[test]
fn alpha_25_and_sa_min_default() {
    let (c, out, e) = run(&[
        "gear", "pair", "--z1", "15", "--z2", "20", "--module", "5 mm", "--x1", "0.2", "--x2", "0.85", "--alpha", "25",
    ]);
    assert_eq!(c, 0, "{e}");
    assert!(out.contains("does not fit this rack"), "{out}");
    let (_, help, _) = run(&["gear", "pair", "--help"]);
    assert!(help.contains("[default: 0.3]"), "{help}");
}

/// Item 13: a misspelt follower kind is named, not the valid stroke.
#[test]
fn misspelt_follower() {
    let text = std::fs::read_to_string(example("cam-oscillating-roller.toml"))
        .unwrap()
        .replace("oscillating-roller", "oscilating-roller");
    let dir = tempdir("follower");
    let f = dir.join("t.toml");
    std::fs::write(&f, text).unwrap();
    let (c, _, e) = run(&["cam", f.to_str().unwrap()]);
    assert_eq!(c, 2);
    assert!(
        e.contains("cam.follower") && e.contains("oscillating-roller") && !e.contains("cam.stroke"),
        "{e}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Item 15: columns count characters on Cyrillic lines; an unknown key is
/// located where it is written, not in a comment that mentions it; zmax
/// below zmin blames zmax; no Rust debug text.
#[test]
fn error_locations() {
    let dir = tempdir("locations");
    let f = dir.join("t.toml");
    std::fs::write(&f, "# the gearbox section comes later\ntitle = \"Кривошип\"\ngearbox = 1\n").unwrap();
    let (c, _, e) = run(&["run", f.to_str().unwrap(), "--out", dir.join("o").to_str().unwrap()]);
    assert_eq!(c, 2);
    assert!(e.contains("t.toml:3:1: gearbox"), "{e}");
    std::fs::write(
        &f,
        "title = \"Механизм\"\n[planetary]\nscheme = \"sun-planet-ring\"\nratio = 6\nplanets = 3\nzmax = 5\n",
    )
    .unwrap();
    let (c, _, e) = run(&["planetary", f.to_str().unwrap()]);
    assert_eq!(c, 2);
    assert!(e.contains("t.toml:6:8: planetary.zmax"), "{e}");
    std::fs::write(&f, "title = \"Механизм\" \n[cam]\nfollower = \"translating-roller\"\nstroke = \"13 mm\"\nphases = \"rise 180 cosine; return 180 cosine\"\nmax_pressure = [1]\n").unwrap();
    let (c, _, e) = run(&["cam", f.to_str().unwrap()]);
    assert_eq!(c, 2);
    assert!(!e.contains("RawQty") && !e.contains("untagged"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Item 15: a ratio no tooth numbers reach names the reachable range.
#[test]
fn unreachable_ratio_names_the_range() {
    let (c, _, e) = run(&["planetary", "--scheme", "sun-planet-ring", "--ratio", "1e6", "--planets", "3"]);
    assert_eq!(c, 2);
    // 1 + zmax/zmin = 1 + 200/17
    assert!(e.contains(&format!("{:.4}", 1.0 + 200.0 / 17.0)), "{e}");
}

/// Item 11: huge requests are refused before they exhaust memory.
#[test]
fn huge_requests_are_refused() {
    let (c, _, e) = run(&[
        "gear", "pair", "--z1", "20000", "--z2", "20000", "--module", "1 mm", "--x1", "0", "--x2", "0",
    ]);
    assert_eq!(c, 2, "{e}");
    let (c, _, e) = run(&["linkage", &example("seed-001-fourbar.toml"), "--positions", "100000"]);
    assert_eq!(c, 2, "{e}");
    assert!(e.contains("--positions"), "{e}");
}

/// Item 18: a given cam is analysed (r0 given), and a program may carry a
/// stroke per phase with an intermediate dwell level.
#[test]
fn cam_analysis_and_per_phase_strokes() {
    // An axial roller follower, cosine rise h over β: the pressure angle
    // tg ϑ = (ds/dφ)/(r0 + s); its maximum is found here by brute force.
    let (h, beta, r0) = (0.013f64, 108f64.to_radians(), 0.0508f64);
    let best = (0..=20000)
        .map(|i| {
            let x = std::f64::consts::PI * i as f64 / 20000.0;
            let s = h / 2.0 * (1.0 - x.cos());
            let ds = h / 2.0 * std::f64::consts::PI / beta * x.sin();
            ds.atan2(r0 + s)
        })
        .fold(0.0f64, f64::max)
        .to_degrees();
    let (c, out, e) = run(&[
        "cam",
        "--follower",
        "translating-roller",
        "--stroke",
        "13 mm",
        "--phases",
        "rise 108 cosine; dwell 15; return 108 cosine; dwell 129",
        "--r0",
        "2 in",
        "--offset",
        "0 mm",
        "--json",
    ]);
    assert_eq!(c, 0, "{e}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let got = v["pressure_angle_max_rise"].as_f64().unwrap().to_degrees();
    assert!((got - best).abs() < 1e-3, "{got} vs {best}");
    let (c, out, e) = run(&[
        "cam",
        "--follower",
        "translating-roller",
        "--phases",
        "rise 90 cosine 20mm; dwell 30; return 60 cosine 10mm; dwell 20; return 60 cosine 10mm; dwell 100",
        "--max-pressure",
        "30",
    ]);
    assert_eq!(c, 0, "{e}");
    assert!(out.contains("20.0000 mm"), "{out}");
}

/// Item 17: a slider block tmm creates has its centre of mass in the JSON,
/// at the block's joint (seed 004: block 3 at C on the guide through A,
/// block 5 at D on the vertical guide 60 mm right of A).
#[test]
fn slider_blocks_have_their_mass_centre() {
    let (c, out, e) = run(&["linkage", &example("seed-004-two-sliders.toml"), "--at", "40", "--json"]);
    assert_eq!(c, 0, "{e}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let row = &v["positions"][0];
    for (link, point) in [("3", "C"), ("5", "D")] {
        let s = &row["links"][link]["mass_center"];
        let p = &row["points"][point];
        for k in ["x", "y", "vx", "vy"] {
            let (a, b) = (s[k].as_f64().unwrap(), p[k].as_f64().unwrap());
            assert!((a - b).abs() < 1e-12, "link {link} {k}: {a} vs {point} {b}");
        }
    }
    assert!(row["links"]["3"]["mass_center"]["y"].as_f64().unwrap().abs() < 1e-12);
    assert!((row["links"]["5"]["mass_center"]["x"].as_f64().unwrap() - 0.06).abs() < 1e-12);
}

/// Items 9 and 15: an empty slider link and a speed out of range are located
/// at the value the user wrote.
#[test]
fn linkage_values_are_located() {
    let dir = tempdir("linkloc");
    let f = dir.join("t.toml");
    let text = std::fs::read_to_string(example("seed-004-two-sliders.toml")).unwrap();
    let bad = text.replacen("link = \"3\"", "link = \"\"", 1);
    let line = bad.lines().position(|l| l == "link = \"\"").unwrap() + 1;
    std::fs::write(&f, &bad).unwrap();
    let (c, _, e) = run(&["linkage", f.to_str().unwrap()]);
    assert_eq!(c, 2);
    assert!(e.contains(&format!("t.toml:{line}:8: linkage.sliders[0].link")), "{e}");
    let bad = text.replacen("speed = \"40.82 rad/s\"", "speed = \"1e300 rpm\"", 1);
    let line = bad.lines().position(|l| l.contains("1e300 rpm")).unwrap() + 1;
    std::fs::write(&f, &bad).unwrap();
    let (c, _, e) = run(&["linkage", f.to_str().unwrap()]);
    assert_eq!(c, 2);
    assert!(e.contains(&format!("t.toml:{line}:")) && e.contains("linkage.input.speed"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The crank angles of a four-bar where the coupler BC and the rocker DC are
/// collinear (derived here): |BD| = BC + DC (extended) or |BC − DC|
/// (folded), and by the law of cosines in triangle ABD
/// |BD|² = AB² + AD² − 2·AB·AD·cos φ, so cos φ = (AB² + AD² − |BD|²)/(2·AB·AD).
/// Returns the angle in [0, π] for a given |BD|.
fn collinear_angle(ab: f64, ad: f64, bd: f64) -> f64 {
    ((ab * ab + ad * ad - bd * bd) / (2.0 * ab * ad)).acos()
}

/// Item 16: a double rocker driven over its swing is analysed over the
/// ranges where it assembles; the ranges' ends are where the coupler and the
/// rocker are collinear. A range ends where the group's velocity equations
/// become singular (sine of the angle between coupler and rocker 1e-4, so
/// |BD| is within b·c·δ²/(2|b ± c|) < 1e-9 m of the collinear length): the
/// end lies within 1e-7 rad of the closed form.
#[test]
fn double_rocker_partial_ranges() {
    let (code, out, err) = run(&["linkage", &example("double-rocker.toml"), "--json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["range"], "partial");
    let (ab, bc, dc, ad) = (0.3, 0.1, 0.35, 0.4);
    let folded = collinear_angle(ab, ad, dc - bc); // |BD| least: 38.62°
    let extended = collinear_angle(ab, ad, bc + dc); // |BD| greatest: 78.58°
    let tau = std::f64::consts::TAU;
    let expected = [(folded, extended), (tau - extended, tau - folded)];
    let ranges = v["assembly_ranges"].as_array().unwrap();
    assert_eq!(ranges.len(), 2, "{ranges:?}");
    for (r, (from, to)) in ranges.iter().zip(expected) {
        assert!((r["from"].as_f64().unwrap() - from).abs() < 1e-7, "{r} vs {from}");
        assert!((r["to"].as_f64().unwrap() - to).abs() < 1e-7, "{r} vs {to}");
    }
    let gaps = v["gaps"].as_array().unwrap();
    assert_eq!(gaps.len(), 2);
    assert!((gaps[0]["from"].as_f64().unwrap() - extended).abs() < 1e-7);
    assert!((gaps[0]["to"].as_f64().unwrap() - (tau - extended)).abs() < 1e-7);
    // the table keeps inside the ranges and its analogs agree with ω3/ω1
    for p in v["positions"].as_array().unwrap() {
        let phi = p["phi"].as_f64().unwrap();
        assert!(expected.iter().any(|&(a, b)| phi > a && phi < b), "{phi}");
        let w3 = p["links"]["3"]["omega"].as_f64().unwrap();
        let ds = p["output"]["ds_dphi"].as_f64().unwrap();
        assert!((ds - w3 / std::f64::consts::PI).abs() < 1e-9 * w3.abs().max(1.0), "{ds} {w3}");
    }
    // the diagrams break at the gap
    assert_eq!(v["diagrams"]["breaks"].as_array().unwrap().len(), 1);
    // the text names the ranges and the gaps
    let (code, out, err) = run(&["linkage", &example("double-rocker.toml")]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("range 1: φ = 38.62") && out.contains("gap 1: φ = 78.58"), "{out}");
}

/// Item 16: `at` outside the ranges names the nearest one; the full-turn
/// default refuses and points at the option; forces refuse a partial range.
#[test]
fn double_rocker_errors() {
    let (code, _, err) = run(&["linkage", &example("double-rocker.toml"), "--at", "100 deg"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("nearest range where it does is 38.62") && !err.contains("panicked"),
        "{err}"
    );
    let (code, out, err) = run(&["linkage", &example("double-rocker.toml"), "--at", "300 deg"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("POINTS at φ = 300.0000°"), "{out}");
    let dir = tempdir("partial");
    let text = std::fs::read_to_string(example("double-rocker.toml")).unwrap();
    let full = dir.join("full.toml");
    std::fs::write(&full, text.replace("range = \"partial\"\n", "")).unwrap();
    let (code, _, err) = run(&["linkage", &full.to_string_lossy()]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("range = \"partial\""), "{err}");
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, text.replace("range = \"partial\"", "range = \"half\"")).unwrap();
    let (code, _, err) = run(&["linkage", &bad.to_string_lossy()]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("linkage.range") && err.contains("\"partial\""), "{err}");
    let forces = dir.join("forces.toml");
    std::fs::write(&forces, format!("{text}\n[forces]\nmass_per_length = \"10 kg/m\"\n")).unwrap();
    let (code, _, err) = run(&["forces", &forces.to_string_lossy()]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("[forces] needs a crank that turns a full revolution"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issues 10/11: a motor with an absurd torque, a huge inertia on the motor
/// shaft or a huge number of points is refused at once with the field named,
/// not run for seconds nor reported as a NaN angle.
#[test]
fn dynamics_bounds() {
    let text = std::fs::read_to_string(example("seed-003-sixbar.toml")).unwrap();
    let dir = tempdir("dynbounds");
    let cases = [
        (
            text.replace("nominal_torque = \"26.7 N m\"", "nominal_torque = \"1e300 N m\""),
            "dynamics.motor.nominal_torque: must be > 0 and at most 1e9",
        ),
        (
            text.replace("nominal_torque = \"26.7 N m\"", "nominal_torque = \"1e9 N m\""),
            "so steep",
        ),
        (
            text.replace("motor_shaft = \"0.015 kg m^2\"", "motor_shaft = \"1e5 kg m^2\""),
            "time constant",
        ),
        (
            text.replace("delta = 0.05", "delta = 0.05\npoints = 1000008"),
            "360…36000 intervals",
        ),
    ];
    for (i, (t, want)) in cases.iter().enumerate() {
        assert_ne!(t, &text, "case {i} did not change the file");
        let f = dir.join(format!("case{i}.toml"));
        std::fs::write(&f, t).unwrap();
        let (code, _, err) = run(&["dynamics", &f.to_string_lossy()]);
        assert_eq!(code, 2, "{err}");
        assert!(
            err.contains(want) && !err.contains("NaN") && !err.contains("panicked"),
            "case {i}: {err}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// A value of 1e300 or 1e-300 is quoted in the message as such, not as 301
/// digits or 300 zeros, and a huge positive shift sum is called too large,
/// not too negative.
#[test]
fn numbers_in_messages_stay_short() {
    let cases: [(&[&str], &str); 5] = [
        (&["--module", "1e-300mm"], "got 1e-300 mm"),
        (&["--module", "1e300"], "got 1e303 mm"),
        (
            &["--module", "3mm", "--x1", "1e300", "--x2", "0"],
            "the shift sum 1e300 is too large",
        ),
        (
            &["--module", "3mm", "--x1", "-1e300", "--x2", "0"],
            "the shift sum -1e300 is too negative",
        ),
        (&["--module", "3mm", "--sa-min", "1e300"], "got 1e300"),
    ];
    for (extra, want) in cases {
        let mut args = vec!["gear", "pair", "--z1", "17", "--z2", "40"];
        args.extend_from_slice(extra);
        let (code, _, err) = run(&args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains(want), "{args:?}: {err}");
        assert!(longest_number(&err) <= 12, "{args:?}: {err}");
    }
}
