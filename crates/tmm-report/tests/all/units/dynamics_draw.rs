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

/// The default project's ω diagram (ω from 93.3053 to 95.1903 rad/s over
/// the cycle), framed with no level drawn yet.
fn omega_chart() -> Chart {
    let phi = XKind::Phi((0..=12).map(|i| 30.0 * f64::from(i)).collect());
    Chart::new(
        Language::Ru,
        SheetFormat::A1,
        Slot::Diagram,
        "ω",
        ("ω_1", "rad/s"),
        (93.3053, 95.1903),
        false,
        phi,
        (0.0, 360.0),
    )
}

/// The names of the ω diagram's levels keep `LEVEL_CLEAR` between their
/// ink and every level's line — the highest near the frame's top, where
/// there is no room above it — and apart from each other.
#[test]
fn level_names_keep_clear_of_the_lines() {
    let levels = [95.1903, 94.2478, 93.3053];
    let mut ch = omega_chart();
    for (v, n) in levels.iter().zip(["ω_{max}", "ω_m", "ω_{min}"]) {
        ch.level(*v, "#c00000", n, "");
    }
    let (cap, drop) = level_name_ink();
    let lines: Vec<f64> = levels.iter().map(|v| ch.map(0.0, *v).1).collect();
    assert_eq!(ch.levels.len(), 3);
    assert_eq!(ch.levels_outside.len(), 3);
    for (i, at) in ch.levels.iter().enumerate() {
        let (top, foot) = (at - cap, at + drop);
        if ch.levels_outside[i] {
            // right of the frame, on its line's height: no line reaches there
            assert!(top < lines[i] && foot > lines[i], "name {i} stands at its line's height");
            continue;
        }
        assert!(top >= ch.fy && foot <= ch.corner().1, "name {i} inside the frame");
        for (j, y) in lines.iter().enumerate() {
            assert!(
                foot <= y - LEVEL_CLEAR + 1e-9 || top >= y + LEVEL_CLEAR - 1e-9,
                "name {i} (ink {top:.2}…{foot:.2} mm) within {LEVEL_CLEAR} mm of line {j} at {y:.2} mm"
            );
        }
        for other in &ch.levels[..i] {
            assert!((at - other).abs() >= cap + drop, "names overlap");
        }
    }
    // the short names fit right of the frame (ω_max about 8 mm wide)
    assert!(ch.levels_outside.iter().all(|o| *o));
}

/// A name too long for the room right of the frame stands inside it; at
/// the frame's top (ω_max 2.4 mm under it, 95.25 at μ 0.025) it hangs
/// under its line, its letters' tops `LEVEL_CLEAR` under the line.
#[test]
fn a_long_level_name_hangs_under_its_line_at_the_frames_top() {
    let mut ch = omega_chart();
    ch.level(95.1903, "#c00000", "ω_{max, установившийся}", "");
    let (cap, drop) = level_name_ink();
    let y = ch.map(0.0, 95.1903).1;
    assert_eq!(ch.levels_outside, [false]);
    let (top, foot) = (ch.levels[0] - cap, ch.levels[0] + drop);
    assert!(top >= y + LEVEL_CLEAR - 1e-9, "tops {top:.2} mm, line {y:.2} mm");
    assert!(foot <= ch.corner().1);
}

/// An indicator table wrapping the cycle's end is one span across it,
/// listed where the cylinder first enters it.
#[test]
fn a_wrapped_process_is_one_span() {
    use tmm_linkage::forces::{Curve, Indicator, Interpolation, Process, TravelScale};
    use tmm_report::dynamics::draw::indicator::tables_in_order;
    let t = |v: &[(f64, f64)]| Curve::new(v, Interpolation::Linear, "t").unwrap();
    let deg = f64::to_radians;
    let process = |name: &str, from: f64, to: f64, table: usize| Process {
        name: name.into(),
        from: deg(from),
        to: deg(to),
        table,
    };
    let ind = Indicator {
        tables: vec![t(&[(0.0, 1.0), (1.0, 2.0)]), t(&[(0.0, 3.0), (1.0, 4.0)])],
        names: vec!["a".into(), "b".into()],
        travel: TravelScale::Stroke,
        pressure_scale: 1.0,
        processes: vec![
            process("b", 0.0, 90.0, 1),
            process("a", 90.0, 270.0, 0),
            process("b", 270.0, 360.0, 1),
        ],
    };
    let o = tables_in_order(&ind);
    assert_eq!(o.len(), 2);
    assert_eq!(o[0].0, 1);
    assert_eq!(o[0].1.len(), 2);
    assert!((o[1].1[0].0 - 90.0).abs() < 1e-9 && (o[1].1[0].1 - 270.0).abs() < 1e-9);
}
