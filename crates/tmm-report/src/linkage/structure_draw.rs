//! The structural scheme (структурная схема) of a linkage and its Assur
//! groups drawn apart: the mechanism at the analysed position with its links
//! numbered (the frame 0) and its pairs lettered by their points, then the
//! input mechanism I(0, 1) and every Assur group on its own, with the
//! group's outer pairs as open joints and its class, order and kind under it
//! (Артоболевский И. И., 1988, §§ 5–6: the groups are separated at their
//! outer pairs).
//!
//! Drawn with the [`Canvas`] of `svg.rs` in paper millimetres: every panel
//! at one scale, the mechanism on top, the groups in a row beneath.

use tmm_geom::Vec2;
use tmm_linkage::Solution;
use tmm_linkage::mechanism::{Mechanism, Pair};

use super::{Analysis, Loaded};
use crate::project::Language;
use crate::svg::{Anchor, Canvas, Style};
use crate::words::word;

/// Lettering heights, mm (GOST 2.304).
const H_TITLE: f64 = 5.0;
const H_LABEL: f64 = 3.5;
/// The paper's width, mm (the text width of the note's page less a margin).
const WIDTH: f64 = 170.0;
/// The radius of a joint's circle, mm.
const JOINT: f64 = 1.2;

/// One panel: the links it draws (its pairs with links outside it are its
/// outer pairs, drawn as open joints) and its title.
struct Panel {
    links: Vec<usize>,
    title: String,
}

/// The structural scheme and the groups apart (SVG), at the analysed
/// position of `a`.
pub fn structure_scheme(l: &Loaded, a: &Analysis, lang: Language) -> String {
    let m = &l.mech;
    let sol = &a.plan_row.sol;
    let crank = m.crank.link;
    let mut panels = vec![Panel {
        links: vec![crank],
        title: format!("I(0, {})", m.link_names[crank]),
    }];
    for g in &m.structure.groups {
        let links: Vec<usize> = g.link_ids.clone();
        let names: Vec<&str> = links.iter().map(|&i| m.link_names[i].as_str()).collect();
        panels.push(Panel {
            links,
            title: format!(
                "{}({}), {} {}, {}",
                tmm_linkage::structure::roman(g.class),
                names.join(", "),
                word(lang, "linkage.group_order"),
                g.order,
                g.kind
            ),
        });
    }
    // the world box of the whole mechanism: every pair's point
    let pts: Vec<Vec2> = m.pairs.iter().map(|p| sol.points[p.point()].p).collect();
    let bb = bounds(&pts);
    let span = (bb.2 - bb.0).max(bb.3 - bb.1).max(1e-9);
    // one scale for every panel: the mechanism 150 mm wide at most, 70 mm high
    let s = (150.0 / (bb.2 - bb.0).max(1e-9)).min(70.0 / (bb.3 - bb.1).max(span * 0.05));
    let top_h = (bb.3 - bb.1) * s + 2.0 * 12.0;
    // the panels of the groups: each its own box, in rows that fit the width
    let mut boxes: Vec<(f64, f64, f64, f64)> = Vec::new();
    for p in &panels {
        let gp: Vec<Vec2> = m
            .pairs
            .iter()
            .filter(|pr| {
                let (x, y) = pr.links();
                p.links.contains(&x) || p.links.contains(&y)
            })
            .map(|pr| sol.points[pr.point()].p)
            .collect();
        boxes.push(bounds(&gp));
    }
    let gap = 14.0;
    let mut rows: Vec<Vec<usize>> = vec![Vec::new()];
    let mut x = 0.0;
    for (i, b) in boxes.iter().enumerate() {
        let w = ((b.2 - b.0) * s).max(text_w(&panels[i].title, H_LABEL)) + gap;
        if x + w > WIDTH && !rows.last().is_some_and(Vec::is_empty) {
            rows.push(Vec::new());
            x = 0.0;
        }
        if let Some(r) = rows.last_mut() {
            r.push(i);
        }
        x += w;
    }
    let row_h: Vec<f64> = rows
        .iter()
        .map(|r| r.iter().map(|&i| (boxes[i].3 - boxes[i].1) * s).fold(0.0, f64::max) + 24.0)
        .collect();
    let height = 10.0 + top_h + row_h.iter().sum::<f64>() + 4.0;
    let mut c = Canvas::new(WIDTH, height);
    // titles
    c.text(
        (WIDTH / 2.0, height - 6.0),
        word(lang, "linkage.structure_scheme"),
        H_TITLE,
        Anchor::Middle,
    );
    // the whole mechanism, centred on top
    let all: Vec<usize> = (1..m.link_names.len()).collect();
    let ox = (WIDTH - (bb.2 - bb.0) * s) / 2.0;
    let oy = height - 10.0 - 12.0 - (bb.3 - bb.1) * s;
    let to = |p: Vec2, ox: f64, oy: f64, b: (f64, f64, f64, f64)| (ox + (p.x - b.0) * s, oy + (p.y - b.1) * s);
    draw_links(&mut c, m, sol, &all, &|p| to(p, ox, oy, bb), true);
    // the groups apart
    let mut y_top = oy - 12.0;
    for (r, row) in rows.iter().enumerate() {
        let widths: Vec<f64> = row
            .iter()
            .map(|&i| ((boxes[i].2 - boxes[i].0) * s).max(text_w(&panels[i].title, H_LABEL)))
            .collect();
        let total: f64 = widths.iter().sum::<f64>() + gap * (row.len().saturating_sub(1)) as f64;
        let mut x = (WIDTH - total) / 2.0;
        for (k, &i) in row.iter().enumerate() {
            let b = boxes[i];
            let w = widths[k];
            let h = (b.3 - b.1) * s;
            let px = x + (w - (b.2 - b.0) * s) / 2.0;
            let py = y_top - 6.0 - h;
            // the input mechanism keeps its frame; a group's outer pairs are free joints
            draw_links(&mut c, m, sol, &panels[i].links, &|p| to(p, px, py, b), i == 0);
            c.text((x + w / 2.0, py - 9.0), &panels[i].title, H_LABEL, Anchor::Middle);
            x += w + gap;
        }
        y_top -= row_h[r];
    }
    c.finish()
}

