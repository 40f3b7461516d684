//! The cam's time diagrams mark the jumps of acceleration as impulses of
//! jerk (the course's "soft impacts"), with the sizes of the constant-
//! acceleration law derived here.

use std::path::Path;

use tmm_report::TaskSource;
use tmm_report::run::run_task;

#[test]
fn constant_acceleration_jumps_are_marked_as_jerk_impulses() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/cam-seed-001-roller.toml");
    let run = run_task(&TaskSource::new("cam.toml", std::fs::read_to_string(path).unwrap())).unwrap();
    let svg = run.docs.get("cam/cam-motion.svg").unwrap().as_text().unwrap();
    let labels: Vec<f64> = svg
        .lines()
        .filter_map(|l| {
            // a label's words sit in its last tspan: `Δa = −1317,175 м/с²`
            let t = &l[..l.find("</tspan></text>")?];
            let t = &t[t.rfind('>')? + 1..];
            t.strip_prefix("Δa = ")?
                .strip_suffix(" м/с²")?
                .replace('−', "-")
                .replace(',', ".")
                .parse()
                .ok()
        })
        .collect();
    // Constant acceleration a1 over u·β, −a2 over the rest: continuity of
    // velocity gives a2 = a1·u/(1 − u); the stroke h = a1·β²·u/2, so
    // a1 = 2h/(u·β²) per rad², times ω² in time.
    let (h, beta, u, w) = (0.013f64, 108f64.to_radians(), 1.0 / 3.0, 200.0f64);
    let a1 = 2.0 * h / (u * beta * beta) * w * w;
    let a2 = a1 * u / (1.0 - u);
    let mut want = vec![a1, -(a1 + a2), a2, -a1, a1 + a2, -a2];
    let mut got = labels.clone();
    want.sort_by(f64::total_cmp);
    got.sort_by(f64::total_cmp);
    assert_eq!(got.len(), 6, "{labels:?}");
    for (g, w) in got.iter().zip(&want) {
        assert!((g - w).abs() < 1e-3 * a1, "{got:?} vs {want:?}");
    }
}
