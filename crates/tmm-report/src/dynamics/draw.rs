//! The diagrams of the `[dynamics]` section, against φ in degrees from the
//! start of the cycle (the start of the working stroke): the reduced moments
//! M_c and M_d, the work A_d, A_c and ΔT, the variable reduced inertia I_II,
//! Mertsalov's T_I with its swing ΔT_max (the note's symbol), Wittenbauer's energy–mass diagram
//! with both tangents, the true ω₁(φ) with ω_max, ω_min, ω_m, ε₁(φ), and the
//! run-up ω₁(t) when there is a motor.
//!
//! The plots here have independent x and y scales and a y range fitted to
//! the data (ω₁ fluctuates by a few per cent about ω_m, which a range from
//! zero would flatten), with the legend beside the frame so that it never
//! covers a curve.

use tmm_linkage::dynamics::Dynamics;

pub(crate) mod cylinder;
#[doc(hidden)]
pub mod indicator;
pub(crate) mod stroke;

use crate::Error;
use crate::output::Documents;
use crate::paper::{Slot, round_mu, slot_mm};
use crate::picture::Picture;
use crate::project::{Language, SheetFormat};
use crate::svg::{Anchor, Canvas, Style, mu_text, num};
use crate::words::word;

const RED: &str = "#c00000";
const BLUE: &str = "#0050c0";
const GREEN: &str = "#008000";
const BROWN: &str = "#a05000";
const PURPLE: &str = "#7000a0";
const GREY: &str = "#606060";

/// Lettering heights (GOST 2.304): labels and ticks.
const H_LABEL: f64 = 3.5;
const H_SMALL: f64 = 2.5;
/// The margins around the frame, mm: left (tick labels), top (title, the
/// scale factors, the quantity's name), bottom (tick labels, positions).
const LEFT: f64 = 17.0;
#[doc(hidden)]
pub const TOP: f64 = 21.0;
#[doc(hidden)]
pub const BOTTOM: f64 = 11.0;
/// The baseline of the x axis' numbers under the frame, mm.
const X_TICKS: f64 = 4.2;
/// The room right of the frame: the names of the marked levels and the legend.
const RIGHT: f64 = 62.0;
/// The legend column's start right of the frame, mm.
const LEGEND_X: f64 = 13.0;
/// The gap between a level's dashed line and the ink of its name, mm.
#[doc(hidden)]
pub const LEVEL_CLEAR: f64 = 1.0;

/// The ink of a level's name (`ω_{max}`, `T_{I min}`) about its baseline,
/// mm: the capitals' height over it and the index's foot under it. The
/// printed capital of osifont at letter size h is 1.14 h (measured on the
/// PDF, `tmm_draw::face`), taken as 1.15 h; the index stands 0.25 h under
/// the baseline ([`crate::svg::rich`]) and its letters have no descenders.
#[doc(hidden)]
pub fn level_name_ink() -> (f64, f64) {
    let h = crate::picture::em(H_SMALL);
    (1.15 * h, 0.25 * h)
}

/// The grid step on paper, mm: the ticks stand at whole multiples of 10·μ.
const GRID: f64 = 10.0;

/// One axis at a round scale factor μ (units per paper mm): the frame runs
/// from `lo` (a whole multiple of the grid step GRID·μ) over `len` mm.
#[derive(Debug, Clone, Copy)]
#[doc(hidden)]
pub struct Axis {
    pub lo: f64,
    pub mu: f64,
    pub len: f64,
}

impl Axis {
    /// The smallest round μ at which `[a, b]`, widened to whole grid steps,
    /// fits in `room` mm.
    #[doc(hidden)]
    pub fn fit(a: f64, b: f64, room: f64) -> Axis {
        let (a, b) = widened(a, b);
        let mut mu = round_mu((b - a) / room.max(1.0));
        for _ in 0..64 {
            let g = GRID * mu;
            let lo = (a / g + 1e-9).floor() * g;
            let hi = (b / g - 1e-9).ceil() * g;
            let len = (hi - lo) / mu;
            if len <= room + 1e-9 {
                return Axis { lo, mu, len };
            }
            mu = round_mu(mu * 1.0001);
        }
        Axis {
            lo: a,
            mu: (b - a) / room.max(1.0),
            len: room,
        }
    }

