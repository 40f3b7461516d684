//! The diagrams of the `[dynamics]` section, against φ in degrees from the
//! start of the cycle (the start of the working stroke): the reduced moments
//! M_c and M_d, the work A_d, A_c and ΔT, the variable reduced inertia I_II,
//! Merkalov's T_I with its swing ΔT_I, Wittenbauer's energy–mass diagram
//! with both tangents, the true ω₁(φ) with ω_max, ω_min, ω_m, ε₁(φ), and the
//! run-up ω₁(t) when there is a motor.
//!
//! The plots here have independent x and y scales and a y range fitted to
//! the data (ω₁ fluctuates by a few per cent about ω_m, which a range from
//! zero would flatten), with the legend beside the frame so that it never
//! covers a curve.

use tmm_linkage::dynamics::Dynamics;

use crate::Error;
use crate::output::Documents;
use crate::svg::{Anchor, Canvas, Style, Ticks};

const RED: &str = "#c00000";
const BLUE: &str = "#0050c0";
const GREEN: &str = "#008000";
const BROWN: &str = "#a05000";
const PURPLE: &str = "#7000a0";
const GREY: &str = "#606060";

/// Paper size, mm.
const W: f64 = 260.0;
const H: f64 = 160.0;
/// The frame on the paper (y up), mm.
const LEFT: f64 = 26.0;
const BOTTOM: f64 = 18.0;
const PW: f64 = 170.0;
const PH: f64 = 124.0;

/// A line chart on its own paper, world = paper mm with y up.
struct Chart {
    c: Canvas,
    x0: f64,
    x1: f64,
    y0: f64,
    y1: f64,
    legend: usize,
}

impl Chart {
    /// A frame for x in `xr`, y in `yr` (widened to whole ticks; `zero`
    /// keeps y = 0 in range), x ticks every `xstep` when given.
    fn new(title: &str, xlabel: &str, ylabel: &str, xr: (f64, f64), yr: (f64, f64), zero: bool, xstep: Option<f64>) -> Self {
        let c = Canvas::new(W, H);
        let (mut ya, mut yb) = yr;
        if zero {
            ya = ya.min(0.0);
            yb = yb.max(0.0);
        }
        let (ya, yb) = widened(ya, yb);
        let pad = 0.04 * (yb - ya);
        let yt = Ticks::new(ya - pad, yb + pad, 6);
        let (y0, y1) = (yt.value(yt.first), yt.value(yt.last));
        let (x0, x1, xticks): (f64, f64, Vec<(f64, String)>) = match xstep {
            Some(s) => {
                let n = ((xr.1 - xr.0) / s).round() as i64;
                (
                    xr.0,
                    xr.1,
                    (0..=n)
                        .map(|i| (xr.0 + i as f64 * s, format!("{:.0}", xr.0 + i as f64 * s)))
                        .collect(),
                )
            }
            None => {
                let (xa, xb) = widened(xr.0, xr.1);
                let xt = Ticks::new(xa, xb, 8);
                (
                    xt.value(xt.first),
                    xt.value(xt.last),
                    (xt.first..=xt.last).map(|i| (xt.value(i), xt.label(i))).collect(),
                )
            }
        };
        let mut ch = Chart {
            c,
            x0,
            x1,
            y0,
            y1,
            legend: 0,
        };
        let grid = Style {
            width: 0.1,
            color: "#bbbbbb",
            dash: None,
            fill: None,
        };
        for i in yt.first..=yt.last {
            let y = yt.value(i);
            let a = ch.map(x0, y);
            let b = ch.map(x1, y);
            ch.c.line(a, b, grid);
            ch.c.text((a.0 - 1.5, a.1 - 0.9), &yt.label(i), 2.6, Anchor::End);
        }
        for (x, label) in &xticks {
            let a = ch.map(*x, y0);
            let b = ch.map(*x, y1);
            ch.c.line(a, b, grid);
            ch.c.text((a.0, a.1 - 4.2), label, 2.6, Anchor::Middle);
        }
        // the frame and the x axis through zero
        let frame = Style::THIN.widened(0.3);
        ch.c.polygon(&[ch.map(x0, y0), ch.map(x1, y0), ch.map(x1, y1), ch.map(x0, y1)], frame);
        if y0 < 0.0 && y1 > 0.0 {
            ch.c.line(ch.map(x0, 0.0), ch.map(x1, 0.0), Style::THIN.widened(0.35));
        }
        ch.c.text_paper((LEFT + PW / 2.0, 8.0), title, 4.0, Anchor::Middle, "#000");
        ch.c.text((LEFT + PW / 2.0, 5.0), xlabel, 3.0, Anchor::Middle);
        ch.c.text((LEFT - 1.0, BOTTOM + PH + 3.0), ylabel, 3.0, Anchor::Start);
        ch
    }

