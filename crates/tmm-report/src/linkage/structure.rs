//! The structural scheme (структурная схема) of a linkage and its Assur
//! groups drawn apart: the mechanism at the plans' position with its links
//! numbered (the frame 0) and its pairs lettered by their points, beside it
//! the input mechanism I(0, 1) and every Assur group on its own, a group's
//! outer pairs left as open joints, each titled with its formula, kind,
//! class and order (Артоболевский И. И. Теория механизмов и машин, 1988,
//! §§ 5–6: a group is separated from the mechanism at its outer pairs).
//!
//! Every panel is drawn at one scale so the groups keep the mechanism's
//! shape; the panels are arranged in the rows (one row, or the mechanism
//! above the groups, or the mechanism with the input mechanism above the
//! groups) that give the largest scale within the drawing's slot on the
//! sheet ([`Slot::Diagram`]), and the paper is cropped to what is drawn.
//! The labels are placed by the canvas' label avoidance, after every line.

use tmm_geom::Vec2;
use tmm_linkage::Solution;
use tmm_linkage::mechanism::{Mechanism, Pair};

use super::{Analysis, Loaded};
use crate::TaskSource;
use crate::paper::{Slot, slot_mm};
use crate::picture::Picture;
use crate::project::SheetFormat;
use crate::svg::{Anchor, Canvas, Style, text_width};
use crate::words::word;

/// The radius of a joint's circle, mm.
const JOINT: f64 = 1.2;
/// The free margin around a panel's links (labels, ground symbols), mm.
const PAD: f64 = 9.0;
/// The gap between two panels, mm.
const GAP: f64 = 4.0;

/// One panel: the links it draws, whether its pairs with the frame are
/// fixed (the mechanism, the input mechanism) and its title lines.
struct Panel {
    links: Vec<usize>,
    frame: bool,
    title: Vec<String>,
    /// The world box of its pairs' points: (xmin, ymin, xmax, ymax), m.
    bb: (f64, f64, f64, f64),
}

impl Panel {
    fn world_w(&self) -> f64 {
        self.bb.2 - self.bb.0
    }
    fn world_h(&self) -> f64 {
        self.bb.3 - self.bb.1
    }
}

/// A panel placed: its index, its origin on the paper (y up) and its
/// titles' top centre (y down).
type Placed = (usize, (f64, f64), (f64, f64));

/// The lettering heights on a sheet: labels and titles, mm (GOST 2.304).
fn heights(sheet: SheetFormat) -> (f64, f64) {
    match sheet {
        SheetFormat::A1 => (3.5, 3.5),
        SheetFormat::A2 | SheetFormat::A4 => (2.5, 2.5),
    }
}

/// The height of the drawing's name on a sheet, mm (GOST 2.304): 5 on A1,
/// 3.5 on the smaller sheets and the note's page.
fn name_height(sheet: SheetFormat) -> f64 {
    match sheet {
        SheetFormat::A1 => 5.0,
        SheetFormat::A2 | SheetFormat::A4 => 3.5,
    }
}

