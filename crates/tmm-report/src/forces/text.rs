//! The human tables of the `[forces]` section.

use std::fmt::Write;

use super::json::{pair_name, rel};
use super::task::ForcesTask;
use super::{Analysis, Row};
use crate::linkage::Loaded;

/// Over a machine's cycle with loads on sliders (an engine, a compressor,
/// a shaper): the slider loads along their guides and every reaction as
/// magnitude and angle (atan2(R_y, R_x) in (−180°, 180°]) at the positions.
fn cycle_tables(out: &mut String, l: &Loaded, t: &ForcesTask, a: &Analysis) {
    let m = &l.mech;
    if t.loads.sliders.is_empty() {
        return;
    }
    let _ = writeln!(
        out,
        "\nLoads on sliders along their guides over the cycle (N; + along the guide's direction; ψ the angle of the machine's cycle):"
    );
    let mut head = format!("  {:>5} {:>9} {:>9}", "pos", "ψ, °", "φ, °");
    for (k, s) in t.loads.sliders.iter().enumerate() {
        let name = t.slider_fields.get(k).map_or("?", |s| s.as_str());
        head.push_str(&format!(" {:>22}", format!("{name} on {}", m.link_names[s.link])));
    }
    let _ = writeln!(out, "{head}");
    for r in &a.rows {
        let mut line = format!(
            "  {:>5} {:>9.3} {:>9.3}",
            r.label,
            r.fs.cycle_angle.to_degrees(),
            r.phi.to_degrees()
        );
        for (k, s) in t.loads.sliders.iter().enumerate() {
            let dir = slider_dir(m, s.link);
            line.push_str(&format!(" {:>22.3}", r.fs.slider_forces.get(k).map_or(0.0, |f| f.dot(dir))));
        }
        let _ = writeln!(out, "{line}");
    }
    let _ = writeln!(
        out,
        "\nReactions over the cycle: |R|, N and its angle, ° (force of `from` on `on`):"
    );
    let mut head = format!("  {:>5} {:>9}", "pos", "ψ, °");
    for x in &a.detail.fs.reactions {
        // R_ij: the force on link i by link j, 0 the frame (the course's notation)
        let n = |i: usize| if i == 0 { "0" } else { m.link_names[i].as_str() };
        let name = format!("R{}{}", n(x.on), n(x.from));
        head.push_str(&format!(" {:>10} {:>8}", format!("|{name}|"), "∠"));
    }
    let _ = writeln!(out, "{head}");
    for r in &a.rows {
        let mut line = format!("  {:>5} {:>9.3}", r.label, r.fs.cycle_angle.to_degrees());
        for x in &r.fs.reactions {
            line.push_str(&format!(
                " {:>10.3} {:>8.2}",
                x.force.hypot(),
                x.force.y.atan2(x.force.x).to_degrees()
            ));
        }
        let _ = writeln!(out, "{line}");
    }
}

/// Where each windowed stroke force starts and stops acting (the shaper's
/// overrun: the book's φ′, φ″ and Δφ_пер).
fn windows(out: &mut String, l: &Loaded, t: &ForcesTask, a: &Analysis) {
    let m = &l.mech;
    for w in &a.windows {
        let name = t.slider_fields.get(w.load).map_or("?", |s| s.as_str());
        let link = t.loads.sliders.get(w.load).map_or("?", |s| m.link_names[s.link].as_str());
        let _ = writeln!(
            out,
            "\n{name} on {link}: acts within {:.4}…{:.4} of the stroke H = {:.6} m ({:.6}…{:.6} m), the acting stroke starting at crank angle {:.4}°. Crank angles from that start, in the direction of rotation: it starts acting at φ′ = {:.4}°, stops at {:.4}°; returning, the slider passes {:.6} m again at φ″ = {:.4}°; the crank turns Δφ = φ′ + (360° − φ″) = {:.4}° with the slider within the first {:.6} m",
            w.window.0,
            w.window.1,
            w.stroke,
            w.window.0 * w.stroke,
            w.window.1 * w.stroke,
            tmm_geom::angle::wrap_2pi(w.phi_start).to_degrees(),
            w.on.to_degrees(),
            w.off.to_degrees(),
            w.window.0 * w.stroke,
            w.back.to_degrees(),
            w.overrun.to_degrees(),
            w.window.0 * w.stroke,
        );
    }
}

