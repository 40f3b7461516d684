//! Section "the unsteady single stroke" (неустановившееся движение за
//! один цикл, the textbook's П4): the machine driven through one cycle by
//! an induction motor by Kloss's formula, the cycle time, the motor's
//! breakdown speed crossed, and the constant-moment model by the energy
//! method beside it. Present when the report's dynamics is a single stroke.

use serde_json::Value;

use super::context::{Ctx, formula, four_parts, num};
use crate::error::NoteError;
use crate::model::{Block, Section};

/// The section, if the report's dynamics is a single stroke.
pub(crate) fn section(cx: &Ctx) -> Result<Option<Section>, NoteError> {
    if cx.s("/dynamics/motion") != Some("single-stroke") {
        return Ok(None);
    }
    let tau = cx.v("/dynamics/time_constant")?;
    let mut assumptions = vec![
        cx.w("assume_rigid")?.into(),
        cx.w("assume_friction")?.into(),
        cx.w("st_assume_clutch")?.into(),
    ];
    if tau == 0.0 {
        assumptions.push(cx.w("st_assume_static")?.into());
    }
    let statement = vec![
        Block::List(assumptions),
        cx.quantities(
            "st_tab_given",
            vec![
                (
                    cx.w("st_q_n0")?,
                    cx.q(cx.v("/dynamics/motor/synchronous_speed")? / std::f64::consts::TAU, "st_u_rev_s")?,
                ),
                (
                    cx.w("st_q_nk")?,
                    cx.q(cx.v("/dynamics/motor/breakdown_speed")? / std::f64::consts::TAU, "st_u_rev_s")?,
                ),
                (cx.w("st_q_mk")?, cx.qv("/dynamics/motor/breakdown_torque", 1.0, "u_nm")?),
                (cx.w("st_q_ratio")?, cx.qv("/dynamics/motor/ratio", 1.0, "")?),
                (cx.w("st_q_inertia")?, cx.qv("/dynamics/inertia_constant", 1.0, "u_kgm2")?),
                (cx.w("st_q_start")?, cx.qv("/dynamics/start_speed", 1.0, "u_rad_s")?),
            ],
        )?,
        cx.para("st_sought", &[])?,
    ];
    // the constant driving moment's symbol in the note's language (M_прДВ,
    // M_звДВ, M_d)
    let md2 = cx.sym("sym_st_md2")?;
    let mut formulas = vec![
        cx.para("st_f_kloss", &[])?,
        formula(&format!(
            "M(S) = (2 M_K S S_K) / (S^2 + S_K^2), quad S = 1 - n / n_0, quad S_K = 1 - n_K / n_0, quad {md2} = u M(u omega / (2 pi))"
        )),
        cx.para("st_f_motion", &[])?,
        formula(&format!(
            "(dif phi) / (dif t) = omega, quad (dif omega) / (dif t) = ({md2}(omega) + M_c (phi) - 1/2 I'_\"II\"(phi) omega^2) / (I_I + I_\"II\"(phi))"
        )),
    ];
    if tau > 0.0 {
        formulas.push(cx.para("st_f_dynamic", &[cx.q(tau, "st_u_s")?])?);
        formulas.push(formula(&format!(
            "tau (dif M) / (dif t) + M = {} (omega)",
            cx.sym("sym_st_static")?
        )));
    }
    formulas.push(cx.para("st_f_energy", &[])?);
    formulas.push(formula(&format!(
        "A_Sigma (phi) = {md2} phi + integral_0^phi M_c dif phi, quad omega(phi) = sqrt((2 A_Sigma (phi) + omega_0^2 I_Sigma (0)) / (I_Sigma (phi))), quad t(phi) = integral_0^phi (dif phi) / omega"
    )));
    let mut given = vec![
        (cx.w("st_q_cycle_time")?, cx.qv("/dynamics/motor_driven/cycle_time", 1.0, "st_u_s")?),
        (cx.w("st_q_omega_end")?, cx.qv("/dynamics/motor_driven/omega_end", 1.0, "u_rad_s")?),
        (cx.w("st_q_omega_min")?, cx.qv("/dynamics/motor_driven/omega_min", 1.0, "u_rad_s")?),
        (
            cx.w("st_q_omega_k")?,
            cx.qv("/dynamics/motor/crank_breakdown_speed", 1.0, "u_rad_s")?,
        ),
        (
            cx.w("st_q_motor_work")?,
            cx.qv("/dynamics/motor_driven/energy_balance/motor_work", 1.0, "u_j")?,
        ),
        (
            cx.w("st_q_loads_work")?,
            cx.qv("/dynamics/motor_driven/energy_balance/loads_work", 1.0, "u_j")?,
        ),
    ];
    if cx.opt("/dynamics/motor_driven/check/cycle_time").is_some() {
        given.push((
            cx.w("st_q_check_time")?,
            cx.qv("/dynamics/motor_driven/check/cycle_time", 1.0, "st_u_s")?,
        ));
    }
    given.extend([
        (cx.w("st_q_md2")?, cx.qv("/dynamics/constant_moment/driving_moment", 1.0, "u_nm")?),
        (cx.w("st_q_a_end")?, cx.qv("/dynamics/constant_moment/work_end", 1.0, "u_j")?),
        (
            cx.w("st_q_omega_end2")?,
            cx.qv("/dynamics/constant_moment/omega_end", 1.0, "u_rad_s")?,
        ),
        (cx.w("st_q_time_end2")?, cx.qv("/dynamics/constant_moment/time_end", 1.0, "st_u_s")?),
    ]);
    if cx.report.pointer("/dynamics/constant_moment/design").is_some_and(|v| !v.is_null()) {
        given.push((
            cx.w("st_q_eps_f2")?,
            cx.qv("/dynamics/constant_moment/design/epsilon", 1.0, "u_rad_s2")?,
        ));
        given.push((
            cx.w("st_q_travel_f")?,
            cx.qv("/dynamics/motor_driven/design/travel", 1.0, "st_u_m")?,
        ));
    }
    let mut results = vec![cx.quantities("st_tab_results", given)?];
    // both models every 30° (the table's rows)
    let arr = |p: &str| -> Vec<f64> {
        cx.report
            .pointer(p)
            .and_then(Value::as_array)
            .map(|a| a.iter().filter_map(Value::as_f64).collect())
            .unwrap_or_default()
    };
    let phi = arr("/dynamics/motor_driven/phi");
    let cols = [
        arr("/dynamics/motor_driven/moment_loads"),
        arr("/dynamics/motor_driven/inertia_total"),
        arr("/dynamics/motor_driven/omega"),
        arr("/dynamics/motor_driven/epsilon"),
        arr("/dynamics/motor_driven/time"),
        arr("/dynamics/constant_moment/omega"),
        arr("/dynamics/constant_moment/time"),
    ];
    let mut rows = Vec::new();
    for (k, p) in phi.iter().enumerate() {
        let deg = p.to_degrees();
        if (deg / 30.0 - (deg / 30.0).round()).abs() > 1e-6 {
            continue;
        }
        let mut row = vec![num(deg)];
        // the rounding noise of an exact zero (M_c at the dead positions)
        // relative to the column's largest value prints as 0
        row.extend(cols.iter().map(|c| {
            let big = c.iter().fold(0.0f64, |a, x| a.max(x.abs()));
            let v = c.get(k).copied().unwrap_or(0.0);
            num(if v.abs() < 1e-9 * big { 0.0 } else { v })
        }));
        rows.push(row);
    }
    results.push(cx.table(
        "st_tab_cycle",
        &[
            ("col_phi", "u_deg"),
            ("col_mc", "u_nm"),
            ("st_col_inertia", "u_kgm2"),
            ("st_col_omega1", "u_rad_s"),
            ("st_col_eps1", "u_rad_s2"),
            ("st_col_t1", "st_u_s"),
            ("st_col_omega2", "u_rad_s"),
            ("st_col_t2", "st_u_s"),
        ],
        rows,
    )?);
    for (path, key) in [
        ("dynamics/stroke-moments.svg", "st_fig_moments"),
        ("dynamics/stroke-omega.svg", "st_fig_omega"),
        ("dynamics/stroke-time.svg", "st_fig_time"),
        ("dynamics/stroke-epsilon.svg", "st_fig_epsilon"),
    ] {
        if let Some(f) = cx.figure(path, key)? {
            results.push(f);
        }
    }
    let crossing = cx
        .report
        .pointer("/dynamics/motor_driven/breakdown_crossings")
        .and_then(Value::as_array)
        .and_then(|a| a.iter().find(|c| c.get("direction").and_then(Value::as_str) == Some("below")))
        .and_then(|c| Some((c.get("phi")?.as_f64()?, c.get("time")?.as_f64()?)));
    let mut conclusions = vec![cx.para(
        "st_conclusion",
        &[
            cx.qv("/dynamics/motor_driven/cycle_time", 1.0, "st_u_s")?,
            cx.qv("/dynamics/constant_moment/time_end", 1.0, "st_u_s")?,
        ],
    )?];
    conclusions.push(match crossing {
        Some((p, t)) => cx.para("st_conclusion_breakdown", &[cx.q(p.to_degrees(), "u_deg")?, cx.q(t, "st_u_s")?])?,
        None => cx.para("st_conclusion_no_breakdown", &[])?,
    });
    Ok(Some(four_parts(cx, "st_sec", statement, formulas, results, conclusions)?))
}
