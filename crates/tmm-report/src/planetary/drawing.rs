//! The planetary sheet (SVG, A4 landscape): the kinematic scheme of the best
//! set (side view, GOST 2.770 symbols simplified), the linear-velocity
//! picture drawn beside it on the same radius scale, and the angular-velocity
//! diagram, with the ratio read off the drawn lines beside Willis' value.

use tmm_planetary::scheme::Mesh;

use super::analysis::Analysis;
use super::text::{fraction_text, teeth_text};
use crate::svg::{Anchor, Canvas, Style};

const W: f64 = 297.0;
const H: f64 = 210.0;
const BLUE: &str = "#1f5fbf";
const GREEN: &str = "#2e8b3a";
const RED: &str = "#c0392b";

/// What the sheet shows and what was read off it.
#[derive(Debug, Clone)]
pub struct Sheet {
    /// The SVG text.
    pub svg: String,
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

/// Draw the sheet.
pub fn sheet(a: &Analysis) -> Sheet {
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
    // Shared radius scale: the whole train (±big plus rims) in 150 mm of height.
    let sr = 135.0 / (2.5 * big);
    let axis_y = 112.0; // paper mm from the bottom
    c.set_transform(sr, (22.0 + 0.1 * big * sr, axis_y));
    c.text_paper(
        (10.0, 12.0),
        &format!("Planetary train, scheme {} — {}", sc.name(), teeth_text(sc, b)),
        4.5,
        Anchor::Start,
        "#000",
    );

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
    c.text_colored((-0.1 * big, 0.04 * big), "1 (ω1)", 3.5, Anchor::Start, BLUE);
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
    c.text_colored((xh + 0.3 * big, 0.04 * big), "H (ωH)", 3.5, Anchor::End, RED);
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
    let span = 85.0; // paper mm for the picture's width
    let sv_paper = span / (vhi - vlo).max(1e-300); // paper mm per m/s
    let scheme_right = 22.0 + (0.1 * big + xh + 0.35 * big) * sr;
    let px0 = scheme_right + 15.0 - vlo * sv_paper; // paper x of the picture's radius axis
    // world for the picture: x = velocity·(sv/sr) so that the transform's scale sr applies to both axes
    let k = sv_paper / sr;
    c.set_transform(sr, (px0, axis_y));
    c.begin_group("velocity-picture");
    c.text_paper((scheme_right + 15.0, 22.0), "Linear-velocity picture", 4.0, Anchor::Start, "#000");
    c.line((0.0, 0.0), (0.0, 1.08 * rmax), Style::THIN);
    c.line((vlo * k, 0.0), (vhi * k, 0.0), Style::THIN);
    c.text((vhi * k, -0.04 * big), "v", 3.0, Anchor::End);
    c.text((0.02 * big, 1.08 * rmax), "r", 3.0, Anchor::Start);
    let x_of = |v: f64| v * k;
    for (name, rr, v) in [("a", p.a.r, p.a.v), ("b", p.b.r, p.b.v), ("c", p.c.r, p.c.v)] {
        // projection line from the scheme
        c.line(
            (-(px0 - 22.0) / sr + 0.2 * big, rr),
            (x_of(v), rr),
            Style::DASHED.colored("#888888"),
        );
        c.dot((x_of(v), rr), 0.6, "#000000");
        c.text((x_of(v) + 0.02 * big, rr - 0.06 * big), name, 3.2, Anchor::Start);
    }
    c.line((0.0, 0.0), (x_of(p.a.v), p.a.r), Style::THICK.widened(0.45).colored(BLUE));
    c.line(
        (x_of(planet_v(lo)), lo),
        (x_of(planet_v(hi)), hi),
        Style::THICK.widened(0.45).colored(GREEN),
    );
    c.line((0.0, 0.0), (x_of(p.b.v), p.b.r), Style::THICK.widened(0.45).colored(RED));
    c.text_colored((x_of(p.a.v) * 0.5, p.a.r * 0.5), "1", 3.2, Anchor::End, BLUE);
    c.text_colored((x_of(p.b.v) * 0.6, p.b.r * 0.6), "H", 3.2, Anchor::Start, RED);
    c.text_colored((x_of(planet_v(hi)), hi), "2", 3.2, Anchor::Start, GREEN);
    c.end_group();
    // The ratio read off the drawn lines: tan ψ = (paper x)/(paper y) from the origin.
    let (pa, pb, po) = (c.to_paper(x_of(p.a.v), p.a.r), c.to_paper(x_of(p.b.v), p.b.r), c.to_paper(0.0, 0.0));
    let tan1 = (pa.0 - po.0) / (po.1 - pa.1);
    let tanh = (pb.0 - po.0) / (po.1 - pb.1);
    let pc = c.to_paper(0.0, p.c.r);
    let tan2 = (pa.0 - pc.0) / (pc.1 - pa.1); // the planet line's paper slope dX/dY
    let ratio_picture = tan1 / tanh;

    // --- the angular-velocity diagram: rays from a pole parallel to the picture's lines ---
    let dx0 = px0 + vhi * sv_paper + 42.0; // paper x of the diagram's vertical through the pole
    let maxtan = [tan1, tanh, tan2].iter().fold(1e-300_f64, |m, v| m.max(v.abs()));
    let hh = (33.0 / maxtan).min(60.0); // pole distance, mm
    let pl_y = 130.0; // paper y (from the top) of the pole
    let ax_y = pl_y - hh; // … and of the ω-axis
    c.begin_group("angular-diagram");
    c.text_paper((dx0 - 34.0, 22.0), "Angular-velocity diagram", 4.0, Anchor::Start, "#000");
    c.line_paper((dx0 - 36.0, ax_y), (dx0 + 36.0, ax_y), Style::THIN);
    c.line_paper((dx0, ax_y), (dx0, pl_y), Style::DASHED);
    c.text_paper((dx0 + 1.0, pl_y + 4.0), "P", 3.2, Anchor::Start, "#000");
    c.text_paper((dx0 + 37.0, ax_y + 1.0), "ω", 3.2, Anchor::Start, "#000");
    let mut cut = |tanv: f64, name: &str, color: &'static str, up: f64| {
        let x = dx0 + hh * tanv;
        c.line_paper((dx0, pl_y), (x, ax_y), Style::THIN.colored(color).widened(0.35));
        c.text_paper((x, ax_y - 2.0 - up), name, 3.2, Anchor::Middle, color);
        x - dx0
    };
    let x1d = cut(tan1, "1", BLUE, 0.0);
    let xhd = cut(tanh, "H", RED, 3.5);
    let _x2d = cut(tan2, "2", GREEN, 7.0);
    c.text_paper((dx0 - 2.0, ax_y - 2.0), "0,3", 3.0, Anchor::End, "#000");
    c.end_group();
    let ratio_diagram = x1d / xhd;

