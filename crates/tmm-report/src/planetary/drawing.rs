//! The planetary sheet (SVG, A4 landscape): the kinematic scheme of the best
//! set (side view, GOST 2.770 symbols simplified), the linear-velocity
//! picture drawn beside it on the same radius scale, and the angular-velocity
//! diagram, with the ratio read off the drawn lines beside Willis' value.

use tmm_planetary::scheme::Mesh;

use super::analysis::Analysis;
use super::text::{fraction_text, teeth_text, willis_text};
use crate::labels::{H_LABEL, Placer, finish, num};
use crate::paper::{Slot, round_mu, slot_mm, standard_scale};
use crate::picture::Picture;
use crate::project::{Language, SheetFormat};
use crate::svg::{Anchor, Canvas, Style};
use crate::words::word;
const BLUE: &str = "#1f5fbf";
const GREEN: &str = "#2e8b3a";
const RED: &str = "#c0392b";

/// What the sheet shows and what was read off it.
#[derive(Debug, Clone)]
pub struct Sheet {
    /// The SVG text.
    pub svg: Picture,
    /// `u_1H` read off the drawn velocity picture (paper slopes).
    pub ratio_picture: f64,
    /// `u_1H` read off the drawn angular-velocity diagram (paper segments).
    pub ratio_diagram: f64,
}

/// A wheel in side view: a rectangle over its pitch diameter.
fn wheel(c: &mut Canvas, x: f64, yc: f64, r: f64, w: f64, color: &'static str) {
    let s = Style::THICK.widened(0.5).filled("#eef3fb").colored(color);
    c.polygon(
        &[
            (x - 0.5 * w, yc - r),
            (x + 0.5 * w, yc - r),
            (x + 0.5 * w, yc + r),
            (x - 0.5 * w, yc + r),
        ],
        s,
    );
}

/// A ring in side view: its rim above and below the axis, teeth inward at radius `r`.
fn ring(c: &mut Canvas, x: f64, r: f64, w: f64, rim: f64, color: &'static str) {
    let s = Style::THICK.widened(0.5).filled("#eef3fb").colored(color);
    for sg in [1.0, -1.0] {
        let (a, b) = (sg * r, sg * (r + rim));
        c.polygon(&[(x - 0.5 * w, a), (x + 0.5 * w, a), (x + 0.5 * w, b), (x - 0.5 * w, b)], s);
    }
}

/// The ground (frame) hatch: a short line with ticks at world `(x, y)`, `len` world long, ticks on the side `dir` (±1 in y).
fn ground(c: &mut Canvas, x: f64, y: f64, len: f64, dir: f64) {
    c.line((x - 0.5 * len, y), (x + 0.5 * len, y), Style::THICK.widened(0.5));
    for i in 0..6 {
        let xi = x - 0.5 * len + len * f64::from(i) / 5.0;
        c.line((xi, y), (xi - 0.2 * len, y + dir * 0.2 * len), Style::THIN);
    }
}

/// μ written as the course does: 0,05 — no exponent.
fn mu_text(lang: Language, mu: f64) -> String {
    let digits = (-(mu.log10().floor()) as i64 + 1).clamp(0, 12) as usize;
    let t = num(lang, mu, digits);
    if t.contains([',', '.']) {
        t.trim_end_matches('0').trim_end_matches([',', '.']).to_string()
    } else {
        t
    }
}

