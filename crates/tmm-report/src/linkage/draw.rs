//! Drawings of the `[linkage]` section: the mechanism in its positions
//! overlaid, the kinematic diagrams of the output, and the velocity and
//! acceleration plans with their scale factors μ.

use tmm_geom::Vec2;
use tmm_linkage::Solution;
use tmm_linkage::mechanism::Pair;
use tmm_linkage::plans::{PlanVector, VectorKind};

use super::{Analysis, Loaded};
use crate::Error;
use crate::output::Documents;
use crate::svg::{Anchor, Canvas, Series, Style, nice_ticks, plot};

/// Every drawing, as documents whose paths start with `dir` (`"linkage/"` gives `linkage/positions.svg`).
pub fn draw_all(l: &Loaded, a: &Analysis, dir: &str, docs: &mut Documents) -> Result<(), Error> {
    docs.add_text(format!("{dir}positions.svg"), positions(l, a))?;
    let w = l.mech.crank.omega.abs();
    let lin = a.reading.output.kind == tmm_linkage::cycle::OutputKind::Linear;
    let (su, vu) = if lin { ("s, m", "m") } else { ("s, rad", "rad") };
    let (ds_label, dds_label) = (format!("ds/dφ, {vu}"), format!("d²s/dφ², {vu}"));
    /// One kinematic diagram: file, title, axis labels, curve, colour, and
    /// how a sample (ψ, s, ds/dφ, d²s/dφ²) maps to a point given |ω1|.
    struct Diagram<'a> {
        file: &'a str,
        title: &'a str,
        x_label: &'a str,
        y_label: &'a str,
        name: &'a str,
        color: &'static str,
        x: fn(&[f64; 4], f64) -> f64,
        y: fn(&[f64; 4], f64) -> f64,
    }
    let by_angle = |d: &[f64; 4], _: f64| d[0].to_degrees();
    let by_time = |d: &[f64; 4], w: f64| d[0] / w;
    let diagrams = [
        Diagram {
            file: "diagram-s.svg",
            title: "Output displacement s(φ)",
            x_label: "crank rotation from the start φ, °",
            y_label: su,
            name: "s",
            color: "#1f4e9c",
            x: by_angle,
            y: |d, _| d[1],
        },
        Diagram {
            file: "diagram-ds.svg",
            title: "Velocity analog ds/dφ",
            x_label: "φ, °",
            y_label: &ds_label,
            name: "ds/dφ",
            color: "#c0392b",
            x: by_angle,
            y: |d, _| d[2],
        },
        Diagram {
            file: "diagram-dds.svg",
            title: "Acceleration analog d²s/dφ²",
            x_label: "φ, °",
            y_label: &dds_label,
            name: "d²s/dφ²",
            color: "#27ae60",
            x: by_angle,
            y: |d, _| d[3],
        },
        Diagram {
            file: "diagram-v.svg",
            title: "Output velocity v(t)",
            x_label: "t, s",
            y_label: if lin { "v, m/s" } else { "ω, rad/s" },
            name: "v",
            color: "#c0392b",
            x: by_time,
            y: |d, w| d[2] * w,
        },
        Diagram {
            file: "diagram-a.svg",
            title: "Output acceleration a(t)",
            x_label: "t, s",
            y_label: if lin { "a, m/s²" } else { "ε, rad/s²" },
            name: "a",
            color: "#27ae60",
            x: by_time,
            y: |d, w| d[3] * w * w,
        },
    ];
    for g in diagrams {
        let (points, gaps) = split_at_gaps(a, |d| ((g.x)(d, w), (g.y)(d, w)));
        let mut series = vec![Series {
            name: g.name,
            points: &points,
            color: g.color,
        }];
        if !gaps.is_empty() {
            series.push(Series {
                name: "does not assemble",
                points: &gaps,
                color: "#999999",
            });
        }
        docs.add_text(
            format!("{dir}{}", g.file),
            plot(g.title, g.x_label, g.y_label, &series, 200.0, 120.0),
        )?;
    }
    docs.add_text(
        format!("{dir}velocity-plan.svg"),
        plan("Velocity plan", "p", "m/s", &a.plans.velocity, a.plan_row.pos.phi),
    )?;
    docs.add_text(
        format!("{dir}acceleration-plan.svg"),
        plan("Acceleration plan", "π", "m/s²", &a.plans.acceleration, a.plan_row.pos.phi),
    )?;
    Ok(())
}

