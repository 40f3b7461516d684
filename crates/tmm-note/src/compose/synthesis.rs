//! Section "metric synthesis" (метрический синтез): the lengths of the
//! links from the time ratio K and the stroke or swing, with the check of
//! the pressure angles.

use serde_json::Value;

use super::assignment::as_given;
use super::context::{Ctx, formula, four_parts, num, text};
use crate::calc::{self, Calculation, Expr, Quantity};
use crate::error::NoteError;
use crate::model::{Block, Section};

/// Keys of the given values that are angles (printed in degrees).
const ANGLES: &[&str] = &[
    "swing",
    "theta",
    "angle",
    "phi",
    "psi",
    "pressure_angle",
    "transmission_angle",
    "arm_angle",
    "max_pressure",
    "extreme_pressure",
    "frame_angle",
    "delta",
];
/// Keys of the given values without a unit.
const PURE: &[&str] = &["k", "kv", "lambda", "ratio", "h_over_b"];

/// Keys of the given values that are speeds (m/s): the crank-slider's mean
/// speed, the shaper's cutting speed.
const VELOCITIES: &[&str] = &["v_mean", "v_cut"];

/// One given value printed with its unit: angles in degrees, ratios bare,
/// everything else a length in mm; its digits and unit as the task's
/// `[synthesis]` writes them ([`as_given`]).
fn given_value(cx: &Ctx, key: &str, v: f64) -> Result<String, NoteError> {
    // the numbered angles of a function generator: phi1, psi2 …
    let stem = key.trim_end_matches(|c: char| c.is_ascii_digit());
    // as the task writes it (K_v = 1,1065, not 1,107; 380 мм, not 380,0 мм)
    let task = &["synthesis"];
    if ANGLES.contains(&key) || ANGLES.contains(&stem) || is_angle_name(key) {
        as_given(cx, task, v.to_degrees(), "u_deg")
    } else if VELOCITIES.contains(&key) {
        as_given(cx, task, v, "u_m_s")
    } else if PURE.contains(&key) || key == "lambda_e" || coupler_ratio(cx, key) {
        as_given(cx, task, v, "")
    } else {
        as_given(cx, task, v * 1000.0, "u_mm")
    }
}

/// Names of the textbook's angles (γн, φ12, θк, …) and the task's other
/// angles (`frame_angle`, `pivot_angle`, `extreme_pressure`,
/// `pivot_max_pressure`, `transmission_min`, `design_position`: the
/// angles of tmm-report's `param_dim`): printed in degrees.
fn is_angle_name(key: &str) -> bool {
    ["gamma", "phi", "psi", "theta", "pressure_"].iter().any(|p| key.starts_with(p))
        || key.ends_with("_angle")
        || key.ends_with("_pressure")
        || matches!(key, "transmission_min" | "design_position")
}

/// Whether the given `coupler` is the slotted lever's ratio of the coupler
/// to the rocker (the task's `coupler_ratio`, a bare number), not a length.
fn coupler_ratio(cx: &Ctx, key: &str) -> bool {
    key == "coupler" && cx.task.get("synthesis").and_then(|s| s.get("coupler_ratio")).is_some()
}

/// The kinds solved by positions and loop equations (the textbook's П1),
/// stated without K as a given.
const BY_POSITIONS: &[&str] = &[
    "crank-slider-positions",
    "rocker-extremes",
    "rocker-extremes-k",
    "three-positions",
    "oscillating-cylinder",
];

/// The rows of the further unknowns found (angles in degrees, coordinates in mm).
fn found_rows(cx: &Ctx) -> Result<Vec<(String, String)>, NoteError> {
    let mut rows = Vec::new();
    for (ptr, angle) in [("/synthesis/angles", true), ("/synthesis/coordinates", false)] {
        if let Some(g) = cx.report.pointer(ptr).and_then(Value::as_object) {
            for (k, v) in g {
                if let Some(x) = v.as_f64() {
                    let value = if angle {
                        cx.q(x.to_degrees(), "u_deg")?
                    } else {
                        cx.q(x * 1000.0, "u_mm")?
                    };
                    rows.push((found_name(cx, k), value));
                }
            }
        }
    }
    Ok(rows)
}

/// The oscillating cylinder's keys named by the words of its own section
/// (`cy_q_…`): the lever's turn β, not a rocker's swing ψ.
const CYLINDER_WORDS: &[(&str, &str)] = &[
    ("h_min", "cy_q_hmin"),
    ("h_max", "cy_q_hmax"),
    ("rod", "cy_q_rod"),
    ("swing", "cy_q_swing"),
    ("pressure_end", "cy_q_pressure_end"),
    ("pressure_start", "cy_q_pressure_start"),
    ("frame_y", "cy_q_frame_y"),
    ("phi1", "cy_q_phi1"),
    ("phi3_start", "cy_q_phi3n"),
    ("phi3_end", "cy_q_phi3k"),
    ("theta_start", "cy_q_thetan"),
    ("theta_end", "cy_q_thetak"),
    ("X_D", "cy_q_xd"),
    ("Y_D", "cy_q_yd"),
];

