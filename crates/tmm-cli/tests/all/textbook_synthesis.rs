//! The BMSTU textbook's synthesis examples (appendix П1) through the
//! command line: each `examples/textbook/p1-*.toml` runs through `tmm run`,
//! its JSON carries every quantity GIVENS.md lists under "Asked", and the
//! `[linkage]` it writes, analysed again by `tmm linkage --at φ`, puts the
//! driven point where the book's givens say (the rocker at γ, the slider's
//! travel, the cylinder's |DB| = h + l_шт and its pressure angle). The new
//! `tmm synth` kinds write a task that runs through `linkage`, `forces` and
//! `run`.

use std::f64::consts::{FRAC_PI_2, PI};
use std::path::{Path, PathBuf};

use crate::common::{self, run};

fn tmp(name: &str) -> PathBuf {
    common::tmp("textbook", name)
}

/// `tmm run FILE --no-pdf --json`: the document and the output folder.
fn run_example(file: &str) -> (serde_json::Value, PathBuf) {
    let d = tmp(file);
    let out = d.join("out");
    let f = common::repo().join("examples/textbook").join(file);
    let (code, stdout, err) = run(&["run", "--no-pdf", f.to_str().unwrap(), "-o", out.to_str().unwrap(), "--json"]);
    assert_eq!(code, 0, "{file}: {err}");
    (serde_json::from_str(&stdout).unwrap(), out)
}

