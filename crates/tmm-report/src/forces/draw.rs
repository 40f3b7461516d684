//! The drawings of the `[forces]` section: each Assur group's free-body
//! diagram to scale with its force polygon (план сил), the input link's,
//! Zhukovsky's lever (the velocity plan turned by 90° with the forces at the
//! images of their points), the balancing torque over the cycle, and the
//! N, Q, M diagrams of the link sized for strength.

use tmm_geom::Vec2;

use super::task::ForcesTask;
use super::{Analysis, Row, json::pair_name};
use crate::linkage::Loaded;
use crate::output::Documents;
use crate::paper::{Slot, round_mu, slot_mm};
use crate::picture::Picture;
use crate::project::{Language, SheetFormat};
use crate::svg::{Anchor, Canvas, Series, Style, mu_text, num, plot_in};
use crate::words::word;
use crate::{Error, TaskSource};

/// Lettering heights, mm (GOST 2.304).
const H_TITLE: f64 = 5.0;
const H_LABEL: f64 = 3.5;

/// A force's label in the course's notation: `R12` → `R_{12}`, the frame
/// as link 0 (`Rframe1` → `R_{01}`), `Pb` → `P_{ур}` (ru), the inertia force `Fu2`
/// → `F_{и2}` (ru), `M2'` → `M_{2'}`; sums of forces part by part.
///
/// ```ignore
/// assert_eq!(force_label("Rframe1", Language::Ru), "R_{01}");
/// ```
fn force_label(label: &str, lang: Language) -> String {
    let l = label.replace("frame", "0");
    l.split('+')
        .map(|part| {
            let mut ch = part.chars();
            let Some(head) = ch.next() else { return String::new() };
            let rest: String = ch.collect();
            let (low, tail) = rest.split_at(rest.find(|c: char| !c.is_ascii_lowercase()).unwrap_or(rest.len()));
            let low = match low {
                "u" => word(lang, "forces.inertia"),
                // the balancing force: P_ур, P_зр, P_b (the note's notation)
                "b" => word(lang, "forces.balancing_sub"),
                _ => low,
            };
            let sub = format!("{low}{tail}");
            if sub.is_empty() {
                head.to_string()
            } else {
                format!("{head}_{{{sub}}}")
            }
        })
        .collect::<Vec<_>>()
        .join("+")
}

const COLORS: [&str; 6] = ["#c00000", "#0050c0", "#008000", "#a05000", "#7000a0", "#007070"];

fn t(v: Vec2) -> (f64, f64) {
    (v.x, v.y)
}

/// One force of a free body: label, point, vector.
struct Arrow {
    label: String,
    at: Vec2,
    f: Vec2,
}

