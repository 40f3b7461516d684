//! Section "dynamics of the machine" (динамика машины): the reduced moment
//! of inertia and of the forces, the driving moment, the flywheel by
//! Mertsalov's and Wittenbauer's methods and the true crank speed.

use super::context::{Ctx, formula, four_parts};
use crate::calc::{self, Calculation, Expr, Quantity};
use crate::error::NoteError;
use crate::model::{Block, Section};

/// The section, if the report has `dynamics`.
pub(crate) fn section(cx: &Ctx) -> Result<Option<Section>, NoteError> {
    // the single stroke has its own section (stroke.rs)
    if cx.report.get("dynamics").is_none() || cx.s("/dynamics/motion") == Some("single-stroke") {
        return Ok(None);
    }
    let statement = vec![
        Block::List(vec![
            cx.w("assume_rigid")?.into(),
            cx.w("assume_friction")?.into(),
            cx.w(if engine(cx) { "assume_mres_constant" } else { "assume_md_constant" })?.into(),
        ]),
        cx.para(
            "dy_given",
            &[
                cx.given("/dynamics/delta_requested", 1.0, "")?,
                cx.qv("/dynamics/omega_nominal", 1.0, "u_rad_s")?,
            ],
        )?,
        cx.para("dy_method", &[])?,
        cx.para("dy_sought", &[])?,
    ];
    let mut statement = statement;
    // the time of one turn T = 60/n1 and of the machine's cycle (two turns
    // of a four-stroke engine)
    if let (Some(t), Some(tc)) = (cx.opt("/dynamics/revolution_time"), cx.opt("/dynamics/cycle_time_nominal"))
        && t > 0.0
    {
        statement.push(cx.para(
            "dy_cycle_time",
            &[cx.q(t, "cy_u_s")?, cx.deg("/dynamics/cycle_period")?, cx.q(tc, "cy_u_s")?],
        )?);
    }
    // the summed loads repeat within the machine's cycle (П2's opposed engine)
    if let (Some(lp), Some(cp)) = (cx.opt("/dynamics/load_period"), cx.opt("/dynamics/cycle_period"))
        && lp < cp * (1.0 - 1e-9)
    {
        statement.push(cx.para(
            "dy_load_period",
            &[cx.deg("/dynamics/load_period")?, cx.deg("/dynamics/cycle_period")?],
        )?);
    }
    let formulas = vec![
        cx.para("dy_f_inertia", &[])?,
        formula("I_\"II\"(phi) = sum_(i != 1) [m_i (v_(S i) / omega_1)^2 + J_(S i) (omega_i / omega_1)^2]"),
        cx.para("where_reduced_inertia", &[])?,
        cx.para(if engine(cx) { "dy_f_moment_engine" } else { "dy_f_moment" }, &[])?,
        formula("M_c (phi) = sum_i (arrow(F)_i dot arrow(v)_i + M_i omega_i) / omega_1, quad A_c (phi) = integral_0^phi M_c dif phi"),
        cx.para(
            if engine(cx) {
                "where_reduced_moment_engine"
            } else {
                "where_reduced_moment"
            },
            &[],
        )?,
        cx.para(if engine(cx) { "dy_f_md_engine" } else { "dy_f_md" }, &[])?,
        formula(&format!(
            "{} = -(A_c ({p})) / ({p}), quad Delta T = A_d + A_c",
            cx.sym(md_sym(cx))?,
            p = period(cx).1
        )),
        cx.para(if engine(cx) { "where_md_engine" } else { "where_md" }, &[])?,
        // Mertsalov's construction (mertsalov.rs in tmm-linkage): T_II at the
        // mean speed, T_I = ΔT − T_II, its swing sizes the flywheel
        cx.para("dy_f_mertsalov", &[])?,
        formula(
            "T_\"II\"(phi) = (I_\"II\"(phi) omega_m^2) / 2, quad T_I (phi) = Delta T(phi) - T_\"II\"(phi), \\ Delta T_max = max T_I - min T_I",
        ),
        cx.para("where_mertsalov", &[])?,
        cx.para("dy_f_flywheel", &[])?,
        formula(&format!(
            "I_\"M\" = (Delta T_max) / (omega_m^2 delta), quad {} = {} - I_I, quad delta = (omega_max - omega_min) / omega_m",
            cx.sym("sym_ifl")?,
            cx.sym("sym_ireq")?
        )),
        cx.para("where_flywheel", &[])?,
    ];
    let mut results = worked(cx)?;
    results.push(cx.quantities(
        "tab_dynamics",
        vec![
            (
                cx.w(if engine(cx) { "q_md_engine" } else { "q_md" })?,
                cx.qv("/dynamics/driving_moment", 1.0, "u_nm")?,
            ),
            (cx.w("q_energy_swing")?, cx.qv("/dynamics/mertsalov/energy_swing", 1.0, "u_j")?),
            (
                cx.w("q_i_mertsalov")?,
                cx.qv("/dynamics/required_inertia/mertsalov", 1.0, "u_kgm2")?,
            ),
            (
                cx.w("q_i_wittenbauer")?,
                cx.qv("/dynamics/required_inertia/wittenbauer", 1.0, "u_kgm2")?,
            ),
            (cx.w("q_i_exact")?, cx.qv("/dynamics/required_inertia/exact", 1.0, "u_kgm2")?),
            (cx.w("q_i_flywheel")?, cx.qv("/dynamics/flywheel_inertia", 1.0, "u_kgm2")?),
            (cx.w("q_omega_max")?, cx.qv("/dynamics/omega_max", 1.0, "u_rad_s")?),
            (cx.w("q_omega_min")?, cx.qv("/dynamics/omega_min", 1.0, "u_rad_s")?),
            // as the given is written (0,02, not 0,02000)
            (cx.w("q_delta_reached")?, cx.given("/dynamics/delta", 1.0, "")?),
        ],
    )?);
    if cx.opt("/dynamics/flywheel/diameter").is_some() {
        let mut rows = vec![
            (cx.w("q_fw_diameter")?, cx.qv("/dynamics/flywheel/diameter", 1000.0, "u_mm")?),
            (cx.w("q_fw_width")?, cx.qv("/dynamics/flywheel/width", 1000.0, "u_mm")?),
        ];
        // a rim's radial thickness (a disc's is its radius)
        if is_rim(cx) {
            rows.push((cx.w("q_fw_thickness")?, cx.qv("/dynamics/flywheel/thickness", 1000.0, "u_mm")?));
        }
        if cx.opt("/dynamics/flywheel/density").is_some() {
            rows.push((cx.w("q_fw_density")?, cx.given("/dynamics/flywheel/density", 1.0, "u_kg_m3")?));
        }
        rows.push((cx.w("q_fw_mass")?, cx.qv("/dynamics/flywheel/mass", 1.0, "u_kg")?));
        results.push(cx.quantities("tab_flywheel", rows)?);
    }
    // the indicator diagram of each cylinder, as the task gives its tables
    for k in 1.. {
        let Some(Block::Figure {
            caption,
            svg,
            width_mm,
            label,
        }) = cx.figure(&format!("dynamics/indicator-{k}.svg"), "fig_dy_indicator")?
        else {
            break;
        };
        results.push(Block::Figure {
            caption: format!("{caption} {k}"),
            svg,
            width_mm,
            label,
        });
    }
    for (path, key) in [
        ("dynamics/moments.svg", "fig_dy_moments"),
        ("dynamics/work.svg", "fig_dy_work"),
        ("dynamics/inertia.svg", "fig_dy_inertia"),
        ("dynamics/energy-constant.svg", "fig_dy_energy"),
        ("dynamics/wittenbauer.svg", "fig_dy_wittenbauer"),
        ("dynamics/omega.svg", "fig_dy_omega"),
    ] {
        if let Some(f) = cx.figure(path, key)? {
            results.push(f);
        }
    }
    let mut conclusions = vec![cx.para(
        if engine(cx) { "dy_conclusion_engine" } else { "dy_conclusion" },
        &[
            cx.qv("/dynamics/driving_moment", 1.0, "u_nm")?,
            cx.qv("/dynamics/flywheel_inertia", 1.0, "u_kgm2")?,
            // the δ reached, trimmed as the given one is (0,02 against 0,02,
            // not 0,02000)
            cx.given("/dynamics/delta", 1.0, "")?,
            cx.given("/dynamics/delta_requested", 1.0, "")?,
        ],
    )?];
    if cx.opt("/dynamics/flywheel/diameter").is_some() {
        conclusions.push(flywheel_conclusion(cx)?);
    }
    Ok(Some(four_parts(cx, "sec_dynamics", statement, formulas, results, conclusions)?))
}

