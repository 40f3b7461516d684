//! Tests of `tmm_report::sheets::layout`, kept outside the library so that the
//! test command compiles it once.

use tmm_report::sheets::layout::*;

/// Brute force: many boxes of pseudo-random sizes into a field with an
/// obstacle; every placed box lies in the field, off the obstacle and
/// off every other box, checked pair by pair.
#[test]
fn placed_boxes_never_overlap() {
    let mut seed: u64 = 12345;
    let mut rnd = move || {
        seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    for round in 0..50 {
        let field = Rect {
            x: 25.0,
            y: 10.0,
            w: 800.0,
            h: 570.0,
        };
        let tb = Rect {
            x: 640.0,
            y: 525.0,
            w: 185.0,
            h: 55.0,
        };
        let mut p = Packer::new(field);
        p.occupy(tb);
        let mut placed: Vec<Rect> = Vec::new();
        for _ in 0..30 {
            let (w, h) = (20.0 + 300.0 * rnd(), 20.0 + 250.0 * rnd());
            if let Some(r) = p.place_by(w, h, round % 2 == 1) {
                assert_eq!((r.w, r.h), (w, h));
                assert!(field.contains(&r) && !r.intersects(&tb), "{r:?}");
                assert!(placed.iter().all(|q| !q.intersects(&r)), "{r:?} overlaps");
                placed.push(r);
            }
        }
        assert!(placed.len() >= 5, "round {round}: only {} placed", placed.len());
    }
}
