//! SVG → DXF (перевод чертежа в DXF): the subset of SVG that tmm's canvas
//! and the sheets write — `line`, `polyline`, `polygon`, `rect`, `circle`,
//! `path` (M, L, H, V, A, C, Q, Z, absolute and relative), `text` with
//! `tspan`s (as one plain text), groups and nested `svg` viewports with
//! `transform`s — turned into DXF entities in millimetres, y up, on the
//! layers of a drawing:
//!
//! | layer | what goes there |
//! | --- | --- |
//! | `contour` | solid strokes at least [`THICK_MM`] wide (основная линия) |
//! | `thin` | thinner solid strokes and short dashes (тонкая, штриховая) |
//! | `axis` | dashed strokes whose dash is at least [`AXIS_DASH_MM`] (штрихпунктирная) |
//! | `dimension` | anything inside a group whose id or class says `dim` (размеры) |
//! | `text` | every text (надписи) |
//!
//! Entities are clipped to the viewport of the nested `svg` they belong to,
//! as the SVG viewer clips them, so the DXF shows what the sheet shows.

use crate::dxf_out::DxfDoc;
use crate::sheets::xml::{Token, tokens};

/// The narrowest stroke that goes to the `contour` layer, mm (GOST 2.303:
/// the main line is s = 0.5 … 1.4 mm; thin lines are s/3 … s/2).
pub const THICK_MM: f64 = 0.45;

/// The shortest dash that makes a stroke an axis line, mm (the dash of a
/// dash-dot line is 5 … 30 mm by GOST 2.303; a hidden line's 2 … 8).
pub const AXIS_DASH_MM: f64 = 4.0;

/// The layers, with their AutoCAD colour index.
pub const LAYERS: [(&str, u8); 5] = [("contour", 7), ("thin", 8), ("axis", 1), ("dimension", 3), ("text", 5)];

/// The ratio of a capital letter's height to the font size (the em), for
/// the DXF text height (GOST 2.304 sizes a font by its capitals).
const CAP: f64 = 0.72;

#[derive(Clone, Copy, Debug, PartialEq)]
struct Affine([f64; 6]);

