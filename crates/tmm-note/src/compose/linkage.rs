//! Section "structure and kinematics" (структурный и кинематический анализ):
//! the structure formula, the 12 positions, the plans of velocities and
//! accelerations at the given position and the kinematic diagrams.

use serde_json::Value;

use super::context::{Ctx, formula, four_parts, num, text};
use crate::calc::{self, Calculation, Expr, Quantity};
use crate::error::NoteError;
use crate::model::{Block, Section};

/// The links of the analysed mechanism with their lengths in m: the largest
/// distance between the link's joints in the first position of the report.
/// The joints come from the task's `[[linkage.links]]`, or from the
/// synthesised `[linkage]` the synthesis report carries.
pub(crate) fn link_lengths(cx: &Ctx) -> Vec<(String, f64)> {
    let links = task_links(cx);
    let points = cx.report.pointer("/linkage/positions/0/points");
    let at = |j: &str| -> Option<(f64, f64)> {
        let p = points?.get(j)?;
        Some((p.get("x")?.as_f64()?, p.get("y")?.as_f64()?))
    };
    let mut out = Vec::new();
    for l in links {
        let Some(name) = l.get("name").and_then(|n| n.as_str()) else {
            continue;
        };
        let joints: Vec<(f64, f64)> = l
            .get("joints")
            .and_then(|j| j.as_array())
            .map(|a| a.iter().filter_map(|j| j.as_str().and_then(at)).collect())
            .unwrap_or_default();
        let mut len: f64 = 0.0;
        for (i, a) in joints.iter().enumerate() {
            for b in &joints[i + 1..] {
                len = len.max((a.0 - b.0).hypot(a.1 - b.1));
            }
        }
        if len > 0.0 {
            out.push((name.to_string(), len));
        }
    }
    out
}

/// The `[[linkage.links]]` of the task, or of the synthesised `[linkage]`
/// the synthesis report carries.
pub(crate) fn task_links(cx: &Ctx) -> Vec<toml::Value> {
    let synthesised: Option<toml::Table> = cx.s("/synthesis/task").and_then(|t| toml::from_str(t).ok());
    let linkage = cx
        .task
        .get("linkage")
        .or_else(|| synthesised.as_ref().and_then(|t| t.get("linkage")))
        .cloned();
    linkage
        .as_ref()
        .and_then(|l| l.get("links"))
        .and_then(|l| l.as_array())
        .cloned()
        .unwrap_or_default()
}

/// A name as a typst-math subscript: a number or letters as they are,
/// anything else quoted.
pub(crate) fn math_name(name: &str) -> String {
    if !name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric()) {
        if name.len() > 1 && name.chars().any(|c| c.is_ascii_alphabetic()) {
            // `OA` would read as one unknown symbol: letters apart
            name.chars().map(String::from).collect::<Vec<_>>().join(" ")
        } else {
            name.to_string()
        }
    } else {
        format!("\"{}\"", name.replace(['\\', '"'], ""))
    }
}

/// The input link (кривошип) as (its frame joint, its moving joint, its
/// length in m): the joint of the link that stays still in the first
/// position is its axis. `None` if the task does not name the joints.
pub(crate) fn crank(cx: &Ctx) -> Option<(String, String, f64)> {
    let input = cx.s("/linkage/input/link")?;
    let links = task_links(cx);
    let link = links.iter().find(|l| l.get("name").and_then(|n| n.as_str()) == Some(input))?;
    let joints: Vec<&str> = link.get("joints")?.as_array()?.iter().filter_map(|j| j.as_str()).collect();
    let points = cx.report.pointer("/linkage/positions/0/points")?;
    let p = |j: &str| -> Option<(f64, f64, f64)> {
        let q = points.get(j)?;
        let f = |k: &str| q.get(k).and_then(Value::as_f64);
        Some((f("x")?, f("y")?, f("vx")?.hypot(f("vy")?)))
    };
    let axis = joints.iter().find(|j| p(j).is_some_and(|(_, _, v)| v < 1e-9))?;
    let pin = joints.iter().find(|j| *j != axis && p(j).is_some_and(|(_, _, v)| v > 1e-9))?;
    let (a, b) = (p(axis)?, p(pin)?);
    Some((axis.to_string(), pin.to_string(), (a.0 - b.0).hypot(a.1 - b.1)))
}