/// The words of `key` for the oscillating cylinder, if it is one of its keys.
fn cylinder_word(cx: &Ctx, key: &str) -> Option<String> {
    if cx.s("/synthesis/kind") != Some("oscillating-cylinder") {
        return None;
    }
    let (_, word) = CYLINDER_WORDS.iter().find(|(k, _)| *k == key)?;
    cx.w(word).ok()
}

/// The name of a given value: the cylinder's own words, the words'
/// `given_<key>`, else the key.
fn given_name(cx: &Ctx, key: &str) -> String {
    if coupler_ratio(cx, key) {
        return cx.w("given_coupler_ratio").unwrap_or_else(|_| key.to_string());
    }
    cylinder_word(cx, key)
        .or_else(|| cx.w(&format!("given_{key}")).ok())
        .unwrap_or_else(|| key.to_string())
}

/// The name of an unknown found: the cylinder's own words, the words'
/// `found_<key>`, else the key.
fn found_name(cx: &Ctx, key: &str) -> String {
    cylinder_word(cx, key)
        .or_else(|| cx.w(&format!("found_{key}")).ok())
        .unwrap_or_else(|| key.to_string())
}

/// Givens of the task's `[synthesis]` the report does not repeat: the
/// frame's direction, the knee press' horizontal, the shaper's design
/// position, the line of the six-bar's crank pivot.
const TASK_ONLY: &[&str] = &["frame_angle", "horizontal", "design_position", "pivot_through"];

/// The given values of the synthesis as (name, value) rows, then the
/// task's givens the report does not repeat, as the task writes them.
pub(crate) fn given_rows(cx: &Ctx) -> Result<Vec<(String, String)>, NoteError> {
    let mut rows = Vec::new();
    let given = cx.report.pointer("/synthesis/given").and_then(Value::as_object);
    if let Some(g) = given {
        for (k, v) in g {
            if let Some(x) = v.as_f64() {
                rows.push((given_name(cx, k), given_value(cx, k, x)?));
            }
        }
    }
    let task = cx.task.get("synthesis").and_then(toml::Value::as_table);
    for key in TASK_ONLY {
        let (Some(v), false) = (task.and_then(|t| t.get(*key)), given.is_some_and(|g| g.contains_key(*key))) else {
            continue;
        };
        let value = match v {
            // a point (x; y)
            toml::Value::Array(a) => {
                let parts: Result<Vec<String>, NoteError> = a.iter().map(|p| super::assignment::quantity_text(cx, p)).collect();
                format!("({})", parts?.join("; "))
            }
            _ => super::assignment::quantity_text(cx, v)?,
        };
        rows.push((given_name(cx, key), value));
    }
    Ok(rows)
}

