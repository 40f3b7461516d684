//! Section "cam mechanism" (синтез кулачкового механизма): the motion law,
//! the minimum size from the allowed pressure angles, the profile.

use serde_json::Value;

use super::assignment::as_given;
use super::context::{Ctx, formula, four_parts, num, text};
use crate::error::NoteError;
use crate::model::{Block, Section};

/// The given values of the cam as (name, value) rows.
pub(crate) fn given_rows(cx: &Ctx) -> Result<Vec<(String, String)>, NoteError> {
    let mut rows = vec![
        (cx.w("q_follower")?, follower(cx)?),
        (
            cx.w(if oscillating(cx) { "q_stroke_oscillating" } else { "q_stroke" })?,
            stroke(cx)?,
        ),
        speed_row(cx)?,
    ];
    // the arm and the roller where the task gives them (l = 150 мм, r_r = 20 мм)
    let task = |key: &str| cx.task.get("cam").and_then(|c| c.get(key)).is_some();
    if task("arm")
        && let Some(arm) = cx.opt("/cam/arm")
    {
        rows.insert(2, (cx.w("q_arm")?, as_given(cx, CAM, arm * 1000.0, "u_mm")?));
    }
    if task("roller")
        && let Some(r) = cx.opt("/cam/roller_radius")
    {
        rows.push((cx.w("q_roller")?, as_given(cx, CAM, r * 1000.0, "u_mm")?));
    }
    // the profile's least radius of curvature and the flat face's margin
    // where the task gives them (ρ_min = 10 мм, 5 мм)
    for (key, word) in [("min_curvature", "q_min_curvature"), ("face_margin", "q_face_margin")] {
        if let Some(v) = super::assignment::task_given(cx, "cam", key, "u_mm")? {
            rows.push((cx.w(word)?, v));
        }
    }
    if let Some(p) = cx.opt("/cam/pressure_angle_limit_rise") {
        rows.push((cx.w("q_limit_rise")?, as_given(cx, CAM, p.to_degrees(), "u_deg")?));
    }
    if let Some(p) = cx.opt("/cam/pressure_angle_limit_return") {
        rows.push((cx.w("q_limit_return")?, as_given(cx, CAM, p.to_degrees(), "u_deg")?));
    }
    Ok(rows)
}

/// The task's table of the cam's givens.
const CAM: &[&str] = &["cam"];

/// The cam's speed as the task gives it: its angular speed ω (рад/с), or
/// its frequency of rotation n (об/мин) where the task writes `rpm`
/// (n = 30·ω/π).
fn speed_row(cx: &Ctx) -> Result<(String, String), NoteError> {
    let omega = cx.v("/cam/omega")?;
    let in_rpm = cx
        .task
        .get("cam")
        .and_then(|c| c.get("omega"))
        .and_then(toml::Value::as_str)
        .is_some_and(|s| s.trim_end().ends_with("rpm"));
    Ok(if in_rpm {
        (
            cx.w("q_cam_n")?,
            as_given(cx, CAM, omega.abs() * 30.0 / std::f64::consts::PI, "u_rpm")?,
        )
    } else {
        (cx.w("q_cam_omega")?, as_given(cx, CAM, omega, "u_rad_s")?)
    })
}

/// An oscillating follower (коромысло): its stroke is an angle, its place
/// is given by the pivot distance and the arm, not by an offset e.
fn oscillating(cx: &Ctx) -> bool {
    cx.s("/cam/follower").is_some_and(|f| f.starts_with("oscillating"))
}