/// The vector equations of the velocity and acceleration plans, written
/// from the mechanism's structure ([`super::group_equations`]), each with
/// its line of symbols; the four-bar's generic equations where the report
/// has no groups.
fn kinematic_equations(cx: &Ctx) -> Result<Vec<Block>, NoteError> {
    let axis = crank(cx).map(|(axis, _, _)| axis);
    let Some(eq) = axis.and_then(|a| super::group_equations::crank_equations(cx, &a)) else {
        return Ok(vec![
            cx.para("lk_f_velocity", &[])?,
            formula("arrow(v)_C = arrow(v)_B + arrow(v)_(C B)"),
            cx.para("lk_f_acceleration", &[])?,
            formula("arrow(a)_C = arrow(a)_B + arrow(a)^n_(C B) + arrow(a)^tau_(C B)"),
        ]);
    };
    equation_blocks(cx, &eq)
}

/// The blocks of the equations: the velocities, the accelerations and the
/// magnitudes (where any), each formula with its line of symbols.
fn equation_blocks(cx: &Ctx, eq: &super::group_equations::Equations) -> Result<Vec<Block>, NoteError> {
    let mut b = vec![
        cx.para("lk_f_velocity_groups", &[])?,
        formula(&eq.velocity),
        eq.where_velocity(cx)?,
        cx.para("lk_f_acceleration_groups", &[])?,
        formula(&eq.acceleration),
        eq.where_acceleration(cx)?,
    ];
    if !eq.magnitudes.is_empty() {
        b.push(cx.para("lk_f_magnitudes", &[])?);
        b.push(formula(&eq.magnitudes));
        b.push(eq.where_magnitudes(cx)?);
    }
    Ok(b)
}

