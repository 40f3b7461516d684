//! Section "kinetostatics" (кинетостатический анализ): inertia loads,
//! reactions group by group, the balancing torque and its check by
//! Zhukovsky's lever, the strength of a link.

use serde_json::Value;

use super::context::{Ctx, formula, four_parts, num, text};
use super::linkage::{crank, math_name};
use crate::calc::{self, Calculation, Expr, Quantity};
use crate::error::NoteError;
use crate::model::{Block, Cell, Section};

/// The statement's sentence on the crank's motion: uniform at the nominal
/// ω1, or (the task's `crank_motion = "dynamics"`) the true ω1 and ε1 of
/// the machine with its flywheel at the position analysed.
fn given(cx: &Ctx, phi: &str) -> Result<Block, NoteError> {
    if cx.s("/forces/crank_motion") == Some("dynamics")
        && let (Some(w), Some(e)) = (cx.opt("/forces/detail/omega1"), cx.opt("/forces/detail/epsilon1"))
    {
        return cx.para("fo_given_dynamics", &[phi.to_string(), cx.q(w, "u_rad_s")?, cx.q(e, "u_rad_s2")?]);
    }
    cx.para("fo_given", &[cx.qv("/forces/omega1", 1.0, "u_rad_s")?, phi.to_string()])
}

/// A reaction's or couple's name of the task (`R30`, `M50`) as the course
/// writes it, its links' numbers lowered (R₃₀) and marked as math; any
/// other name stays literal.
fn reaction_symbol(name: &str) -> String {
    let mut chars = name.chars();
    match (chars.next(), chars.as_str()) {
        (Some(c @ ('R' | 'M')), digits) if !digits.is_empty() && digits.chars().all(|d| d.is_ascii_digit()) => {
            crate::notation::notation(&format!("{c}_{digits}"))
        }
        _ => crate::notation::strip(name),
    }
}

