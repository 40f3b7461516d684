//! Section "cam mechanism" (синтез кулачкового механизма): the motion law,
//! the minimum size from the allowed pressure angles, the profile.

use serde_json::Value;

use super::context::{Ctx, formula, four_parts, num, text};
use crate::error::NoteError;
use crate::model::{Block, Section};

/// The given values of the cam as (name, value) rows.
pub(crate) fn given_rows(cx: &Ctx) -> Result<Vec<(String, String)>, NoteError> {
    let mut rows = vec![
        (cx.w("q_follower")?, follower(cx)?),
        (cx.w("q_stroke")?, cx.qv("/cam/stroke", 1000.0, "u_mm")?),
        (cx.w("q_cam_omega")?, cx.qv("/cam/omega", 1.0, "u_rad_s")?),
    ];
    if let Some(p) = cx.opt("/cam/pressure_angle_limit_rise") {
        rows.push((cx.w("q_limit_rise")?, cx.q(p.to_degrees(), "u_deg")?));
    }
    if let Some(p) = cx.opt("/cam/pressure_angle_limit_return") {
        rows.push((cx.w("q_limit_return")?, cx.q(p.to_degrees(), "u_deg")?));
    }
    Ok(rows)
}

/// The follower's kind in words.
fn follower(cx: &Ctx) -> Result<String, NoteError> {
    let f = cx.s("/cam/follower").unwrap_or("");
    Ok(cx.w(&format!("follower_{}", f.replace('-', "_"))).unwrap_or_else(|_| f.to_string()))
}

/// The section, if the report has `cam`.
pub(crate) fn section(cx: &Ctx) -> Result<Option<Section>, NoteError> {
    let Some(cam) = cx.report.get("cam") else { return Ok(None) };
    let statement = vec![
        Block::List(vec![cx.w("assume_rigid")?.into(), cx.w("assume_friction")?.into()]),
        cx.para("cam_given", &[follower(cx)?, cx.qv("/cam/stroke", 1000.0, "u_mm")?])?,
        cx.para("cam_method", &[])?,
        cx.para("cam_sought", &[])?,
    ];
    let formulas = vec![
        cx.para("cam_f_analogs", &[])?,
        formula("v = omega (dif s) / (dif phi), quad a = omega^2 (dif^2 s) / (dif phi^2)"),
        cx.para("cam_f_pressure", &[])?,
        formula("tan vartheta = ((dif s) / (dif phi) - e) / (s_0 + s), quad s_0 = sqrt(r_0^2 - e^2)"),
        cx.para("cam_f_roller", &[])?,
        // the numbers with the language's decimal separator
        formula(&format!(
            "r_r <= {} r_0, quad r_r <= {} rho_min",
            crate::number::math_number(0.4, 1, cx.lang)?,
            crate::number::math_number(0.7, 1, cx.lang)?
        )),
    ];
    let mut rows = Vec::new();
    if let Some(ph) = cam.get("phases").and_then(Value::as_array) {
        for p in ph {
            let kind = p.get("kind").and_then(Value::as_str).unwrap_or("");
            let angle = p.get("angle").and_then(Value::as_f64).unwrap_or(0.0);
            rows.push(vec![
                text(cx.w(&format!("phase_{kind}")).unwrap_or_else(|_| kind.to_string())),
                num(angle.to_degrees()),
                num(p.get("ds_dphi_max").and_then(Value::as_f64).unwrap_or(0.0) * 1000.0),
                num(p.get("d2s_dphi2_max").and_then(Value::as_f64).unwrap_or(0.0) * 1000.0),
            ]);
        }
    }
    let mut results = vec![cx.table(
        "tab_cam_phases",
        &[
            ("col_phase", ""),
            ("col_phase_angle", "u_deg"),
            ("col_ds_max", "u_mm"),
            ("col_dds_max", "u_mm"),
        ],
        rows,
    )?];
    let mut q = vec![
        (cx.w("q_r0")?, cx.qv("/cam/r0", 1000.0, "u_mm")?),
        (cx.w("q_e")?, cx.qv("/cam/e", 1000.0, "u_mm")?),
        (cx.w("q_pressure_rise")?, cx.deg("/cam/pressure_angle_max_rise")?),
        (cx.w("q_pressure_return")?, cx.deg("/cam/pressure_angle_max_return")?),
        (cx.w("q_rho_min")?, cx.qv("/cam/rho_min", 1000.0, "u_mm")?),
    ];
    if let Some(r) = cx.opt("/cam/roller_radius") {
        q.insert(2, (cx.w("q_roller")?, cx.q(r * 1000.0, "u_mm")?));
    }
    results.push(cx.quantities("tab_cam", q)?);
    for (path, key) in [
        ("cam/cam-motion.svg", "fig_cam_motion"),
        ("cam/cam-analogs.svg", "fig_cam_analogs"),
        ("cam/cam-sizing.svg", "fig_cam_sizing"),
        ("cam/cam-pressure.svg", "fig_cam_pressure"),
        ("cam/cam.svg", "fig_cam_profile"),
    ] {
        if let Some(f) = cx.figure(path, key)? {
            results.push(f);
        }
    }
    let undercut = cam.get("undercut").and_then(Value::as_bool).unwrap_or(false);
    let conclusions = vec![cx.para(
        if undercut { "cam_conclusion_undercut" } else { "cam_conclusion" },
        &[
            cx.qv("/cam/r0", 1000.0, "u_mm")?,
            cx.deg("/cam/pressure_angle_max_rise")?,
            cx.deg("/cam/pressure_angle_max_return")?,
            cx.qv("/cam/rho_min", 1000.0, "u_mm")?,
        ],
    )?];
    Ok(Some(four_parts(cx, "sec_cam", statement, formulas, results, conclusions)?))
}
