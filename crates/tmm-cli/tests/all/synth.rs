//! `tmm synth` and `[synthesis]` from the outside: each kind's result is
//! analysed again by `tmm linkage` from the task file `--task` writes (K,
//! stroke or swing, the given positions — the linkage core's own cycle
//! analysis, not the synthesis), the JSON contract, the table of variants,
//! bad input answered with exit code 2 naming the option or the located
//! field, and the examples run through `tmm run`.

use std::path::PathBuf;

use crate::common::{self, run};

/// Requests of `tmm synth` used by several tests (seed 002's knee press and
/// shaper, seed 003's six-bars).
const KNEE: &[&str] = &[
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
];
const SHAPER: &[&str] = &[
    "slotted-lever",
    "--stroke",
    "400 mm",
    "--k",
    "1.5",
    "--pivots",
    "50 mm",
    "--coupler-ratio",
    "3",
];
const INVERSION: &[&str] = &[
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
];
const PRESSURE: &[&str] = &[
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
];

fn root() -> PathBuf {
    common::repo()
}

fn tmp(name: &str) -> PathBuf {
    common::tmp("synth", name)
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
            &[KNEE, &["--horizontal", "280 mm", "--direction", "cw"]].concat(),
            1.12,
            0.09,
        ),
        ("shaper", SHAPER, 1.5, 0.4),
        ("inversion", &[INVERSION, &["--pivot-through", "0 m, 0.2 m"]].concat(), 1.15, 0.36),
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
    let a = [PRESSURE, &["--extreme-pressure", "38"]].concat();
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
            &["--max-pressure", "42.7989", "(the rest unchanged): 42.8°"],
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
    let (code, _, err) = run(&["run", "--no-pdf", f.to_str().unwrap(), "-o", d.join("out").to_str().unwrap()]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("t.toml:6:16: synthesis.max_pressure"), "{err}");
    assert!(err.contains("42.7989") && err.contains("42.8°"), "{err}");
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
            "--no-pdf",
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
    let (code, out, err) = run(&["run", "--no-pdf", t.to_str().unwrap(), "-o", d.join("out").to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("The task's own [linkage] is analysed"), "{out}");
}

/// The number after `label` in a message (`… (the rest unchanged): 1.909`).
fn number_after(text: &str, label: &str) -> f64 {
    let at = text.find(label).unwrap_or_else(|| panic!("`{label}` not in\n{text}")) + label.len();
    let t: String = text[at..]
        .trim_start()
        .chars()
        .take_while(|c| c.is_ascii_digit() || *c == '.' || *c == '-')
        .collect();
    t.parse().unwrap_or_else(|_| panic!("no number after `{label}` in\n{text}"))
}

