//! Human-readable tables of a cam design (mm, degrees).

use std::fmt::Write as _;

use tmm_cams::design::{CamDesign, CamTask};
use tmm_cams::mechanism::Mechanism;

/// The tables: data, results, and a position table every `step_deg`.
pub fn tables(task: &CamTask, d: &CamDesign, step_deg: usize) -> String {
    let osc = task.follower.oscillating();
    let (su, sk) = if osc { ("deg", 180.0 / std::f64::consts::PI) } else { ("mm", 1e3) };
    let mut t = String::new();
    let _ = writeln!(
        t,
        "Cam mechanism: {} follower, cam turning {}",
        task.follower.name(),
        if task.rotation.sign() > 0.0 {
            "counter-clockwise"
        } else {
            "clockwise"
        }
    );
    let _ = writeln!(t, "  stroke h                      {:>10.4} {su}", task.program.stroke() * sk);
    let _ = writeln!(t, "  cam speed ω                   {:>10.4} rad/s", task.omega);
    let _ = writeln!(t, "\nPhases");
    let _ = writeln!(
        t,
        "  {:<8} {:>9} {:>9}  {:<22} {:>10}",
        "phase", "start °", "angle °", "law", "continuity"
    );
    for (k, ph) in task.program.phases().iter().enumerate() {
        let (law, c) = ph.law.as_ref().map_or(("—".to_string(), "".to_string()), |l| {
            (
                l.kind().to_string(),
                match l.continuity() {
                    1 => "C1 (a jumps)".into(),
                    2 => "C2 (jerk jumps)".into(),
                    _ => "C3".into(),
                },
            )
        });
        let _ = writeln!(
            t,
            "  {:<8} {:>9.3} {:>9.3}  {:<22} {:>10}",
            ph.kind.name(),
            task.program.start(k).to_degrees(),
            ph.angle.to_degrees(),
            law,
            c
        );
    }
    let _ = writeln!(t, "\nSize");
    let _ = writeln!(t, "  r0   smallest radius of the theoretical profile {:>10.4} mm", d.r0 * 1e3);
    let _ = writeln!(t, "  rb   smallest radius of the working profile     {:>10.4} mm", d.rb * 1e3);
    if let Some(e) = d.offset() {
        let _ = writeln!(t, "  e    offset of the follower axis                {:>10.4} mm", e * 1e3);
    }
    match d.mechanism {
        Mechanism::OscillatingRoller { pivot, arm, .. } => {
            let _ = writeln!(
                t,
                "  a    pivot distance OA                          {:>10.4} mm",
                pivot.hypot() * 1e3
            );
            let _ = writeln!(t, "  l    arm length AB                              {:>10.4} mm", arm * 1e3);
        }
        Mechanism::OscillatingFlat { a, .. } => {
            let _ = writeln!(t, "  a    pivot distance OA                          {:>10.4} mm", a * 1e3);
        }
        _ => {}
    }
    if !d.mechanism.is_flat() {
        let _ = writeln!(t, "  roller radius                                   {:>10.4} mm", d.roller * 1e3);
        if let Some(r) = d.roller_rule {
            let _ = writeln!(t, "  roller bound min(0.4·r0, 0.7·ρp)                {:>10.4} mm", r * 1e3);
        }
        if let Some(r) = d.rho_min_pitch.filter(|r| r.is_finite()) {
            let _ = writeln!(t, "  ρp   smallest convex radius of the pitch curve  {:>10.4} mm", r * 1e3);
        }
        let _ = writeln!(
            t,
            "  largest pressure angle: rise {:.3}° (allowed {:.3}°), return {:.3}° (allowed {:.3}°)",
            d.pressure_max_rise.to_degrees(),
            task.limits.rise.to_degrees(),
            d.pressure_max_return.to_degrees(),
            task.limits.ret.to_degrees()
        );
    } else {
        let _ = writeln!(
            t,
            "  largest pressure angle: rise {:.3}°, return {:.3}°",
            d.pressure_max_rise.to_degrees(),
            d.pressure_max_return.to_degrees()
        );
    }
    let _ = writeln!(
        t,
        "  ρ    sharpest curvature of the working profile  {:>10.4} mm ({})",
        d.rho_min * 1e3,
        if d.rho_min > 0.0 { "convex" } else { "concave" }
    );
    if let Some(c) = d.rho_min_concave {
        let _ = writeln!(t, "       smallest concave radius                    {:>10.4} mm", c.abs() * 1e3);
    }
    if let Some(f) = d.face {
        let _ = writeln!(
            t,
            "  face width                                      {:>10.4} mm (contact from {:.4} to {:.4} mm, margin {:.1} mm)",
            f.width * 1e3,
            f.contact_min * 1e3,
            f.contact_max * 1e3,
            task.face_margin * 1e3
        );
    }
    let _ = writeln!(t, "\nPositions (φ from the start of the rise; v, a at ω)");
    let vu = if osc { ("rad/s", "rad/s²") } else { ("m/s", "m/s²") };
    let _ = writeln!(
        t,
        "  {:>6} {:>10} {:>11} {:>12} {:>10} {:>12} {:>8} {:>11}",
        "φ °",
        format!("s {su}"),
        format!("ds/dφ {su}"),
        format!("d²s/dφ² {su}"),
        format!("v {}", vu.0),
        format!("a {}", vu.1),
        "ϑ °",
        "ρ mm"
    );
    let n = d.profile.phi.len();
    let step = step_deg.max(1);
    // ρ of a straight piece of profile (curvature 0) is printed as "—"
    let mut straight = false;
    for deg in (0..360).step_by(step) {
        let i = (deg * n) / 360;
        let m = d.profile.motion[i];
        let k = d.profile.curvature[i];
        let rho = if k.abs() < 1e-12 {
            straight = true;
            "—".to_string()
        } else {
            format!("{:.3}", 1e3 / k)
        };
        let _ = writeln!(
            t,
            "  {:>6.1} {:>10.4} {:>11.4} {:>12.4} {:>10.4} {:>12.3} {:>8.3} {:>11}",
            d.profile.phi[i].to_degrees(),
            m.s * sk,
            m.v * sk,
            m.a * sk,
            m.v * task.omega,
            m.a * task.omega * task.omega,
            d.profile.pressure[i].to_degrees(),
            rho
        );
    }
    if straight {
        let _ = writeln!(t, "  ρ —: a straight piece of profile (curvature 0)");
    }
    t
}