    /// Data to paper (mm, y up).
    fn map(&self, x: f64, y: f64) -> (f64, f64) {
        (
            LEFT + (x - self.x0) / (self.x1 - self.x0) * PW,
            BOTTOM + (y - self.y0) / (self.y1 - self.y0) * PH,
        )
    }

    /// A curve with a legend entry beside the frame.
    fn curve(&mut self, pts: &[(f64, f64)], color: &'static str, name: &str, dash: Option<(f64, f64)>) {
        let p: Vec<(f64, f64)> = pts.iter().map(|&(x, y)| self.map(x, y)).collect();
        let s = Style {
            width: 0.45,
            color,
            dash,
            fill: None,
        };
        self.c.polyline(&p, s);
        self.legend_entry(name, s);
    }

    fn legend_entry(&mut self, name: &str, s: Style) {
        if name.is_empty() {
            return;
        }
        let x = LEFT + PW + 5.0;
        let y = BOTTOM + PH - 2.0 - 5.0 * self.legend as f64;
        self.c.line((x, y + 0.9), (x + 7.0, y + 0.9), s.widened(0.6));
        self.c.text((x + 9.0, y), name, 2.8, Anchor::Start);
        self.legend += 1;
    }

    /// A horizontal dashed line across the frame with a legend entry.
    fn hline(&mut self, y: f64, color: &'static str, name: &str) {
        let s = Style {
            width: 0.3,
            color,
            dash: Some((2.5, 1.5)),
            fill: None,
        };
        self.c.line(self.map(self.x0, y), self.map(self.x1, y), s);
        self.legend_entry(name, s);
    }

    /// A note below the legend, beside the frame.
    fn note(&mut self, text: &str) {
        let x = LEFT + PW + 5.0;
        let y = BOTTOM + PH - 2.0 - 5.0 * self.legend as f64 - 2.0;
        self.c.text((x, y), text, 2.6, Anchor::Start);
        self.legend += 1;
    }

    /// A dot at a data point with a label beside it.
    fn mark(&mut self, x: f64, y: f64, label: &str, color: &'static str, anchor: Anchor, dy: f64) {
        let p = self.map(x, y);
        self.c.dot(p, 0.7, color);
        let dx = match anchor {
            Anchor::Start => 1.5,
            Anchor::End => -1.5,
            Anchor::Middle => 0.0,
        };
        self.c.text_colored((p.0 + dx, p.1 + dy), label, 2.6, anchor, color);
    }