/// The section, if the report has `forces`.
pub(crate) fn section(cx: &Ctx) -> Result<Option<Section>, NoteError> {
    let Some(fo) = cx.report.get("forces") else { return Ok(None) };
    let phi = cx.deg("/forces/detail/phi")?;
    let statement = vec![
        Block::List(vec![
            cx.w("assume_rigid")?.into(),
            cx.w("assume_pairs")?.into(),
            cx.w("assume_friction")?.into(),
        ]),
        given(cx, &phi)?,
        cx.para("fo_method", &[])?,
        cx.para("fo_sought", &[])?,
    ];
    let formulas = vec![
        cx.para("fo_f_inertia", &[])?,
        formula(&format!(
            "arrow(F)_{0} = -m arrow(a)_S, quad M_{0} = -J_S epsilon",
            cx.sym("sym_inertia_sub")?
        )),
        cx.para("where_inertia", &[])?,
        cx.para("fo_f_group", &[])?,
        formula("sum arrow(F) = 0, quad sum M_C = 0"),
        cx.para("where_group", &[])?,
        cx.para("fo_f_balancing", &[])?,
        formula(&format!("{} = {} l_1", cx.sym("sym_mb")?, cx.sym("sym_pb")?)),
        cx.para("where_balancing", &[])?,
        cx.para("fo_f_zhukovsky", &[])?,
        formula(&format!(
            "{} omega_1 = -(sum_i arrow(F)_i dot arrow(v)_i + sum_i M_i omega_i)",
            cx.sym("sym_mzh")?
        )),
        cx.para("where_zhukovsky", &[])?,
    ];
    let mut results = Vec::new();
    let mut rows = Vec::new();
    if let Some(loads) = fo.pointer("/detail/loads").and_then(Value::as_object) {
        for (name, l) in loads {
            let f = l.get("inertia_force").and_then(Value::as_array);
            let fm = f
                .map(|a| {
                    let x = a.first().and_then(Value::as_f64).unwrap_or(0.0);
                    let y = a.get(1).and_then(Value::as_f64).unwrap_or(0.0);
                    x.hypot(y)
                })
                .unwrap_or(0.0);
            let m = l.get("inertia_moment").and_then(Value::as_f64).unwrap_or(0.0);
            rows.push(vec![text(cx.fill("link_n", std::slice::from_ref(name))?), num(fm), num(m)]);
        }
    }
    results.push(cx.para("fo_results_at", std::slice::from_ref(&phi))?);
    results.push(cx.table(
        "tab_inertia",
        &[("col_link", ""), ("col_inertia_force", "u_n"), ("col_inertia_moment", "u_nm")],
        rows,
    )?);
    let mut rows = Vec::new();
    let (mut force_case, mut force_row) = (None, None);
    if let Some(rs) = fo.pointer("/detail/reactions").and_then(Value::as_array) {
        for r in rs {
            let g = |k: &str| r.get(k).and_then(Value::as_f64).unwrap_or(0.0);
            let name = |k: &str| -> Result<String, NoteError> {
                let v = r.get(k).and_then(Value::as_str).unwrap_or("");
                if v == "frame" { cx.w("frame_short") } else { Ok(v.to_string()) }
            };
            let pair = r.get("pair").and_then(Value::as_str).unwrap_or("");
            rows.push(vec![
                text(pair),
                text(format!("{}→{}", name("from")?, name("on")?)),
                num(g("magnitude")),
                num(g("normal")),
                num(g("tangential")),
            ]);
            // the frame's reaction on the crank when the balancing force
            // holds it (the input link's force plan draws that case): a row
            // of its own under the torque case's
            if r.get("from").and_then(Value::as_str) == Some("frame")
                && crank(cx).is_some_and(|(axis, _, _)| axis == pair)
                && let Some(v) = fo.pointer("/detail/frame_reaction_with_balancing_force").and_then(Value::as_array)
            {
                let c = |i: usize| v.get(i).and_then(Value::as_f64).unwrap_or(0.0);
                if c(0).hypot(c(1)) > 0.0 {
                    force_case = Some(pair.to_string());
                    force_row = Some(vec![
                        text(format!("{pair} ({})", cx.w("with_pb")?)),
                        text(format!("{}→{}", name("from")?, name("on")?)),
                        num(c(0).hypot(c(1))),
                        Cell::Empty,
                        Cell::Empty,
                    ]);
                }
            }
        }
    }
    rows.extend(force_row);
    results.push(cx.table(
        "tab_reactions",
        &[
            ("col_pair", ""),
            ("col_from_on", ""),
            ("col_reaction", "u_n"),
            ("col_reaction_n", "u_n"),
            ("col_reaction_t", "u_n"),
        ],
        rows,
    )?);
    if let Some(pair) = force_case {
        results.push(cx.para("fo_reaction_cases", &[pair])?);
    }
    let mb = cx.v("/forces/detail/balancing_moment")?;
    let mzh = cx.v("/forces/detail/zhukovsky_moment")?;
    results.push(cx.quantities(
        "tab_balancing",
        vec![
            (cx.w("q_mb")?, cx.q(mb, "u_nm")?),
            (cx.w("q_pb")?, cx.qv("/forces/detail/balancing_force", 1.0, "u_n")?),
            (cx.w("q_mzh")?, cx.q(mzh, "u_nm")?),
        ],
    )?);
    results.extend(worked(cx, mb, mzh)?);
    for (path, key) in [
        ("forces/group-1.svg", "fig_force_group"),
        ("forces/input-link.svg", "fig_input_link"),
        ("forces/zhukovsky-lever.svg", "fig_zhukovsky"),
        ("forces/balancing-torque.svg", "fig_balancing_torque"),
        ("forces/strength-M.svg", "fig_strength_m"),
    ] {
        if let Some(f) = cx.figure(path, key)? {
            results.push(f);
        }
    }
    // the reactions over the cycle the task asked to draw (П3: R50, M50, R54; the hodographs of R21)
    if let Some(rc) = fo.get("reaction_cycle") {
        let names = |k: &str| -> Vec<String> {
            rc.get(k)
                .and_then(Value::as_array)
                .map(|v| v.iter().filter_map(|x| x.as_str().map(str::to_string)).collect())
                .unwrap_or_default()
        };
        let mut figs: Vec<(String, &str, String)> = Vec::new();
        for n in names("diagrams") {
            // a reaction R50 or a guide's couple M50
            let key = if n.starts_with('M') {
                "fig_couple_over_cycle"
            } else {
                "fig_reaction_over_cycle"
            };
            figs.push((format!("forces/reaction-{n}.svg"), key, n));
        }
        for n in names("hodographs") {
            figs.push((format!("forces/hodograph-{n}.svg"), "fig_hodograph", n.clone()));
            figs.push((format!("forces/hodograph-{n}-polar.svg"), "fig_hodograph_polar", n));
        }
        for (path, key, name) in figs {
            if let Some(Block::Figure {
                caption,
                svg,
                width_mm,
                label,
            }) = cx.figure(&path, key)?
            {
                let name = reaction_symbol(&name);
                let caption = if caption.contains("{1}") {
                    caption.replace("{1}", &name)
                } else {
                    format!("{caption} {name}")
                };
                results.push(Block::Figure {
                    caption,
                    svg,
                    width_mm,
                    label,
                });
            }
        }
    }
    let strength = fo.get("strength").filter(|s| !s.is_null());
    if strength.is_some() {
        results.push(cx.quantities(
            "tab_strength",
            vec![
                (cx.w("q_allowed_stress")?, cx.qv("/forces/strength/allowed_stress", 1e-6, "u_mpa")?),
                (cx.w("q_round_d")?, cx.qv("/forces/strength/round/d", 1000.0, "u_mm")?),
                (cx.w("q_rect_b")?, cx.qv("/forces/strength/rectangle/b", 1000.0, "u_mm")?),
                (cx.w("q_rect_h")?, cx.qv("/forces/strength/rectangle/h", 1000.0, "u_mm")?),
            ],
        )?);
    }
    let mut conclusions = vec![cx.para(
        "fo_conclusion",
        &[
            phi,
            cx.q(mb, "u_nm")?,
            cx.q(mzh, "u_nm")?,
            // a relative difference under 10⁻⁹ is the rounding noise of
            // an exact agreement: printed as 0 %, not as 1,959·10⁻¹⁴
            cx.relative(cx.v("/forces/detail/relative_difference")?)?,
            cx.relative(cx.v("/forces/max_relative_difference")?)?,
        ],
    )?];
    if let Some(cycle) = fo.get("cycle").and_then(Value::as_array) {
        let m: Vec<f64> = cycle
            .iter()
            .filter_map(|c| c.get("balancing_moment").and_then(Value::as_f64))
            .collect();
        if !m.is_empty() {
            let lo = m.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = m.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            conclusions.push(cx.para("fo_conclusion_cycle", &[cx.q(lo, "u_nm")?, cx.q(hi, "u_nm")?])?);
        }
    }
    if strength.is_some() {
        conclusions.push(cx.para(
            "fo_conclusion_strength",
            &[
                cx.s("/forces/strength/link").unwrap_or("").to_string(),
                cx.qv("/forces/strength/round/d", 1000.0, "u_mm")?,
            ],
        )?);
    }
    Ok(Some(four_parts(cx, "sec_forces", statement, formulas, results, conclusions)?))
}