/// The section, if the report has `linkage`.
pub(crate) fn section(cx: &Ctx) -> Result<Option<Section>, NoteError> {
    let Some(lk) = cx.report.get("linkage") else { return Ok(None) };
    if cx.s("/linkage/input/kind") == Some("slider") {
        return slider_section(cx, lk).map(Some);
    }
    let structure = Structure::read(cx)?;
    let omega = cx.v("/linkage/input/omega")?;

    let statement = vec![
        Block::List(vec![
            cx.w("assume_rigid")?.into(),
            cx.w("assume_pairs")?.into(),
            cx.w("assume_omega")?.into(),
        ]),
        cx.para("lk_given", &[cx.q(omega, "u_rad_s")?, cx.deg("/linkage/plans/phi")?])?,
        cx.para("lk_method", &[])?,
        cx.para("lk_sought", &[])?,
    ];
    // a crank that turns fully has a time ratio; a partial-range input
    // (`range = "partial"`) has assembly ranges instead
    let kv = cx.opt("/linkage/kv");
    let mut formulas = vec![
        cx.para("lk_f_dof", &[])?,
        formula("W = 3 n - 2 p_5 - p_4"),
        cx.para("where_dof", &[])?,
    ];
    formulas.extend(kinematic_equations(cx)?);
    if kv.is_some() {
        formulas.push(cx.para("lk_f_kv", &[])?);
        formulas.push(formula("K_v = (180° + theta) / (180° - theta)"));
        formulas.push(cx.para("where_kv", &[])?);
    }
    let mut results = structure.dof_blocks(cx)?;
    if let (Some((axis, pin, l)), Some(v)) = (crank(cx), plan_speed(cx)) {
        let pin_m = math_name(&pin);
        results.push(cx.para("calc_vb", &[cx.deg("/linkage/plans/phi")?])?);
        results.push(Block::Calculation(Calculation::new(
            Quantity::new(&format!("v_({pin_m})"), v, &cx.w("u_m_s")?),
            Expr::Mul(vec![
                // a speed's magnitude: a clockwise crank has ω1 < 0 in the report
                calc::q("omega_1", omega.abs(), ""),
                calc::q(&format!("l_({} {pin_m})", math_name(&axis)), l, ""),
            ]),
        )));
    }
    structure.paragraph_and_figures(cx, &mut results)?;
    // the plan position: the point speeds and accelerations from the plans
    let rows = plan_rows(lk);
    if !rows.is_empty() {
        results.push(cx.para("lk_plans", &[cx.deg("/linkage/plans/phi")?])?);
        results.push(cx.table(
            "tab_point_kinematics",
            &[("col_point", ""), ("col_speed", "u_m_s"), ("col_acceleration", "u_m_s2")],
            rows,
        )?);
    }
    let conclusions = vec![
        structure.conclusion(cx)?,
        match kv {
            Some(kv) => cx.para(
                "lk_conclusion_kinematics",
                &[cx.q(kv, "")?, cx.deg("/linkage/theta")?, pressure_max(cx)?],
            )?,
            // assembled over the whole turn (the input link only swings in
            // use, as the oscillating cylinder's lever): no "does not turn"
            // the oscillating cylinder: the angle of the rod's force on the
            // lever, not the analysed group's (identically zero)
            None if assembles_everywhere(cx) => match cylinder_pressure(cx) {
                Some((start, end, max)) => cx.para(
                    "lk_conclusion_cylinder",
                    &[cx.q(start, "u_deg")?, cx.q(end, "u_deg")?, cx.q(max, "u_deg")?],
                )?,
                None => cx.para("lk_conclusion_full_range", &[pressure_max(cx)?])?,
            },
            None => cx.para("lk_conclusion_partial", &[assembly_ranges(cx)?, pressure_max(cx)?])?,
        },
    ];
    // the analysed mechanism (the task's lengths) against the synthesised one
    let mut conclusions = conclusions;
    // with the given K_v's digits, or the first more that tell the two
    // apart (1,10650 synthesised, 1,10647 analysed), up to seven
    if let (Some(kv), Some(ks), Some(given)) = (kv, cx.opt("/synthesis/check/k"), cx.opt("/synthesis/k")) {
        let digits = super::assignment::given_precision(cx, &["synthesis"], given, "");
        let f = |x: f64, d: u8| crate::number::format_number(x, d, cx.lang).map(|n| n.to_string());
        for d in digits..=digits.max(7) {
            let (s, a) = (f(ks, d)?, f(kv, d)?);
            if s != a {
                conclusions.push(cx.para("lk_conclusion_vs_synthesis", &[s, a])?);
                break;
            }
        }
    }
    Ok(Some(four_parts(cx, "sec_linkage", statement, formulas, results, conclusions)?))
}

/// The structure's numbers from the report (the crank and the slider
/// input alike): moving links n, lower and higher pairs p5, p4, the degree
/// of freedom W, the structure formula and the mechanism's class.
struct Structure {
    dof: f64,
    n: f64,
    p5: f64,
    p4: f64,
    formula: String,
    class: f64,
}

impl Structure {
    fn read(cx: &Ctx) -> Result<Self, NoteError> {
        let st = "/linkage/structure";
        Ok(Self {
            dof: cx.v(&format!("{st}/dof"))?,
            n: cx.v(&format!("{st}/n"))?,
            p5: cx.v(&format!("{st}/p5"))?,
            p4: cx.v(&format!("{st}/p4"))?,
            formula: cx.s(&format!("{st}/formula")).unwrap_or("").to_string(),
            class: cx.v(&format!("{st}/class"))?,
        })
    }