/// The follower's stroke: a length in mm, or the arm's swing in degrees.
fn stroke(cx: &Ctx) -> Result<String, NoteError> {
    if oscillating(cx) {
        let swing = as_given(cx, CAM, cx.v("/cam/stroke")?.to_degrees(), "u_deg")?;
        // the task's arc (80 мм) beside the swing found from it
        match super::assignment::task_length_text(cx, "cam", "stroke")? {
            Some(arc) => cx.fill("cam_stroke_arc", &[swing, arc]),
            None => Ok(swing),
        }
    } else {
        as_given(cx, CAM, cx.v("/cam/stroke")? * 1000.0, "u_mm")
    }
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
        cx.para(
            if oscillating(cx) { "cam_given_oscillating" } else { "cam_given" },
            &[follower(cx)?, stroke(cx)?],
        )?,
        cx.para("cam_method", &[])?,
        cx.para("cam_sought", &[])?,
    ];
    let osc = oscillating(cx);
    // an oscillating follower's arm turns: its angular speed and
    // acceleration through the analogues of its angle ψ (ω_2 = ω·dψ/dφ,
    // ε_2 = ω²·d²ψ/dφ² at a constant ω of the cam; Артоболевский 1988, ch. 7)
    let mut formulas = if osc {
        vec![
            cx.para("cam_f_analogs_oscillating", &[])?,
            formula("omega_2 = omega (dif psi) / (dif phi), quad epsilon_2 = omega^2 (dif^2 psi) / (dif phi^2)"),
            cx.para("where_cam_analogs_oscillating", &[])?,
        ]
    } else {
        vec![
            cx.para("cam_f_analogs", &[])?,
            formula("v = omega (dif s) / (dif phi), quad a = omega^2 (dif^2 s) / (dif phi^2)"),
            cx.para("where_cam_analogs", &[])?,
        ]
    };
    if osc {
        formulas.push(cx.para("cam_f_pressure_oscillating", &[])?);
    } else {
        formulas.push(cx.para("cam_f_pressure", &[])?);
        formulas.push(formula(
            "tan theta.alt = ((dif s) / (dif phi) - e) / (s_0 + s), quad s_0 = sqrt(r_0^2 - e^2)",
        ));
        formulas.push(cx.para("where_cam_pressure", &[])?);
    }
    formulas.extend([
        cx.para("cam_f_roller", &[])?,
        // the numbers with the language's decimal separator
        formula(&format!(
            "r_r <= {} r_0, quad r_r <= {} rho_min",
            crate::number::math_number(0.4, 1, cx.lang)?,
            crate::number::math_number(0.7, 1, cx.lang)?
        )),
        cx.para("where_cam_roller", &[])?,
    ]);
    // the analogues of an oscillating follower are of an angle: dψ/dφ is a
    // pure number, d²ψ/dφ² per radian; of a translating one, lengths in mm
    let (analog_scale, analog_unit) = if osc { (1.0, "") } else { (1000.0, "u_mm") };
    let mut rows = Vec::new();
    if let Some(ph) = cam.get("phases").and_then(Value::as_array) {
        for p in ph {
            let kind = p.get("kind").and_then(Value::as_str).unwrap_or("");
            let angle = p.get("angle").and_then(Value::as_f64).unwrap_or(0.0);
            rows.push(vec![
                text(cx.w(&format!("phase_{kind}")).unwrap_or_else(|_| kind.to_string())),
                num(angle.to_degrees()),
                num(p.get("ds_dphi_max").and_then(Value::as_f64).unwrap_or(0.0) * analog_scale),
                num(p.get("d2s_dphi2_max").and_then(Value::as_f64).unwrap_or(0.0) * analog_scale),
            ]);
        }
    }
    let mut results = vec![cx.table(
        "tab_cam_phases",
        &[
            ("col_phase", ""),
            ("col_phase_angle", "u_deg"),
            ("col_ds_max", analog_unit),
            ("col_dds_max", analog_unit),
        ],
        rows,
    )?];
    let mut q = vec![(cx.w("q_r0")?, cx.qv("/cam/r0", 1000.0, "u_mm")?)];
    // where the follower is: the offset e of a translating one; the pivot
    // distance, the arm and its initial angle of an oscillating one
    if let Some(e) = cx.opt("/cam/e") {
        q.push((cx.w("q_e")?, cx.q(e * 1000.0, "u_mm")?));
    }
    if let Some(a) = cx.opt("/cam/pivot_distance") {
        q.push((cx.w("q_pivot_distance")?, cx.q(a * 1000.0, "u_mm")?));
    }
    if let Some(l) = cx.opt("/cam/arm") {
        q.push((cx.w("q_arm")?, cx.q(l * 1000.0, "u_mm")?));
    }
    if cx.opt("/cam/arm_angle_start").is_some() {
        q.push((cx.w("q_arm_angle_start")?, cx.deg("/cam/arm_angle_start")?));
    }
    if cx.opt("/cam/face_angle_start").is_some() {
        q.push((cx.w("q_face_angle_start")?, cx.deg("/cam/face_angle_start")?));
    }
    if let Some(r) = cx.opt("/cam/roller_radius").filter(|r| *r > 0.0) {
        q.push((cx.w("q_roller")?, cx.q(r * 1000.0, "u_mm")?));
    }
    q.extend([
        (cx.w("q_pressure_rise")?, cx.deg("/cam/pressure_angle_max_rise")?),
        (cx.w("q_pressure_fall")?, cx.deg("/cam/pressure_angle_max_return")?),
        (cx.w("q_rho_min")?, cx.qv("/cam/rho_min", 1000.0, "u_mm")?),
    ]);
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
    results.extend(worked(cx, osc)?);
    let book = book_blocks(cx)?;
    formulas.extend(book.formulas);
    results.extend(book.results);
    let undercut = cam.get("undercut").and_then(Value::as_bool).unwrap_or(false);
    let mut conclusions = vec![cx.para(
        if undercut { "cam_conclusion_undercut" } else { "cam_conclusion" },
        &[
            cx.qv("/cam/r0", 1000.0, "u_mm")?,
            cx.deg("/cam/pressure_angle_max_rise")?,
            cx.deg("/cam/pressure_angle_max_return")?,
            cx.qv("/cam/rho_min", 1000.0, "u_mm")?,
        ],
    )?];
    conclusions.extend(book.conclusions);
    Ok(Some(four_parts(cx, "sec_cam", statement, formulas, results, conclusions)?))
}