/// The unit direction of a slider's frame guide (x when it has none).
fn slider_dir(m: &tmm_linkage::Mechanism, link: usize) -> tmm_geom::Vec2 {
    m.pairs
        .iter()
        .find_map(|p| match *p {
            tmm_linkage::mechanism::Pair::P { slider, guide: 0, d, .. } if slider == link => Some(d * (1.0 / d.hypot())),
            _ => None,
        })
        .unwrap_or(tmm_geom::Vec2::new(1.0, 0.0))
}

fn position(out: &mut String, l: &Loaded, r: &Row) {
    let m = &l.mech;
    let f = &r.fs;
    let _ = writeln!(
        out,
        "\nPosition {} — φ = {:.3}° ({} {:.3}°); ω1 = {:.4} rad/s, ε1 = {:.3} rad/s²",
        r.label,
        r.phi.to_degrees(),
        if r.machine_cycle {
            "the angle of the machine's cycle"
        } else {
            "crank travel from the start of the working stroke"
        },
        r.psi.to_degrees(),
        r.sol.links[m.crank.link].omega,
        r.sol.links[m.crank.link].eps
    );
    if let Some(p) = f.phase {
        let _ = writeln!(
            out,
            "  {} stroke; useful resistance {}",
            if p.working { "working" } else { "return" },
            f.resistance.iter().map(|v| format!("{v:.3}")).collect::<Vec<_>>().join(", ")
        );
    }
    let _ = writeln!(out, "  Loads on the links (at the centre of mass S):");
    let _ = writeln!(
        out,
        "  {:>6} {:>12} {:>12} {:>12} {:>12} {:>12} {:>12}",
        "link", "Fu, N", "Mu, N·m", "G, N", "ΣFx, N", "ΣFy, N", "ΣM_S, N·m"
    );
    for (i, lf) in f.links.iter().enumerate().skip(1) {
        let _ = writeln!(
            out,
            "  {:>6} {:>12.3} {:>12.4} {:>12.3} {:>12.3} {:>12.3} {:>12.4}",
            m.link_names[i],
            lf.inertia_force.hypot(),
            lf.inertia_moment,
            lf.weight.hypot(),
            lf.force.x,
            lf.force.y,
            lf.moment
        );
    }
    let _ = writeln!(
        out,
        "  Reactions, group by group from the last (force of link `from` on link `on`; R^n along the axis of `on`, R^τ across it):"
    );
    let _ = writeln!(
        out,
        "  {:>6} {:>4} {:>9} {:>12} {:>12} {:>12} {:>12} {:>12} {:>10}",
        "pair", "kind", "from→on", "Rx, N", "Ry, N", "|R|, N", "R^n, N", "R^τ, N", "shift, mm"
    );
    let mut order: Vec<usize> = Vec::new();
    for g in m.groups.iter().rev() {
        order.extend(g.info.pair_ids.iter().copied());
    }
    let rest: Vec<usize> = (0..m.pairs.len()).filter(|p| !order.contains(p)).collect();
    order.extend(rest);
    for p in order {
        let x = &f.reactions[p];
        let _ = writeln!(
            out,
            "  {:>6} {:>4} {:>9} {:>12.3} {:>12.3} {:>12.3} {:>12.3} {:>12.3} {:>10}",
            pair_name(l, p),
            if x.prismatic { "P" } else { "R" },
            format!("{}→{}", m.link_names[x.from], m.link_names[x.on]),
            x.force.x,
            x.force.y,
            x.force.hypot(),
            x.normal,
            x.tangential,
            if x.prismatic {
                format!("{:.3}", x.offset * 1e3)
            } else {
                "—".into()
            }
        );
    }
    let _ = writeln!(
        out,
        "  Balancing torque on the input link (kinetostatics): M_b = {:.4} N·m",
        f.balancing_moment
    );
    let _ = writeln!(
        out,
        "  Balancing force at the crank pin ⟂ crank:            P_b = {:.4} N",
        f.balancing_force
    );
    let _ = writeln!(
        out,
        "  Balancing torque by Zhukovsky's lever:               M_Zh = {:.4} N·m  (relative difference {:.2e})",
        f.zhukovsky_moment,
        f.relative_difference()
    );
}

