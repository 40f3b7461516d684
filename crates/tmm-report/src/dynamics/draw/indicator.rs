//! The indicator diagram of each cylinder (индикаторная диаграмма): the
//! gauge pressure p against the piston's travel s from its outer dead
//! centre, one curve per process table of the task (intake, compression,
//! expansion, exhaust of a four-stroke engine; re-expansion, suction,
//! compression, delivery of a compressor) interpolated as the task says
//! (spline or linear, `tmm_linkage::forces::spline`), the table's own
//! points marked, at round scale factors μ_p (MPa per mm) and μ_s (m per
//! mm), the axes through p = 0 and s = 0 as the course draws them
//! (Chernaya & Timofeev 2019, П2, the indicator diagram of the engine).
//!
//! Each table's curve sits in a group `<g class="indicator-table"
//! data-table="NAME">`, and the root element carries the paper point of
//! s = 0, p = 0 (`data-origin="x y"`, mm, y down), so that the drawing can
//! be read back against the task's tables.

use tmm_linkage::dynamics::Dynamics;
use tmm_linkage::forces::{Indicator, SliderLoadKind, TravelScale};

use super::{Chart, XKind};
use crate::Error;
use crate::output::Documents;
use crate::paper::Slot;
use crate::picture::Picture;
use crate::project::{Language, SheetFormat};
use crate::svg::{Style, num};
use crate::words::word;

/// The colours of the processes, in the order the cylinder goes through them.
const COLORS: [&str; 6] = ["#0050c0", "#008000", "#c00000", "#a05000", "#7000a0", "#606060"];
/// Dash patterns that tell the processes apart in black and white.
const DASHES: [Option<(f64, f64)>; 6] = [Some((3.0, 1.5)), None, None, Some((1.0, 1.0)), Some((5.0, 1.5)), Some((2.0, 2.0))];
/// Intervals sampled between a table's ends (its own points are added).
const SAMPLES: usize = 240;

/// One indicator diagram per cylinder with a gas force:
/// `{prefix}indicator-{k}.svg`, k = 1, 2, … in the task's order of
/// `[[forces.cylinders]]`.
pub(crate) fn draw_all(d: &Dynamics, prefix: &str, lang: Language, sheet: SheetFormat, docs: &mut Documents) -> Result<(), Error> {
    let names = &d.reducer.unit.link_names;
    let mut k = 0;
    for a in &d.reducer.sliders {
        let SliderLoadKind::Gas { bore, indicator } = &a.load.kind else {
            continue;
        };
        k += 1;
        let link = names.get(a.load.link).map_or("?", String::as_str);
        let svg = draw(indicator, a.stroke.travel, *bore, link, lang, sheet);
        docs.add_text(format!("{prefix}indicator-{k}.svg"), svg)?;
    }
    Ok(())
}

/// The travel (m) of a table's abscissa `x` for a stroke `h` (m).
fn travel_m(scale: TravelScale, x: f64, h: f64) -> f64 {
    match scale {
        TravelScale::Metres => x,
        TravelScale::Stroke => x * h,
    }
}

/// The tables in the order the cylinder's processes first use them, each
/// with the spans of the machine's cycle (degrees) where it holds.
#[doc(hidden)]
pub fn tables_in_order(ind: &Indicator) -> Vec<(usize, Vec<(f64, f64)>)> {
    let mut out: Vec<(usize, Vec<(f64, f64)>)> = Vec::new();
    for p in &ind.processes {
        let span = (p.from.to_degrees(), p.to.to_degrees());
        match out.iter_mut().find(|(t, _)| *t == p.table) {
            Some((_, spans)) => {
                // spans that meet are one
                if let Some(last) = spans.last_mut()
                    && (last.1 - span.0).abs() < 1e-9
                {
                    last.1 = span.1;
                } else {
                    spans.push(span);
                }
            }
            None => out.push((p.table, vec![span])),
        }
    }
    out
}

/// The name of a process in `lang` (the task's own name when the words
/// have none).
fn process_name(name: &str, lang: Language) -> String {
    let key = format!("dynamics.process_{}", name.replace('-', "_"));
    let w = word(lang, &key);
    if w == key { name.to_string() } else { w.to_string() }
}

