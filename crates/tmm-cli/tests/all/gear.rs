//! `tmm gear pair`, `tmm gear contour` and the `[gear]` section end to end:
//! exit codes, exactly one JSON document, files written, errors naming the
//! option or the field with its place in the file.

use std::f64::consts::PI;
use std::path::{Path, PathBuf};
use std::process::Output;

use crate::common::{self, json};

fn tmm(args: &[&str]) -> Output {
    common::tmm_in(Path::new(env!("CARGO_MANIFEST_DIR")), args)
}

fn tmp(name: &str) -> PathBuf {
    common::tmp("gear", name)
}

fn f(v: &serde_json::Value, k: &str) -> f64 {
    v[k].as_f64().unwrap_or_else(|| panic!("{k} is not a number: {}", v[k]))
}

fn bad(o: &Output, needle: &str) {
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "stderr: {err}");
    assert!(err.contains(needle), "the message should name {needle}: {err}");
    assert!(!err.contains("panicked"), "{err}");
}

const SEED_001: &[&str] = &[
    "gear", "pair", "--z1", "15", "--z2", "20", "--module", "5 mm", "--x1", "0.2", "--x2", "0.85",
];

#[test]
fn seed_001_pair_json() {
    let mut a = SEED_001.to_vec();
    a.push("--json");
    let v = json(&tmm(&a));
    assert_eq!(v["units"], "SI");
    for k in [
        "a",
        "aw",
        "alpha_w",
        "y",
        "dy",
        "d1",
        "d2",
        "db1",
        "db2",
        "dw1",
        "dw2",
        "da1",
        "da2",
        "df1",
        "df2",
        "s1",
        "s2",
        "sa1",
        "sa2",
        "eps_alpha",
        "xmin1",
        "xmin2",
        "rho_p1",
        "rho_p2",
        "rho_l1",
        "rho_l2",
        "theta1_max",
        "theta2_max",
    ] {
        assert!(v[k].is_number(), "{k} missing: {}", v[k]);
    }
    // a = m (z1 + z2) / 2 = 87.5 mm, SI
    assert!((f(&v, "a") - 0.0875).abs() < 1e-15);
    // aw = a cos α / cos αw
    assert!((f(&v, "aw") - 0.0875 * (20f64.to_radians()).cos() / f(&v, "alpha_w").cos()).abs() < 1e-12);
    // identity aw = ra1 + rf2 + c* m
    assert!((f(&v, "aw") - (f(&v, "da1") / 2.0 + f(&v, "df2") / 2.0 + 0.25 * 0.005)).abs() < 1e-12);
    // εα by the length of action
    let rb = |d: f64| d / 2.0;
    let ga = ((f(&v, "da1") / 2.0).powi(2) - rb(f(&v, "db1")).powi(2)).sqrt()
        + ((f(&v, "da2") / 2.0).powi(2) - rb(f(&v, "db2")).powi(2)).sqrt()
        - f(&v, "aw") * f(&v, "alpha_w").sin();
    assert!((f(&v, "eps_alpha") - ga / (PI * 0.005 * 20f64.to_radians().cos())).abs() < 1e-12);
    let checks = v["checks"].as_object().unwrap();
    assert!(checks.len() >= 7);
    for (k, c) in checks {
        assert!(c["value"].is_number() && c["limit"].is_number(), "{k}");
        assert_eq!(c["pass"], true, "{k}");
    }
}

