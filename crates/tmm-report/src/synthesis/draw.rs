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
use crate::paper::{Scale, Slot, slot_mm, standard_scale};
use crate::picture::Picture;
use crate::project::{Language, SheetFormat};
use crate::svg::{Anchor, Canvas, Series, Style, mu_text, num, plot_in};
use crate::words::word;

const BLUE: &str = "#1f4e9c";
const RED: &str = "#c0392b";
const GREEN: &str = "#1e8449";
const GREY: &str = "#7f8c8d";

/// Both drawings, with the words of `lang`, sized for a sheet of `sheet`.
pub fn drawings(s: &Solved, lang: Language, sheet: SheetFormat) -> Result<Documents, Error> {
    let mut d = Documents::new();
    d.add_text("synthesis/construction.svg", construction(s, lang, sheet))?;
    d.add_text("synthesis/pressure.svg", pressure(s, lang, sheet)?)?;
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
    // the given positions of a problem by positions (the textbook's П1)
    if !y.shown.is_empty()
        && let Ok(m) = Mechanism::new(&y.def)
    {
        let mut sol = m.solution();
        return y
            .shown
            .iter()
            .filter_map(|phi| {
                m.solve(*phi, &mut sol).ok()?;
                Some(m.points.iter().zip(&sol.points).map(|(p, q)| (p.name.clone(), q.p)).collect())
            })
            .collect();
    }
    if y.kind != Kind::FunctionGeneration {
        // the first drawn (blue, ′) is the one whose driven point is the
        // construction's first extreme, so the colours, the primes and the
        // legend agree
        let mut dead = y.check.dead_positions.clone();
        let k = &y.construction;
        let miss = |pos: &Vec<(String, Vec2)>| {
            pos.iter()
                .find(|(n, _)| *n == k.point)
                .map_or(f64::INFINITY, |(_, p)| (*p - k.extremes[0]).hypot())
        };
        if dead.len() == 2 && miss(&dead[1]) < miss(&dead[0]) {
            dead.swap(0, 1);
        }
        return dead;
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

/// Lettering heights (GOST 2.304).
const H_LABEL: f64 = 3.5;
const H_SMALL: f64 = 2.5;

/// The construction drawing at a GOST 2.302 standard scale on the Small
/// slot of a sheet of `sheet`, with the words of `lang`: the root carries
/// `data-scale` and `data-mu-l`, the chord between the driven point's
/// extremes is the line of class `chord`.
pub fn construction(s: &Solved, lang: Language, sheet: SheetFormat) -> Picture {
    let wd = |k: &str| word(lang, &format!("synthesis.{k}")).to_string();
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
    let mut world = (b.0 - 0.05 * size, b.1 + 0.05 * size, b.2 - 0.05 * size, b.3 + 0.05 * size);
    if let Some(l) = &k.locus {
        // the course draws the centre O* that sees the chord at 2θ: when it
        // lies within one size of the mechanism and the circle is no larger
        // than the mechanism, the view takes the whole circle in
        let wide: Box4 = (b.0 - size, b.1 + size, b.2 - size, b.3 + size);
        let everything: Box4 = (f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY);
        let circle_view = if inside(wide, l.center) && l.radius <= size {
            everything
        } else {
            view
        };
        for i in 0..720 {
            let a = i as f64 * std::f64::consts::TAU / 720.0;
            let p = l.center + Vec2::new(a.cos(), a.sin()) * l.radius;
            if inside(circle_view, p) {
                world = grow(world, p);
            }
        }
        if inside(circle_view, l.center) {
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
    let (w, h) = slot_mm(Slot::Small, sheet);
    let mut c = Canvas::new(w, h);
    // the legend under the drawing: each entry broken into lines that stay
    // on the paper at the printed letter size, its sample by the first
    let function = y.kind == Kind::FunctionGeneration;
    // a lever driven by a cylinder has no time ratio K_v nor angle θ of
    // the crank: its header gives the lever's swing β instead
    let cylinder = y.kind == Kind::OscillatingCylinder;
    // the extreme positions named by their point (B′, B″) and the chosen
    // pivot by its letter, so the legend reads without its colours
    let extreme = |key: &str| wd(key).replace("{1}", &k.point);
    let mut leg: Vec<(Option<&str>, String)> = vec![
        (Some(BLUE), if function { wd("first_position") } else { extreme("extreme_first") }),
        (Some(RED), if function { wd("last_position") } else { extreme("extreme_second") }),
    ];
    if k.locus.is_some() {
        leg.push((Some(GREEN), wd("locus")));
    }
    if !function && let Some((name, _)) = y.frame.iter().find(|(_, p)| (*p - k.pivot).hypot() <= 1e-9 * size) {
        // a cylinder drive's pivot is the lever's, not a crank's
        let pivot = if cylinder {
            word(lang, "synthesis_cylinder.lever_pivot").to_string()
        } else {
            wd("chosen_pivot")
        };
        leg[1].1 = format!("{};  {}", leg[1].1, pivot.replace("{1}", name));
    }
    let side = 6.0;
    let rows: Vec<(Option<&str>, String)> = leg
        .iter()
        .flat_map(|(col, t)| {
            crate::labels::wrap_text(t, H_SMALL, w - side - 10.0 - 0.5)
                .into_iter()
                .enumerate()
                .map(move |(i, l)| (if i == 0 { *col } else { None }, l))
        })
        .collect();
    // rows as far apart as the lettering printed (its floor, picture::em)
    let row_step = (1.25 * crate::picture::em(H_SMALL)).max(4.5);
    // the paper box left for the drawing: under the title and the scale,
    // over the legend
    let (top, bottom) = (16.0, (5.0 + row_step * (rows.len() as f64 - 1.0) + 2.5).max(17.0));
    let (aw, ah) = (w - 2.0 * side, h - top - bottom);
    let (ww, wh) = ((world.1 - world.0) * 1000.0, (world.3 - world.2) * 1000.0);
    let scale = match (standard_scale(ww, aw), standard_scale(wh, ah)) {
        (Some(a), Some(b)) => {
            if a.factor <= b.factor {
                a
            } else {
                b
            }
        }
        (Some(a), None) | (None, Some(a)) => a,
        (None, None) => Scale { factor: 1.0, text: "1:1" },
    };
    let k_mm = scale.factor * 1000.0; // paper mm per m
    let ox = side + 0.5 * (aw - ww * scale.factor) - k_mm * world.0;
    let oy = bottom + 0.5 * (ah - wh * scale.factor) - k_mm * world.2;
    c.set_transform(k_mm, (ox, oy));
    c.root_attr("data-scale", scale.text);
    c.root_attr("data-mu-l", &format!("{}", 0.001 / scale.factor));
    let h_title = if sheet == SheetFormat::A1 { 5.0 } else { H_LABEL };
    let title = if function {
        wd("title_function")
    } else if cylinder {
        word(lang, "synthesis_cylinder.title").to_string()
    } else {
        wd("title")
    };
    c.title((0.5 * w, 6.0), &title, h_title, Anchor::Middle);
    let sub = if function {
        format!(
            "{} {},   μ_l = {} {}",
            word(lang, "common.scale"),
            crate::svg::scale_text(scale.text, lang),
            mu_text(0.001 / scale.factor, lang),
            wd("m_per_mm")
        )
    } else if cylinder {
        let swing = y.given.iter().find(|(n, _)| n == "swing").map_or(0.0, |g| g.1);
        format!(
            "{} {},   μ_l = {} {},   {} β = {}°",
            word(lang, "common.scale"),
            crate::svg::scale_text(scale.text, lang),
            mu_text(0.001 / scale.factor, lang),
            wd("m_per_mm"),
            word(lang, "synthesis_cylinder.swing"),
            num(swing.to_degrees(), 2, lang)
        )
    } else {
        format!(
            "{} {},   μ_l = {} {},   K_v = {},   θ = {}°",
            word(lang, "common.scale"),
            crate::svg::scale_text(scale.text, lang),
            mu_text(0.001 / scale.factor, lang),
            wd("m_per_mm"),
            num(y.k, 4, lang),
            num(y.theta.to_degrees(), 2, lang)
        )
    };
    c.rich_paper((0.5 * w, 12.0), &sub, H_SMALL + 0.5, Anchor::Middle, "#000");
    let clip = (world.0, world.1, world.2, world.3);
    // ---- the lines first (the labels keep clear of them) ----
    let mut labels: Vec<((f64, f64), String, &'static str)> = Vec::new();
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
            labels.push((
                xy(l.center),
                format!("O^* (2θ = {}°)", num(2.0 * y.theta.to_degrees(), 2, lang)),
                GREEN,
            ));
        }
    }
    for (_, p, q) in &k.lines {
        c.line(xy(*p), xy(*q), Style::AXIS.colored(GREY));
    }
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
                if let Some(p) = at(n)
                    && !y.frame.iter().any(|f| &f.0 == n)
                {
                    c.joint(xy(p), 0.8);
                    c.reserve_point(xy(p), 1.0);
                }
            }
        }
    }
    // the chord between the extremes (its drawn length is the stroke × scale)
    let (pa, pb) = (
        c.to_paper(k.extremes[0].x, k.extremes[0].y),
        c.to_paper(k.extremes[1].x, k.extremes[1].y),
    );
    c.line_classed("chord", pa, pb, Style::THIN.widened(0.35).colored("#000"));
    c.reserve_segment(pa, pb);
    if !function {
        c.line(xy(k.pivot), xy(k.extremes[0]), Style::DASHED);
        c.line(xy(k.pivot), xy(k.extremes[1]), Style::DASHED);
    }
    // θ between the rays at the pivot
    let r0 = k.extremes[0] - k.pivot;
    let r1 = k.extremes[1] - k.pivot;
    let (n0, n1) = (r0.hypot(), r1.hypot());
    if n0 > 0.0 && n1 > 0.0 && y.theta > 0.0 && k.locus.is_some() {
        let rr = 0.3 * n0.min(n1);
        let (a0, a1) = (r0.atan2(), r1.atan2());
        let d = tmm_geom::angle::diff(a0, a1);
        c.arc(xy(k.pivot), rr, a0, a0 + d, Style::THIN);
        let am = a0 + 0.5 * d;
        labels.push((xy(k.pivot + Vec2::new(am.cos(), am.sin()) * rr), "θ".to_string(), "#000"));
    }
    for (_, p) in &y.frame {
        c.fixed_pivot(xy(*p), 1.2);
        c.reserve_point(xy(*p), 1.5);
    }
    c.dot(xy(k.pivot), 1.0, RED);
    // ---- then the labels, each placed clear of the lines and the others ----
    // ′ (blue) marks the extreme position drawn in blue, the one that starts
    // the working stroke (the first dead position the core found)
    let first = shown
        .first()
        .and_then(|pos| pos.iter().find(|(n, _)| *n == k.point))
        .map(|(_, p)| *p);
    let order = match first {
        Some(p) if (p - k.extremes[1]).hypot() < (p - k.extremes[0]).hypot() => [1, 0],
        _ => [0, 1],
    };
    for (i, &j) in order.iter().enumerate() {
        labels.push((
            xy(k.extremes[j]),
            format!("{}{}", k.point, if i == 0 { "′" } else { "″" }),
            colors[i],
        ));
    }
    for (n, p) in &y.frame {
        let chosen = !function && (*p - k.pivot).hypot() <= 1e-9 * size;
        labels.push((xy(*p), n.clone(), if chosen { RED } else { "#000" }));
    }
    // the legend under the drawing (before the labels, which keep off it),
    // a group of its own: the note's figure closes the gap above it
    // (`crate::crop`)
    c.begin_group(crate::crop::LEGEND);
    for (i, (col, t)) in rows.iter().enumerate() {
        let yy = h - bottom + 5.0 + row_step * i as f64;
        if let Some(col) = col {
            c.line_paper((side, yy - 0.9), (side + 8.0, yy - 0.9), Style::THICK.colored(col).widened(0.5));
        }
        c.rich_paper((side + 10.0, yy), t, H_SMALL, Anchor::Start, "#000");
    }
    c.end_group();
    for (at, text, col) in &labels {
        c.label_led(*at, text, H_LABEL, col);
    }
    c.finish()
}