impl Affine {
    const ID: Affine = Affine([1.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
    fn then(self, o: Affine) -> Affine {
        // the product self · o: o applied first (SVG: parent · child)
        let [a, b, c, d, e, f] = o.0;
        let [a2, b2, c2, d2, e2, f2] = self.0;
        Affine([
            a2 * a + c2 * b,
            b2 * a + d2 * b,
            a2 * c + c2 * d,
            b2 * c + d2 * d,
            a2 * e + c2 * f + e2,
            b2 * e + d2 * f + f2,
        ])
    }
    fn apply(&self, (x, y): (f64, f64)) -> (f64, f64) {
        let [a, b, c, d, e, f] = self.0;
        (a * x + c * y + e, b * x + d * y + f)
    }
    fn scale(&self) -> f64 {
        let [a, b, c, d, ..] = self.0;
        (a * d - b * c).abs().sqrt()
    }
}

fn numbers(s: &str) -> Vec<f64> {
    let mut out = Vec::new();
    let b = s.as_bytes();
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        if c.is_ascii_digit() || c == b'-' || c == b'+' || c == b'.' {
            let j0 = i;
            i += 1;
            let mut dot = c == b'.';
            let mut exp = false;
            while i < b.len() {
                let d = b[i];
                if d.is_ascii_digit() {
                    i += 1;
                } else if d == b'.' && !dot && !exp {
                    dot = true;
                    i += 1;
                } else if (d == b'e' || d == b'E') && !exp {
                    exp = true;
                    i += 1;
                    if i < b.len() && (b[i] == b'-' || b[i] == b'+') {
                        i += 1;
                    }
                } else {
                    break;
                }
            }
            if let Ok(v) = s[j0..i].parse::<f64>() {
                out.push(v);
            }
        } else {
            i += 1;
        }
    }
    out
}

/// A length attribute in mm: `12`, `12mm`, `1.2cm`, `1in`, `10pt`, `96px`.
pub fn length_mm(s: &str) -> Option<f64> {
    let t = s.trim();
    let (num, unit) = match t.find(|c: char| c.is_ascii_alphabetic() || c == '%') {
        Some(k) => (&t[..k], &t[k..]),
        None => (t, ""),
    };
    let v: f64 = num.trim().parse().ok()?;
    let k = match unit {
        "" | "mm" => 1.0,
        "cm" => 10.0,
        "in" => 25.4,
        "pt" => 25.4 / 72.0,
        "px" => 25.4 / 96.0,
        "pc" => 25.4 / 6.0,
        _ => return None,
    };
    Some(v * k).filter(|v| v.is_finite())
}

fn transform(s: &str) -> Affine {
    let mut m = Affine::ID;
    for part in s.split(')') {
        let Some((name, args)) = part.split_once('(') else { continue };
        let v = numbers(args);
        let g = |i: usize| v.get(i).copied().unwrap_or(0.0);
        let t = match name.trim().trim_start_matches(',').trim() {
            "matrix" if v.len() == 6 => Affine([v[0], v[1], v[2], v[3], v[4], v[5]]),
            "translate" => Affine([1.0, 0.0, 0.0, 1.0, g(0), g(1)]),
            "scale" => {
                let sx = v.first().copied().unwrap_or(1.0);
                Affine([sx, 0.0, 0.0, v.get(1).copied().unwrap_or(sx), 0.0, 0.0])
            }
            "rotate" => {
                let (s, c) = g(0).to_radians().sin_cos();
                let (cx, cy) = (g(1), g(2));
                Affine([c, s, -s, c, cx - c * cx + s * cy, cy - s * cx - c * cy])
            }
            _ => Affine::ID,
        };
        m = m.then(t);
    }
    m
}

#[derive(Clone, Debug)]
struct State {
    m: Affine,
    clip: (f64, f64, f64, f64),
    stroke: String,
    stroke_width: f64,
    dash: Vec<f64>,
    fill: String,
    font_size: f64,
    anchor: String,
    dim: bool,
}

fn style_of(t: &Token<'_>, s: &mut State) {
    let mut set = |k: &str, v: &str| match k {
        "stroke" => s.stroke = v.trim().to_string(),
        "stroke-width" => s.stroke_width = length_mm(v).unwrap_or(s.stroke_width),
        "stroke-dasharray" => s.dash = if v.trim() == "none" { Vec::new() } else { numbers(v) },
        "fill" => s.fill = v.trim().to_string(),
        "font-size" => s.font_size = length_mm(v).unwrap_or(s.font_size),
        "text-anchor" => s.anchor = v.trim().to_string(),
        _ => {}
    };
    if let Token::Start { attrs, .. } = t {
        for (k, v) in attrs {
            set(k, v);
        }
        if let Some(style) = t.attr("style") {
            for kv in style.split(';') {
                if let Some((k, v)) = kv.split_once(':') {
                    set(k.trim(), v);
                }
            }
        }
    }
    let dimlike = |v: Option<&str>| v.is_some_and(|v| v.to_ascii_lowercase().contains("dim"));
    if dimlike(t.attr("id")) || dimlike(t.attr("class")) {
        s.dim = true;
    }
}

fn visible_stroke(s: &State) -> bool {
    s.stroke != "none" && !s.stroke.is_empty() && s.stroke_width * s.m.scale() > 1e-6
}

fn visible_fill(s: &State) -> bool {
    let f = s.fill.to_ascii_lowercase();
    !(f == "none" || f == "#ffffff" || f == "#fff" || f == "white" || f == "transparent")
}

fn layer_of(s: &State) -> &'static str {
    if s.dim {
        "dimension"
    } else if !s.dash.is_empty() && s.dash.iter().any(|&d| d > 0.0) {
        if s.dash[0] * s.m.scale() >= AXIS_DASH_MM { "axis" } else { "thin" }
    } else if visible_stroke(s) && s.stroke_width * s.m.scale() >= THICK_MM {
        "contour"
    } else {
        "thin"
    }
}

struct Out<'a> {
    dxf: &'a mut DxfDoc,
    sheet_h: f64,
    count: usize,
}