/// The structural scheme and the Assur groups apart, at the plans' position
/// of `a`, sized for the task's sheet.
///
/// ```
/// use tmm_report::{TaskSource, run::DEFAULT_TASK, linkage};
/// let task = TaskSource::new("t.toml", DEFAULT_TASK);
/// let l = linkage::load(&task).unwrap().unwrap();
/// let a = linkage::analyse(&l, &task, None, l.task.positions).unwrap();
/// let p = linkage::structure_drawing(&l, &a, &task);
/// assert!(p.width <= 260.0 && p.height <= 120.0);
/// assert!(p.svg().contains("I(0, 1)") && p.svg().contains("II(2, 3)"));
/// ```
pub fn structure_scheme(l: &Loaded, a: &Analysis, task: &TaskSource) -> Picture {
    let lang = task.lang;
    let m = &l.mech;
    let sol = &a.plan_row.sol;
    let (h_label, h_title) = heights(task.sheet);
    let (slot_w, slot_h) = slot_mm(Slot::Diagram, task.sheet);
    // the drawing's name (наименование изображения) in a band of its own
    // over the panels: on the sheets it names the drawing, the note leaves
    // it to the figure's caption
    let name = crate::sheets::caption("linkage/structure.svg", lang);
    let h_name = name_height(task.sheet);
    let band = 2.0 * crate::picture::em(h_name);
    let name_w = text_width(h_name, name.chars().count()) + 2.0;
    let crank = m.crank.link;
    let class_w = word(lang, "linkage.group_class");
    let order_w = word(lang, "linkage.group_order");
    let mut panels = vec![
        Panel {
            links: (1..m.link_names.len()).collect(),
            frame: true,
            title: vec![m.structure.formula.replace(',', ", ").replace("→", " → ").replace("  ", " ")],
            bb: (0.0, 0.0, 0.0, 0.0),
        },
        Panel {
            links: vec![crank],
            frame: true,
            title: vec![format!("I(0, {})", m.link_names[crank]), format!("{class_w} I")],
            bb: (0.0, 0.0, 0.0, 0.0),
        },
    ];
    for g in &m.structure.groups {
        let names: Vec<&str> = g.link_ids.iter().map(|&i| m.link_names[i].as_str()).collect();
        let roman = tmm_linkage::structure::roman(g.class);
        panels.push(Panel {
            links: g.link_ids.clone(),
            frame: false,
            title: vec![
                format!("{roman}({}), {}", names.join(", "), g.kind),
                format!("{class_w} {roman}, {order_w} {}", g.order),
            ],
            bb: (0.0, 0.0, 0.0, 0.0),
        });
    }
    // the world box of each panel: its pairs' points
    let mut span: f64 = 0.0;
    for p in &mut panels {
        let pts: Vec<Vec2> = m
            .pairs
            .iter()
            .filter(|pr| {
                let (x, y) = pr.links();
                p.links.contains(&x) || p.links.contains(&y)
            })
            .map(|pr| sol.points[pr.point()].p)
            .collect();
        p.bb = bounds(&pts);
        span = span.max(p.world_w()).max(p.world_h());
    }
    // a panel of collinear points keeps a little height (and width)
    let least = 0.02 * span.max(1e-9);
    for p in &mut panels {
        for (lo, hi) in [(0usize, 2usize), (1, 3)] {
            let (a0, a1) = (get(p.bb, lo), get(p.bb, hi));
            if a1 - a0 < least {
                let mid = 0.5 * (a0 + a1);
                set(&mut p.bb, lo, mid - 0.5 * least);
                set(&mut p.bb, hi, mid + 0.5 * least);
            }
        }
    }
    let title_h = |p: &Panel| p.title.len() as f64 * 1.5 * crate::picture::em(h_title);
    let title_w = |p: &Panel| {
        p.title
            .iter()
            .map(|t| text_width(h_title, t.chars().count()) + 1.0)
            .fold(0.0, f64::max)
    };
    // the arrangements tried: one row; the mechanism above the rest; the
    // mechanism and the input mechanism above the groups
    let n = panels.len();
    let mut layouts: Vec<Vec<Vec<usize>>> = vec![(0..n).collect::<Vec<_>>()].into_iter().map(|r| vec![r]).collect();
    layouts.push(vec![vec![0], (1..n).collect()]);
    if n > 2 {
        layouts.push(vec![vec![0, 1], (2..n).collect()]);
    }
    let size = |rows: &[Vec<usize>], s: f64| -> (f64, f64) {
        let mut w: f64 = 0.0;
        let mut h = 0.0;
        for r in rows {
            let rw: f64 = r
                .iter()
                .map(|&i| (panels[i].world_w() * s + 2.0 * PAD).max(title_w(&panels[i])))
                .sum::<f64>()
                + GAP * r.len().saturating_sub(1) as f64;
            let rh = r
                .iter()
                .map(|&i| panels[i].world_h() * s + 2.0 * PAD + title_h(&panels[i]))
                .fold(0.0, f64::max);
            w = w.max(rw);
            h += rh;
        }
        (w, h)
    };
    let fits = |rows: &[Vec<usize>], s: f64, lim_h: f64| {
        let (w, h) = size(rows, s);
        w <= slot_w && h <= lim_h
    };
    // the largest scale of each arrangement whose panels stay within
    // `lim_h` high, by bisection (paper mm per metre); the best of them
    let choose = |lim_h: f64| {
        let mut best: Option<(f64, usize)> = None;
        for (k, rows) in layouts.iter().enumerate() {
            let (mut lo, mut hi) = (0.0, 1e5);
            if !fits(rows, lo, lim_h) {
                continue;
            }
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if fits(rows, mid, lim_h) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            if best.is_none_or(|b: (f64, usize)| lo > b.0 * 1.0001) {
                best = Some((lo, k));
            }
        }
        best
    };
    // the name's band comes out of the height the panels alone take: the
    // drawing keeps its size on the sheet, its panels a little smaller
    let best = match choose(slot_h) {
        Some((s0, k0)) => {
            let h0 = size(&layouts[k0], s0).1;
            choose(h0.min(slot_h) - band).or(Some((s0, k0)))
        }
        None => None,
    };
    let (s, rows) = match best {
        Some((s, k)) => (s, layouts.swap_remove(k)),
        // nothing fits (more groups than the slot holds): one row, small
        None => (0.0, layouts.swap_remove(0)),
    };
    let (w, h) = size(&rows, s);
    // whole millimetres, as the sheets place a drawing at its own size
    let (w, h) = ((w.max(name_w) - 1e-6).ceil().min(slot_w), (h - 1e-6).ceil().min(slot_h - band));
    // the panels below the name's band: their y-up coordinates 0 … h
    let hh = h + band;
    let mut c = Canvas::new(w, hh);
    c.title((0.5 * w, 1.4 * crate::picture::em(h_name)), &name, h_name, Anchor::Middle);
    // metres per paper mm, as the other drawings write μ_l
    c.root_attr("data-mu-l", &format!("{}", 1.0 / s.max(1e-9)));
    // each panel's origin on the paper (y up) and its title's top centre (y down)
    let mut placed: Vec<Placed> = Vec::new();
    let mut top = h;
    for r in &rows {
        let widths: Vec<f64> = r
            .iter()
            .map(|&i| (panels[i].world_w() * s + 2.0 * PAD).max(title_w(&panels[i])))
            .collect();
        let rh = r
            .iter()
            .map(|&i| panels[i].world_h() * s + 2.0 * PAD + title_h(&panels[i]))
            .fold(0.0, f64::max);
        let total = widths.iter().sum::<f64>() + GAP * r.len().saturating_sub(1) as f64;
        let mut x = 0.5 * (w - total);
        let bottom = top - rh;
        for (k, &i) in r.iter().enumerate() {
            let p = &panels[i];
            let dw = p.world_w() * s;
            let dh = p.world_h() * s;
            let ox = x + 0.5 * (widths[k] - dw) - p.bb.0 * s;
            // the links in the middle of what the titles leave
            let th = title_h(p);
            let oy = bottom + th + 0.5 * (rh - th - dh) - p.bb.1 * s;
            placed.push((i, (ox, oy), (x + 0.5 * widths[k], hh - bottom - th)));
            x += widths[k] + GAP;
        }
        top = bottom;
    }
    let to = |o: (f64, f64), v: Vec2| (o.0 + s * v.x, o.1 + s * v.y);
    // the lines of every panel first, then the titles, then the labels
    c.begin_group("links");
    for &(i, o, _) in &placed {
        draw_links(&mut c, m, sol, &panels[i], &|v| to(o, v));
    }
    c.end_group();
    c.begin_group("titles");
    for &(i, _, t) in &placed {
        for (k, line) in panels[i].title.iter().enumerate() {
            let y = t.1 + crate::picture::em(h_title) * (1.1 + 1.5 * k as f64);
            c.rich_paper((t.0, y), line, h_title, Anchor::Middle, "#000");
        }
    }
    c.end_group();
    c.begin_group("labels");
    for &(i, o, _) in &placed {
        labels(&mut c, m, sol, &panels[i], &|v| to(o, v), h_label);
    }
    c.end_group();
    c.finish()
}

