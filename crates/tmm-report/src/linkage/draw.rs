//! Drawings of the `[linkage]` section as the course draws them: the
//! kinematic scheme in its 12 positions at a GOST 2.302 standard scale
//! (joints lettered, links numbered, ω1 arrow, smooth paths of the points),
//! the kinematic diagrams over the crank's positions 0 … 12 with their scale
//! factors μ, and the velocity and acceleration plans (poles p and π, images
//! a, b, c, s2, points n1, n2 …) at round μ_v and μ_a — each made in paper
//! millimetres for its slot on the sheet ([`crate::paper::slot_mm`]).

use tmm_geom::Vec2;
use tmm_linkage::Solution;
use tmm_linkage::mechanism::Pair;
use tmm_linkage::plans::{PlanVector, VectorKind};

use super::{Analysis, Loaded};
use crate::output::Documents;
use crate::paper::{Slot, round_mu, slot_mm, standard_scale};
use crate::picture::Picture;
use crate::project::Language;
use crate::svg::{Anchor, Canvas, Style, mu_text, num};
use crate::words::word;
use crate::{Error, TaskSource};

/// Lettering heights, mm (GOST 2.304): titles, labels, small marks.
const H_TITLE: f64 = 5.0;
const H_LABEL: f64 = 3.5;
const H_SMALL: f64 = 2.5;

/// Which plans to draw for which positions.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlansAt {
    /// The plans of the analysed position only (`velocity-plan.svg`, `acceleration-plan.svg`).
    One,
    /// Also a plan of each position of the table (`plan-velocity-N.svg`, `plan-acceleration-N.svg`).
    All,
}

/// Every drawing, as documents whose paths start with `dir` (`"linkage/"` gives `linkage/positions.svg`).
pub fn draw_all(l: &Loaded, a: &Analysis, task: &TaskSource, dir: &str, docs: &mut Documents) -> Result<(), Error> {
    draw_with(l, a, task, dir, PlansAt::One, docs)
}

/// [`draw_all`] with the plans of every position when `plans` is [`PlansAt::All`].
pub fn draw_with(l: &Loaded, a: &Analysis, task: &TaskSource, dir: &str, plans: PlansAt, docs: &mut Documents) -> Result<(), Error> {
    let lang = task.lang;
    docs.add_text(format!("{dir}positions.svg"), scheme(l, a, task))?;
    docs.add_text(format!("{dir}structure.svg"), super::structure::structure_scheme(l, a, task))?;
    for d in diagrams(l, a, task) {
        docs.add_text(format!("{dir}{}", d.0), d.1)?;
    }
    let pos = bold_label(a, lang);
    docs.add_text(
        format!("{dir}velocity-plan.svg"),
        plan(task, Kind::Velocity, &a.plans.velocity, &pos),
    )?;
    docs.add_text(
        format!("{dir}acceleration-plan.svg"),
        plan(task, Kind::Acceleration, &a.plans.acceleration, &pos),
    )?;
    if plans == PlansAt::All {
        for r in &a.rows {
            let p = tmm_linkage::plans::plans(&l.mech, &r.sol);
            let name = r.pos.label.replace('\'', "p");
            let label = position_text(lang, &r.pos.label);
            docs.add_text(
                format!("{dir}plan-velocity-{name}.svg"),
                plan(task, Kind::Velocity, &p.velocity, &label),
            )?;
            docs.add_text(
                format!("{dir}plan-acceleration-{name}.svg"),
                plan(task, Kind::Acceleration, &p.acceleration, &label),
            )?;
        }
    }
    Ok(())
}

/// The velocity and acceleration plans (SVG) of one solved position at the
/// crank angle `phi`, titled with that angle: the plans a view that follows
/// the crank redraws, without the rest of the section.
pub fn plans_at(l: &Loaded, sol: &Solution, phi: f64, task: &TaskSource) -> (String, String) {
    let p = tmm_linkage::plans::plans(&l.mech, sol);
    let pos = input_text(l, phi, task.lang);
    (
        plan(task, Kind::Velocity, &p.velocity, &pos).into(),
        plan(task, Kind::Acceleration, &p.acceleration, &pos).into(),
    )
}

/// The input coordinate as drawn: `φ_1 = 30°` for a crank, `s = 40 mm`
/// for a slider.
fn input_text(l: &Loaded, q: f64, lang: Language) -> String {
    if l.mech.drive.is_some() {
        format!("s = {} {}", num(q * 1e3, 1, lang), word(lang, "linkage.unit_mm"))
    } else {
        format!("φ_1 = {}°", num(q.to_degrees(), 1, lang))
    }
}

/// "position 1" in the drawing's language.
fn position_text(lang: Language, label: &str) -> String {
    format!("{} {label}", word(lang, "linkage.position"))
}

