//! The meshing drawing (картина зацепления) as SVG and DXF: both wheels with
//! several generated teeth at the operating centre distance; reference, base,
//! tip, root and operating circles; the line of action N1N2, its active part
//! AB, the pole P, the working parts of the profiles, the arcs of action; the
//! specific-sliding diagrams; a table of the parameters.
//!
//! Placement (derived here, docs/gears.md §Meshing drawing): O1 at the origin,
//! the pole P = (0, rw1); the line of action rises to the right at αw; wheel 1
//! has a tooth just left of P whose right flank passes through P, wheel 2 the
//! mating tooth just right of P.

use std::f64::consts::PI;

use tmm_gears::generate::ToothProfile;
use tmm_gears::{Kind, Pair};

use crate::dxf_out::DxfDoc;
use crate::labels::{CHAR_WIDTH, DASH_DOT, DASH_DOT_DOT, H_HEAD, H_LABEL, Placer, Rect, finish_all, label_box, num, plain};
use crate::paper::{Scale, Slot, slot_mm, standard_scale};
use crate::picture::Picture;
use crate::project::{Language, SheetFormat};
use crate::svg::{Canvas, Style};
use crate::words::word;

#[doc(hidden)]
pub type Pt = (f64, f64);

/// The geometry of the drawing in millimetres.
#[doc(hidden)]
pub struct Scene {
    pub o1: Pt,
    pub o2: Pt,
    pub p: Pt,
    pub n1: Pt,
    pub n2: Pt,
    pub a: Pt,
    pub b: Pt,
    pub rot1: f64,
    pub rot2: f64,
    /// (centre, radius, name, DXF layer, style)
    pub circles: Vec<(Pt, f64, &'static str, &'static str, Style)>,
    pub work1: Vec<Pt>,
    pub work2: Vec<Pt>,
    /// (centre, r, a0, a1) rad
    pub arcs: Vec<(Pt, f64, f64, f64)>,
}

#[doc(hidden)]
pub fn turn(p: Pt, a: f64, c: Pt) -> Pt {
    let (s, co) = a.sin_cos();
    (c.0 + co * p.0 - s * p.1, c.1 + s * p.0 + co * p.1)
}

fn inv(a: f64) -> f64 {
    a.tan() - a
}