/// The diagram of one cylinder: its `indicator` for a stroke `h` (m), bore
/// `bore` (m), piston `link`.
fn draw(ind: &Indicator, h: f64, bore: f64, link: &str, lang: Language, sheet: SheetFormat) -> Picture {
    let wd = |k: &str| word(lang, &format!("dynamics.{k}")).to_string();
    const MPA: f64 = 1e6;
    // every curve, sampled, in (m, MPa)
    let order = tables_in_order(ind);
    let curves: Vec<Vec<(f64, f64)>> = order
        .iter()
        .map(|(t, _)| {
            let c = &ind.tables[*t];
            let end = ind.travel.end(h);
            let mut xs: Vec<f64> = (0..=SAMPLES).map(|i| end * i as f64 / SAMPLES as f64).collect();
            xs.extend(c.x.iter().copied().filter(|x| (0.0..=end).contains(x)));
            xs.sort_by(f64::total_cmp);
            xs.dedup_by(|a, b| (*a - *b).abs() <= 1e-12 * end.max(1e-300));
            xs.iter()
                .map(|&x| (travel_m(ind.travel, x, h), c.eval(x) * ind.pressure_scale / MPA))
                .collect()
        })
        .collect();
    let fold = |f: fn(f64, f64) -> f64, init: f64, y: bool| curves.iter().flatten().map(|p| if y { p.1 } else { p.0 }).fold(init, f);
    let yr = (fold(f64::min, f64::INFINITY, true), fold(f64::max, f64::NEG_INFINITY, true));
    // the name; the bore, a parameter, goes in the legend
    let title = format!("{} {link}", wd("title_indicator"));
    let mut ch = Chart::new(
        lang,
        sheet,
        Slot::Small,
        &title,
        ("p", &wd("unit_mpa")),
        yr,
        true,
        XKind::Other("s".into(), wd("unit_m")),
        (0.0, h.max(fold(f64::max, 0.0, false))),
    );
    let origin = ch.map(0.0, 0.0);
    ch.c.root_attr("data-origin", &format!("{:.4} {:.4}", origin.0, origin.1));
    // the p axis at the outer dead centre (s = 0), the s axis at p = 0
    let (_, ytop) = ch.map(0.0, ch.y.lo + ch.y.len * ch.y.mu);
    let (_, ybot) = ch.map(0.0, ch.y.lo);
    ch.c.line_paper((origin.0, ybot), (origin.0, ytop), Style::THIN.widened(0.35));
    let (xr, _) = ch.map(ch.x.lo + ch.x.len * ch.x.mu, 0.0);
    ch.c.line_paper((origin.0, origin.1), (xr, origin.1), Style::THIN.widened(0.35));
    let (hx, _) = ch.map(h, 0.0);
    ch.c.line_paper((hx, ybot), (hx, ytop), Style::DASHED.colored("#606060"));
    ch.c.label_paper((hx, ytop + 3.0), "H", 2.5, "#606060");
    for (k, ((t, spans), pts)) in order.iter().zip(&curves).enumerate() {
        let color = COLORS[k % COLORS.len()];
        let name = &ind.names[*t];
        let spans: Vec<String> = spans
            .iter()
            .map(|(a, b)| format!("{}…{}°", num(*a, 0, lang), num(*b, 0, lang)))
            .collect();
        let label = format!("{}, φ {}", process_name(name, lang), spans.join(", "));
        ch.c.begin_group_data("indicator-table", &[("data-table", name.as_str())]);
        ch.curve(pts, color, &label, DASHES[k % DASHES.len()]);
        ch.c.end_group();
        // the table's own points
        let c = &ind.tables[*t];
        let hgt = ch.c.size().1;
        for (&x, &y) in c.x.iter().zip(&c.y) {
            let p = ch.map(travel_m(ind.travel, x, h), y * ind.pressure_scale / MPA);
            ch.c.dot((p.0, hgt - p.1), 0.45, color);
        }
    }
    ch.note(&format!("H = {} {}", num(h, 4, lang), wd("unit_m")));
    ch.note(&format!("d = {} {}", num(bore * 1000.0, 1, lang), wd("unit_mm")));
    ch.finish()
}
