//! The diagrams of `[cylinder]` against the piston's travel s: the reduced
//! mass m_пр(s), the speed V(s), the acceleration a(s), the time t(s)
//! (left open at s_max when the end is reached only asymptotically) and
//! the reduced forces — the resistance F_прC, the control force F_прДВ and
//! their sum — with the symbols of the drawing's language (`cylinder.sym_*`:
//! m_зв, F_звC … in Ukrainian, m_red, F_c, F_d, F_Σ in English).

use tmm_linkage::linear::{EndReached, MotionRow};

use super::{BLUE, BROWN, Chart, GREEN, PURPLE, RED, XKind, range};
use crate::Error;
use crate::cylinder::Analysis;
use crate::output::Documents;
use crate::paper::Slot;
use crate::project::{Language, SheetFormat};
use crate::svg::num;
use crate::words::word;

/// Every diagram, under `prefix`.
pub fn draw_all(a: &Analysis, prefix: &str, lang: Language, sheet: SheetFormat, docs: &mut Documents) -> Result<(), Error> {
    let wc = |k: &str| word(lang, &format!("cylinder.{k}")).to_string();
    let mo = &a.motion;
    let rows = &mo.rows;
    let smax = mo.control.travel;
    let xr = (0.0, smax);
    let chart = |title: &str, y: (&str, &str), yr: (f64, f64)| {
        Chart::new(
            lang,
            sheet,
            Slot::Diagram,
            title,
            y,
            yr,
            true,
            XKind::Other("s".into(), wc("unit_m")),
            xr,
        )
    };
    let xy = |f: &dyn Fn(&MotionRow) -> f64| -> Vec<(f64, f64)> { rows.iter().map(|r| (r.reduced.s, f(r))).collect() };

    let yr = range(rows.iter().map(|r| r.reduced.mass));
    let mut ch = chart(&wc("title_mass"), (&wc("sym_mass"), &wc("unit_kg")), yr);
    ch.curve(&xy(&|r| r.reduced.mass), BLUE, &wc("sym_mass"), None);
    docs.add_text(format!("{prefix}mass.svg"), ch.finish())?;

    let yr = range(rows.iter().map(|r| r.speed));
    let mut ch = chart(&wc("title_speed"), ("V", &wc("unit_mps")), yr);
    ch.curve(&xy(&|r| r.speed), GREEN, "V", None);
    ch.mark(
        a.reactions.s,
        a.reactions.speed,
        &format!("s = {} {}", num(a.reactions.s, 3, lang), wc("unit_m")),
        RED,
    );
    docs.add_text(format!("{prefix}speed.svg"), ch.finish())?;

    let yr = range(rows.iter().map(|r| r.accel));
    let mut ch = chart(&wc("title_accel"), ("a", &wc("unit_mps2")), yr);
    ch.curve(&xy(&|r| r.accel), BROWN, "a", None);
    docs.add_text(format!("{prefix}accel.svg"), ch.finish())?;

    let timed: Vec<(f64, f64)> = rows.iter().filter_map(|r| r.time.map(|t| (r.reduced.s, t))).collect();
    let yr = range(timed.iter().map(|p| p.1));
    let mut ch = chart(&wc("title_time"), ("t", &wc("unit_s")), yr);
    ch.curve(&timed, PURPLE, "t", None);
    match mo.end {
        EndReached::Asymptotic { time_constant } => {
            ch.note(&wc("time_asymptotic"));
            if let Some(tau) = time_constant {
                ch.note(&format!("τ = {} {}", num(tau, 4, lang), wc("unit_s")));
            }
        }
        EndReached::Finite { time } => ch.note(&format!("t(s_max) = {} {}", num(time, 4, lang), wc("unit_s"))),
    }
    docs.add_text(format!("{prefix}time.svg"), ch.finish())?;

    let yr = range(rows.iter().flat_map(|r| [r.reduced.force, r.control, r.total]));
    let mut ch = chart(&wc("title_forces"), ("F", &wc("unit_n")), yr);
    ch.curve(&xy(&|r| r.reduced.force), RED, &wc("sym_fc"), None);
    ch.curve(&xy(&|r| r.control), GREEN, &wc("sym_fd"), None);
    ch.curve(&xy(&|r| r.total), BLUE, &wc("sym_fsum"), Some((2.0, 1.0)));
    ch.note(&format!("F_H = {} {}", num(mo.control.start, 1, lang), wc("unit_n")));
    ch.note(&format!("F_K = {} {}", num(mo.control.end, 1, lang), wc("unit_n")));
    docs.add_text(format!("{prefix}forces.svg"), ch.finish())?;
    Ok(())
}
