//! Tests of `tmm_report::labels`, kept outside the library so that the
//! test command compiles it once.

use tmm_report::labels::*;

#[test]
fn placed_labels_never_overlap() {
    let mut p = Placer::new(100.0, 50.0);
    let mut n = 0;
    for i in 0..40 {
        let at = (10.0 + (i % 8) as f64 * 3.0, 10.0 + (i / 8) as f64 * 2.0);
        if p.place(&Placer::around(at, "d_a1", 3.5, 0.5), "d_a1", 3.5, "#000").is_some() {
            n += 1;
        }
    }
    assert!(n > 5);
    let b = p.boxes();
    for i in 0..b.len() {
        assert!(b[i].inside(&Rect {
            x0: 0.0,
            y0: 0.0,
            x1: 100.0,
            y1: 50.0
        }));
        for j in 0..i {
            assert!(!b[i].hits(&b[j], 0.0), "{i} {j}");
        }
    }
}

#[test]
fn finish_marks_the_scale_and_dash_dot() {
    let mut c = tmm_report::svg::Canvas::new(10.0, 10.0);
    c.line((0.0, 0.0), (5.0, 5.0), DASH_DOT);
    let s = finish(c.finish(), &Placer::new(10.0, 10.0), Some("1:2"));
    assert!(s.contains("data-scale=\"1:2\"") && s.contains("12 3 1 3"));
}
