//! GOST 2.304 lettering: the height series, index sizes, rich text, wrapping.

use tmm_draw::{Rich, TextHeight, wrap};

#[test]
fn no_height_under_two_and_a_half_mm_can_be_made() {
    for h in [0.0, 1.0, 1.8, 2.0, 2.49, 3.0, 4.0, 6.0, f64::NAN] {
        assert!(TextHeight::new(h).is_err(), "{h}");
    }
    for h in [0.0, 1.8, 2.49, f64::NAN] {
        assert!(TextHeight::at_most(h).is_err(), "{h}");
    }
    // every constructible height, indices included, is ≥ 2.5
    for h in TextHeight::series() {
        assert!(h.mm() >= 2.5 && h.index().mm() >= 2.5);
        assert!(h.index().mm() <= h.mm());
    }
    let msg = TextHeight::new(1.8).unwrap_err().to_string();
    assert!(msg.contains("2.5") && msg.contains("GOST 2.304"), "{msg}");
}

#[test]
fn at_most_picks_the_largest_size_that_fits() {
    assert_eq!(TextHeight::at_most(3.49).unwrap().mm(), 2.5);
    assert_eq!(TextHeight::at_most(3.5).unwrap().mm(), 3.5);
    assert_eq!(TextHeight::at_most(100.0).unwrap().mm(), 20.0);
}

#[test]
fn indices_are_structured_not_flattened() {
    let r = Rich::parse("M_{ур}").unwrap();
    assert_eq!(r.spans.len(), 1);
    assert_eq!((r.spans[0].base.as_str(), r.spans[0].sub.as_deref()), ("M", Some("ур")));
    let r = Rich::parse("aK_v").unwrap();
    assert_eq!(r.spans[0].base, "a");
    assert_eq!((r.spans[1].base.as_str(), r.spans[1].sub.as_deref()), ("K", Some("v")));
    let r = Rich::parse("R_{12}^τ").unwrap();
    assert_eq!(r.spans.len(), 1);
    assert_eq!((r.spans[0].sub.as_deref(), r.spans[0].sup.as_deref()), (Some("12"), Some("τ")));
    assert_eq!(Rich::parse(r"a\_b").unwrap().plain(), "a_b");
    assert!(Rich::parse("x_{12").is_err());
}

#[test]
fn type_b_widths_follow_the_standard() {
    // GOST 2.304 type B: capital 6/10 h wide plus a 2/10 h gap
    let h = TextHeight::H5;
    assert!((Rich::plain_text("НН").width(h) - 2.0 * 0.8 * 5.0).abs() < 1e-12);
    // an index is measured at the index height
    let w = Rich::parse("K_v").unwrap().width(h);
    assert!((w - (0.8 * 5.0 + 0.7 * 3.5)).abs() < 1e-12);
}

#[test]
fn wrapping_keeps_every_line_within_the_width() {
    let text = "Национальный технический университет «Харьковский политехнический институт»";
    for width in [40.0, 60.0, 110.0] {
        let lines = wrap(text, TextHeight::H3_5, width).unwrap();
        for l in &lines {
            assert!(Rich::plain_text(l).width(TextHeight::H3_5) <= width + 1e-9, "{l}");
        }
        assert_eq!(lines.join(" ").replace(' ', ""), text.replace(' ', ""));
    }
    assert!(wrap("Ж", TextHeight::H3_5, 1.0).is_none());
}
