//! Human tables of a gear pair (millimetres and degrees for reading).

use std::fmt::Write as _;

use tmm_gears::{CheckKind, Kind, Limits, Pair};

use super::solve::Solved;

fn mm(v: f64) -> String {
    format!("{:.4}", v * 1e3)
}

/// The pair as text: input, geometry, quality checks, sliding table.
pub fn pair_text(s: &Solved, lim: &Limits) -> String {
    let p: &Pair = &s.pair;
    let sp = &p.spec;
    let mut t = String::new();
    let kind = if sp.kind == Kind::Internal {
        "internal (wheel 2 is a ring)"
    } else {
        "external"
    };
    let _ = writeln!(
        t,
        "Gear pair, {kind}: z1 = {}, z2 = {}, m = {} mm, x1 = {:.4}, x2 = {:.4}",
        sp.z1,
        sp.z2,
        mm(sp.m),
        sp.x1,
        sp.x2
    );
    let _ = writeln!(
        t,
        "Basic rack: α = {:.3}°, ha* = {}, c* = {}, hl* = {:.4}, ρf* = {:.3}",
        sp.rack.alpha.to_degrees(),
        sp.rack.ha,
        sp.rack.c,
        sp.rack.hl,
        sp.rack.fillet_radius()
    );
    if s.fillet.reduced {
        let _ = writeln!(
            t,
            "  The nominal tip fillet ρf* = {:.3} does not fit this rack: the largest that fits, ρf* = {:.3}, is used (hl* = {:.3}).",
            s.fillet.rho_f_nominal, s.fillet.rho_f, sp.rack.hl
        );
    }
    if let Some(c) = s.criterion {
        let _ = writeln!(
            t,
            "Shifts chosen by the criterion {}{}",
            c.name(),
            s.aw_required
                .map_or(String::new(), |a| format!(" on the line of the shift sum for aw = {} mm", mm(a)))
        );
        if let Some(r) = &s.reason {
            let _ = writeln!(t, "  ({r})");
        }
    }
    let _ = writeln!(t, "\nGeometry (GOST 16532-70)");
    let _ = writeln!(t, "  a     = {:>12} mm   reference centre distance", mm(p.a));
    let _ = writeln!(t, "  inv αw= {:>12.9}      αw = {:.4}°", p.inv_alpha_w, p.alpha_w.to_degrees());
    let _ = writeln!(t, "  aw    = {:>12} mm   centre distance", mm(p.aw));
    let _ = writeln!(t, "  y     = {:>12.5}      Δy = {:.5}", p.y, p.dy);
    let _ = writeln!(t, "  u     = {:>12.5}      p = {} mm, pb = {} mm", p.u, mm(p.p), mm(p.pb));
    let _ = writeln!(t, "  {:<28} {:>12} {:>12}", "", "wheel 1", "wheel 2");
    let row = |t: &mut String, name: &str, a: String, b: String| {
        let _ = writeln!(t, "  {name:<28} {a:>12} {b:>12}");
    };
    let (w1, w2) = (&p.w1, &p.w2);
    row(&mut t, "d, mm", mm(w1.d), mm(w2.d));
    row(&mut t, "db, mm", mm(w1.db), mm(w2.db));
    row(&mut t, "dw, mm", mm(w1.dw), mm(w2.dw));
    row(&mut t, "da, mm", mm(w1.da), mm(w2.da));
    row(&mut t, "df, mm", mm(w1.df), mm(w2.df));
    row(&mut t, "h, mm", mm(w1.h), mm(w2.h));
    row(&mut t, "s (reference circle), mm", mm(w1.s), mm(w2.s));
    row(&mut t, "sa (tip), mm", mm(w1.sa), mm(w2.sa));
    row(
        &mut t,
        "αa, °",
        format!("{:.4}", w1.alpha_a.to_degrees()),
        format!("{:.4}", w2.alpha_a.to_degrees()),
    );
    row(&mut t, "ρp (lower active point), mm", mm(w1.rho_p), mm(w2.rho_p));
    row(&mut t, "ρl (boundary point), mm", mm(w1.rho_l), mm(w2.rho_l));
    let xm = |v: Option<f64>| v.map_or("—".into(), |x| format!("{x:.5}"));
    row(&mut t, "xmin", xm(w1.xmin), xm(w2.xmin));
    let th = |v: Option<f64>, n: usize| v.map_or(format!("unbounded (contact reaches N{n})"), |x| format!("{x:.4}"));
    row(&mut t, "ϑmax (specific sliding)", th(p.theta1_max(), 1), th(p.theta2_max(), 2));
    let _ = writeln!(
        t,
        "  εα = {:.5} over the real active line{}",
        p.eps_alpha,
        if (p.eps_alpha - p.eps_alpha_gost).abs() > 1e-9 {
            format!(
                " (GOST 16532-70's tan formula gives {:.5}: it counts contact past N1/N2 or below the involute, which interference rules out)",
                p.eps_alpha_gost
            )
        } else {
            String::new()
        }
    );
    let _ = writeln!(t, "\nQuality checks");
    for c in p.checks(lim).as_slice() {
        let (v, l) = match c.kind {
            CheckKind::Interference(_) | CheckKind::RingInterference | CheckKind::Pointing(_) => {
                (format!("{} mm", mm(c.value)), format!("{} mm", mm(c.limit)))
            }
            _ => (format!("{:.5}", c.value), format!("{:.5}", c.limit)),
        };
        let _ = writeln!(
            t,
            "  {:<4} {:<52} value {v:>14}  limit {l:>14}",
            if c.pass { "ok" } else { "FAIL" },
            c.kind.describe()
        );
    }
    let _ = writeln!(t, "\nSpecific sliding along the active line (s from N1, mm)");
    let _ = writeln!(t, "  {:>10} {:>10} {:>10} {:>10}", "s=ρ1", "ρ2", "ϑ1", "ϑ2");
    for q in p.sliding_table(11) {
        let _ = writeln!(t, "  {:>10} {:>10} {:>10.4} {:>10.4}", mm(q.s), mm(q.rho2), q.theta1, q.theta2);
    }
    t
}