fn get(b: (f64, f64, f64, f64), k: usize) -> f64 {
    [b.0, b.1, b.2, b.3][k]
}

fn set(b: &mut (f64, f64, f64, f64), k: usize, v: f64) {
    match k {
        0 => b.0 = v,
        1 => b.1 = v,
        2 => b.2 = v,
        _ => b.3 = v,
    }
}

/// Whether the pair belongs to the panel (one of its links is drawn).
fn mine(p: &Panel, pr: &Pair) -> bool {
    let (a, b) = pr.links();
    p.links.contains(&a) || p.links.contains(&b)
}

/// The panel's links as thick lines through their joints, the pairs with
/// the frame as fixed pivots (or the guide hatched) where the panel keeps
/// the frame, a pair with a link not drawn as an open joint, sliders as
/// blocks on their guides.
fn draw_links(c: &mut Canvas, m: &Mechanism, sol: &Solution, p: &Panel, to: &dyn Fn(Vec2) -> (f64, f64)) {
    for &li in &p.links {
        let joints = joints_of(m, sol, li);
        for (i, a) in joints.iter().enumerate() {
            for b in &joints[i + 1..] {
                c.line(to(*a), to(*b), Style::THICK);
            }
        }
    }
    for pr in m.pairs.iter().filter(|pr| mine(p, pr)) {
        let (a, b) = pr.links();
        let at = to(sol.points[pr.point()].p);
        let with_frame = a == 0 || b == 0;
        match *pr {
            Pair::R { .. } => {
                if with_frame && p.frame {
                    c.fixed_pivot(at, JOINT);
                } else {
                    c.joint(at, JOINT);
                }
            }
            Pair::P { guide, .. } => {
                let (dir, normal) = slider_axes(m, sol, pr);
                slider(c, at, dir, normal, with_frame && p.frame, p.links.contains(&guide) || guide == 0);
            }
        }
        c.reserve_point(at, 1.8);
    }
}