#[doc(hidden)]
pub fn scene(pair: &Pair, t1: &ToothProfile, t2: &ToothProfile) -> Scene {
    let k = 1e3; // m → mm
    let internal = pair.spec.kind == Kind::Internal;
    let (w1, w2) = (&pair.w1, &pair.w2);
    let al = pair.spec.rack.alpha;
    let aw = pair.aw * k;
    let rw1 = w1.dw / 2.0 * k;
    let o1 = (0.0, 0.0);
    let o2 = if internal { (0.0, -aw) } else { (0.0, aw) };
    let p = (0.0, rw1);
    let t = (pair.alpha_w.cos(), pair.alpha_w.sin());
    let n1 = (p.0 - rw1 * pair.alpha_w.sin() * t.0, p.1 - rw1 * pair.alpha_w.sin() * t.1);
    let at = |s: f64| (n1.0 + s * k * t.0, n1.1 + s * k * t.1);
    let n2 = at(if internal { -pair.g } else { pair.g });
    let (a, b) = (at(pair.s_start), at(pair.s_end));
    // half-thickness angles at the operating circles
    let psi1 = w1.s / w1.d + inv(al) - inv(pair.alpha_w);
    let psi2 = if internal {
        w2.s / w2.d - inv(al) + inv(pair.alpha_w)
    } else {
        w2.s / w2.d + inv(al) - inv(pair.alpha_w)
    };
    let rot1 = psi1;
    let rot2 = if internal { -psi2 } else { -PI + psi2 };
    let mut circles = Vec::new();
    for (c, w, n) in [(o1, w1, 1), (o2, w2, 2)] {
        let _ = n;
        circles.push((c, w.d / 2.0 * k, "reference", "CIRCLE_REFERENCE", Style::AXIS));
        circles.push((c, w.db / 2.0 * k, "base", "CIRCLE_BASE", Style::THIN.colored("#1f5fbf")));
        circles.push((c, w.da / 2.0 * k, "tip", "CIRCLE_TIP", Style::THIN));
        circles.push((c, w.df / 2.0 * k, "root", "CIRCLE_ROOT", Style::THIN));
        circles.push((c, w.dw / 2.0 * k, "operating", "CIRCLE_OPERATING", Style::DASHED.colored("#b03000")));
    }
    // working parts: wheel 1's left flank of the tooth at rot1 from ρp1 to the tip
    let work = |t: &ToothProfile, side: f64, rmin: f64, rot: f64, c: Pt| -> Vec<Pt> {
        t.half
            .iter()
            .filter(|q| q.r * k >= rmin - 1e-9)
            .map(|q| turn((side * -q.r * k * q.psi.sin(), q.r * k * q.psi.cos()), rot, c))
            .collect()
    };
    let r_of = |rb: f64, rho: f64| ((rb * k).powi(2) + (rho * k).powi(2)).sqrt();
    let work1 = work(t1, -1.0, r_of(w1.db / 2.0, w1.rho_p), rot1, o1);
    let work2 = if internal {
        // ring: its working part runs from the tip (inside) out to ρp2
        let rmax = r_of(w2.db / 2.0, w2.rho_p);
        t2.half
            .iter()
            .filter(|q| q.r * k <= rmax + 1e-9)
            .map(|q| turn((-q.r * k * q.psi.sin(), q.r * k * q.psi.cos()), rot2, o2))
            .collect()
    } else {
        work(t2, -1.0, r_of(w2.db / 2.0, w2.rho_p), rot2, o2)
    };
    // arcs of action on the operating circles
    let sp = w1.db / 2.0 * pair.alpha_w.tan();
    let (d0, d1) = ((sp - pair.s_start) / (w1.db / 2.0), (pair.s_end - sp) / (w1.db / 2.0));
    let (e0, e1) = ((sp - pair.s_start) / (w2.db / 2.0), (pair.s_end - sp) / (w2.db / 2.0));
    // wheel 1 turns clockwise while the contact runs from A to B
    let mut arcs = vec![(o1, rw1, PI / 2.0 - d1, PI / 2.0 + d0)];
    let rw2 = w2.dw / 2.0 * k;
    if internal {
        arcs.push((o2, rw2, PI / 2.0 - e1, PI / 2.0 + e0));
    } else {
        arcs.push((o2, rw2, -PI / 2.0 - e0, -PI / 2.0 + e1));
    }
    Scene {
        o1,
        o2,
        p,
        n1,
        n2,
        a,
        b,
        rot1,
        rot2,
        circles,
        work1,
        work2,
        arcs,
    }
}

/// Teeth `-n..=n` around the one at the pole, each as its own polyline (mm).
fn teeth_near(t: &ToothProfile, rot: f64, c: Pt, n: i32) -> Vec<Vec<Pt>> {
    let one: Vec<Pt> = t.tooth_outline().iter().map(|&(x, y)| (x * 1e3, y * 1e3)).collect();
    let tau = 2.0 * PI / t.z as f64;
    (-n..=n)
        .map(|k| one.iter().map(|&q| turn(q, rot + k as f64 * tau, c)).collect())
        .collect()
}

/// The parameter table rows.
fn table(pair: &Pair) -> Vec<String> {
    let mm = |v: f64| format!("{:.3}", v * 1e3);
    let (w1, w2) = (&pair.w1, &pair.w2);
    let th = |v: Option<f64>, n: usize| v.map_or(format!("unbounded (contact reaches N{n})"), |x| format!("{x:.3}"));
    vec![
        format!("z1 = {}, z2 = {}, m = {} mm", w1.z, w2.z, mm(pair.spec.m)),
        format!("x1 = {:.4}, x2 = {:.4}", w1.x, w2.x),
        format!("αw = {:.4}°, aw = {} mm", pair.alpha_w.to_degrees(), mm(pair.aw)),
        format!("y = {:.4}, Δy = {:.4}", pair.y, pair.dy),
        format!("d: {} / {} mm", mm(w1.d), mm(w2.d)),
        format!("db: {} / {} mm", mm(w1.db), mm(w2.db)),
        format!("dw: {} / {} mm", mm(w1.dw), mm(w2.dw)),
        format!("da: {} / {} mm", mm(w1.da), mm(w2.da)),
        format!("df: {} / {} mm", mm(w1.df), mm(w2.df)),
        format!("s: {} / {} mm", mm(w1.s), mm(w2.s)),
        format!("sa: {} / {} mm", mm(w1.sa), mm(w2.sa)),
        format!("p = {} mm, pb = {} mm", mm(pair.p), mm(pair.pb)),
        format!("εα = {:.4}", pair.eps_alpha),
        format!("ϑ1max = {}, ϑ2max = {}", th(pair.theta1_max(), 1), th(pair.theta2_max(), 2)),
    ]
}