/// The textbook's constructions (`cam.book`), when the report has them.
#[derive(Default)]
struct BookBlocks {
    formulas: Vec<Block>,
    results: Vec<Block>,
    conclusions: Vec<Block>,
}

/// A signed angle at `ptr` in degrees.
fn deg_at(cx: &Ctx, ptr: &str) -> Result<String, NoteError> {
    cx.deg(ptr)
}

/// The book's tangent methods (translating follower, П6.4) or level lines
/// (oscillating follower, П6.5) beside tmm's design, and the roller rules.
fn book_blocks(cx: &Ctx) -> Result<BookBlocks, NoteError> {
    let mut b = BookBlocks::default();
    let Some(method) = cx.s("/cam/book/method") else { return Ok(b) };
    let mm = |v: f64| num(v * 1000.0);
    let dg = |v: f64| num(v.to_degrees());
    let at = |p: &str| cx.opt(p).unwrap_or(0.0);
    // the largest |θ| of a phase, from its signed range `{p}_min`, `{p}_max`
    let largest = |p: &str| at(&format!("{p}_max")).max(-at(&format!("{p}_min")));
    if method == "tangents" {
        b.formulas.push(cx.para("cam_f_book_tangents", &[])?);
        b.formulas.push(formula(
            "tan theta.alt = (v_q - e) / (s_0 + S), quad v_q / a_q = tan delta, quad delta = pi / 2 - theta.alt",
        ));
        let mut rows = Vec::new();
        for (key, ptr) in [
            ("cam_book_step1", "/cam/book/approximate"),
            ("cam_book_method1", "/cam/book/method_1"),
            ("cam_book_method2", "/cam/book/method_2"),
            ("cam_book_exact", "/cam/book/exact"),
        ] {
            rows.push(vec![
                text(cx.w(key)?),
                mm(at(&format!("{ptr}/e_book"))),
                mm(at(&format!("{ptr}/s0"))),
                mm(at(&format!("{ptr}/r0"))),
                dg(largest(&format!("{ptr}/pressure_rise"))),
                dg(largest(&format!("{ptr}/pressure_return"))),
                dg(at(&format!("{ptr}/limit_excess"))),
            ]);
        }
        b.results.push(cx.table(
            "tab_cam_book",
            &[
                ("col_centre", ""),
                ("col_e_book", "u_mm"),
                ("col_s0", "u_mm"),
                ("col_r0", "u_mm"),
                ("col_theta_rise", "u_deg"),
                ("col_theta_return", "u_deg"),
                ("col_excess", "u_deg"),
            ],
            rows,
        )?);
        let q = vec![
            (cx.w("q_phi_speed_rise")?, deg_at(cx, "/cam/book/phi_speed_rise")?),
            (cx.w("q_phi_speed_return")?, deg_at(cx, "/cam/book/phi_speed_return")?),
            (cx.w("q_phi_tangent_rise")?, deg_at(cx, "/cam/book/phi_tangent_rise")?),
            (cx.w("q_phi_tangent_return")?, deg_at(cx, "/cam/book/phi_tangent_return")?),
            (cx.w("q_delta_r")?, cx.q(at("/cam/book/delta_r") * 100.0, "u_percent")?),
            (cx.w("q_delta_e")?, cx.q(at("/cam/book/delta_e") * 100.0, "u_percent")?),
            (cx.w("q_r0_vs_exact")?, cx.q(at("/cam/book/r0_vs_exact") * 100.0, "u_percent")?),
        ];
        b.results.push(cx.quantities("tab_cam_book_points", q)?);
        let over = at("/cam/book/method_1/limit_excess") > 1e-9;
        b.conclusions.push(cx.para(
            if over {
                "cam_conclusion_book_tangents"
            } else {
                "cam_conclusion_book_tangents_ok"
            },
            &[
                cx.qv("/cam/book/method_1/r0", 1000.0, "u_mm")?,
                cx.qv("/cam/book/exact/r0", 1000.0, "u_mm")?,
                cx.q(at("/cam/book/r0_vs_exact") * 100.0, "u_percent")?,
                cx.q(at("/cam/book/method_1/limit_excess").to_degrees(), "u_deg")?,
            ],
        )?);
    } else {
        b.formulas.push(cx.para("cam_f_book_levels", &[])?);
        b.formulas.push(formula(
            "N = (l_T - v_q) e(phi_2), quad k = tan(phi_2 + pi / 2 plus.minus theta.alt), quad X_V = (Y_1 - b) / k - X_1",
        ));
        let mut rows = Vec::new();
        for (key, ptr) in [
            ("cam_book_point2", "/cam/book/point_2"),
            ("cam_book_vertex", "/cam/book/vertex"),
            ("cam_book_exact", "/cam/book/exact"),
        ] {
            rows.push(vec![
                text(cx.w(key)?),
                mm(at(&format!("{ptr}/x"))),
                mm(at(&format!("{ptr}/y"))),
                mm(at(&format!("{ptr}/centre_distance"))),
                dg(at(&format!("{ptr}/initial_angle"))),
                dg(largest(&format!("{ptr}/pressure_rise"))),
                dg(largest(&format!("{ptr}/pressure_return"))),
                dg(at(&format!("{ptr}/limit_excess"))),
            ]);
        }
        b.results.push(cx.table(
            "tab_cam_book_levels",
            &[
                ("col_centre", ""),
                ("col_x", "u_mm"),
                ("col_y", "u_mm"),
                ("col_aw", "u_mm"),
                ("col_phi20", "u_deg"),
                ("col_theta_rise", "u_deg"),
                ("col_theta_return", "u_deg"),
                ("col_excess", "u_deg"),
            ],
            rows,
        )?);
        let p1 = cx.report.pointer("/cam/book/point_1").and_then(Value::as_array);
        let c = |i: usize| p1.and_then(|a| a.get(i)).and_then(Value::as_f64).unwrap_or(0.0) * 1000.0;
        let q = vec![
            (cx.w("q_point1")?, format!("{}; {}", cx.q(c(0), "u_mm")?, cx.q(c(1), "u_mm")?)),
            (cx.w("q_phi_v_min")?, deg_at(cx, "/cam/book/phi_v_min")?),
            (cx.w("q_phi_v_max")?, deg_at(cx, "/cam/book/phi_v_max")?),
            (
                cx.w("q_pivot_distance")?,
                cx.qv("/cam/book/point_2/centre_distance", 1000.0, "u_mm")?,
            ),
            (cx.w("q_phi20")?, deg_at(cx, "/cam/book/point_2/initial_angle")?),
        ];
        b.results.push(cx.quantities("tab_cam_book_points", q)?);
        let over = at("/cam/book/point_2/limit_excess") > 1e-9;
        b.conclusions.push(cx.para(
            if over {
                "cam_conclusion_book_levels"
            } else {
                "cam_conclusion_book_levels_ok"
            },
            &[
                cx.qv("/cam/book/point_2/centre_distance", 1000.0, "u_mm")?,
                deg_at(cx, "/cam/book/point_2/initial_angle")?,
                cx.q(at("/cam/book/point_2/limit_excess").to_degrees(), "u_deg")?,
                cx.qv("/cam/book/vertex/centre_distance", 1000.0, "u_mm")?,
            ],
        )?);
    }
    if cx.report.pointer("/cam/book/roller_rules").is_some_and(|v| !v.is_null()) {
        let yes = |p: &str| -> Result<String, NoteError> {
            let ok = cx.report.pointer(p).and_then(Value::as_bool).unwrap_or(false);
            cx.w(if ok { "check_pass" } else { "check_fail" })
        };
        let r = "/cam/book/roller_rules";
        b.results.push(cx.table(
            "tab_cam_roller_rules",
            &[("col_check", ""), ("col_limit", "u_mm"), ("col_verdict", "")],
            vec![
                vec![
                    text(cx.w("cam_rule_low")?),
                    mm(at(&format!("{r}/range_low"))),
                    text(yes(&format!("{r}/above_range_low"))?),
                ],
                vec![
                    text(cx.w("cam_rule_high")?),
                    mm(at(&format!("{r}/range_high"))),
                    text(yes(&format!("{r}/below_range_high"))?),
                ],
                vec![
                    text(cx.w("cam_rule_rho08")?),
                    mm(at(&format!("{r}/rho_bound"))),
                    text(yes(&format!("{r}/below_rho_bound"))?),
                ],
                vec![
                    text(cx.w("cam_rule_rho")?),
                    mm(at(&format!("{r}/rho_min_pitch"))),
                    text(yes(&format!("{r}/below_rho_min"))?),
                ],
            ],
        )?);
    }
    Ok(b)
}

