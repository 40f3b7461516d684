//! Tests of `tmm_report::dynamics::json`, kept outside the library so that the
//! test command compiles it once.

use tmm_report::dynamics::json::stride;

#[test]
fn stride_keeps_at_least_360_intervals() {
    for n in [360, 372, 720, 1440, 3600, 36_000, 3612] {
        let s = stride(n);
        assert_eq!(n % s, 0);
        assert!(n / s >= 360, "{n}: {s}");
    }
    assert_eq!(stride(3600), 10);
    assert_eq!(stride(720), 1);
}