impl Out<'_> {
    fn flip(&self, p: (f64, f64)) -> (f64, f64) {
        (p.0, self.sheet_h - p.1)
    }

    /// A polyline in sheet coordinates (y down), clipped to `clip`.
    fn poly(&mut self, pts: &[(f64, f64)], closed: bool, clip: (f64, f64, f64, f64)) {
        if pts.len() < 2 {
            return;
        }
        let inside = |p: &(f64, f64)| p.0 >= clip.0 - 1e-6 && p.0 <= clip.2 + 1e-6 && p.1 >= clip.1 - 1e-6 && p.1 <= clip.3 + 1e-6;
        if pts.iter().all(inside) {
            let q: Vec<(f64, f64)> = pts.iter().map(|&p| self.flip(p)).collect();
            if q.len() == 2 && !closed {
                self.dxf.line(q[0], q[1]);
            } else {
                self.dxf.polyline(&q, closed);
            }
            self.count += 1;
            return;
        }
        let mut seg: Vec<(f64, f64)> = pts.to_vec();
        if closed {
            seg.push(pts[0]);
        }
        let mut run: Vec<(f64, f64)> = Vec::new();
        for w in seg.windows(2) {
            match clip_segment(w[0], w[1], clip) {
                Some((a, b)) => {
                    if run.last().is_none_or(|l| (l.0 - a.0).abs() > 1e-9 || (l.1 - a.1).abs() > 1e-9) {
                        self.flush(&mut run);
                        run.push(a);
                    }
                    run.push(b);
                }
                None => self.flush(&mut run),
            }
        }
        self.flush(&mut run);
    }

    fn flush(&mut self, run: &mut Vec<(f64, f64)>) {
        if run.len() >= 2 {
            let q: Vec<(f64, f64)> = run.iter().map(|&p| self.flip(p)).collect();
            if q.len() == 2 {
                self.dxf.line(q[0], q[1]);
            } else {
                self.dxf.polyline(&q, false);
            }
            self.count += 1;
        }
        run.clear();
    }
}

/// Liang–Barsky clipping of segment `a`–`b` to the box `(x0, y0, x1, y1)`.
fn clip_segment(a: (f64, f64), b: (f64, f64), c: (f64, f64, f64, f64)) -> Option<((f64, f64), (f64, f64))> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    for (p, q) in [(-dx, a.0 - c.0), (dx, c.2 - a.0), (-dy, a.1 - c.1), (dy, c.3 - a.1)] {
        if p.abs() < 1e-15 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    (t0 <= t1).then_some(((a.0 + t0 * dx, a.1 + t0 * dy), (a.0 + t1 * dx, a.1 + t1 * dy)))
}

/// The points of an SVG elliptical arc (SVG 1.1 appendix F.6.5, endpoint to
/// centre parameterisation), `a` excluded, `b` included.
fn arc_points(a: (f64, f64), r: (f64, f64), phi_deg: f64, large: bool, sweep: bool, b: (f64, f64)) -> Vec<(f64, f64)> {
    let (mut rx, mut ry) = (r.0.abs(), r.1.abs());
    if rx < 1e-12 || ry < 1e-12 || (a.0 - b.0).hypot(a.1 - b.1) < 1e-12 {
        return vec![b];
    }
    let (sp, cp) = phi_deg.to_radians().sin_cos();
    let (hx, hy) = ((a.0 - b.0) / 2.0, (a.1 - b.1) / 2.0);
    let (x1, y1) = (cp * hx + sp * hy, -sp * hx + cp * hy);
    let lam = (x1 / rx).powi(2) + (y1 / ry).powi(2);
    if lam > 1.0 {
        rx *= lam.sqrt();
        ry *= lam.sqrt();
    }
    let num = (rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1).max(0.0);
    let den = rx * rx * y1 * y1 + ry * ry * x1 * x1;
    let mut k = if den > 0.0 { (num / den).sqrt() } else { 0.0 };
    if large == sweep {
        k = -k;
    }
    let (cx1, cy1) = (k * rx * y1 / ry, -k * ry * x1 / rx);
    let (cx, cy) = (cp * cx1 - sp * cy1 + (a.0 + b.0) / 2.0, sp * cx1 + cp * cy1 + (a.1 + b.1) / 2.0);
    let ang = |ux: f64, uy: f64| uy.atan2(ux);
    let th1 = ang((x1 - cx1) / rx, (y1 - cy1) / ry);
    let mut dth = ang((-x1 - cx1) / rx, (-y1 - cy1) / ry) - th1;
    let tau = std::f64::consts::TAU;
    if sweep && dth < 0.0 {
        dth += tau;
    } else if !sweep && dth > 0.0 {
        dth -= tau;
    }
    let n = ((dth.abs() / 0.05).ceil() as usize).clamp(2, 720);
    (1..=n)
        .map(|i| {
            let t = th1 + dth * i as f64 / n as f64;
            let (st, ct) = t.sin_cos();
            (cx + cp * rx * ct - sp * ry * st, cy + sp * rx * ct + cp * ry * st)
        })
        .collect()
}