/// A free-body diagram with its force polygon, for the links `links`; the
/// forces are the core's polygon number `which` (the groups in order, then
/// the input link with the balancing force), so the drawn polygon is the one
/// whose closure the core guarantees.
///
/// `title` is the drawing's name; `value` (the input link's balancing
/// force) opens the line of the angle and the scales under it.
fn free_body(l: &Loaded, r: &Row, links: &[usize], which: usize, title: &str, value: Option<&str>, task: &TaskSource) -> Picture {
    let lang = task.lang;
    let m = &l.mech;
    let f = &r.fs;
    let sol = &r.sol;
    let mut couples: Vec<(Vec2, f64, String, f64)> = Vec::new();
    // Two couples per link, each labelled as what it is, so that the figure
    // shows the inertia torque of the table (M_и3 = −J_S·ε) and not the sum
    // of all the couples on the link: the inertia torque, and the rest of the
    // link's moment about S (its external couples, the useful resistance
    // among them, and the moments about S of the external forces, which the
    // polygon's load F_i carries to S).
    let unit = word(lang, "forces.unit_nm");
    for &li in links {
        let lf = &f.links[li];
        let name = &m.link_names[li];
        let rest = lf.moment - lf.inertia_moment;
        let scale = lf.moment.abs().max(lf.inertia_moment.abs());
        if lf.inertia_moment != 0.0 {
            couples.push((
                lf.s,
                lf.inertia_moment,
                format!(
                    "M_{{{}{name}}} = {} {unit}",
                    word(lang, "forces.inertia"),
                    num(lf.inertia_moment.abs(), 2, lang)
                ),
                6.0,
            ));
        }
        if rest.abs() > 1e-12 * scale {
            // on a larger arc than the inertia torque's, its label below it
            let ring = if lf.inertia_moment != 0.0 { 10.0 } else { 6.0 };
            couples.push((lf.s, rest, format!("M_{{{name}}} = {} {unit}", num(rest.abs(), 2, lang)), ring));
        }
    }
    let polygons = f.polygons(m);
    let arrows: Vec<Arrow> = polygons
        .get(which)
        .map(|p| {
            p.forces
                .iter()
                .map(|x| Arrow {
                    label: x.label.clone(),
                    at: x.at,
                    f: x.force,
                })
                .collect()
        })
        .unwrap_or_default();
    // the links: segments between every pair of their joints
    let mut segs: Vec<(Vec2, Vec2)> = Vec::new();
    let mut pts: Vec<Vec2> = Vec::new();
    for &li in links {
        let mut jp: Vec<Vec2> = m
            .pairs
            .iter()
            .filter(|p| p.links().0 == li || p.links().1 == li)
            .map(|p| sol.points[p.point()].p)
            .collect();
        jp.push(f.links[li].s);
        for i in 0..jp.len() {
            for j in i + 1..jp.len() {
                segs.push((jp[i], jp[j]));
            }
        }
        pts.extend(jp);
    }
    let (mut xmin, mut xmax, mut ymin, mut ymax) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
    for p in &pts {
        xmin = xmin.min(p.x);
        xmax = xmax.max(p.x);
        ymin = ymin.min(p.y);
        ymax = ymax.max(p.y);
    }
    let size = (xmax - xmin).max(ymax - ymin).max(1e-6);
    let fmax = arrows.iter().map(|a| a.f.hypot()).fold(0.0, f64::max).max(1e-12);
    let mu = 0.35 * size / fmax; // m per N on the free body
    for a in &arrows {
        let e = a.at + a.f * mu;
        xmin = xmin.min(e.x);
        xmax = xmax.max(e.x);
        ymin = ymin.min(e.y);
        ymax = ymax.max(e.y);
    }
    // the force polygon to the right, its own scale: total height ≈ size
    let sum: f64 = arrows.iter().map(|a| a.f.hypot()).sum::<f64>().max(1e-12);
    let mup = 1.2 * size / sum.max(fmax) * (arrows.len() as f64).sqrt().max(1.0);
    let origin = Vec2::new(xmax + 0.3 * size, 0.5 * (ymin + ymax));
    let mut poly = vec![origin];
    for a in &arrows {
        let last = *poly.last().unwrap_or(&origin);
        poly.push(last + a.f * mup);
    }
    let (mut pxmin, mut pxmax, mut pymin, mut pymax) = (xmin, xmax, ymin, ymax);
    for p in &poly {
        pxmin = pxmin.min(p.x);
        pxmax = pxmax.max(p.x);
        pymin = pymin.min(p.y);
        pymax = pymax.max(p.y);
    }
    // the body at a length scale and the polygon at a round μ_F, side by side
    let (w, h) = slot_mm(Slot::Plan, task.sheet);
    let mut c = Canvas::new(w, h);
    let pad = 0.08 * (pxmax - pxmin).max(pymax - pymin);
    let k = c.fit((pxmin - pad, pxmax + pad, pymin - pad, pymax + pad), (6.0, 6.0, w - 12.0, h - 30.0));
    // round the scale factors: the world scale is kept, the forces' factors rounded
    let mu_body = round_mu(1.0 / (mu * k));
    let mu_poly = round_mu(1.0 / (mup * k));
    let mu = 1.0 / (mu_body * k);
    let mup = 1.0 / (mu_poly * k);
    let mut poly = vec![origin];
    for a in &arrows {
        let last = *poly.last().unwrap_or(&origin);
        poly.push(last + a.f * mup);
    }
    c.root_attr("data-mu-f", &format!("{mu_poly}"));
    c.title((w / 2.0, 8.0), title, H_TITLE, Anchor::Middle);
    // the angle and both scale factors in two lines under the name
    c.rich_paper(
        (w / 2.0, 14.0),
        &format!(
            "{}φ = {}°;  μ_F = {} {u} ({}),",
            value.map(|v| format!("{v};  ")).unwrap_or_default(),
            num(r.phi.to_degrees(), 1, lang),
            mu_text(mu_body, lang),
            word(lang, "forces.on_body"),
            u = word(lang, "forces.unit_n_per_mm"),
        ),
        H_LABEL - 0.5,
        Anchor::Middle,
        "#000",
    );
    c.rich_paper(
        (w / 2.0, 19.5),
        &format!(
            "μ_F = {} {u} ({})",
            mu_text(mu_poly, lang),
            word(lang, "forces.in_polygon"),
            u = word(lang, "forces.unit_n_per_mm"),
        ),
        H_LABEL - 0.5,
        Anchor::Middle,
        "#000",
    );
    c.begin_group("links");
    for (a, b) in &segs {
        c.line(t(*a), t(*b), Style::THICK);
    }
    for p in &pts {
        c.dot(t(*p), 0.8, "#000000");
        c.reserve_point(t(*p), 1.2);
    }
    c.end_group();
    c.begin_group("forces");
    for (i, a) in arrows.iter().enumerate() {
        let col = COLORS[i % COLORS.len()];
        c.arrow(t(a.at), t(a.at + a.f * mu), Style::THIN.colored(col).widened(0.5), 3.0);
    }
    let mut arcs = Vec::new();
    for (p, mo, label, ring) in &couples {
        let r0 = ring / k;
        let (a0, a1) = if *mo > 0.0 { (0.0, 4.5) } else { (4.5, 0.0) };
        c.arc(t(*p), r0, a0, a1, Style::THIN.colored("#606060"));
        let tip = *p + Vec2::new(a1.cos(), a1.sin()) * r0;
        let back = *p + Vec2::new((a1 - 0.3 * (a1 - a0).signum()).cos(), (a1 - 0.3 * (a1 - a0).signum()).sin()) * r0;
        c.arrow(t(back), t(tip), Style::THIN.colored("#606060"), 2.0);
        arcs.push((*p + Vec2::new(0.0, -r0), label.clone()));
    }
    c.end_group();
    c.begin_group("force-polygon");
    for (i, _) in arrows.iter().enumerate() {
        let col = COLORS[i % COLORS.len()];
        c.arrow(t(poly[i]), t(poly[i + 1]), Style::THIN.colored(col).widened(0.5), 3.0);
    }
    c.end_group();
    c.begin_group("labels");
    for (i, a) in arrows.iter().enumerate() {
        let col = COLORS[i % COLORS.len()];
        c.label(
            t(a.at + a.f * mu),
            &format!(
                "{} {} {}",
                force_label(&a.label, lang),
                num(a.f.hypot(), 1, lang),
                word(lang, "forces.unit_n")
            ),
            H_LABEL - 0.5,
            col,
        );
    }
    for (p, label) in &arcs {
        c.label(t(*p), label, H_LABEL - 0.5, "#404040");
    }
    for (i, a) in arrows.iter().enumerate() {
        let col = COLORS[i % COLORS.len()];
        c.label(t((poly[i] + poly[i + 1]) * 0.5), &force_label(&a.label, lang), H_LABEL - 0.5, col);
    }
    let gap = (*poly.last().unwrap_or(&origin) - origin).hypot();
    // the polygon's closure as a reader takes it: "≈ 0" where it is round-off
    // (under 1e-9 of the largest force), else the gap in newtons
    let largest = arrows.iter().map(|a| a.f.hypot()).fold(0.0, f64::max);
    let closure = gap / mup;
    let closure = if closure <= 1e-9 * largest {
        "≈ 0".to_string()
    } else {
        num(closure, 3, lang)
    };
    c.rich_paper(
        (w / 2.0, h - 4.0),
        &format!("{} {closure} {}", word(lang, "forces.closure"), word(lang, "forces.unit_n")),
        H_LABEL - 0.5,
        Anchor::Middle,
        "#404040",
    );
    c.end_group();
    c.finish()
}

