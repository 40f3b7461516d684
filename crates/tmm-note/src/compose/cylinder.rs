//! Section "a mechanism with a linear generalized coordinate" (механизм с
//! линейной обобщённой координатой, the textbook's П5): a lever driven by
//! an oscillating cylinder, the piston's travel s as the coordinate — the
//! synthesis, the analogues d/ds, the reduced mass and forces, the
//! zero-work control force, V(s), a(s), t(s) and how the end is reached,
//! the kinetostatics at one s with the balancing force checked against
//! the control force. Present when the report has `cylinder`.

use serde_json::Value;

use super::assignment::as_given;
use super::context::{Ctx, formula, four_parts, num, text};
use crate::error::NoteError;
use crate::model::{Block, Section};

fn arr(cx: &Ctx, p: &str) -> Vec<Option<f64>> {
    cx.report
        .pointer(p)
        .and_then(Value::as_array)
        .map(|a| a.iter().map(Value::as_f64).collect())
        .unwrap_or_default()
}

/// The task's tables of the cylinder drive's givens.
const TASK: &[&str] = &["cylinder", "synthesis"];

/// The given values of `[cylinder]` as (name, value) rows: the geometry,
/// the masses, the control force's switch point and the kinetostatics'
/// position (the section's table and the technical assignment's).
pub(crate) fn given_rows(cx: &Ctx) -> Result<Vec<(String, String)>, NoteError> {
    let synthesised = cx.report.pointer("/cylinder/synthesis").is_some();
    // each value as the task's `[cylinder]` writes it (h_min = 50 мм)
    let given = |ptr: &str, unit: &str| as_given(cx, TASK, cx.v(ptr)?, unit);
    let deg = |ptr: &str| as_given(cx, TASK, cx.v(ptr)?.to_degrees(), "u_deg");
    let mut rows = vec![
        (cx.w("cy_q_hmin")?, given("/cylinder/geometry/h_min", "cy_u_m")?),
        (cx.w("cy_q_hmax")?, given("/cylinder/geometry/h_max", "cy_u_m")?),
        (cx.w("cy_q_rod")?, given("/cylinder/geometry/rod", "cy_u_m")?),
        (cx.w("cy_q_lcs2")?, given("/cylinder/geometry/l_CS2", "cy_u_m")?),
        (cx.w("cy_q_lak")?, given("/cylinder/geometry/l_AK", "cy_u_m")?),
        (cx.w("cy_q_alpha")?, deg("/cylinder/geometry/alpha")?),
        (cx.w("cy_q_load")?, given("/cylinder/masses/load", "u_kg")?),
        (cx.w("cy_q_m1")?, given("/cylinder/masses/m1", "u_kg")?),
        (cx.w("cy_q_i1")?, given("/cylinder/masses/I1S", "u_kgm2")?),
        (cx.w("cy_q_m2")?, given("/cylinder/masses/m2", "u_kg")?),
        (cx.w("cy_q_i2")?, given("/cylinder/masses/I2S", "u_kgm2")?),
        (cx.w("cy_q_m3")?, given("/cylinder/masses/m3", "u_kg")?),
        (cx.w("cy_q_i3")?, given("/cylinder/masses/I3S", "u_kgm2")?),
        (cx.w("cy_q_switch")?, given("/cylinder/control/switch", "cy_u_m")?),
        (cx.w("cy_q_at")?, given("/cylinder/kinetostatics/s", "cy_u_m")?),
    ];
    if synthesised {
        rows.insert(3, (cx.w("cy_q_swing")?, deg("/cylinder/geometry/swing")?));
        // the pressure angle given at the end or the start, and Y_D
        let mut at = 4;
        for (key, word) in [("pressure_end", "cy_q_pressure_end"), ("pressure_start", "cy_q_pressure_start")] {
            if let Some(v) = cx
                .report
                .pointer(&format!("/cylinder/synthesis/given/{key}"))
                .and_then(Value::as_f64)
            {
                rows.insert(at, (cx.w(word)?, as_given(cx, TASK, v.to_degrees(), "u_deg")?));
                at += 1;
            }
        }
        if cx.report.pointer("/cylinder/synthesis/given/frame_y").is_some() {
            rows.insert(at, (cx.w("cy_q_frame_y")?, given("/cylinder/synthesis/given/frame_y", "cy_u_m")?));
        }
    }
    Ok(rows)
}

