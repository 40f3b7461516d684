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
