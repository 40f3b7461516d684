//! The machine meshing (станочное зацепление): wheel 1 being cut by the
//! rack-type tool (реечный инструмент) of the basic rack, drawn as the course
//! draws it — the tool's teeth (its outline with the tip fillets, the body
//! shaded), the tool's reference line (делительная прямая рейки) and the
//! machine pitch line (станочно-начальная прямая) apart by the shift x·m
//! (dimensioned), the rack's pitch p = π·m dimensioned, the generated teeth
//! of the wheel with the tool's positions around the cut that envelope them,
//! the wheel's reference, base, tip and root circles, and the line of action
//! of the machine meshing from the pole P to its tangency N with the base
//! circle. The two lines run past the tool's teeth on the right, where a
//! leader turns down from each line's end to a shelf under the tool's body
//! carrying the line's name, its printed ink 1 mm clear of every line: no
//! name lies on the teeth.
//!
//! Geometry (Chernaya & Timofeev 2019, ch. 3, "станочное зацепление";
//! derived here for the placement): the pole P at the origin, the machine
//! pitch line y = 0 tangent to the reference circle r = m·z/2 at P, the
//! wheel's centre O = (0, r) above it; the tool's reference line at
//! y = −x·m (a positive shift moves the tool away from the wheel's centre);
//! a tool tooth centred on the y axis, its flanks inclined at α to the
//! vertical, its half-width p/4 − y_r·tan α at height y_r above the tool's
//! reference line, its tip (ha* + c*)·m above it. In cutting, the reference
//! circle rolls on the machine pitch line: a turn φ of the wheel (CCW about
//! O) goes with a travel r·φ of the tool along +x, so in the wheel's frame
//! the tool at φ is its outline shifted by r·φ and turned by −φ about O. The
//! line of action is the normal to the flanks through P, at α to the pitch
//! line, tangent to the base circle r_b = r·cos α at
//! N = r·sin α·(cos α, sin α).
//!
//! Groups of the SVG (read back by the tests): `<g class="rack-tool">` the
//! tool's outline, `<g class="rack-reference-line">` and
//! `<g class="machine-pitch-line">` the two lines; the root element carries
//! the scale (`data-scale`).

use std::f64::consts::PI;

use tmm_gears::Pair;
use tmm_gears::generate::ToothProfile;

use crate::labels::{H_HEAD, H_LABEL};
use crate::paper::{Slot, slot_mm, standard_scale};
use crate::project::{Language, SheetFormat};
use crate::svg::{Anchor, Canvas, Style, num};
use crate::words::word;

type Pt = (f64, f64);

/// Room above the drawing for its name and the scale's line, mm (the
/// circles' names stand above the drawing's top, clear of the scale).
const TITLE_H: f64 = 21.0;
/// Room left of the drawing for the dimension of x·m at least, mm; more
/// when its text needs it (the text's ink, the 9.5 mm from the tool's end
/// to the text and a margin).
const LEFT: f64 = 26.0;
/// The margin on the other sides, mm.
const MARGIN: f64 = 4.0;
/// Room right of the tool for the two lines' ends and the leaders that
/// turn down from them to their names, mm.
const NAME_ENDS: f64 = 7.0;
/// How far the lower line runs past the tool's window, and the upper one
/// past the lower one's end, mm.
const END_STEP: f64 = 3.0;
/// Room under the tool's body for the two names on their shelves, mm.
const NAME_ROWS: f64 = 14.0;
/// The paper between a name's printed ink and the edge of every line
/// (thin lines 0.3 mm wide, half of it counted on each side), mm.
const NAME_CLEAR: f64 = 1.0 + 0.15;
/// Tool teeth each side of the one at the pole.
const TEETH: i32 = 2;
/// Positions of the tool drawn each side of the one shown, enveloping the teeth.
const ENVELOPE: i32 = 6;

const TOOL: &str = "#000000";
const WHEEL: &str = "#1f5fbf";
const TRACE: &str = "#9a9a9a";
const RED: &str = "#c00000";

