//! The task files of `examples/` and `examples/textbook/` (the textbook's
//! worked examples), embedded so that the page offers them offline. A test
//! checks that every file of the two folders is here.

/// (file name, text) of every example, in the folder's alphabetical order,
/// then the textbook's (`textbook/…`).
pub const EXAMPLES: &[(&str, &str)] = &[
    (
        "cam-oscillating-roller.toml",
        include_str!("../../../examples/cam-oscillating-roller.toml"),
    ),
    ("cam-seed-001-flat.toml", include_str!("../../../examples/cam-seed-001-flat.toml")),
    (
        "cam-seed-001-roller.toml",
        include_str!("../../../examples/cam-seed-001-roller.toml"),
    ),
    ("class3-triad.toml", include_str!("../../../examples/class3-triad.toml")),
    (
        "compressor-two-stage.toml",
        include_str!("../../../examples/compressor-two-stage.toml"),
    ),
    ("crank-slider-axial.toml", include_str!("../../../examples/crank-slider-axial.toml")),
    (
        "crank-slider-offset.toml",
        include_str!("../../../examples/crank-slider-offset.toml"),
    ),
    ("double-rocker.toml", include_str!("../../../examples/double-rocker.toml")),
    ("gear-internal.toml", include_str!("../../../examples/gear-internal.toml")),
    ("gear-seed001.toml", include_str!("../../../examples/gear-seed001.toml")),
    ("gear-seed003.toml", include_str!("../../../examples/gear-seed003.toml")),
    ("planetary-ext-ext.toml", include_str!("../../../examples/planetary-ext-ext.toml")),
    ("planetary-ext-int.toml", include_str!("../../../examples/planetary-ext-int.toml")),
    ("planetary-int-int.toml", include_str!("../../../examples/planetary-int-int.toml")),
    (
        "planetary-sun-planet-ring.toml",
        include_str!("../../../examples/planetary-sun-planet-ring.toml"),
    ),
    ("prp-moving-guides.toml", include_str!("../../../examples/prp-moving-guides.toml")),
    ("rpp-moving-guides.toml", include_str!("../../../examples/rpp-moving-guides.toml")),
    ("seed-001-fourbar.toml", include_str!("../../../examples/seed-001-fourbar.toml")),
    (
        "seed-002-knee-press.toml",
        include_str!("../../../examples/seed-002-knee-press.toml"),
    ),
    ("seed-002-shaper.toml", include_str!("../../../examples/seed-002-shaper.toml")),
    ("seed-003-sixbar.toml", include_str!("../../../examples/seed-003-sixbar.toml")),
    (
        "seed-004-two-sliders.toml",
        include_str!("../../../examples/seed-004-two-sliders.toml"),
    ),
    ("slider-input.toml", include_str!("../../../examples/slider-input.toml")),
    (
        "synth-seed-002-ex1-crank-rocker.toml",
        include_str!("../../../examples/synth-seed-002-ex1-crank-rocker.toml"),
    ),
    (
        "synth-seed-002-ex2-knee-press-bell-crank.toml",
        include_str!("../../../examples/synth-seed-002-ex2-knee-press-bell-crank.toml"),
    ),
    (
        "synth-seed-002-ex2-knee-press.toml",
        include_str!("../../../examples/synth-seed-002-ex2-knee-press.toml"),
    ),
    (
        "synth-seed-002-ex3-shaper.toml",
        include_str!("../../../examples/synth-seed-002-ex3-shaper.toml"),
    ),
    (
        "synth-seed-002-ex4-six-bar.toml",
        include_str!("../../../examples/synth-seed-002-ex4-six-bar.toml"),
    ),
    (
        "synth-seed-003-six-bar.toml",
        include_str!("../../../examples/synth-seed-003-six-bar.toml"),
    ),
    (
        "textbook/p1-1-crank-slider-two-positions.toml",
        include_str!("../../../examples/textbook/p1-1-crank-slider-two-positions.toml"),
    ),
    (
        "textbook/p1-2-four-bar-extreme-positions.toml",
        include_str!("../../../examples/textbook/p1-2-four-bar-extreme-positions.toml"),
    ),
    (
        "textbook/p1-3-four-bar-extreme-positions-k.toml",
        include_str!("../../../examples/textbook/p1-3-four-bar-extreme-positions-k.toml"),
    ),
    (
        "textbook/p1-4-four-bar-three-positions.toml",
        include_str!("../../../examples/textbook/p1-4-four-bar-three-positions.toml"),
    ),
    (
        "textbook/p1-5-oscillating-cylinder-v1.toml",
        include_str!("../../../examples/textbook/p1-5-oscillating-cylinder-v1.toml"),
    ),
    (
        "textbook/p1-5-oscillating-cylinder-v2.toml",
        include_str!("../../../examples/textbook/p1-5-oscillating-cylinder-v2.toml"),
    ),
    (
        "textbook/p1-5-oscillating-cylinder-v3.toml",
        include_str!("../../../examples/textbook/p1-5-oscillating-cylinder-v3.toml"),
    ),
    ("textbook/p2-engine.toml", include_str!("../../../examples/textbook/p2-engine.toml")),
    ("textbook/p3-shaper.toml", include_str!("../../../examples/textbook/p3-shaper.toml")),
    ("textbook/p4-press.toml", include_str!("../../../examples/textbook/p4-press.toml")),
    (
        "textbook/p5-pneumatic-cylinder.toml",
        include_str!("../../../examples/textbook/p5-pneumatic-cylinder.toml"),
    ),
    (
        "textbook/p6-cam-oscillating.toml",
        include_str!("../../../examples/textbook/p6-cam-oscillating.toml"),
    ),
    (
        "textbook/p6-cam-translating.toml",
        include_str!("../../../examples/textbook/p6-cam-translating.toml"),
    ),
];

/// The examples as JSON `[{"name": …, "text": …}, …]`.
///
/// ```
/// let v: serde_json::Value = serde_json::from_str(&tmm_web::examples::json()).unwrap();
/// assert!(v.as_array().unwrap().iter().any(|e| e["name"] == "seed-003-sixbar.toml"));
/// ```
pub fn json() -> String {
    let v: Vec<serde_json::Value> = EXAMPLES
        .iter()
        .map(|(name, text)| serde_json::json!({ "name": name, "text": text }))
        .collect();
    serde_json::Value::Array(v).to_string()
}
