//! Section "planetary train" (синтез планетарной передачи): the tooth
//! numbers for the ratio and the number of planets under the conditions of
//! coaxiality, assembly and neighbourhood; the velocity picture.

use serde_json::Value;

use super::context::{Ctx, formula, four_parts};
use crate::calc::{self, Calculation, Expr, Quantity};
use crate::error::NoteError;
use crate::model::{Block, Section};

/// The section, if the report has `planetary`.
pub(crate) fn section(cx: &Ctx) -> Result<Option<Section>, NoteError> {
    let Some(pl) = cx.report.get("planetary") else { return Ok(None) };
    let scheme = pl.get("scheme").and_then(Value::as_str).unwrap_or("");
    let statement = vec![
        Block::List(vec![cx.w("assume_rigid")?.into(), cx.w("assume_pl_equal")?.into()]),
        cx.para(
            "pl_given",
            &[
                cx.qv("/planetary/request/ratio", 1.0, "")?,
                format!("{}", cx.v("/planetary/request/planets")?),
                cx.qv("/planetary/request/module", 1000.0, "u_mm")?,
            ],
        )?,
        cx.para("pl_method", &[])?,
        cx.para("pl_sought", &[])?,
    ];
    let mut formulas = vec![
        cx.para("pl_f_willis", &[])?,
        formula("u_(1 H) = 1 - u^((H))_(1 3)"),
        cx.para("where_willis", &[])?,
    ];
    if scheme == "sun-planet-ring" {
        formulas.extend([
            cx.para("pl_f_spr", &[])?,
            formula(
                "u_(1 H) = 1 + z_3 / z_1, quad z_1 + 2 z_2 = z_3, \\ (z_1 + z_3) / k in NN, quad (z_1 + z_2) sin(pi / k) > z_2 + 2 h_a^*",
            ),
            cx.para("where_spr", &[])?,
        ]);
    }
    let z: Vec<String> = pl
        .pointer("/best/z")
        .and_then(Value::as_array)
        .map(|a| a.iter().map(|v| v.to_string()).collect())
        .unwrap_or_default();
    let order: Vec<String> = pl
        .get("z_order")
        .and_then(Value::as_array)
        .map(|a| a.iter().filter_map(Value::as_str).map(str::to_string).collect())
        .unwrap_or_default();
    // the teeth's names as the course writes them, z₁, z₂′ (the report's
    // `z1`, `z2'`: a letter, the wheel's digits, primes)
    let z_name = |n: &str| -> String {
        let mut ch = n.chars();
        match (ch.next(), ch.next()) {
            (Some(l), Some(d)) if l.is_ascii_alphabetic() && d.is_ascii_digit() && n.is_ascii() => {
                crate::notation::notation(&format!("{l}_{}", &n[1..]))
            }
            _ => n.to_string(),
        }
    };
    let mut q: Vec<(String, String)> = order.iter().zip(&z).map(|(n, v)| (z_name(n), v.clone())).collect();
    q.push((cx.w("q_ratio_reached")?, cx.qv("/planetary/best/ratio", 1.0, "")?));
    if let Some(c) = cx.opt("/planetary/best/centre_distance") {
        q.push((cx.w("q_aw")?, cx.q(c * 1000.0, "u_mm")?));
    }
    if let Some(r) = cx.opt("/planetary/best/radial_size_m") {
        q.push((cx.w("q_radial_size")?, cx.q(r * 1000.0, "u_mm")?));
    }
    if let Some(e) = cx.opt("/planetary/best/efficiency/value") {
        q.push((cx.w("q_efficiency")?, cx.q(e, "")?));
    }
    if let Some(w) = cx.opt("/planetary/best/velocity_picture/omega_carrier") {
        q.push((cx.w("q_omega_carrier")?, cx.q(w, "u_rad_s")?));
    }
    let mut results = Vec::new();
    // the worked ratio of the single-row train with the chosen teeth
    if let (true, Some(zs), Some(u)) = (
        scheme == "sun-planet-ring",
        pl.pointer("/best/z").and_then(Value::as_array),
        cx.opt("/planetary/best/ratio"),
    ) && let (Some(z1), Some(z3)) = (zs.first().and_then(Value::as_f64), zs.get(2).and_then(Value::as_f64))
    {
        results.push(cx.para("calc_willis", &[])?);
        results.push(Block::Calculation(Calculation::new(
            Quantity::new("u_(1 H)", u, ""),
            Expr::Sum(vec![calc::int(1), calc::div(calc::count("z_3", z3), calc::count("z_1", z1))]),
        )));
    }
    results.push(cx.quantities("tab_planetary", q)?);
    if let Some(f) = cx.figure("planetary/planetary.svg", "fig_planetary")? {
        results.push(f);
    }
    let conclusions = vec![cx.para(
        "pl_conclusion",
        &[
            z.join(", "),
            cx.qv("/planetary/best/ratio", 1.0, "")?,
            cx.qv("/planetary/request/ratio", 1.0, "")?,
            format!("{}", cx.v("/planetary/candidates_total")?),
        ],
    )?];
    Ok(Some(four_parts(cx, "sec_planetary", statement, formulas, results, conclusions)?))
}