/// The tool's outline (mm, the drawing's frame) for a shift `x` (the tool's
/// reference line at y = −x·m): the teeth k = −n…n, from the left end of the
/// root line to the right one, the tip fillets sampled.
#[doc(hidden)]
pub fn tool_outline(m: f64, x: f64, alpha: f64, ha: f64, c: f64, rho: f64, n: i32) -> Vec<Pt> {
    let p = PI * m;
    let y_ref = -x * m;
    let (tip, root) = (ha + c, -(ha + c));
    let t = alpha.tan();
    // the right flank's half-width at height y (above the tool's reference line)
    let w = |y: f64| 0.25 * p - y * t;
    // the tip fillet, tangent to the tip line and to the flank (right side):
    // centre (u_c, y_c), y_c = h − ρ, u_c = p/4 − y_c·tan α − ρ/cos α
    let h = tip * m;
    let rho = rho.max(0.0);
    let yc = h - rho;
    let uc = 0.25 * p - yc * t - rho / alpha.cos();
    let mut out = Vec::new();
    for k in -n..=n {
        let u0 = k as f64 * p;
        let mut right: Vec<Pt> = Vec::new();
        // up the right flank from the root to the fillet, then the fillet
        // from the flank's normal (cos α, sin α) round to the top (0, 1)
        right.push((w(root * m), root * m));
        let steps = 8;
        for i in 0..=steps {
            let a = alpha + (0.5 * PI - alpha) * i as f64 / steps as f64;
            right.push((uc + rho * a.cos(), yc + rho * a.sin()));
        }
        // the left side is the mirror image, walked up
        for &(u, y) in right.iter() {
            out.push((u0 - u, y_ref + y));
        }
        for &(u, y) in right.iter().rev() {
            out.push((u0 + u, y_ref + y));
        }
    }
    out
}

/// The circle of radius `r` about `o`, sampled, split into the runs inside
/// the window `(x0, x1, y0, y1)`.
fn clipped_circle(o: Pt, r: f64, win: (f64, f64, f64, f64)) -> Vec<Vec<Pt>> {
    let n = 720;
    let pts: Vec<Pt> = (0..=n)
        .map(|i| {
            let a = -0.5 * PI + 2.0 * PI * i as f64 / n as f64;
            (o.0 + r * a.cos(), o.1 + r * a.sin())
        })
        .collect();
    runs(&pts, win)
}

/// The runs of `pts` inside the window.
fn runs(pts: &[Pt], (x0, x1, y0, y1): (f64, f64, f64, f64)) -> Vec<Vec<Pt>> {
    pts.split(|q| !(q.0 >= x0 && q.0 <= x1 && q.1 >= y0 && q.1 <= y1))
        .filter(|r| r.len() >= 2)
        .map(<[Pt]>::to_vec)
        .collect()
}

