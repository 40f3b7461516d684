//! The cam's motion diagrams (диаграммы движения толкателя) as the course
//! draws them: one panel per quantity over one turn of the cam, 0 … 360°,
//! at round scale factors μ (written under each title), the phase
//! boundaries φу, φдс, φв, φбс marked, the jumps kept as vertical steps and
//! the impacts drawn as arrows; words in the project's language.
//!
//! Each panel is a `Slot::Diagram` box of the sheet; a file stacks its panels
//! one under another. Every panel is a `<g class="diagram">` carrying its
//! scale factors and the paper position of its axes (`data-mu-y`,
//! `data-mu-phi`, `data-x0`, `data-y-zero`) so the drawing can be read back.

use tmm_cams::design::CamTask;
use tmm_cams::program::PhaseKind;

use crate::labels::{H_LABEL, H_TITLE, Placer, finish};
use crate::paper::{Slot, round_mu, slot_mm};
use crate::picture::Picture;
use crate::project::{Language, SheetFormat};
use crate::svg::{Canvas, Style, mu_text};
use crate::words::word;

/// Lettering of the scale lines and tick values (GOST 2.304: 2.5 mm).
const H_SMALL: f64 = 2.5;

/// An impact (удар) at a jump: an arrow at the cam angle `phi_deg`, up when
/// `sign` > 0, with its label.
pub struct Arrow {
    /// Cam angle, degrees.
    pub phi_deg: f64,
    /// The sign of the jump.
    pub sign: f64,
    /// `Δv = 2,6 м/с`.
    pub label: String,
}

/// A horizontal line at a value (an allowed pressure angle) with its label.
pub struct Level {
    /// The value in the panel's unit.
    pub value: f64,
    /// What it is.
    pub label: String,
}

/// One diagram: a quantity over the cam angle.
pub struct Panel {
    /// The title (translated).
    pub title: String,
    /// The quantity's symbol as drawn (`s`, `ds/dφ`, `ϑ`).
    pub sym: String,
    /// The symbol in the scale factor's subscript (`s`, `v`).
    pub mu_sym: String,
    /// The unit (translated).
    pub unit: String,
    /// (cam angle in degrees 0 … 360, value); a non-finite value lifts the pen.
    pub pts: Vec<(f64, f64)>,
    /// Impacts drawn as arrows.
    pub arrows: Vec<Arrow>,
    /// Horizontal levels (allowed values).
    pub levels: Vec<Level>,
}

/// The phase boundaries of the task in degrees (0, …, 360) and each phase's
/// symbol (φу, φдс, φв, φбс in Russian).
pub fn phases(task: &CamTask, lang: Language) -> (Vec<f64>, Vec<String>) {
    let prog = &task.program;
    let mut bounds = vec![0.0];
    let mut names = Vec::new();
    for (i, ph) in prog.phases().iter().enumerate() {
        bounds.push((prog.start(i) + ph.angle).to_degrees());
        let key = match ph.kind {
            PhaseKind::Rise => "cam.phase_rise",
            PhaseKind::Return => "cam.phase_return",
            PhaseKind::Dwell if prog.level_before(i) > 0.5 * prog.stroke() => "cam.phase_far",
            PhaseKind::Dwell => "cam.phase_near",
        };
        names.push(word(lang, key).to_string());
    }
    (bounds, names)
}

/// The scale factor of the cam angle, ° per mm, for a panel `w` mm wide:
/// 360° over the width less the margins, rounded up to a round μ.
///
/// ```
/// use tmm_report::cam::diagrams::mu_phi;
/// assert_eq!(mu_phi(260.0), 2.0); // A1: 360° over 224 mm → 2 °/mm, 180 mm drawn
/// assert_eq!(mu_phi(180.0), 2.5); // A2: 360° over 144 mm exactly
/// ```
pub fn mu_phi(w: f64) -> f64 {
    round_mu(360.0 / (w - LEFT - RIGHT))
}

const LEFT: f64 = 24.0;
const RIGHT: f64 = 12.0;
const TOP: f64 = 24.0;
const BOTTOM: f64 = 16.0;
/// The band over the panels that holds the name of a drawing of several
/// panels, mm: its 5 mm letters and their clearance.
const NAME_BAND: f64 = 12.0;
/// The length of an impact's arrow, mm.
const IMPACT_MM: f64 = 9.0;
/// The paper between a label's printed ink and every line and every other
/// label, mm.
pub const LABEL_CLEAR: f64 = 1.0;

/// An arrowhead: its tip, the unit direction it points, its length (paper mm).
type Head = ((f64, f64), (f64, f64), f64);