    /// The value of grid line `k` (exact multiple of the step).
    fn grid(&self, k: usize) -> f64 {
        self.lo + k as f64 * GRID * self.mu
    }

    /// The number of grid steps.
    fn steps(&self) -> usize {
        (self.len / GRID).round() as usize
    }

    /// The decimals that print every grid value exactly.
    fn decimals(&self) -> usize {
        let g = GRID * self.mu;
        (2 - g.log10().floor() as i32).clamp(0, 12) as usize
    }
}

/// What the horizontal axis is.
#[doc(hidden)]
pub enum XKind {
    /// The cycle angle φ over the machine's cycle (0…360°, or 0…720° for a
    /// four-stroke engine; the x range's end) at μ_φ, marked with the positions 0…12.
    Phi(Vec<f64>),
    /// Another quantity: its symbol and unit.
    Other(String, String),
}

/// A diagram on its own paper, drawn in paper mm (y down).
#[doc(hidden)]
pub struct Chart {
    pub c: Canvas,
    pub x: Axis,
    pub y: Axis,
    /// The frame's top-left corner.
    pub fx: f64,
    pub fy: f64,
    pub legend: usize,
    /// Paper y of the level names' baselines (at the frame's right end).
    pub levels: Vec<f64>,
    /// Whether each level's name stands right of the frame (clear of every
    /// line drawn in it) rather than inside it over or under its line.
    pub levels_outside: Vec<bool>,
}

/// The longest y axis of a diagram in the note (A4), mm: a diagram is then
/// at most about 40 + 21 + 11 − 8 mm high with its scales (its name left
/// out, the caption names it), and three with their captions (about 15 mm
/// each) fill the 243 mm of a framed page, where two left a third of it
/// empty.
const NOTE_AXIS_MM: f64 = 40.0;

/// The longest y axis of a larger diagram in the note (A4; the energy–mass
/// diagram, Wittenbauer's), mm: with a diagram of [`NOTE_AXIS_MM`] and
/// their captions it fits a page.
const NOTE_SMALL_AXIS_MM: f64 = 75.0;

/// `a unit/mm`, the unit in brackets when it is a ratio.
fn per_mm(unit: &str, lang: Language) -> String {
    let mm = word(lang, "dynamics.unit_mm");
    if unit.contains('/') || unit.contains('·') {
        format!("({unit})/{mm}")
    } else {
        format!("{unit}/{mm}")
    }
}