/// The section, if the report has `cylinder`.
pub(crate) fn section(cx: &Ctx) -> Result<Option<Section>, NoteError> {
    if cx.report.get("cylinder").is_none() {
        return Ok(None);
    }
    let synthesised = cx.report.pointer("/cylinder/synthesis").is_some();
    let given = given_rows(cx)?;
    let statement = vec![
        Block::List(vec![
            cx.w("assume_rigid")?.into(),
            cx.w("assume_friction")?.into(),
            cx.w("cy_assume_control")?.into(),
        ]),
        cx.quantities("cy_tab_given", given)?,
        cx.para("cy_sought", &[])?,
    ];
    let mut formulas = Vec::new();
    if synthesised {
        formulas.push(cx.para("cy_f_synthesis", &[])?);
    }
    // the symbols in the note's language (m_пр, m_зв, m_red …)
    let (m, mds, fc, fs, rod) = (
        cx.sym("sym_cy_mass")?,
        cx.sym("sym_cy_mass_ds")?,
        cx.sym("sym_cy_fc")?,
        cx.sym("sym_cy_fsum")?,
        cx.sym("sym_cy_rod")?,
    );
    formulas.extend([
        cx.para("cy_f_positions", &[])?,
        formula(&format!("X_D + (h_min + s + {rod}) cos phi_3 = l_(A B) cos phi_1,")),
        formula(&format!("Y_D + (h_min + s + {rod}) sin phi_3 = l_(A B) sin phi_1")),
        cx.para("cy_f_analogues", &[])?,
        formula("omega_(q 1) = 1 / (l_(A B) cos theta), quad theta = phi_1 + pi/2 - phi_3,"),
        formula(&format!(
            "omega_(q 3) = (l_(A B) omega_(q 1) cos(phi_1 - phi_3)) / (h_min + s + {rod})"
        )),
        cx.para("cy_f_reduced", &[])?,
        formula(&format!(
            "{m} = I_(1 S) omega_(q 1)^2 + (I_(2 S) + I_(3 S)) omega_(q 3)^2 + m_2 |V_(q S 2)|^2 + M |V_(q K)|^2,"
        )),
        formula(&format!("{fc} = G_2 V_(q S 2 y) + G V_(q K y)")),
        cx.para("cy_f_control", &[])?,
        formula("F_H s_c + (F_H + F_K)(s_max - s_c) / 2 = -A_C,"),
        formula(&format!("A_C = integral_0^(s_max) {fc} dif s, quad F_K = |{fc}(s_max)|")),
        cx.para("cy_f_motion", &[])?,
        formula(&format!(
            "V(s) = sqrt((2 A_Sigma (s)) / ({m}(s))), quad a(s) = ({fs} - 1/2 {mds} V^2) / {m},"
        )),
        formula("t(s) = integral_0^s (dif s) / V"),
        cx.para("cy_f_kinetostatics", &[])?,
        formula("epsilon_k = epsilon_(q k) V^2 + omega_(q k) a, quad a_P = a_(q P) V^2 + V_(q P) a,"),
        formula("Phi = -m a_S, quad M_Phi = -I_S epsilon"),
    ]);
    let mut results = Vec::new();
    if synthesised {
        results.push(cx.quantities(
            "cy_tab_synthesis",
            vec![
                (cx.w("cy_q_xd")?, cx.qv("/cylinder/synthesis/X_D", 1.0, "cy_u_m")?),
                (cx.w("cy_q_yd")?, cx.qv("/cylinder/synthesis/Y_D", 1.0, "cy_u_m")?),
                (cx.w("cy_q_lab")?, cx.qv("/cylinder/synthesis/l_AB", 1.0, "cy_u_m")?),
                (cx.w("cy_q_phi1")?, cx.deg("/cylinder/synthesis/phi1")?),
                (cx.w("cy_q_phi3n")?, cx.deg("/cylinder/synthesis/phi3_start")?),
                (cx.w("cy_q_phi3k")?, cx.deg("/cylinder/synthesis/phi3_end")?),
                (cx.w("cy_q_thetan")?, cx.deg("/cylinder/synthesis/theta_start")?),
                (cx.w("cy_q_thetak")?, cx.deg("/cylinder/synthesis/theta_end")?),
            ],
        )?);
    }
    if let Some(f) = cx.figure("cylinder/mechanism.svg", "cy_fig_mechanism")? {
        results.push(f);
    }
    // the analogues at every tenth of the travel (the JSON's first 11 rows)
    let s = arr(cx, "/cylinder/analogues/s");
    let cols = [
        ("/cylinder/analogues/phi1", true),
        ("/cylinder/analogues/phi3", true),
        ("/cylinder/analogues/omega_q1", false),
        ("/cylinder/analogues/omega_q3", false),
        ("/cylinder/analogues/eps_q1", false),
        ("/cylinder/analogues/eps_q3", false),
    ]
    .map(|(p, d)| (arr(cx, p), d));
    let mut rows = Vec::new();
    for (k, sv) in s.iter().enumerate().take(11) {
        let mut row = vec![num(sv.unwrap_or(0.0))];
        row.extend(cols.iter().map(|(c, d)| {
            let v = c.get(k).copied().flatten().unwrap_or(0.0);
            num(if *d { v.to_degrees() } else { v })
        }));
        rows.push(row);
    }
    results.push(cx.table(
        "cy_tab_analogues",
        &[
            ("cy_col_s", "cy_u_m"),
            ("cy_col_phi1", "u_deg"),
            ("cy_col_phi3", "u_deg"),
            ("cy_col_wq1", "cy_u_rad_m"),
            ("cy_col_wq3", "cy_u_rad_m"),
            ("cy_col_eq1", "cy_u_rad_m2"),
            ("cy_col_eq3", "cy_u_rad_m2"),
        ],
        rows,
    )?);
    results.push(cx.quantities(
        "cy_tab_control",
        vec![
            (cx.w("cy_q_ac")?, cx.qv("/cylinder/control/work_resistance", 1.0, "u_j")?),
            (cx.w("cy_q_fk")?, cx.qv("/cylinder/control/F_K", 1.0, "u_n")?),
            (cx.w("cy_q_fh")?, cx.qv("/cylinder/control/F_H", 1.0, "u_n")?),
        ],
    )?);
    let ms = arr(cx, "/cylinder/motion/s");
    let mcols = [
        "/cylinder/motion/reduced_mass",
        "/cylinder/motion/reduced_mass_derivative",
        "/cylinder/motion/force_resistance",
        "/cylinder/motion/force_control",
        "/cylinder/motion/speed",
        "/cylinder/motion/acceleration",
        "/cylinder/motion/time",
    ]
    .map(|p| arr(cx, p));
    let n = ms.len().saturating_sub(1);
    let mut rows = Vec::new();
    if n > 0 {
        for k in 0..=10 {
            let i = k * n / 10;
            let mut row = vec![num(ms[i].unwrap_or(0.0))];
            row.extend(mcols.iter().map(|c| match c.get(i).copied().flatten() {
                Some(v) => num(v),
                None => text(cx.w("cy_infinite").unwrap_or_default()),
            }));
            rows.push(row);
        }
    }
    results.push(cx.table(
        "cy_tab_motion",
        &[
            ("cy_col_s", "cy_u_m"),
            ("cy_col_mass", "u_kg"),
            ("cy_col_dmass", "cy_u_kg_m"),
            ("cy_col_fc", "u_n"),
            ("cy_col_fd", "u_n"),
            ("cy_col_v", "u_m_s"),
            ("cy_col_a", "u_m_s2"),
            ("cy_col_t", "cy_u_s"),
        ],
        rows,
    )?);
    for (path, key) in [
        ("cylinder/mass.svg", "cy_fig_mass"),
        ("cylinder/forces.svg", "cy_fig_forces"),
        ("cylinder/speed.svg", "cy_fig_speed"),
        ("cylinder/accel.svg", "cy_fig_accel"),
        ("cylinder/time.svg", "cy_fig_time"),
    ] {
        if let Some(f) = cx.figure(path, key)? {
            results.push(f);
        }
    }
    let kin: Vec<(String, String)> = vec![
        (cx.w("cy_q_phi1_at")?, cx.deg("/cylinder/position/phi1")?),
        (cx.w("cy_q_phi3_at")?, cx.deg("/cylinder/position/phi3")?),
        (cx.w("cy_q_v_at")?, cx.qv("/cylinder/kinetostatics/speed", 1.0, "u_m_s")?),
        (cx.w("cy_q_a_at")?, cx.qv("/cylinder/kinetostatics/acceleration", 1.0, "u_m_s2")?),
        (
            crate::notation::notation("R_AX"),
            cx.qv("/cylinder/kinetostatics/R_AX", 1.0, "u_n")?,
        ),
        (
            crate::notation::notation("R_AY"),
            cx.qv("/cylinder/kinetostatics/R_AY", 1.0, "u_n")?,
        ),
        (
            crate::notation::notation("R_BX"),
            cx.qv("/cylinder/kinetostatics/R_BX", 1.0, "u_n")?,
        ),
        (
            crate::notation::notation("R_BY"),
            cx.qv("/cylinder/kinetostatics/R_BY", 1.0, "u_n")?,
        ),
        (
            crate::notation::notation("R_32"),
            cx.qv("/cylinder/kinetostatics/R_32", 1.0, "u_n")?,
        ),
        (
            crate::notation::notation("M_32"),
            cx.qv("/cylinder/kinetostatics/M_32", 1.0, "u_nm")?,
        ),
        (
            crate::notation::notation("R_DX"),
            cx.qv("/cylinder/kinetostatics/R_DX", 1.0, "u_n")?,
        ),
        (
            crate::notation::notation("R_DY"),
            cx.qv("/cylinder/kinetostatics/R_DY", 1.0, "u_n")?,
        ),
        (cx.w("cy_q_fur")?, cx.qv("/cylinder/kinetostatics/F_balancing", 1.0, "u_n")?),
        (cx.w("cy_q_fdv_at")?, cx.qv("/cylinder/kinetostatics/F_control", 1.0, "u_n")?),
    ];
    results.push(cx.quantities("cy_tab_kinetostatics", kin)?);
    let mut conclusions = Vec::new();
    match cx.s("/cylinder/end/reached") {
        Some("asymptotically") => match cx.opt("/cylinder/end/time_constant") {
            Some(tau) => conclusions.push(cx.para("cy_conclusion_asymptotic", &[cx.q(tau, "cy_u_s")?])?),
            None => conclusions.push(cx.para("cy_conclusion_asymptotic_slow", &[])?),
        },
        _ => conclusions.push(cx.para("cy_conclusion_finite", &[cx.qv("/cylinder/end/time", 1.0, "cy_u_s")?])?),
    }
    conclusions.push(cx.para(
        "cy_conclusion_check",
        &[
            cx.qv("/cylinder/kinetostatics/F_balancing", 1.0, "u_n")?,
            cx.qv("/cylinder/kinetostatics/F_control", 1.0, "u_n")?,
        ],
    )?);
    Ok(Some(four_parts(cx, "cy_sec", statement, formulas, results, conclusions)?))
}