/// The machine meshing of wheel 1 of `pair` (its generated tooth `t1`) as
/// SVG on the Small slot of `sheet` at a GOST 2.302 scale, words in `lang`.
pub fn machine_mesh_svg(pair: &Pair, t1: &ToothProfile, lang: Language, sheet: SheetFormat) -> crate::picture::Picture {
    let s = &pair.spec;
    let k = 1e3;
    let (m, x, z) = (s.m * k, pair.w1.x, s.z1);
    let rack = &s.rack;
    let (alpha, ha, c) = (rack.alpha, rack.ha, rack.c);
    let p = PI * m;
    let r = 0.5 * m * z as f64;
    let rb = r * alpha.cos();
    let o = (0.0, r);
    let n_pt = (r * alpha.sin() * alpha.cos(), r * alpha.sin() * alpha.sin());
    let y_ref = -x * m;
    // the window: the tool's teeth either side of P, its body below the root
    // line, the wheel's teeth and a band of its body above, N
    let half = (TEETH as f64 + 0.5) * p;
    let (wx0, wx1) = (-half, half.max(n_pt.0 + m));
    let wy0 = y_ref - (ha + c) * m - 1.6 * m;
    let wy1 = ((ha + c - x) * m + 2.5 * m).max(n_pt.1 + m).max(y_ref + (ha + c) * m + 1.5 * m);
    let (pw, ph) = slot_mm(Slot::Small, sheet);
    let xm_text = format!("x·m = {} {}", num(x * m, 3, lang), word(lang, "gear.mm"));
    let xm_ink = name_ink(&xm_text);
    let left = LEFT.max(9.5 + (xm_ink.x1 - xm_ink.x0) + MARGIN);
    let room = (pw - left - MARGIN - NAME_ENDS, ph - TITLE_H - MARGIN - NAME_ROWS);
    let scale = match (standard_scale(wx1 - wx0, room.0), standard_scale(wy1 - wy0, room.1)) {
        (Some(a), Some(b)) => {
            if a.factor < b.factor {
                a
            } else {
                b
            }
        }
        _ => return Canvas::new(10.0, 10.0).finish(),
    };
    let f = scale.factor;
    let ph = (TITLE_H + MARGIN + NAME_ROWS + f * (wy1 - wy0)).min(ph);
    let mut cv = Canvas::new(pw, ph);
    cv.set_transform(f, (left - f * wx0, MARGIN + NAME_ROWS - f * wy0));
    cv.root_attr("data-scale", scale.text);
    let win = (wx0, wx1, wy0, wy1);
    // the name, and under it the scale (the note keeps the scale only)
    cv.title((0.5 * pw, 7.0), word(lang, "gear.machine_mesh_title"), H_HEAD, Anchor::Middle);
    cv.text_paper(
        (0.5 * pw, 12.5),
        &format!("{} {}", word(lang, "common.scale"), crate::svg::scale_text(scale.text, lang)),
        H_LABEL,
        Anchor::Middle,
        "#000",
    );

    // the tool: its body shaded, its outline thick
    let rho = t1.fillet_radius * k;
    let tool = tool_outline(m, x, alpha, ha, c, rho, TEETH + 1);
    let mut body: Vec<Pt> = tool.iter().map(|&(u, y)| (u.clamp(wx0, wx1), y.min(wy1))).collect();
    body.push((wx1, wy0));
    body.push((wx0, wy0));
    cv.polygon(&body, Style::THIN.colored("#ffffff").widened(0.0).filled("#dcdcdc"));
    // the tool's positions around the one shown: their envelope is the wheel's teeth
    let tau = 2.0 * PI / z as f64;
    for j in -ENVELOPE..=ENVELOPE {
        if j == 0 {
            continue;
        }
        let phi = tau * j as f64 / ENVELOPE as f64;
        let (sn, cs) = (-phi).sin_cos();
        let moved: Vec<Pt> = tool_outline(m, x, alpha, ha, c, rho, 1)
            .into_iter()
            .map(|(u, y)| {
                let (dx, dy) = (u + r * phi - o.0, y - o.1);
                (o.0 + cs * dx - sn * dy, o.1 + sn * dx + cs * dy)
            })
            .collect();
        for run in runs(&moved, win) {
            cv.polyline(&run, Style::THIN.colored(TRACE).widened(0.18));
        }
    }
    cv.begin_group_data("rack-tool", &[]);
    for run in runs(&tool, win) {
        cv.polyline(&run, Style::THICK.colored(TOOL));
    }
    cv.end_group();

    // the wheel: a space of it faces the tool's tooth at P (a tooth centred
    // half a pitch angle from −y), its teeth and circles
    let rot = -PI + 0.5 * tau;
    let wheel: Vec<Pt> = t1.wheel_outline(rot).iter().map(|&(a, b)| (o.0 + a * k, o.1 + b * k)).collect();
    for run in runs(&wheel, win) {
        cv.polyline(&run, Style::THICK.colored(WHEEL));
    }
    let (ra, rf) = (pair.w1.da / 2.0 * k, pair.w1.df / 2.0 * k);
    let mut circle_names = Vec::new();
    for (rad, style, name) in [
        (r, Style::AXIS.colored(WHEEL), "r"),
        (rb, Style::THIN.colored(WHEEL), "r_{b}"),
        (ra, Style::THIN.colored(WHEEL).widened(0.2), "r_{a}"),
        (rf, Style::THIN.colored(WHEEL).widened(0.2), "r_{f}"),
    ] {
        let pieces = clipped_circle(o, rad, win);
        for run in &pieces {
            cv.polyline(run, style);
        }
        // the name at the circle's right end within the window
        if let Some(end) = pieces.iter().flatten().filter(|q| q.0 > 0.0).max_by(|a, b| a.0.total_cmp(&b.0)) {
            circle_names.push((*end, name));
        }
    }

    // the two lines and the shift between them: each runs past the tool's
    // window (the upper one farther), where a leader turns down from its
    // end to a shelf under the tool's body that carries its name, so no
    // name lies on the teeth
    let (upper_y, lower_y) = if y_ref <= 0.0 { (0.0, y_ref) } else { (y_ref, 0.0) };
    let past = |y: f64| if y == upper_y { 2.0 * END_STEP / f } else { END_STEP / f };
    cv.begin_group_data("machine-pitch-line", &[]);
    cv.line((wx0, 0.0), (wx1 + past(0.0), 0.0), Style::THIN.colored(RED));
    cv.end_group();
    cv.begin_group_data("rack-reference-line", &[]);
    cv.line((wx0, y_ref), (wx1 + past(y_ref), y_ref), Style::AXIS.colored(TOOL));
    cv.end_group();
    let lx = cv.to_paper(wx0, 0.0).0;
    let py = |y: f64| cv.to_paper(0.0, y).1;
    let (y0p, y1p) = (py(0.0), py(y_ref));
    let (top_name, top_color, low_name, low_color) = if y_ref <= 0.0 {
        ("gear.machine_pitch_line", RED, "gear.rack_reference_line", "#000")
    } else {
        ("gear.rack_reference_line", "#000", "gear.machine_pitch_line", RED)
    };
    let body_bottom = py(wy0);
    let names = [
        (word(lang, low_name), low_color, lower_y),
        (word(lang, top_name), top_color, upper_y),
    ];
    for (i, (baseline, shelf)) in name_shelves(body_bottom, names[0].0, names[1].0).into_iter().enumerate() {
        let (name, color, y) = names[i];
        let (xe, ye) = cv.to_paper(wx1 + past(y), y);
        let st = if color == RED { Style::THIN.colored(RED) } else { Style::THIN };
        let w = name_ink(name);
        let x_text = xe - NAME_CLEAR - w.x1;
        cv.line_paper((xe, ye), (xe, shelf), st);
        cv.line_paper((xe, shelf), (x_text + w.x0 - NAME_CLEAR, shelf), st);
        cv.text_paper((x_text, baseline), name, H_LABEL - 1.0, Anchor::Start, color);
    }
    let dx = lx - 8.0;
    if (y1p - y0p).abs() > 1e-9 {
        cv.line_paper((lx, y0p), (dx - 2.0, y0p), Style::THIN);
        cv.line_paper((lx, y1p), (dx - 2.0, y1p), Style::THIN);
        let head = 2.0f64.min(0.45 * (y1p - y0p).abs());
        let (ya, yb) = if (y1p - y0p).abs() >= 6.0 { (y0p, y1p) } else { (y1p, y0p) };
        cv.arrow_paper((dx, 0.5 * (ya + yb)), (dx, ya), Style::THIN, head);
        cv.arrow_paper((dx, 0.5 * (ya + yb)), (dx, yb), Style::THIN, head);
    }
    cv.text_paper((dx - 1.5, 0.5 * (y0p + y1p) + 1.0), &xm_text, H_LABEL - 1.0, Anchor::End, "#000");

    for (end, name) in circle_names {
        cv.label(end, name, H_LABEL, WHEEL);
    }

    // the rack's pitch p = π·m between the right flanks of two teeth on the
    // tool's reference line, under the tool's root line
    let yd = y_ref - (ha + c) * m - 0.9 * m;
    let (u1, u2) = (0.25 * p - p, 0.25 * p);
    for u in [u1, u2] {
        cv.line((u, y_ref), (u, yd - 0.2 * m), Style::THIN);
    }
    let (pa, pb) = (cv.to_paper(u1, yd), cv.to_paper(u2, yd));
    let mid = (0.5 * (pa.0 + pb.0), pa.1);
    cv.arrow_paper(mid, pa, Style::THIN, 2.0);
    cv.arrow_paper(mid, pb, Style::THIN, 2.0);
    cv.text_paper(
        (mid.0, pa.1 - 1.0),
        &format!("p = πm = {} {}", num(p, 3, lang), word(lang, "gear.mm")),
        H_LABEL - 1.0,
        Anchor::Middle,
        "#000",
    );

    // the line of action of the machine meshing: N on the base circle, P, on past P
    let beyond = (-(n_pt.0) * 0.8, -(n_pt.1) * 0.8);
    cv.line(n_pt, beyond, Style::THIN.colored(RED).widened(0.35));
    cv.dot((0.0, 0.0), 0.8, RED);
    cv.dot(n_pt, 0.8, RED);
    cv.label((0.0, 0.0), "P", H_LABEL, RED);
    cv.label(n_pt, "N", H_LABEL, RED);
    cv.finish()
}

