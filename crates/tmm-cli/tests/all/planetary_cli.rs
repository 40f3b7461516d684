//! `tmm planetary` and the `[planetary]` section through the binary: exit
//! codes, one JSON document, files written, errors that name the field.

use std::path::PathBuf;
use std::process::{Command, Output};

fn tmm(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tmm")).args(args).output().expect("run tmm")
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn temp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("tmm-planetary-cli-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d.join(name)
}

fn repo(path: &str) -> String {
    format!("{}/../../{path}", env!("CARGO_MANIFEST_DIR"))
}

/// No null (a NaN that serde_json turned into null) anywhere in the document.
fn no_nulls(v: &serde_json::Value) -> bool {
    match v {
        serde_json::Value::Null => false,
        serde_json::Value::Array(a) => a.iter().all(no_nulls),
        serde_json::Value::Object(m) => m.values().all(no_nulls),
        _ => true,
    }
}

#[test]
fn best_set_in_the_table() {
    let o = tmm(&["planetary", "--scheme", "sun-planet-ring", "--ratio", "4", "--planets", "3"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let s = stdout(&o);
    // u = 4 → z3 = 3·z1, z2 = z1, ring ≥ 85 and 4·z1/3 whole → z1 = 30
    assert!(s.contains("Best: z1 = 30, z2 = 30, z3 = 90"), "{s}");
    assert!(s.contains("read off the picture"));
}

#[test]
fn json_is_one_document() {
    let o = tmm(&["planetary", "--scheme", "ext-int", "--ratio", "9", "--planets", "3", "--json"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).expect("one JSON document");
    assert_eq!(v["units"], "SI");
    assert_eq!(v["scheme"], "ext-int");
    assert_eq!(v["z_order"], serde_json::json!(["z1", "z2", "z2'", "z3"]));
    let z: Vec<u64> = v["best"]["z"].as_array().unwrap().iter().map(|x| x.as_u64().unwrap()).collect();
    assert_eq!(z.len(), 4);
    // Willis from the printed teeth: 1 + z2·z3/(z1·z2′) = 9
    assert_eq!(z[0] * z[2] * 8, z[1] * z[3]);
    assert_eq!(v["best"]["ratio"].as_f64().unwrap(), 9.0);
    assert!((v["best"]["ratio_from_picture"].as_f64().unwrap() - 9.0).abs() < 1e-9);
    assert!(!v["candidates"].as_array().unwrap().is_empty());
    assert!(v["best"]["radial_size"].as_f64().unwrap() > 0.0);
    assert!(no_nulls(&v));
}

#[test]
fn svg_sheet_written() {
    let path = temp("sheet.svg");
    let o = tmm(&[
        "planetary",
        "--scheme",
        "ext-ext",
        "--ratio",
        "1/30",
        "--planets",
        "3",
        "--svg",
        path.to_str().unwrap(),
        "--json",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let _: serde_json::Value = serde_json::from_str(&stdout(&o)).expect("still one JSON document with --svg");
    let svg = std::fs::read_to_string(&path).unwrap();
    assert!(svg.contains("<svg") && svg.contains("velocity-picture") && svg.contains("angular-diagram"));
    assert!(!svg.contains("NaN") && !svg.contains("inf"));
}

#[test]
fn impossible_ratio_names_the_condition() {
    let o = tmm(&["planetary", "--scheme", "sun-planet-ring", "--ratio", "1.01", "--planets", "3"]);
    assert_eq!(o.status.code(), Some(2));
    let e = stderr(&o);
    assert!(e.contains("--ratio") && e.contains("ratio and coaxiality"), "{e}");
    assert!(stdout(&o).is_empty());
}

#[test]
fn ten_planets_fail_the_neighbour_condition() {
    let o = tmm(&["planetary", "--scheme", "sun-planet-ring", "--ratio", "4", "--planets", "10"]);
    assert_eq!(o.status.code(), Some(2));
    let e = stderr(&o);
    assert!(e.contains("--planets") && e.contains("neighbour"), "{e}");
}

#[test]
fn bad_options() {
    for (args, name) in [
        (vec!["planetary", "--scheme", "star", "--ratio", "4", "--planets", "3"], "--scheme"),
        (
            vec!["planetary", "--scheme", "ext-int", "--ratio", "4 mm", "--planets", "3"],
            "--ratio",
        ),
        (vec!["planetary", "--scheme", "ext-int", "--planets", "3"], "--ratio"),
        (
            vec!["planetary", "--scheme", "ext-int", "--ratio", "4", "--planets", "0"],
            "--planets",
        ),
        (
            vec![
                "planetary",
                "--scheme",
                "ext-int",
                "--ratio",
                "4",
                "--planets",
                "3",
                "--tolerance",
                "0.9",
            ],
            "--tolerance",
        ),
        (
            vec![
                "planetary",
                "--scheme",
                "ext-int",
                "--ratio",
                "4",
                "--planets",
                "3",
                "--module",
                "-2 mm",
            ],
            "--module",
        ),
    ] {
        let o = tmm(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(stderr(&o).contains(name), "{args:?}: {}", stderr(&o));
    }
}

#[test]
fn task_file_errors_are_located() {
    let path = temp("bad.toml");
    std::fs::write(&path, "[planetary]\nscheme = \"sun-planet-ring\"\nratio = 4\nplanets = 10\n").unwrap();
    let o = tmm(&["planetary", path.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    let e = stderr(&o);
    assert!(e.contains("bad.toml:4:11: planetary.planets") && e.contains("neighbour"), "{e}");

    std::fs::write(&path, "[planetary]\nscheme = \"sun-planet-ring\"\nratio = \"4 kg\"\nplanets = 3\n").unwrap();
    let e = stderr(&tmm(&["planetary", path.to_str().unwrap()]));
    assert!(e.contains("bad.toml:3:9: planetary.ratio"), "{e}");

    std::fs::write(
        &path,
        "[planetary]\nscheme = \"sun-planet-ring\"\nratio = 4\nplanets = 3\nplanet = 3\n",
    )
    .unwrap();
    let o = tmm(&["planetary", path.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("planet"), "{}", stderr(&o));

    // an option overrides the file and is named as the option
    std::fs::write(&path, "[planetary]\nscheme = \"sun-planet-ring\"\nratio = 4\nplanets = 3\n").unwrap();
    let o = tmm(&["planetary", path.to_str().unwrap(), "--planets", "10"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--planets"), "{}", stderr(&o));
}

#[test]
fn examples_and_run() {
    for f in [
        "planetary-sun-planet-ring",
        "planetary-ext-int",
        "planetary-ext-ext",
        "planetary-int-int",
    ] {
        let o = tmm(&["planetary", &repo(&format!("examples/{f}.toml")), "--json"]);
        assert_eq!(o.status.code(), Some(0), "{f}: {}", stderr(&o));
        let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
        assert!(no_nulls(&v), "{f}");
    }
    let out = temp("run-out");
    let task = temp("run.toml");
    std::fs::copy(repo("examples/planetary-int-int.toml"), &task).unwrap();
    let o = tmm(&["run", "--no-pdf", task.to_str().unwrap(), "--out", out.to_str().unwrap(), "--json"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["planetary"]["equal_spacing"], false);
    assert_eq!(v["planetary"]["best"]["z"], serde_json::json!([100, 30, 28, 98]));
    assert!(out.join("planetary/planetary.svg").exists());
}