#[test]
fn a_sweep_needs_not_the_option_it_sweeps() {
    // λ2 swept with no --lambda (nor --offset, --max-pressure, --optimum)
    let v = json(&[
        "synth",
        "crank-slider",
        "--stroke",
        "300 mm",
        "--k",
        "1.2",
        "--sweep",
        "lambda=2..6:5",
        "--json",
    ]);
    let arr = v.as_array().unwrap();
    assert_eq!(arr.len(), 5);
    for (i, r) in arr.iter().enumerate() {
        assert_eq!(r["feasible"], true, "{r}");
        let l = &r["lengths"];
        close("λ2", l["AB"].as_f64().unwrap() / l["OA"].as_f64().unwrap(), 2.0 + i as f64, 1e-12);
        close("K", r["k"].as_f64().unwrap(), 1.2, 1e-9);
    }
    // the offset and the largest pressure angle likewise
    for sweep in ["offset=20 mm..60 mm:3", "max_pressure=45..60:4"] {
        let (code, out, err) = run(&["synth", "crank-slider", "--stroke", "300 mm", "--k", "1.2", "--sweep", sweep]);
        assert_eq!(code, 0, "{sweep}: {err}");
        assert!(out.contains("Variants:"), "{out}");
    }
    // a crank-rocker's crank, frame or frame angle, a knee press's pivot line
    for (kind, sweep) in [
        ("crank-rocker", "crank=80 mm..120 mm:3"),
        ("crank-rocker", "frame=300 mm..400 mm:3"),
        ("crank-rocker", "frame_angle=80..100:3"),
    ] {
        let v = json(&[
            "synth", kind, "--k", "1.28", "--swing", "60", "--rocker", "245 mm", "--sweep", sweep, "--json",
        ]);
        let arr = v.as_array().unwrap();
        assert!(arr.iter().all(|r| r["feasible"] == true), "{sweep}: {v}");
        if sweep.starts_with("crank") {
            for (r, want) in arr.iter().zip([0.08, 0.1, 0.12]) {
                close("l_OA", r["lengths"]["OA"].as_f64().unwrap(), want, 1e-12);
            }
        }
    }
    let v = json(&[
        "synth",
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
        "--sweep",
        "horizontal=260 mm..300 mm:3",
        "--json",
    ]);
    assert!(v.as_array().unwrap().iter().any(|r| r["feasible"] == true), "{v}");
    // in a task file: without the swept field `tmm run` analyses the first variant
    let d = tmp("sweep-task");
    let f = d.join("t.toml");
    std::fs::write(
        &f,
        "[synthesis]\nkind = \"crank-slider\"\nstroke = \"300 mm\"\nk = 1.2\nsweep = \"lambda=3..5:3\"\n",
    )
    .unwrap();
    let (code, out, err) = run(&[
        "run",
        "--no-pdf",
        f.to_str().unwrap(),
        "-o",
        d.join("out").to_str().unwrap(),
        "--json",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let l = &v["synthesis"]["lengths"];
    close(
        "λ2 of the first variant",
        l["AB"].as_f64().unwrap() / l["OA"].as_f64().unwrap(),
        3.0,
        1e-12,
    );
    assert_eq!(v["synthesis"]["variants"].as_array().unwrap().len(), 3);
}

#[test]
fn an_infeasible_k_names_a_nearest_value_that_works() {
    // K ≥ 3: beyond any crank-slider; with λ2 = 3.5 the largest K is that of
    // θ = 2·arctan(1/√3.5) (docs/synthesis.md § 3)
    let th = 2.0 * (1.0 / 3.5f64.sqrt()).atan();
    let kmax = (std::f64::consts::PI + th) / (std::f64::consts::PI - th);
    for k in ["3", "3.5", "1e300"] {
        let a = ["synth", "crank-slider", "--stroke", "300 mm", "--k", k, "--lambda", "3.5"];
        let (code, _, err) = run(&a);
        assert_eq!(code, 2, "{err}");
        assert!(err.contains("--k") && err.contains("K < 3"), "{err}");
        let n = number_after(&err, "nearest feasible value of --k (the rest unchanged):");
        assert!(n < kmax && n > kmax - 2e-3, "{n} vs {kmax}");
        let ns = n.to_string();
        let (code, _, err) = run(&["synth", "crank-slider", "--stroke", "300 mm", "--k", &ns, "--lambda", "3.5"]);
        assert_eq!(code, 0, "K = {ns}: {err}");
    }
    // a crank-rocker whose K is too large for its swing
    for (k, swing) in [("5", "20"), ("10", "30"), ("1e300", "30")] {
        let a = [
            "synth",
            "crank-rocker",
            "--k",
            k,
            "--swing",
            swing,
            "--rocker",
            "245 mm",
            "--optimum",
        ];
        let (code, _, err) = run(&a);
        assert_eq!(code, 2, "{err}");
        assert!(err.contains("--k"), "{err}");
        let n = number_after(&err, "nearest feasible value of --k (the rest unchanged):");
        assert!(n > 1.0 && n < k.parse::<f64>().unwrap(), "{n}");
        assert!(n.to_string().len() <= 6, "not rounded: {n}");
        let ns = n.to_string();
        let (code, _, err) = run(&[
            "synth",
            "crank-rocker",
            "--k",
            &ns,
            "--swing",
            swing,
            "--rocker",
            "245 mm",
            "--optimum",
        ]);
        assert_eq!(code, 0, "K = {ns}: {err}");
    }
}

/// Extreme values of every option of every kind: exit 0 or 2, never a
/// panic, never a number that is not finite in the output.
#[test]
fn extreme_values_give_exit_2_or_finite_results() {
    let bases: [Vec<&str>; 6] = [
        vec!["crank-slider", "--stroke", "300 mm", "--k", "1.2", "--lambda", "3.5"],
        vec![
            "crank-rocker",
            "--k",
            "1.28",
            "--swing",
            "60",
            "--rocker",
            "245 mm",
            "--crank",
            "100 mm",
        ],
        SHAPER.to_vec(),
        [KNEE, &["--horizontal", "280 mm"]].concat(),
        [PRESSURE, &["--extreme-pressure", "38"]].concat(),
        vec![
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
        ],
    ];
    let values = ["0", "-1", "1e300", "1e-300", "1", "3", "180", "360", "NaN", "inf"];
    let mut runs = 0;
    for base in &bases {
        // each value option of the base in turn
        for i in (1..base.len()).step_by(2) {
            for v in values {
                let mut a: Vec<&str> = vec!["synth"];
                a.extend_from_slice(base);
                a[i + 2] = v;
                a.push("--json");
                let (code, out, err) = run(&a);
                runs += 1;
                assert!(code == 0 || code == 2, "{a:?}: exit {code}\n{err}");
                assert!(!err.contains("panicked"), "{a:?}: {err}");
                if code == 0 {
                    let j: serde_json::Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{a:?}: {e}"));
                    for k in ["k", "theta", "transmission_angle_min"] {
                        assert!(j[k].as_f64().is_some_and(f64::is_finite), "{a:?}: {k} = {}", j[k]);
                    }
                    for (n, l) in j["lengths"].as_object().unwrap() {
                        assert!(l.as_f64().is_some_and(f64::is_finite), "{a:?}: {n} = {l}");
                    }
                } else {
                    assert!(!err.contains("NaN") || v == "NaN", "{a:?}: {err}");
                }
            }
        }
    }
    // a swing of 180° and more, K = 1 and K ≥ 3 of a crank-rocker
    for (k, swing) in [("1", "60"), ("3", "60"), ("1.28", "180"), ("1.28", "179.9"), ("1", "180")] {
        let (code, _, err) = run(&[
            "synth",
            "crank-rocker",
            "--k",
            k,
            "--swing",
            swing,
            "--rocker",
            "245 mm",
            "--optimum",
        ]);
        assert!(code == 0 || code == 2, "K {k} ψ {swing}: {err}");
        assert!(!err.contains("panicked") && !err.contains("NaN"), "{err}");
    }
    assert!(runs > 250, "{runs}");
}

#[test]
fn every_kind_written_with_task_runs_through_linkage_forces_and_run() {
    let cases: [(&str, &[&str]); 8] = [
        ("t-cs", &["crank-slider", "--stroke", "300 mm", "--k", "1.2", "--offset", "40 mm"]),
        (
            "t-csp",
            &[
                "crank-slider-positions",
                "--lambda",
                "4",
                "--phi-start",
                "10",
                "--phi-end",
                "150",
                "--travel",
                "200 mm",
            ],
        ),
        (
            "t-cr",
            &[
                "crank-rocker",
                "--k",
                "1.28",
                "--swing",
                "60",
                "--rocker",
                "245 mm",
                "--frame",
                "350 mm",
            ],
        ),
        (
            "t-fg",
            &[
                "function-generation",
                "--frame",
                "300 mm",
                "--position",
                "30, 60",
                "--position",
                "60, 75",
                "--position",
                "90, 95",
            ],
        ),
        ("t-sl", &[SHAPER, &["--lever", "oscillating"]].concat()),
        ("t-kp", &[KNEE, &["--optimum"]].concat()),
        ("t-inv", INVERSION),
        ("t-pr", &[PRESSURE, &["--optimum"]].concat()),
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
        for p in ["synthesis/construction.svg", "synthesis/pressure.svg"] {
            assert!(d.join("svg").join(p).is_file(), "{n}: {p}");
        }
        for cmd in [
            vec!["linkage", ts],
            vec!["forces", ts],
            vec!["run", "--no-pdf", ts, "-o", d.join("out").to_str().unwrap()],
        ] {
            let (code, _, err) = run(&cmd);
            assert_eq!(code, 0, "{n}: tmm {}: {err}", cmd[0]);
        }
    }
}
