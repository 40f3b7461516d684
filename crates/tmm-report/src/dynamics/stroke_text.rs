//! The human tables of the single stroke: the motor and the machine, the
//! motor-driven stroke (cycle time, the least speed, the crossings of the
//! motor's breakdown speed, the energy balance, the check by a second
//! integrator) and the constant-moment stroke, then both side by side at
//! every 10° (or the nearest output angles) and at the design position.

use std::f64::consts::PI;
use std::fmt::Write;

use tmm_linkage::dynamics::SingleStroke;

use crate::linkage::Loaded;

fn rps(w: f64) -> f64 {
    w / (2.0 * PI)
}

/// The whole report.
pub fn report(l: &Loaded, s: &SingleStroke) -> String {
    let mut o = String::new();
    let sp = &s.spec;
    let mo = &sp.motor;
    let m = &s.motor;
    let e = &s.energy;
    let red = &s.reducer;
    let _ = writeln!(o, "Unsteady single stroke of the machine ({})", l.mech.structure.formula);
    let _ = writeln!(
        o,
        "φ is the crank angle turned {} from the start of the cycle at crank angle {:.3}°{}; the cycle ends at φ = 360°.",
        if red.dir > 0.0 { "counter-clockwise" } else { "clockwise" },
        red.phi_start.to_degrees().rem_euclid(360.0),
        if red.stroke.is_some() {
            " (the start of the working stroke)"
        } else {
            ""
        }
    );
    let _ = writeln!(
        o,
        "Motor (Kloss): n₀ = {:.4} rev/s, n_K = {:.4} rev/s, M_K = {:.1} N·m, S_K = {:.5}; reducer u = {}; at the crank ω₀ = {:.5} rad/s, ω_K = {:.5} rad/s, u·M_K = {:.1} N·m.",
        rps(mo.synchronous_speed),
        rps(mo.breakdown_speed),
        mo.breakdown_torque,
        mo.breakdown_slip(),
        mo.ratio,
        mo.crank_synchronous_speed(),
        mo.crank_breakdown_speed(),
        mo.ratio * mo.breakdown_torque
    );
    let _ = writeln!(
        o,
        "Constant inertia at the crank I_I = {:.6e} kg·m²; start speed ω(0) = {:.5} rad/s; {}.",
        s.inertia_constant,
        sp.start_speed,
        if sp.time_constant > 0.0 {
            format!("dynamic characteristic τ·dM/dt + M = M_st(ω), τ = {} s", sp.time_constant)
        } else {
            "static characteristic".to_string()
        }
    );
    let _ = writeln!(
        o,
        "\nModel 1, the motor's characteristic (time integration, Dormand–Prince 5(4), rtol 1e-12):"
    );
    let _ = writeln!(o, "  cycle time t_ц = {:.6} s (the event φ = 360°)", m.cycle_time);
    let _ = writeln!(o, "  ω at the end = {:.6} rad/s", m.omega_end);
    let _ = writeln!(
        o,
        "  least speed ω_min = {:.6} rad/s at φ = {:.3}°, t = {:.5} s",
        m.omega_min,
        m.phi_omega_min.to_degrees(),
        m.time_omega_min
    );
    let _ = writeln!(
        o,
        "  largest motor torque {:.2} N·m (M_K = {:.2} N·m)",
        m.torque_max, mo.breakdown_torque
    );
    if m.crossings.is_empty() {
        let _ = writeln!(
            o,
            "  the crank's speed stays {} the motor's breakdown speed ω_K = {:.5} rad/s all through the stroke",
            if m.omega_min > mo.crank_breakdown_speed() {
                "above"
            } else {
                "below"
            },
            mo.crank_breakdown_speed()
        );
    }
    for c in &m.crossings {
        let _ = writeln!(
            o,
            "  the speed {} the breakdown speed ω_K = {:.5} rad/s at φ = {:.3}°, t = {:.5} s, travel {:.5} m{}",
            if c.falling { "falls below" } else { "rises above" },
            mo.crank_breakdown_speed(),
            c.phi.to_degrees(),
            c.time,
            c.travel,
            if c.falling {
                " (the motor passes onto the unstable branch)"
            } else {
                ""
            }
        );
    }
    let _ = writeln!(o, "  time below the breakdown speed {:.5} s", m.time_below_breakdown);
    let b = &m.balance;
    let _ = writeln!(
        o,
        "  energy balance: motor work {:.3} J + loads' work {:.3} J = ΔT {:.3} J (T: {:.3} → {:.3} J), residual {:.2e}",
        b.motor_work,
        b.loads_work,
        b.kinetic_end - b.kinetic_start,
        b.kinetic_start,
        b.kinetic_end,
        b.residual
    );
    if let Some(c) = &s.check {
        let _ = writeln!(
            o,
            "  check by RK4 in the crank angle ({} steps): t_ц = {:.6} s ({:+.2e}), ω(360°) = {:.6} rad/s ({:+.2e})",
            c.steps,
            c.cycle_time,
            (c.cycle_time - m.cycle_time) / m.cycle_time,
            c.omega_end,
            (c.omega_end - m.omega_end) / m.omega_end
        );
    }
    let _ = writeln!(o, "  steps: {} accepted, {} rejected", m.steps.0, m.steps.1);
    let _ = writeln!(
        o,
        "\nModel 2, constant driving moment M_прДВ = u·M = {:.2} N·m (energy method):",
        e.driving_moment
    );
    let _ = writeln!(o, "  A_Σ(360°) = {:.3} J", e.work_end);
    let _ = writeln!(o, "  ω(360°) = {:.6} rad/s", e.omega_end);
    let _ = writeln!(o, "  t(360°) = {:.6} s", e.time_end);
    let _ = writeln!(o, "  least speed {:.6} rad/s", e.omega_min);
    if let (Some(d), Some(de)) = (&m.design, &e.design) {
        let _ = writeln!(
            o,
            "\nDesign position φ = {:.3}° (crank angle {:.3}°), travel h = {:.5} m:",
            d.phi.to_degrees(),
            d.crank_angle.to_degrees().rem_euclid(360.0),
            d.travel
        );
        let _ = writeln!(
            o,
            "  I_II = {:.3} kg·m², I_Σ = {:.3} kg·m², M_c = {:.3} N·m",
            d.inertia_variable, d.inertia_total, d.moment_loads
        );
        let _ = writeln!(
            o,
            "  model 1: ω = {:.6} rad/s, ε = {:.5} rad/s², t = {:.6} s, u·M = {:.3} N·m",
            d.omega, d.epsilon, d.time, d.moment_motor
        );
        let _ = writeln!(
            o,
            "  model 2: A_Σ = {:.3} J, ω = {:.6} rad/s, ε = {:.5} rad/s², t = {:.6} s",
            de.work_total, de.omega, de.epsilon, de.time
        );
    }
    let _ = writeln!(o, "\nOver the cycle (model 1: the motor; model 2: constant moment):");
    let _ = writeln!(
        o,
        "{:>7} {:>8} {:>11} {:>12} {:>12} {:>11} {:>9} {:>10} {:>8} {:>12} {:>9} {:>10} {:>8}",
        "φ, °",
        "h, m",
        "I_II, kg·m²",
        "I_Σ, kg·m²",
        "M_c, N·m",
        "u·M, N·m",
        "ω₁, 1/s",
        "ε₁, 1/s²",
        "t₁, s",
        "A_Σ₂, J",
        "ω₂, 1/s",
        "ε₂, 1/s²",
        "t₂, s"
    );
    let every = (m.rows.len() / 36).max(1);
    for (k, (r, q)) in m.rows.iter().zip(&e.rows).enumerate() {
        let design = sp.design_angle.is_some_and(|f| (r.phi - f).abs() < 1e-9);
        if k % every != 0 && k + 1 != m.rows.len() && !design {
            continue;
        }
        let _ = writeln!(
            o,
            "{:>7.2} {:>8.5} {:>11.3} {:>12.3} {:>12.3} {:>11.3} {:>9.5} {:>10.4} {:>8.5} {:>12.3} {:>9.5} {:>10.4} {:>8.5}",
            r.phi.to_degrees(),
            r.travel,
            r.inertia_variable,
            r.inertia_total,
            r.moment_loads,
            r.moment_motor,
            r.omega,
            r.epsilon,
            r.time,
            q.work_total,
            q.omega,
            q.epsilon,
            q.time
        );
    }
    o
}