impl Chart {
    /// A framed diagram for y in `yr` (`zero` keeps 0 in range) over the x
    /// axis `xk` with data range `xr`, on the paper of `slot`; the title,
    /// then both scale factors under it, then the quantity's name.
    #[allow(clippy::too_many_arguments)]
    #[doc(hidden)]
    pub fn new(
        lang: Language,
        sheet: SheetFormat,
        slot: Slot,
        title: &str,
        (ysym, yunit): (&str, &str),
        yr: (f64, f64),
        zero: bool,
        xk: XKind,
        xr: (f64, f64),
    ) -> Self {
        let (w, h) = slot_mm(slot, sheet);
        // on the note's page (A4) a diagram's y axis at most NOTE_AXIS_MM
        // long, μ the next of the standard series: three diagrams with
        // their captions share a page
        let h = match (sheet, slot) {
            (SheetFormat::A4, Slot::Diagram) => h.min(TOP + NOTE_AXIS_MM + BOTTOM),
            (SheetFormat::A4, Slot::Small) => h.min(TOP + NOTE_SMALL_AXIS_MM + BOTTOM),
            _ => h,
        };
        let (mut ya, mut yb) = yr;
        if zero {
            ya = ya.min(0.0);
            yb = yb.max(0.0);
        }
        let y = Axis::fit(ya, yb, h - TOP - BOTTOM);
        let x = match &xk {
            XKind::Phi(_) => {
                // the machine's cycle: 360°, or 720° for a four-stroke engine
                let span = xr.1;
                let mu = round_mu(span / (w - LEFT - RIGHT));
                Axis {
                    lo: 0.0,
                    mu,
                    len: span / mu,
                }
            }
            XKind::Other(..) => Axis::fit(xr.0, xr.1, w - LEFT - RIGHT),
        };
        let (fx, fy) = (LEFT, TOP);
        // the paper as high as the frame needs, within the slot
        let mut c = Canvas::new(w, (TOP + y.len + BOTTOM).min(h));
        let h_title = if sheet == SheetFormat::A1 { 5.0 } else { H_LABEL };
        c.title((0.5 * w, 6.0), title, h_title, Anchor::Middle);
        let (xsym, xunit) = match &xk {
            XKind::Phi(_) => ("φ".to_string(), "°".to_string()),
            XKind::Other(s, u) => (s.clone(), u.clone()),
        };
        // μ's index: the quantity's letter (μ_ω, μ_T, μ_M)
        let base = |s: &str| s.split(['_', ',', ' ', '(']).next().unwrap_or(s).to_string();
        let (ymu, xmu) = (base(ysym), base(&xsym));
        let scales = format!(
            "μ_{{{}}} = {} {},   μ_{{{}}} = {} {}",
            ymu,
            mu_text(y.mu, lang),
            per_mm(yunit, lang),
            xmu,
            mu_text(x.mu, lang),
            per_mm(&xunit, lang)
        );
        c.rich_paper((0.5 * w, 12.5), &scales, H_LABEL, Anchor::Middle, "#000");
        c.rich_paper((fx, fy - 2.0), &format!("{ysym}, {yunit}"), H_SMALL + 0.5, Anchor::Start, "#000");
        let mut ch = Chart {
            c,
            x,
            y,
            fx,
            fy,
            legend: 0,
            levels: Vec::new(),
            levels_outside: Vec::new(),
        };
        // the grid (not kept as lines to avoid: the names sit on the frame)
        let (x1, y1) = (fx + x.len, fy + y.len);
        let mut grid = Vec::new();
        for k in 0..=y.steps() {
            let v = y.grid(k);
            let (_, py) = ch.map(0.0, v);
            grid.push(((fx, py), (x1, py)));
            ch.c.rich_paper(
                (fx - 1.2, py + 0.9),
                &crate::svg::tick_num(v, y.decimals(), lang),
                H_SMALL,
                Anchor::End,
                "#000",
            );
        }
        match &xk {
            XKind::Phi(marks) => {
                for (i, phi) in marks.iter().chain(std::iter::once(&xr.1)).enumerate() {
                    let (px, _) = ch.map(*phi, 0.0);
                    grid.push(((px, fy), (px, y1)));
                    let n = if *phi >= xr.1 - 1e-9 { marks.len() } else { i };
                    ch.c.rich_paper((px, y1 + X_TICKS), &n.to_string(), H_SMALL, Anchor::Middle, "#000");
                }
                ch.c.rich_paper((x1 + 3.0, y1 + X_TICKS), "φ", H_LABEL, Anchor::Start, "#000");
            }
            XKind::Other(s, u) => {
                for k in 0..=x.steps() {
                    let v = x.grid(k);
                    let (px, _) = ch.map(v, 0.0);
                    grid.push(((px, fy), (px, y1)));
                    // every second tick; not the frame's corner, where the
                    // lowest y number stands
                    if k % 2 == 0 && k > 0 {
                        ch.c.rich_paper(
                            (px, y1 + X_TICKS),
                            &crate::svg::tick_num(v, x.decimals(), lang),
                            H_SMALL,
                            Anchor::Middle,
                            "#000",
                        );
                    }
                }
                ch.c.rich_paper((x1, y1 + X_TICKS + 4.8), &format!("{s}, {u}"), H_SMALL + 0.5, Anchor::End, "#000");
            }
        }
        let thin = Style::THIN.widened(0.1).colored("#bbbbbb");
        ch.c.segments_paper(Some("grid"), grid, thin);
        let frame = Style::THIN.widened(0.3);
        for (a, b) in [
            ((fx, fy), (x1, fy)),
            ((x1, fy), (x1, y1)),
            ((x1, y1), (fx, y1)),
            ((fx, y1), (fx, fy)),
        ] {
            ch.c.line_paper(a, b, frame);
        }
        if ch.y.lo < 0.0 && ch.y.lo + ch.y.len * ch.y.mu > 0.0 {
            let (_, pz) = ch.map(0.0, 0.0);
            ch.c.line_paper((fx, pz), (x1, pz), Style::THIN.widened(0.35));
        }
        ch
    }

