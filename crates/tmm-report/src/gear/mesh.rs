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
use crate::svg::{Anchor, Canvas, Style};

type Pt = (f64, f64);

/// The geometry of the drawing in millimetres.
struct Scene {
    o1: Pt,
    o2: Pt,
    p: Pt,
    n1: Pt,
    n2: Pt,
    a: Pt,
    b: Pt,
    rot1: f64,
    rot2: f64,
    internal: bool,
    /// (centre, radius, name, DXF layer, style)
    circles: Vec<(Pt, f64, &'static str, &'static str, Style)>,
    work1: Vec<Pt>,
    work2: Vec<Pt>,
    /// (centre, r, a0, a1) rad
    arcs: Vec<(Pt, f64, f64, f64)>,
}

fn turn(p: Pt, a: f64, c: Pt) -> Pt {
    let (s, co) = a.sin_cos();
    (c.0 + co * p.0 - s * p.1, c.1 + s * p.0 + co * p.1)
}

fn inv(a: f64) -> f64 {
    a.tan() - a
}

fn scene(pair: &Pair, t1: &ToothProfile, t2: &ToothProfile) -> Scene {
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
        internal,
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
    let th = |v: Option<f64>| v.map_or("∞".to_string(), |x| format!("{x:.3}"));
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
        format!("ϑ1max = {}, ϑ2max = {}", th(pair.theta1_max()), th(pair.theta2_max())),
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

/// The meshing drawing as SVG on an A3 landscape sheet.
pub fn mesh_svg(pair: &Pair, t1: &ToothProfile, t2: &ToothProfile) -> String {
    let sc = scene(pair, t1, t2);
    let (pw, ph) = (420.0, 297.0);
    let mut c = Canvas::new(pw, ph);
    let pitch = pair.p * 1e3;
    let half_w = 2.8 * pitch;
    let half_h = 2.8 * pitch;
    let world = (sc.p.0 - half_w, sc.p.0 + half_w, sc.p.1 - half_h, sc.p.1 + half_h);
    let scale = c.fit(world, (10.0, 10.0, 270.0, 277.0));
    let in_win = |q: &Pt| q.0 >= world.0 && q.0 <= world.1 && q.1 >= world.2 && q.1 <= world.3;
    c.text_paper(
        (145.0, 8.0),
        &format!("Meshing drawing, scale {:.2} : 1", scale),
        4.5,
        Anchor::Middle,
        "#000",
    );
    c.begin_group("circles");
    for &(cen, r, name, _, st) in &sc.circles {
        // the part of the circle inside the window, as runs of a fine polyline
        let n = 720;
        let pts: Vec<Pt> = (0..=n)
            .map(|i| {
                let a = 2.0 * PI * i as f64 / n as f64;
                (cen.0 + r * a.cos(), cen.1 + r * a.sin())
            })
            .collect();
        let mut label_at: Option<Pt> = None;
        for run in pts.split(|q| !in_win(q)) {
            if run.len() >= 2 {
                c.polyline(run, st);
                label_at = label_at.or(run.last().copied());
            }
        }
        if let Some(q) = label_at {
            c.text(q, name, 2.0, Anchor::Start);
        }
    }
    c.end_group();
    c.begin_group("teeth");
    for (t, rot, cen) in [(t1, sc.rot1, sc.o1), (t2, sc.rot2, sc.o2)] {
        let n = ((half_w * 1.2 / (pitch)).ceil() as i32 + 1).min(t.z as i32 / 2);
        for tooth in teeth_near(t, rot, cen, n) {
            for run in tooth.split(|q| !in_win(q)) {
                c.polyline(run, Style::THICK.widened(0.5));
            }
        }
    }
    c.end_group();
    c.begin_group("line-of-action");
    c.line(sc.n1, sc.n2, Style::THIN);
    c.line(sc.a, sc.b, Style::THICK.colored("#c00000").widened(0.6));
    c.polyline(&sc.work1, Style::THICK.colored("#d000d0").widened(0.8));
    c.polyline(&sc.work2, Style::THICK.colored("#ff8c00").widened(0.8));
    for &(cen, r, a0, a1) in &sc.arcs {
        c.arc(cen, r, a0, a1, Style::THICK.colored("#008000").widened(0.9));
    }
    for (q, name) in [(sc.p, "P"), (sc.n1, "N1"), (sc.n2, "N2"), (sc.a, "A"), (sc.b, "B")] {
        if in_win(&q) {
            c.dot(q, 0.7, "#000");
            c.text((q.0 + 0.02 * half_w, q.1 + 0.02 * half_w), name, 3.0, Anchor::Start);
        }
    }
    c.end_group();
    let _ = sc.internal;
    // parameter table and the sliding diagram on the right
    let mut y = 20.0;
    c.text_paper((290.0, y), "Parameters", 4.0, Anchor::Start, "#000");
    for row in table(pair) {
        y += 6.0;
        c.text_paper((290.0, y), &row, 3.0, Anchor::Start, "#000");
    }
    let legend: [(&str, Style); 6] = [
        ("active line of action AB", Style::THICK.colored("#c00000").widened(0.6)),
        ("working profile, wheel 1", Style::THICK.colored("#d000d0").widened(0.8)),
        ("working profile, wheel 2", Style::THICK.colored("#ff8c00").widened(0.8)),
        ("arcs of action (operating circles)", Style::THICK.colored("#008000").widened(0.9)),
        ("operating circles", Style::DASHED.colored("#b03000")),
        ("base circles", Style::THIN.colored("#1f5fbf")),
    ];
    y += 4.0;
    for (name, st) in legend {
        y += 5.0;
        c.line_paper((290.0, y - 1.0), (298.0, y - 1.0), st);
        c.text_paper((300.0, y), name, 2.8, Anchor::Start, "#000");
    }
    let (th1, th2) = sliding_curves(pair, 81);
    let (bx, by, bw, bh) = (292.0, 170.0, 118.0, 105.0);
    let (s0, s1) = (pair.s_start * 1e3, pair.s_end * 1e3);
    let mapx = |s: f64| bx + (s - s0) / (s1 - s0).max(1e-9) * bw;
    let mapy = |v: f64| by + (1.0 - v) / 5.0 * bh;
    c.text_paper(
        (bx, by - 6.0),
        "Specific sliding on the active line AB (clipped to [−4, 1])",
        2.8,
        Anchor::Start,
        "#000",
    );
    c.line_paper((bx, mapy(0.0)), (bx + bw, mapy(0.0)), Style::THIN);
    c.line_paper((bx, by), (bx, by + bh), Style::THIN);
    for v in [1.0, 0.0, -1.0, -2.0, -3.0, -4.0] {
        c.text_paper((bx - 1.5, mapy(v) + 1.0), &format!("{v}"), 2.5, Anchor::End, "#000");
        c.line_paper(
            (bx, mapy(v)),
            (bx + bw, mapy(v)),
            Style {
                width: 0.1,
                color: "#bbbbbb",
                dash: None,
                fill: None,
            },
        );
    }
    for (curve, col, name) in [(&th1, "#c00000", "ϑ1"), (&th2, "#1f5fbf", "ϑ2")] {
        let pts: Vec<Pt> = curve.iter().filter(|q| q.1.is_finite()).map(|&(s, v)| (mapx(s), mapy(v))).collect();
        for w in pts.windows(2) {
            c.line_paper(w[0], w[1], Style::THICK.colored(col).widened(0.5));
        }
        if let Some(&l) = pts.last() {
            c.text_paper((l.0 + 1.0, l.1), name, 3.0, Anchor::Start, col);
        }
    }
    c.text_paper((bx, by + bh + 6.0), "A", 3.0, Anchor::Middle, "#000");
    c.text_paper((bx + bw, by + bh + 6.0), "B", 3.0, Anchor::Middle, "#000");
    c.finish()
}

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

#[cfg(test)]
mod tests {
    use super::*;
    use tmm_gears::{PairSpec, generate::generate};

    fn dist_to_polyline(p: Pt, pl: &[Pt]) -> f64 {
        pl.windows(2)
            .map(|w| {
                let (a, b) = (w[0], w[1]);
                let (dx, dy) = (b.0 - a.0, b.1 - a.1);
                let t = (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / (dx * dx + dy * dy).max(1e-300)).clamp(0.0, 1.0);
                ((a.0 + t * dx - p.0).powi(2) + (a.1 + t * dy - p.1).powi(2)).sqrt()
            })
            .fold(f64::INFINITY, f64::min)
    }

    /// Both working profiles pass through the pole, and their tangents there are
    /// perpendicular to N1N2 (the placement derived in docs/gears.md).
    #[test]
    fn working_profiles_meet_at_the_pole() {
        let cases = [
            (15u32, 20u32, 0.2, 0.85, Kind::External),
            (17, 40, 0.0, 0.0, Kind::External),
            (12, 31, 0.5, -0.1, Kind::External),
            (20, 60, 0.5, 0.8, Kind::Internal),
        ];
        for &(z1, z2, x1, x2, kind) in &cases {
            let pair = Pair::new(&PairSpec {
                kind,
                ..PairSpec::external(z1, z2, 0.005, x1, x2)
            })
            .unwrap();
            let (t1, t2) = crate::gear::profiles(&pair, &crate::gear::input::Origin::Cli).unwrap();
            let sc = scene(&pair, &t1, &t2);
            let line = (sc.n2.0 - sc.n1.0, sc.n2.1 - sc.n1.1);
            for (w, work) in [(1, &sc.work1), (2, &sc.work2)] {
                assert!(
                    dist_to_polyline(sc.p, work) < 0.02,
                    "{z1}/{z2}: wheel {w} misses P by {} first {:?} last {:?} P {:?}",
                    dist_to_polyline(sc.p, work),
                    work.first(),
                    work.last(),
                    sc.p
                );
                let near = work
                    .windows(2)
                    .min_by(|a, b| dist_to_polyline(sc.p, a).total_cmp(&dist_to_polyline(sc.p, b)))
                    .unwrap();
                let tang = (near[1].0 - near[0].0, near[1].1 - near[0].1);
                let cos = (tang.0 * line.0 + tang.1 * line.1) / (tang.0.hypot(tang.1) * line.0.hypot(line.1));
                assert!(cos.abs() < 0.03, "{z1}/{z2} wheel {w}: cos {cos}");
            }
            // A and B lie on the tip circles of wheel 2 and wheel 1
            let d = |a: Pt, b: Pt| (a.0 - b.0).hypot(a.1 - b.1);
            assert!((d(sc.a, sc.o2) - pair.w2.da / 2.0 * 1e3).abs() < 1e-9);
            assert!((d(sc.b, sc.o1) - pair.w1.da / 2.0 * 1e3).abs() < 1e-9);
        }
    }

    /// The arcs of action: turning wheel 1 to the start of its arc brings its
    /// working profile through A, to the end through B; each arc over the
    /// angular pitch is εα (seed 003 §17 measures εα this way off the drawing).
    #[test]
    fn arcs_of_action() {
        let cases = [
            (15u32, 20u32, 0.2, 0.85, Kind::External),
            (17, 40, 0.0, 0.0, Kind::External),
            (20, 60, 0.5, 0.8, Kind::Internal),
        ];
        for &(z1, z2, x1, x2, kind) in &cases {
            let pair = Pair::new(&PairSpec {
                kind,
                ..PairSpec::external(z1, z2, 0.005, x1, x2)
            })
            .unwrap();
            let (t1, t2) = crate::gear::profiles(&pair, &crate::gear::input::Origin::Cli).unwrap();
            let sc = scene(&pair, &t1, &t2);
            let (c1, r1, a0, a1) = sc.arcs[0];
            assert_eq!(c1, sc.o1);
            let tau1 = 2.0 * PI / z1 as f64;
            assert!(((a1 - a0) / tau1 - pair.eps_alpha).abs() < 1e-12);
            let (_, _, b0, b1) = sc.arcs[1];
            assert!(((b1 - b0) / (2.0 * PI / z2 as f64) - pair.eps_alpha).abs() < 1e-12);
            assert!(a0 < PI / 2.0 && PI / 2.0 < a1 && (r1 - pair.w1.dw / 2.0 * 1e3).abs() < 1e-9);
            // the arc's ends, reached from the pole position
            let full: Vec<Pt> = t1
                .half
                .iter()
                .map(|q| turn((q.r * 1e3 * q.psi.sin(), q.r * 1e3 * q.psi.cos()), sc.rot1, sc.o1))
                .collect();
            let at = |turn_by: f64| -> Vec<Pt> { full.iter().map(|&q| turn(q, turn_by, sc.o1)).collect() };
            // wheel 1 turns clockwise while the contact runs from A to B
            assert!(dist_to_polyline(sc.a, &at(a1 - PI / 2.0)) < 0.02, "{z1}/{z2}: wheel 1 misses A");
            assert!(dist_to_polyline(sc.b, &at(a0 - PI / 2.0)) < 0.02, "{z1}/{z2}: wheel 1 misses B");
            // wheel 2 the other way (a ring the same way)
            let ring = kind == Kind::Internal;
            let sgn = if ring { -1.0 } else { 1.0 };
            let full2: Vec<Pt> = t2
                .half
                .iter()
                .map(|q| turn((sgn * q.r * 1e3 * q.psi.sin(), q.r * 1e3 * q.psi.cos()), sc.rot2, sc.o2))
                .collect();
            let at2 = |turn_by: f64| -> Vec<Pt> {
                full2
                    .iter()
                    .map(|&q| turn((q.0 - sc.o2.0, q.1 - sc.o2.1), turn_by, sc.o2))
                    .collect()
            };
            let mid = if ring { PI / 2.0 } else { -PI / 2.0 };
            let (ta, tb) = if ring { (b1 - mid, b0 - mid) } else { (b0 - mid, b1 - mid) };
            assert!(dist_to_polyline(sc.a, &at2(ta)) < 0.02, "{z1}/{z2}: wheel 2 misses A");
            assert!(dist_to_polyline(sc.b, &at2(tb)) < 0.02, "{z1}/{z2}: wheel 2 misses B");
        }
    }

    /// The DXF reads back with its layers and one closed outline per wheel.
    #[test]
    fn dxf_reads_back_with_layers() {
        let pair = Pair::new(&PairSpec::external(15, 20, 0.005, 0.2, 0.85)).unwrap();
        let r = pair.spec.rack;
        let t1 = generate(15, 0.005, 0.2, &r, pair.w1.da / 2.0, 40).unwrap();
        let t2 = generate(20, 0.005, 0.85, &r, pair.w2.da / 2.0, 40).unwrap();
        let text = mesh_dxf(&pair, &t1, &t2).to_text().unwrap();
        let back = dxf::Drawing::load(&mut text.as_bytes()).unwrap();
        let layers: Vec<String> = back.layers().map(|l| l.name.clone()).collect();
        for l in [
            "WHEEL1",
            "WHEEL2",
            "LINE_OF_ACTION",
            "ACTIVE_LINE",
            "WORKING_PROFILES",
            "ARCS_OF_ACTION",
            "CIRCLE_BASE",
            "SLIDING",
            "TABLE",
        ] {
            assert!(layers.iter().any(|x| x == l), "{l}");
        }
        let outlines = back
            .entities()
            .filter(|e| matches!(e.specific, dxf::entities::EntityType::LwPolyline(_)) && e.common.layer.starts_with("WHEEL"))
            .count();
        assert_eq!(outlines, 2);
    }
}
