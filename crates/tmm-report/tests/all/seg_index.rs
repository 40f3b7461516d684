//! The labels' segment index counts exactly what a scan over every segment
//! counts, on random segments and boxes (some off the paper, some longer than
//! the paper, some of zero length).

use tmm_report::labels::Rect;
use tmm_report::seg_index::SegIndex;
use tmm_report::svg::Rect as SvgRect;

/// `v` moved to the nearest multiple of the index's cell (8 mm) when `on`.
fn snap(v: f64, on: bool) -> f64 {
    if on { (v / 8.0).round() * 8.0 } else { v }
}

#[test]
fn count_equals_the_full_scan() {
    let mut z = 0x2545_f491_4f6c_dd1du64;
    let mut u = move || {
        z ^= z << 13;
        z ^= z >> 7;
        z ^= z << 17;
        (z >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut cut_some = 0;
    for _ in 0..50 {
        let mut ix = SegIndex::new(200.0, 150.0);
        for _ in 0..300 {
            // some ends on the cells' edges (multiples of 8 mm)
            let (x, y, on) = (u() * 260.0 - 30.0, u() * 200.0 - 25.0, u() < 0.2);
            let a = (snap(x, on), snap(y, on));
            let len = if u() < 0.1 { 500.0 } else { 20.0 };
            let b = if u() < 0.05 {
                a
            } else {
                (a.0 + (u() - 0.5) * len, a.1 + (u() - 0.5) * len)
            };
            ix.push((a, b));
        }
        ix.push(((f64::NAN, 0.0), (10.0, 10.0)));
        for _ in 0..300 {
            let (x, y, on) = (u() * 240.0 - 20.0, u() * 180.0 - 15.0, u() < 0.2);
            let (x, y) = (snap(x, on), snap(y, on));
            let r = Rect {
                x0: x,
                y0: y,
                x1: x + u() * 30.0,
                y1: y + u() * 10.0,
            };
            let all = ix.segments().iter().filter(|s| r.cuts(s.0, s.1)).count();
            assert_eq!(ix.count((r.x0, r.y0, r.x1, r.y1), |s| r.cuts(s.0, s.1)), all, "{r:?}");
            // the drawings' own box, which counts a touch as a cut
            let t = SvgRect {
                x0: r.x0,
                y0: r.y0,
                x1: r.x1,
                y1: r.y1,
            };
            let touching = ix.segments().iter().filter(|s| t.cuts(s.0, s.1)).count();
            assert_eq!(ix.count((t.x0, t.y0, t.x1, t.y1), |s| t.cuts(s.0, s.1)), touching, "{t:?}");
            cut_some += usize::from(all > 1);
        }
    }
    // the boxes do meet segments, several at a time
    assert!(cut_some > 1000, "{cut_some}");
}
