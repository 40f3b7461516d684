//! The technical assignment (техническое задание): the task's data as
//! tables, one per part of the project, from the report's given values.

use super::context::{Ctx, num, text};
use super::linkage::link_lengths;
use crate::error::NoteError;
use crate::model::{Block, Cell};

/// The assignment's blocks.
pub(crate) fn blocks(cx: &Ctx) -> Result<Vec<Block>, NoteError> {
    let mut b = vec![cx.para("assign_intro", &[])?];
    // a synthesised mechanism: the task gives the synthesis' data (П3's
    // H, K, λ, l_BC, l_OC), not the lengths it finds
    let synthesised = cx.report.get("synthesis").is_some();
    if synthesised {
        b.push(cx.quantities("assign_synthesis", super::synthesis::given_rows(cx)?)?);
    }
    if cx.report.get("linkage").is_some() {
        let mut rows: Vec<Vec<Cell>> = Vec::new();
        for (name, l) in link_lengths(cx) {
            rows.push(vec![text(cx.fill("link_n", &[name])?), num(l * 1000.0)]);
        }
        if !synthesised {
            b.push(cx.table("assign_links", &[("col_link", ""), ("col_length", "u_mm")], rows)?);
        }
        if cx.s("/linkage/input/kind") == Some("slider") {
            let mm = |ptr: &str| -> Result<String, NoteError> { cx.q(cx.v(ptr)? * 1e3, "u_mm") };
            let q = vec![
                (cx.w("q_slider_speed")?, cx.q(cx.v("/linkage/input/speed")?, "u_m_s")?),
                (cx.w("q_slider_from")?, mm("/linkage/input/travel/from")?),
                (cx.w("q_slider_to")?, mm("/linkage/input/travel/to")?),
                (cx.w("q_slider_position")?, mm("/linkage/plans/s")?),
            ];
            b.push(cx.quantities("assign_linkage", q)?);
        } else {
            let omega = cx.v("/linkage/input/omega")?;
            let mut q = vec![
                (cx.w("q_omega1")?, cx.q(omega, "u_rad_s")?),
                (cx.w("q_n1")?, cx.q(omega.abs() * 30.0 / std::f64::consts::PI, "u_rpm")?),
            ];
            // the time of one turn T = 60/n1
            if omega != 0.0 {
                q.push((cx.w("q_revolution_time")?, cx.q(std::f64::consts::TAU / omega.abs(), "cy_u_s")?));
            }
            q.push((cx.w("q_position")?, cx.deg("/linkage/plans/phi")?));
            b.push(cx.quantities("assign_linkage", q)?);
        }
    }
    if cx.report.get("forces").is_some() {
        let mut rows = Vec::new();
        if let Some(links) = cx.report.pointer("/forces/links").and_then(|v| v.as_object()) {
            for (name, l) in links {
                let m = l.get("mass").and_then(|v| v.as_f64()).unwrap_or(0.0);
                let j = l.get("inertia").and_then(|v| v.as_f64()).unwrap_or(0.0);
                rows.push(vec![text(cx.fill("link_n", std::slice::from_ref(name))?), num(m), num(j)]);
            }
        }
        b.push(cx.table(
            "assign_masses",
            &[("col_link", ""), ("col_mass", "u_kg"), ("col_inertia", "u_kgm2")],
            rows,
        )?);
    }
    if cx.report.get("dynamics").is_some() && cx.s("/dynamics/motion") != Some("single-stroke") {
        b.push(cx.quantities(
            "assign_dynamics",
            vec![
                (cx.w("q_delta")?, cx.given("/dynamics/delta_requested", 1.0, "")?),
                (cx.w("q_omega_m")?, cx.qv("/dynamics/omega_nominal", 1.0, "u_rad_s")?),
            ],
        )?);
    }
    if cx.report.get("gear").is_some() {
        b.push(cx.quantities("assign_gear", super::gear::given_rows(cx)?)?);
    }
    if cx.report.get("planetary").is_some() {
        b.push(cx.quantities(
            "assign_planetary",
            vec![
                (cx.w("q_ratio")?, cx.qv("/planetary/request/ratio", 1.0, "")?),
                (cx.w("q_planets")?, format!("{}", cx.v("/planetary/request/planets")?)),
                (cx.w("q_module")?, cx.qv("/planetary/request/module", 1000.0, "u_mm")?),
                (cx.w("q_omega_sun")?, cx.qv("/planetary/request/omega1", 1.0, "u_rad_s")?),
            ],
        )?);
    }
    if cx.report.get("cam").is_some() {
        b.push(cx.quantities("assign_cam", super::cam::given_rows(cx)?)?);
    }
    if cx.report.get("cylinder").is_some() {
        b.push(cx.quantities("assign_cylinder", super::cylinder::given_rows(cx)?)?);
    }
    b.push(cx.para("assign_rounding", &[super::DIGITS.to_string()])?);
    Ok(b)
}