/// Points of a plotted line.
type Polyline = Vec<(f64, f64)>;

/// A diagram's points with a break (a non-finite point, where the plot lifts
/// its pen) between assembly ranges, and the gaps as
/// boxes over the curve's height, each followed by a break.
fn split_at_gaps(a: &Analysis, f: impl Fn(&[f64; 4]) -> (f64, f64)) -> (Polyline, Polyline) {
    const BREAK: (f64, f64) = (f64::NAN, f64::NAN);
    let mut points = Vec::with_capacity(a.diagram.len() + a.diagram_breaks.len());
    for (k, d) in a.diagram.iter().enumerate() {
        if a.diagram_breaks.contains(&k) {
            points.push(BREAK);
        }
        points.push(f(d));
    }
    // each gap framed by a box over the curve's height
    let (lo, hi) = points
        .iter()
        .filter(|p| p.1.is_finite())
        .fold((0.0f64, 0.0f64), |(lo, hi), p| (lo.min(p.1), hi.max(p.1)));
    let mut gaps = Vec::new();
    for &(from, to) in &a.diagram_gaps {
        let (x0, x1) = (f(&[from, 0.0, 0.0, 0.0]).0, f(&[to, 0.0, 0.0, 0.0]).0);
        gaps.extend([(x0, lo), (x0, hi), (x1, hi), (x1, lo), (x0, lo), BREAK]);
    }
    (points, gaps)
}

/// Segments of each link between its joints, at one solution.
fn link_segments(l: &Loaded, sol: &Solution) -> Vec<(Vec2, Vec2)> {
    let m = &l.mech;
    let mut segs = Vec::new();
    for li in 1..m.link_names.len() {
        let mut joints: Vec<Vec2> = Vec::new();
        for p in m.pairs.iter().filter(|p| matches!(p, Pair::R { .. })) {
            let (a, b) = p.links();
            if a == li || b == li {
                let pos = sol.points[p.point()].p;
                if !joints.iter().any(|j| (*j - pos).hypot() < 1e-12) {
                    joints.push(pos);
                }
            }
        }
        for i in 0..joints.len() {
            for j in i + 1..joints.len() {
                if joints.len() <= 3 || j == i + 1 {
                    segs.push((joints[i], joints[j]));
                }
            }
        }
    }
    segs
}

fn positions(l: &Loaded, a: &Analysis) -> String {
    let m = &l.mech;
    let mut pts: Vec<Vec2> = Vec::new();
    for r in &a.rows {
        pts.extend(r.sol.points.iter().map(|p| p.p));
    }
    let (xmin, xmax) = pts
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.x), b.max(p.x)));
    let (ymin, ymax) = pts
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.y), b.max(p.y)));
    let mut c = Canvas::new(297.0, 210.0);
    let scale = c.fit((xmin, xmax, ymin, ymax), (15.0, 20.0, 267.0, 165.0));
    c.text_paper(
        (148.5, 10.0),
        &format!(
            "Mechanism in {} positions (μl = {:.5} m/mm); bold: φ = {:.2}°",
            a.rows.len(),
            1.0 / scale,
            a.plan_row.pos.phi.to_degrees()
        ),
        4.0,
        Anchor::Middle,
        "#000",
    );
    let xy = |v: Vec2| (v.x, v.y);
    // trajectories of the joints
    for (k, p) in m.points.iter().enumerate() {
        if p.link == 0 || !m.pairs.iter().any(|pr| pr.point() == k) {
            continue;
        }
        let tr: Vec<(f64, f64)> = a.rows.iter().map(|r| xy(r.sol.points[k].p)).collect();
        // one trajectory per assembly range
        let mut from = 0;
        for to in a.row_breaks.iter().copied().chain([tr.len()]) {
            c.polyline(&tr[from..to.max(from)], Style::DASHED.colored("#999999"));
            from = to;
        }
    }
    for r in &a.rows {
        for (p, q) in link_segments(l, &r.sol) {
            c.line(xy(p), xy(q), Style::THIN.colored("#7f8c8d"));
        }
        if let Some(k) = m.points.iter().position(|p| p.name == m.points[m.crank.pin].name) {
            let pp = r.sol.points[k].p;
            c.text_colored((pp.x, pp.y), &r.pos.label, 2.5, Anchor::Start, "#555");
        }
    }
    let sol = &a.plan_row.sol;
    for (p, q) in link_segments(l, sol) {
        c.line(xy(p), xy(q), Style::THICK);
    }
    // guides
    for pr in &m.pairs {
        if let Pair::P { guide, point, q, d, .. } = *pr {
            let g = &sol.links[guide];
            let qq = g.pos(q);
            let dd = tmm_linkage::state::rot(g.u, d);
            let sp = sol.points[point].p;
            let t = (sp - qq).dot(dd);
            let span = 0.25 * (xmax - xmin).max(ymax - ymin);
            c.line(xy(qq + dd * (t - span)), xy(qq + dd * (t + span)), Style::AXIS);
            let half = 3.0 / scale;
            let n = Vec2::new(-dd.y, dd.x);
            let corners = [
                sp + dd * half + n * half * 0.6,
                sp - dd * half + n * half * 0.6,
                sp - dd * half - n * half * 0.6,
                sp + dd * half - n * half * 0.6,
            ];
            c.polygon(&corners.map(xy), Style::THICK.widened(0.5).filled("#ffffff"));
        }
    }
    for (k, p) in m.points.iter().enumerate() {
        let pos = sol.points[k].p;
        let is_joint = m.pairs.iter().any(|pr| pr.point() == k);
        if p.link == 0 {
            c.fixed_pivot(xy(pos), 1.3);
        } else if is_joint {
            c.joint(xy(pos), 1.0);
        } else {
            c.dot(xy(pos), 0.6, "#000000");
        }
        // a label once per place (a centre of mass at a joint keeps the joint's name)
        let first_here = m
            .points
            .iter()
            .enumerate()
            .position(|(j, _)| (sol.points[j].p - pos).hypot() * scale < 1.0)
            == Some(k);
        if first_here {
            c.text((pos.x + 2.0 / scale, pos.y + 2.0 / scale), &p.name, 3.2, Anchor::Start);
        }
    }
    c.finish()
}

