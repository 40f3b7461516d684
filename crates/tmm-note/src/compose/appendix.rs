//! The appendices (приложения): the full tables over the 12 positions of
//! the crank — kinematics, kinetostatics and dynamics.

use serde_json::Value;

use super::context::{Ctx, num, text};
use crate::error::NoteError;
use crate::model::{Block, Cell, Section};

/// The appendices the report has data for.
pub(crate) fn appendices(cx: &Ctx) -> Result<Vec<Section>, NoteError> {
    let mut out = Vec::new();
    if let Some(p) = cx.report.pointer("/linkage/positions").and_then(Value::as_array) {
        let mut s = Section::new(cx.w("app_kinematics")?);
        let names: Vec<String> = p
            .first()
            .and_then(|p| p.get("links"))
            .and_then(Value::as_object)
            .map(|l| l.keys().cloned().collect())
            .unwrap_or_default();
        for (key, unit, caption) in [("omega", "u_rad_s", "tab_app_omega"), ("epsilon", "u_rad_s2", "tab_app_epsilon")] {
            // a slider input's positions are its travel s (mm), a crank's its angle φ
            let slider = p.first().and_then(|p| p.get("s")).is_some();
            let mut header = vec![cx.w("col_position")?, if slider { "s".to_string() } else { cx.w("col_phi")? }];
            let mut units = vec![String::new(), cx.w(if slider { "u_mm" } else { "u_deg" })?];
            for n in &names {
                // ω₁, ε₁ as the course writes them; a link's name other than
                // letters and digits stays literal after the letter
                let g = if key == "omega" { "ω" } else { "ε" };
                header.push(if !n.is_empty() && n.chars().all(|c| c.is_ascii_alphanumeric()) {
                    crate::notation::notation(&format!("{g}_{n}"))
                } else {
                    format!("{g}{n}")
                });
                units.push(cx.w(unit)?);
            }
            let mut rows = Vec::new();
            for pos in p {
                let mut r = vec![
                    text(pos.get("label").and_then(Value::as_str).unwrap_or("")),
                    num(if slider {
                        pos.get("s").and_then(Value::as_f64).unwrap_or(0.0) * 1e3
                    } else {
                        pos.get("phi").and_then(Value::as_f64).unwrap_or(0.0).to_degrees()
                    }),
                ];
                for n in &names {
                    r.push(
                        pos.pointer(&format!("/links/{n}/{key}"))
                            .and_then(Value::as_f64)
                            .map_or(Cell::Empty, num),
                    );
                }
                rows.push(r);
            }
            s.blocks.push(Block::Table {
                caption: cx.w(caption)?,
                header,
                rows,
                units,
                label: None,
            });
        }
        out.push(s);
    }
    if let Some(p) = cx.report.pointer("/forces/positions").and_then(Value::as_array) {
        let mut s = Section::new(cx.w("app_forces")?);
        let rows = p
            .iter()
            .map(|pos| {
                let g = |k: &str| pos.get(k).and_then(Value::as_f64).unwrap_or(0.0);
                let rmax = pos
                    .get("reactions")
                    .and_then(Value::as_array)
                    .map(|r| {
                        r.iter()
                            .filter_map(|r| r.get("magnitude").and_then(Value::as_f64))
                            .fold(0.0, f64::max)
                    })
                    .unwrap_or(0.0);
                vec![
                    text(pos.get("label").and_then(Value::as_str).unwrap_or("")),
                    num(g("phi").to_degrees()),
                    num(g("balancing_moment")),
                    num(g("balancing_force")),
                    num(g("zhukovsky_moment")),
                    num(rmax),
                ]
            })
            .collect();
        s.blocks.push(cx.table(
            "tab_app_forces",
            &[
                ("col_position", ""),
                ("col_phi", "u_deg"),
                ("col_mb", "u_nm"),
                ("col_pb", "u_n"),
                ("col_mzh", "u_nm"),
                ("col_rmax", "u_n"),
            ],
            rows,
        )?);
        out.push(s);
    }
    if let Some(p) = cx.report.pointer("/dynamics/positions").and_then(Value::as_array) {
        let mut s = Section::new(cx.w("app_dynamics")?);
        let rows = p
            .iter()
            .map(|pos| {
                let g = |k: &str| pos.get(k).and_then(Value::as_f64).unwrap_or(0.0);
                // the crank's absolute angle, as appendices А and Б print it
                // (φ of the dynamics runs from the start of the working stroke)
                let phi = pos.get("crank_angle").and_then(Value::as_f64).unwrap_or(g("phi"));
                vec![
                    text(pos.get("index").map(|v| v.to_string()).unwrap_or_default()),
                    num(phi.to_degrees().rem_euclid(360.0)),
                    num(g("reduced_inertia_variable")),
                    num(g("reduced_moment")),
                    num(g("work")),
                    num(g("kinetic_energy_change")),
                    num(g("omega")),
                ]
            })
            .collect();
        s.blocks.push(cx.table(
            "tab_app_dynamics",
            &[
                ("col_position", ""),
                ("col_phi", "u_deg"),
                ("col_i2", "u_kgm2"),
                ("col_mc", "u_nm"),
                ("col_ac", "u_j"),
                ("col_dt", "u_j"),
                ("col_omega1", "u_rad_s"),
            ],
            rows,
        )?);
        out.push(s);
    }
    Ok(out)
}
