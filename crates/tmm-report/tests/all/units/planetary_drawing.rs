//! Tests of `tmm_report::planetary::drawing`, kept outside the library so that the
//! test command compiles it once.

use tmm_planetary::{Request, Scheme};

use tmm_report::planetary::drawing::sheet;
use tmm_report::planetary::{Origin, Params, analyse};

/// The ratios read off the drawn lines (paper coordinates) equal Willis'
/// exact fraction, in every scheme, and the sheet holds no non-finite number.
#[test]
fn drawn_ratio_is_willis() {
    for (scheme, u, k) in [
        (Scheme::SunPlanetRing, 4.0, 3),
        (Scheme::ExtInt, 12.5, 3),
        (Scheme::ExtExt, 1.0 / 30.0, 3),
        (Scheme::IntInt, -0.05, 3),
    ] {
        let a = analyse(&Params::new(Request::new(scheme, u, k)), &Origin::cli()).unwrap();
        let s = sheet(&a, Default::default(), Default::default());
        let w = a.best.ratio.value();
        assert!(
            (s.ratio_picture - w).abs() < 1e-9 * w.abs().max(1.0),
            "{scheme:?}: {} vs {w}",
            s.ratio_picture
        );
        assert!(
            (s.ratio_diagram - w).abs() < 1e-9 * w.abs().max(1.0),
            "{scheme:?}: {} vs {w}",
            s.ratio_diagram
        );
        assert!(!s.svg.contains("NaN") && !s.svg.contains("inf"));
    }
}

/// The drawing's ratios (Willis', read off the picture and off the
/// diagram) carry four significant digits as the note's numbers do: the
/// int-int train's u_1H = −1/20 (z = 100, 30, 28, 98 of
/// examples/planetary-int-int.toml: 1 − 30·98/(100·28)) as −0,05000, not
/// −0,050000; the sun-planet-ring train's 1 + 85/17 = 6 as 6,000.
#[test]
fn drawn_ratios_have_four_significant_digits() {
    for (scheme, u, printed, silly) in [
        (Scheme::IntInt, -0.05, "0,05000", "0,050000"),
        (Scheme::SunPlanetRing, 6.0, "6,000", "6,0000"),
    ] {
        let a = analyse(&Params::new(Request::new(scheme, u, 3)), &Origin::cli()).unwrap();
        let s = sheet(&a, Default::default(), Default::default());
        assert!((a.best.ratio.value() - u).abs() < 1e-12, "{scheme:?}");
        assert_eq!(s.svg.matches(printed).count(), 3, "{scheme:?}: the three ratios as {printed}");
        assert!(!s.svg.contains(silly), "{scheme:?}: a ratio with six decimals");
    }
}