/// The ink of a line's name written from x = 0 on the baseline y = 0
/// (paper mm, y down), as [`crate::labels::ink_rect`] measures it.
fn name_ink(name: &str) -> crate::labels::Rect {
    let e = crate::picture::em(H_LABEL - 1.0);
    let r = crate::labels::ink_rect((0.0, 0.0), name, H_LABEL - 1.0, true);
    let base = 0.35 * e;
    crate::labels::Rect {
        x0: r.x0,
        y0: r.y0 - base,
        x1: r.x1,
        y1: r.y1 - base,
    }
}

/// The baselines and the shelves (paper mm, y down) of the names of the
/// two lines of the machine meshing under the tool's body, whose lower
/// edge is at `body`: the lower line's name `low` first, its ink 1 mm
/// under the body and 1 mm over its shelf, then the upper line's `top`,
/// its ink 1 mm under the first shelf and over its own
/// ([`tmm_draw::face::ink`]'s capitals and descenders), so no letter
/// touches a line.
#[doc(hidden)]
pub fn name_shelves(body: f64, low: &str, top: &str) -> [(f64, f64); 2] {
    let (a, b) = (name_ink(low), name_ink(top));
    let base1 = body + NAME_CLEAR - a.y0;
    let shelf1 = base1 + a.y1 + NAME_CLEAR;
    let base2 = shelf1 + NAME_CLEAR - b.y0;
    let shelf2 = base2 + b.y1 + NAME_CLEAR;
    [(base1, shelf1), (base2, shelf2)]
}
