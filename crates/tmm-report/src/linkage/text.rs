//! Human tables of the `[linkage]` section.

use std::fmt::Write as _;

use tmm_linkage::cycle::{Cycle, OutputKind};
use tmm_linkage::ranges::PartialCycle;

use super::{Analysis, Loaded};

/// The report: structure, cycle, the positions table and the velocities of
/// every point at the plan position.
pub fn report(l: &Loaded, a: &Analysis) -> String {
    if let Some(t) = a.travel {
        return super::travel::report(l, a, t);
    }
    let mut o = structure(l);
    crank_tables(&mut o, l, a);
    o
}

/// The structure (n, p5, W, the formula, the groups, the class) and the
/// geometry as analysed.
pub(super) fn structure(l: &Loaded) -> String {
    let m = &l.mech;
    let s = &m.structure;
    let mut o = String::new();
    let _ = writeln!(o, "LEVER MECHANISM — structure (структурный анализ)");
    let _ = writeln!(
        o,
        "  n = {}, p5 = {}, p4 = {}; W = 3·{} − 2·{} − {} = {}",
        s.n, s.p5, s.p4, s.n, s.p5, s.p4, s.dof
    );
    if s.redundant != 0 || s.passive != 0 || s.dof_rank != s.dof {
        let _ = writeln!(
            o,
            "  by rank: DOF = {}, redundant constraints q = {}, passive freedoms = {}",
            s.dof_rank, s.redundant, s.passive
        );
    }
    let _ = writeln!(o, "  structure formula: {}", s.formula);
    for g in &s.groups {
        let _ = writeln!(
            o,
            "  group ({}): class {}, order {}, kind {}",
            g.links.join(","),
            tmm_linkage::structure::roman(g.class),
            g.order,
            g.kind
        );
    }
    let _ = writeln!(o, "  class of the mechanism: {}", tmm_linkage::structure::roman(s.class));
    geometry(&mut o, l);
    o
}

/// The cycle, the positions and the points of a crank-driven mechanism.
fn crank_tables(o: &mut String, l: &Loaded, a: &Analysis) {
    let m = &l.mech;
    let out = a.reading.output;
    let unit = if out.kind == OutputKind::Linear { "m" } else { "rad" };
    let _ = writeln!(
        o,
        "\nCYCLE — output link `{}` ({})",
        m.link_names[out.link],
        if out.kind == OutputKind::Linear {
            "travel along its guide"
        } else {
            "angle"
        }
    );
    if let Some(c) = &a.cycle {
        full_cycle(o, c);
    }
    if let Some(p) = &a.partial {
        partial_cycle(o, p, out.kind);
    }
    for &(p, v, phi) in &a.pressure_max {
        let _ = writeln!(
            o,
            "  max pressure angle at {}: ϑ = {:.3}° (γ = {:.3}°) at φ = {:.2}°",
            m.points[p].name,
            v.to_degrees(),
            90.0 - v.to_degrees(),
            phi.to_degrees()
        );
    }
    let _ = writeln!(o, "\nPOSITIONS (φ absolute, ψ from the start; s in {unit})");
    let mut head = format!(
        "  {:>4} {:>9} {:>9} {:>11} {:>11} {:>12}",
        "pos", "φ,°", "ψ,°", "s", "ds/dφ", "d²s/dφ²"
    );
    for n in m.link_names.iter().skip(1) {
        let _ = write!(head, " {:>10} {:>11}", format!("ω{n}"), format!("ε{n}"));
    }
    let _ = writeln!(o, "{head}");
    for r in &a.rows {
        let mut line = format!(
            "  {:>4} {:>9.3} {:>9.3} {:>11.6} {:>11.6} {:>12.6}",
            r.pos.label,
            r.pos.phi.to_degrees(),
            r.pos.psi.to_degrees(),
            r.analogs.0,
            r.analogs.1,
            r.analogs.2
        );
        for i in 1..m.link_names.len() {
            let _ = write!(line, " {:>10.4} {:>11.3}", r.sol.links[i].omega, r.sol.links[i].eps);
        }
        let _ = writeln!(o, "{line}");
    }
    let r = &a.plan_row;
    let _ = writeln!(o, "\nPOINTS at φ = {:.4}° (m, m/s, m/s²)", r.pos.phi.to_degrees());
    points_table(o, l, r);
}