/// The subpaths of a path's `d`, flattened to points (curves in 16 pieces).
fn path_points(d: &str) -> Vec<(Vec<(f64, f64)>, bool)> {
    let mut out: Vec<(Vec<(f64, f64)>, bool)> = Vec::new();
    let mut cur: Vec<(f64, f64)> = Vec::new();
    let (mut p, mut start) = ((0.0, 0.0), (0.0, 0.0));
    // split into (command, numbers)
    let mut cmds: Vec<(char, Vec<f64>)> = Vec::new();
    let idx: Vec<(usize, char)> = d
        .char_indices()
        .filter(|(_, c)| c.is_ascii_alphabetic() && *c != 'e' && *c != 'E')
        .collect();
    for (n, &(i, c)) in idx.iter().enumerate() {
        let end = idx.get(n + 1).map_or(d.len(), |x| x.0);
        cmds.push((c, numbers(&d[i + 1..end])));
    }
    let flush = |cur: &mut Vec<(f64, f64)>, closed: bool, out: &mut Vec<(Vec<(f64, f64)>, bool)>| {
        if cur.len() >= 2 {
            out.push((std::mem::take(cur), closed));
        }
        cur.clear();
    };
    for (c, v) in cmds {
        let rel = c.is_ascii_lowercase();
        let off = |p: (f64, f64), x: f64, y: f64| if rel { (p.0 + x, p.1 + y) } else { (x, y) };
        match c.to_ascii_uppercase() {
            'M' => {
                flush(&mut cur, false, &mut out);
                for (k, xy) in v.chunks_exact(2).enumerate() {
                    p = off(p, xy[0], xy[1]);
                    if k == 0 {
                        start = p;
                    }
                    cur.push(p);
                }
            }
            'L' => {
                for xy in v.chunks_exact(2) {
                    p = off(p, xy[0], xy[1]);
                    cur.push(p);
                }
            }
            'H' => {
                for &x in &v {
                    p = (if rel { p.0 + x } else { x }, p.1);
                    cur.push(p);
                }
            }
            'V' => {
                for &y in &v {
                    p = (p.0, if rel { p.1 + y } else { y });
                    cur.push(p);
                }
            }
            'A' => {
                for a in v.chunks_exact(7) {
                    let b = off(p, a[5], a[6]);
                    if cur.is_empty() {
                        cur.push(p);
                    }
                    cur.extend(arc_points(p, (a[0], a[1]), a[2], a[3] != 0.0, a[4] != 0.0, b));
                    p = b;
                }
            }
            'C' | 'Q' => {
                let k = if c.eq_ignore_ascii_case(&'C') { 6 } else { 4 };
                for a in v.chunks_exact(k) {
                    let pts: Vec<(f64, f64)> = a.chunks_exact(2).map(|xy| off(p, xy[0], xy[1])).collect();
                    if cur.is_empty() {
                        cur.push(p);
                    }
                    for i in 1..=16 {
                        let t = i as f64 / 16.0;
                        let u = 1.0 - t;
                        let q = if k == 6 {
                            let w = [u * u * u, 3.0 * u * u * t, 3.0 * u * t * t, t * t * t];
                            let all = [p, pts[0], pts[1], pts[2]];
                            (
                                all.iter().zip(w).map(|(a, w)| a.0 * w).sum(),
                                all.iter().zip(w).map(|(a, w)| a.1 * w).sum(),
                            )
                        } else {
                            let w = [u * u, 2.0 * u * t, t * t];
                            let all = [p, pts[0], pts[1]];
                            (
                                all.iter().zip(w).map(|(a, w)| a.0 * w).sum(),
                                all.iter().zip(w).map(|(a, w)| a.1 * w).sum(),
                            )
                        };
                        cur.push(q);
                    }
                    p = pts[pts.len() - 1];
                }
            }
            'Z' => {
                flush(&mut cur, true, &mut out);
                p = start;
            }
            _ => {}
        }
    }
    flush(&mut cur, false, &mut out);
    out
}