    /// Data to paper (mm, y down).
    #[doc(hidden)]
    pub fn map(&self, x: f64, y: f64) -> (f64, f64) {
        (
            self.fx + (x - self.x.lo) / self.x.mu,
            self.fy + self.y.len - (y - self.y.lo) / self.y.mu,
        )
    }

    /// The frame's right edge and bottom, paper mm.
    #[doc(hidden)]
    pub fn corner(&self) -> (f64, f64) {
        (self.fx + self.x.len, self.fy + self.y.len)
    }

    /// A curve (a path of the data points) with a legend entry.
    fn curve(&mut self, pts: &[(f64, f64)], color: &'static str, name: &str, dash: Option<(f64, f64)>) {
        let mut d: Vec<(f64, f64)> = Vec::new();
        let mut pen = false;
        let mut kept: Option<(f64, f64)> = None;
        for &(x, y) in pts {
            if !(x.is_finite() && y.is_finite()) {
                pen = false;
                kept = None;
                continue;
            }
            let (px, py) = self.map(x, y);
            if !pen {
                d.push((f64::NAN, f64::NAN));
            }
            d.push((px, py));
            pen = true;
            // the labels placed later keep off the curve: its chords of ≥ 1 mm
            match kept {
                Some(k) if (k.0 - px).hypot(k.1 - py) < 1.0 => {}
                Some(k) => {
                    self.c.reserve_segment(k, (px, py));
                    kept = Some((px, py));
                }
                None => kept = Some((px, py)),
            }
        }
        if let (Some(k), Some(&(x, y))) = (kept, pts.last()) {
            let p = self.map(x, y);
            if p.0.is_finite() && p.1.is_finite() {
                self.c.reserve_segment(k, p);
            }
        }
        let st = Style {
            width: 0.6,
            color,
            dash,
            fill: None,
        };
        self.c.path_paper(Some("curve"), &d, st);
        self.legend_entry(
            name,
            Style {
                width: 0.6,
                color,
                dash,
                fill: None,
            },
        );
    }

    fn legend_entry(&mut self, name: &str, s: Style) {
        if name.is_empty() {
            return;
        }
        let (x1, _) = self.corner();
        let x = x1 + LEGEND_X;
        let y = self.fy + 3.0 + 5.0 * self.legend as f64;
        self.c.line_paper((x, y - 0.9), (x + 6.0, y - 0.9), s);
        self.legend_lines(x + 7.5, name);
    }

    /// A text line in the legend's column, with no sample line.
    fn note(&mut self, text: &str) {
        let (x1, _) = self.corner();
        self.legend_lines(x1 + LEGEND_X, text);
    }

    /// `text` in the legend's column from `x`, on the next rows, broken
    /// into lines that stay on the paper.
    fn legend_lines(&mut self, x: f64, text: &str) {
        let room = self.c.size().0 - x - 0.5;
        for line in crate::labels::wrap_text(text, H_SMALL, room) {
            let y = self.fy + 3.0 + 5.0 * self.legend as f64;
            self.c.rich_paper((x, y), &line, H_SMALL, Anchor::Start, "#000");
            self.legend += 1;
        }
    }

    /// A dashed level across the frame, its name right of the frame at its
    /// height (moved down clear of the names above it) and its value in
    /// the legend.
    #[doc(hidden)]
    pub fn level(&mut self, v: f64, color: &'static str, name: &str, value: &str) {
        let s = Style {
            width: 0.35,
            color,
            dash: Some((2.5, 1.5)),
            fill: None,
        };
        let (x1, _) = self.corner();
        let (_, py) = self.map(self.x.lo, v);
        self.c.line_paper((self.fx, py), (x1, py), s);
        let ink = tmm_draw::face::ink(&crate::labels::plain(name), tmm_draw::TextHeight::H2_5);
        let (x, at, anchor) = match self.level_name_outside(py, &ink) {
            Some(at) => (x1 + LEVEL_CLEAR - ink.left.min(0.0), at, Anchor::Start),
            None => {
                let (x, at) = self.level_name_inside(py, &ink);
                (x, at, Anchor::End)
            }
        };
        self.levels_outside.push(anchor == Anchor::Start);
        self.levels.push(at);
        self.c.rich_paper((x, at), name, H_SMALL, anchor, color);
        self.legend_entry(&format!("{name} = {value}"), s);
    }