    /// The structural analysis' blocks and W worked by Chebyshev's formula.
    fn dof_blocks(&self, cx: &Ctx) -> Result<Vec<Block>, NoteError> {
        let mut results = super::structure::blocks(cx)?;
        results.extend([
            cx.para("calc_dof", &[])?,
            Block::Calculation(Calculation::new(
                Quantity::count("W", self.dof),
                calc::sub(
                    calc::sub(
                        Expr::Mul(vec![calc::int(3), calc::count("n", self.n)]),
                        Expr::Mul(vec![calc::int(2), calc::count("p_5", self.p5)]),
                    ),
                    calc::count("p_4", self.p4),
                ),
            )),
        ]);
        Ok(results)
    }

    /// The class as the table of Assur groups prints it: II, not 2.
    fn class_roman(&self) -> String {
        if self.class >= 0.0 && self.class.fract() == 0.0 {
            super::structure::roman(self.class as u64)
        } else {
            format!("{}", self.class)
        }
    }

    /// The conclusion's sentence on the structure.
    fn conclusion(&self, cx: &Ctx) -> Result<Block, NoteError> {
        cx.para(
            "lk_conclusion_structure",
            &[self.formula.clone(), self.class_roman(), format!("{}", self.dof)],
        )
    }

    /// The structure's paragraph, then the section's figures (positions,
    /// plans, diagrams) that the run made.
    fn paragraph_and_figures(&self, cx: &Ctx, results: &mut Vec<Block>) -> Result<(), NoteError> {
        results.push(cx.para(
            "lk_structure",
            &[
                format!("{}", self.n),
                format!("{}", self.p5),
                format!("{}", self.p4),
                format!("{}", self.dof),
                self.formula.clone(),
                self.class_roman(),
            ],
        )?);
        for (path, key) in [
            ("linkage/positions.svg", "fig_positions"),
            ("linkage/velocity-plan.svg", "fig_velocity_plan"),
            ("linkage/acceleration-plan.svg", "fig_acceleration_plan"),
            ("linkage/diagram-s.svg", "fig_diagram_s"),
            ("linkage/diagram-v.svg", "fig_diagram_v"),
            ("linkage/diagram-a.svg", "fig_diagram_a"),
        ] {
            if let Some(f) = cx.figure(path, key)? {
                results.push(f);
            }
        }
        Ok(())
    }
}

/// A length of the report (m) printed in mm, as the task's `[linkage]`
/// writes it.
fn mm(cx: &Ctx, ptr: &str) -> Result<String, NoteError> {
    super::assignment::as_given(cx, &["linkage"], cx.v(ptr)? * 1e3, "u_mm")
}

/// The section of a linkage driven by a slider on a fixed guide: the
/// input, the structure, the analogues taken by s, the figures and the
/// points' speeds and accelerations at the plans' s.
fn slider_section(cx: &Ctx, lk: &Value) -> Result<Section, NoteError> {
    let structure = Structure::read(cx)?;
    let statement = vec![
        cx.para(
            "lk_slider_given",
            &[
                cx.s("/linkage/input/link").unwrap_or("").to_string(),
                super::assignment::as_given(cx, &["linkage"], cx.v("/linkage/input/speed")?, "u_m_s")?,
                mm(cx, "/linkage/input/travel/from")?,
                mm(cx, "/linkage/input/travel/to")?,
                mm(cx, "/linkage/plans/s")?,
            ],
        )?,
        cx.para("lk_slider_method", &[])?,
    ];
    let mut formulas = vec![
        cx.para("lk_f_dof", &[])?,
        formula("W = 3 n - 2 p_5 - p_4"),
        cx.para("where_dof", &[])?,
    ];
    // the slider's own equations (v_B = v, a_B = a), then the groups'
    if let Some(eq) = super::group_equations::slider_equations(cx) {
        formulas.extend(equation_blocks(cx, &eq)?);
    }
    formulas.push(formula("x' = dot(x) / v, quad x'' = (dot.double(x) - x' a) / v^2"));
    let mut results = structure.dof_blocks(cx)?;
    structure.paragraph_and_figures(cx, &mut results)?;
    let rows = plan_rows(lk);
    if !rows.is_empty() {
        results.push(cx.para("lk_slider_plans", &[mm(cx, "/linkage/plans/s")?])?);
        results.push(cx.table(
            "tab_point_kinematics",
            &[("col_point", ""), ("col_speed", "u_m_s"), ("col_acceleration", "u_m_s2")],
            rows,
        )?);
    }
    let conclusions = vec![structure.conclusion(cx)?, cx.para("lk_slider_conclusion", &[pressure_max(cx)?])?];
    four_parts(cx, "sec_linkage", statement, formulas, results, conclusions)
}