/// The index in the table of the position drawn bold (the plans' one), if it is one of them.
fn bold_index(a: &Analysis) -> Option<usize> {
    a.rows.iter().position(|r| {
        let d = (r.pos.phi - a.plan_row.pos.phi).rem_euclid(std::f64::consts::TAU);
        d.min(std::f64::consts::TAU - d) < 1e-9
    })
}

fn bold_label(a: &Analysis, lang: Language) -> String {
    bold_index(a).map_or_else(
        || match a.travel {
            Some(_) => format!("s = {} {}", num(a.plan_row.pos.phi * 1e3, 1, lang), word(lang, "linkage.unit_mm")),
            None => format!("φ_1 = {}°", num(a.plan_row.pos.phi.to_degrees(), 1, lang)),
        },
        |i| a.rows[i].pos.label.clone(),
    )
}

/// A point's name typeset: trailing digits lowered (`S2` → `S_2`), in the
/// case asked.
fn typeset_name(name: &str, lower: bool) -> String {
    let n = if lower { name.to_lowercase() } else { name.to_string() };
    let cut = n.trim_end_matches(|c: char| c.is_ascii_digit()).len();
    if cut > 0 && cut < n.len() {
        format!("{}_{}", &n[..cut], &n[cut..])
    } else {
        n
    }
}

/// Segments of each link between its joints, at one solution, with the link's index.
fn link_segments(l: &Loaded, sol: &Solution) -> Vec<(usize, Vec2, Vec2)> {
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
                    segs.push((li, joints[i], joints[j]));
                }
            }
        }
    }
    segs
}

fn xy(v: Vec2) -> (f64, f64) {
    (v.x, v.y)
}

