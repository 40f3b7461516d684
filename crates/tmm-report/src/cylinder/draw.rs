//! The mechanism of `[cylinder]` drawn to a standard scale in three
//! positions: the start (s = 0) and the end (s = s_max) thin, the
//! kinetostatics' position thick, with the points named as the book (A, B,
//! C, D, K, S2) and the cylinder drawn as its barrel from D along the axis.

use tmm_geom::{Vec2, perp};
use tmm_linkage::linear::CylinderState;

use super::Analysis;
use crate::paper::{Scale, Slot, slot_mm, standard_scale};
use crate::project::{Language, SheetFormat};
use crate::svg::{Anchor, Canvas, Style, mu_text, num};
use crate::words::word;

const BLUE: &str = "#1f4e9c";
const RED: &str = "#c0392b";
const BLACK: &str = "#000000";
const H_LABEL: f64 = 3.5;
const H_SMALL: f64 = 2.5;

/// The drawing's SVG.
pub fn mechanism(a: &Analysis, lang: Language, sheet: SheetFormat) -> crate::picture::Picture {
    let wd = |k: &str| word(lang, &format!("cylinder.{k}")).to_string();
    let d = &a.task.drive;
    let first = a.table[0];
    let last = a.table[a.table.len() - 1];
    let poses: [(&CylinderState, &'static str, bool); 3] = [(&first, BLUE, false), (&last, RED, false), (&a.at, BLACK, true)];
    // the barrel: from D to h_max + a tenth of the travel along the axis, its
    // width 0.06·(h_max + l_шт)
    let barrel_len = d.h_max + 0.1 * d.travel();
    let half_w = 0.03 * (d.h_max + d.rod).max(1e-6);
    let mut b = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    let mut grow = |p: Vec2| {
        b = (b.0.min(p.x), b.1.max(p.x), b.2.min(p.y), b.3.max(p.y));
    };
    grow(d.d);
    for (st, _, _) in &poses {
        let e3 = Vec2::new(st.phi3.cos(), st.phi3.sin());
        for p in [st.b.p, st.k.p, d.d + e3 * barrel_len] {
            grow(p);
        }
        grow(d.d + e3 * barrel_len + perp(e3) * half_w);
        grow(d.d + e3 * barrel_len - perp(e3) * half_w);
    }
    let size = (b.1 - b.0).max(b.3 - b.2).max(1e-9);
    let world = (b.0 - 0.08 * size, b.1 + 0.08 * size, b.2 - 0.08 * size, b.3 + 0.08 * size);
    let (w, h_slot) = slot_mm(Slot::Scheme, sheet);
    let (top, bottom, side) = (18.0, 14.0, 8.0);
    let (aw, ah_slot) = (w - 2.0 * side, h_slot - top - bottom);
    let (ww, wh) = ((world.1 - world.0) * 1000.0, (world.3 - world.2) * 1000.0);
    let scale = match (standard_scale(ww, aw), standard_scale(wh, ah_slot)) {
        (Some(x), Some(y)) => {
            if x.factor <= y.factor {
                x
            } else {
                y
            }
        }
        (Some(x), None) | (None, Some(x)) => x,
        (None, None) => Scale { factor: 1.0, text: "1:1" },
    };
    // on the note's page the drawing is as high as its content at the chosen
    // scale (GOST 2.105: no figure mostly empty); on a sheet it fills its slot
    let h = if sheet == SheetFormat::A4 {
        (wh * scale.factor + top + bottom).min(h_slot)
    } else {
        h_slot
    };
    let ah = h - top - bottom;
    let mut c = Canvas::new(w, h);
    let k_mm = scale.factor * 1000.0;
    let ox = side + 0.5 * (aw - ww * scale.factor) - k_mm * world.0;
    let oy = bottom + 0.5 * (ah - wh * scale.factor) - k_mm * world.2;
    c.set_transform(k_mm, (ox, oy));
    c.root_attr("data-scale", scale.text);
    c.root_attr("data-mu-l", &format!("{}", 0.001 / scale.factor));
    let h_title = if sheet == SheetFormat::A1 { 5.0 } else { H_LABEL };
    c.title((0.5 * w, 6.0), &wd("title_mechanism"), h_title, Anchor::Middle);
    c.rich_paper(
        (0.5 * w, 12.0),
        &format!(
            "{} {},   μ_l = {} {},   s_max = {} {},   β = {}°",
            word(lang, "common.scale"),
            crate::svg::scale_text(scale.text, lang),
            mu_text(0.001 / scale.factor, lang),
            wd("m_per_mm"),
            num(d.travel(), 3, lang),
            wd("unit_m"),
            num(a.task.swing.to_degrees(), 2, lang)
        ),
        H_SMALL + 0.5,
        Anchor::Middle,
        "#000",
    );
    let xy = |v: Vec2| (v.x, v.y);
    for (st, col, main) in poses {
        let e3 = Vec2::new(st.phi3.cos(), st.phi3.sin());
        let n3 = perp(e3);
        let thick = if main {
            Style::THICK
        } else {
            Style::THIN.colored(col).widened(0.4)
        };
        let thin = if main { Style::THIN } else { Style::THIN.colored(col) };
        // the barrel (open at its far end)
        let (p0, p1) = (d.d, d.d + e3 * barrel_len);
        c.polyline(
            &[
                xy(p1 + n3 * half_w),
                xy(p0 + n3 * half_w),
                xy(p0 - n3 * half_w),
                xy(p1 - n3 * half_w),
            ],
            thick,
        );
        c.line(xy(p0), xy(p0 + e3 * (0.5 * d.h_min)), thin);
        // the piston at C and the rod C–B
        c.line(
            xy(st.c.p + n3 * (0.85 * half_w)),
            xy(st.c.p - n3 * (0.85 * half_w)),
            thick.widened(if main { 1.0 } else { 0.6 }),
        );
        c.line(xy(st.c.p), xy(st.b.p), thick);
        // the lever A–B and its arm A–K with the load
        c.line((0.0, 0.0), xy(st.b.p), thick);
        c.line((0.0, 0.0), xy(st.k.p), thick);
        c.line(xy(st.b.p), xy(st.k.p), thin);
        c.joint(xy(st.b.p), 1.0);
        c.dot(xy(st.k.p), if main { 2.2 } else { 1.6 }, col);
        if main {
            c.dot(xy(st.s2.p), 0.9, BLACK);
        }
    }
    c.fixed_pivot((0.0, 0.0), 1.2);
    c.fixed_pivot(xy(d.d), 1.2);
    // the markers and the pivots' supports are kept free of the labels (the
    // placer avoids lines and texts; a dot is neither)
    for (st, _, main) in &poses {
        c.reserve_point(xy(st.k.p), if *main { 2.8 } else { 2.2 });
        c.reserve_point(xy(st.b.p), 1.4);
    }
    c.reserve_point(xy(a.at.s2.p), 1.2);
    c.reserve_point((0.0, 0.0), 2.5);
    c.reserve_point(xy(d.d), 2.5);
    let st = &a.at;
    for (p, name) in [
        (Vec2::ZERO, "A"),
        (d.d, "D"),
        (st.b.p, "B"),
        (st.c.p, "C"),
        (st.s2.p, "S_2"),
        (st.k.p, "K"),
    ] {
        c.label(xy(p), name, H_LABEL, "#000");
    }
    // the positions named at the load, on a leader when the load's
    // neighbourhood is taken
    for (st, col, txt) in [(&first, BLUE, "s = 0"), (&last, RED, "s = s_max")] {
        c.label_led(xy(st.k.p), txt, H_SMALL, col);
    }
    c.label_led(
        xy(a.at.k.p),
        &format!("s = {} {}", num(a.at.s, 3, lang), wd("unit_m")),
        H_SMALL,
        BLACK,
    );
    c.finish()
}