    // --- the ratios beside each other ---
    let lines = [
        format!("u_1H by Willis: {} = {:.6}", fraction_text(b), b.ratio.value()),
        format!("u_1H read off the velocity picture: tan ψ1 / tan ψH = {ratio_picture:.6}"),
        format!("u_1H read off the angular-velocity diagram: 0–1 / 0–H = {ratio_diagram:.6}"),
        format!(
            "k = {} planets, radial size {:.1} modules, a_w = {:.2} mm, m = {} mm, efficiency {:.4} ({} drives)",
            r.planets,
            b.radial_size,
            a.centre_distance * 1e3,
            m1 * 1e3,
            a.efficiency,
            if a.driver == tmm_planetary::Driver::Sun {
                "wheel 1"
            } else {
                "carrier"
            }
        ),
    ];
    for (i, l) in lines.iter().enumerate() {
        c.text_paper((10.0, 180.0 + 6.0 * i as f64), l, 3.6, Anchor::Start, "#000");
    }
    Sheet {
        svg: c.finish(),
        ratio_picture,
        ratio_diagram,
    }
}

#[cfg(test)]
mod tests {
    use tmm_planetary::{Request, Scheme};

    use super::sheet;
    use crate::planetary::{Origin, Params, analyse};

    /// The ratios read off the drawn lines (paper coordinates) equal Willis'
    /// exact fraction, in every scheme, and the sheet holds no non-finite number.
    #[test]
    fn drawn_ratio_is_willis() {
        for (scheme, u, k) in [
            (Scheme::SunPlanetRing, 4.0, 3),
            (Scheme::ExtInt, 12.5, 3),
            (Scheme::ExtExt, 1.0 / 30.0, 3),
            (Scheme::IntInt, -0.05, 3),
        ] {
            let a = analyse(&Params::new(Request::new(scheme, u, k)), &Origin::cli()).unwrap();
            let s = sheet(&a);
            let w = a.best.ratio.value();
            assert!(
                (s.ratio_picture - w).abs() < 1e-9 * w.abs().max(1.0),
                "{scheme:?}: {} vs {w}",
                s.ratio_picture
            );
            assert!(
                (s.ratio_diagram - w).abs() < 1e-9 * w.abs().max(1.0),
                "{scheme:?}: {} vs {w}",
                s.ratio_diagram
            );
            assert!(!s.svg.contains("NaN") && !s.svg.contains("inf"));
        }
    }
}