/// The section, if the report has `synthesis`.
pub(crate) fn section(cx: &Ctx) -> Result<Option<Section>, NoteError> {
    let Some(sy) = cx.report.get("synthesis") else { return Ok(None) };
    if cx.s("/synthesis/kind") == Some("function-generation") {
        return function_generation(cx, sy).map(Some);
    }
    let by_positions = cx.s("/synthesis/kind").is_some_and(|k| BY_POSITIONS.contains(&k));
    if by_positions {
        return section_by_positions(cx, sy).map(Some);
    }
    let k = cx.v("/synthesis/k")?;
    let statement = vec![
        Block::List(vec![cx.w("assume_rigid")?.into(), cx.w("assume_pairs")?.into()]),
        cx.para("sy_given", &[as_given(cx, &["synthesis"], k, "")?])?,
        cx.quantities("tab_given", given_rows(cx)?)?,
        // the textbook's П3: the crank pivot sees the chord between the
        // extreme positions of B at θ, one equation for the direction of OC
        cx.para(
            if cx.s("/synthesis/kind") == Some("shaper") {
                "sy_method_shaper"
            } else {
                "sy_method"
            },
            &[],
        )?,
        cx.para("sy_sought", &[])?,
    ];
    let formulas = vec![
        cx.para("sy_f_theta", &[])?,
        formula("theta = 180° (K_v - 1) / (K_v + 1)"),
        cx.para("where_theta", &[])?,
        cx.para("sy_f_pressure", &[])?,
        formula("gamma = 90° - theta.alt, quad theta.alt_max <= [theta.alt]"),
        cx.para("where_gamma", &[])?,
    ];
    // the worked angle of overlap with the given K (seed 004: θ = 180°·(1,1065 − 1)/(1,1065 + 1))
    let kq = || calc::qd("K_v", k, "", 5);
    let mut results = vec![
        cx.para("calc_theta", &[])?,
        Block::Calculation(Calculation::new(
            Quantity::new("theta", cx.v("/synthesis/theta")?.to_degrees(), "°"),
            Expr::Mul(vec![
                calc::exact(180.0, "180°"),
                calc::div(calc::sub(kq(), calc::int(1)), Expr::Sum(vec![kq(), calc::int(1)])),
            ]),
        )),
        lengths(cx, sy)?,
    ];
    // further unknowns found (the shaper's φ₀, β, X_C, Y_C, Y_S5)
    let found = found_rows(cx)?;
    if !found.is_empty() {
        results.push(cx.quantities("tab_synth_found", found)?);
    }
    // the K_v reproduced, with the given's digits (1,1065 against 1,1065)
    let check = cx.v("/synthesis/check/k")?;
    let digits = super::assignment::given_precision(cx, &["synthesis"], k, "");
    let f = |x: f64| crate::number::format_number(crate::number::zero_noise(x, 0.0), digits, cx.lang).map(|n| n.to_string());
    // met: written as the given is (1,28 for 1,28, not 1,280)
    let k_check = if f(check)? == f(k)? {
        as_given(cx, &["synthesis"], k, "")?
    } else {
        f(check)?
    };
    let mut q = vec![
        (cx.w("q_theta")?, cx.deg("/synthesis/theta")?),
        (cx.w("q_k_check")?, k_check.clone()),
    ];
    q.extend(angle_checks(cx)?);
    results.push(cx.quantities("tab_synth_results", q)?);
    results.extend(figures(cx)?);
    let conclusions = vec![cx.para(
        "sy_conclusion",
        &[k_check, as_given(cx, &["synthesis"], k, "")?, cx.relative(((check - k) / k).abs())?],
    )?];
    Ok(Some(four_parts(cx, "sec_synthesis", statement, formulas, results, conclusions)?))
}

/// The section of a function generator (by given positions, Freudenstein):
/// no time ratio is given, and the crank may not turn fully (then the check
/// has no K_v).
fn function_generation(cx: &Ctx, sy: &Value) -> Result<Section, NoteError> {
    let statement = vec![
        Block::List(vec![cx.w("assume_rigid")?.into(), cx.w("assume_pairs")?.into()]),
        cx.para("sy_given_function", &[])?,
        cx.quantities("tab_given", given_rows(cx)?)?,
        cx.para("sy_method_function", &[])?,
        cx.para("sy_sought", &[])?,
    ];
    let formulas = vec![
        cx.para("sy_f_function", &[])?,
        // Freudenstein 1955; Norton, Design of Machinery, § 5.12 (as the core's
        // tmm_linkage::synthesis::function_gen states it)
        formula(
            "K_1 cos psi - K_2 cos phi + K_3 = cos(phi - psi), quad K_1 = d / a, quad K_2 = d / c, quad K_3 = (a^2 - b^2 + c^2 + d^2) / (2 a c)",
        ),
        cx.para("sy_f_pressure", &[])?,
        formula("gamma = 90° - theta.alt, quad theta.alt_max <= [theta.alt]"),
    ];
    let mut results = vec![lengths(cx, sy)?];
    let check = cx.opt("/synthesis/check/k");
    let mut q = Vec::new();
    if let Some(k) = check {
        q.push((cx.w("q_k_check")?, cx.q(k, "")?));
    }
    q.extend(angle_checks(cx)?);
    if !q.is_empty() {
        results.push(cx.quantities("tab_synth_results", q)?);
    }
    results.extend(figures(cx)?);
    let conclusions = vec![match check {
        Some(k) => cx.para("sy_conclusion_function_full", &[cx.q(k, "")?])?,
        None => cx.para("sy_conclusion_function_partial", &[])?,
    }];
    four_parts(cx, "sec_synthesis", statement, formulas, results, conclusions)
}

/// The table of the synthesised lengths.
fn lengths(cx: &Ctx, sy: &Value) -> Result<Block, NoteError> {
    let mut rows = Vec::new();
    if let Some(l) = sy.get("lengths").and_then(Value::as_object) {
        for (name, v) in l {
            if let Some(x) = v.as_f64() {
                rows.push(vec![text(crate::notation::notation(&format!("l_{name}"))), num(x * 1000.0)]);
            }
        }
    }
    cx.table("tab_synth_lengths", &[("col_length_name", ""), ("col_length", "u_mm")], rows)
}

/// The drawings of the synthesis the run made.
fn figures(cx: &Ctx) -> Result<Vec<Block>, NoteError> {
    let mut out = Vec::new();
    for (path, key) in [
        ("synthesis/construction.svg", "fig_synth_construction"),
        ("synthesis/pressure.svg", "fig_synth_pressure"),
    ] {
        if let Some(f) = cx.figure(path, key)? {
            out.push(f);
        }
    }
    Ok(out)
}

