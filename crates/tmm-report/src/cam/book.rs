//! The textbook's constructions beside the design (`book_methods = true`,
//! `--book-methods`): the tangent methods of a translating follower, the
//! level lines of an oscillating one, the roller rules — as a JSON object
//! (SI, rad) under `cam.book` and as tables (mm, degrees).

use std::fmt::Write as _;

use serde_json::{Map, Value, json};
use tmm_cams::design::{CamDesign, CamTask};
use tmm_cams::levels;
use tmm_cams::roller_rules::RollerCheck;
use tmm_cams::tangents::{self, Centre};
use tmm_cams::textbook::{BookMethods, Checked, PressureRange};
use tmm_geom::Vec2;

use crate::output::num;

fn pressure(m: &mut Map<String, Value>, p: &PressureRange, task: &CamTask) {
    m.insert("pressure_rise_min".into(), num(p.rise.0));
    m.insert("pressure_rise_max".into(), num(p.rise.1));
    m.insert("pressure_return_min".into(), num(p.ret.0));
    m.insert("pressure_return_max".into(), num(p.ret.1));
    m.insert("limit_excess".into(), num(p.excess(task.limits.rise, task.limits.ret)));
}

fn centre(c: &Checked<Centre>, task: &CamTask) -> Value {
    let mut m = Map::new();
    m.insert("e".into(), num(c.centre.e));
    m.insert("e_book".into(), num(-c.centre.e));
    m.insert("s0".into(), num(c.centre.s0));
    m.insert("r0".into(), num(c.centre.r0()));
    pressure(&mut m, &c.pressure, task);
    Value::Object(m)
}

fn point(c: &Checked<Vec2>, arm: f64, task: &CamTask) -> Value {
    let (a, f) = levels::distance_and_angle(c.centre);
    let mut m = Map::new();
    m.insert("x".into(), num(c.centre.x));
    m.insert("y".into(), num(c.centre.y));
    m.insert("centre_distance".into(), num(a));
    m.insert("initial_angle".into(), num(f));
    // the knife edge's lowest point B₀ = (l, 0): r₀ = |O B₀|
    m.insert("r0".into(), num((c.centre - Vec2::new(arm, 0.0)).hypot()));
    pressure(&mut m, &c.pressure, task);
    Value::Object(m)
}

fn rules(r: &RollerCheck) -> Value {
    json!({
        "roller": num(r.roller),
        "range_low": num(r.low),
        "range_high": num(r.high),
        "in_range": r.in_range(),
        "above_range_low": r.above_low(),
        "below_range_high": r.below_high(),
        "rho_min_pitch": if r.rho_pitch.is_finite() { num(r.rho_pitch) } else { Value::Null },
        "rho_bound": if r.rho_bound.is_finite() { num(r.rho_bound) } else { Value::Null },
        "below_rho_bound": r.below_rho_bound(),
        "below_rho_min": r.below_rho(),
    })
}

fn rel(a: f64, b: f64) -> Value {
    if b != 0.0 { num((a - b) / b) } else { Value::Null }
}