    /// The baseline of a level's name right of the frame, centred on its
    /// line's height (raised to stay within the frame's height), where the name fits between the frame and the
    /// legend's samples ([`LEGEND_X`]) with [`LEVEL_CLEAR`] on both sides and
    /// keeps clear of the names already written: there it crosses no line
    /// or curve of the diagram.
    fn level_name_outside(&self, py: f64, ink: &tmm_draw::face::Ink) -> Option<f64> {
        let (cap, drop) = level_name_ink();
        let wide = ink.right - ink.left.min(0.0);
        // within the frame's height: the x axis' numbers stand under it
        let (_, y1) = self.corner();
        let at = (py + 0.5 * (cap - drop)).min(y1 - drop - 0.5);
        let step = cap + drop + 0.8;
        let apart = self.levels.iter().all(|l| (at - l).abs() >= step);
        (wide <= LEGEND_X - 2.0 * LEVEL_CLEAR && at - cap >= 0.0 && apart).then_some(at)
    }

    /// The right end and the baseline of a level's name written inside the
    /// frame: on [`Chart::level_name_baseline`]'s baseline at the frame's
    /// right end, or moved left a millimetre at a time until its ink, grown
    /// by [`LEVEL_CLEAR`], crosses no curve nor line drawn so far and no
    /// kept place (the curve may pass right where the level's line ends);
    /// where no place on that baseline is clear, a printed line farther
    /// from its level's line (twice at most); where none is, the right end.
    fn level_name_inside(&self, py: f64, ink: &tmm_draw::face::Ink) -> (f64, f64) {
        let (x1, y1) = self.corner();
        let (cap, drop) = level_name_ink();
        let wide = ink.right - ink.left.min(0.0);
        // a hair less than LEVEL_CLEAR up and down, so that the level's own
        // line, LEVEL_CLEAR from the ink, does not count; 0.5 mm sideways,
        // so that the frame 1 mm right of the name does not
        let (v, h) = (LEVEL_CLEAR - 0.05, 0.5);
        let clear_at = |x: f64, at: f64| {
            self.c.occupied(crate::svg::Rect {
                x0: x - wide - h,
                y0: at - cap - v,
                x1: x + h,
                y1: at + drop + v,
            }) == 0
        };
        let base = self.level_name_baseline(py);
        let away = if base < py { -1.0 } else { 1.0 };
        let step = cap + drop + 0.8;
        for k in 0..3 {
            let at = base + away * step * f64::from(k);
            if at - cap < self.fy + 0.3 || at + drop > y1 - 0.3 {
                break;
            }
            let mut x = x1 - 1.0;
            while x - wide >= self.fx + 1.0 {
                if clear_at(x, at) {
                    return (x, at);
                }
                x -= 1.0;
            }
        }
        (x1 - 1.0, base)
    }

    /// The baseline of a level's name inside the frame at its right end,
    /// where the name is too long for the room right of the frame: its
    /// index's foot [`LEVEL_CLEAR`] over the level's line at `py`,
    /// or, where the frame's top leaves no room above, its letters' tops
    /// as far under it; then moved down a printed line at a time clear of
    /// the names already written, and kept inside the frame.
    fn level_name_baseline(&self, py: f64) -> f64 {
        let (cap, drop) = level_name_ink();
        let (_, y1) = self.corner();
        let over = py - LEVEL_CLEAR - drop;
        let mut at = if over - cap >= self.fy + 0.3 {
            over
        } else {
            py + LEVEL_CLEAR + cap
        };
        let step = cap + drop + 0.8;
        for l in &self.levels {
            if (at - l).abs() < step {
                at = l + step;
            }
        }
        at.min(y1 - drop - 0.3)
    }

    /// A dot at a data point with its label put clear of the other text.
    fn mark(&mut self, x: f64, y: f64, label: &str, color: &'static str) {
        let p = self.map(x, y);
        let h = self.c.size().1;
        self.c.dot((p.0, h - p.1), 0.7, color);
        self.c.label_paper(p, label, H_SMALL, color);
    }

