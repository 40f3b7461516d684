//! `tmm synth` and `[synthesis]` from the outside: each kind's result is
//! analysed again by `tmm linkage` from the task file `--task` writes (K,
//! stroke or swing, the given positions — the linkage core's own cycle
//! analysis, not the synthesis), the JSON contract, the table of variants,
//! bad input answered with exit code 2 naming the option or the located
//! field, and the examples run through `tmm run`.

use std::path::PathBuf;
use std::process::Command;

fn tmm() -> Command {
    Command::new(env!("CARGO_BIN_EXE_tmm"))
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("tmm-synth-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn run(args: &[&str]) -> (i32, String, String) {
    let o = tmm().args(args).output().unwrap();
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

fn json(args: &[&str]) -> serde_json::Value {
    let (code, out, err) = run(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    serde_json::from_str(&out).unwrap_or_else(|e| panic!("{args:?}: {e}\n{out}"))
}

/// `tmm synth KIND ARGS --task t.toml`, then `tmm linkage t.toml --json [--at φ]`.
fn synth_then_linkage(name: &str, synth: &[&str], at: Option<&str>) -> serde_json::Value {
    let d = tmp(name);
    let t = d.join("t.toml");
    let mut a: Vec<&str> = vec!["synth"];
    a.extend_from_slice(synth);
    let ts = t.to_str().unwrap();
    a.extend_from_slice(&["--task", ts]);
    let (code, _, err) = run(&a);
    assert_eq!(code, 0, "{a:?}: {err}");
    let mut l = vec!["linkage", ts, "--json"];
    if let Some(p) = at {
        l.extend_from_slice(&["--at", p]);
    }
    json(&l)
}

fn close(what: &str, got: f64, want: f64, tol: f64) {
    assert!((got - want).abs() <= tol, "{what}: {got} vs {want}");
}

fn deg(x: f64) -> f64 {
    x.to_radians()
}

#[test]
fn crank_rocker_each_condition_reaches_k_and_swing() {
    for (n, cond) in [
        ("cr-crank", ["--crank", "100 mm"].as_slice()),
        ("cr-frame", ["--frame", "350 mm"].as_slice()),
        ("cr-opt", ["--optimum"].as_slice()),
    ] {
        let mut a = vec![
            "crank-rocker",
            "--k",
            "1.28",
            "--swing",
            "60",
            "--rocker",
            "245 mm",
            "--speed",
            "900 rpm",
        ];
        a.extend_from_slice(cond);
        let v = synth_then_linkage(n, &a, None);
        close("Kv", v["kv"].as_f64().unwrap(), 1.28, 1e-9);
        close("swing", v["stroke"].as_f64().unwrap(), deg(60.0), 1e-9);
        close(
            "ω1",
            v["input"]["omega"].as_f64().unwrap(),
            900.0 * std::f64::consts::TAU / 60.0,
            1e-9,
        );
    }
}

#[test]
fn crank_slider_each_condition_reaches_k_and_stroke() {
    for (n, cond) in [
        ("cs-lambda", ["--lambda", "3.5"].as_slice()),
        ("cs-offset", ["--offset", "40 mm"].as_slice()),
        ("cs-pressure", ["--max-pressure", "45"].as_slice()),
        ("cs-cw", ["--lambda", "4", "--direction", "cw"].as_slice()),
    ] {
        let mut a = vec!["crank-slider", "--stroke", "300 mm", "--k", "1.2"];
        a.extend_from_slice(cond);
        let v = synth_then_linkage(n, &a, None);
        close("Kv", v["kv"].as_f64().unwrap(), 1.2, 1e-9);
        close("stroke", v["stroke"].as_f64().unwrap(), 0.3, 1e-9);
        let w = v["input"]["omega"].as_f64().unwrap();
        assert_eq!(w < 0.0, n == "cs-cw", "{n}: direction");
    }
}

#[test]
fn knee_press_shaper_and_six_bars_reach_k_and_stroke() {
    let cases: [(&str, &[&str], f64, f64); 3] = [
        (
            "knee",
            &[
                "knee-press",
                "--stroke",
                "90 mm",
                "--k",
                "1.12",
                "--rocker",
                "220 mm",
                "--link",
                "220 mm",
                "--delta",
                "5",
                "--horizontal",
                "280 mm",
                "--direction",
                "cw",
            ],
            1.12,
            0.09,
        ),
        (
            "shaper",
            &[
                "slotted-lever",
                "--stroke",
                "400 mm",
                "--k",
                "1.5",
                "--pivots",
                "50 mm",
                "--coupler-ratio",
                "3",
            ],
            1.5,
            0.4,
        ),
        (
            "inversion",
            &[
                "six-bar-inversion",
                "--k",
                "1.15",
                "--travel",
                "360 mm",
                "--guide",
                "-320 mm",
                "--start",
                "180 mm",
                "--coupler",
                "320 mm",
                "--swing",
                "70",
                "--lever",
                "360 mm",
                "--pivot-through",
                "0 m, 0.2 m",
            ],
            1.15,
            0.36,
        ),
    ];
    for (n, a, k, h) in cases {
        let v = synth_then_linkage(n, a, None);
        close("Kv", v["kv"].as_f64().unwrap(), k, 1e-9);
        close("stroke", v["stroke"].as_f64().unwrap(), h, 1e-9);
    }
    // seed 003: K given; the slider's stroke follows from the lever's swing:
    // C swings on a circle of 0.6 m by 55° symmetric about the vertical, and
    // D stays at a fixed horizontal distance from C at one height of C... so
    // the stroke is compared with the one the synthesis reports, and l_CD
    // with its closed form 0.4/sin 38°.
    let a = [
        "six-bar-pressure",
        "--k",
        "1.07",
        "--swing",
        "55",
        "--arm-b",
        "0.6 m",
        "--arm-c",
        "0.6 m",
        "--guide",
        "-0.2 m",
        "--max-pressure",
        "38",
        "--extreme-pressure",
        "38",
    ];
    let v = synth_then_linkage("pressure", &a, None);
    close("Kv", v["kv"].as_f64().unwrap(), 1.07, 1e-9);
    let mut j = vec!["synth"];
    j.extend_from_slice(&a);
    j.push("--json");
    let s = json(&j);
    close("stroke", v["stroke"].as_f64().unwrap(), s["stroke"].as_f64().unwrap(), 1e-9);
    close("l_CD", s["lengths"]["CD"].as_f64().unwrap(), 0.4 / deg(38.0).sin(), 1e-12);
}

#[test]
fn function_generator_passes_through_its_positions() {
    let pos = [(30.0, 60.0), (60.0, 75.0), (90.0, 95.0)];
    let mut a: Vec<String> = vec!["function-generation".into(), "--frame".into(), "300 mm".into()];
    for (p, q) in pos {
        a.push("--position".into());
        a.push(format!("{p} deg, {q} deg"));
    }
    let a: Vec<&str> = a.iter().map(String::as_str).collect();
    for (i, (p, q)) in pos.iter().enumerate() {
        let v = synth_then_linkage(&format!("fg{i}"), &a, Some(&p.to_string()));
        let row = &v["positions"][0];
        close("φ", row["phi"].as_f64().unwrap(), deg(*p), 1e-12);
        // the rocker C→B at ψ from the frame line O→C (along +x)
        let psi = row["links"]["3"]["angle"].as_f64().unwrap();
        let d = (psi - deg(*q)).rem_euclid(std::f64::consts::TAU);
        assert!(d.min(std::f64::consts::TAU - d) < 1e-9, "ψ at φ = {p}: {psi}");
    }
}

#[test]
fn two_positions_crank_slider_travels_between_them() {
    let a = [
        "crank-slider-positions",
        "--lambda",
        "4",
        "--lambda-e",
        "0.2",
        "--phi-start",
        "10",
        "--phi-end",
        "150",
        "--travel",
        "200 mm",
    ];
    let x = |at: &str, n: &str| {
        synth_then_linkage(n, &a, Some(at))["positions"][0]["points"]["B"]["x"]
            .as_f64()
            .unwrap()
    };
    // h_C = x_Cн − x_Cк (seed 000 § 1.2.2)
    close("travel", x("10", "tp0") - x("150", "tp1"), 0.2, 1e-9);
}

#[test]
fn json_has_the_contract_keys() {
    let v = json(&[
        "synth",
        "crank-slider",
        "--stroke",
        "300 mm",
        "--k",
        "1.2",
        "--lambda",
        "3.5",
        "--json",
    ]);
    for k in [
        "kind",
        "given",
        "lengths",
        "frame",
        "k",
        "theta",
        "stroke",
        "pressure_angle_max",
        "transmission_angle_min",
        "free_parameter",
        "task",
    ] {
        assert!(v.get(k).is_some(), "missing {k}");
    }
    assert_eq!(v["kind"], "crank-slider");
    assert!(v["pressure_angle_max"]["working"].is_number() && v["pressure_angle_max"]["return"].is_number());
    assert!(v["free_parameter"]["reason"].is_string());
    // θ = π (K − 1)/(K + 1) (seed 000 (1.3))
    close("θ", v["theta"].as_f64().unwrap(), std::f64::consts::PI * 0.2 / 2.2, 1e-15);
    // λ2 = l2/l1 as asked
    close(
        "λ2",
        v["lengths"]["AB"].as_f64().unwrap() / v["lengths"]["OA"].as_f64().unwrap(),
        3.5,
        1e-12,
    );
    assert!(v["task"].as_str().unwrap().starts_with("[linkage]"));
    let r = json(&[
        "synth",
        "crank-rocker",
        "--k",
        "1.28",
        "--swing",
        "60",
        "--rocker",
        "245 mm",
        "--optimum",
        "--json",
    ]);
    assert!(r.get("swing").is_some() && r.get("stroke").is_none());
}

#[test]
fn sweep_prints_a_table_and_an_array() {
    let base = ["synth", "crank-slider", "--stroke", "300 mm", "--k", "1.2", "--lambda", "3.5"];
    let mut a = base.to_vec();
    a.extend_from_slice(&["--sweep", "lambda=2..6:5"]);
    let (code, out, err) = run(&a);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("Variants: lambda over 5 values"), "{out}");
    let rows = out
        .lines()
        .filter(|l| l.trim_start().starts_with(|c: char| c.is_ascii_digit()))
        .count();
    assert_eq!(rows, 5, "{out}");
    a.push("--json");
    let v = json(&a);
    let arr = v.as_array().unwrap();
    assert_eq!(arr.len(), 5);
    for (i, r) in arr.iter().enumerate() {
        close("value", r["value"].as_f64().unwrap(), 2.0 + i as f64, 1e-12);
        close("K", r["k"].as_f64().unwrap(), 1.2, 1e-9);
        let l = &r["lengths"];
        close("λ2", l["AB"].as_f64().unwrap() / l["OA"].as_f64().unwrap(), 2.0 + i as f64, 1e-12);
    }
    // a crank length beyond the locus' limit h = l3·sin(ψ/2) cannot work
    let v = json(&[
        "synth",
        "crank-rocker",
        "--k",
        "1.28",
        "--swing",
        "60",
        "--rocker",
        "245 mm",
        "--optimum",
        "--sweep",
        "crank=80 mm..140 mm:4",
        "--json",
    ]);
    let arr = v.as_array().unwrap();
    assert_eq!(arr.len(), 4);
    assert_eq!(arr[3]["feasible"], false, "0.14 m > 0.245·sin 30° = 0.1225 m");
    assert_eq!(arr[0]["feasible"], true);
}

#[test]
fn bad_input_names_the_option_and_exits_2() {
    let cases: [(&[&str], &[&str]); 6] = [
        (
            &[
                "synth",
                "crank-slider",
                "--stroke",
                "300 mm",
                "--k",
                "1.2",
                "--lambda",
                "3.5",
                "--sweep",
                "bogus=1..2:3",
            ],
            &["--sweep", "stroke, k, lambda, offset, max_pressure"],
        ),
        (
            &[
                "synth",
                "crank-slider",
                "--stroke",
                "300 mm",
                "--k",
                "1.2",
                "--lambda",
                "3.5",
                "--sweep",
                "lambda=2..6",
            ],
            &["--sweep", ":N"],
        ),
        // seed example: H = 0.3 m, K = 1.2 cannot have ϑmax = 40°; the smallest is 42.80°
        (
            &["synth", "crank-slider", "--stroke", "300 mm", "--k", "1.2", "--max-pressure", "40"],
            &["--max-pressure", "42.799"],
        ),
        (
            &["synth", "crank-slider", "--stroke", "300 mm", "--k", "1.2"],
            &["--lambda", "--offset", "--max-pressure"],
        ),
        (
            &[
                "synth",
                "crank-rocker",
                "--k",
                "1.28",
                "--swing",
                "60",
                "--rocker",
                "245 mm",
                "--crank",
                "0.1",
                "--frame",
                "0.35",
            ],
            &["--frame", "only one"],
        ),
        (
            &[
                "synth",
                "crank-rocker",
                "--k",
                "1.28",
                "--swing",
                "60 kg",
                "--rocker",
                "245 mm",
                "--optimum",
            ],
            &["--swing"],
        ),
    ];
    for (a, words) in cases {
        let (code, _, err) = run(a);
        assert_eq!(code, 2, "{a:?}: {err}");
        for w in words {
            assert!(err.contains(w), "{a:?}: `{w}` not in\n{err}");
        }
    }
}

#[test]
fn a_task_file_error_is_located_at_the_field() {
    let d = tmp("located");
    let f = d.join("t.toml");
    std::fs::write(
        &f,
        "title = \"x\"\n[synthesis]\nkind = \"crank-slider\"\nstroke = \"300 mm\"\nk = 1.2\nmax_pressure = \"40 deg\"\n",
    )
    .unwrap();
    let (code, _, err) = run(&["run", f.to_str().unwrap(), "-o", d.join("out").to_str().unwrap()]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("t.toml:6:16: synthesis.max_pressure"), "{err}");
    assert!(err.contains("42.799"), "{err}");
}

#[test]
fn examples_run_and_reach_their_k() {
    let cases = [
        ("synth-seed-002-ex1-crank-rocker.toml", 1.28),
        ("synth-seed-002-ex2-knee-press.toml", 1.12),
        ("synth-seed-002-ex3-shaper.toml", 1.5),
        ("synth-seed-002-ex4-six-bar.toml", 1.15),
        ("synth-seed-003-six-bar.toml", 1.07),
    ];
    for (f, k) in cases {
        let d = tmp(f);
        let out = d.join("out");
        let (code, stdout, err) = run(&[
            "run",
            root().join("examples").join(f).to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "--json",
        ]);
        assert_eq!(code, 0, "{f}: {err}");
        let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
        close(f, v["linkage"]["kv"].as_f64().unwrap(), k, 1e-9);
        close(f, v["synthesis"]["k"].as_f64().unwrap(), k, 0.0);
        for p in ["synthesis/construction.svg", "synthesis/pressure.svg", "linkage/positions.svg"] {
            assert!(out.join(p).is_file(), "{f}: {p}");
        }
    }
}

#[test]
fn the_written_task_runs_with_forces_and_compares_the_given_linkage() {
    let d = tmp("forces");
    let t = d.join("t.toml");
    let (code, _, err) = run(&[
        "synth",
        "crank-rocker",
        "--k",
        "1.28",
        "--swing",
        "60",
        "--rocker",
        "245 mm",
        "--crank",
        "100 mm",
        "--task",
        t.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    let (code, _, err) = run(&["forces", t.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    let (code, out, err) = run(&["run", t.to_str().unwrap(), "-o", d.join("out").to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("The task's own [linkage] is analysed"), "{out}");
}