/// Draw the sheet for the Scheme slot of `format`, words in `lang`: the
/// scheme at a GOST 2.302 scale, the velocity picture at a round μ_v.
pub fn sheet(a: &Analysis, lang: Language, format: SheetFormat) -> Sheet {
    let (w_paper, h_paper) = slot_mm(Slot::Scheme, format);
    #[allow(non_snake_case)]
    let (W, H) = (w_paper, h_paper);
    let r = &a.params.request;
    let sc = r.scheme;
    let b = &a.best;
    let t = b.teeth;
    let m1 = a.params.module;
    let q = b.modules.value();
    let r1 = 0.5 * m1 * f64::from(t.z1);
    let r2 = 0.5 * m1 * f64::from(t.z2);
    let r2p = 0.5 * m1 * q * f64::from(t.z2p);
    let r3 = 0.5 * m1 * q * f64::from(t.z3);
    let aw = a.centre_distance;
    let big = 0.5 * b.radial_size * m1;
    let (mesh1, mesh2) = sc.meshes();

    let mut c = Canvas::new(W, H);
    let mut lab = Placer::new(W, H);
    // Shared radius scale: the whole train (±big plus rims) in 0.64·H mm of
    // height, at the largest standard scale that fits (GOST 2.302).
    let scale = standard_scale(2.5 * big * 1e3, 0.64 * H).unwrap_or(crate::paper::Scale { factor: 1.0, text: "1:1" });
    let sr = scale.factor * 1e3; // paper mm per metre
    let axis_y = 0.533 * H; // paper mm from the bottom
    c.set_transform(sr, (22.0 + 0.1 * big * sr, axis_y));
    // the name, then the tooth numbers (z with its index: z1 → z_1,
    // z2' → z_{2}') and the scale: the note keeps these only
    let title = format!(
        "{} {}",
        word(lang, "planetary.title"),
        word(lang, &format!("planetary.scheme_{}", sc.name().replace('-', "_"))),
    );
    let teeth = teeth_text(sc, b)
        .split(", ")
        .map(|t| match t.strip_prefix('z') {
            Some(rest) => match rest.split_once(' ') {
                Some((i, v)) => format!("z_{{{}}}{} {v}", i.trim_end_matches('\''), if i.ends_with('\'') { "'" } else { "" }),
                None => t.to_string(),
            },
            None => t.to_string(),
        })
        .collect::<Vec<_>>()
        .join(", ");
    let params = format!(
        "{teeth}. {} {}",
        word(lang, "common.scale"),
        crate::svg::scale_text(scale.text, lang)
    );
    // in lines that stay on the paper (the labels' boxes are CHAR_WIDTH =
    // 0.62 of the size a letter, the wrapping's 0.6: 4 % narrower room)
    let room = 0.96 * (W - 10.0 - 0.6);
    let (names, rest) = (
        crate::labels::wrap_text(&title, H_LABEL, room),
        crate::labels::wrap_text(&params, H_LABEL, room),
    );
    let line_y = |i: usize| 10.0 + 1.25 * crate::picture::em(H_LABEL) * i as f64;
    lab.begin_title();
    for (i, l) in names.iter().enumerate() {
        lab.put_left((10.0, line_y(i)), l, H_LABEL, "#000");
    }
    lab.end_title();
    for (i, l) in rest.iter().enumerate() {
        lab.put_left((10.0, line_y(names.len() + i)), l, H_LABEL, "#000");
    }

    // --- the scheme ---
    c.begin_group("scheme");
    let (w, rim) = (0.09 * big, 0.07 * big);
    let x1 = 0.35 * big;
    let x2 = if sc.double_planet() { 0.8 * big } else { x1 };
    let xh = x2 + 0.35 * big;
    c.line((-0.15 * big, 0.0), (xh + 0.35 * big, 0.0), Style::AXIS);
    // wheel 1 and its shaft
    if mesh1 == Mesh::External {
        wheel(&mut c, x1, 0.0, r1, w, BLUE);
        c.line((-0.1 * big, 0.0), (x1, 0.0), Style::THICK.colored(BLUE));
    } else {
        ring(&mut c, x1, r1, w, rim, BLUE);
        let xw = x1 - 0.5 * w - 0.12 * big;
        c.line((xw, -(r1 + 0.5 * rim)), (xw, r1 + 0.5 * rim), Style::THICK.colored(BLUE));
        for sg in [1.0, -1.0] {
            c.line(
                (xw, sg * (r1 + 0.5 * rim)),
                (x1 - 0.5 * w, sg * (r1 + 0.5 * rim)),
                Style::THICK.colored(BLUE),
            );
        }
        c.line((-0.1 * big, 0.0), (xw, 0.0), Style::THICK.colored(BLUE));
    }
    let p1 = c.to_paper(-0.1 * big, 0.04 * big);
    c.rich_paper(p1, "1 (ω_1)", 3.5, Anchor::Start, BLUE);
    c.text_colored(
        (x1 + 0.5 * w + 0.02 * big, 0.5 * r1.min(aw - r2).max(0.05 * big)),
        "1",
        3.5,
        Anchor::Start,
        BLUE,
    );
    // wheel 3, fixed
    if mesh2 == Mesh::Internal {
        ring(&mut c, x2, r3, w, rim, "#000000");
        for sg in [1.0, -1.0] {
            ground(&mut c, x2, sg * (r3 + rim + 0.02 * big), 0.2 * big, sg);
            c.line((x2, sg * (r3 + rim)), (x2, sg * (r3 + rim + 0.02 * big)), Style::THICK);
        }
        c.text((x2 + 0.5 * w + 0.02 * big, r3 + 0.5 * rim), "3", 3.5, Anchor::Start);
    } else {
        wheel(&mut c, x2, 0.0, r3, w, "#000000");
        c.line((x2 + 0.5 * w, 0.06 * big), (x2 + 0.5 * w + 0.08 * big, 0.06 * big), Style::THICK);
        c.line(
            (x2 + 0.5 * w + 0.08 * big, 0.06 * big),
            (x2 + 0.5 * w + 0.08 * big, -r3 - 0.05 * big),
            Style::THICK,
        );
        ground(&mut c, x2 + 0.5 * w + 0.08 * big, -r3 - 0.05 * big, 0.2 * big, -1.0);
        c.text((x2 + 0.5 * w + 0.1 * big, 0.3 * r3), "3", 3.5, Anchor::Start);
    }
    // planets (upper and lower) on the carrier
    for sg in [1.0, -1.0] {
        let yc = sg * aw;
        c.line((x1 - 0.5 * w - 0.03 * big, yc), (xh, yc), Style::THICK.colored(RED));
        wheel(&mut c, x1, yc, r2, w, GREEN);
        if sc.double_planet() {
            wheel(&mut c, x2, yc, r2p, w, GREEN);
        }
    }
    c.text_colored((x1 - 0.5 * w - 0.02 * big, aw + 0.5 * r2), "2", 3.5, Anchor::End, GREEN);
    if sc.double_planet() {
        c.text_colored((x2 - 0.5 * w - 0.02 * big, aw + 0.5 * r2p), "2′", 3.5, Anchor::End, GREEN);
    }
    c.line((xh, -aw), (xh, aw), Style::THICK.colored(RED));
    c.line((xh, 0.0), (xh + 0.3 * big, 0.0), Style::THICK.colored(RED));
    let ph = c.to_paper(xh + 0.3 * big, 0.04 * big);
    c.rich_paper(ph, "H (ω_H)", 3.5, Anchor::End, RED);
    c.end_group();

    // --- the velocity picture, same radius scale, levels projected across ---
    let p = &a.picture;
    let rmax = p.a.r.max(p.b.r).max(p.c.r);
    // the planet line, extended over the planet's extent on the radius axis
    let lo = (aw - r2.max(r2p)).min(p.a.r).min(p.c.r).max(0.0);
    let hi = (aw + r2.max(r2p)).max(p.a.r).max(p.c.r);
    let planet_v = |rr: f64| p.a.v + (rr - p.a.r) * (p.c.v - p.a.v) / (p.c.r - p.a.r);
    let vals = [0.0, p.a.v, p.b.v, planet_v(lo), planet_v(hi)];
    let vlo = vals.iter().fold(0.0_f64, |m, v| m.min(*v));
    let vhi = vals.iter().fold(0.0_f64, |m, v| m.max(*v));
    let span = (85.0 - (297.0 - W)).max(50.0); // paper mm at most for the picture's width
    let mu_v = round_mu((vhi - vlo).max(1e-300) / span); // (m/s)/mm, a round value
    let sv_paper = 1.0 / mu_v; // paper mm per m/s
    let scheme_right = 22.0 + (0.1 * big + xh + 0.35 * big) * sr;
    let px0 = scheme_right + 15.0 - vlo * sv_paper; // paper x of the picture's radius axis
    // world for the picture: x = velocity·(sv/sr) so that the transform's scale sr applies to both axes
    let k = sv_paper / sr;
    c.set_transform(sr, (px0, axis_y));
    c.begin_group("velocity-picture");
    // the picture's heading and μ_v, moved left where they would leave the paper
    let fits_at =
        |x: f64, text: &str| x.min(W - 1.0 - crate::labels::CHAR_WIDTH * crate::picture::em(H_LABEL) * text.chars().count() as f64);
    let mu_line = format!("μ_v = {} {}", mu_text(lang, mu_v), word(lang, "planetary.mu_v_unit"));
    lab.put_left(
        (fits_at(scheme_right + 15.0, word(lang, "planetary.picture")), 22.0),
        word(lang, "planetary.picture"),
        H_LABEL,
        "#000",
    );
    lab.put_left((fits_at(scheme_right + 15.0, &mu_line), 28.0), &mu_line, H_LABEL, "#000");
    // the radius axis reaches 8 mm past the highest point; its name stands
    // left of its end, its box kept free of the points' labels
    let r_top = rmax + 8.0 / sr;
    c.line((0.0, 0.0), (0.0, r_top), Style::THIN);
    c.line((vlo * k, 0.0), (vhi * k, 0.0), Style::THIN);
    c.text((vhi * k, -0.04 * big), "v", 3.0, Anchor::End);
    let r_at = c.to_paper(0.0, r_top);
    c.text_paper((r_at.0 - 1.2, r_at.1 + 2.0), "r", 3.0, Anchor::End, "#000");
    lab.reserve(crate::labels::label_box((r_at.0 - 2.2, r_at.1 + 1.0), 1, 3.0));
    let x_of = |v: f64| v * k;
    let mut pts: Vec<((f64, f64), &str)> = Vec::new();
    for (name, rr, v) in [("a", p.a.r, p.a.v), ("b", p.b.r, p.b.v), ("c", p.c.r, p.c.v)] {
        // projection line from the scheme
        c.line(
            (-(px0 - 22.0) / sr + 0.2 * big, rr),
            (x_of(v), rr),
            Style::DASHED.colored("#888888"),
        );
        c.dot((x_of(v), rr), 0.6, "#000000");
        pts.push((c.to_paper(x_of(v), rr), name));
    }
    for &(q, _) in &pts {
        lab.reserve(crate::labels::label_box(q, 1, 1.2));
    }
    for &(q, name) in &pts {
        lab.place(&Placer::around(q, name, H_LABEL, 0.8), name, H_LABEL, "#000");
    }
    c.line((0.0, 0.0), (x_of(p.a.v), p.a.r), Style::THICK.widened(0.45).colored(BLUE));
    c.line(
        (x_of(planet_v(lo)), lo),
        (x_of(planet_v(hi)), hi),
        Style::THICK.widened(0.45).colored(GREEN),
    );
    c.line((0.0, 0.0), (x_of(p.b.v), p.b.r), Style::THICK.widened(0.45).colored(RED));
    // the lines' names beside them, where no other label is
    let along = |c: &Canvas, a: (f64, f64), b: (f64, f64)| -> Vec<(f64, f64)> {
        (0..=20)
            .flat_map(|i| {
                let t = 0.3 + 0.6 * f64::from(i) / 20.0;
                let q = c.to_paper(a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1));
                [(q.0 + 3.0, q.1), (q.0 - 3.0, q.1)]
            })
            .collect()
    };
    let c1 = along(&c, (0.0, 0.0), (x_of(p.a.v), p.a.r));
    lab.place(&c1, "1", H_LABEL, BLUE);
    let ch = along(&c, (0.0, 0.0), (x_of(p.b.v), p.b.r));
    lab.place(&ch, "H", H_LABEL, RED);
    let c2 = along(&c, (x_of(planet_v(lo)), lo), (x_of(planet_v(hi)), hi));
    lab.place(&c2, "2", H_LABEL, GREEN);
    c.end_group();
    // The ratio read off the drawn lines: tan ψ = (paper x)/(paper y) from the origin.
    let (pa, pb, po) = (c.to_paper(x_of(p.a.v), p.a.r), c.to_paper(x_of(p.b.v), p.b.r), c.to_paper(0.0, 0.0));
    let tan1 = (pa.0 - po.0) / (po.1 - pa.1);
    let tanh = (pb.0 - po.0) / (po.1 - pb.1);
    let pc = c.to_paper(0.0, p.c.r);
    let tan2 = (pa.0 - pc.0) / (pc.1 - pa.1); // the planet line's paper slope dX/dY
    let ratio_picture = tan1 / tanh;

    // --- the angular-velocity diagram: rays from a pole parallel to the picture's lines ---
    // paper x of the diagram's vertical through the pole: right of the
    // picture; on a paper too narrow for that (the note's A4 page) under the
    // picture's radius axis, right of the scheme, where the picture (r ≥ 0)
    // leaves the paper free
    let beside = px0 + vhi * sv_paper + 42.0;
    let under = beside + 40.0 > W - 1.0;
    let dx0 = if under { (px0 + 40.0).min(W - 41.0) } else { beside };
    let maxtan = [tan1, tanh, tan2].iter().fold(1e-300_f64, |m, v| m.max(v.abs()));
    let hh = (33.0 / maxtan).min(if under { 45.0 } else { 60.0 }); // pole distance, mm
    // paper y (from the top) of the ω-axis and of the pole
    let (ax_y, pl_y) = if under {
        let ax = H - axis_y + 16.0;
        (ax, ax + hh)
    } else {
        (130.0 - hh, 130.0)
    };
    c.begin_group("angular-diagram");
    let head = word(lang, "planetary.diagram");
    let hw = crate::labels::CHAR_WIDTH * H_LABEL * head.chars().count() as f64;
    let hx = (dx0 - 34.0 + 0.5 * hw).min(W - 1.0 - 0.5 * hw);
    let heads: Vec<(f64, f64)> = if under {
        (0..3).map(|i| (hx, pl_y + 9.0 + 6.0 * f64::from(i))).collect()
    } else {
        (0..8).map(|i| (hx, 22.0 + 6.0 * f64::from(i))).collect()
    };
    lab.place(&heads, head, H_LABEL, "#000");
    c.line_paper((dx0 - 36.0, ax_y), (dx0 + 36.0, ax_y), Style::THIN);
    c.line_paper((dx0, ax_y), (dx0, pl_y), Style::DASHED);
    c.text_paper((dx0 + 1.0, pl_y + 4.0), "P", 3.2, Anchor::Start, "#000");
    c.text_paper((dx0 + 37.0, ax_y + 1.0), "ω", 3.2, Anchor::Start, "#000");
    // the point 0 (where the fixed wheel 3's ray meets the axis: ω_3 = 0),
    // written "0; 3" (a comma would read as a decimal one)
    let zero = "0; 3";
    let zero_w = crate::labels::CHAR_WIDTH * 3.0 * zero.chars().count() as f64;
    let mut taken: Vec<(f64, f64, f64)> = vec![(dx0 - 0.5 * zero_w, dx0 + 0.5 * zero_w, 0.0)];
    c.text_paper((dx0, ax_y - 2.0), zero, 3.0, Anchor::Middle, "#000");
    let mut cut = |tanv: f64, name: &str, color: &'static str| {
        let x = dx0 + hh * tanv;
        c.line_paper((dx0, pl_y), (x, ax_y), Style::THIN.colored(color).widened(0.35));
        // a name over its ray's foot, lifted by 3.5 mm steps only where a
        // name already stands within 1 mm of it
        let half = 0.5 * crate::labels::CHAR_WIDTH * 3.2 * name.chars().count() as f64;
        let (lo, hi) = (x - half - 1.0, x + half + 1.0);
        let up = (0..4)
            .map(|i| 3.5 * f64::from(i))
            .find(|u| !taken.iter().any(|t| t.2 == *u && t.0 < hi && lo < t.1))
            .unwrap_or(14.0);
        taken.push((lo + 1.0, hi - 1.0, up));
        c.text_paper((x, ax_y - 2.0 - up), name, 3.2, Anchor::Middle, color);
        x - dx0
    };
    let x1d = cut(tan1, "1", BLUE);
    let xhd = cut(tanh, "H", RED);
    let _x2d = cut(tan2, "2", GREEN);
    c.end_group();
    let ratio_diagram = x1d / xhd;

    // --- the ratios beside each other ---
    let mm = word(lang, "planetary.mm");
    let lines = [
        format!(
            "{}: {}{} = {}",
            word(lang, "planetary.willis"),
            willis_text(sc, &b.teeth),
            if b.ratio.den == 1 {
                String::new()
            } else {
                format!(" = {}", fraction_text(b))
            },
            ratio_text(lang, b.ratio.value())
        ),
        format!("{} = {}", word(lang, "planetary.read_picture"), ratio_text(lang, ratio_picture)),
        format!("{} = {}", word(lang, "planetary.read_diagram"), ratio_text(lang, ratio_diagram)),
        format!(
            // no-break spaces hold each "name = value unit" on one line
            "k\u{a0}=\u{a0}{}; {}\u{a0}{}; a_w\u{a0}=\u{a0}{}\u{a0}{mm}; m\u{a0}=\u{a0}{}\u{a0}{mm}; η\u{a0}=\u{a0}{} ({})",
            r.planets,
            word(lang, "planetary.radial"),
            num(lang, b.radial_size, 1),
            num(lang, a.centre_distance * 1e3, 2),
            num(lang, m1 * 1e3, 2),
            num(lang, a.efficiency, 4),
            if a.driver == tmm_planetary::Driver::Sun {
                word(lang, "planetary.drives_sun")
            } else {
                word(lang, "planetary.drives_carrier")
            }
        ),
    ];
    // each line wrapped to the paper's width, the last 6 mm above its foot
    let wrapped: Vec<String> = lines
        .iter()
        .flat_map(|l| crate::labels::wrap_text(l, H_LABEL, 0.96 * (W - 10.0 - 0.6)))
        .collect();
    let n = wrapped.len().max(4);
    for (i, l) in wrapped.iter().enumerate() {
        lab.put_left((10.0, H - 6.0 * (n - i) as f64), l, H_LABEL, "#000");
    }
    Sheet {
        svg: finish(c.finish(), &lab, Some(scale.text)),
        ratio_picture,
        ratio_diagram,
    }
}

/// A ratio with four significant digits, as the note prints its numbers
/// (−0,05000, 6,000, 12,50), not six decimals (−0,050000, 6,000000).
fn ratio_text(lang: Language, v: f64) -> String {
    if !v.is_finite() || v == 0.0 {
        return num(lang, v, 0);
    }
    let decimals = (3 - v.abs().log10().floor() as i64).clamp(0, 8) as usize;
    num(lang, v, decimals)
}