    #[doc(hidden)]
    pub fn finish(&self) -> Picture {
        self.c.finish()
    }
}

/// A range of at least a millionth of its magnitude (a constant quantity,
/// such as I_II of massless links, gets ±10 % about its value, or ±1 about
/// zero), so that the ticks are few and finite.
fn widened(a: f64, b: f64) -> (f64, f64) {
    let (a, b) = if a.is_finite() && b.is_finite() {
        (a.min(b), a.max(b))
    } else {
        (0.0, 1.0)
    };
    let mag = a.abs().max(b.abs());
    if b - a > 1e-6 * mag && b - a > 1e-200 {
        return (a, b);
    }
    let c = 0.5 * (a + b);
    let h = if c.abs() > 1e-200 { 0.1 * c.abs() } else { 1.0 };
    (c - h, c + h)
}

fn range(v: impl Iterator<Item = f64>) -> (f64, f64) {
    v.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)))
}

/// Every diagram, under `prefix`, in `lang`, for a sheet of `sheet`.
pub fn draw_all(d: &Dynamics, prefix: &str, lang: Language, sheet: SheetFormat, docs: &mut Documents) -> Result<(), Error> {
    let wd = |k: &str| word(lang, &format!("dynamics.{k}")).to_string();
    let c = &d.cycle;
    let deg: Vec<f64> = c.phi.iter().map(|p| p.to_degrees()).collect();
    let xy = |v: &[f64]| -> Vec<(f64, f64)> { deg.iter().copied().zip(v.iter().copied()).collect() };
    let marks: Vec<f64> = d.positions.iter().map(|p| p.phi.to_degrees()).collect();
    let phi = || XKind::Phi(marks.clone());
    let xr = (0.0, d.reducer.period.to_degrees());
    let (u_nm, u_j, u_i) = (wd("unit_nm"), wd("unit_j"), wd("unit_kgm2"));
    let (u_w, u_e) = (wd("unit_radps"), wd("unit_radps2"));
    let n3 = |v: f64| num(v, 3, lang);
    let chart =
        |title: &str, y: (&str, &str), yr: (f64, f64), zero: bool| Chart::new(lang, sheet, Slot::Diagram, title, y, yr, zero, phi(), xr);

    // the reduced moments
    let md = c.driving_moment;
    // an engine's constant moment is the driven machine's resistance (its
    // loads drive), not a driving torque
    let engine = d.spec.driving == tmm_linkage::dynamics::DrivingMoment::Engine;
    let (mc, mdn) = (wd("sym_mc"), wd(if engine { "sym_mres" } else { "sym_md" }));
    let mut ch = chart(
        &wd("title_moments"),
        ("M", &u_nm),
        range(c.moment.iter().copied().chain([md])),
        true,
    );
    ch.curve(&xy(&c.moment), RED, &mc, None);
    ch.curve(&[(0.0, md), (xr.1, md)], BLUE, &format!("{mdn} = {} {u_nm}", n3(md)), None);
    docs.add_text(format!("{prefix}moments.svg"), ch.finish())?;

    // the work and the change of kinetic energy
    let yr = range(c.work_loads.iter().chain(&c.work_driving).chain(&c.energy).copied());
    let mut ch = chart(&wd("title_work"), ("A, ΔT", &u_j), yr, true);
    ch.curve(&xy(&c.work_driving), BLUE, &wd("sym_ad"), None);
    ch.curve(&xy(&c.work_loads), RED, &wd("sym_ac"), None);
    ch.curve(&xy(&c.energy), GREEN, "ΔT", None);
    docs.add_text(format!("{prefix}work.svg"), ch.finish())?;

    // the variable reduced inertia
    let mut ch = chart(&wd("title_inertia"), ("I_{II}", &u_i), range(c.inertia.iter().copied()), true);
    ch.curve(&xy(&c.inertia), PURPLE, "I_{II}", None);
    docs.add_text(format!("{prefix}inertia.svg"), ch.finish())?;

    // Mertsalov's T_I and its swing
    let mk = &d.mertsalov;
    let yr = range(mk.energy_constant.iter().copied().chain([mk.energy_max, mk.energy_min]));
    let mut ch = chart(&wd("title_mertsalov"), ("T_I", &u_j), yr, true);
    ch.curve(&xy(&mk.energy_constant), GREEN, "T_I", None);
    // the double arrow of ΔT_I where the curve is farthest from mid-height
    // (before the levels' names, which keep off it and its label)
    let mid = 0.5 * (mk.energy_max + mk.energy_min);
    let xa = deg
        .iter()
        .zip(&mk.energy_constant)
        .filter(|(x, _)| (15.0..=345.0).contains(*x))
        .max_by(|a, b| (a.1 - mid).abs().total_cmp(&(b.1 - mid).abs()))
        .map_or(180.0, |(x, _)| *x);
    let (a, b) = (ch.map(xa, mk.energy_min), ch.map(xa, mk.energy_max));
    ch.c.arrow_paper(a, b, Style::THIN.colored(RED), 2.5);
    ch.c.arrow_paper(b, a, Style::THIN.colored(RED), 2.5);
    let dt = ch.c.label_paper((a.0, 0.5 * (a.1 + b.1)), "ΔT_{max}", H_SMALL, RED);
    ch.c.reserve(dt);
    // the arrowheads (filled, not seen as lines): 2.5 mm long, 1 mm wide
    for p in [a, b] {
        ch.c.reserve(crate::svg::Rect {
            x0: p.0 - 1.0,
            y0: p.1 - 2.6,
            x1: p.0 + 1.0,
            y1: p.1 + 2.6,
        });
    }
    ch.level(mk.energy_max, GREY, "T_{I max}", &format!("{} {u_j}", n3(mk.energy_max)));
    ch.level(mk.energy_min, GREY, "T_{I min}", &format!("{} {u_j}", n3(mk.energy_min)));
    ch.note(&format!("ΔT_{{max}} = {} {u_j}", n3(mk.energy_swing)));
    ch.note(&format!("I_I = {} {u_i}", num(mk.inertia, 5, lang)));
    for p in [mk.phi_max, mk.phi_min] {
        let e = if p == mk.phi_max { mk.energy_max } else { mk.energy_min };
        ch.mark(p.to_degrees(), e, &format!("φ = {}°", num(p.to_degrees(), 1, lang)), GREY);
    }
    docs.add_text(format!("{prefix}energy-constant.svg"), ch.finish())?;

    docs.add_text(format!("{prefix}wittenbauer.svg"), wittenbauer(d, lang, sheet))?;

    // the true speed
    let mo = &d.motion;
    let yr = range(mo.omega.iter().copied().chain([mo.omega_max, mo.omega_min]));
    let mut ch = chart(&wd("title_omega"), ("ω_1", &u_w), yr, false);
    ch.curve(&xy(&mo.omega), GREEN, "ω_1", None);
    // the coefficient of unevenness, a parameter of the curve: in the legend
    ch.note(&format!("δ = {}", num(mo.delta, 5, lang)));
    ch.level(mo.omega_max, RED, "ω_{max}", &format!("{} {u_w}", num(mo.omega_max, 4, lang)));
    ch.level(mo.omega_mean, GREY, "ω_m", &format!("{} {u_w}", num(mo.omega_mean, 4, lang)));
    ch.level(mo.omega_min, BLUE, "ω_{min}", &format!("{} {u_w}", num(mo.omega_min, 4, lang)));
    docs.add_text(format!("{prefix}omega.svg"), ch.finish())?;

    // the crank's acceleration
    let mut ch = chart(&wd("title_epsilon"), ("ε_1", &u_e), range(mo.epsilon.iter().copied()), true);
    ch.curve(&xy(&mo.epsilon), BROWN, "ε_1", None);
    docs.add_text(format!("{prefix}epsilon.svg"), ch.finish())?;

    if let Some(r) = &d.runup {
        let n = r.trace_time.len();
        let step = n.div_ceil(4000).max(1);
        let mut pts: Vec<(f64, f64)> = r
            .trace_time
            .iter()
            .copied()
            .zip(r.trace_omega.iter().copied())
            .step_by(step)
            .collect();
        if let (Some(&t), Some(&w)) = (r.trace_time.last(), r.trace_omega.last())
            && pts.last() != Some(&(t, w))
        {
            pts.push((t, w));
        }
        let xr = range(pts.iter().map(|p| p.0));
        let yr = range(pts.iter().map(|p| p.1));
        let mut ch = Chart::new(
            lang,
            sheet,
            Slot::Diagram,
            &wd("title_runup"),
            ("ω_1", &u_w),
            yr,
            true,
            XKind::Other("t".into(), wd("unit_s")),
            (xr.0.min(0.0), xr.1),
        );
        ch.curve(&pts, GREEN, "ω_{1}(t)", None);
        ch.level(r.steady.omega_mean, GREY, "ω_m", &format!("{} {u_w}", n3(r.steady.omega_mean)));
        let (a, b) = (ch.map(r.time, ch.y.lo), ch.map(r.time, ch.y.lo + ch.y.len * ch.y.mu));
        ch.c.line_paper(a, b, Style::DASHED.colored(RED));
        ch.legend_entry(
            &format!("t_р = {} {}", n3(r.time), wd("unit_s")).replace("t_р", &wd("sym_runup")),
            Style::DASHED.colored(RED),
        );
        docs.add_text(format!("{prefix}runup.svg"), ch.finish())?;
    }
    indicator::draw_all(d, prefix, lang, sheet, docs)
}