/// Sliding curves over the active line: (s in mm, ϑ1, ϑ2), clipped to [-4, 1].
fn sliding_curves(pair: &Pair, n: usize) -> (Vec<Pt>, Vec<Pt>) {
    let tab = pair.sliding_table(n);
    let clip = |v: f64| if v.is_finite() { v.clamp(-4.0, 1.0) } else { f64::NAN };
    (
        tab.iter().map(|q| (q.s * 1e3, clip(q.theta1))).collect(),
        tab.iter().map(|q| (q.s * 1e3, clip(q.theta2))).collect(),
    )
}

/// The parameter table rows in `lang` (indices marked for [`crate::labels::parts`]).
fn table_rows(pair: &Pair, lang: Language) -> Vec<String> {
    let mm = word(lang, "gear.mm");
    let n = |v: f64, d: usize| num(lang, v, d);
    let l = |v: f64| num(lang, v * 1e3, 3);
    let (w1, w2) = (&pair.w1, &pair.w2);
    // unbounded where the contact reaches N1 or N2 (ρ = 0 there): said in words
    let th = |v: Option<f64>, k: &str| v.map_or_else(|| word(lang, k).to_string(), |x| n(x, 3));
    vec![
        format!("z_1 = {}, z_2 = {}, m = {} {mm}", w1.z, w2.z, l(pair.spec.m)),
        format!("x_1 = {}, x_2 = {}", n(w1.x, 4), n(w2.x, 4)),
        format!("α_w = {}°", n(pair.alpha_w.to_degrees(), 4)),
        format!("a_w = {} {mm}", l(pair.aw)),
        format!("y = {}, Δy = {}", n(pair.y, 4), n(pair.dy, 4)),
        format!("d_1 = {}, d_2 = {} {mm}", l(w1.d), l(w2.d)),
        format!("d_b1 = {}, d_b2 = {} {mm}", l(w1.db), l(w2.db)),
        format!("d_w1 = {}, d_w2 = {} {mm}", l(w1.dw), l(w2.dw)),
        format!("d_a1 = {}, d_a2 = {} {mm}", l(w1.da), l(w2.da)),
        format!("d_f1 = {}, d_f2 = {} {mm}", l(w1.df), l(w2.df)),
        format!("s_1 = {}, s_2 = {} {mm}", l(w1.s), l(w2.s)),
        format!("s_a1 = {}, s_a2 = {} {mm}", l(w1.sa), l(w2.sa)),
        format!("p = {}, p_b = {} {mm}", l(pair.p), l(pair.pb)),
        format!("ε_α = {}", n(pair.eps_alpha, 4)),
        format!(
            "ϑ_1max = {}, ϑ_2max = {}",
            th(pair.theta1_max(), "gear.sliding_unbounded_1"),
            th(pair.theta2_max(), "gear.sliding_unbounded_2")
        ),
    ]
}

/// Where the meshing drawing puts the pair: the standard scale and the
/// paper position of the world origin (O1), mm from the bottom-left corner.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshLayout {
    /// The GOST 2.302 scale.
    pub scale: Scale,
    /// Paper = origin + scale · world (mm, y up).
    pub origin: (f64, f64),
    /// Width of the paper, mm.
    pub width: f64,
    /// Height of the paper, mm.
    pub height: f64,
    /// Left edge of the parameter table, mm.
    pub table_x: f64,
}

/// Width of the parameter table and legend on the right, mm.
const TABLE_W: f64 = 92.0;
/// Room for the name and the scale's line above the wheels, mm.
const TITLE_H: f64 = 17.0;