#[test]
fn pair_tables_and_files() {
    let d = tmp("files");
    let (svg, dxf, csv) = (d.join("mesh.svg"), d.join("mesh.dxf"), d.join("p.csv"));
    let mut a = SEED_001.to_vec();
    let (s1, s2, s3) = (
        svg.to_str().unwrap().to_string(),
        dxf.to_str().unwrap().to_string(),
        csv.to_str().unwrap().to_string(),
    );
    a.extend(["--svg", &s1, "--dxf", &s2, "--profiles", &s3]);
    let o = tmm(&a);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(out.contains("Quality checks") && out.contains("εα"));
    let s = std::fs::read_to_string(&svg).unwrap();
    assert!(s.starts_with("<?xml") && s.contains("line-of-action"));
    let x = std::fs::read_to_string(&dxf).unwrap();
    for layer in [
        "WHEEL1",
        "WHEEL2",
        "LINE_OF_ACTION",
        "ACTIVE_LINE",
        "WORKING_PROFILES",
        "ARCS_OF_ACTION",
        "CIRCLE_BASE",
        "SLIDING",
    ] {
        assert!(x.contains(layer), "DXF layer {layer}");
    }
    let c = std::fs::read_to_string(&csv).unwrap();
    assert!(c.lines().next().unwrap().starts_with("wheel,part,x_mm"));
    assert!(c.contains(",involute,") && c.contains(",fillet,"));
    assert!(!c.contains("NaN") && !c.contains("inf"));
}

#[test]
fn centre_distance_given_seed_003() {
    let v = json(&tmm(&[
        "gear",
        "pair",
        "--z1",
        "16",
        "--z2",
        "20",
        "--module",
        "30 mm",
        "--aw",
        "560 mm",
        "--criterion",
        "balanced",
        "--json",
    ]));
    assert!((f(&v, "aw") - 0.560).abs() < 1e-12);
    assert_eq!(v["shifts"]["criterion"], "balanced");
    // the shift sum that gives 560 mm: (inv αw − inv α)(z1 + z2)/(2 tg α)
    let inv = |a: f64| a.tan() - a;
    let al = 20f64.to_radians();
    let aw_a = (540.0 * al.cos() / 560.0f64).acos();
    let xs = (inv(aw_a) - inv(al)) * 36.0 / (2.0 * al.tan());
    assert!((f(&v, "x1") + f(&v, "x2") - xs).abs() < 1e-9);
}

#[test]
fn chosen_without_criterion_says_why() {
    let v = json(&tmm(&["gear", "pair", "--z1", "16", "--z2", "20", "--module", "30 mm", "--json"]));
    assert_eq!(v["shifts"]["criterion"], "equal-sliding");
    assert!(v["shifts"]["reason"].as_str().unwrap().contains("no criterion given"));
    assert!((f(&v, "theta1_max") - f(&v, "theta2_max")).abs() < 1e-6);
}

#[test]
fn contour_json_and_svg() {
    let d = tmp("contour");
    let p = d.join("c.svg");
    let v = json(&tmm(&[
        "gear",
        "contour",
        "--z1",
        "16",
        "--z2",
        "20",
        "--svg",
        p.to_str().unwrap(),
        "--json",
    ]));
    assert_eq!(v["units"], "SI");
    let lines = v["lines"].as_array().unwrap();
    for key in [
        "undercut1",
        "interference1",
        "sa1=0m",
        "eps_alpha=1",
        "eps_alpha=1.2",
        "equal_sliding",
    ] {
        assert!(
            lines
                .iter()
                .any(|l| l["boundary"] == key && !l["polylines"].as_array().unwrap().is_empty()),
            "{key}"
        );
    }
    assert!(v["chosen"]["x1"].is_number());
    // the loose drawings speak the default language of the project (Russian)
    assert!(std::fs::read_to_string(&p).unwrap().contains("Блокирующий контур"));
}

#[test]
fn internal_pair() {
    let v = json(&tmm(&[
        "gear",
        "pair",
        "--z1",
        "20",
        "--z2",
        "60",
        "--module",
        "2 mm",
        "--x1",
        "0.5",
        "--x2",
        "0.8",
        "--internal",
        "--json",
    ]));
    assert_eq!(v["kind"], "internal");
    assert!(v["xmin2"].is_null());
    // a = m (z2 − z1)/2 = 40 mm before the shifts; aw > a for x2 > x1
    assert!((f(&v, "a") - 0.040).abs() < 1e-15 && f(&v, "aw") > 0.040);
    assert!(v["checks"]["tip_interference"]["pass"].as_bool().unwrap());
}

