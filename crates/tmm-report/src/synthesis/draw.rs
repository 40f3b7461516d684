//! Drawings of a synthesis: the construction as the course draws it, to
//! scale — the mechanism at its two extreme (dead) positions, the chord
//! between the driven point's extreme positions, the circle through them
//! whose centre sees the chord at 2θ, the arc of it from which the chord is
//! seen at θ (the locus of crank pivots), and the chosen pivot with its rays
//! to the extremes — and the pressure-angle curve over the cycle, computed by
//! the linkage core (not by the synthesis formulas).

use tmm_geom::Vec2;
use tmm_linkage::Mechanism;
use tmm_linkage::cycle::{Cycle, Working, pressure_angles};

use tmm_linkage::synthesis::Kind;

use super::Solved;
use crate::Error;
use crate::output::Documents;
use crate::svg::{Anchor, Canvas, Series, Style, plot};

const BLUE: &str = "#1f4e9c";
const RED: &str = "#c0392b";
const GREEN: &str = "#1e8449";
const GREY: &str = "#7f8c8d";

/// Both drawings.
pub fn drawings(s: &Solved) -> Result<Documents, Error> {
    let mut d = Documents::new();
    d.add_text("synthesis/construction.svg", construction(s))?;
    d.add_text("synthesis/pressure.svg", pressure(s)?)?;
    Ok(d)
}

type Box4 = (f64, f64, f64, f64);

fn grow(b: Box4, p: Vec2) -> Box4 {
    (b.0.min(p.x), b.1.max(p.x), b.2.min(p.y), b.3.max(p.y))
}

fn inside(b: Box4, p: Vec2) -> bool {
    p.x >= b.0 && p.x <= b.1 && p.y >= b.2 && p.y <= b.3
}

/// An arc drawn only where it lies inside the box `b` (a large locus circle
/// would otherwise shrink the mechanism to a dot).
fn clipped_arc(c: &mut Canvas, center: Vec2, r: f64, a0: f64, sweep: f64, b: Box4, st: Style) {
    let n = ((sweep.abs() / 0.005).ceil() as usize).clamp(8, 4000);
    let mut run: Vec<(f64, f64)> = Vec::new();
    for i in 0..=n {
        let a = a0 + sweep * i as f64 / n as f64;
        let p = center + Vec2::new(a.cos(), a.sin()) * r;
        if inside(b, p) {
            run.push((p.x, p.y));
        } else if run.len() > 1 {
            c.polyline(&run, st);
            run.clear();
        } else {
            run.clear();
        }
    }
    if run.len() > 1 {
        c.polyline(&run, st);
    }
}

/// The positions the drawing shows: the two dead positions, or for a
/// function generator the given crank angles (solved by the linkage core).
fn drawn_positions(s: &Solved) -> Vec<Vec<(String, Vec2)>> {
    let y = &s.syn;
    if y.kind != Kind::FunctionGeneration {
        return y.check.dead_positions.clone();
    }
    let Ok(m) = Mechanism::new(&y.def) else {
        return y.check.dead_positions.clone();
    };
    let mut sol = m.solution();
    let phis: Vec<f64> = y.given.iter().filter(|(n, _)| n.starts_with("phi")).map(|(_, p)| *p).collect();
    // a crank of negative length a turns the crank by π (docs/synthesis.md § 8):
    // the offset that puts the driven point at the construction's first position
    let k = &y.construction;
    let miss = |off: f64, sol: &mut tmm_linkage::Solution| -> f64 {
        let (Some(&p0), Some(i)) = (phis.first(), m.point(&k.point)) else {
            return f64::INFINITY;
        };
        match m.solve(p0 + off, sol) {
            Ok(()) => (sol.points[i].p - k.extremes[0]).hypot(),
            Err(_) => f64::INFINITY,
        }
    };
    let off = if miss(0.0, &mut sol) <= miss(std::f64::consts::PI, &mut sol) {
        0.0
    } else {
        std::f64::consts::PI
    };
    phis.iter()
        .filter_map(|phi| {
            m.solve(*phi + off, &mut sol).ok()?;
            Some(
                m.points
                    .iter()
                    .enumerate()
                    .map(|(i, p)| (p.name.clone(), sol.points[i].p))
                    .collect(),
            )
        })
        .collect()
}

