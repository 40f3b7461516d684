//! Section "gear pair" (синтез эвольвентного зацепления): the geometry of
//! the profile-shifted pair, its quality checks, the meshing drawing, the
//! blocking contour and the specific sliding.

use serde_json::Value;

use super::assignment::as_given;
use super::context::{Ctx, formula, four_parts, num, text};
use crate::calc::{self, Calculation, Expr, Quantity};
use crate::error::NoteError;
use crate::model::{Block, Section};

/// The task's table of the gear pair's givens.
const GEAR: &[&str] = &["gear"];

/// The given values of the pair as (name, value) rows.
pub(crate) fn given_rows(cx: &Ctx) -> Result<Vec<(String, String)>, NoteError> {
    let rows = vec![
        (cx.w("q_z1")?, format!("{}", cx.v("/gear/z1")?)),
        (cx.w("q_z2")?, format!("{}", cx.v("/gear/z2")?)),
        (cx.w("q_module")?, as_given(cx, GEAR, cx.v("/gear/m")? * 1000.0, "u_mm")?),
        (cx.w("q_x1")?, as_given(cx, GEAR, cx.v("/gear/x1")?, "")?),
        (cx.w("q_x2")?, as_given(cx, GEAR, cx.v("/gear/x2")?, "")?),
        (
            cx.w("q_alpha")?,
            as_given(cx, GEAR, cx.v("/gear/rack/alpha")?.to_degrees(), "u_deg")?,
        ),
        (cx.w("q_ha")?, as_given(cx, GEAR, cx.v("/gear/rack/ha")?, "")?),
        (cx.w("q_c")?, as_given(cx, GEAR, cx.v("/gear/rack/c")?, "")?),
    ];
    // a centre distance the task gives (a_w = 560 мм)
    let mut rows = rows;
    if cx.task.get("gear").and_then(|g| g.get("aw")).is_some() {
        rows.push((cx.w("q_aw")?, as_given(cx, GEAR, cx.v("/gear/aw")? * 1000.0, "u_mm")?));
    }
    // the least tip thickness where the task gives it, a share of the
    // module as written and in mm (s_a min = 0,3·m = 1,5 мм; ГОСТ 16532-70)
    if let Some(given) = super::assignment::task_given(cx, "gear", "sa_min", "")? {
        let m = cx.v("/gear/m")? * 1000.0;
        let value = match super::assignment::task_share(cx, "gear", "sa_min") {
            Some(share) if given.contains('%') => format!("{given} ({})", cx.q(share * m, "u_mm")?),
            Some(share) => format!(
                "{given}·{} = {}",
                crate::notation::notation_with("m", true),
                cx.q(share * m, "u_mm")?
            ),
            None => given,
        };
        rows.push((cx.w("q_sa_min")?, value));
    }
    Ok(rows)
}