/// The largest standard scale at which both centres O1, O2, the pole, the
/// ends N1, N2 of the line of action and three pitches either side of the
/// pole fit the drawing's part of the Scheme slot (derived here: the spans
/// of these points plus 24 mm for the centres' marks and labels).
pub fn mesh_layout(pair: &Pair, sheet: SheetFormat) -> Option<MeshLayout> {
    let (w, h) = slot_mm(Slot::Scheme, sheet);
    let sc = key_points(pair);
    let (xmin, xmax, ymin, ymax) = sc
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY), |a, p| {
            (a.0.min(p.0), a.1.max(p.0), a.2.min(p.1), a.3.max(p.1))
        });
    let (dw, dh) = (w - TABLE_W - 4.0, h - TITLE_H - 4.0);
    let sx = standard_scale(xmax - xmin, dw - 24.0)?;
    let sy = standard_scale(ymax - ymin, dh - 24.0)?;
    let scale = if sx.factor < sy.factor { sx } else { sy };
    let s = scale.factor;
    let origin = (2.0 + 0.5 * dw - s * 0.5 * (xmin + xmax), 2.0 + 0.5 * dh - s * 0.5 * (ymin + ymax));
    Some(MeshLayout {
        scale,
        origin,
        width: w,
        height: h,
        table_x: w - TABLE_W,
    })
}

/// The points the meshing drawing must show (mm): O1, O2, P, N1, N2 and the
/// pole ± three pitches along the pole tangent, ± the tooth height.
fn key_points(pair: &Pair) -> Vec<Pt> {
    let k = 1e3;
    let internal = pair.spec.kind == Kind::Internal;
    let aw = pair.aw * k;
    let rw1 = pair.w1.dw / 2.0 * k;
    let p = (0.0, rw1);
    let t = (pair.alpha_w.cos(), pair.alpha_w.sin());
    let n1 = (p.0 - rw1 * pair.alpha_w.sin() * t.0, p.1 - rw1 * pair.alpha_w.sin() * t.1);
    let g = if internal { -pair.g } else { pair.g } * k;
    let n2 = (n1.0 + g * t.0, n1.1 + g * t.1);
    let o2 = if internal { (0.0, -aw) } else { (0.0, aw) };
    let (pitch, m) = (pair.p * k, pair.spec.m * k);
    vec![
        (0.0, 0.0),
        o2,
        p,
        n1,
        n2,
        (p.0 - 3.0 * pitch, p.1 - 2.5 * m),
        (p.0 + 3.0 * pitch, p.1 + 2.5 * m),
    ]
}