/// The checked pressure and transmission angles the report has.
fn angle_checks(cx: &Ctx) -> Result<Vec<(String, String)>, NoteError> {
    let mut q = Vec::new();
    if let Some(w) = cx.opt("/synthesis/pressure_angle_max/working") {
        q.push((cx.w("q_pressure_working")?, cx.q(w.to_degrees(), "u_deg")?));
    }
    if let Some(r) = cx.opt("/synthesis/pressure_angle_max/return") {
        q.push((cx.w("q_pressure_return")?, cx.q(r.to_degrees(), "u_deg")?));
    }
    if let Some(t) = cx.opt("/synthesis/transmission_angle_min") {
        q.push((cx.w("q_transmission_min")?, cx.q(t.to_degrees(), "u_deg")?));
    }
    Ok(q)
}

/// The lengths of the synthesised mechanism as table rows; a length of a
/// position (`DB_start`, the cylinder's D to B at the start) as `l_DB` and
/// the position in words.
fn length_rows(cx: &Ctx, sy: &Value) -> Result<Vec<Vec<crate::model::Cell>>, NoteError> {
    let mut rows = Vec::new();
    if let Some(l) = sy.get("lengths").and_then(Value::as_object) {
        for (name, v) in l {
            if let Some(x) = v.as_f64() {
                let label = if let Some(base) = name.strip_suffix("_start") {
                    format!("{} {}", crate::notation::notation(&format!("l_{base}")), cx.w("sy_len_start")?)
                } else if let Some(base) = name.strip_suffix("_end") {
                    format!("{} {}", crate::notation::notation(&format!("l_{base}")), cx.w("sy_len_end")?)
                } else {
                    crate::notation::notation(&format!("l_{name}"))
                };
                rows.push(vec![text(label), num(x * 1000.0)]);
            }
        }
    }
    Ok(rows)
}

/// The section of a synthesis by positions (the textbook's П1): the loop
/// equations at the given positions, the unknowns found, the check by the
/// kinematic analysis; K only where the crank turns fully.
fn section_by_positions(cx: &Ctx, sy: &Value) -> Result<Section, NoteError> {
    let statement = vec![
        Block::List(vec![cx.w("assume_rigid")?.into(), cx.w("assume_pairs")?.into()]),
        cx.para("sy_given_positions", &[])?,
        cx.quantities("tab_given", given_rows(cx)?)?,
        cx.para("sy_method_positions", &[])?,
        cx.para("sy_sought_positions", &[])?,
    ];
    let formulas = vec![
        cx.para("sy_f_pressure", &[])?,
        formula("gamma = 90° - theta.alt, quad theta.alt_max <= [theta.alt]"),
    ];
    let mut results = vec![cx.table(
        "tab_synth_lengths",
        &[("col_length_name", ""), ("col_length", "u_mm")],
        length_rows(cx, sy)?,
    )?];
    let found = found_rows(cx)?;
    if !found.is_empty() {
        results.push(cx.quantities("tab_synth_found", found)?);
    }
    let mut q = Vec::new();
    if let Some(k) = cx.opt("/synthesis/check/k") {
        q.push((cx.w("q_k_check")?, cx.q(k, "")?));
    }
    if let Some(w) = cx.opt("/synthesis/pressure_angle_max/working") {
        q.push((cx.w("q_pressure_working")?, cx.q(w.to_degrees(), "u_deg")?));
    }
    if let Some(r) = cx.opt("/synthesis/pressure_angle_max/return") {
        q.push((cx.w("q_pressure_return")?, cx.q(r.to_degrees(), "u_deg")?));
    }
    if let Some(t) = cx.opt("/synthesis/transmission_angle_min") {
        q.push((cx.w("q_transmission_min")?, cx.q(t.to_degrees(), "u_deg")?));
    }
    results.push(cx.quantities("tab_synth_results", q)?);
    // the oscillating cylinder's diagram is of the pressure angle in the
    // analysed group with the lever as the input, identically zero (the
    // rod's force and the cylinder's point B both across DB); the angle
    // that matters, the rod's on the lever, is in the table and the
    // kinematic analysis' conclusion
    let cylinder = cx.s("/synthesis/kind") == Some("oscillating-cylinder");
    for (path, key) in [
        ("synthesis/construction.svg", "fig_synth_positions"),
        ("synthesis/pressure.svg", "fig_synth_pressure"),
    ] {
        if cylinder && key == "fig_synth_pressure" {
            continue;
        }
        if let Some(f) = cx.figure(path, key)? {
            results.push(f);
        }
    }
    let conclusions = vec![cx.para("sy_conclusion_positions", &[])?];
    four_parts(cx, "sec_synthesis", statement, formulas, results, conclusions)
}
