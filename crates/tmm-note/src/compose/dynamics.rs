//! Section "dynamics of the machine" (динамика машины): the reduced moment
//! of inertia and of the forces, the driving moment, the flywheel by
//! Mertsalov's and Wittenbauer's methods and the true crank speed.

use super::context::{Ctx, formula, four_parts};
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
            cx.w("assume_md_constant")?.into(),
        ]),
        cx.para(
            "dy_given",
            &[
                cx.qv("/dynamics/delta_requested", 1.0, "")?,
                cx.qv("/dynamics/omega_nominal", 1.0, "u_rad_s")?,
            ],
        )?,
        cx.para("dy_method", &[])?,
        cx.para("dy_sought", &[])?,
    ];
    let mut statement = statement;
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
        formula("I_(I I)(phi) = sum_(i != 1) [m_i (v_(S i) / omega_1)^2 + J_(S i) (omega_i / omega_1)^2]"),
        cx.para("dy_f_moment", &[])?,
        formula("M_c (phi) = sum_i (arrow(F)_i dot arrow(v)_i + M_i omega_i) / omega_1, quad A_c (phi) = integral_0^phi M_c dif phi"),
        cx.para("dy_f_md", &[])?,
        formula("M_d = -(A_c |_(phi = 2 pi)) / (2 pi), quad Delta T = A_d + A_c"),
        cx.para("dy_f_flywheel", &[])?,
        formula("I_\"fl\" = (Delta E_max) / (omega_m^2 delta) - I_I, quad delta = (omega_max - omega_min) / omega_m"),
    ];
    let mut results = vec![cx.quantities(
        "tab_dynamics",
        vec![
            (cx.w("q_md")?, cx.qv("/dynamics/driving_moment", 1.0, "u_nm")?),
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
            (cx.w("q_delta_reached")?, cx.qv("/dynamics/delta", 1.0, "")?),
        ],
    )?];
    if cx.opt("/dynamics/flywheel/diameter").is_some() {
        results.push(cx.quantities(
            "tab_flywheel",
            vec![
                (cx.w("q_fw_diameter")?, cx.qv("/dynamics/flywheel/diameter", 1000.0, "u_mm")?),
                (cx.w("q_fw_width")?, cx.qv("/dynamics/flywheel/width", 1000.0, "u_mm")?),
                (cx.w("q_fw_mass")?, cx.qv("/dynamics/flywheel/mass", 1.0, "u_kg")?),
            ],
        )?);
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
        "dy_conclusion",
        &[
            cx.qv("/dynamics/driving_moment", 1.0, "u_nm")?,
            cx.qv("/dynamics/flywheel_inertia", 1.0, "u_kgm2")?,
            cx.qv("/dynamics/delta", 1.0, "")?,
            cx.qv("/dynamics/delta_requested", 1.0, "")?,
        ],
    )?];
    if cx.opt("/dynamics/flywheel/diameter").is_some() {
        conclusions.push(cx.para(
            "dy_conclusion_flywheel",
            &[
                cx.qv("/dynamics/flywheel/diameter", 1000.0, "u_mm")?,
                cx.qv("/dynamics/flywheel/mass", 1.0, "u_kg")?,
            ],
        )?);
    }
    Ok(Some(four_parts(cx, "sec_dynamics", statement, formulas, results, conclusions)?))
}
