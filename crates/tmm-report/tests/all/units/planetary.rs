//! Tests of `tmm_report::planetary`, kept outside the library so that the
//! test command compiles it once.

use tmm_report::TaskSource;
use tmm_report::planetary::run_section;

#[test]
fn section_absent_or_present() {
    let none = TaskSource::new("t.toml", "title = \"x\"\n");
    assert!(run_section(&none).unwrap().is_none());
    let t = TaskSource::new(
        "t.toml",
        "[planetary]\nscheme = \"sun-planet-ring\"\nratio = 6\nplanets = 3\nmodule = \"2 mm\"\n",
    );
    let o = run_section(&t).unwrap().unwrap();
    // u = 6: z3 = 5·z1 ≥ 85 → z1 = 17, z2 = 2·z1 = 34; 6·17/3 = 34 is whole
    assert_eq!(o.json["best"]["z"], serde_json::json!([17, 34, 85]));
    assert_eq!(o.json["units"], "SI");
    assert!((o.json["best"]["radial_size_m"].as_f64().unwrap() - 0.17).abs() < 1e-12);
    assert!(o.docs.get("planetary/planetary.svg").is_some());
    let bad = TaskSource::new("t.toml", "[planetary]\nscheme = \"sun\"\nratio = 6\nplanets = 3\n");
    let e = run_section(&bad).unwrap_err();
    assert_eq!(e.exit_code(), 2);
    assert!(e.to_string().starts_with("t.toml:2:10: planetary.scheme"), "{e}");
}