/// A panel's vertical frame: its top on the paper, the range of its
/// values, their scale factor and the paper height of the zero line.
#[derive(Clone, Copy)]
struct Frame {
    y_off: f64,
    ymin: f64,
    ymax: f64,
    mu_y: f64,
    y_zero: f64,
}

impl Frame {
    /// (cam angle in degrees, value) to paper mm at μ_φ `mu_p`.
    fn map(&self, mu_p: f64, x: f64, y: f64) -> (f64, f64) {
        (LEFT + x / mu_p, self.y_zero - y / self.mu_y)
    }
}

/// Draw `panels` one under another, each in a `Slot::Diagram` box of
/// `sheet` (on the note's page, the page's height shared between them); `omega` (rad/s) adds the time scale μ_t to the scale line.
pub fn draw(task: &CamTask, panels: &[Panel], name: Option<&str>, lang: Language, sheet: SheetFormat, omega: Option<f64>) -> Picture {
    let (w, mut ph) = slot_mm(Slot::Diagram, sheet);
    if sheet == SheetFormat::A4 {
        // the note's page: the panels share its height
        ph = ph.min(crate::paper::NOTE_HEIGHT_MM / panels.len().max(1) as f64);
    }
    // a drawing of several panels has its name in a band over them (the
    // panels' titles name each panel); one panel's title is the name
    let name = name.filter(|_| panels.len() > 1);
    let band = if name.is_some() { NAME_BAND } else { 0.0 };
    // the band comes out of the panels' heights, so the drawing keeps its
    // slots on the sheet
    ph -= band / panels.len().max(1) as f64;
    let total = band + ph * panels.len().max(1) as f64;
    let mut c = Canvas::new(w, total);
    let mut lab = Placer::new(w, total);
    let (bounds, names) = phases(task, lang);
    let mu_p = mu_phi(w);
    let per_mm = word(lang, "cam.per_mm");
    let deg = word(lang, "cam.unit_deg");
    // the lines of every panel first, then their labels, each placed
    // where its ink keeps LABEL_CLEAR from every line and every other label
    let mut frames = Vec::with_capacity(panels.len());
    let mut curves: Vec<(f64, f64)> = Vec::new();
    // the arrowheads: (tip, the unit direction, the head's length)
    let mut heads: Vec<Head> = Vec::new();
    for (k, p) in panels.iter().enumerate() {
        let y_off = band + ph * k as f64;
        let (mut ymin, mut ymax) = (0.0f64, 0.0f64);
        for q in p.pts.iter().filter(|q| q.1.is_finite()) {
            ymin = ymin.min(q.1);
            ymax = ymax.max(q.1);
        }
        for l in &p.levels {
            ymin = ymin.min(l.value);
            ymax = ymax.max(l.value);
        }
        if ymax - ymin < 1e-300 {
            ymax = ymin + 1.0;
        }
        let avail = ph - TOP - BOTTOM;
        let mu_y = round_mu((ymax - ymin) / avail);
        let used = (ymax - ymin) / mu_y;
        let y_zero = y_off + TOP + 0.5 * (avail - used) + ymax / mu_y;
        let f = Frame {
            y_off,
            ymin,
            ymax,
            mu_y,
            y_zero,
        };
        let map = |x: f64, y: f64| f.map(mu_p, x, y);
        c.begin_group_data(
            "diagram",
            &[
                ("data-quantity", &p.mu_sym),
                ("data-mu-y", &format!("{mu_y}")),
                ("data-mu-phi", &format!("{mu_p}")),
                ("data-x0", &format!("{LEFT}")),
                ("data-y-zero", &format!("{y_zero:.4}")),
            ],
        );
        // the axes
        let (x0, yz) = map(0.0, 0.0);
        let (x1, _) = map(360.0, 0.0);
        let (_, ytop) = map(0.0, ymax);
        let (_, ybot) = map(0.0, ymin);
        c.arrow_paper((x0, yz), (x1 + 8.0, yz), Style::THIN, 3.0);
        c.arrow_paper((x0, ybot.max(yz) + 1.0), (x0, ytop - 5.0), Style::THIN, 3.0);
        heads.push(((x1 + 8.0, yz), (1.0, 0.0), 3.0));
        heads.push(((x0, ytop - 5.0), (0.0, -1.0), 3.0));
        // the y ticks every 10 mm at the round μ
        for (_, v) in crate::paper::grid_values(ymin, ymax, 10.0 * mu_y) {
            let (_, yp) = map(0.0, v);
            c.line_paper((x0 - 1.2, yp), (x0, yp), Style::THIN);
        }
        // the phase boundaries: thin lines across the panel
        c.begin_group_data("phase-marks", &[]);
        for &b in &bounds {
            let (xp, _) = map(b, 0.0);
            c.begin_group_data("phase-mark", &[("data-phi", &format!("{b}"))]);
            c.line_paper((xp, ytop.min(yz) - 2.0), (xp, ybot.max(yz) + 2.0), Style::THIN.colored("#777777"));
            c.end_group();
        }
        c.end_group();
        // allowed levels, dashed
        for l in &p.levels {
            let (_, yl) = map(0.0, l.value);
            c.line_paper((x0, yl), (x1, yl), Style::DASHED.colored("#c62828"));
        }
        // the curve, thick
        let curve = crate::svg::mapped_path(&p.pts, map);
        c.path_paper(Some("curve"), &curve, Style::THICK.widened(0.7).colored("#000"));
        curves.extend(curve);
        curves.push((f64::NAN, f64::NAN));
        // impacts: arrows from the axis
        for a in &p.arrows {
            let (xp, _) = map(a.phi_deg, 0.0);
            c.arrow_paper(
                (xp, yz),
                (xp, yz - a.sign.signum() * IMPACT_MM),
                Style::THIN.widened(0.35).colored("#c62828"),
                2.5,
            );
            heads.push(((xp, yz - a.sign.signum() * IMPACT_MM), (0.0, -a.sign.signum()), 2.5));
        }
        c.end_group();
        frames.push(f);
    }
    // the lines the labels keep off: every stroke, the curves' chords
    let mut segs: Vec<crate::line_grid::Segment> = c.segments().to_vec();
    segs.extend(
        curves
            .windows(2)
            .filter(|w| w.iter().all(|q| q.0.is_finite() && q.1.is_finite()))
            .map(|w| (w[0], w[1])),
    );
    // and the arrowheads' edges (the canvas keeps their shafts only)
    segs.extend(heads.iter().flat_map(|&(tip, (ux, uy), len)| {
        let w = 0.3 * len;
        let (bx, by) = (tip.0 - len * ux, tip.1 - len * uy);
        let (l, r) = ((bx - w * uy, by + w * ux), (bx + w * uy, by - w * ux));
        [(tip, l), (l, r), (r, tip)]
    }));
    lab.avoid_lines(&segs);
    lab.keep_clear(LABEL_CLEAR);
    if let Some(name) = name {
        lab.put_title((0.5 * w, 0.5 * NAME_BAND + 1.0), name, H_TITLE - 2.0);
    }
    for (p, f) in panels.iter().zip(&frames) {
        let map = |x: f64, y: f64| f.map(mu_p, x, y);
        let y_off = f.y_off;
        // the title and, under it, the scale factors
        // a drawing of one panel: its title is the drawing's name; of
        // several, each panel's title names that panel and stays
        if panels.len() == 1 {
            lab.put_title((0.5 * w, y_off + 6.0), &p.title, H_TITLE - 2.0);
        } else {
            lab.put((0.5 * w, y_off + 6.0), &p.title, H_TITLE - 2.0, "#000");
        }
        let unit_per = if p.unit.contains('/') {
            format!("({}){per_mm}", p.unit)
        } else {
            format!("{}{per_mm}", p.unit)
        };
        let mut scales = format!(
            "μ_{} = {} {unit_per},   μ_φ = {} {deg}{per_mm}",
            p.mu_sym,
            mu_text(f.mu_y, lang),
            mu_text(mu_p, lang)
        );
        if let Some(om) = omega {
            let mu_t = mu_p.to_radians() / om * 1e3;
            scales.push_str(&format!(
                ",   μ_t = {} {}{per_mm}",
                crate::labels::num(lang, mu_t, 4),
                word(lang, "cam.unit_ms")
            ));
        }
        lab.put((0.5 * w, y_off + 12.5), &scales, H_SMALL + 0.5, "#000");
        let (x0, yz) = map(0.0, 0.0);
        let (x1, _) = map(360.0, 0.0);
        let (_, ytop) = map(0.0, f.ymax);
        let (_, ybot) = map(0.0, f.ymin);
        lab.put_left((x0 + 2.5, ytop - 4.5), &format!("{}, {}", p.sym, p.unit), H_SMALL + 0.5, "#000");
        lab.put((x1 + 9.0, yz + 3.5), "φ", H_LABEL, "#000");
        // the tick values, their ink ending LABEL_CLEAR left of the tick
        for (t, v) in crate::paper::grid_values(f.ymin, f.ymax, 10.0 * f.mu_y) {
            let (_, yp) = map(0.0, v);
            if t != 0 {
                let txt = mu_text(v.abs(), lang);
                let txt = if v < 0.0 { format!("−{txt}") } else { txt };
                let ink = crate::labels::ink_rect((0.0, 0.0), &txt, H_SMALL, true);
                lab.put_left((x0 - 1.2 - LABEL_CLEAR - 0.3 - ink.x1, yp), &txt, H_SMALL, "#000");
            }
        }
        // the allowed levels' names over or under their lines
        for l in &p.levels {
            let (_, yl) = map(0.0, l.value);
            let n = crate::labels::plain(&l.label).chars().count() as f64;
            let wl = crate::labels::CHAR_WIDTH * crate::picture::em(H_SMALL) * n;
            let cands: Vec<(f64, f64)> = (0..12)
                .flat_map(|j| {
                    let x = x1 - 0.5 * wl - 8.0 * j as f64;
                    [(x, yl - 4.0), (x, yl + 4.0), (x, yl - 6.0), (x, yl + 6.0)]
                })
                .collect();
            lab.place(&cands, &l.label, H_SMALL, "#c62828");
        }
        // the impacts' sizes beside their arrows: the ink LABEL_CLEAR off
        // the arrow's side first, by the tip, then farther along and off it
        for a in &p.arrows {
            let (xp, _) = map(a.phi_deg, 0.0);
            let tip = (xp, yz - a.sign.signum() * IMPACT_MM);
            let ink = crate::labels::ink_rect((0.0, 0.0), &a.label, H_SMALL, false);
            let side = [ink.x1, -ink.x0];
            let cands: Vec<(f64, f64)> = [0.0, 3.0, 8.0, 16.0, 24.0]
                .iter()
                .flat_map(|&dx| {
                    [(1.0, side[1]), (-1.0, side[0])].into_iter().flat_map(move |(s, half)| {
                        [0.0, -2.0, 2.0, -4.0, 4.0, -8.0, 8.0, -12.0, 12.0, -16.0, 16.0]
                            .map(|dy| (xp + s * (half + LABEL_CLEAR + 0.4 + dx), tip.1 - a.sign.signum() * dy))
                            .into_iter()
                    })
                })
                .collect();
            if lab.place(&cands, &a.label, H_SMALL, "#c62828").is_some() {
                continue;
            }
            // no room for it between the phase lines: farther out, on a
            // leader to the arrow's tip; else (the note's low panels) the
            // jump's value alone, its sign and digits (`+1317,175`), the
            // same ways
            let value = a.label.rsplit_once("= ").map_or(a.label.as_str(), |(_, v)| v);
            let value = value.split_once(' ').map_or(value, |(v, _)| v);
            if self::led(&mut c, &mut lab, tip, &a.label) {
                continue;
            }
            let ink = crate::labels::ink_rect((0.0, 0.0), value, H_SMALL, false);
            let near: Vec<(f64, f64)> = [(1.0, -ink.x0), (-1.0, ink.x1)]
                .into_iter()
                .flat_map(|(s, half)| {
                    [0.0, -2.0, 2.0, -4.0, 4.0, -8.0, 8.0].map(|dy| (xp + s * (half + LABEL_CLEAR + 0.4), tip.1 - a.sign.signum() * dy))
                })
                .collect();
            if lab.place(&near, value, H_SMALL, "#c62828").is_none() {
                self::led(&mut c, &mut lab, tip, value);
            }
        }
        // the phases named under the plot, under their span (after the
        // impacts, which have one place each)
        let row = ybot.max(yz) + 5.5;
        for (i, name) in names.iter().enumerate() {
            let (xa, _) = map(bounds[i], 0.0);
            let (xb, _) = map(bounds[i + 1], 0.0);
            let xm = 0.5 * (xa + xb);
            let full = format!("{name} = {}{deg}", crate::labels::num(lang, bounds[i + 1] - bounds[i], 0));
            let cands: Vec<(f64, f64)> = [0.0, 4.5, 9.0]
                .into_iter()
                .flat_map(|dy| [0.0, -3.0, 3.0, -6.0, 6.0].map(|dx| (xm + dx, row + dy)))
                .collect();
            if lab.place(&cands, &full, H_SMALL + 0.5, "#000").is_none() {
                lab.place(&cands, name, H_SMALL + 0.5, "#000");
            }
        }
    }
    finish(c.finish(), &lab, None)
}

/// Place `text` near `tip` on a leader drawn to it ([`Placer::place_near`]);
/// whether it found a place.
fn led(c: &mut Canvas, lab: &mut Placer, tip: (f64, f64), text: &str) -> bool {
    match lab.place_near(&[tip], text, H_SMALL, "#c62828") {
        Some(n) => {
            if let Some((from, to)) = n.leader {
                // started LABEL_CLEAR off the label's ink, not its box
                let (dx, dy) = (to.0 - from.0, to.1 - from.1);
                let len = dx.hypot(dy);
                let k = ((LABEL_CLEAR + 1.5) / len).min(0.5);
                c.line_paper((from.0 + k * dx, from.1 + k * dy), to, Style::THIN.colored("#c62828"));
            }
            true
        }
        None => false,
    }
}