/// Zhukovsky's lever: the velocity plan turned by 90° with the forces at
/// the images of their points, at a round μ_v; the labels placed clear of
/// the lines and of each other.
fn lever(l: &Loaded, a: &Analysis, task: &TaskSource) -> Picture {
    let lang = task.lang;
    // the note's symbols: M_ур, P_ур, M_Ж (ru)
    let (b, zh) = (word(lang, "forces.balancing_sub"), word(lang, "forces.lever_sub"));
    let m = &l.mech;
    let r = &a.detail;
    let imgs: Vec<Vec2> = r.sol.points.iter().map(|p| tmm_geom::perp(p.v)).collect();
    let vmax = imgs.iter().map(|v| v.hypot()).fold(0.0, f64::max).max(1e-12);
    let fmax = a.lever.iter().map(|x| x.force.hypot()).fold(0.0, f64::max).max(1e-12);
    let mu = 0.3 * vmax / fmax;
    let (mut xmin, mut xmax, mut ymin, mut ymax) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for p in imgs
        .iter()
        .copied()
        .chain(a.lever.iter().flat_map(|x| [x.image, x.image + x.force * mu]))
        // the feet of the arms drawn from the pole
        .chain(lever_arms(a, f64::INFINITY, mu).into_iter().map(|arm| arm.foot))
    {
        xmin = xmin.min(p.x);
        xmax = xmax.max(p.x);
        ymin = ymin.min(p.y);
        ymax = ymax.max(p.y);
    }
    // on the note's page as tall as a figure may be (the page's figure is
    // cut to its content, `crate::crop`), so a tall plan is drawn larger
    let (w, h) = match task.sheet {
        crate::project::SheetFormat::A4 => (crate::paper::NOTE_WIDTH_MM, crate::paper::NOTE_HEIGHT_MM),
        sheet => slot_mm(Slot::Plan, sheet),
    };
    let mut c = Canvas::new(w, h);
    // the arms' lengths listed under the μ lines, in columns (every arm
    // that may be drawn: those under 0.5 mm are left out once the scale
    // is known), the arms themselves marked h_k where they are drawn
    let n_arms = lever_arms(a, f64::INFINITY, mu).len();
    // a column as wide as the widest entry may be (three digits before
    // the comma) and a 5 mm gap
    let col_w = crate::svg::rich_ink(
        &format!("h_{{{}}} = 888,8 {}", n_arms.max(10), word(lang, "forces.unit_mm")),
        H_LABEL - 0.5,
    )
    .0 + 5.0;
    let cols = (((w - 8.0) / col_w).floor() as usize).max(1);
    let rows = n_arms.div_ceil(cols);
    let (margin, top) = (16.0, 29.0 + ARM_LIST_ROW_MM * rows as f64);
    // the scale the plan takes without the list; the list costs no scale
    // step when the plan, rounded up to that standard μ, still leaves
    // its rows free above it (seed 003's A1 lever stays at 0.05, not 0.1)
    let mu_for = |top: f64| {
        let raw = ((xmax - xmin) / (w - 2.0 * margin)).max((ymax - ymin) / (h - margin - top));
        round_mu(raw.max(1e-12))
    };
    let mu_bare = mu_for(29.0);
    let fits_above = (ymax - ymin) / mu_bare <= h - margin - top;
    // else, a tall narrow plan leaves its sides free: the list goes down
    // the left side in one column, the plan keeps its scale
    let aside = !fits_above && (xmax - xmin) / mu_bare <= w - 2.0 * (col_w + 8.0) && 30.5 + ARM_LIST_ROW_MM * n_arms as f64 <= h - margin;
    let mu_v = if fits_above || aside { mu_bare } else { mu_for(top) };
    let top = if aside { 29.0 } else { top };
    let s = 1.0 / mu_v;
    c.set_transform(
        s,
        (
            0.5 * w - s * 0.5 * (xmin + xmax),
            0.5 * (h - top + margin) - s * 0.5 * (ymin + ymax) - 0.5 * margin,
        ),
    );
    c.root_attr("data-mu", &format!("{mu_v}"));
    // the name; the angle opens the line of μ under it
    c.title((w / 2.0, 8.0), word(lang, "forces.lever"), H_TITLE, Anchor::Middle);
    c.rich_paper(
        (w / 2.0, 15.5),
        &format!(
            "φ = {}°;  μ_v = {} {};  M_{{{zh}}} = P_{{{b}}}·l_1 = {} {}",
            num(r.phi.to_degrees(), 1, lang),
            mu_text(mu_v, lang),
            word(lang, "forces.mu_v_unit"),
            num(r.fs.zhukovsky_moment, 3, lang),
            word(lang, "forces.unit_nm")
        ),
        H_LABEL - 0.5,
        Anchor::Middle,
        "#404040",
    );
    c.rich_paper(
        (w / 2.0, 22.5),
        &format!(
            "P_{{{b}}} = {} {};  {}: M_{{{b}}} = {} {}",
            num(r.fs.zhukovsky_moment / m.crank.radius, 3, lang),
            word(lang, "forces.unit_n"),
            word(lang, "forces.kinetostatics"),
            num(r.fs.balancing_moment, 3, lang),
            word(lang, "forces.unit_nm")
        ),
        H_LABEL - 0.5,
        Anchor::Middle,
        "#404040",
    );
    // the arms' lengths (плечи сил), in the arms' order and colours
    let arms = lever_arms(a, s, mu);
    let used = cols.min(arms.len()).max(1);
    for (j, arm) in arms.iter().enumerate() {
        let (row, k) = if aside { (j, 0) } else { (j / cols, j % cols) };
        let x = if aside {
            8.0 + 0.5 * col_w
        } else {
            0.5 * w + (k as f64 - 0.5 * (used - 1) as f64) * col_w
        };
        c.rich_paper(
            (x, 30.5 + ARM_LIST_ROW_MM * row as f64),
            &format!(
                "h_{{{}}} = {} {}",
                arm.force + 1,
                num(arm.mm, 1, lang),
                word(lang, "forces.unit_mm")
            ),
            H_LABEL - 0.5,
            Anchor::Middle,
            COLORS[arm.force % COLORS.len()],
        );
    }
    c.begin_group("plan");
    for p in &imgs {
        if p.hypot() * s > 0.05 {
            c.line((0.0, 0.0), t(*p), Style::THIN.colored("#a0a0a0"));
        }
    }
    // images of the same link joined
    for li in 1..m.link_names.len() {
        let js: Vec<usize> = m
            .pairs
            .iter()
            .filter(|p| p.links().0 == li || p.links().1 == li)
            .map(|p| p.point())
            .collect();
        for i in 0..js.len() {
            for j in i + 1..js.len() {
                c.line(t(imgs[js[i]]), t(imgs[js[j]]), Style::THICK);
            }
        }
    }
    c.fixed_pivot((0.0, 0.0), 1.5);
    c.end_group();
    c.begin_group("forces");
    for (i, x) in a.lever.iter().enumerate() {
        let col = COLORS[i % COLORS.len()];
        let end = x.image + x.force * mu;
        let (from, to) = (c.to_paper(x.image.x, x.image.y), c.to_paper(end.x, end.y));
        c.arrow_paper(from, to, Style::THIN.colored(col).widened(0.5), 3.0);
        reserve_head(&mut c, from, to, 3.0);
    }
    c.end_group();
    // the arms h of the forces about the pole p (плечи сил): the
    // perpendicular from p to each force's line of action, that line
    // carried on to its foot, the arm's length in paper mm (the lever's
    // equation Σ ±F_i·h_i = 0 is read in these)
    c.begin_group("arms");
    for arm in &arms {
        let col = COLORS[arm.force % COLORS.len()];
        c.line((0.0, 0.0), t(arm.foot), Style::THIN.colored(col));
        if let Some(from) = arm.carried_from {
            c.line(t(from), t(arm.foot), Style::DASHED.colored(col));
        }
    }
    c.end_group();
    for p in &imgs {
        c.dot(t(*p), 0.6, "#000000");
        c.reserve_point(t(*p), 1.0);
    }
    c.begin_group("labels");
    // every label 1 mm clear of the lines and of the other labels, its box
    // the ink of the drawing face
    c.label_clear((0.0, 0.0), "p", H_LABEL, "#000", LEVER_CLEAR_MM);
    let mut named: Vec<Vec2> = vec![Vec2::ZERO];
    for (i, p) in imgs.iter().enumerate() {
        if named.iter().any(|q| (*q - *p).hypot() * s < 0.5) {
            continue;
        }
        named.push(*p);
        let n = m.points[i].name.to_lowercase();
        let cut = n.trim_end_matches(|c: char| c.is_ascii_digit()).len();
        let n = if cut > 0 && cut < n.len() {
            format!("{}_{}", &n[..cut], &n[cut..])
        } else {
            n
        };
        c.label_clear(t(*p), &n, H_LABEL, "#000", LEVER_CLEAR_MM);
    }
    // each arm marked h_k beside it, placed before the forces' labels
    // (those may stand anywhere round their arrows' tips): square off the
    // arm at most ARM_LABEL_REACH_MM from it, else round the arm's foot,
    // else along the arm back towards the pole; its length in the list
    for arm in &arms {
        let col = COLORS[arm.force % COLORS.len()];
        let mark = format!("h_{{{}}}", arm.force + 1);
        let foot = t(arm.foot);
        if c.label_beside(((0.0, 0.0), foot), &mark, H_LABEL - 0.5, col, LEVER_CLEAR_MM, ARM_LABEL_REACH_MM)
            .is_some()
        {
            continue;
        }
        let along: Vec<(f64, f64)> = (0..=18)
            .map(|k| 1.0 - 0.05 * k as f64)
            .chain([1.08, 1.16])
            .map(|f| t(arm.foot * f))
            .collect();
        c.label_clear_near(&along, &mark, H_LABEL - 0.5, col, LEVER_CLEAR_MM);
    }
    // each force numbered as its arm is (h_k for the force (k)), so the
    // pairs read without the colours
    for (i, x) in a.lever.iter().enumerate() {
        let col = COLORS[i % COLORS.len()];
        // by the arrow's tip, else along the arrow back to its middle
        let along: Vec<(f64, f64)> = (0..=5).map(|k| t(x.image + x.force * (mu * (1.0 - 0.1 * k as f64)))).collect();
        c.label_clear_near(
            &along,
            &format!(
                "({}) {} {} {}",
                i + 1,
                force_label(&x.label, lang),
                num(x.force.hypot(), 1, lang),
                word(lang, "forces.unit_n")
            ),
            H_LABEL - 0.5,
            col,
            LEVER_CLEAR_MM,
        );
    }
    c.end_group();
    c.finish()
}