/// Whether the task gives a sliding friction force on a slider
/// (`[[forces.friction]]`): the assumptions then say that friction is
/// neglected only in the pairs, not everywhere.
pub(crate) fn has_friction(t: &ForcesTask) -> bool {
    t.loads
        .sliders
        .iter()
        .any(|s| matches!(s.kind, tmm_linkage::forces::SliderLoadKind::Friction { .. }))
}

/// The report.
pub fn report(l: &Loaded, t: &ForcesTask, a: &Analysis) -> String {
    let m = &l.mech;
    let mut out = String::new();
    let _ = writeln!(out, "Kinetostatics (force analysis) — {}", m.structure.formula);
    let friction = if has_friction(t) {
        "Friction neglected in the pairs, the given sliding friction on the guides taken"
    } else {
        "Friction neglected"
    };
    match t.crank_motion {
        super::CrankMotion::Constant => {
            let _ = writeln!(
                out,
                "{friction}; rigid links, no clearances (seed 000, assumptions 1.1–1.4). ω1 = {:.4} rad/s constant.",
                m.crank.omega
            );
        }
        super::CrankMotion::Dynamics => {
            let _ = writeln!(
                out,
                "{friction}; rigid links, no clearances (seed 000, assumptions 1.1–1.4). The crank moves with its true ω1(φ), ε1(φ) from [dynamics] (nominal ω1 = {:.4} rad/s); the balancing torque is the drive's M_d less the inertia torque of the flywheel and the other constant masses on the crank shaft.",
                m.crank.omega
            );
        }
    }
    if t.loads.gravity.hypot() > 0.0 {
        let _ = writeln!(out, "Gravity g = ({:.4}, {:.4}) m/s².", t.loads.gravity.x, t.loads.gravity.y);
        if let Some(w) = a.flywheel_weight {
            let _ = writeln!(
                out,
                "The flywheel's weight G = m·g = {w:.3} N (its mass from [dynamics]) acts at the crank's pivot: it is in the frame's reaction on the crank."
            );
        }
    } else {
        let _ = writeln!(out, "Weights neglected (no gravity given).");
    }
    let _ = writeln!(
        out,
        "\n  {:>6} {:>10} {:>12} {:>20}",
        "link", "m, kg", "J_S, kg·m²", "S (local), mm"
    );
    for (i, ld) in t.loads.links.iter().enumerate().skip(1) {
        let s = m.mass_centers[i];
        let _ = writeln!(
            out,
            "  {:>6} {:>10.4} {:>12.6} {:>20}",
            m.link_names[i],
            ld.mass,
            ld.inertia,
            format!("({:.1}, {:.1})", s.x * 1e3, s.y * 1e3)
        );
    }
    position(&mut out, l, &a.detail);
    let _ = writeln!(out, "\nBalancing torque at the {} positions:", a.rows.len());
    let _ = writeln!(
        out,
        "  {:>5} {:>10} {:>14} {:>14} {:>14} {:>10} {:>14}",
        "pos", "φ, °", "M_b, N·m", "P_b, N", "M_Zh, N·m", "rel.diff", "max |R|, N"
    );
    for r in &a.rows {
        let f = &r.fs;
        let rmax = f.reactions.iter().map(|x| x.force.hypot()).fold(0.0, f64::max);
        let _ = writeln!(
            out,
            "  {:>5} {:>10.3} {:>14.4} {:>14.4} {:>14.4} {:>10.2e} {:>14.3}",
            r.label,
            r.phi.to_degrees(),
            f.balancing_moment,
            f.balancing_force,
            f.zhukovsky_moment,
            f.relative_difference(),
            rmax
        );
    }
    cycle_tables(&mut out, l, t, a);
    windows(&mut out, l, t, a);
    if let Some(rc) = &a.reaction_cycle {
        rc.text(&mut out);
    }
    let max_diff = a.curve.iter().map(|c| rel(c[2], c[3])).fold(0.0, f64::max);
    let (mn, mx) = a
        .curve
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), c| (a.min(c[2]), b.max(c[2])));
    let mean = a.curve[..a.curve.len() - 1].iter().map(|c| c[2]).sum::<f64>() / (a.curve.len() - 1) as f64;
    let _ = writeln!(
        out,
        "Over the cycle (1° steps): M_b from {mn:.4} to {mx:.4} N·m, mean {mean:.4} N·m; kinetostatics and Zhukovsky's lever differ by at most {max_diff:.2e} (relative)."
    );
    if let Some(b) = &a.beam {
        let s = &b.sizes;
        let _ = writeln!(
            out,
            "\nStrength of link {} as a beam {}–{} (L = {:.2} mm) at φ = {:.3}°:",
            m.link_names[b.beam.link],
            b.names.0,
            b.names.1,
            b.beam.length * 1e3,
            a.detail.phi.to_degrees()
        );
        let _ = writeln!(
            out,
            "  Concentrated loads (axial along {}→{}, transverse across it):",
            b.names.0, b.names.1
        );
        for x in &b.beam.loads {
            let _ = writeln!(
                out,
                "  {:>30} z = {:>9.3} mm  N-dir {:>11.4} N  Q-dir {:>11.4} N  couple {:>10.5} N·m",
                x.label,
                x.z * 1e3,
                x.fe,
                x.fn_,
                x.couple
            );
        }
        let _ = writeln!(
            out,
            "  Distributed weight and inertia: q_axial = {:.4} + {:.4}·z + {:.4}·z² N/m, q_transverse = {:.4} + {:.4}·z + {:.4}·z² N/m",
            b.beam.qe[0], b.beam.qe[1], b.beam.qe[2], b.beam.qn[0], b.beam.qn[1], b.beam.qn[2]
        );
        let _ = writeln!(out, "  {:>10} {:>12} {:>12} {:>12}", "z, mm", "N, N", "Q, N", "M, N·m");
        let step = (b.samples.len() / 20).max(1);
        for (i, x) in b.samples.iter().enumerate() {
            if i % step == 0 || i + 1 == b.samples.len() {
                let _ = writeln!(out, "  {:>10.3} {:>12.4} {:>12.4} {:>12.5}", x.z * 1e3, x.n, x.q, x.m);
            }
        }
        let z = |i: usize| b.samples.get(i).map_or(f64::NAN, |x| x.z * 1e3);
        let _ = writeln!(out, "  [σ] = {:.1} MPa, σ = |N|/A + |M|/W:", b.allowed / 1e6);
        let _ = writeln!(
            out,
            "  round bar:           d = {:.3} mm (dangerous section z = {:.3} mm)",
            s.round_d * 1e3,
            z(s.round_at)
        );
        let _ = writeln!(
            out,
            "  rectangle h = {:.2}·b: b = {:.3} mm, h = {:.3} mm (dangerous section z = {:.3} mm)",
            b.k,
            s.rect_b * 1e3,
            s.rect_h * 1e3,
            z(s.rect_at)
        );
        match s.ibeam {
            Some((ib, i, sig)) => {
                let _ = writeln!(
                    out,
                    "  I-section GOST 8239-89 No. {} (σ = {:.2} MPa at z = {:.3} mm)",
                    ib.number,
                    sig / 1e6,
                    z(i)
                );
            }
            None => {
                let _ = writeln!(out, "  no I-section of the table (No. 10…30) holds");
            }
        }
    }
    out
}