    fn finish(&self) -> String {
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

/// Every diagram, under `prefix`.
pub fn draw_all(d: &Dynamics, prefix: &str, docs: &mut Documents) -> Result<(), Error> {
    let c = &d.cycle;
    let deg: Vec<f64> = c.phi.iter().map(|p| p.to_degrees()).collect();
    let xy = |v: &[f64]| -> Vec<(f64, f64)> { deg.iter().copied().zip(v.iter().copied()).collect() };
    let xr = (0.0, 360.0);
    let xs = Some(30.0);
    let xl = "φ, ° (crank angle from the start of the working stroke)";

    // the reduced moments
    let md = c.driving_moment;
    let yr = range(c.moment.iter().copied().chain([md]));
    let mut ch = Chart::new("Reduced moments: loads M_c and drive M_d", xl, "M, N·m", xr, yr, true, xs);
    ch.curve(&xy(&c.moment), RED, "M_c (loads)", None);
    ch.curve(&[(0.0, md), (360.0, md)], BLUE, &format!("M_d = {md:.3} N·m"), None);
    docs.add_text(format!("{prefix}moments.svg"), ch.finish())?;

    // the work and the change of kinetic energy
    let yr = range(c.work_loads.iter().chain(&c.work_driving).chain(&c.energy).copied());
    let mut ch = Chart::new(
        "Work of the drive A_d, of the loads A_c, and ΔT = A_d + A_c",
        xl,
        "A, ΔT, J",
        xr,
        yr,
        true,
        xs,
    );
    ch.curve(&xy(&c.work_driving), BLUE, "A_d", None);
    ch.curve(&xy(&c.work_loads), RED, "A_c", None);
    ch.curve(&xy(&c.energy), GREEN, "ΔT", None);
    docs.add_text(format!("{prefix}work.svg"), ch.finish())?;

    // the variable reduced inertia
    let yr = range(c.inertia.iter().copied());
    let mut ch = Chart::new(
        "Variable part of the reduced moment of inertia I_II",
        xl,
        "I_II, kg·m²",
        xr,
        yr,
        true,
        xs,
    );
    ch.curve(&xy(&c.inertia), PURPLE, "I_II", None);
    docs.add_text(format!("{prefix}inertia.svg"), ch.finish())?;

    // Merkalov's T_I and its swing
    let mk = &d.merkalov;
    let yr = range(mk.energy_constant.iter().copied().chain([mk.energy_max, mk.energy_min]));
    let mut ch = Chart::new(
        "Merkalov: T_I = ΔT − I_II·ω_m²/2 and its swing ΔT_I",
        xl,
        "T_I, J",
        xr,
        yr,
        true,
        xs,
    );
    ch.curve(&xy(&mk.energy_constant), GREEN, "T_I", None);
    ch.hline(mk.energy_max, GREY, &format!("max T_I = {:.3} J", mk.energy_max));
    ch.hline(mk.energy_min, GREY, &format!("min T_I = {:.3} J", mk.energy_min));
    // the double arrow of ΔT_I where the curve is farthest from mid-height,
    // so that neither the arrow's label nor its shaft lies on the curve
    let mid = 0.5 * (mk.energy_max + mk.energy_min);
    let xa = deg
        .iter()
        .zip(&mk.energy_constant)
        .filter(|(x, _)| (15.0..=345.0).contains(*x))
        .max_by(|a, b| (a.1 - mid).abs().total_cmp(&(b.1 - mid).abs()))
        .map_or(180.0, |(x, _)| *x);
    let (a, b) = (ch.map(xa, mk.energy_min), ch.map(xa, mk.energy_max));
    ch.c.arrow(a, b, Style::THIN.colored(RED), 2.5);
    ch.c.arrow(b, a, Style::THIN.colored(RED), 2.5);
    ch.c.text_colored((a.0 + 1.5, 0.5 * (a.1 + b.1)), "ΔT_I", 3.0, Anchor::Start, RED);
    ch.note(&format!("ΔT_I = {:.3} J", mk.energy_swing));
    ch.note(&format!("I_I = ΔT_I/(δ·ω_m²) = {:.5} kg·m²", mk.inertia));
    ch.mark(
        mk.phi_max.to_degrees(),
        mk.energy_max,
        &format!("{:.1}°", mk.phi_max.to_degrees()),
        GREY,
        Anchor::Start,
        1.5,
    );
    ch.mark(
        mk.phi_min.to_degrees(),
        mk.energy_min,
        &format!("{:.1}°", mk.phi_min.to_degrees()),
        GREY,
        Anchor::Start,
        -4.0,
    );
    docs.add_text(format!("{prefix}energy-constant.svg"), ch.finish())?;

    docs.add_text(format!("{prefix}wittenbauer.svg"), wittenbauer(d))?;

    // the true speed
    let mo = &d.motion;
    let yr = range(mo.omega.iter().copied().chain([mo.omega_max, mo.omega_min]));
    let mut ch = Chart::new(
        &format!("True crank speed ω₁(φ) with the flywheel, δ = {:.5}", mo.delta),
        xl,
        "ω₁, rad/s",
        xr,
        yr,
        false,
        xs,
    );
    ch.hline(mo.omega_max, RED, &format!("ω_max = {:.4} rad/s", mo.omega_max));
    ch.hline(mo.omega_mean, GREY, &format!("ω_m = {:.4} rad/s", mo.omega_mean));
    ch.hline(mo.omega_min, BLUE, &format!("ω_min = {:.4} rad/s", mo.omega_min));
    ch.curve(&xy(&mo.omega), GREEN, "ω₁", None);
    docs.add_text(format!("{prefix}omega.svg"), ch.finish())?;

    // the crank's acceleration
    let yr = range(mo.epsilon.iter().copied());
    let mut ch = Chart::new(
        "Crank angular acceleration ε₁(φ) with the flywheel",
        xl,
        "ε₁, rad/s²",
        xr,
        yr,
        true,
        xs,
    );
    ch.curve(&xy(&mo.epsilon), BROWN, "ε₁", None);
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
        let mut ch = Chart::new("Run-up from rest with the motor: ω₁(t)", "t, s", "ω₁, rad/s", xr, yr, true, None);
        ch.hline(r.steady.omega_mean, GREY, &format!("steady ω_m = {:.3} rad/s", r.steady.omega_mean));
        ch.curve(&pts, GREEN, "ω₁(t)", None);
        let (a, b) = (ch.map(r.time, ch.y0), ch.map(r.time, ch.y1));
        ch.c.line(a, b, Style::DASHED.colored(RED));
        ch.legend_entry(&format!("run-up time {:.3} s", r.time), Style::DASHED.colored(RED));
        docs.add_text(format!("{prefix}runup.svg"), ch.finish())?;
    }
    Ok(())
}

/// Wittenbauer's energy–mass diagram: ΔT against I_II over the cycle with
/// the two tangents of slopes ω_max²/2 and ω_min²/2. They meet at
/// O′ = (−I_I, −T₀), far off the drawing; both are clipped to the frame.
fn wittenbauer(d: &Dynamics) -> String {
    let c = &d.cycle;
    let w = &d.wittenbauer;
    let xr = range(c.inertia.iter().copied());
    let yr = range(c.energy.iter().copied());
    let dx = 0.08 * (xr.1 - xr.0).max(1e-12);
    let mut ch = Chart::new(
        "Wittenbauer's energy–mass diagram ΔT(I_II) and the tangents",
        "I_II, kg·m²",
        "ΔT, J",
        (xr.0 - dx, xr.1 + dx),
        yr,
        true,
        None,
    );
    let pts: Vec<(f64, f64)> = c.inertia.iter().copied().zip(c.energy.iter().copied()).collect();
    ch.curve(&pts, GREEN, "ΔT(I_II)", None);
    for (t, color, name) in [(&w.upper, RED, "ω_max²/2"), (&w.lower, BLUE, "ω_min²/2")] {
        if let Some(seg) = clip(t.slope, t.intercept, (ch.x0, ch.x1, ch.y0, ch.y1)) {
            ch.curve(&[seg.0, seg.1], color, &format!("{name} = {:.1} s⁻²", t.slope), None);
        }
        // the label on the side of the tangent away from the curve: above
        // and left of the upper one, below and right of the lower one
        let up = std::ptr::eq(t, &w.upper);
        ch.mark(
            t.inertia,
            t.energy,
            &format!("φ = {:.1}°", t.phi.to_degrees()),
            color,
            if up { Anchor::End } else { Anchor::Start },
            if up { 2.5 } else { -4.0 },
        );
    }
    ch.note(&format!(
        "O′ = (−I_I, −T₀) = ({:.4}, {:.1})",
        -d.required.wittenbauer, -w.energy_start
    ));
    ch.note("(off the drawing)");
    ch.note(&format!("I_I = {:.5} kg·m²", d.required.wittenbauer));
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A constant or empty quantity still gets a frame with a few finite
    /// ticks (a massless mechanism has I_II ≡ 0).
    #[test]
    fn flat_data_gets_a_finite_frame() {
        for (a, b) in [
            (0.0, 0.0),
            (5.0, 5.0),
            (-1e-300, 1e-300),
            (1e9, 1e9 + 1e-7),
            (f64::INFINITY, f64::NEG_INFINITY),
        ] {
            let ch = Chart::new("t", "x", "y", (a, b), (a, b), false, None);
            assert!(ch.y1 > ch.y0 && ch.x1 > ch.x0, "{a} {b}");
            let svg = ch.finish();
            assert!(svg.matches("<line").count() < 100, "{a} {b}");
        }
    }
}