/// The construction drawing.
pub fn construction(s: &Solved) -> String {
    let y = &s.syn;
    let k = &y.construction;
    let xy = |v: Vec2| (v.x, v.y);
    // the mechanism's own box: frame, extremes, pivot, both dead positions
    let mut b: Box4 = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
    for p in y.frame.iter().map(|f| f.1).chain(k.extremes).chain([k.pivot]) {
        b = grow(b, p);
    }
    let shown = drawn_positions(s);
    for pos in &shown {
        for (_, p) in pos {
            b = grow(b, *p);
        }
    }
    let size = (b.1 - b.0).max(b.3 - b.2).max(1e-9);
    // the locus circle's centre and as much of the circle as stays within
    // 35 % of the size beyond the mechanism
    let margin = 0.35 * size;
    let view: Box4 = (b.0 - margin, b.1 + margin, b.2 - margin, b.3 + margin);
    let mut world = (b.0 - 0.08 * size, b.1 + 0.08 * size, b.2 - 0.08 * size, b.3 + 0.08 * size);
    if let Some(l) = &k.locus {
        for i in 0..720 {
            let a = i as f64 * std::f64::consts::TAU / 720.0;
            let p = l.center + Vec2::new(a.cos(), a.sin()) * l.radius;
            if inside(view, p) {
                world = grow(world, p);
            }
        }
        if inside(view, l.center) {
            world = grow(world, l.center);
        }
    }
    for (_, p, q) in &k.lines {
        for r in [p, q] {
            if inside(view, *r) {
                world = grow(world, *r);
            }
        }
    }
    let mut c = Canvas::new(297.0, 210.0);
    let scale = c.fit(world, (15.0, 22.0, 267.0, 160.0));
    let txt = 3.5;
    let function = y.kind == Kind::FunctionGeneration;
    c.text_paper(
        (148.5, 10.0),
        &if function {
            format!(
                "Synthesis of the function generator: the mechanism at the {} given positions (μl = {:.5} m/mm)",
                shown.len(),
                1.0 / scale
            )
        } else {
            format!(
                "Synthesis of the {}: construction (μl = {:.5} m/mm), K = {:.4}, θ = {:.3}°",
                s.spec.kind,
                1.0 / scale,
                y.k,
                y.theta.to_degrees()
            )
        },
        4.5,
        Anchor::Middle,
        "#000",
    );
    let clip = (world.0, world.1, world.2, world.3);
    // the circle seen at 2θ (thin dashed), its arc of pivots seen at θ (green)
    if let Some(l) = &k.locus {
        clipped_arc(
            &mut c,
            l.center,
            l.radius,
            0.0,
            std::f64::consts::TAU,
            clip,
            Style::DASHED.colored(GREY),
        );
        clipped_arc(
            &mut c,
            l.center,
            l.radius,
            l.arc_start,
            l.arc_sweep,
            clip,
            Style::THIN.colored(GREEN).widened(0.6),
        );
        if inside(clip, l.center) {
            c.line(xy(l.center), xy(k.extremes[0]), Style::THIN.colored(GREEN));
            c.line(xy(l.center), xy(k.extremes[1]), Style::THIN.colored(GREEN));
            c.dot(xy(l.center), 0.8, GREEN);
            let mid = (k.extremes[0] + k.extremes[1]) * 0.5;
            c.line(xy(l.center), xy(mid), Style::AXIS.colored(GREEN));
            // the label on the far side of the centre from the chord
            let off = l.center - mid;
            let off = if off.hypot() > 0.0 {
                off * (1.0 / off.hypot())
            } else {
                Vec2::new(0.0, 1.0)
            };
            c.text_colored(
                xy(l.center + off * (4.0 / scale) + Vec2::new(0.0, -1.2 / scale)),
                &format!("O* (2θ = {:.2}°)", 2.0 * y.theta.to_degrees()),
                txt,
                Anchor::Middle,
                GREEN,
            );
        }
        // label the locus at the middle of its arc
        let am = l.arc_start + 0.5 * l.arc_sweep;
        let pm = l.center + Vec2::new(am.cos(), am.sin()) * l.radius;
        if inside(clip, pm) {
            c.text_colored(
                xy(pm + Vec2::new(am.cos(), am.sin()) * (3.0 / scale)),
                "locus of crank pivots (chord seen at θ)",
                txt * 0.85,
                if am.cos() >= 0.0 { Anchor::Start } else { Anchor::End },
                GREEN,
            );
        }
    }
    // other construction lines
    for (name, p, q) in &k.lines {
        c.line(xy(*p), xy(*q), Style::AXIS.colored(GREY));
        let m = *p + (*q - *p) * 0.2;
        if inside(clip, m) {
            c.text_colored(xy(m + Vec2::new(0.0, 1.5 / scale)), name, txt * 0.8, Anchor::Middle, GREY);
        }
    }
    // the mechanism at both dead positions
    let colors = [BLUE, RED];
    let last = shown.len().saturating_sub(1);
    for (i, pos) in shown.iter().enumerate() {
        let col = if i == 0 {
            BLUE
        } else if i == last {
            RED
        } else {
            GREY
        };
        let at = |n: &str| pos.iter().find(|(m, _)| m == n).map(|(_, p)| *p);
        for l in &y.def.links {
            let pts: Vec<Vec2> = l.points.iter().filter_map(|(n, _)| at(n)).collect();
            for w in 1..pts.len() {
                c.line(xy(pts[0]), xy(pts[w]), Style::THICK.colored(col).widened(0.5));
            }
        }
        for l in &y.def.links {
            for (n, _) in &l.points {
                if let Some(p) = at(n) {
                    if !y.frame.iter().any(|f| &f.0 == n) {
                        c.joint(xy(p), 0.8);
                    }
                }
            }
        }
    }
    // chord between the extremes, rays from the pivot
    c.line(xy(k.extremes[0]), xy(k.extremes[1]), Style::THIN);
    if !function {
        c.line(xy(k.pivot), xy(k.extremes[0]), Style::DASHED);
        c.line(xy(k.pivot), xy(k.extremes[1]), Style::DASHED);
    }
    for (i, p) in k.extremes.iter().enumerate() {
        let other = k.extremes[1 - i];
        let away = (*p - other) * (1.0 / (*p - other).hypot().max(1e-12));
        c.text_colored(
            xy(*p + away * (3.0 / scale) + Vec2::new(0.0, -1.2 / scale)),
            &format!("{}{}", k.point, if i == 0 { "′" } else { "″" }),
            txt,
            if away.x >= 0.0 { Anchor::Start } else { Anchor::End },
            colors[i],
        );
    }
    // θ between the rays at the pivot
    let r0 = k.extremes[0] - k.pivot;
    let r1 = k.extremes[1] - k.pivot;
    let (n0, n1) = (r0.hypot(), r1.hypot());
    if n0 > 0.0 && n1 > 0.0 && y.theta > 0.0 && k.locus.is_some() {
        // the arc of θ at the pivot, the label beyond it on the bisector
        let rr = 0.3 * n0.min(n1);
        let (a0, a1) = (r0.atan2(), r1.atan2());
        let d = tmm_geom::angle::diff(a0, a1);
        c.arc(xy(k.pivot), rr, a0, a0 + d, Style::THIN);
        let am = a0 + 0.5 * d;
        let at = k.pivot + Vec2::new(am.cos(), am.sin()) * (rr + 2.0 / scale);
        c.text(
            xy(at),
            &format!("θ = {:.2}°", y.theta.to_degrees()),
            txt * 0.85,
            if am.cos() >= 0.0 { Anchor::Start } else { Anchor::End },
        );
    }
    for (n, p) in &y.frame {
        c.fixed_pivot(xy(*p), 1.2);
        let chosen = !function && (*p - k.pivot).hypot() <= 1e-9 * size;
        let label = if chosen { format!("{n} (chosen crank pivot)") } else { n.clone() };
        c.text_colored(
            xy(*p + Vec2::new(2.2 / scale, 1.6 / scale)),
            &label,
            txt,
            Anchor::Start,
            if chosen { RED } else { "#000000" },
        );
    }
    c.dot(xy(k.pivot), 1.0, RED);
    // legend
    let leg = [
        (
            BLUE,
            if function {
                "the first given position"
            } else {
                "extreme position ′ (start of the working stroke)"
            },
        ),
        (
            RED,
            if function {
                "the last given position"
            } else {
                "extreme position ″"
            },
        ),
        (GREEN, "circle seen at 2θ from O*, arc of pivots"),
    ];
    let shown = if k.locus.is_some() { 3 } else { 2 };
    for (i, (col, t)) in leg.iter().take(shown).enumerate() {
        let yy = 192.0 + 5.0 * i as f64;
        c.line_paper((15.0, yy - 1.0), (25.0, yy - 1.0), Style::THICK.colored(col).widened(0.5));
        c.text_paper((27.0, yy), t, 3.2, Anchor::Start, "#000");
    }
    c.finish()
}

