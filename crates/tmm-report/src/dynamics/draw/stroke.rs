//! The diagrams of the unsteady single stroke against φ in degrees from
//! the start of the cycle: ω(φ) of both models with the motor's
//! synchronous and breakdown speeds, t(φ) with the cycle time, ε(φ), and
//! the reduced moments (the loads', the motor's, the constant one).

use tmm_linkage::dynamics::SingleStroke;

use super::{BLUE, BROWN, Chart, GREEN, GREY, PURPLE, RED, XKind, range};
use crate::Error;
use crate::output::Documents;
use crate::paper::Slot;
use crate::project::{Language, SheetFormat};
use crate::svg::num;
use crate::words::word;

/// Every diagram of the single stroke, under `prefix`.
pub fn draw_all(s: &SingleStroke, prefix: &str, lang: Language, sheet: SheetFormat, docs: &mut Documents) -> Result<(), Error> {
    let wd = |k: &str| word(lang, &format!("dynamics.{k}")).to_string();
    let ws = |k: &str| word(lang, &format!("stroke.{k}")).to_string();
    let m = &s.motor;
    let e = &s.energy;
    let mo = &s.spec.motor;
    let (u_w, u_e, u_s, u_nm) = (wd("unit_radps"), wd("unit_radps2"), wd("unit_s"), wd("unit_nm"));
    let marks: Vec<f64> = (0..12).map(|k| 30.0 * k as f64).collect();
    let xr = (0.0, s.reducer.period.to_degrees());
    let chart = |title: &str, y: (&str, &str), yr: (f64, f64), zero: bool| {
        Chart::new(lang, sheet, Slot::Diagram, title, y, yr, zero, XKind::Phi(marks.clone()), xr)
    };
    let xy1 = |f: &dyn Fn(&tmm_linkage::dynamics::StrokeRow) -> f64| -> Vec<(f64, f64)> {
        m.rows.iter().map(|r| (r.phi.to_degrees(), f(r))).collect()
    };
    let xy2 = |f: &dyn Fn(&tmm_linkage::dynamics::EnergyRow) -> f64| -> Vec<(f64, f64)> {
        e.rows.iter().map(|r| (r.phi.to_degrees(), f(r))).collect()
    };
    let (n1, n2) = (ws("model_motor"), ws("model_constant"));

    // the speed
    let (w0, wk) = (mo.crank_synchronous_speed(), mo.crank_breakdown_speed());
    let yr = range(
        m.rows
            .iter()
            .map(|r| r.omega)
            .chain(e.rows.iter().map(|r| r.omega))
            .chain([w0, wk, s.spec.start_speed]),
    );
    let mut ch = chart(&ws("title_omega"), ("ω_1", &u_w), yr, true);
    ch.curve(&xy1(&|r| r.omega), GREEN, &n1, None);
    ch.curve(&xy2(&|r| r.omega), BLUE, &n2, Some((2.0, 1.0)));
    ch.level(w0, GREY, "ω_0", &format!("{} {u_w}", num(w0, 4, lang)));
    ch.level(wk, RED, "ω_K", &format!("{} {u_w}", num(wk, 4, lang)));
    for c in &m.crossings {
        ch.mark(
            c.phi.to_degrees(),
            wk,
            &format!("φ = {}°, t = {} {u_s}", num(c.phi.to_degrees(), 1, lang), num(c.time, 3, lang)),
            RED,
        );
    }
    docs.add_text(format!("{prefix}stroke-omega.svg"), ch.finish())?;

    // the time
    let yr = range(m.rows.iter().map(|r| r.time).chain(e.rows.iter().map(|r| r.time)));
    let mut ch = chart(&ws("title_time"), ("t", &u_s), yr, true);
    ch.curve(&xy1(&|r| r.time), GREEN, &n1, None);
    ch.curve(&xy2(&|r| r.time), BLUE, &n2, Some((2.0, 1.0)));
    ch.note(&format!("t_ц1 = {} {u_s}", num(m.cycle_time, 4, lang)));
    ch.note(&format!("t_ц2 = {} {u_s}", num(e.time_end, 4, lang)));
    docs.add_text(format!("{prefix}stroke-time.svg"), ch.finish())?;

    // the acceleration
    let yr = range(m.rows.iter().map(|r| r.epsilon).chain(e.rows.iter().map(|r| r.epsilon)));
    let mut ch = chart(&ws("title_epsilon"), ("ε_1", &u_e), yr, true);
    ch.curve(&xy1(&|r| r.epsilon), BROWN, &n1, None);
    ch.curve(&xy2(&|r| r.epsilon), BLUE, &n2, Some((2.0, 1.0)));
    docs.add_text(format!("{prefix}stroke-epsilon.svg"), ch.finish())?;

    // the reduced moments
    let md2 = e.driving_moment;
    let yr = range(m.rows.iter().flat_map(|r| [r.moment_loads, r.moment_motor]).chain([md2]));
    let mut ch = chart(&ws("title_moments"), ("M", &u_nm), yr, true);
    ch.curve(&xy1(&|r| r.moment_loads), RED, "M_c", None);
    ch.curve(&xy1(&|r| r.moment_motor), GREEN, &ws("sym_motor"), None);
    ch.curve(
        &[(0.0, md2), (xr.1, md2)],
        PURPLE,
        &format!("{} = {} {u_nm}", ws("sym_constant"), num(md2, 1, lang)),
        Some((2.0, 1.0)),
    );
    docs.add_text(format!("{prefix}stroke-moments.svg"), ch.finish())?;
    Ok(())
}
