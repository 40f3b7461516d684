//! The tables of a synthesis: the given data, the free parameter and why,
//! the lengths and the frame, K, θ and the stroke as requested and as the
//! linkage core finds them, the pressure and transmission angles, and the
//! table of variants of a sweep.

use std::fmt::Write as _;

use tmm_geom::units::Dim;
use tmm_linkage::synthesis::sweep::Variant;

use super::{Comparison, Solved, Spec, given_dim, show, stroke_of};

/// The tables of one synthesis.
pub fn report(s: &Solved, vars: Option<&[Variant]>, cmp: Option<&Comparison>) -> String {
    let y = &s.syn;
    let c = &y.check;
    let mut t = String::new();
    let _ = writeln!(t, "Metric synthesis: {} ({})", s.spec.kind, describe(s.spec.kind));
    t.push_str("Given:\n");
    for (n, v) in &y.given {
        // n1 (seed 000 § 1.2.3) is in revolutions per second
        let value = if n == "n1" {
            format!("{v:.4} rev/s")
        } else {
            show(given_dim(&s.spec, n), *v)
        };
        let _ = writeln!(t, "  {n:<14} {value}");
    }
    if !s.spec.speed_given {
        t.push_str("  (no input speed given: the [linkage] uses 1 rad/s)\n");
    }
    if let Some(f) = &y.free_parameter {
        let _ = writeln!(t, "Free parameter: {} = {:.6} — {}", f.name, f.value, f.reason);
    }
    t.push_str("Lengths:\n");
    for (n, v) in &y.lengths {
        let _ = writeln!(t, "  l_{n:<12} {:>12.3} mm", v * 1e3);
    }
    if !y.angles.is_empty() {
        t.push_str("Angles found:\n");
        for (n, v) in &y.angles {
            let _ = writeln!(t, "  {n:<14} {:>12.4}°", v.to_degrees());
        }
    }
    if !y.coordinates.is_empty() {
        t.push_str("Coordinates found:\n");
        for (n, v) in &y.coordinates {
            let _ = writeln!(t, "  {n:<14} {:>12.3} mm", v * 1e3);
        }
    }
    t.push_str("Frame (fixed points):\n");
    for (n, p) in &y.frame {
        let _ = writeln!(t, "  {n:<14} ({:.3}, {:.3}) mm", p.x * 1e3, p.y * 1e3);
    }
    // a lever driven by a cylinder works over its turn β only: no K
    let no_k = y.kind == tmm_linkage::synthesis::Kind::OscillatingCylinder;
    if !no_k {
        let _ = writeln!(
            t,
            "K requested {:.6}, found by the linkage core {}; θ = {}",
            y.k,
            c.k.map_or("— (the crank does not turn fully)".into(), |k| format!("{k:.9}")),
            show(Dim::Angle, y.theta)
        );
    }
    if let Some((v, dim, word)) = stroke_of(y.stroke) {
        let found = stroke_of(c.stroke).map_or("—".into(), |(f, _, _)| show(dim, f));
        let _ = writeln!(t, "{word} of the construction {}, found by the linkage core {found}", show(dim, v));
    }
    let _ = writeln!(
        t,
        "Largest pressure angle: working stroke {}, return stroke {}; smallest transmission angle {}",
        show(Dim::Angle, c.pressure_angle_max.0),
        show(Dim::Angle, c.pressure_angle_max.1),
        show(Dim::Angle, c.transmission_angle_min)
    );
    let _ = writeln!(t, "Assembly: {}", c.branch);
    let _ = writeln!(
        t,
        "Overall size (diagonal at both dead positions): {:.3} mm",
        y.overall_size() * 1e3
    );
    if let Some(c2) = cmp {
        let (dim, word) = match y.stroke {
            Some(tmm_linkage::synthesis::Stroke::Angular(_)) => (Dim::Angle, "swing"),
            _ => (Dim::Length, "stroke"),
        };
        let _ = writeln!(
            t,
            "The task's own [linkage] is analysed (it wins over the synthesis): its K = {:.6} (synthesis {:.6}, difference {:+.6}), {word} {} (synthesis {})",
            c2.k,
            y.k,
            c2.k - y.k,
            show(dim, c2.stroke),
            stroke_of(y.stroke).map_or("—".into(), |(v, _, _)| show(dim, v)),
        );
    }
    if let Some(v) = vars {
        t.push('\n');
        t.push_str(&variants(&s.spec, v));
    }
    t
}

fn describe(kind: &str) -> &'static str {
    super::task::KINDS.iter().find(|k| k.0 == kind).map_or("", |k| k.1)
}

/// The table of variants: feasible rows, then the values that fail and why.
pub fn variants(spec: &Spec, v: &[Variant]) -> String {
    let mut t = String::new();
    let param = spec.sweep.as_ref().map_or("value", |s| s.param.as_str());
    let dim = super::task::param_dim(&spec.request, param);
    let ok: Vec<_> = v.iter().filter_map(|x| x.outcome.as_ref().ok().map(|r| (x.value, r))).collect();
    let _ = writeln!(t, "Variants: {param} over {} values, {} feasible", v.len(), ok.len());
    if let Some((_, first)) = ok.first() {
        let mut head = format!("  {param:>14}");
        for (n, _) in &first.lengths {
            let _ = write!(head, " {:>11}", format!("l_{n}, mm"));
        }
        let _ = write!(
            head,
            " {:>12} {:>9} {:>9} {:>9} {:>10}",
            "K found", "ϑw, °", "ϑr, °", "γmin, °", "size, mm"
        );
        t.push_str(&head);
        t.push('\n');
        for (val, r) in &ok {
            let mut row = format!("  {:>14}", show(dim, *val));
            for (_, l) in &r.lengths {
                let _ = write!(row, " {:>11.3}", l * 1e3);
            }
            let _ = write!(
                row,
                " {:>12} {:>9.3} {:>9.3} {:>9.3} {:>10.3}",
                r.k.map_or("—".into(), |k| format!("{k:.9}")),
                r.pressure_angle_max.0.to_degrees(),
                r.pressure_angle_max.1.to_degrees(),
                r.transmission_angle_min.to_degrees(),
                r.size * 1e3
            );
            t.push_str(&row);
            t.push('\n');
        }
    }
    let bad: Vec<_> = v.iter().filter_map(|x| x.outcome.as_ref().err().map(|e| (x.value, e))).collect();
    if !bad.is_empty() {
        t.push_str("Infeasible values:\n");
        for (val, e) in bad {
            let _ = writeln!(t, "  {:>14}: {e}", show(dim, val));
        }
    }
    t
}
