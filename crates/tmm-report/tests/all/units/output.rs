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

/// The first non-finite word, found the plain way: each word searched for
/// with `str::find`, an occurrence accepted when no word character stands
/// beside it, the earliest of the three.
fn first_word_by_search(text: &str) -> Option<usize> {
    let b = text.as_bytes();
    let is_word = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    ["NaN", "inf", "Infinity"]
        .iter()
        .filter_map(|w| {
            text.match_indices(w).map(|(s, _)| s).find(|&s| {
                let e = s + w.len();
                (s == 0 || !is_word(b[s - 1])) && (e >= b.len() || !is_word(b[e]))
            })
        })
        .min()
}

#[test]
fn the_one_pass_scan_finds_what_a_search_per_word_finds() {
    // every string over a small alphabet that makes the words, their
    // neighbours, the markers and multi-byte letters, up to three pieces
    let parts = [
        "N", "a", "i", "n", "f", "I", "_", " ", "NaN", "inf", "Infinity", "\u{1}", "\\u0001", "я", "-",
    ];
    let mut texts = vec![String::new()];
    for _ in 0..3 {
        let mut next = Vec::new();
        for t in &texts {
            for p in parts {
                next.push(format!("{t}{p}"));
            }
        }
        texts.extend(next);
    }
    for t in &texts {
        assert_eq!(find_nonfinite_word(t), first_word_by_search(t), "{t:?}");
        let marker = [NONFINITE, "\\u0001NaN"].iter().filter_map(|m| t.find(m)).min();
        let expected = match (marker, first_word_by_search(t)) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        };
        assert_eq!(find_nonfinite(t), expected, "{t:?}");
    }
}