/// A slider's block axes at its pair: the unit direction of its guide and
/// the unit normal towards the links jointed at its point (the guide lies
/// on the other side, `-normal`); ((1, 0), (0, 1)) for a turning pair.
fn slider_axes(m: &Mechanism, sol: &Solution, pr: &Pair) -> ((f64, f64), (f64, f64)) {
    let Pair::P { guide, d, point, .. } = *pr else {
        return ((1.0, 0.0), (0.0, 1.0));
    };
    let u = tmm_linkage::state::rot(sol.links[guide].u, d);
    // the guide on the side of the block away from the links jointed there
    let here = sol.points[point].p;
    let mut away = Vec2::new(0.0, 0.0);
    for q in m.pairs.iter().filter(|q| q.point() == point) {
        let (x, y) = q.links();
        for li in [x, y].into_iter().filter(|&li| li != 0 && li != guide) {
            for jt in joints_of(m, sol, li) {
                away += jt - here;
            }
        }
    }
    let n = Vec2::new(-u.y, u.x);
    let side = if away.dot(n) < 0.0 { -1.0 } else { 1.0 };
    ((u.x, u.y), (n.x * side, n.y * side))
}

/// The labels of a panel: each pair's point once, the frame's 0 by its
/// fixed pairs, each link's number by the middle of a side (a slider's by
/// its block).
fn labels(c: &mut Canvas, m: &Mechanism, sol: &Solution, p: &Panel, to: &dyn Fn(Vec2) -> (f64, f64), size: f64) {
    let mut lettered: Vec<usize> = Vec::new();
    for pr in m.pairs.iter().filter(|pr| mine(p, pr)) {
        let k = pr.point();
        // one letter for the pairs at one place (a slider's R and P at D)
        let here = sol.points[k].p;
        if lettered.iter().any(|&j| j == k || (sol.points[j].p - here).hypot() < 1e-9) {
            continue;
        }
        lettered.push(k);
        c.label(to(here), &typeset(&m.points[k].name), size, "#000");
    }
    if p.frame {
        // the frame is link 0: its number by each fixed pivot's ground and
        // each fixed guide
        let mut done: Vec<Vec2> = Vec::new();
        for pr in m.pairs.iter().filter(|pr| mine(p, pr)) {
            let (a, b) = pr.links();
            let here = sol.points[pr.point()].p;
            if (a == 0 || b == 0) && !done.iter().any(|q| (*q - here).hypot() < 1e-9) {
                done.push(here);
                let (x, y) = to(here);
                // below the ground symbol (a pivot) or beyond the guide's
                // hatching, off the block (not crowded beside the slider's
                // point and number as "3 B 0")
                let under = match pr {
                    Pair::R { .. } => (x, y - 3.0 * JOINT * 2.3),
                    Pair::P { .. } => {
                        let (_, (nx, ny)) = slider_axes(m, sol, pr);
                        (x - nx * 6.5, y - ny * 6.5)
                    }
                };
                c.label_led(under, "0", size, "#000");
            }
        }
    }
    for &li in &p.links {
        let joints = joints_of(m, sol, li);
        // a slider (one point) numbered beyond its block's end away from
        // the links jointed at it, apart from its point's letter and the
        // frame's 0 beyond the guide
        let block = m
            .pairs
            .iter()
            .find(|pr| matches!(pr, Pair::P { slider, .. } if *slider == li) && joints.len() == 1);
        let spot = match block {
            Some(pr) => {
                let here = sol.points[pr.point()].p;
                let (x, y) = to(here);
                let ((ux, uy), (nx, ny)) = slider_axes(m, sol, pr);
                let mut along = 0.0;
                for q in m.pairs.iter().filter(|q| q.point() == pr.point()) {
                    let (a, b) = q.links();
                    for l in [a, b].into_iter().filter(|&l| l != 0 && l != li) {
                        for jt in joints_of(m, sol, l) {
                            along += (jt.x - here.x) * ux + (jt.y - here.y) * uy;
                        }
                    }
                }
                let s = if along > 0.0 { -1.0 } else { 1.0 };
                (x + s * ux * 6.5 + nx * 1.5, y + s * uy * 6.5 + ny * 1.5)
            }
            None => to(number_spot(&joints).unwrap_or_else(|| joints.first().copied().unwrap_or_default())),
        };
        c.label(spot, &m.link_names[li], size, "#000");
    }
}

