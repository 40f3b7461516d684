//! Tests of `tmm_report::dynamics::draw`, kept outside the library so that the
//! test command compiles it once.

use tmm_report::dynamics::draw::*;
use tmm_report::paper::{Slot, round_mu};
use tmm_report::project::{Language, SheetFormat};

/// A constant or empty quantity still gets a frame with a few finite
/// ticks (a massless mechanism has I_II ≡ 0), inside the slot.
#[test]
fn flat_data_gets_a_finite_frame() {
    for (a, b) in [
        (0.0, 0.0),
        (5.0, 5.0),
        (-1e-300, 1e-300),
        (1e9, 1e9 + 1e-7),
        (f64::INFINITY, f64::NEG_INFINITY),
    ] {
        let ch = Chart::new(
            Language::En,
            SheetFormat::A1,
            Slot::Diagram,
            "t",
            ("y", "m"),
            (a, b),
            false,
            XKind::Other("x".into(), "s".into()),
            (a, b),
        );
        assert!(ch.y.len > 0.0 && ch.x.len > 0.0, "{a} {b}");
        assert!(ch.y.len <= 120.0 - TOP - BOTTOM + 1e-9, "{a} {b}");
        let svg = ch.finish();
        assert!(svg.matches("<line").count() < 100, "{a} {b}");
    }
}

/// The axis' μ is round and the grid covers the data inside the room.
#[test]
fn axis_fits_at_a_round_mu() {
    for (a, b, room) in [(31.1, 31.75, 90.0), (-1234.0, 877.0, 50.0), (0.0, 0.0123, 113.0)] {
        let ax = Axis::fit(a, b, room);
        assert_eq!(ax.mu, round_mu(ax.mu));
        assert!(ax.lo <= a && ax.lo + ax.len * ax.mu >= b - 1e-12 && ax.len <= room + 1e-9);
    }
}