/// The pressure angle at each dyad's inner joint over the cycle, from the
/// start of the working stroke, by the linkage core.
pub fn pressure(s: &Solved, lang: Language, sheet: SheetFormat) -> Result<Picture, Error> {
    let wd = |k: &str| word(lang, &format!("synthesis.{k}")).to_string();
    let m = Mechanism::new(&s.syn.def).map_err(|e| Error::input("synthesis", e))?;
    // K = 1 (an axial crank-slider): neither stroke is the slower one; the
    // working stroke is then the one on which the output coordinate grows,
    // as in the check (tmm_linkage::synthesis::check)
    let cy = match Cycle::new(&m, Working::Slower) {
        Ok(c) => c,
        Err(_) if !s.syn.check.crank_turns_fully => return Ok(pressure_partial(&m, lang, sheet)),
        Err(e) => Cycle::new(&m, Working::Increasing).map_err(|_| Error::input("synthesis", e))?,
    };
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
    let w = cy.working_angle.to_degrees();
    // the allowed angles on each stroke, when the request gives them
    let q = &s.spec.request;
    let limits = tmm_linkage::synthesis::Limits {
        pressure_working: q.value("pressure_working"),
        pressure_return: q.value("pressure_return"),
        transmission_min: q.value("transmission_min"),
    };
    let (lw, lr) = limits.pressure();
    // one step line: [ϑ]w over the working stroke, [ϑ]r over the return
    let mut lim: Vec<(f64, f64)> = Vec::new();
    if let Some(l) = lw {
        lim.extend([(0.0, l.to_degrees()), (w, l.to_degrees())]);
    }
    match lr {
        Some(l) => lim.extend([(w, l.to_degrees()), (360.0, l.to_degrees())]),
        None if !lim.is_empty() => lim.push((f64::NAN, f64::NAN)),
        None => {}
    }
    let data_top = curves
        .iter()
        .flat_map(|c| c.1.iter().map(|p| p.1))
        .chain(lim.iter().map(|p| p.1).filter(|y| y.is_finite()))
        .fold(0.0_f64, f64::max);
    // the legend sits over the top of the plot, one 4.5 mm row per series:
    // the end-of-stroke line reaches high enough to keep the curves below it
    let (_, ph_mm) = slot_mm(Slot::Diagram, sheet);
    let rows = curves.len() + 1 + usize::from(!lim.is_empty());
    let free = 1.0 - (4.5 * rows as f64 + 2.0) / (ph_mm - 30.0);
    let top = if free > 0.3 { data_top / free } else { data_top };
    let marker = [(w, 0.0), (w, top)];
    let names: Vec<String> = curves.iter().map(|c| format!("ϑ {}", m.points[c.0].name)).collect();
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
    let end_name = wd("end_working");
    series.push(Series {
        name: &end_name,
        points: &marker,
        color: GREY,
    });
    let lim_name = wd("limit");
    if !lim.is_empty() {
        series.push(Series {
            name: &lim_name,
            points: &lim,
            color: "#000",
        });
    }
    let (w, h) = slot_mm(Slot::Diagram, sheet);
    Ok(plot_in(
        lang,
        &format!("{} (0…{}°)", wd("title_pressure"), num(cy.working_angle.to_degrees(), 1, lang)),
        &wd("axis_crank"),
        "ϑ, °",
        &series,
        w,
        h,
    ))
}