/// The meshing drawing (картина зацепления) as SVG, made for the Scheme
/// slot of `sheet` at a GOST 2.302 scale, words in `lang`: the wheels' teeth
/// near the pole, both centres O1 and O2, the circles d, d_b, d_a, d_f, d_w
/// of both wheels labelled, the line of action N1N2 with its active part AB
/// and the pole P, the working parts of the profiles, the arcs of action,
/// the centre distance a_w and the working pressure angle α_w dimensioned,
/// the parameter table and the legend.
pub fn mesh_svg(pair: &Pair, t1: &ToothProfile, t2: &ToothProfile, lang: Language, sheet: SheetFormat) -> Picture {
    let sc = scene(pair, t1, t2);
    let Some(lay) = mesh_layout(pair, sheet) else {
        return Canvas::new(10.0, 10.0).finish();
    };
    let (pw, ph) = (lay.width, lay.height);
    let s = lay.scale.factor;
    let mut c = Canvas::new(pw, ph);
    c.set_transform(s, lay.origin);
    let mut lab = Placer::new(pw, ph);
    // the drawing's window in world mm
    let (wx0, wx1) = ((2.0 - lay.origin.0) / s, (lay.table_x - 4.0 - lay.origin.0) / s);
    let (wy0, wy1) = ((2.0 - lay.origin.1) / s, (ph - TITLE_H - lay.origin.1) / s);
    let in_win = |q: &Pt| q.0 >= wx0 && q.0 <= wx1 && q.1 >= wy0 && q.1 <= wy1;
    let paper = |q: Pt| c_to_paper(&lay, q, ph);
    // the title over the drawing; one wider than the drawing's part (the
    // note's A4 page) over the whole paper, the table moved under it
    let title = word(lang, "gear.mesh_title");
    let title_w = CHAR_WIDTH * H_HEAD * plain(title).chars().count() as f64;
    let title_wide = title_w > lay.table_x - 6.0;
    let title_x = if title_wide {
        (0.5 * pw).min(pw - 1.0 - 0.5 * title_w).max(1.0 + 0.5 * title_w)
    } else {
        0.5 * (lay.table_x - 2.0)
    };
    // the name, and under it the scale (the note keeps the scale only)
    lab.put_title((title_x, 7.0), title, H_HEAD);
    lab.put(
        (title_x, 12.5),
        &format!("{} {}", word(lang, "common.scale"), crate::svg::scale_text(lay.scale.text, lang)),
        H_LABEL,
        "#000",
    );
    let k_line = Style::THICK.widened(0.6);
    c.begin_group("teeth");
    for (t, rot, cen) in [(t1, sc.rot1, sc.o1), (t2, sc.rot2, sc.o2)] {
        let n = t.z as i32 / 2 + 1;
        for tooth in teeth_near(t, rot, cen, n) {
            for run in tooth.split(|q| !in_win(q)) {
                if run.len() >= 2 {
                    c.polyline(run, k_line);
                }
            }
        }
    }
    c.end_group();
    // centre lines and centres
    c.begin_group("centres");
    let cross = 6.0 / s;
    // the line of centres 5 mm past both wheels' outer circles (GOST
    // 2.303: a centre line runs 2 … 5 mm beyond the contour), within the
    // window: on the note's page the figure then ends with the wheels
    let past = 5.0 / s;
    // (an internal wheel's root circle is its outer one)
    let (ra1, ra2) = (pair.w1.da.max(pair.w1.df) / 2.0 * 1e3, pair.w2.da.max(pair.w2.df) / 2.0 * 1e3);
    let reach_lo = (sc.o1.1 - ra1).min(sc.o2.1 - ra2) - past;
    let reach_hi = (sc.o1.1 + ra1).max(sc.o2.1 + ra2) + past;
    c.line((0.0, reach_lo.max(wy0)), (0.0, reach_hi.min(wy1)), DASH_DOT);
    for o in [sc.o1, sc.o2] {
        c.line((o.0 - 2.0 * cross, o.1), (o.0 + 2.0 * cross, o.1), DASH_DOT);
    }
    for (o, name) in [(sc.o1, "O_1"), (sc.o2, "O_2")] {
        c.begin_group(&format!("centre-{}", plain(name)));
        c.dot(o, 0.8, "#000");
        c.end_group();
        lab.reserve(label_box(paper(o), 1, 1.6));
    }
    c.end_group();
    // the line of action, the perpendiculars O1N1, O2N2, the active part
    c.begin_group("line-of-action");
    c.line(sc.o1, sc.n1, Style::THIN);
    c.line(sc.o2, sc.n2, Style::THIN);
    c.line(sc.n1, sc.n2, Style::THIN.widened(0.35));
    c.line(sc.a, sc.b, Style::THICK.colored(RED).widened(0.7));
    c.polyline(&sc.work1, Style::THICK.colored(MAGENTA).widened(0.8));
    c.polyline(&sc.work2, Style::THICK.colored(ORANGE).widened(0.8));
    for &(cen, r, a0, a1) in &sc.arcs {
        c.arc(cen, r, a0, a1, Style::THICK.colored(GREEN).widened(0.9));
    }
    for q in [sc.p, sc.n1, sc.n2, sc.a, sc.b] {
        c.dot(q, 0.7, "#000");
        lab.reserve(label_box(paper(q), 1, 1.4));
    }
    c.end_group();
    // the working pressure angle: between the pole tangent and N1N2
    c.begin_group("dimensions");
    let r_ang = (3.2 * pair.spec.m * 1e3 * s).clamp(22.0, 40.0);
    let pp = paper(sc.p);
    c.line_paper((pp.0 - r_ang - 6.0, pp.1), (pp.0 + r_ang + 6.0, pp.1), Style::THIN);
    let aw_ang = pair.alpha_w;
    let arc_pt = |a: f64, r: f64| (pp.0 + r * a.cos(), pp.1 - r * a.sin());
    let n_arc = 24;
    let arc_pts: Vec<Pt> = (0..=n_arc).map(|i| arc_pt(aw_ang * i as f64 / n_arc as f64, r_ang)).collect();
    for w in arc_pts.windows(2) {
        c.line_paper(w[0], w[1], Style::THIN);
    }
    // arrowheads at both ends, along the arc
    let head = 2.5;
    let e0 = arc_pts[0];
    let e1 = arc_pts[n_arc];
    c.arrow_paper((e0.0, e0.1 - head), e0, Style::THIN, head);
    c.arrow_paper((e1.0 + head * aw_ang.sin(), e1.1 + head * aw_ang.cos()), e1, Style::THIN, head);
    // the centre distance: a dimension line beside the wheels, where no
    // tooth is (left of the wheels for an external pair; between the
    // pinion and the ring's teeth for an internal one)
    let o1p = paper(sc.o1);
    let o2p = paper(sc.o2);
    let xd = aw_dimension_x(pair, &lay, o1p, o2p);
    c.line_paper((o1p.0 - 2.0, o1p.1), (xd - 2.0, o1p.1), Style::THIN);
    c.line_paper((o2p.0 - 2.0, o2p.1), (xd - 2.0, o2p.1), Style::THIN);
    let mid = (xd, 0.5 * (o1p.1 + o2p.1));
    c.arrow_paper(mid, (xd, o1p.1), Style::THIN, 3.0);
    c.arrow_paper(mid, (xd, o2p.1), Style::THIN, 3.0);
    c.end_group();
    // the circles, clipped to the window; their labels' anchors on them
    c.begin_group("circles");
    let mut circle_labels: Vec<(String, &'static str, Vec<Pt>)> = Vec::new();
    for (wheel, (cen, w)) in [(sc.o1, &pair.w1), (sc.o2, &pair.w2)].into_iter().enumerate() {
        let i = wheel + 1;
        let circles = [
            (w.d / 2.0, format!("d_{i}"), DASH_DOT),
            (w.db / 2.0, format!("d_b{i}"), Style::THIN.colored(BLUE)),
            (w.da / 2.0, format!("d_a{i}"), Style::THIN),
            (w.df / 2.0, format!("d_f{i}"), Style::THIN),
            (w.dw / 2.0, format!("d_w{i}"), DASH_DOT_DOT.colored(BROWN)),
        ];
        for (r, name, st) in circles {
            let r = r * 1e3;
            let n = 1440;
            let pts: Vec<Pt> = (0..=n)
                .map(|j| {
                    let a = 2.0 * PI * j as f64 / n as f64;
                    (cen.0 + r * a.cos(), cen.1 + r * a.sin())
                })
                .collect();
            // anchors about 3 mm apart on paper, far from the pole first
            let step = ((3.0 / (2.0 * PI * r * s / n as f64)).round() as usize).clamp(1, 120);
            let mut anchors: Vec<(f64, Pt)> = Vec::new();
            c.begin_group(&format!("circle-{}", plain(&name)));
            for run in pts.split(|q| !in_win(q)) {
                if run.len() >= 2 {
                    c.polyline(run, st);
                }
                for q in run.iter().skip(step / 2).step_by(step) {
                    anchors.push(((q.0 - sc.p.0).hypot(q.1 - sc.p.1), paper(*q)));
                }
            }
            c.end_group();
            anchors.sort_by(|a, b| b.0.total_cmp(&a.0));
            circle_labels.push((name, st.color, anchors.into_iter().map(|x| x.1).collect()));
        }
    }
    c.end_group();
    // the labels, after every line: clear of the lines, of each other, of
    // the table on the right; a label that cannot sit next to its point or
    // circle stands off on a leader
    let tx = lay.table_x;
    lab.reserve(Rect {
        x0: tx - 2.0,
        y0: 0.0,
        x1: pw,
        y1: ph,
    });
    lab.avoid_lines(c.segments());
    let mut leaders: Vec<(Pt, Pt, bool)> = Vec::new();
    let mut near =
        |lab: &mut Placer, anchors: &[Pt], text: &str, color: &str, arrow: bool| match lab.place_near(anchors, text, H_LABEL, color) {
            Some(n) => {
                if let Some((a, b)) = n.leader {
                    leaders.push((a, b, arrow));
                }
            }
            // nowhere clear within reach: next to the point, as before
            None => {
                if let Some(&p) = anchors.first() {
                    lab.put((p.0 + 4.0, p.1 - 3.0), text, H_LABEL, color);
                }
            }
        };
    for (q, name) in [
        (sc.o1, "O_1"),
        (sc.o2, "O_2"),
        (sc.p, "P"),
        (sc.n1, "N_1"),
        (sc.n2, "N_2"),
        (sc.a, "A"),
        (sc.b, "B"),
    ] {
        near(&mut lab, &[paper(q)], name, "#000", false);
    }
    // α_w beside its arc, on the bisector outside it, else on a leader
    let ang_txt = format!("α_w = {}°", num(lang, aw_ang.to_degrees(), 2));
    let ang_c: Vec<Pt> = (0..12)
        .flat_map(|i| {
            let r = r_ang + 4.0 + 2.0 * i as f64;
            let w = CHAR_WIDTH * H_LABEL * plain(&ang_txt).chars().count() as f64;
            [
                (pp.0 + r * (0.5 * aw_ang).cos() + 0.5 * w, pp.1 - r * (0.5 * aw_ang).sin()),
                (pp.0 - r * (0.5 * aw_ang).cos() - 0.5 * w, pp.1 + r * (0.5 * aw_ang).sin()),
            ]
        })
        .collect();
    if lab.place(&ang_c, &ang_txt, H_LABEL, "#000").is_none() {
        near(&mut lab, &[arc_pt(0.5 * aw_ang, r_ang)], &ang_txt, "#000", true);
    }
    // a_w beside its dimension line, on either side
    let aw_txt = format!("a_w = {}", num(lang, pair.aw * 1e3, 2));
    let naw = plain(&aw_txt).chars().count() as f64 * CHAR_WIDTH * H_LABEL;
    let aw_c: Vec<Pt> = (0..16)
        .flat_map(|i| {
            let dy = 5.0 * i as f64;
            let (r, l) = (xd + 1.5 + 0.5 * naw, xd - 1.5 - 0.5 * naw);
            [(r, mid.1 - dy), (r, mid.1 + dy), (l, mid.1 - dy), (l, mid.1 + dy)]
        })
        .collect();
    if lab.place(&aw_c, &aw_txt, H_LABEL, "#000").is_none() {
        near(&mut lab, &[mid], &aw_txt, "#000", true);
    }
    for (name, color, anchors) in &circle_labels {
        near(&mut lab, anchors, name, color, true);
    }
    for (a, b, arrow) in leaders {
        if arrow {
            c.arrow_paper(a, b, Style::THIN, 2.0);
        } else {
            c.line_paper(a, b, Style::THIN);
        }
    }
    let mut side = Placer::new(pw, ph);
    let left = |p: &mut Placer, y: f64, text: &str, h: f64| p.put_left((tx, y), text, h, "#000");
    let mut y = if title_wide { 20.0 } else { 8.0 };
    left(&mut side, y, word(lang, "gear.parameters"), H_LABEL);
    y += 2.0;
    for row in table_rows(pair, lang) {
        y += 5.5;
        left(&mut side, y, &row, 3.0);
    }
    y += 4.0;
    let legend: [(String, Style); 8] = [
        (word(lang, "gear.legend_active").to_string(), Style::THICK.colored(RED).widened(0.7)),
        (
            word(lang, "gear.legend_work1").to_string(),
            Style::THICK.colored(MAGENTA).widened(0.8),
        ),
        (
            word(lang, "gear.legend_work2").to_string(),
            Style::THICK.colored(ORANGE).widened(0.8),
        ),
        (word(lang, "gear.legend_arcs").to_string(), Style::THICK.colored(GREEN).widened(0.9)),
        (word(lang, "gear.legend_reference").to_string(), DASH_DOT),
        (word(lang, "gear.legend_operating").to_string(), DASH_DOT_DOT.colored(BROWN)),
        (word(lang, "gear.legend_base").to_string(), Style::THIN.colored(BLUE)),
        (word(lang, "gear.legend_tip_root").to_string(), Style::THIN),
    ];
    for (name, st) in legend {
        y += 5.5;
        c.line_paper((tx, y), (tx + 12.0, y), st);
        side.put_left((tx + 14.0, y), &name, 3.0, "#000");
    }
    finish_all(c.finish(), &[&lab, &side], Some(lay.scale.text))
}

/// The paper x of the centre distance's dimension line: 10 mm from the
/// paper's left edge for an external pair (left of both wheels); for an
/// internal pair the ring's teeth reach there, so the middle of the free
/// band between the ring's tip circle and the pinion's tip circle over the
/// height O1 … O2 (derived here: at the height of O1, the farthest from O2,
/// the ring's tip circle lies at x = x_O2 − √(r_a2² − a_w²) on paper, the
/// pinion's at x_O1 − r_a1), when that band is at least 30 mm wide.
fn aw_dimension_x(pair: &Pair, lay: &MeshLayout, o1p: Pt, o2p: Pt) -> f64 {
    if pair.spec.kind != Kind::Internal {
        return 10.0;
    }
    let s = lay.scale.factor * 1e3; // paper mm per m
    let (ra1, ra2, aw) = (pair.w1.da / 2.0 * s, pair.w2.da / 2.0 * s, pair.aw * s);
    if ra2 <= aw {
        return 10.0;
    }
    let left = o2p.0 - (ra2 * ra2 - aw * aw).sqrt();
    let right = o1p.0 - ra1;
    if right - left >= 30.0 { 0.5 * (left + right) } else { 10.0 }
}

fn c_to_paper(lay: &MeshLayout, q: Pt, ph: f64) -> Pt {
    (lay.origin.0 + lay.scale.factor * q.0, ph - (lay.origin.1 + lay.scale.factor * q.1))
}

const RED: &str = "#c00000";
const MAGENTA: &str = "#b000b0";
const ORANGE: &str = "#e07000";
const GREEN: &str = "#008000";
const BLUE: &str = "#1f5fbf";
const BROWN: &str = "#8a3a00";

/// The meshing drawing as DXF (mm, 1:1) with layers.
pub fn mesh_dxf(pair: &Pair, t1: &ToothProfile, t2: &ToothProfile) -> DxfDoc {
    let sc = scene(pair, t1, t2);
    let mut d = DxfDoc::new();
    for &(cen, r, _, layer, _) in &sc.circles {
        let color = match layer {
            "CIRCLE_REFERENCE" => 4,
            "CIRCLE_BASE" => 5,
            "CIRCLE_OPERATING" => 6,
            _ => 8,
        };
        d.layer(layer, color);
        d.circle(cen, r);
    }
    d.layer("WHEEL1", 7);
    let full = |t: &ToothProfile, rot: f64, c: Pt| -> Vec<Pt> {
        t.wheel_outline(rot).iter().map(|&(x, y)| (c.0 + x * 1e3, c.1 + y * 1e3)).collect()
    };
    d.polyline(&full(t1, sc.rot1, sc.o1), true);
    d.layer("WHEEL2", 7);
    d.polyline(&full(t2, sc.rot2, sc.o2), true);
    d.layer("LINE_OF_ACTION", 3);
    d.line(sc.n1, sc.n2);
    d.layer("ACTIVE_LINE", 1);
    d.line(sc.a, sc.b);
    d.layer("WORKING_PROFILES", 1);
    d.polyline(&sc.work1, false);
    d.polyline(&sc.work2, false);
    d.layer("ARCS_OF_ACTION", 3);
    for &(cen, r, a0, a1) in &sc.arcs {
        d.arc(cen, r, a0.to_degrees(), a1.to_degrees());
    }
    d.layer("TEXT", 7);
    let h = (pair.spec.m * 1e3 * 0.6).max(1.0);
    for (q, name) in [
        (sc.p, "P"),
        (sc.n1, "N1"),
        (sc.n2, "N2"),
        (sc.a, "A"),
        (sc.b, "B"),
        (sc.o1, "O1"),
        (sc.o2, "O2"),
    ] {
        d.text((q.0 + 0.3 * h, q.1 + 0.3 * h), h, name);
    }
    // the sliding diagram beside the wheels: s along x, ϑ scaled by 10 m per unit
    d.layer("SLIDING", 2);
    let r_big = pair.w1.da.max(pair.w2.da) * 1e3;
    let ox = r_big * 1.3 + 20.0;
    let unit = 4.0 * pair.spec.m * 1e3;
    let (th1, th2) = sliding_curves(pair, 81);
    for curve in [&th1, &th2] {
        let pts: Vec<Pt> = curve
            .iter()
            .filter(|q| q.1.is_finite())
            .map(|&(s, v)| (ox + s * 5.0, v * unit))
            .collect();
        d.polyline(&pts, false);
    }
    d.line((ox + pair.s_start * 5e3, 0.0), (ox + pair.s_end * 5e3, 0.0));
    d.text((ox, 1.5 * unit), h, "specific sliding (x: s·5, y: ϑ·4m)");
    d.layer("TABLE", 7);
    let mut y = -r_big * 0.2;
    for row in table(pair) {
        d.text((ox, y), h, &row);
        y -= 1.8 * h;
    }
    d
}