/// Wittenbauer's energy–mass diagram: ΔT against I_II over the cycle with
/// the two tangents of slopes ω_max²/2 and ω_min²/2, at round μ_I and μ_T,
/// on the Small slot. The tangents meet at O′ = (−I_I, −T₀), far off the
/// drawing; both are clipped to the frame.
fn wittenbauer(d: &Dynamics, lang: Language, sheet: SheetFormat) -> Picture {
    let wd = |k: &str| word(lang, &format!("dynamics.{k}")).to_string();
    let c = &d.cycle;
    let w = &d.wittenbauer;
    let xr = range(c.inertia.iter().copied());
    let yr = range(c.energy.iter().copied());
    let dx = 0.08 * (xr.1 - xr.0).max(1e-12);
    let u_i = wd("unit_kgm2");
    let u_s = wd("unit_s2");
    let mut ch = Chart::new(
        lang,
        sheet,
        Slot::Small,
        &wd("title_wittenbauer"),
        ("ΔT", &wd("unit_j")),
        yr,
        true,
        XKind::Other("I_{II}".into(), u_i.clone()),
        (xr.0 - dx, xr.1 + dx),
    );
    let pts: Vec<(f64, f64)> = c.inertia.iter().copied().zip(c.energy.iter().copied()).collect();
    ch.curve(&pts, GREEN, "ΔT(I_{II})", None);
    let top = ch.y.lo + ch.y.len * ch.y.mu;
    let right = ch.x.lo + ch.x.len * ch.x.mu;
    let bx = (ch.x.lo, right, ch.y.lo, top);
    let tangents = [(&w.upper, RED, "ω^{2}_{max}/2"), (&w.lower, BLUE, "ω^{2}_{min}/2")];
    for (t, color, name) in tangents {
        if let Some(seg) = clip(t.slope, t.intercept, bx) {
            ch.curve(&[seg.0, seg.1], color, &format!("{name} = {} {u_s}", num(t.slope, 1, lang)), None);
        }
    }
    // the legend's notes before the touching points' labels, which keep off them
    ch.note(&wd("off_drawing"));
    ch.note(&format!("I_I = {} {u_i}", num(d.required.wittenbauer, 5, lang)));
    for (t, color, _) in tangents {
        ch.mark(t.inertia, t.energy, &format!("φ = {}°", num(t.phi.to_degrees(), 1, lang)), color);
    }
    ch.finish()
}

/// The part of the line y = k·x + b inside the box (x0, x1, y0, y1).
fn clip(k: f64, b: f64, bx: (f64, f64, f64, f64)) -> Option<((f64, f64), (f64, f64))> {
    let (x0, x1, y0, y1) = bx;
    let (mut lo, mut hi) = (x0, x1);
    if k.abs() > 0.0 {
        let (xa, xb) = ((y0 - b) / k, (y1 - b) / k);
        lo = lo.max(xa.min(xb));
        hi = hi.min(xa.max(xb));
    } else if !(y0..=y1).contains(&b) {
        return None;
    }
    (lo < hi).then_some(((lo, k * lo + b), (hi, k * hi + b)))
}
