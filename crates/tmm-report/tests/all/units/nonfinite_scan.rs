//! `output::find_nonfinite_in` on long outputs: the quick look for the
//! three words before the scan finds every marker and word where it stands
//! and passes a text without them.

use tmm_report::output::find_nonfinite_in;

#[test]
fn every_marker_and_word_is_found_where_it_stands() {
    let big = "0.125 ".repeat(10_000);
    for (text, at) in [
        (format!("{big}NaN"), Some(big.len())),
        (format!("{big}x inf"), Some(big.len() + 2)),
        (format!("{big}-Infinity"), Some(big.len() + 1)),
        (format!("{big}\u{1}NaN"), Some(big.len())),
        (format!("{big}\"\\u0001NaN\""), Some(big.len() + 1)),
        (format!("{big}info Info 1inf NaNs"), None),
        (big.clone(), None),
    ] {
        assert_eq!(find_nonfinite_in(&text, &[]), at, "{:?}", &text[big.len()..]);
    }
    // the user's own word is excused, a later one is not
    let t = format!("{big}name \"NaN-river\" NaN");
    let excused = ["NaN-river".to_string()];
    assert_eq!(find_nonfinite_in(&t, &excused), Some(big.len() + 17));
}