/// The scheme in its positions (схема механизма): a standard scale, the
/// paths of the joints sampled every degree, the positions numbered at the
/// crank pin, the analysed one bold with its joints lettered and its links
/// numbered, the ω1 arrow.
fn scheme(l: &Loaded, a: &Analysis, task: &TaskSource) -> Picture {
    let lang = task.lang;
    let m = &l.mech;
    let (w, h) = slot_mm(Slot::Scheme, task.sheet);
    // the paths, densely: every point of a moving link that is a joint
    let joints: Vec<usize> = (0..m.points.len())
        .filter(|&k| m.points[k].link != 0 && m.pairs.iter().any(|pr| pr.point() == k))
        .collect();
    let mut paths: Vec<Vec<(f64, f64)>> = vec![Vec::new(); joints.len()];
    let mut sol = m.solution();
    let sg = m.crank.omega.signum();
    for k in 0..=720 {
        let phi = match a.travel {
            // a slider input: over its travel
            Some(t) => t.from + (t.to - t.from) * k as f64 / 720.0,
            None => a.start + sg * std::f64::consts::TAU * k as f64 / 720.0,
        };
        let ok = m.solve(phi, &mut sol).is_ok();
        for (j, &p) in joints.iter().enumerate() {
            // a gap where the crank cannot turn stays a gap
            paths[j].push(if ok { xy(sol.points[p].p) } else { (f64::NAN, f64::NAN) });
        }
    }
    let mut pts: Vec<(f64, f64)> = paths.iter().flatten().copied().filter(|p| p.0.is_finite()).collect();
    for r in &a.rows {
        pts.extend(r.sol.points.iter().map(|p| xy(p.p)));
    }
    pts.extend(a.plan_row.sol.points.iter().map(|p| xy(p.p)));
    let (mut xmin, mut xmax, mut ymin, mut ymax) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
    for p in &pts {
        xmin = xmin.min(p.0);
        xmax = xmax.max(p.0);
        ymin = ymin.min(p.1);
        ymax = ymax.max(p.1);
    }
    // room for the guides, the labels and the title (less on the note's
    // page, where a wide margin would cost a whole step of scale)
    let (margin, top) = if task.sheet == crate::project::SheetFormat::A4 {
        (12.0, 12.0)
    } else {
        (22.0, 16.0)
    };
    let sx = standard_scale((xmax - xmin).max(1e-6) * 1e3, w - 2.0 * margin);
    let sy = standard_scale((ymax - ymin).max(1e-6) * 1e3, h - 2.0 * margin - top);
    let scale = match (sx, sy) {
        (Some(x), Some(y)) => {
            if x.factor <= y.factor {
                x
            } else {
                y
            }
        }
        (Some(s), None) | (None, Some(s)) => s,
        (None, None) => crate::paper::Scale { factor: 1.0, text: "1:1" },
    };
    let s = scale.factor * 1e3; // paper mm per metre
    // the paper no taller than the drawing needs: no empty band above and
    // below it on the note's page or on the sheet
    let h = h.min(s * (ymax - ymin) + 2.0 * margin + top);
    let mut c = Canvas::new(w, h);
    let cx = 0.5 * w - s * 0.5 * (xmin + xmax);
    let cy = 0.5 * (h - top) - s * 0.5 * (ymin + ymax);
    c.set_transform(s, (cx, cy));
    c.root_attr("data-scale", scale.text);
    c.root_attr("data-mu-l", &format!("{}", 1.0 / s));
    // the name, and under it the scale and μ (the note keeps these only)
    c.title((0.5 * w, 8.0), word(lang, "linkage.scheme"), H_TITLE, Anchor::Middle);
    let scale_line = format!(
        "{} {},  μ_l = {} {}",
        word(lang, "linkage.scale_short"),
        crate::svg::scale_text(scale.text, lang),
        mu_text(1.0 / s, lang),
        word(lang, "linkage.m_per_mm")
    );
    c.rich_paper((0.5 * w, 14.0), &scale_line, H_LABEL, Anchor::Middle, "#000");
    c.begin_group("paths");
    for p in &paths {
        c.polyline(p, Style::THIN);
    }
    c.end_group();
    let bold = bold_index(a);
    c.begin_group("positions");
    for (i, r) in a.rows.iter().enumerate() {
        if Some(i) == bold {
            continue;
        }
        for (_, p, q) in link_segments(l, &r.sol) {
            c.line(xy(p), xy(q), Style::THIN);
        }
    }
    c.end_group();
    let sol = &a.plan_row.sol;
    c.begin_group("bold-position");
    let segs = link_segments(l, sol);
    for (_, p, q) in &segs {
        c.line(xy(*p), xy(*q), Style::THICK);
    }
    // guides and sliders
    let mut sliders: Vec<(usize, Vec2)> = Vec::new();
    for pr in &m.pairs {
        if let Pair::P {
            guide,
            point,
            q,
            d,
            slider,
            ..
        } = *pr
        {
            let g = &sol.links[guide];
            let qq = g.pos(q);
            let dd = tmm_linkage::state::rot(g.u, d);
            let sp = sol.points[point].p;
            let t = (sp - qq).dot(dd);
            if guide == 0 {
                // the fixed guide over the slider's stroke, 10 mm beyond each end
                let (mut t0, mut t1) = (t, t);
                if let Some(j) = joints.iter().position(|&k| k == point) {
                    for &(x, y) in paths[j].iter().filter(|p| p.0.is_finite()) {
                        let tt = (Vec2::new(x, y) - qq).dot(dd);
                        t0 = t0.min(tt);
                        t1 = t1.max(tt);
                    }
                }
                let ext = 10.0 / s;
                c.line(xy(qq + dd * (t0 - ext)), xy(qq + dd * (t1 + ext)), Style::AXIS);
            }
            let half = 4.0 / s;
            let n = Vec2::new(-dd.y, dd.x);
            let corners = [
                sp + dd * half + n * half * 0.6,
                sp - dd * half + n * half * 0.6,
                sp - dd * half - n * half * 0.6,
                sp + dd * half - n * half * 0.6,
            ];
            c.polygon(&corners.map(xy), Style::THICK.filled("#ffffff"));
            sliders.push((slider, sp + n * half * 0.6));
        }
    }
    // the input's motion: ω1 as an arc arrow around the crank's pivot, or
    // the slider's v as an arrow along its guide with the travel's ends marked
    let (input_mark, input_sym) = match (&m.drive, a.travel) {
        (Some(d), Some(t)) => {
            let sp = sol.points[d.point].p;
            let n = Vec2::new(-d.dir.y, d.dir.x);
            let off = n * (7.0 / s);
            let dv = d.dir * (m.crank.omega.signum() * 14.0 / s);
            c.arrow(xy(sp + off), xy(sp + off + dv), Style::THIN, 3.0);
            for end in [t.from, t.to] {
                let e = d.through + d.dir * end;
                c.line(xy(e - n * (4.0 / s)), xy(e + n * (4.0 / s)), Style::THIN);
            }
            (sp + off + dv * 0.5, format!("v_{}", typeset_name(&m.points[d.point].name, false)))
        }
        _ => {
            let piv = m.crank.pivot;
            let pin_angle = {
                let pin = sol.points[m.crank.pin].p - piv;
                pin.y.atan2(pin.x)
            };
            let r_arc = (0.45 * m.crank.radius * s).clamp(7.0, 14.0) / s;
            let (a0, a1) = if sg > 0.0 {
                (pin_angle + 0.5, pin_angle + 2.2)
            } else {
                (pin_angle - 0.5, pin_angle - 2.2)
            };
            c.arc(xy(piv), r_arc, a0, a1, Style::THIN);
            let tip = piv + Vec2::new(a1.cos(), a1.sin()) * r_arc;
            let back_a = a1 - sg * 0.25;
            let back = piv + Vec2::new(back_a.cos(), back_a.sin()) * r_arc;
            c.arrow(xy(back), xy(tip), Style::THIN, 3.0);
            let mid_a = 0.5 * (a0 + a1);
            (piv + Vec2::new(mid_a.cos(), mid_a.sin()) * r_arc, "ω_1".to_string())
        }
    };
    c.end_group();
    // joints
    for (k, p) in m.points.iter().enumerate() {
        let pos = sol.points[k].p;
        let is_joint = m.pairs.iter().any(|pr| pr.point() == k);
        if p.link == 0 {
            c.fixed_pivot(xy(pos), 1.5);
        } else if is_joint {
            c.joint(xy(pos), 1.2);
        } else {
            c.dot(xy(pos), 0.7, "#000000");
        }
        c.reserve_point(xy(pos), 2.0);
    }
    for r in &a.rows {
        c.reserve_point(xy(r.sol.points[m.crank.pin].p), 0.6);
    }
    // labels: joints, the ω1 arrow, link numbers, position numbers
    c.begin_group("labels");
    for (k, p) in m.points.iter().enumerate() {
        let pos = sol.points[k].p;
        let first_here = (0..m.points.len()).position(|j| (sol.points[j].p - pos).hypot() * s < 1.0) == Some(k);
        if first_here {
            c.label(xy(pos), &typeset_name(&p.name, false), H_LABEL, "#000");
        }
    }
    c.label(xy(input_mark), &input_sym, H_LABEL, "#000");
    if let (Some(d), Some(t)) = (&m.drive, a.travel) {
        // the travel's ends, their s beside their marks
        let n = Vec2::new(-d.dir.y, d.dir.x);
        for end in [t.from, t.to] {
            let e = d.through + d.dir * end - n * (6.0 / s);
            c.label(
                xy(e),
                &format!("s = {} {}", num(end * 1e3, 1, lang), word(lang, "linkage.unit_mm")),
                H_SMALL,
                "#000",
            );
        }
    }
    // each position's number out along its crank, off the cranks that
    // meet at the pivot and the other numbers, placed before the links'
    // numbers so that it keeps the place next to its pin (a number that
    // finds none within 8 mm goes out on a leader line)
    let outward = |pin: Vec2| {
        let d = pin - m.crank.pivot;
        d.y.atan2(d.x)
    };
    for r in &a.rows {
        let pin = r.sol.points[m.crank.pin].p;
        c.label_toward(xy(pin), outward(pin), &r.pos.label, H_SMALL, "#000");
    }
    if bold.is_none() {
        // the plans' position is not one of the table's: its angle beside its crank pin
        let pin = sol.points[m.crank.pin].p;
        c.label_toward(xy(pin), outward(pin), &bold_label(a, lang), H_SMALL, "#000");
    }
    // a link's number with no clear place by its link goes out on a
    // leader line, never onto the scale line or another label (the
    // engine's short crank on the note's page)
    let mut numbered: Vec<usize> = Vec::new();
    for (li, p, q) in &segs {
        if !numbered.contains(li) {
            numbered.push(*li);
            c.label_led(xy((*p + *q) * 0.5), &m.link_names[*li], H_TITLE, "#000");
        }
    }
    for (li, at) in sliders {
        if !numbered.contains(&li) {
            numbered.push(li);
            c.label_led(xy(at), &m.link_names[li], H_TITLE, "#000");
        }
    }
    c.end_group();
    c.finish()
}