/// A point's name as the plans and the scheme letter it: in italics, its
/// trailing number lowered (`S2` → S₂, as the drawings' `S_2`); a name of
/// other characters stays literal.
fn point_cell(name: &str) -> crate::model::Cell {
    let base = name.trim_end_matches(|c: char| c.is_ascii_digit());
    let index = &name[base.len()..];
    if base.is_empty() || !base.chars().all(|c| c.is_ascii_alphabetic()) {
        return text(name);
    }
    let math = if index.is_empty() {
        math_name(base)
    } else {
        format!("{}_({index})", math_name(base))
    };
    crate::model::Cell::Text(crate::model::Text(vec![crate::model::Span::Math(math)]))
}

/// The points' speeds and accelerations read off the plans' absolute vectors.
fn plan_rows(lk: &Value) -> Vec<Vec<crate::model::Cell>> {
    let Some(plan) = lk.pointer("/plans/velocity").and_then(Value::as_array) else {
        return Vec::new();
    };
    let acc = lk
        .pointer("/plans/acceleration")
        .and_then(Value::as_array)
        .cloned()
        .unwrap_or_default();
    let mut rows = Vec::new();
    for v in plan.iter().filter(|v| v.get("kind").and_then(Value::as_str) == Some("absolute")) {
        let label = v.get("label").and_then(Value::as_str).unwrap_or("");
        let point = label.trim_start_matches("V_").trim_start_matches("v_");
        let mag = vec_len(v);
        let a = acc
            .iter()
            .find(|a| {
                a.get("kind").and_then(Value::as_str) == Some("absolute")
                    && a.get("label").and_then(Value::as_str).map(|l| l.trim_start_matches("a_")) == Some(point)
            })
            .map(vec_len);
        rows.push(vec![point_cell(point), num(mag), a.map_or(crate::model::Cell::Empty, num)]);
    }
    rows
}

/// The crank-angle ranges where a partial-range linkage assembles
/// (`/linkage/assembly_ranges`), printed as `38.62°…78.58°, 281.4°…321.4°`.
/// Whether the report's one assembly range spans the whole turn of the
/// input link (to 10⁻⁹ rad).
fn assembles_everywhere(cx: &Ctx) -> bool {
    let ranges = cx.report.pointer("/linkage/assembly_ranges").and_then(Value::as_array);
    match ranges.map(Vec::as_slice) {
        Some([r]) => {
            let (from, to) = (r.get("from").and_then(Value::as_f64), r.get("to").and_then(Value::as_f64));
            matches!((from, to), (Some(a), Some(b)) if b - a >= std::f64::consts::TAU - 1e-9)
        }
        _ => false,
    }
}

fn assembly_ranges(cx: &Ctx) -> Result<String, NoteError> {
    let ranges = cx
        .report
        .pointer("/linkage/assembly_ranges")
        .and_then(Value::as_array)
        .cloned()
        .unwrap_or_default();
    let mut out = Vec::new();
    for r in &ranges {
        let (Some(from), Some(to)) = (r.get("from").and_then(Value::as_f64), r.get("to").and_then(Value::as_f64)) else {
            continue;
        };
        // the report may give a range past 360° when it runs over 0°
        let wrap = |a: f64| {
            let d = a.to_degrees();
            if d > 360.0 + 1e-9 { d - 360.0 } else { d }
        };
        out.push(format!("{}…{}", cx.q(wrap(from), "u_deg")?, cx.q(wrap(to), "u_deg")?));
    }
    Ok(out.join(", "))
}