fn circle_points(c: (f64, f64), r: f64) -> Vec<(f64, f64)> {
    (0..96)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / 96.0;
            (c.0 + r * t.cos(), c.1 + r * t.sin())
        })
        .collect()
}

/// Convert an SVG document (a sheet or a single drawing; its user unit is
/// taken as 1 mm when the root has no viewBox) into `dxf` entities on the
/// layers of [`LAYERS`], the y axis flipped about the height `sheet_h_mm`.
/// Returns how many entities were written.
///
/// ```
/// use tmm_report::{dxf_out::DxfDoc, sheets::svg_to_dxf::convert};
/// let mut d = DxfDoc::new();
/// let svg = "<svg width=\"100mm\" height=\"50mm\" viewBox=\"0 0 100 50\">\
///   <line x1=\"10\" y1=\"10\" x2=\"90\" y2=\"10\" stroke=\"#000\" stroke-width=\"0.7\"/>\
///   <text x=\"5\" y=\"45\" font-size=\"5\">A</text></svg>";
/// assert_eq!(convert(svg, &mut d, 50.0).unwrap(), 2);
/// let back = dxf::Drawing::load(&mut d.to_bytes().unwrap().as_slice()).unwrap();
/// let line = back.entities().find_map(|e| match &e.specific {
///     dxf::entities::EntityType::Line(l) => Some((e.common.layer.clone(), l.p1.y)),
///     _ => None,
/// });
/// assert_eq!(line, Some(("contour".to_string(), 40.0))); // y = 50 − 10, a main line
/// ```
pub fn convert(svg: &str, dxf: &mut DxfDoc, sheet_h_mm: f64) -> Result<usize, String> {
    for (name, aci) in LAYERS {
        dxf.layer(name, aci);
    }
    let toks = tokens(svg)?;
    let mut out = Out {
        dxf,
        sheet_h: sheet_h_mm,
        count: 0,
    };
    let big = 1e9;
    let root = State {
        m: Affine::ID,
        clip: (-big, -big, big, big),
        stroke: "none".into(),
        stroke_width: 1.0,
        dash: Vec::new(),
        fill: "#000000".into(),
        font_size: 3.5,
        anchor: "start".into(),
        dim: false,
    };
    let mut stack: Vec<State> = vec![root];
    let mut depth_svg = 0usize;
    let mut text: Option<(State, (f64, f64), String, usize)> = None;
    let mut skip_depth: usize = 0;
    for t in &toks {
        match t {
            Token::Start { name, empty, .. } => {
                let Some(parent) = stack.last() else { continue };
                let mut s = parent.clone();
                if skip_depth > 0 {
                    if !empty {
                        skip_depth += 1;
                    }
                    continue;
                }
                if matches!(
                    *name,
                    "defs" | "title" | "desc" | "metadata" | "style" | "clipPath" | "marker" | "symbol"
                ) {
                    if !empty {
                        skip_depth = 1;
                    }
                    continue;
                }
                style_of(t, &mut s);
                if let Some(tr) = t.attr("transform") {
                    s.m = s.m.then(transform(tr));
                }
                let f = |k: &str| t.attr(k).and_then(length_mm).unwrap_or(0.0);
                match *name {
                    "svg" => {
                        let (x, y) = (f("x"), f("y"));
                        let vb = t.attr("viewBox").map(numbers).filter(|v| v.len() == 4 && v[2] > 0.0 && v[3] > 0.0);
                        if depth_svg == 0 {
                            // the root: user unit = 1 mm (its viewBox spans width × height mm)
                            if let (Some(v), Some(w)) = (&vb, t.attr("width").and_then(length_mm)) {
                                let k = w / v[2];
                                s.m = Affine([k, 0.0, 0.0, k, -k * v[0], -k * v[1]]);
                            }
                        } else {
                            let (w, h) = (f("width"), f("height"));
                            let (k, dx, dy) = match &vb {
                                Some(v) => {
                                    let k = (w / v[2]).min(h / v[3]);
                                    (k, x + 0.5 * (w - k * v[2]) - k * v[0], y + 0.5 * (h - k * v[3]) - k * v[1])
                                }
                                None => (1.0, x, y),
                            };
                            let (p0, p1) = (s.m.apply((x, y)), s.m.apply((x + w, y + h)));
                            let c = (p0.0.min(p1.0), p0.1.min(p1.1), p0.0.max(p1.0), p0.1.max(p1.1));
                            s.clip = (c.0.max(s.clip.0), c.1.max(s.clip.1), c.2.min(s.clip.2), c.3.min(s.clip.3));
                            s.m = s.m.then(Affine([k, 0.0, 0.0, k, dx, dy]));
                        }
                        if !empty {
                            depth_svg += 1;
                        }
                    }
                    "line" => emit_poly(&mut out, &s, &[(f("x1"), f("y1")), (f("x2"), f("y2"))], false),
                    "polyline" | "polygon" => {
                        let v = numbers(t.attr("points").unwrap_or(""));
                        let pts: Vec<(f64, f64)> = v.chunks_exact(2).map(|c| (c[0], c[1])).collect();
                        emit_poly(&mut out, &s, &pts, *name == "polygon");
                    }
                    "rect" => {
                        let (x, y, w, h) = (f("x"), f("y"), f("width"), f("height"));
                        emit_poly(&mut out, &s, &[(x, y), (x + w, y), (x + w, y + h), (x, y + h)], true);
                    }
                    "circle" => {
                        let (c, r) = ((f("cx"), f("cy")), f("r"));
                        if r > 0.0 && (visible_stroke(&s) || visible_fill(&s)) {
                            let cc = s.m.apply(c);
                            let rr = r * s.m.scale();
                            let cl = s.clip;
                            if cc.0 - rr >= cl.0 && cc.0 + rr <= cl.2 && cc.1 - rr >= cl.1 && cc.1 + rr <= cl.3 {
                                out.dxf.layer(layer_of(&s), 0);
                                out.dxf.circle(out.flip(cc), rr);
                                out.count += 1;
                            } else {
                                emit_poly(&mut out, &s, &circle_points(c, r), true);
                            }
                        }
                    }
                    "path" => {
                        for (pts, closed) in path_points(t.attr("d").unwrap_or("")) {
                            emit_poly(&mut out, &s, &pts, closed);
                        }
                    }
                    "text" => {
                        text = Some((s.clone(), (f("x"), f("y")), String::new(), stack.len()));
                    }
                    _ => {}
                }
                if !empty {
                    stack.push(s);
                }
            }
            Token::End { name, .. } => {
                if skip_depth > 0 {
                    skip_depth -= 1;
                    continue;
                }
                if *name == "svg" {
                    depth_svg = depth_svg.saturating_sub(1);
                }
                if *name == "text"
                    && let Some((s, at, value, _)) = text.take()
                {
                    emit_text(&mut out, &s, at, value.trim());
                }
                if stack.len() > 1 {
                    stack.pop();
                }
            }
            Token::Text(v) => {
                if skip_depth == 0
                    && let Some((_, _, value, _)) = text.as_mut()
                {
                    value.push_str(v);
                }
            }
        }
    }
    Ok(out.count)
}