/// Every point's position, speed, acceleration and pressure angle at one row.
pub(super) fn points_table(o: &mut String, l: &Loaded, r: &super::Row) {
    let m = &l.mech;
    let _ = writeln!(
        o,
        "  {:>6} {:>10} {:>10} {:>10} {:>11} {:>11}",
        "point", "x", "y", "|v|", "|a|", "ϑ,°"
    );
    for (i, p) in m.points.iter().enumerate() {
        let s = &r.sol.points[i];
        let pa = r
            .pressure
            .iter()
            .find(|x| x.0 == i)
            .map(|x| format!("{:.3}", x.1.to_degrees()))
            .unwrap_or_default();
        let _ = writeln!(
            o,
            "  {:>6} {:>10.5} {:>10.5} {:>10.5} {:>11.4} {:>11}",
            p.name,
            s.p.x,
            s.p.y,
            s.v.hypot(),
            s.a.hypot(),
            pa
        );
    }
}

/// The dead positions, Kv and stroke of a full turn.
fn full_cycle(o: &mut String, c: &Cycle) {
    if c.dead.is_empty() {
        let _ = writeln!(o, "  the output turns fully: no dead positions");
    } else {
        let _ = writeln!(
            o,
            "  dead positions: φ = {:.6}° (start of the working stroke), {:.6}°",
            c.dead[0].to_degrees(),
            c.dead[1].to_degrees()
        );
        let _ = writeln!(
            o,
            "  working stroke {:.4}°, return {:.4}°, θ = {:.4}°, Kv = {:.5}",
            c.working_angle.to_degrees(),
            c.return_angle.to_degrees(),
            c.theta.to_degrees(),
            c.kv
        );
        let stroke = if c.output.kind == OutputKind::Linear {
            format!("{:.6} m", c.stroke)
        } else {
            format!("{:.6} rad = {:.4}°", c.stroke, c.stroke.to_degrees())
        };
        let _ = writeln!(o, "  stroke of the output: {stroke}");
    }
}

/// The assembly ranges and gaps, with the output's extremes on each range.
fn partial_cycle(o: &mut String, p: &PartialCycle, kind: OutputKind) {
    let _ = writeln!(
        o,
        "  the crank cannot turn fully: analysed over the crank angles where the mechanism assembles (range = \"partial\")"
    );
    let val = |x: f64| {
        if kind == OutputKind::Linear {
            format!("{x:.6} m")
        } else {
            format!("{:.4}°", x.to_degrees())
        }
    };
    for (i, r) in p.ranges.iter().enumerate() {
        let _ = writeln!(
            o,
            "  range {}: φ = {:.4}°…{:.4}° (span {:.4}°); output from {} to {}",
            i + 1,
            r.range.from.to_degrees(),
            r.range.to.to_degrees(),
            r.range.span().to_degrees(),
            val(r.s_min),
            val(r.s_max)
        );
        if !r.dead.is_empty() {
            let d: Vec<String> = r.dead.iter().map(|x| format!("{:.4}°", x.to_degrees())).collect();
            let _ = writeln!(o, "    dead positions of the output inside it: φ = {}", d.join(", "));
        }
    }
    for (i, g) in p.map.gaps.iter().enumerate() {
        let _ = writeln!(
            o,
            "  gap {}: φ = {:.4}°…{:.4}° (span {:.4}°): does not assemble",
            i + 1,
            g.from.to_degrees(),
            g.to.to_degrees(),
            g.span().to_degrees()
        );
    }
    if let Some(why) = &p.map.reason {
        let _ = writeln!(o, "  at the gaps: {why}");
    }
}

/// The geometry as analysed: every link's lengths (the distance between
/// every two of its points), the frame's, and the crank's speed with the
/// time of one turn T = 2π/|ω1| = 60/n1.
fn geometry(o: &mut String, l: &Loaded) {
    let _ = writeln!(o, "\nGEOMETRY (m)");
    let pairwise = |pts: &[(String, tmm_geom::Vec2)]| -> Vec<String> {
        let mut v = Vec::new();
        for (i, (a, pa)) in pts.iter().enumerate() {
            for (b, pb) in &pts[i + 1..] {
                v.push(format!("l_{a}{b} = {:.6}", (*pb - *pa).hypot()));
            }
        }
        v
    };
    for k in &l.def.links {
        let v = pairwise(&k.points);
        if !v.is_empty() {
            let _ = writeln!(o, "  link {}: {}", k.name, v.join(", "));
        }
    }
    let v = pairwise(&l.def.fixed);
    if !v.is_empty() {
        let _ = writeln!(o, "  frame: {}", v.join(", "));
    }
    let w = l.mech.crank.omega.abs();
    if w > 0.0 && l.mech.drive.is_none() {
        let t = std::f64::consts::TAU / w;
        let _ = writeln!(
            o,
            "  crank: |ω1| = {w:.6} rad/s, n1 = {:.4} rpm, one turn T = 60/n1 = {t:.6} s",
            60.0 / t
        );
    }
}