/// Whether the machine is an engine (`driving = "engine"`): its loads
/// (the gas forces, the weights) drive, and the constant moment found from
/// the cycle's zero work is the driven machine's resistance, not a driving
/// torque (Чёрная, Тимофеев 2019, П2).
fn engine(cx: &Ctx) -> bool {
    // the report's `driving` names the constant moment's model; the task
    // names the engine
    cx.task.get("dynamics").and_then(|d| d.get("driving")).and_then(toml::Value::as_str) == Some("engine")
}

/// The symbol of the constant moment: the driving torque, or an engine's
/// moment of resistance.
fn md_sym(cx: &Ctx) -> &'static str {
    if engine(cx) { "sym_mres" } else { "sym_md" }
}

/// The machine's cycle Φ in radians and as typst math: 2π for one turn,
/// 4π for the two turns of a four-stroke engine (`/dynamics/cycle_period`);
/// the constant moment is −A_c(Φ)/Φ (the work over the cycle is zero).
fn period(cx: &Ctx) -> (f64, String) {
    let tau = std::f64::consts::TAU;
    let phi = cx
        .opt("/dynamics/cycle_period")
        .filter(|p| p.is_finite() && *p > 0.0)
        .unwrap_or(tau);
    let turns = (phi / tau).round();
    if turns >= 1.0 && (phi - turns * tau).abs() < 1e-9 * phi {
        (turns * tau, format!("{} pi", 2.0 * turns))
    } else {
        (
            phi,
            crate::number::format_number(phi, 4, cx.lang)
                .map(|f| f.mantissa)
                .unwrap_or_default(),
        )
    }
}