/// The `cam.book` object.
pub fn json(task: &CamTask, d: &CamDesign, b: &BookMethods) -> Value {
    let prog = &task.program;
    let sigma = task.rotation.sign();
    let mut m = Map::new();
    m.insert("source".into(), "Chernaya, Timofeev, BMSTU 2019, appendix П6".into());
    if let Some(t) = &b.translating {
        let s = &t.sizing;
        let (dr, de) = s.deltas();
        m.insert("method".into(), "tangents".into());
        m.insert("phi_speed_rise".into(), num(s.speed_rise));
        m.insert("phi_speed_return".into(), num(s.speed_return));
        m.insert("approximate".into(), centre(&t.approximate, task));
        m.insert("phi_tangent_rise".into(), num(s.tangent_rise));
        m.insert("phi_tangent_return".into(), num(s.tangent_return));
        let mut m1 = centre(&t.method1, task);
        if let Some(o) = m1.as_object_mut() {
            o.insert("X".into(), num(s.method1_xy.0));
            o.insert("Y".into(), num(s.method1_xy.1));
        }
        m.insert("method_1".into(), m1);
        m.insert("method_2".into(), centre(&t.method2, task));
        m.insert("delta_r".into(), num(dr));
        m.insert("delta_e".into(), num(de));
        m.insert("exact".into(), centre(&t.exact, task));
        m.insert("r0_vs_exact".into(), rel(t.method1.centre.r0(), t.exact.centre.r0()));
        m.insert("e_vs_exact".into(), rel(t.method1.centre.e, t.exact.centre.e));
        m.insert("s0_vs_exact".into(), rel(t.method1.centre.s0, t.exact.centre.s0));
        m.insert(
            "rho_min_pitch_book".into(),
            if t.rho_pitch_book.is_finite() {
                num(t.rho_pitch_book)
            } else {
                Value::Null
            },
        );
        let c = t.method1.centre;
        m.insert(
            "theta".into(),
            Value::Array(
                d.profile
                    .phi
                    .iter()
                    .map(|&p| num(tangents::signed_pressure(prog, sigma, c, p)))
                    .collect(),
            ),
        );
    }
    if let Some(o) = &b.oscillating {
        let l = &o.levels;
        m.insert("method".into(), "level-lines".into());
        m.insert("arm".into(), num(o.arm));
        m.insert("phi_speed_rise".into(), num(l.speed_rise));
        m.insert("phi_speed_return".into(), num(l.speed_return));
        m.insert("point_1".into(), json!([num(l.point1.x), num(l.point1.y)]));
        m.insert("phi_v_min".into(), num(l.level_rise));
        m.insert("phi_v_max".into(), num(l.level_return));
        m.insert("x_v_min".into(), num(l.level_values.0));
        m.insert("x_v_max".into(), num(l.level_values.1));
        m.insert("point_2".into(), point(&o.point2, o.arm, task));
        m.insert("vertex".into(), point(&o.vertex, o.arm, task));
        m.insert("vertex_passes".into(), l.passes.into());
        m.insert("exact".into(), point(&o.exact, o.arm, task));
        let (a2, _) = levels::distance_and_angle(o.point2.centre);
        let (ax, _) = levels::distance_and_angle(o.exact.centre);
        m.insert("centre_distance_vs_exact".into(), rel(a2, ax));
        let r0 = |p: Vec2| (p - Vec2::new(o.arm, 0.0)).hypot();
        m.insert("r0_vs_exact".into(), rel(r0(o.point2.centre), r0(o.exact.centre)));
        let c = o.point2.centre;
        m.insert(
            "theta".into(),
            Value::Array(
                d.profile
                    .phi
                    .iter()
                    .map(|&p| num(levels::signed_pressure(prog, sigma, 1.0, o.arm, c, p)))
                    .collect(),
            ),
        );
    }
    m.insert("roller_rules".into(), b.roller.as_ref().map_or(Value::Null, rules));
    m.insert("roller_rules_book".into(), b.roller_book.as_ref().map_or(Value::Null, rules));
    Value::Object(m)
}

fn range(p: (f64, f64)) -> String {
    format!("{:.3}…{:.3}", p.0.to_degrees(), p.1.to_degrees())
}

fn rules_text(t: &mut String, what: &str, r: &RollerCheck) {
    let yes = |b: bool| if b { "yes" } else { "NO" };
    let _ = writeln!(
        t,
        "  roller {:.3} mm with {what}: 0.25·r0…0.40·r0 = {:.3}…{:.3} mm: {} (≥ 0.25·r0 {}, ≤ 0.40·r0 {}); 0.8·ρmin of the pitch curve = {:.3} mm: below {}; below ρmin = {:.3} mm {}",
        r.roller * 1e3,
        r.low * 1e3,
        r.high * 1e3,
        yes(r.in_range()),
        yes(r.above_low()),
        yes(r.below_high()),
        r.rho_bound * 1e3,
        yes(r.below_rho_bound()),
        r.rho_pitch * 1e3,
        yes(r.below_rho())
    );
}

/// θ(φ) of the book's centre every 15° of the working phases, six to a row.
fn theta_rows(t: &mut String, what: &str, task: &CamTask, theta: impl Fn(f64) -> f64) {
    let _ = writeln!(t, "  θ(φ) at {what}, signed (positive on the rise's driving side), °:");
    let prog = &task.program;
    let cells: Vec<String> = (0..24)
        .map(|i| (i * 15) as f64)
        .filter(|&deg| {
            let p = deg.to_radians();
            prog.phases()[prog.phase_at(p)].kind != tmm_cams::program::PhaseKind::Dwell
        })
        .map(|deg| format!("{deg:>5.0}: {:>8.3}", theta(deg.to_radians()).to_degrees()))
        .collect();
    for row in cells.chunks(6) {
        let _ = writeln!(t, "   {}", row.join("  "));
    }
}