/// How far Zhukovsky's lever keeps its labels off its lines and off each
/// other, mm.
pub const LEVER_CLEAR_MM: f64 = 1.0;

/// How far an arm's mark h_k may stand off its arm on Zhukovsky's lever
/// (its ink's nearest edge), mm: beside it, the clearance and a step or
/// two.
pub const ARM_LABEL_REACH_MM: f64 = 5.5;

/// The height of a row of the list of the lever's arms (h_k = … mm) under
/// its μ lines, mm.
const ARM_LIST_ROW_MM: f64 = 7.5;

/// An arm drawn on Zhukovsky's lever.
struct Arm {
    /// The force's index in the lever's list.
    force: usize,
    /// The foot of the perpendicular from the pole on the line of action, m/s (the plan's units).
    foot: Vec2,
    /// Where the drawn force ends nearest the foot, when the foot lies beyond it.
    carried_from: Option<Vec2>,
    /// The arm's length on the paper, mm.
    mm: f64,
}

/// The arms of the lever's forces about the pole at the plan's scale `s`
/// (paper mm per m/s): h = |r × F| / |F| for the image r of the force's
/// point (derived here: the distance from the origin to the line through
/// r along F). Arms under 0.5 mm (a line of action through the pole) are
/// left out; the force drawn from r to r + F·μ at `mu`.
fn lever_arms(a: &Analysis, s: f64, mu: f64) -> Vec<Arm> {
    let fmax = a.lever.iter().map(|x| x.force.hypot()).fold(0.0, f64::max).max(1e-12);
    a.lever
        .iter()
        .enumerate()
        .filter_map(|(i, x)| {
            let f = x.force.hypot();
            if f <= 1e-9 * fmax {
                return None;
            }
            let u = x.force / f;
            let foot = x.image - u * x.image.dot(u);
            let mm = foot.hypot() * s;
            (mm >= 0.5).then(|| {
                // along the line: 0 at the image, the arrow from 0 to its length
                let (along, drawn) = ((foot - x.image).dot(u), f * mu);
                let carried_from = (along < 0.0 || along > drawn).then(|| if along < 0.0 { x.image } else { x.image + x.force * mu });
                Arm {
                    force: i,
                    foot,
                    carried_from,
                    mm,
                }
            })
        })
        .collect()
}