/// Whether the task's flywheel is a rim (обод), not a disc (диск).
fn is_rim(cx: &Ctx) -> bool {
    cx.s("/dynamics/flywheel/shape") == Some("rim") && cx.opt("/dynamics/flywheel/thickness").is_some()
}

/// The material a flywheel's density names: steel at 7700 … 7900 kg/m³
/// (carbon steels 7750 … 7870), grey cast iron at 6800 … 7400 kg/m³
/// (Анурьев В. И., Справочник конструктора-машиностроителя, т. 1: the
/// densities of steels and of cast irons СЧ); none for another density,
/// which the sentence gives alone.
fn flywheel_material(density: f64) -> &'static str {
    if (7700.0..=7900.0).contains(&density) {
        "fw_steel"
    } else if (6800.0..=7400.0).contains(&density) {
        "fw_cast_iron"
    } else {
        ""
    }
}

/// The conclusion's sentence on the flywheel as the task makes it: its
/// shape (a disc, or a rim with its thickness), its material or density,
/// its size and mass.
fn flywheel_conclusion(cx: &Ctx) -> Result<Block, NoteError> {
    let material = match cx.opt("/dynamics/flywheel/density").map(flywheel_material) {
        Some(key) if !key.is_empty() => cx.w(key)?,
        _ => String::new(),
    };
    let density = match cx.opt("/dynamics/flywheel/density") {
        Some(_) => cx.given("/dynamics/flywheel/density", 1.0, "u_kg_m3")?,
        None => String::new(),
    };
    let d = cx.qv("/dynamics/flywheel/diameter", 1000.0, "u_mm")?;
    let b = cx.qv("/dynamics/flywheel/width", 1000.0, "u_mm")?;
    let m = cx.qv("/dynamics/flywheel/mass", 1.0, "u_kg")?;
    let (key, args) = if is_rim(cx) {
        let h = cx.qv("/dynamics/flywheel/thickness", 1000.0, "u_mm")?;
        ("dy_conclusion_flywheel_rim", vec![material, density, d, b, h, m])
    } else {
        ("dy_conclusion_flywheel_disc", vec![material, density, d, b, m])
    };
    let text = cx.fill(key, &args)?;
    // no material word: the sentence closes up around its place
    let text = text.split(' ').filter(|w| !w.is_empty()).collect::<Vec<_>>().join(" ");
    Ok(Block::Paragraph(crate::model::Text::plain(text)))
}