/// The largest pressure angle of the report's list, printed.
fn pressure_max(cx: &Ctx) -> Result<String, NoteError> {
    let list = cx.report.pointer("/linkage/pressure_angle_max").and_then(Value::as_array);
    let m = list
        .map(|l| l.iter().filter_map(|p| p.get("max").and_then(Value::as_f64)).fold(0.0, f64::max))
        .unwrap_or(0.0);
    cx.q(m.to_degrees(), "u_deg")
}

/// The oscillating cylinder's pressure angle over the lever's working turn
/// (угол давления в паре штока и рычага): at the start, at the end and the
/// largest, in degrees; `None` for any other mechanism.
///
/// The pressure angle is the angle between the force on the driven link and
/// the velocity of its point of application (Артоболевский 1988, § 24): the
/// rod pushes the lever at B along DB, and B of the lever turning about O
/// moves across OB, v_B ∥ (−sin φ, cos φ)·sign(φ_к − φ_н); so
/// θ(φ) = arccos(DB·v_B / (|DB| |v_B|)), φ from φ_н to φ_к (the synthesis'
/// shown positions), sampled at 720 steps for the largest value.
fn cylinder_pressure(cx: &Ctx) -> Option<(f64, f64, f64)> {
    if cx.s("/synthesis/kind") != Some("oscillating-cylinder") {
        return None;
    }
    let pt = |p: &str| -> Option<(f64, f64)> {
        let a = cx.report.pointer(p)?.as_array()?;
        Some((a.first()?.as_f64()?, a.get(1)?.as_f64()?))
    };
    let (o, d) = (pt("/synthesis/frame/O")?, pt("/synthesis/frame/D")?);
    let l = cx.opt("/synthesis/lengths/OB")?;
    let (start, end) = pt("/synthesis/shown_phi")?;
    let sense = if end >= start { 1.0 } else { -1.0 };
    let theta = |phi: f64| -> Option<f64> {
        let b = (o.0 + l * phi.cos(), o.1 + l * phi.sin());
        let f = (b.0 - d.0, b.1 - d.1);
        let v = (-phi.sin() * sense, phi.cos() * sense);
        let n = f.0.hypot(f.1);
        (n > 0.0).then(|| ((f.0 * v.0 + f.1 * v.1) / n).clamp(-1.0, 1.0).acos().to_degrees())
    };
    const STEPS: usize = 720;
    let mut max = 0.0_f64;
    for k in 0..=STEPS {
        max = max.max(theta(start + (end - start) * k as f64 / STEPS as f64)?);
    }
    let (a, b) = (theta(start)?, theta(end)?);
    (a.is_finite() && b.is_finite() && max.is_finite()).then_some((a, b, max))
}

/// The crank pin's speed on the velocity plan, m/s.
fn plan_speed(cx: &Ctx) -> Option<f64> {
    let (_, pin, _) = crank(cx)?;
    let plan = cx.report.pointer("/linkage/plans/velocity")?.as_array()?;
    let v = plan.iter().find(|v| {
        v.get("kind").and_then(Value::as_str) == Some("absolute")
            && v.get("label")
                .and_then(Value::as_str)
                .map(|l| l.trim_start_matches("V_").trim_start_matches("v_"))
                == Some(pin.as_str())
    })?;
    Some(vec_len(v))
}

/// The magnitude of a plan vector `{from, to}`.
fn vec_len(v: &Value) -> f64 {
    let p = |k: &str, i: usize| v.get(k).and_then(|a| a.get(i)).and_then(Value::as_f64).unwrap_or(0.0);
    (p("to", 0) - p("from", 0)).hypot(p("to", 1) - p("from", 1))
}