/// The section, if the report has `gear`.
pub(crate) fn section(cx: &Ctx) -> Result<Option<Section>, NoteError> {
    let Some(g) = cx.report.get("gear") else { return Ok(None) };
    let statement = vec![
        cx.para(
            "ge_given",
            &[
                format!("{}", cx.v("/gear/z1")?),
                format!("{}", cx.v("/gear/z2")?),
                cx.given("/gear/m", 1000.0, "u_mm")?,
                cx.given("/gear/x1", 1.0, "")?,
                cx.given("/gear/x2", 1.0, "")?,
            ],
        )?,
        cx.para("ge_method", &[])?,
        cx.para("ge_sought", &[])?,
    ];
    let formulas = vec![
        cx.para("ge_f_alpha_w", &[])?,
        formula("\"inv\" alpha_w = 2 (x_1 + x_2) / (z_1 + z_2) tan alpha + \"inv\" alpha"),
        cx.para("where_gear_alpha", &[])?,
        cx.para("ge_f_aw", &[])?,
        formula("a_w = m (z_1 + z_2) / 2 dot (cos alpha) / (cos alpha_w), quad y = (a_w - a) / m, quad Delta y = x_1 + x_2 - y"),
        cx.para("where_gear_aw", &[])?,
        cx.para("ge_f_diameters", &[])?,
        formula("d = m z, quad d_b = d cos alpha, \\ d_a = d + 2 (h_a^* + x - Delta y) m, quad d_f = d - 2 (h_a^* + c^* - x) m"),
        cx.para("where_gear_d", &[])?,
        cx.para("ge_f_eps", &[])?,
        formula("epsilon_alpha = (z_1 (tan alpha_(a 1) - tan alpha_w) + z_2 (tan alpha_(a 2) - tan alpha_w)) / (2 pi)"),
        cx.para("where_gear_eps", &[])?,
    ];
    let mut formulas = formulas;
    formulas.extend(worked(cx)?);
    let mm = |p: &str| -> Result<f64, NoteError> { Ok(cx.v(p)? * 1000.0) };
    let rows = vec![
        vec![text(cx.w("q_d")?), num(mm("/gear/d1")?), num(mm("/gear/d2")?)],
        vec![text(cx.w("q_db")?), num(mm("/gear/db1")?), num(mm("/gear/db2")?)],
        vec![text(cx.w("q_dw")?), num(mm("/gear/dw1")?), num(mm("/gear/dw2")?)],
        vec![text(cx.w("q_da")?), num(mm("/gear/da1")?), num(mm("/gear/da2")?)],
        vec![text(cx.w("q_df")?), num(mm("/gear/df1")?), num(mm("/gear/df2")?)],
        vec![text(cx.w("q_s")?), num(mm("/gear/s1")?), num(mm("/gear/s2")?)],
        vec![text(cx.w("q_sa")?), num(mm("/gear/sa1")?), num(mm("/gear/sa2")?)],
    ];
    let mut results = vec![
        cx.quantities(
            "tab_gear_pair",
            vec![
                (cx.w("q_a")?, cx.qv("/gear/a", 1000.0, "u_mm")?),
                (cx.w("q_aw")?, cx.qv("/gear/aw", 1000.0, "u_mm")?),
                (cx.w("q_alpha_w")?, cx.deg("/gear/alpha_w")?),
                (cx.w("q_y")?, cx.qv("/gear/y", 1.0, "")?),
                (cx.w("q_dy")?, cx.qv("/gear/dy", 1.0, "")?),
                (cx.w("q_eps")?, cx.qv("/gear/eps_alpha", 1.0, "")?),
            ],
        )?,
        cx.table(
            "tab_gear_wheels",
            &[("col_quantity", ""), ("col_wheel1", "u_mm"), ("col_wheel2", "u_mm")],
            rows,
        )?,
    ];
    let mut rows = Vec::new();
    let mut failed = Vec::new();
    if let Some(checks) = g.get("checks").and_then(Value::as_object) {
        for (k, c) in checks {
            let pass = c.get("pass").and_then(Value::as_bool).unwrap_or(false);
            let name = cx.w(&format!("check_{k}")).unwrap_or_else(|_| k.clone());
            if !pass {
                failed.push(name.clone());
            }
            let (scale, digits_mm) = if k.starts_with("interference") || k.starts_with("pointing") {
                (1000.0, true)
            } else {
                (1.0, false)
            };
            let v = c.get("value").and_then(Value::as_f64).unwrap_or(0.0) * scale;
            let l = c.get("limit").and_then(Value::as_f64).unwrap_or(0.0) * scale;
            let unit = if digits_mm { "u_mm" } else { "" };
            rows.push(vec![
                text(name),
                text(cx.q(v, unit)?),
                text(cx.q(l, unit)?),
                text(cx.w(if pass { "check_pass" } else { "check_fail" })?),
            ]);
        }
    }
    results.push(cx.table(
        "tab_gear_checks",
        &[("col_check", ""), ("col_value", ""), ("col_limit", ""), ("col_verdict", "")],
        rows,
    )?);
    for (path, key) in [
        ("gear/mesh.svg", "fig_gear_mesh"),
        ("gear/contour.svg", "fig_gear_contour"),
        ("gear/sliding.svg", "fig_gear_sliding"),
    ] {
        if let Some(f) = cx.figure(path, key)? {
            results.push(f);
        }
    }
    let eps = cx.qv("/gear/eps_alpha", 1.0, "")?;
    let conclusions = vec![if failed.is_empty() {
        cx.para("ge_conclusion_pass", &[eps, cx.qv("/gear/aw", 1000.0, "u_mm")?])?
    } else {
        cx.para("ge_conclusion_fail", &[failed.join("; "), eps])?
    }];
    Ok(Some(four_parts(cx, "sec_gear", statement, formulas, results, conclusions)?))
}

/// The worked angle of engagement and centre distance with the run's numbers.
fn worked(cx: &Ctx) -> Result<Vec<Block>, NoteError> {
    let (Some(alpha), Some(aw_angle)) = (cx.opt("/gear/rack/alpha"), cx.opt("/gear/alpha_w")) else {
        return Ok(Vec::new());
    };
    if cx.s("/gear/kind") != Some("external") {
        return Ok(Vec::new());
    }
    let (z1, z2) = (cx.v("/gear/z1")?, cx.v("/gear/z2")?);
    let (x1, x2) = (cx.v("/gear/x1")?, cx.v("/gear/x2")?);
    let m = cx.v("/gear/m")? * 1000.0;
    let al = || calc::q("alpha", alpha.to_degrees(), "°");
    let alw = || calc::q("alpha_w", aw_angle.to_degrees(), "°");
    let zs = || Expr::Sum(vec![calc::count("z_1", z1), calc::count("z_2", z2)]);
    let inv_w = calc::Func::Inv;
    Ok(vec![
        cx.para("calc_gear", &[])?,
        Block::Calculation(Calculation::new(
            Quantity {
                digits: 5,
                ..Quantity::new(
                    "\"inv\" alpha_w",
                    {
                        let a = aw_angle;
                        a.tan() - a
                    },
                    "",
                )
            },
            Expr::Sum(vec![
                Expr::Mul(vec![
                    calc::int(2),
                    calc::div(Expr::Sum(vec![calc::q("x_1", x1, ""), calc::q("x_2", x2, "")]), zs()),
                    calc::func(calc::Func::Tan, al()),
                ]),
                calc::func(inv_w, al()),
            ]),
        )),
        Block::Calculation(Calculation::new(
            Quantity::new("a_w", cx.v("/gear/aw")? * 1000.0, &cx.w("u_mm")?),
            Expr::Mul(vec![
                calc::div(Expr::Mul(vec![calc::q("m", m, ""), calc::paren(zs())]), calc::int(2)),
                calc::div(calc::func(calc::Func::Cos, al()), calc::func(calc::Func::Cos, alw())),
            ]),
        )),
    ])
}