/// The worked balancing torque from the balancing force and its check by
/// Zhukovsky's lever as the sum of the powers of the loads (the lever's
/// forces of the report, each at its point's velocity: the lever's image is
/// the velocity turned by +90°, `image = (−v_y, v_x)`; a slider's gas force
/// is among them, `Fc<link>`).
fn worked(cx: &Ctx, mb: f64, mzh: f64) -> Result<Vec<Block>, NoteError> {
    let mut out = Vec::new();
    let (Some((_, _, l)), Some(pb)) = (crank(cx), cx.opt("/forces/detail/balancing_force")) else {
        return Ok(out);
    };
    let unit_nm = cx.w("u_nm")?;
    out.push(cx.para("calc_mb", &[])?);
    out.push(Block::Calculation(Calculation::new(
        Quantity::new(&cx.sym("sym_mb")?, mb, &unit_nm),
        Expr::Mul(vec![
            calc::q(&cx.sym("sym_pb")?, pb, ""),
            // l_1 as in formula (3.3) and its where-line: the crank's length
            calc::q("l_1", l, ""),
        ]),
    )));
    let Some(lever) = cx.report.pointer("/forces/lever").and_then(Value::as_array) else {
        return Ok(out);
    };
    // the power of each load: forces one by one, a couple's two forces as M·ω of its link
    let mut terms: Vec<(String, f64)> = Vec::new();
    for e in lever {
        let label = e.get("label").and_then(Value::as_str).unwrap_or("");
        let c = |k: &str, i: usize| e.get(k).and_then(|a| a.get(i)).and_then(Value::as_f64).unwrap_or(0.0);
        let power = c("force", 0) * c("image", 1) - c("force", 1) * c("image", 0);
        let symbol = if label == "Pb" {
            continue;
        } else if let Some(link) = label.strip_prefix("Fc") {
            // a slider load (a gas force on a piston), at its point
            format!("arrow(F)_(c {0}) dot arrow(v)_(c {0})", math_name(link))
        } else if let Some(link) = label.strip_prefix('M').map(|r| r.trim_end_matches('\'')) {
            format!("M_({0}) omega_({0})", math_name(link))
        } else if let Some((f, _)) = label.strip_prefix("Fu").and_then(|r| r.split_once('+')) {
            format!("arrow(F)_({0}) dot arrow(v)_(S {0})", math_name(f))
        } else {
            format!("arrow(F)_({0}) dot arrow(v)_({0})", math_name(label.trim_start_matches('F')))
        };
        match terms.iter_mut().find(|(s, _)| *s == symbol) {
            Some(t) => t.1 += power,
            None => terms.push((symbol, power)),
        }
    }
    if terms.is_empty() {
        return Ok(out);
    }
    // a power that is the rounding noise of zero (a centripetal force on a crank turning evenly) is 0
    let largest = terms.iter().fold(0.0_f64, |m, t| m.max(t.1.abs()));
    for t in &mut terms {
        if t.1.abs() < 1e-9 * largest {
            t.1 = 0.0;
        }
    }
    let total: f64 = terms.iter().map(|t| t.1).sum();
    let unit_w = cx.w("u_w")?;
    out.push(cx.para("calc_power", &[])?);
    out.push(Block::Calculation(Calculation::new(
        Quantity::new("P", total, &unit_w),
        Expr::Terms {
            symbol: "sum_i arrow(F)_i dot arrow(v)_i + sum_i M_i omega_i".into(),
            terms: terms.iter().map(|(s, p)| calc::q(s, *p, "")).collect(),
        },
    )));
    out.push(Block::Calculation(Calculation::new(
        Quantity::new(&cx.sym("sym_mzh")?, mzh, &unit_nm),
        calc::neg(calc::div(
            calc::q("P", total, ""),
            calc::q("omega_1", cx.v("/forces/detail/omega1").or_else(|_| cx.v("/forces/omega1"))?, ""),
        )),
    )));
    Ok(out)
}