/// Keep labels off an arrow's head drawn from `from` to `to` (paper, mm):
/// its two sides, `head_mm` long and 0.3 of it wide each way.
fn reserve_head(c: &mut Canvas, from: (f64, f64), to: (f64, f64), head_mm: f64) {
    let (dx, dy) = (to.0 - from.0, to.1 - from.1);
    let len = dx.hypot(dy);
    if len < 1e-9 {
        return;
    }
    let h = head_mm.min(0.5 * len);
    let (ux, uy) = (dx / len, dy / len);
    let (bx, by) = (to.0 - h * ux, to.1 - h * uy);
    let w = 0.3 * h;
    let (l, r) = ((bx - w * uy, by + w * ux), (bx + w * uy, by - w * ux));
    c.reserve_segment(to, l);
    c.reserve_segment(to, r);
    c.reserve_segment(l, r);
}

/// Every drawing, as documents whose paths start with `dir` (`"forces/"`).
pub fn draw_all(l: &Loaded, _t: &ForcesTask, a: &Analysis, task: &TaskSource, dir: &str, docs: &mut Documents) -> Result<(), Error> {
    let lang = task.lang;
    let m = &l.mech;
    for (g, grp) in m.groups.iter().enumerate().rev() {
        let names: Vec<String> = grp.info.pair_ids.iter().map(|&p| pair_name(l, p)).collect();
        let title = format!(
            "{} {} ({}: {}), {}",
            word(lang, "forces.group"),
            g + 1,
            word(lang, "forces.pairs"),
            names.join(", ").replace("frame", "0"),
            word(lang, "forces.force_plan")
        );
        docs.add_text(
            format!("{dir}group-{}.svg", g + 1),
            free_body(l, &a.detail, &grp.info.link_ids, g, &title, None, task),
        )?;
    }
    let title = format!("{} {}", word(lang, "forces.input_link"), m.link_names[m.crank.link]);
    let value = format!(
        "P_{{{}}} = {} {}",
        word(lang, "forces.balancing_sub"),
        num(a.detail.fs.balancing_force, 1, lang),
        word(lang, "forces.unit_n")
    );
    docs.add_text(
        format!("{dir}input-link.svg"),
        free_body(l, &a.detail, &[m.crank.link], m.groups.len(), &title, Some(&value), task),
    )?;
    docs.add_text(format!("{dir}zhukovsky-lever.svg"), lever(l, a, task))?;
    // the balancing torque over the cycle: by kinetostatics as the curve, by
    // Zhukovsky's lever at the positions as circles (as the course builds
    // the lever at each of the 12 positions)
    let mb: Vec<(f64, f64)> = a.curve.iter().map(|c| (c[0].to_degrees(), c[2])).collect();
    let mz: Vec<(f64, f64)> = a
        .rows
        .iter()
        .map(|r| (r.psi.to_degrees(), r.fs.zhukovsky_moment))
        .chain(a.curve.last().map(|c| (c[0].to_degrees(), c[3])))
        .collect();
    let marks: Vec<(f64, String)> = a.rows.iter().map(|r| (r.psi.to_degrees(), r.label.clone())).collect();
    let svg = crate::linkage::draw::cycle_diagram(
        task,
        word(lang, "forces.torque_title"),
        word(lang, "forces.torque_sym"),
        word(lang, "forces.unit_nm"),
        &mb,
        &marks,
        l.mech.crank.omega.abs(),
        Some(crate::linkage::draw::CycleDots {
            points: &mz,
            curve_name: word(lang, "forces.kinetostatics"),
            dots_name: word(lang, "forces.lever"),
        }),
    );
    docs.add_text(format!("{dir}balancing-torque.svg"), svg)?;
    // the chosen reactions over the cycle and their hodographs
    if let Some(rc) = &a.reaction_cycle {
        // 200 × 110 mm on a sheet; on A4 (the note's width, 165 mm) lower,
        // so that three of them share a page with their captions
        let height = if task.sheet == SheetFormat::A4 { 85.0 } else { 110.0 };
        for name in &rc.diagrams {
            if let Some(svg) = rc.diagram(lang, name, height) {
                docs.add_text(format!("{dir}reaction-{name}.svg"), svg)?;
            }
        }
        for name in &rc.hodographs {
            for (polar, suffix) in [(false, ""), (true, "-polar")] {
                if let Some(svg) = rc.hodograph(lang, name, polar) {
                    docs.add_text(format!("{dir}hodograph-{name}{suffix}.svg"), svg)?;
                }
            }
        }
    }
    if let Some(b) = &a.beam {
        // 200 × 110 mm on a sheet, the note's width on its page
        let (w, h) = crate::paper::fit_page((200.0, 110.0), task.sheet);
        let link = &m.link_names[b.beam.link];
        for (key, name, unit, idx) in [
            ("N", "forces.strength_n", "forces.unit_n", 0),
            ("Q", "forces.strength_q", "forces.unit_n", 1),
            ("M", "forces.strength_m", "forces.unit_nm", 2),
        ] {
            let pts: Vec<(f64, f64)> = b.samples.iter().map(|s| (s.z * 1e3, [s.n, s.q, s.m][idx])).collect();
            let svg = plot_in(
                lang,
                &format!(
                    "{} {link} ({}–{}): {}",
                    word(lang, "forces.link"),
                    b.names.0,
                    b.names.1,
                    word(lang, name)
                ),
                &format!("z, {}", word(lang, "forces.unit_mm")),
                &format!("{key}, {}", word(lang, unit)),
                &[Series {
                    name: key,
                    points: &pts,
                    color: "#c00000",
                }],
                w,
                h,
            );
            docs.add_text(format!("{dir}strength-{key}.svg"), svg)?;
        }
    }
    Ok(())
}
