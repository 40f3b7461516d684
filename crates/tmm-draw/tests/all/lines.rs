//! GOST 2.303 lines: thickness range, widths, dash patterns.

use tmm_draw::{LegendStyle, LineType, Thickness};

#[test]
fn thickness_is_refused_outside_half_to_one_point_four_mm() {
    for s in [0.49, 1.41, 0.0, -0.7, f64::NAN] {
        assert!(Thickness::new(s).is_err(), "{s}");
    }
    for s in [0.5, 0.7, 1.0, 1.4] {
        assert!(Thickness::new(s).is_ok(), "{s}");
    }
}

#[test]
fn thin_lines_are_between_a_third_and_a_half_of_s() {
    for k in 0..=18 {
        let s = (0.5 + 0.05 * k as f64).min(1.4);
        let t = Thickness::new(s).unwrap();
        for lt in LineType::ALL {
            let w = lt.width(t);
            if lt == LineType::Main {
                assert_eq!(w, s);
            } else {
                assert!(w >= s / 3.0 - 1e-9 && w <= s / 2.0 + 1e-9, "{lt:?} s={s}: {w}");
            }
        }
    }
}

#[test]
fn dash_patterns_keep_to_gost_ranges_for_every_s() {
    for k in 0..=18 {
        let s = (0.5 + 0.05 * k as f64).min(1.4);
        let t = Thickness::new(s).unwrap();
        for lt in [LineType::Main, LineType::Thin, LineType::Wavy] {
            assert!(lt.dashes(t).is_empty());
        }
        let d = LineType::Dashed.dashes(t);
        assert_eq!(d.len(), 2);
        assert!((2.0..=8.0).contains(&d[0]) && (1.0..=2.0).contains(&d[1]), "dashed {d:?}");
        let a = LineType::Axis.dashes(t);
        assert_eq!(a.len(), 4);
        assert!((5.0..=30.0).contains(&a[0]), "axis dash {a:?}");
        let gap = LineType::Axis.gost_gap(t);
        assert!((3.0 - 1e-9..=5.0 + 1e-9).contains(&gap), "axis gap {gap}");
        let p = LineType::Phantom.dashes(t);
        assert_eq!(p.len(), 6);
        let gap = LineType::Phantom.gost_gap(t);
        assert!((4.0 - 1e-9..=6.0 + 1e-9).contains(&gap), "phantom gap {gap}");
        // every piece is positive (no zero-length dash an SVG viewer drops)
        assert!(a.iter().chain(&p).chain(&d).all(|&v| v > 0.0));
    }
}

#[test]
fn axis_pattern_at_a1_thickness_is_iso_proportional() {
    // s = 0.7: thin width d = 0.25; long dash 24d = 6 mm, gap (dot included) 3 mm
    let a = LineType::Axis.dashes(Thickness::A1);
    assert!((a[0] - 6.0).abs() < 1e-12);
    assert!((a[1] + a[2] + a[3] - 3.0).abs() < 1e-12);
    assert!((a[2] - 0.25).abs() < 1e-12);
}

#[test]
fn legend_styles_differ_without_colour() {
    let v: Vec<LegendStyle> = (0..20).map(LegendStyle::nth).collect();
    for i in 0..v.len() {
        for j in 0..i {
            assert_ne!(v[i], v[j], "{i} {j}");
        }
    }
}