/// The worked driving moment, Mertsalov's required inertia and the
/// flywheel's inertia with the run's numbers.
fn worked(cx: &Ctx) -> Result<Vec<Block>, NoteError> {
    let mut out = Vec::new();
    let work_end = cx
        .report
        .pointer("/dynamics/work")
        .and_then(serde_json::Value::as_array)
        .and_then(|w| w.last())
        .and_then(serde_json::Value::as_f64);
    let (Some(ac), Some(md)) = (work_end, cx.opt("/dynamics/driving_moment")) else {
        return Ok(out);
    };
    // the machine's cycle: one turn, or two of a four-stroke engine (4π)
    let (phi_c, p) = period(cx);
    out.push(cx.para(if engine(cx) { "calc_md_engine" } else { "calc_md" }, &[])?);
    out.push(Block::Calculation(Calculation::new(
        Quantity::new(&cx.sym(md_sym(cx))?, md, &cx.w("u_nm")?),
        calc::neg(calc::div(calc::q(&format!("A_c ({p})"), ac, ""), calc::exact(phi_c, &p))),
    )));
    let omega = cx.v("/dynamics/omega_nominal")?;
    let delta = cx.v("/dynamics/delta_requested")?;
    let unit = cx.w("u_kgm2")?;
    if let (Some(swing), Some(im)) = (
        cx.opt("/dynamics/mertsalov/energy_swing"),
        cx.opt("/dynamics/required_inertia/mertsalov"),
    ) {
        // the swing of T_I read off its extremes (Fig. "energy of the
        // constant inertia": T_I max, T_I min)
        if let (Some(emax), Some(emin)) = (cx.opt("/dynamics/mertsalov/energy_max"), cx.opt("/dynamics/mertsalov/energy_min")) {
            let unit_j = cx.w("u_j")?;
            out.push(cx.para("calc_energy_swing", &[])?);
            out.push(Block::Calculation(Calculation::new(
                Quantity::new("Delta T_max", swing, &unit_j),
                calc::sub(calc::q("max T_I", emax, ""), calc::q("min T_I", emin, "")),
            )));
        }
        out.push(cx.para("calc_imertsalov", &[])?);
        out.push(Block::Calculation(Calculation::new(
            Quantity::new("I_\"M\"", im, &unit),
            calc::div(
                calc::q("Delta T_max", swing, ""),
                Expr::Mul(vec![
                    calc::pow(calc::q("omega_m", omega, ""), 2),
                    // the given δ as the task gives it (0,02, not 0,02000)
                    calc::qd("delta", delta, "", cx.given_digits("/dynamics/delta_requested")?),
                ]),
            ),
        )));
    }
    if let (Some(req), Some(given), Some(fl)) = (
        cx.opt("/dynamics/required_inertia/exact"),
        cx.opt("/dynamics/inertia_constant_given"),
        cx.opt("/dynamics/flywheel_inertia_crank"),
    ) {
        let on_crank = cx.s("/dynamics/flywheel/place").is_none_or(|p| p == "crank");
        let crank_sym = if on_crank { cx.sym("sym_ifl")? } else { cx.sym("sym_ifl_crank")? };
        out.push(cx.para("calc_ifl", &[])?);
        out.push(Block::Calculation(Calculation::new(
            Quantity::new(&crank_sym, fl, &unit),
            calc::sub(calc::q(&cx.sym("sym_ireq")?, req, ""), calc::q("I_I", given, "")),
        )));
        // a flywheel on the motor's shaft: reduced back by the square of the gear ratio
        if let (false, Some("motor"), Some(u), Some(on_motor)) = (
            on_crank,
            cx.s("/dynamics/flywheel/place"),
            cx.opt("/dynamics/motor/ratio"),
            cx.opt("/dynamics/flywheel_inertia"),
        ) {
            out.push(cx.para("calc_ifl_motor", &[])?);
            out.push(Block::Calculation(Calculation::new(
                Quantity::new(&cx.sym("sym_ifl")?, on_motor, &unit),
                calc::div(calc::q(&crank_sym, fl, ""), calc::pow(calc::q(&cx.sym("sym_u_motor")?, u, ""), 2)),
            )));
        }
    }
    Ok(out)
}
