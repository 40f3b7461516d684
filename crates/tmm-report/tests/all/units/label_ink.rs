//! `labels::ink_rect` (and the placer, which measures a label's text once
//! and adds each place tried): the rectangle at any place is the one
//! measured afresh there, to the bit.

use tmm_report::labels::{CAP_PER_EM, Rect, ink_rect, parts};

/// The ink rectangle measured afresh at `c`, every step written out.
fn afresh(c: (f64, f64), text: &str, h: f64, start: bool) -> Rect {
    let e = tmm_report::picture::em(h);
    let ie = tmm_report::picture::index_em(h);
    let k = |em: f64| em * CAP_PER_EM / 2.5;
    let parts = parts(text);
    let all: String = parts.iter().map(|p| p.0.as_str()).collect();
    let i = tmm_draw::face::ink(&all, tmm_draw::TextHeight::H2_5);
    let kk = k(e.max(ie));
    let (left, right) = (kk * i.left, kk * i.right.max(i.width));
    let (mut above, mut below) = (kk * i.above, kk * i.below);
    for (t, lvl) in &parts {
        let j = tmm_draw::face::ink(t, tmm_draw::TextHeight::H2_5);
        match lvl.signum() {
            1 => above = above.max(k(ie) * j.above + 0.35 * e),
            -1 => below = below.max(k(ie) * j.below + 0.35 * e),
            _ => {}
        }
    }
    let x = if start { c.0 } else { c.0 - 0.5 * kk * i.width };
    let base = c.1 + 0.35 * e;
    Rect {
        x0: x + left.min(0.0),
        y0: base - above,
        x1: x + right,
        y1: base + below,
    }
}

#[test]
fn a_label_s_ink_is_the_same_at_every_place_as_measured_there() {
    for text in ["φдс", "R^τ_{12} = 5 кН", "a_n^{CB}", "Ж", ""] {
        for h in [2.5, 3.5, 5.0] {
            for c in [(0.0, 0.0), (12.345, 67.891), (-3.1, 400.25), (1e3 / 7.0, 0.1)] {
                for start in [false, true] {
                    assert_eq!(ink_rect(c, text, h, start), afresh(c, text, h, start), "{text:?} {h} {c:?} {start}");
                }
            }
        }
    }
}