/// The tables.
pub fn text(task: &CamTask, b: &BookMethods) -> String {
    let mut t = String::new();
    let prog = &task.program;
    let sigma = task.rotation.sign();
    let (lr, lt) = (task.limits.rise.to_degrees(), task.limits.ret.to_degrees());
    if let Some(x) = &b.translating {
        let s = &x.sizing;
        let _ = writeln!(
            t,
            "\nThe textbook's sizing by the tangents to the s–ds/dφ diagram (BMSTU 2019, П6.4), ϑ allowed {lr:.3}° rise, {lt:.3}° return"
        );
        let _ = writeln!(
            t,
            "  largest |ds/dφ| at φ = {:.4}° (rise), {:.4}° (return); rays touch the diagram at φ = {:.4}° (rise), {:.4}° (return)",
            s.speed_rise.to_degrees(),
            s.speed_return.to_degrees(),
            s.tangent_rise.to_degrees(),
            s.tangent_return.to_degrees()
        );
        let _ = writeln!(
            t,
            "  {:<34} {:>9} {:>9} {:>9} {:>18} {:>18} {:>9}",
            "centre", "e mm", "s0 mm", "r0 mm", "ϑ rise °", "ϑ return °", "over °"
        );
        for (name, c) in [
            ("step 1, largest-speed points", &x.approximate),
            ("method 1, tangents intersected", &x.method1),
            ("method 2, equations at tangency", &x.method2),
            ("tmm, both sides bounded", &x.exact),
        ] {
            let _ = writeln!(
                t,
                "  {:<34} {:>9.4} {:>9.4} {:>9.4} {:>18} {:>18} {:>9.4}",
                name,
                c.centre.e * 1e3,
                c.centre.s0 * 1e3,
                c.centre.r0() * 1e3,
                range(c.pressure.rise),
                range(c.pressure.ret),
                c.pressure.excess(task.limits.rise, task.limits.ret).to_degrees()
            );
        }
        let (dr, de) = s.deltas();
        let _ = writeln!(
            t,
            "  method 1 on the diagram: X = e_book = {:.4} mm, Y = −s0 = {:.4} mm (the book's e is −e)",
            s.method1_xy.0 * 1e3,
            s.method1_xy.1 * 1e3
        );
        let _ = writeln!(
            t,
            "  Δr = (r0 − r0пр)/r0 = {:.4} %, Δe = (e − eпр)/e = {:.4} %",
            dr * 100.0,
            de * 100.0
        );
        let c = x.method1.centre;
        theta_rows(&mut t, "the book's centre (method 1)", task, |p| {
            tangents::signed_pressure(prog, sigma, c, p)
        });
        let (r1, rx) = (x.method1.centre.r0(), x.exact.centre.r0());
        let _ = writeln!(
            t,
            "  the book's r0 against tmm's: {:.4} mm vs {:.4} mm ({:+.4} %); e {:.4} vs {:.4} mm",
            r1 * 1e3,
            rx * 1e3,
            (r1 - rx) / rx * 100.0,
            x.method1.centre.e * 1e3,
            x.exact.centre.e * 1e3
        );
    }
    if let Some(o) = &b.oscillating {
        let l = &o.levels;
        let _ = writeln!(
            t,
            "\nThe textbook's level-line method for the oscillating follower (BMSTU 2019, П6.5), pivot A at the origin, arm {:.3} mm along +x",
            o.arm * 1e3
        );
        let _ = writeln!(
            t,
            "  largest |ds/dφ| at φ = {:.4}° (rise), {:.4}° (return); point 1 = ({:.4}, {:.4}) mm",
            l.speed_rise.to_degrees(),
            l.speed_return.to_degrees(),
            l.point1.x * 1e3,
            l.point1.y * 1e3
        );
        let _ = writeln!(
            t,
            "  level line through point 1: φVmin = {:.4}° (XV = {:.4} mm), φVmax = {:.4}° (XV = {:.4} mm)",
            l.level_rise.to_degrees(),
            l.level_values.0 * 1e3,
            l.level_return.to_degrees(),
            l.level_values.1 * 1e3
        );
        let _ = writeln!(
            t,
            "  {:<34} {:>9} {:>9} {:>9} {:>9} {:>9} {:>18} {:>18} {:>9}",
            "cam centre O", "X mm", "Y mm", "aw mm", "φ20 °", "r0 mm", "ϑ rise °", "ϑ return °", "over °"
        );
        for (name, c) in [
            ("point 2, level lines", &o.point2),
            ("vertex of the envelopes", &o.vertex),
            ("tmm, smallest r0, both sides", &o.exact),
        ] {
            let (a, f) = levels::distance_and_angle(c.centre);
            let _ = writeln!(
                t,
                "  {:<34} {:>9.4} {:>9.4} {:>9.4} {:>9.4} {:>9.4} {:>18} {:>18} {:>9.4}",
                name,
                c.centre.x * 1e3,
                c.centre.y * 1e3,
                a * 1e3,
                f.to_degrees(),
                (c.centre - Vec2::new(o.arm, 0.0)).hypot() * 1e3,
                range(c.pressure.rise),
                range(c.pressure.ret),
                c.pressure.excess(task.limits.rise, task.limits.ret).to_degrees()
            );
        }
        let _ = writeln!(
            t,
            "  ϑ allowed {lr:.3}° rise, {lt:.3}° return; signed ϑ is positive on the rise's driving side"
        );
        let c = o.point2.centre;
        theta_rows(&mut t, "point 2", task, |p| levels::signed_pressure(prog, sigma, 1.0, o.arm, c, p));
    }
    if let Some(r) = &b.roller {
        let _ = writeln!(t, "\nThe textbook's roller rules (p. 111)");
        rules_text(&mut t, "tmm's r0", r);
        if let Some(rb) = &b.roller_book {
            rules_text(&mut t, "the book's r0", rb);
        }
    }
    t
}