/// Draws `links` of the mechanism: each link a thick line through its
/// joints, its number at the middle; the pairs lettered; a pair with the
/// frame as a fixed pivot when `frame` (the whole mechanism), a pair with a
/// link not drawn as an open joint (an outer pair of a group).
fn draw_links(c: &mut Canvas, m: &Mechanism, sol: &Solution, links: &[usize], to: &dyn Fn(Vec2) -> (f64, f64), frame: bool) {
    let mut lettered: Vec<usize> = Vec::new();
    for &li in links {
        let joints: Vec<Vec2> = joints_of(m, sol, li);
        for (i, a) in joints.iter().enumerate() {
            for b in &joints[i + 1..] {
                c.line(to(*a), to(*b), Style::THICK);
            }
        }
        // the link's number beside the middle of its longest side
        if let Some((a, b)) = longest(&joints) {
            let (pa, pb) = (to(a), to(b));
            let (dx, dy) = (pb.0 - pa.0, pb.1 - pa.1);
            let len = dx.hypot(dy).max(1e-9);
            let at = ((pa.0 + pb.0) / 2.0 - dy / len * 3.5, (pa.1 + pb.1) / 2.0 + dx / len * 3.5 - 1.2);
            c.text(at, &m.link_names[li], H_LABEL, Anchor::Middle);
        }
    }
    for p in &m.pairs {
        let (a, b) = p.links();
        let mine = links.contains(&a) || links.contains(&b);
        if !mine {
            continue;
        }
        let k = p.point();
        let at = to(sol.points[k].p);
        let with_frame = a == 0 || b == 0;
        match p {
            Pair::R { .. } => {
                if with_frame && frame {
                    c.fixed_pivot(at, JOINT);
                } else {
                    c.joint(at, JOINT);
                }
            }
            Pair::P { guide, d, .. } => {
                // the slider block along its guide, the guide as a thin line
                let u = sol.links[*guide].u;
                let dir = (d.x * u.x - d.y * u.y, d.x * u.y + d.y * u.x);
                slider(c, at, dir, with_frame && frame);
            }
        }
        if !lettered.contains(&k) {
            lettered.push(k);
            c.text((at.0 + 2.2, at.1 + 2.2), &m.points[k].name, H_LABEL, Anchor::Start);
        }
    }
}

/// A slider block (5 × 3 mm) at `at` along the unit direction `dir`, with its
/// guide line; hatched beneath when the guide is the frame.
fn slider(c: &mut Canvas, at: (f64, f64), dir: (f64, f64), frame: bool) {
    let (ux, uy) = dir;
    let (nx, ny) = (-uy, ux);
    let corner = |a: f64, b: f64| (at.0 + ux * a + nx * b, at.1 + uy * a + ny * b);
    let block = [corner(-2.5, -1.5), corner(2.5, -1.5), corner(2.5, 1.5), corner(-2.5, 1.5)];
    c.polygon(&block, Style::THICK.filled("#ffffff"));
    c.line(corner(-9.0, -1.5), corner(9.0, -1.5), Style::THIN);
    if frame {
        for i in 0..6 {
            let a = -8.0 + 3.0 * i as f64;
            c.line(corner(a, -1.5), corner(a - 1.5, -3.5), Style::THIN);
        }
    }
    c.joint(at, JOINT * 0.8);
}

/// The joints of a link at the solution: the points of its pairs.
fn joints_of(m: &Mechanism, sol: &Solution, li: usize) -> Vec<Vec2> {
    let mut out: Vec<Vec2> = Vec::new();
    for p in &m.pairs {
        let (a, b) = p.links();
        if a == li || b == li {
            let q = sol.points[p.point()].p;
            if !out.iter().any(|j| (*j - q).hypot() < 1e-12) {
                out.push(q);
            }
        }
    }
    out
}

fn longest(j: &[Vec2]) -> Option<(Vec2, Vec2)> {
    let mut best: Option<(Vec2, Vec2, f64)> = None;
    for (i, a) in j.iter().enumerate() {
        for b in &j[i + 1..] {
            let d = (*a - *b).hypot();
            if best.is_none_or(|x| d > x.2) {
                best = Some((*a, *b, d));
            }
        }
    }
    best.map(|(a, b, _)| (a, b))
}

/// (xmin, ymin, xmax, ymax) of points.
fn bounds(p: &[Vec2]) -> (f64, f64, f64, f64) {
    let mut b = (f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY);
    for q in p {
        b = (b.0.min(q.x), b.1.min(q.y), b.2.max(q.x), b.3.max(q.y));
    }
    if !b.0.is_finite() {
        return (0.0, 0.0, 1.0, 1.0);
    }
    b
}

/// The width of a text of `size` mm, for the panels' spacing.
fn text_w(t: &str, size: f64) -> f64 {
    crate::svg::text_width(size, t.chars().count())
}