/// The follower's largest speed and acceleration worked from the analogues
/// with the run's numbers (v = ω·ds/dφ, a = ω²·d²s/dφ², the formulas of the
/// section), at the cam angles where the report's speed and acceleration
/// are largest; for a translating follower (an oscillating one's analogues
/// are of an angle).
fn worked(cx: &Ctx, osc: bool) -> Result<Vec<Block>, NoteError> {
    use crate::calc::{self, Calculation, Expr, Quantity};
    let mut out = Vec::new();
    if osc {
        return Ok(out);
    }
    let arr = |k: &str| -> Vec<f64> {
        cx.report
            .pointer(&format!("/cam/{k}"))
            .and_then(Value::as_array)
            .map(|a| a.iter().filter_map(Value::as_f64).collect())
            .unwrap_or_default()
    };
    let (v, ds, a, dds) = (arr("velocity"), arr("ds_dphi"), arr("acceleration"), arr("d2s_dphi2"));
    let Some(omega) = cx.opt("/cam/omega").map(f64::abs) else {
        return Ok(out);
    };
    let largest = |x: &[f64]| (0..x.len()).max_by(|&i, &j| x[i].abs().total_cmp(&x[j].abs()));
    let (Some(iv), Some(ia)) = (largest(&v), largest(&a)) else {
        return Ok(out);
    };
    if ds.len() != v.len() || dds.len() != a.len() {
        return Ok(out);
    }
    out.push(cx.para("calc_cam", &[])?);
    // the analogues in mm, the speed in m/s: ds/dφ·10⁻³
    let milli = || calc::exact(1e-3, "10^(-3)");
    out.push(Block::Calculation(Calculation::new(
        Quantity::new("v_max", v[iv], &cx.w("u_m_s")?),
        Expr::Mul(vec![
            calc::q("omega", omega, ""),
            calc::q("(dif s) / (dif phi)", ds[iv] * 1e3, ""),
            milli(),
        ]),
    )));
    out.push(Block::Calculation(Calculation::new(
        Quantity::new("a_max", a[ia], &cx.w("u_m_s2")?),
        Expr::Mul(vec![
            calc::pow(calc::q("omega", omega, ""), 2),
            calc::q("(dif^2 s) / (dif phi^2)", dds[ia] * 1e3, ""),
            milli(),
        ]),
    )));
    Ok(out)
}