/// A point's name typeset: trailing digits lowered (`O1` → `O_1`).
fn typeset(name: &str) -> String {
    let cut = name.trim_end_matches(|c: char| c.is_ascii_digit()).len();
    if cut > 0 && cut < name.len() {
        format!("{}_{}", &name[..cut], &name[cut..])
    } else {
        name.to_string()
    }
}

/// A slider block (5 × 3 mm) at `at` along the unit direction `dir`; its
/// guide as a thin line along the block's side towards `-normal` when the
/// guide is drawn in the panel (hatched when it is the fixed frame).
fn slider(c: &mut Canvas, at: (f64, f64), dir: (f64, f64), normal: (f64, f64), hatched: bool, guide: bool) {
    let (ux, uy) = dir;
    // the guide's side is -normal
    let (nx, ny) = normal;
    let corner = |a: f64, b: f64| (at.0 + ux * a + nx * b, at.1 + uy * a + ny * b);
    if guide {
        c.line(corner(-8.0, -1.5), corner(8.0, -1.5), Style::THIN);
    }
    if hatched {
        for i in 0..6 {
            let a = -7.0 + 2.8 * i as f64;
            c.line(corner(a, -1.5), corner(a - 1.5, -3.5), Style::THIN);
        }
    }
    let block = [corner(-2.5, -1.5), corner(2.5, -1.5), corner(2.5, 1.5), corner(-2.5, 1.5)];
    c.polygon(&block, Style::THICK.filled("#ffffff"));
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

/// Where a link's number goes: the middle of the side between two of its
/// joints that lies farthest from every joint (on a link B–E–C the middle
/// of B–E, not of B–C, which is E).
fn number_spot(j: &[Vec2]) -> Option<Vec2> {
    let mut best: Option<(Vec2, f64)> = None;
    for (i, a) in j.iter().enumerate() {
        for b in &j[i + 1..] {
            let mid = (*a + *b) * 0.5;
            let clear = j.iter().map(|q| (*q - mid).hypot()).fold(f64::INFINITY, f64::min);
            if best.is_none_or(|x| clear > x.1) {
                best = Some((mid, clear));
            }
        }
    }
    best.map(|(m, _)| m)
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