fn emit_poly(out: &mut Out<'_>, s: &State, pts: &[(f64, f64)], closed: bool) {
    if !(visible_stroke(s) || visible_fill(s)) || pts.iter().any(|p| !(p.0.is_finite() && p.1.is_finite())) {
        return;
    }
    let q: Vec<(f64, f64)> = pts.iter().map(|&p| s.m.apply(p)).collect();
    out.dxf.layer(layer_of(s), 0);
    out.poly(&q, closed, s.clip);
}

fn emit_text(out: &mut Out<'_>, s: &State, at: (f64, f64), value: &str) {
    if value.is_empty() || !visible_fill(s) {
        return;
    }
    let p = s.m.apply(at);
    let c = s.clip;
    if !(p.0 >= c.0 && p.0 <= c.2 && p.1 >= c.1 && p.1 <= c.3) {
        return;
    }
    let [a, b, ..] = s.m.0;
    // the text's x axis on the sheet (y down) → angle in DXF (y up)
    let rot = (-b).atan2(a).to_degrees();
    let align = match s.anchor.as_str() {
        "middle" => 1,
        "end" => 2,
        _ => 0,
    };
    let h = CAP * s.font_size * s.m.scale();
    let value: String = value.split_whitespace().collect::<Vec<_>>().join(" ");
    out.dxf.layer("text", 0);
    out.dxf
        .text_aligned(out.flip(p), h, &value, if rot.abs() < 1e-9 { 0.0 } else { rot }, align);
    out.count += 1;
}