fn plan(title: &str, pole: &str, unit: &str, v: &[PlanVector], phi: f64) -> String {
    let mut c = Canvas::new(210.0, 210.0);
    let mut pts = vec![Vec2::ZERO];
    for p in v {
        pts.push(p.from);
        pts.push(p.to);
    }
    let (xmin, xmax) = pts
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.x), b.max(p.x)));
    let (ymin, ymax) = pts
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.y), b.max(p.y)));
    let span = (xmax - xmin).max(ymax - ymin).max(1e-12);
    // a round scale factor μ (units per mm) so that the plan fits 170 mm
    let (_, _, step) = nice_ticks(0.0, span / 170.0, 1);
    let mu = step;
    let s = 1.0 / mu;
    let cx = 105.0 - s * 0.5 * (xmin + xmax);
    let cy = 100.0 - s * 0.5 * (ymin + ymax);
    c.set_transform(s, (cx, cy));
    c.text_paper(
        (105.0, 10.0),
        &format!("{title} at φ = {:.2}°,  μ = {mu} {unit}/mm", phi.to_degrees()),
        4.0,
        Anchor::Middle,
        "#000",
    );
    let color = |k: VectorKind| match k {
        VectorKind::Absolute => "#1f4e9c",
        VectorKind::Relative => "#c0392b",
        VectorKind::Normal => "#8e44ad",
        VectorKind::Tangential => "#c0392b",
        VectorKind::Sliding => "#27ae60",
        VectorKind::Coriolis => "#d35400",
    };
    for p in v {
        if (p.to - p.from).hypot() * s < 0.05 {
            continue;
        }
        c.arrow(
            (p.from.x, p.from.y),
            (p.to.x, p.to.y),
            Style::THIN.widened(0.35).colored(color(p.kind)),
            3.0,
        );
        if p.kind == VectorKind::Absolute {
            // the plan point, named as the course names it: b, c, s2…
            let name = p.label.split_once('_').map_or(p.label.as_str(), |x| x.1).to_lowercase();
            c.text((p.to.x, p.to.y), &name, 3.2, Anchor::Start);
        } else {
            let mid = (p.from + p.to) * 0.5;
            c.text_colored((mid.x, mid.y), &p.label, 2.4, Anchor::Start, color(p.kind));
        }
    }
    c.dot((0.0, 0.0), 0.8, "#000000");
    c.text((0.0, 0.0), pole, 3.5, Anchor::End);
    c.finish()
}
