//! Tests of `tmm_report::output`, kept outside the library so that the
//! test command compiles it once.

use tmm_report::output::*;

#[test]
fn words_that_contain_inf_pass() {
    for ok in ["info", "infeasible", "inflection", "x_inf2", "NaNo", "", "1.0e-300"] {
        assert!(find_nonfinite(ok).is_none(), "{ok}");
    }
    for bad in ["NaN", "x=NaN", "-inf", "\"inf\"", "a inf b", "Infinity"] {
        assert!(find_nonfinite(bad).is_some(), "{bad}");
    }
}

#[test]
fn json_marks_nonfinite() {
    let mut d = Documents::new();
    assert!(d.add_json("a.json", &serde_json::json!({"x": num(f64::NAN)})).is_err());
    assert!(d.add_json("a.json", &serde_json::json!({"x": num(1.5)})).is_ok());
    assert_eq!(d.len(), 1);
}