/// The pressure angle at each dyad's inner joint over the cycle, from the
/// start of the working stroke, by the linkage core.
pub fn pressure(s: &Solved) -> Result<String, Error> {
    let m = Mechanism::new(&s.syn.def).map_err(|e| Error::input("synthesis", e))?;
    let cy = Cycle::new(&m, Working::Slower).map_err(|e| Error::input("synthesis", e))?;
    let mut sol = m.solution();
    let mut out = Vec::new();
    let mut curves: Vec<(usize, Vec<(f64, f64)>)> = Vec::new();
    for p in cy.positions(&m, 360) {
        if m.solve(p.phi, &mut sol).is_err() {
            continue;
        }
        pressure_angles(&m, &sol, &mut out);
        for &(pt, v) in &out {
            match curves.iter_mut().find(|c| c.0 == pt) {
                Some(c) => c.1.push((p.psi.to_degrees(), v.to_degrees())),
                None => curves.push((pt, vec![(p.psi.to_degrees(), v.to_degrees())])),
            }
        }
    }
    let top = curves.iter().flat_map(|c| c.1.iter().map(|p| p.1)).fold(0.0_f64, f64::max);
    let w = cy.working_angle.to_degrees();
    let marker = [(w, 0.0), (w, top)];
    let names: Vec<String> = curves.iter().map(|c| format!("ϑ at {}", m.points[c.0].name)).collect();
    let cols = [BLUE, RED, GREEN, "#8e44ad", "#d35400"];
    let mut series: Vec<Series<'_>> = curves
        .iter()
        .enumerate()
        .map(|(i, c)| Series {
            name: &names[i],
            points: &c.1,
            color: cols[i % cols.len()],
        })
        .collect();
    series.push(Series {
        name: "end of the working stroke",
        points: &marker,
        color: GREY,
    });
    Ok(plot(
        &format!(
            "Pressure angles over the cycle (working stroke 0…{:.1}°)",
            cy.working_angle.to_degrees()
        ),
        "crank rotation from the start of the working stroke, °",
        "ϑ, °",
        &series,
        297.0,
        180.0,
    ))
}