/// The kinematic diagrams: (file, SVG).
fn diagrams(l: &Loaded, a: &Analysis, task: &TaskSource) -> Vec<(&'static str, Picture)> {
    if let Some(t) = a.travel {
        return travel_diagrams(l, a, task, t);
    }
    let lang = task.lang;
    let w = l.mech.crank.omega.abs();
    let lin = a.reading.output.kind == tmm_linkage::cycle::OutputKind::Linear;
    let out = &l.mech.link_names[l.mech.output];
    let u = |k: &str| word(lang, k).to_string();
    let (su, vu, au, dsu) = if lin {
        (
            u("linkage.unit_m"),
            u("linkage.unit_mps"),
            u("linkage.unit_mps2"),
            u("linkage.unit_m"),
        )
    } else {
        (
            u("linkage.unit_rad"),
            u("linkage.unit_radps"),
            u("linkage.unit_radps2"),
            u("linkage.unit_rad"),
        )
    };
    let (sym_s, sym_v, sym_a) = if lin {
        ("s".to_string(), "v".to_string(), "a".to_string())
    } else {
        (format!("ψ_{out}"), format!("ω_{out}"), format!("ε_{out}"))
    };
    type Pick = fn(&[f64; 4], f64) -> f64;
    let list: [(&'static str, &str, String, String, Pick); 5] = [
        ("diagram-s.svg", "linkage.diagram_s", sym_s.clone(), su, |d, _| d[1]),
        (
            "diagram-ds.svg",
            "linkage.diagram_ds",
            format!("d{sym_s}/dφ"),
            dsu.clone(),
            |d, _| d[2],
        ),
        ("diagram-dds.svg", "linkage.diagram_dds", format!("d²{sym_s}/dφ²"), dsu, |d, _| d[3]),
        ("diagram-v.svg", "linkage.diagram_v", sym_v, vu, |d, w| d[2] * w),
        ("diagram-a.svg", "linkage.diagram_a", sym_a, au, |d, w| d[3] * w * w),
    ];
    list.into_iter()
        .map(|(file, title, sym, unit, pick)| {
            let mut pts: Vec<(f64, f64)> = Vec::with_capacity(a.diagram.len() + a.diagram_breaks.len());
            for (k, d) in a.diagram.iter().enumerate() {
                if a.diagram_breaks.contains(&k) {
                    // the pen lifts over a range where the mechanism does not assemble
                    pts.push((f64::NAN, f64::NAN));
                }
                pts.push((d[0].to_degrees(), pick(d, w)));
            }
            let marks: Vec<(f64, String)> = a.rows.iter().map(|r| (r.pos.psi.to_degrees(), r.pos.label.clone())).collect();
            (file, cycle_diagram(task, word(lang, title), &sym, &unit, &pts, &marks, w, None))
        })
        .collect()
}

/// The diagrams of a slider-driven mechanism over the slider's travel s (mm):
/// the output's x, dx/ds, d²x/ds², its velocity and acceleration.
fn travel_diagrams(l: &Loaded, a: &Analysis, task: &TaskSource, t: super::Travel) -> Vec<(&'static str, Picture)> {
    let lang = task.lang;
    let m = &l.mech;
    let (v, acc) = (m.crank.omega, m.crank.eps);
    let lin = a.reading.output.kind == tmm_linkage::cycle::OutputKind::Linear;
    let out = &m.link_names[m.output];
    let u = |k: &str| word(lang, k).to_string();
    let (su, vu, au) = if lin {
        (u("linkage.unit_m"), u("linkage.unit_mps"), u("linkage.unit_mps2"))
    } else {
        (u("linkage.unit_rad"), u("linkage.unit_radps"), u("linkage.unit_radps2"))
    };
    let (sym_s, sym_v, sym_a) = if lin {
        ("x".to_string(), "v".to_string(), "a".to_string())
    } else {
        (format!("ψ_{out}"), format!("ω_{out}"), format!("ε_{out}"))
    };
    let (w, h) = slot_mm(Slot::Diagram, task.sheet);
    let xlabel = format!("s, {}", u("linkage.unit_mm"));
    type Pick = fn(&[f64; 4], f64, f64) -> f64;
    let list: [(&'static str, &str, String, String, Pick); 5] = [
        ("diagram-s.svg", "linkage.diagram_s", sym_s.clone(), su.clone(), |d, _, _| d[1]),
        (
            "diagram-ds.svg",
            "linkage.diagram_ds",
            format!("d{sym_s}/ds"),
            format!("{su}/{}", u("linkage.unit_m")),
            |d, _, _| d[2],
        ),
        (
            "diagram-dds.svg",
            "linkage.diagram_dds",
            format!("d²{sym_s}/ds²"),
            format!("{su}/{}²", u("linkage.unit_m")),
            |d, _, _| d[3],
        ),
        ("diagram-v.svg", "linkage.diagram_v", sym_v, vu, |d, v, _| d[2] * v),
        ("diagram-a.svg", "linkage.diagram_a", sym_a, au, |d, v, acc| {
            d[3] * v * v + d[2] * acc
        }),
    ];
    list.into_iter()
        .map(|(file, title, sym, unit, pick)| {
            let pts: Vec<(f64, f64)> = a.diagram.iter().map(|d| ((t.from + d[0]) * 1e3, pick(d, v, acc))).collect();
            let series = [crate::svg::Series {
                name: "",
                points: &pts,
                color: "#000",
            }];
            let ylabel = format!("{sym}, {unit}");
            (file, crate::svg::plot_in(lang, word(lang, title), &xlabel, &ylabel, &series, w, h))
        })
        .collect()
}

/// Values found another way at the positions, drawn as circles over the
/// curve, with a legend naming the curve and the circles (the balancing
/// torque by kinetostatics as the curve, by Zhukovsky's lever at the 12
/// positions as circles).
pub(crate) struct CycleDots<'a> {
    /// (φ from the start of the working stroke in degrees, value).
    pub points: &'a [(f64, f64)],
    /// The curve's name in the legend.
    pub curve_name: &'a str,
    /// The circles' name in the legend.
    pub dots_name: &'a str,
}

/// A diagram over one revolution of the crank: the φ axis 0 … 360° marked
/// with the positions (0 … 12), the quantity's axis at a round μ, both μ
/// and the time's μ_t = μ_φ/ω1 written under the title; `dots` adds values
/// at points as circles, with a legend.
#[allow(clippy::too_many_arguments)]
pub(crate) fn cycle_diagram(
    task: &TaskSource,
    title: &str,
    sym: &str,
    unit: &str,
    pts: &[(f64, f64)],
    marks: &[(f64, String)],
    omega: f64,
    dots: Option<CycleDots<'_>>,
) -> Picture {
    let lang = task.lang;
    let (w, h) = slot_mm(Slot::Diagram, task.sheet);
    let mut c = Canvas::new(w, h);
    let (left, right, top, bottom) = (24.0, 16.0, 22.0, 14.0);
    // x: the cycle (360°, or 720° for a four-stroke engine's data) at a
    // round μ_φ (° per mm)
    let span = if pts.iter().any(|p| p.0 > 360.0 + 1e-6) { 720.0 } else { 360.0 };
    let mu_phi = round_mu(span / (w - left - right));
    let (mut ymin, mut ymax) = (0.0f64, 0.0f64);
    let dot_pts = dots.as_ref().map_or(&[][..], |d| d.points);
    for p in pts.iter().chain(dot_pts).filter(|p| p.1.is_finite()) {
        ymin = ymin.min(p.1);
        ymax = ymax.max(p.1);
    }
    if ymax - ymin < 1e-300 {
        ymax = ymin + 1.0;
    }
    let avail = h - top - bottom;
    let mu_y = round_mu((ymax - ymin) / avail);
    // the zero line: the curve centred in the height available
    let used = (ymax - ymin) / mu_y;
    let y_zero = top + 0.5 * (avail - used) + ymax / mu_y; // paper y of value 0
    let map = |x: f64, y: f64| (left + x / mu_phi, y_zero - y / mu_y);
    c.title((0.5 * w, 7.0), title, H_TITLE, Anchor::Middle);
    let deg = word(lang, "linkage.unit_deg_per_mm");
    let mu_t = mu_phi.to_radians() / omega;
    let scales = format!(
        "μ_{sym_plain} = {} {unit_per},  μ_φ = {} {deg},  μ_t = {} {}/{mm}",
        mu_text(mu_y, lang),
        mu_text(mu_phi, lang),
        num(mu_t, 6, lang),
        word(lang, "linkage.unit_s"),
        sym_plain = sym.split('_').next().unwrap_or(sym).replace(['²', '/', 'd'], ""),
        mm = word(lang, "linkage.unit_mm"),
        unit_per = if unit.contains('/') {
            format!("({unit})/{}", word(lang, "linkage.unit_mm"))
        } else {
            format!("{unit}/{}", word(lang, "linkage.unit_mm"))
        },
    );
    c.rich_paper((0.5 * w, 13.5), &scales, H_SMALL + 0.5, Anchor::Middle, "#000");
    // axes
    let (x0, yz) = map(0.0, 0.0);
    let (x1, _) = map(span, 0.0);
    c.arrow_paper((x0, yz), (x1 + 8.0, yz), Style::THIN, 3.0);
    let (_, ytop) = map(0.0, ymax);
    let (_, ybot) = map(0.0, ymin);
    c.arrow_paper((x0, ybot.max(yz) + 1.0), (x0, ytop - 6.0), Style::THIN, 3.0);
    c.rich_paper(
        (x0 + 3.0, ytop - 3.0),
        &format!("{sym}, {unit}"),
        H_SMALL + 0.5,
        Anchor::Start,
        "#000",
    );
    c.rich_paper((x1 + 9.0, yz + 4.5), "φ", H_LABEL, Anchor::Middle, "#000");
    // the positions' marks and ordinates
    for (x, _) in marks {
        let (xp, _) = map(*x, 0.0);
        c.line_paper((xp, yz - 1.2), (xp, yz + 1.2), Style::THIN);
    }
    let (xe, _) = map(span, 0.0);
    c.line_paper((xe, yz - 1.2), (xe, yz + 1.2), Style::THIN);
    // the y ticks: every 10 mm at the round μ
    for (k, v) in crate::paper::grid_values(ymin, ymax, 10.0 * mu_y) {
        let (_, yp) = map(0.0, v);
        c.line_paper((x0 - 1.2, yp), (x0, yp), Style::THIN);
        if k != 0 {
            c.rich_paper((x0 - 2.0, yp + 0.9), &signed(v, lang), H_SMALL, Anchor::End, "#000");
        }
    }
    // the curve, thick
    let curve: Vec<(f64, f64)> = pts.iter().map(|p| map(p.0, p.1)).collect();
    c.path_paper(Some("curve"), &curve, Style::THICK.widened(0.7).colored("#000"));
    let dot_paper: Vec<(f64, f64)> = dot_pts.iter().map(|p| map(p.0, p.1)).collect();
    if let Some(dots) = &dots {
        let mark = Style::THIN.widened(0.35).colored("#0050c0");
        for &(x, y) in dots.points.iter().filter(|p| p.0.is_finite() && p.1.is_finite()) {
            c.marker_paper("dot", map(x, y), 1.1, mark);
        }
        // the legend, top right inside the paper
        let (lx, ly) = (w - right - 52.0, top - 3.0);
        c.line_paper((lx, ly - 0.9), (lx + 6.0, ly - 0.9), Style::THIN.widened(0.7));
        c.rich_paper((lx + 7.5, ly), dots.curve_name, H_SMALL, Anchor::Start, "#000");
        c.marker_paper("legend", (lx + 3.0, ly + 3.5 - 0.9), 1.1, mark);
        c.rich_paper((lx + 7.5, ly + 3.5), dots.dots_name, H_SMALL, Anchor::Start, "#000");
    }
    // position numbers under the axis, clear of the curve
    // the full turn's end numbered after the last position, unless a
    // position stands there already (a range that ends within 2 mm of it)
    // (the cycle's end: 360°, or 720° for a four-stroke engine, numbered
    // as many as there are positions)
    let count = marks.iter().filter(|m| !m.1.ends_with('\'')).count();
    let end_free = marks.iter().all(|(x, _)| (map(span, 0.0).0 - map(*x, 0.0).0).abs() > 2.0);
    let end = end_free.then(|| (span, count.to_string()));
    // numbers closer than two digits' width (about 4.5 mm at 2.5 mm
    // lettering) are written at every other position, the ticks kept
    let pitch = marks
        .windows(2)
        .map(|m| (m[1].0 - m[0].0).abs() / mu_phi)
        .fold(f64::INFINITY, f64::min);
    let every = if pitch < 4.5 && count > 12 { 2 } else { 1 };
    for (i, (x, label)) in marks.iter().chain(end.iter()).enumerate() {
        if label.ends_with('\'') && marks.len() > 1 {
            // the extreme position: its number above the axis
            let (xp, _) = map(*x, 0.0);
            c.rich_paper((xp, yz - 2.0), label, H_SMALL, Anchor::Middle, "#000");
            continue;
        }
        let (xp, _) = map(*x, 0.0);
        let n = if *x >= span - 1e-9 { count.to_string() } else { label.clone() };
        if every > 1 && i < marks.len() && label.parse::<usize>().is_ok_and(|k| k % every != 0) {
            continue;
        }
        // under the axis unless the curve or a circle passes there: then above
        let (bx0, bx1) = (xp - 1.5, xp + 1.5);
        let hits = |y0: f64, y1: f64| {
            curve
                .iter()
                .chain(dot_paper.iter())
                .any(|&(px, py)| (bx0 - 1.2..=bx1 + 1.2).contains(&px) && (y0 - 1.2..=y1 + 1.2).contains(&py))
        };
        let y = match (hits(yz + 2.0, yz + 4.5), hits(yz - 4.5, yz - 2.0)) {
            (false, _) => yz + 4.5,
            (true, false) => yz - 2.0,
            // the curve crosses the axis there: lower, clear of a circle on the axis
            (true, true) => yz + 6.0,
        };
        c.rich_paper((xp, y), &n, H_SMALL, Anchor::Middle, "#000");
    }
    c.finish()
}

/// A tick value: a multiple of a round μ, printed exactly with a minus sign
/// when negative.
fn signed(v: f64, lang: Language) -> String {
    let t = mu_text(v.abs(), lang);
    if v < 0.0 { format!("−{t}") } else { t }
}

/// The greatest height of a plan's vectors on the note's page, mm: the
/// velocity and the acceleration plan of one position, each with its μ line
/// (about 8 mm) and its caption and the gaps around it (about 20 mm), stand
/// together in the text area of an A4 page with the frame (243 mm):
/// 2 · (95 + 8 + 20) = 246 mm at the worst, the labels usually inside the
/// vectors' box.
const PLAN_PAIR_MM: f64 = 95.0;

/// Which plan.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    Velocity,
    Acceleration,
}