#[test]
fn bad_inputs_exit_2_and_name_the_option() {
    let base = |extra: &[&'static str]| {
        let mut a: Vec<&str> = vec!["gear", "pair", "--module", "5 mm"];
        a.extend_from_slice(extra);
        tmm(&a)
    };
    // z below the smallest that can be cut
    bad(&base(&["--z1", "6", "--z2", "20", "--x1", "0", "--x2", "0"]), "--z1");
    bad(&base(&["--z1", "0", "--z2", "20"]), "--z1");
    // m ≤ 0
    bad(
        &tmm(&[
            "gear", "pair", "--z1", "15", "--z2", "20", "--module", "0 mm", "--x1", "0", "--x2", "0",
        ]),
        "--module",
    );
    bad(
        &tmm(&[
            "gear", "pair", "--z1", "15", "--z2", "20", "--module", "-5 mm", "--x1", "0", "--x2", "0",
        ]),
        "--module",
    );
    bad(
        &tmm(&[
            "gear", "pair", "--z1", "15", "--z2", "20", "--module", "5 kg", "--x1", "0", "--x2", "0",
        ]),
        "--module",
    );
    // shifts giving da ≤ df: a large shift sum shortens the tips below the roots
    let o = tmm(&[
        "gear", "pair", "--z1", "20", "--z2", "20", "--module", "1 mm", "--x1", "5", "--x2", "5",
    ]);
    bad(&o, "--x1");
    assert!(String::from_utf8_lossy(&o.stderr).contains("not above the root diameter"));
    // a tip inside the base circle
    bad(&base(&["--z1", "15", "--z2", "20", "--x1", "-1.5", "--x2", "6"]), "--x1");
    // an aw no shift sum can reach (below a·cos α)
    bad(&base(&["--z1", "15", "--z2", "20", "--aw", "80 mm"]), "--aw");
    // internal pairs that cannot assemble
    bad(&base(&["--z1", "30", "--z2", "36", "--x1", "0", "--x2", "0", "--internal"]), "--z2");
    bad(&base(&["--z1", "30", "--z2", "20", "--x1", "0", "--x2", "0", "--internal"]), "--z2");
    // unknown criterion, one shift only
    bad(&base(&["--z1", "15", "--z2", "20", "--criterion", "best"]), "--criterion");
    bad(&base(&["--z1", "15", "--z2", "20", "--x1", "0.3"]), "--x2");
}

#[test]
fn task_file_errors_name_the_field_and_place() {
    let d = tmp("task");
    let p = d.join("t.toml");
    std::fs::write(&p, "[gear]\nz1 = 15\nz2 = 20\nmodule = \"-5 mm\"\nx1 = 0.2\nx2 = 0.85\n").unwrap();
    let o = tmm(&["run", "--no-pdf", p.to_str().unwrap(), "-o", d.join("out").to_str().unwrap()]);
    bad(&o, "gear.module");
    assert!(
        String::from_utf8_lossy(&o.stderr).contains("t.toml:4:"),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    std::fs::write(&p, "[gear]\nz1 = 15\nz2 = 20\nmodule = \"5 mm\"\nteeth = 3\n").unwrap();
    bad(
        &tmm(&["run", "--no-pdf", p.to_str().unwrap(), "-o", d.join("out").to_str().unwrap()]),
        "teeth",
    );
    std::fs::write(&p, "[gear]\nz1 = 15\nz2 = 20\nmodule = \"5 mm\"\naw = \"70 mm\"\n").unwrap();
    bad(
        &tmm(&["run", "--no-pdf", p.to_str().unwrap(), "-o", d.join("out").to_str().unwrap()]),
        "gear.aw",
    );
}

#[test]
fn run_example_writes_the_gear_files() {
    let d = tmp("run");
    let ex = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/gear-seed001.toml");
    let v = json(&tmm(&["run", "--no-pdf", ex, "-o", d.to_str().unwrap(), "--json"]));
    assert!((f(&v["gear"], "eps_alpha") - 1.2048).abs() < 1e-3);
    for name in ["mesh.svg", "mesh.dxf", "contour.svg", "sliding.svg", "profiles.csv"] {
        assert!(d.join("gear").join(name).exists(), "{name}");
    }
}