/// The pressure angle at each dyad's inner joint against the absolute crank
/// angle φ, for a crank that does not turn fully (no cycle, no working
/// stroke): sampled each degree, a curve broken where the mechanism does not
/// assemble.
fn pressure_partial(m: &Mechanism, lang: Language, sheet: SheetFormat) -> Picture {
    let wd = |k: &str| word(lang, &format!("synthesis.{k}")).to_string();
    let mut sol = m.solution();
    let mut out = Vec::new();
    let mut curves: Vec<(usize, Vec<(f64, f64)>)> = Vec::new();
    let mut assembled = true;
    for i in 0..=360 {
        let phi = f64::from(i).to_radians();
        if m.solve(phi, &mut sol).is_err() {
            // a break in every curve (the plot leaves a gap at a NaN point)
            if assembled {
                for c in &mut curves {
                    c.1.push((f64::NAN, f64::NAN));
                }
            }
            assembled = false;
            continue;
        }
        assembled = true;
        pressure_angles(m, &sol, &mut out);
        for &(pt, v) in &out {
            let at = (f64::from(i), v.to_degrees());
            match curves.iter_mut().find(|c| c.0 == pt) {
                Some(c) => c.1.push(at),
                None => curves.push((pt, vec![at])),
            }
        }
    }
    let names: Vec<String> = curves.iter().map(|c| format!("ϑ {}", m.points[c.0].name)).collect();
    let cols = [BLUE, RED, GREEN, "#8e44ad", "#d35400"];
    let series: Vec<Series<'_>> = curves
        .iter()
        .enumerate()
        .map(|(i, c)| Series {
            name: &names[i],
            points: &c.1,
            color: cols[i % cols.len()],
        })
        .collect();
    let (w, h) = slot_mm(Slot::Diagram, sheet);
    plot_in(
        lang,
        &wd("title_pressure_partial"),
        &wd("axis_crank_absolute"),
        "ϑ, °",
        &series,
        w,
        h,
    )
}