/// The points of the written `[linkage]` at crank angle `deg`, by the core.
fn points_at(linkage: &Path, deg: f64) -> serde_json::Value {
    let (code, stdout, err) = run(&["linkage", linkage.to_str().unwrap(), "--json", "--at", &format!("{deg}")]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    v["positions"][0]["points"].clone()
}

fn xy(p: &serde_json::Value) -> (f64, f64) {
    (p["x"].as_f64().unwrap(), p["y"].as_f64().unwrap())
}

fn f(v: &serde_json::Value, ptr: &str) -> f64 {
    v.pointer(ptr)
        .and_then(|x| x.as_f64())
        .unwrap_or_else(|| panic!("no number at {ptr}"))
}

fn close(what: &str, got: f64, want: f64, tol: f64) {
    assert!((got - want).abs() <= tol, "{what}: {got} vs {want}");
}

fn wrap(a: f64) -> f64 {
    (a + PI).rem_euclid(2.0 * PI) - PI
}

/// The rocker's angle D→C at crank angle `deg`.
fn rocker_at(linkage: &Path, deg: f64) -> f64 {
    let p = points_at(linkage, deg);
    let (c, d) = (xy(&p["C"]), xy(&p["D"]));
    (c.1 - d.1).atan2(c.0 - d.0)
}

#[test]
fn p1_1_runs_and_its_slider_travels_between_the_two_positions() {
    let (v, out) = run_example("p1-1-crank-slider-two-positions.toml");
    let s = &v["synthesis"];
    for p in [
        "/lengths/OA",
        "/lengths/AB",
        "/lengths/e",
        "/angles/phi2_start",
        "/angles/phi2_end",
        "/coordinates/X_C_start",
    ] {
        f(s, p);
    }
    let (l1, l2, e) = (f(s, "/lengths/OA"), f(s, "/lengths/AB"), f(s, "/lengths/e"));
    close("λ2", l2 / l1, 2.5, 1e-12);
    close("λe", e / l1, 0.4, 1e-12);
    let lk = out.join("synthesis/linkage.toml");
    let (b0, b1) = (xy(&points_at(&lk, 60.0)["B"]), xy(&points_at(&lk, 150.0)["B"]));
    close("X_Cн", b0.0, f(s, "/coordinates/X_C_start"), 1e-9);
    close("h_C", b0.0 - b1.0, 0.15, 1e-9);
    close("guide", b0.1, e, 1e-9);
    // the rod's angles at A, from the positions
    let a0 = xy(&points_at(&lk, 60.0)["A"]);
    close("φ2н", (b0.1 - a0.1).atan2(b0.0 - a0.0), f(s, "/angles/phi2_start"), 1e-9);
}

#[test]
fn p1_2_runs_and_its_rocker_swings_between_the_given_angles() {
    let (v, out) = run_example("p1-2-four-bar-extreme-positions.toml");
    let s = &v["synthesis"];
    for p in ["/lengths/AB", "/lengths/BC", "/angles/phi1_start", "/angles/theta"] {
        f(s, p);
    }
    let th = f(s, "/angles/theta");
    close("K", f(&v, "/linkage/kv"), (PI + th) / (PI - th), 1e-9);
    close("swing", f(&v, "/linkage/stroke"), 60f64.to_radians(), 1e-9);
    let lk = out.join("synthesis/linkage.toml");
    let p0 = f(s, "/angles/phi1_start").to_degrees();
    close("γн", rocker_at(&lk, p0), 70f64.to_radians(), 1e-9);
    close("γк", rocker_at(&lk, p0 + 180.0 + th.to_degrees()), 130f64.to_radians(), 1e-9);
}

#[test]
fn p1_3_runs_reaches_k_and_its_frame_abscissa_gives_the_extremes() {
    let (v, out) = run_example("p1-3-four-bar-extreme-positions-k.toml");
    let s = &v["synthesis"];
    for p in [
        "/lengths/AB",
        "/lengths/BC",
        "/angles/phi1_start",
        "/angles/theta",
        "/coordinates/X_D",
    ] {
        f(s, p);
    }
    close("X_D in the frame", f(s, "/frame/D/0"), f(s, "/coordinates/X_D"), 0.0);
    close("K", f(&v, "/linkage/kv"), 1.2, 1e-9);
    close("θ", f(s, "/angles/theta"), PI * 0.2 / 2.2, 1e-12);
    let lk = out.join("synthesis/linkage.toml");
    let p0 = f(s, "/angles/phi1_start").to_degrees();
    close("γн", rocker_at(&lk, p0), 50f64.to_radians(), 1e-9);
    close(
        "γк",
        rocker_at(&lk, p0 + 180.0 + f(s, "/angles/theta").to_degrees()),
        110f64.to_radians(),
        1e-9,
    );
}

#[test]
fn p1_4_runs_and_passes_through_its_three_positions() {
    let (v, out) = run_example("p1-4-four-bar-three-positions.toml");
    let s = &v["synthesis"];
    for p in [
        "/lengths/AB",
        "/lengths/BC",
        "/angles/phi1_start",
        "/angles/phi2_1",
        "/angles/phi2_2",
        "/angles/phi2_3",
    ] {
        f(s, p);
    }
    let lk = out.join("synthesis/linkage.toml");
    let p0 = f(s, "/angles/phi1_start").to_degrees();
    for (j, (dp, g)) in [(0.0, 70.0), (30.0, 80.0), (120.0, 120.0)].into_iter().enumerate() {
        close(&format!("γ{}", j + 1), rocker_at(&lk, p0 + dp), f64::to_radians(g), 1e-9);
        let p = points_at(&lk, p0 + dp);
        let (b, c) = (xy(&p["B"]), xy(&p["C"]));
        close(
            &format!("φ2{}", j + 1),
            wrap((c.1 - b.1).atan2(c.0 - b.0) - f(s, &format!("/angles/phi2_{}", j + 1))),
            0.0,
            1e-9,
        );
    }
}

#[test]
fn p1_5_runs_each_variant_with_the_cylinders_stroke_and_pressure_angles() {
    for (file, given_end, yd) in [
        ("p1-5-oscillating-cylinder-v1.toml", true, 0.05),
        ("p1-5-oscillating-cylinder-v2.toml", true, -0.121),
        ("p1-5-oscillating-cylinder-v3.toml", false, -0.193),
    ] {
        let (v, out) = run_example(file);
        let s = &v["synthesis"];
        for p in [
            "/coordinates/X_D",
            "/coordinates/Y_D",
            "/lengths/OB",
            "/angles/phi1",
            "/angles/phi3_start",
            "/angles/phi3_end",
            "/angles/theta_start",
            "/angles/theta_end",
        ] {
            f(s, p);
        }
        close("Y_D", f(s, "/coordinates/Y_D"), yd, 1e-12);
        assert!(s["free_parameter"]["reason"].as_str().unwrap().contains("turn about O"));
        let lk = out.join("synthesis/linkage.toml");
        let p1 = f(s, "/angles/phi1");
        for (k, (len, th)) in [(0.44, "/angles/theta_start"), (0.69, "/angles/theta_end")].into_iter().enumerate() {
            let phi = p1 + k as f64 * 60f64.to_radians();
            let p = points_at(&lk, phi.to_degrees());
            let (b, d) = (xy(&p["B"]), xy(&p["D"]));
            let axis = (b.1 - d.1).atan2(b.0 - d.0);
            close(&format!("{file}: |DB|"), (b.0 - d.0).hypot(b.1 - d.1), len, 1e-9);
            close(&format!("{file}: θ"), wrap(phi + FRAC_PI_2 - axis - f(s, th)), 0.0, 1e-9);
        }
        let given = if given_end {
            ("/angles/theta_end", 50.0)
        } else {
            ("/angles/theta_start", 10.0)
        };
        close("given θ", f(s, given.0), f64::to_radians(given.1), 1e-9);
    }
}

#[test]
fn the_new_kinds_write_a_task_that_runs_through_linkage_forces_and_run() {
    let cases: [(&str, &[&str]); 4] = [
        (
            "re",
            &[
                "rocker-extremes",
                "--frame-x",
                "0.8 m",
                "--frame-y",
                "-0.1 m",
                "--rocker",
                "0.5 m",
                "--gamma-start",
                "70",
                "--gamma-end",
                "130",
            ],
        ),
        (
            "rek",
            &[
                "rocker-extremes-k",
                "--k",
                "1.2",
                "--frame-y",
                "-0.1 m",
                "--rocker",
                "0.5 m",
                "--gamma-start",
                "50",
                "--gamma-end",
                "110",
            ],
        ),
        (
            "tp",
            &[
                "three-positions",
                "--frame-x",
                "0.5 m",
                "--frame-y",
                "-0.1 m",
                "--rocker",
                "0.5 m",
                "--gamma1",
                "70",
                "--gamma2",
                "80",
                "--gamma3",
                "120",
                "--phi12",
                "30",
                "--phi13",
                "120",
            ],
        ),
        (
            "oc",
            &[
                "oscillating-cylinder",
                "--h-min",
                "50 mm",
                "--h-max",
                "300 mm",
                "--rod",
                "390 mm",
                "--swing",
                "60",
                "--pressure-start",
                "10",
            ],
        ),
    ];
    for (n, a) in cases {
        let d = tmp(n);
        let t = d.join("t.toml");
        let ts = t.to_str().unwrap();
        let svg = d.join("svg");
        let mut args = vec!["synth"];
        args.extend_from_slice(a);
        args.extend_from_slice(&["--task", ts, "--svg", svg.to_str().unwrap()]);
        let (code, _, err) = run(&args);
        assert_eq!(code, 0, "{n}: {err}");
        // a lever that does not turn fully (the oscillating cylinder's) is
        // written with range = "partial" and without [forces], which needs a
        // full turn
        let partial = std::fs::read_to_string(&t).unwrap().contains("range = \"partial\"");
        let mut cmds = vec![vec!["linkage", ts]];
        if !partial {
            cmds.push(vec!["forces", ts]);
        }
        let out = d.join("out");
        cmds.push(vec!["run", "--no-pdf", ts, "-o", out.to_str().unwrap()]);
        for cmd in cmds {
            let (code, _, err) = run(&cmd);
            assert_eq!(code, 0, "{n}: tmm {}: {err}", cmd[0]);
        }
    }
}

#[test]
fn bad_textbook_input_names_the_field_and_exits_2() {
    // the first position folded: D far to the left
    let (code, _, err) = run(&[
        "synth",
        "rocker-extremes",
        "--frame-x",
        "-0.8 m",
        "--frame-y",
        "-0.1 m",
        "--rocker",
        "0.5 m",
        "--gamma-start",
        "70",
        "--gamma-end",
        "130",
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--frame-x") && err.contains("extended"), "{err}");
    // Y_D beyond the reach |OD| of the family
    let (code, _, err) = run(&[
        "synth",
        "oscillating-cylinder",
        "--h-min",
        "50 mm",
        "--h-max",
        "300 mm",
        "--rod",
        "390 mm",
        "--swing",
        "60",
        "--pressure-end",
        "50",
        "--frame-y",
        "2 m",
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--frame-y") && err.contains("nearest feasible"), "{err}");
    // both pressure angles
    let (code, _, err) = run(&[
        "synth",
        "oscillating-cylinder",
        "--h-min",
        "50 mm",
        "--h-max",
        "300 mm",
        "--rod",
        "390 mm",
        "--swing",
        "60",
        "--pressure-end",
        "50",
        "--pressure-start",
        "10",
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("only one of"), "{err}");
}

#[test]
fn seed_002_knee_press_with_the_bell_crank_runs_and_reaches_k_and_stroke() {
    let d = tmp("knee-bell");
    let out = d.join("out");
    let file = common::repo().join("examples/synth-seed-002-ex2-knee-press-bell-crank.toml");
    let (code, stdout, err) = run(&["run", "--no-pdf", file.to_str().unwrap(), "-o", out.to_str().unwrap(), "--json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    close("K", f(&v, "/linkage/kv"), 1.12, 1e-9);
    close("H_F", f(&v, "/linkage/stroke"), 0.09, 1e-9);
    let s = &v["synthesis"];
    assert!((f(s, "/lengths/OA") / 0.055 - 1.0).abs() < 0.011);
    assert!((f(s, "/lengths/AB") / 0.255 - 1.0).abs() < 0.011);
    close("l_BD", f(s, "/lengths/BD"), 0.11, 1e-15);
}
