//! The drawings of the `[forces]` section: each Assur group's free-body
//! diagram to scale with its force polygon (план сил), the input link's,
//! Zhukovsky's lever (the velocity plan turned by 90° with the forces at the
//! images of their points), the balancing torque over the cycle, and the
//! N, Q, M diagrams of the link sized for strength.

use tmm_geom::Vec2;

use super::task::ForcesTask;
use super::{Analysis, Row, json::pair_name};
use crate::Error;
use crate::linkage::Loaded;
use crate::output::Documents;
use crate::svg::{Anchor, Canvas, Series, Style, plot};

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
fn free_body(l: &Loaded, r: &Row, links: &[usize], which: usize, title: &str) -> String {
    let m = &l.mech;
    let f = &r.fs;
    let sol = &r.sol;
    let mut couples: Vec<(Vec2, f64, String)> = Vec::new();
    for &li in links {
        let lf = &f.links[li];
        if lf.moment != 0.0 {
            couples.push((lf.s, lf.moment, format!("M{} = {:.2} N·m", m.link_names[li], lf.moment)));
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
    let mut c = Canvas::new(297.0, 210.0);
    let pad = 0.08 * (pxmax - pxmin).max(pymax - pymin);
    c.fit((pxmin - pad, pxmax + pad, pymin - pad, pymax + pad), (10.0, 10.0, 277.0, 175.0));
    c.text_paper((10.0, 10.0), title, 4.0, Anchor::Start, "#000000");
    c.text_paper(
        (10.0, 16.0),
        &format!(
            "φ = {:.2}°; forces: μ_F = {:.4e} N/mm on the body, {:.4e} N/mm in the polygon (план сил)",
            r.phi.to_degrees(),
            1.0 / (mu * c.scale()),
            1.0 / (mup * c.scale())
        ),
        3.0,
        Anchor::Start,
        "#404040",
    );
    c.begin_group("links");
    for (a, b) in &segs {
        c.line(t(*a), t(*b), Style::THICK);
    }
    for p in &pts {
        c.dot(t(*p), 0.8, "#000000");
    }
    c.end_group();
    c.begin_group("forces");
    for (i, a) in arrows.iter().enumerate() {
        let col = COLORS[i % COLORS.len()];
        c.arrow(t(a.at), t(a.at + a.f * mu), Style::THIN.colored(col).widened(0.5), 3.0);
        c.text_colored(
            t(a.at + a.f * mu),
            &format!("{} {:.1} N", a.label, a.f.hypot()),
            2.8,
            Anchor::Start,
            col,
        );
    }
    for (p, mo, label) in &couples {
        let r0 = 0.08 * size;
        let (a0, a1) = if *mo > 0.0 { (0.0, 4.5) } else { (4.5, 0.0) };
        c.arc(t(*p), r0, a0, a1, Style::THIN.colored("#606060"));
        let tip = *p + Vec2::new(a1.cos(), a1.sin()) * r0;
        let back = *p + Vec2::new((a1 - 0.3 * (a1 - a0).signum()).cos(), (a1 - 0.3 * (a1 - a0).signum()).sin()) * r0;
        c.arrow(t(back), t(tip), Style::THIN.colored("#606060"), 2.0);
        c.text_colored(t(*p + Vec2::new(0.0, -1.6 * r0)), label, 2.6, Anchor::Middle, "#606060");
    }
    c.end_group();
    c.begin_group("force-polygon");
    for (i, a) in arrows.iter().enumerate() {
        let col = COLORS[i % COLORS.len()];
        c.arrow(t(poly[i]), t(poly[i + 1]), Style::THIN.colored(col).widened(0.5), 3.0);
        let mid = (poly[i] + poly[i + 1]) * 0.5;
        c.text_colored(t(mid), &a.label, 2.6, Anchor::Start, col);
    }
    let gap = (*poly.last().unwrap_or(&origin) - origin).hypot();
    c.text_colored(
        t(origin + Vec2::new(0.0, -0.1 * size)),
        &format!("closure {:.2e} N", gap / mup),
        2.6,
        Anchor::Start,
        "#404040",
    );
    c.end_group();
    c.finish()
}

/// Zhukovsky's lever: the velocity plan turned by 90° with the forces.
fn lever(l: &Loaded, a: &Analysis) -> String {
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
    {
        xmin = xmin.min(p.x);
        xmax = xmax.max(p.x);
        ymin = ymin.min(p.y);
        ymax = ymax.max(p.y);
    }
    let mut c = Canvas::new(297.0, 210.0);
    let pad = 0.08 * (xmax - xmin).max(ymax - ymin).max(1e-9);
    c.fit((xmin - pad, xmax + pad, ymin - pad, ymax + pad), (10.0, 10.0, 277.0, 170.0));
    c.text_paper(
        (10.0, 10.0),
        &format!(
            "Zhukovsky's lever at φ = {:.2}°: the velocity plan turned by +90°, forces at the images of their points",
            r.phi.to_degrees()
        ),
        4.0,
        Anchor::Start,
        "#000000",
    );
    c.text_paper(
        (10.0, 16.0),
        &format!(
            "Σ moments about the pole = 0 ⇒ M_Zh = {:.4} N·m, P_b = {:.4} N (kinetostatics: M_b = {:.4} N·m)",
            r.fs.zhukovsky_moment,
            r.fs.zhukovsky_moment / m.crank.radius,
            r.fs.balancing_moment
        ),
        3.0,
        Anchor::Start,
        "#404040",
    );
    c.begin_group("plan");
    for (i, p) in imgs.iter().enumerate() {
        c.line((0.0, 0.0), t(*p), Style::THIN.colored("#a0a0a0"));
        c.dot(t(*p), 0.6, "#000000");
        c.text(t(*p), &m.points[i].name.to_lowercase(), 3.0, Anchor::Start);
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
    c.text((0.0, 0.0), "p", 3.0, Anchor::End);
    c.end_group();
    c.begin_group("forces");
    for (i, x) in a.lever.iter().enumerate() {
        let col = COLORS[i % COLORS.len()];
        c.arrow(t(x.image), t(x.image + x.force * mu), Style::THIN.colored(col).widened(0.5), 3.0);
        c.text_colored(
            t(x.image + x.force * mu),
            &format!("{} {:.1} N", x.label, x.force.hypot()),
            2.6,
            Anchor::Start,
            col,
        );
    }
    c.end_group();
    c.finish()
}

/// Every drawing, as documents whose paths start with `dir` (`"forces/"`).
pub fn draw_all(l: &Loaded, _t: &ForcesTask, a: &Analysis, dir: &str, docs: &mut Documents) -> Result<(), Error> {
    let m = &l.mech;
    for (g, grp) in m.groups.iter().enumerate().rev() {
        let names: Vec<String> = grp.info.pair_ids.iter().map(|&p| pair_name(l, p)).collect();
        let title = format!(
            "Group {} — {} (pairs {}): free body and force polygon",
            g + 1,
            grp.label(),
            names.join(", ")
        );
        docs.add_text(
            format!("{dir}group-{}.svg", g + 1),
            free_body(l, &a.detail, &grp.info.link_ids, g, &title),
        )?;
    }
    let title = format!(
        "Input link {} with the balancing force P_b = {:.3} N at the crank pin",
        m.link_names[m.crank.link], a.detail.fs.balancing_force
    );
    docs.add_text(
        format!("{dir}input-link.svg"),
        free_body(l, &a.detail, &[m.crank.link], m.groups.len(), &title),
    )?;
    docs.add_text(format!("{dir}zhukovsky-lever.svg"), lever(l, a))?;
    let mb: Vec<(f64, f64)> = a.curve.iter().map(|c| (c[0].to_degrees(), c[2])).collect();
    let mz: Vec<(f64, f64)> = a.curve.iter().map(|c| (c[0].to_degrees(), c[3])).collect();
    let svg = plot(
        "Balancing torque on the input link over the cycle",
        "crank travel from the start of the working stroke ψ, °",
        "M_b, N·m",
        &[
            Series {
                name: "kinetostatics",
                points: &mb,
                color: "#c00000",
            },
            Series {
                name: "Zhukovsky's lever",
                points: &mz,
                color: "#0050c0",
            },
        ],
        240.0,
        150.0,
    );
    docs.add_text(format!("{dir}balancing-torque.svg"), svg)?;
    if let Some(b) = &a.beam {
        let link = &m.link_names[b.beam.link];
        for (key, name, unit, idx) in [
            ("N", "axial force N(z)", "N, N", 0),
            ("Q", "shear force Q(z)", "Q, N", 1),
            ("M", "bending moment M(z)", "M, N·m", 2),
        ] {
            let pts: Vec<(f64, f64)> = b.samples.iter().map(|s| (s.z * 1e3, [s.n, s.q, s.m][idx])).collect();
            let svg = plot(
                &format!("Link {link} ({}–{}): {name}", b.names.0, b.names.1),
                "z, mm",
                unit,
                &[Series {
                    name: key,
                    points: &pts,
                    color: "#c00000",
                }],
                200.0,
                110.0,
            );
            docs.add_text(format!("{dir}strength-{key}.svg"), svg)?;
        }
    }
    Ok(())
}