/// A vector's label in the course's notation: `V_CB` → `v_CB`, `a^t_CB` →
/// `a^τ_CB`, `a^k_…` stays k, `a^r_…` stays r.
fn vector_label(label: &str) -> String {
    let l = label.replacen("a^t_", "a^τ_", 1);
    match l.strip_prefix("V_") {
        Some(rest) => format!("v_{rest}"),
        None => l,
    }
}

/// A velocity or acceleration plan at a round μ: the pole (p or π), the
/// images of the points (a, b, c, s2 …), the points n of the normal
/// accelerations, each vector in its `<g class="plan-vector">` with its
/// label and kind for reading back.
fn plan(task: &TaskSource, kind: Kind, v: &[PlanVector], position: &str) -> Picture {
    let lang = task.lang;
    let (w, h) = slot_mm(Slot::Plan, task.sheet);
    let mut c = Canvas::new(w, h);
    let (pole, title_key, unit_key, sym) = match kind {
        Kind::Velocity => ("p", "linkage.velocity_plan", "linkage.mu_v_unit", "μ_v"),
        Kind::Acceleration => ("π", "linkage.acceleration_plan", "linkage.mu_a_unit", "μ_a"),
    };
    let mut pts = vec![Vec2::ZERO];
    for p in v {
        pts.push(p.from);
        pts.push(p.to);
    }
    let (mut xmin, mut xmax, mut ymin, mut ymax) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
    for p in &pts {
        xmin = xmin.min(p.x);
        xmax = xmax.max(p.x);
        ymin = ymin.min(p.y);
        ymax = ymax.max(p.y);
    }
    let (margin, top) = (14.0, 18.0);
    // on the note's page (A4) the two plans of one position share a page:
    // each plan's vectors at most PLAN_PAIR_MM high, so the pair with its
    // captions fits the text area (243 mm with the frame), μ the next of
    // the standard series (`round_mu`: 1, 2, 2.5, 4, 5 · 10ᵏ)
    let tall = if task.sheet == crate::project::SheetFormat::A4 {
        PLAN_PAIR_MM
    } else {
        h - 2.0 * margin - top
    };
    let raw = ((xmax - xmin) / (w - 2.0 * margin)).max((ymax - ymin) / tall);
    let mu = round_mu(raw.max(1e-12));
    let s = 1.0 / mu;
    let cx = 0.5 * w - s * 0.5 * (xmin + xmax);
    let cy = 0.5 * (h - top) - s * 0.5 * (ymin + ymax);
    c.set_transform(s, (cx, cy));
    c.root_attr("data-mu", &format!("{mu}"));
    let pos_text = if position.starts_with('φ') || position.contains(' ') {
        position.to_string()
    } else {
        position_text(lang, position)
    };
    // the name; under it the position and μ (the note keeps these only)
    c.title((0.5 * w, 8.0), word(lang, title_key), H_TITLE, Anchor::Middle);
    c.rich_paper(
        (0.5 * w, 15.0),
        &format!("{pos_text},  {sym} = {} {}", mu_text(mu, lang), word(lang, unit_key)),
        H_LABEL,
        Anchor::Middle,
        "#000",
    );
    let shown: Vec<&PlanVector> = v.iter().filter(|p| (p.to - p.from).hypot() * s >= 0.05).collect();
    for p in &shown {
        let st = match p.kind {
            VectorKind::Absolute => Style::THICK.widened(0.5),
            _ => Style::THIN.widened(0.35),
        };
        c.begin_group_data("plan-vector", &[("data-label", &p.label), ("data-kind", &format!("{:?}", p.kind))]);
        c.arrow(xy(p.from), xy(p.to), st, 3.0);
        c.end_group();
    }
    // points: the pole, the images, the n points
    c.dot((0.0, 0.0), 0.8, "#000000");
    c.reserve_point((0.0, 0.0), 1.2);
    for p in &shown {
        c.dot(xy(p.to), 0.5, "#000000");
        c.reserve_point(xy(p.to), 1.0);
    }
    c.label((0.0, 0.0), pole, H_LABEL, "#000");
    let mut named: Vec<Vec2> = vec![Vec2::ZERO];
    let mut n_count = 0;
    for p in &shown {
        let name = match p.kind {
            VectorKind::Absolute => {
                let n = p.label.split_once('_').map_or(p.label.as_str(), |x| x.1);
                typeset_name(n, true)
            }
            VectorKind::Normal => {
                n_count += 1;
                format!("n_{n_count}")
            }
            _ => continue,
        };
        if named.iter().any(|q| (*q - p.to).hypot() * s < 0.5) {
            continue;
        }
        named.push(p.to);
        c.label(xy(p.to), &name, H_LABEL, "#000");
    }
    // the relative vectors' names, beside their middles
    for p in &shown {
        if p.kind == VectorKind::Absolute || (p.to - p.from).hypot() * s < 6.0 {
            continue;
        }
        c.label(xy((p.from + p.to) * 0.5), &vector_label(&p.label), H_SMALL, "#000");
    }
    c.finish()
}
