//! The human tables of the `[dynamics]` section: the 12 positions (I_II,
//! M_c, the work, ΔT, T_I, ω₁, ε₁) and the summary (M_d, the inertia
//! required by the three methods side by side, the flywheel, the speeds,
//! δ achieved, the cycle time and the run-up).

use std::fmt::Write;

use tmm_linkage::dynamics::{DrivingMoment, Dynamics, FlywheelPlace, FlywheelShape};

use crate::linkage::Loaded;

/// Relative difference of `a` from `b`, in per cent.
fn pct(a: f64, b: f64) -> f64 {
    if b == 0.0 { 0.0 } else { 100.0 * (a - b) / b }
}

/// A value as the user wrote it, in scientific notation when it is very
/// large or small.
fn sci(x: f64) -> String {
    // 12 significant digits, then the shortest text of that value: a ratio
    // the task gives as 0.1 and the code derives as 0.09999999999999998
    // prints as 0.1
    let x: f64 = format!("{x:.11e}").parse().unwrap_or(x);
    if x == 0.0 || (1e-3..1e6).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// An engine, or a cycle longer than one turn: the cycle's start and
/// length are named.
fn engine_or_long(d: &Dynamics) -> bool {
    d.spec.driving == DrivingMoment::Engine || d.reducer.period > 1.5 * std::f64::consts::TAU
}

/// The whole report.
pub fn report(l: &Loaded, d: &Dynamics) -> String {
    let mut o = String::new();
    let sp = &d.spec;
    let c = &d.cycle;
    let mo = &d.motion;
    let _ = writeln!(o, "Dynamics of the machine ({}), δ = {}", l.mech.structure.formula, sci(sp.delta));
    let _ = writeln!(
        o,
        "Nominal crank speed ω_m = {:.4} rad/s ({:.2} rpm), {}; φ is the crank angle turned from the start of the cycle at crank angle {:.3}°{}",
        d.omega_nominal,
        d.omega_nominal * 30.0 / std::f64::consts::PI,
        if d.reducer.dir > 0.0 { "counter-clockwise" } else { "clockwise" },
        d.reducer.phi_start.to_degrees(),
        if engine_or_long(d) {
            format!(" (the start of the machine's cycle of {:.0}°)", d.reducer.period.to_degrees())
        } else if d.reducer.stroke.is_some() {
            " (the start of the working stroke)".to_string()
        } else {
            String::new()
        }
    );
    // the time of one turn T = 2π/ω_m = 60/n1 and of the machine's cycle
    // Φ/ω_m (two turns of a four-stroke engine: 2T)
    if d.omega_nominal > 0.0 {
        let _ = writeln!(
            o,
            "Time of one turn T = 60/n1 = {:.6} s; of the machine's cycle of {:.0}° at the nominal speed {:.6} s",
            std::f64::consts::TAU / d.omega_nominal,
            d.reducer.period.to_degrees(),
            d.reducer.period / d.omega_nominal
        );
    }
    let _ = writeln!(
        o,
        "Grid: {} intervals; the work by 3-point Gauss–Legendre; every extremum refined between the nodes.",
        c.len()
    );
    if d.load_period < d.reducer.period {
        let _ = writeln!(
            o,
            "The summed loads repeat every {:.0}° of the {:.0}° cycle (M_c and I_II at φ and φ + {:.0}° agree to {:e} at every node), though each cylinder's cycle is {:.0}°: Mertsalov's, Wittenbauer's and the exact flywheel are found over 0…{:.0}°, as the book restricts its analysis, and are the ones over the whole cycle (the time integration below runs over the whole {:.0}° with this flywheel); the extremes below are given within 0…{:.0}°.",
            d.load_period.to_degrees(),
            d.reducer.period.to_degrees(),
            d.load_period.to_degrees(),
            tmm_linkage::dynamics::load_period::TOLERANCE,
            d.reducer.period.to_degrees(),
            d.load_period.to_degrees(),
            d.reducer.period.to_degrees(),
            d.load_period.to_degrees()
        );
    } else if d.reducer.period > std::f64::consts::TAU * (1.0 + 1e-9) {
        let _ = writeln!(
            o,
            "The summed loads repeat only over the whole {:.0}° cycle: Mertsalov's, Wittenbauer's and the exact flywheel walk all of it.",
            d.reducer.period.to_degrees()
        );
    }
    let _ = writeln!(o, "\nThe 12 positions (ω₁, ε₁ in the direction of rotation, with the flywheel):");
    let _ = writeln!(
        o,
        "{:>3} {:>7} {:>12} {:>11} {:>11} {:>11} {:>11} {:>11} {:>10} {:>10}",
        "#", "φ, °", "I_II, kg·m²", "M_c, N·m", "A_c, J", "A_d, J", "ΔT, J", "T_I, J", "ω₁, rad/s", "ε₁, 1/s²"
    );
    for p in &d.positions {
        let _ = writeln!(
            o,
            "{:>3} {:>7.1} {:>12.6} {:>11.3} {:>11.3} {:>11.3} {:>11.3} {:>11.3} {:>10.4} {:>10.2}",
            p.index,
            p.phi.to_degrees(),
            p.inertia,
            p.moment,
            p.work_loads,
            p.work_driving,
            p.energy,
            p.energy_constant,
            p.omega,
            p.epsilon
        );
    }
    let _ = writeln!(o, "\nSummary");
    if sp.driving == DrivingMoment::Engine {
        let _ = writeln!(
            o,
            "  an engine: the loads (gas forces, weights) drive, M_c above is their reduced moment; work of the loads over the cycle A_c({:.0}°) = {:.6} J; resistance moment of the driven machine M_d = {:.6} N·m (constant, zero work over the cycle)",
            d.reducer.period.to_degrees(),
            c.work_loads[c.len()],
            c.driving_moment
        );
    } else if engine_or_long(d) {
        let _ = writeln!(
            o,
            "  work of the loads over the cycle A_c({:.0}°) = {:.6} J; driving moment M_d = {:.6} N·m (constant, zero work over the steady cycle)",
            d.reducer.period.to_degrees(),
            c.work_loads[c.len()],
            c.driving_moment
        );
    } else {
        let _ = writeln!(
            o,
            "  work of the loads over the cycle A_c(2π) = {:.6} J; driving moment M_d = {:.6} N·m (constant, zero work over the steady cycle)",
            c.work_loads[c.len()],
            c.driving_moment
        );
    }
    let _ = writeln!(
        o,
        "  Mertsalov: T_I = ΔT − I_II·ω_m²/2, max {:.4} J at φ = {:.2}°, min {:.4} J at φ = {:.2}°, ΔT_I = {:.4} J",
        d.mertsalov.energy_max,
        d.mertsalov.phi_max.to_degrees(),
        d.mertsalov.energy_min,
        d.mertsalov.phi_min.to_degrees(),
        d.mertsalov.energy_swing
    );
    let (u, lo) = (&d.wittenbauer.upper, &d.wittenbauer.lower);
    let _ = writeln!(
        o,
        "  Wittenbauer: upper tangent slope ω_max²/2 = {:.3} s⁻², touching at φ = {:.2}° (I_II = {:.6} kg·m², ΔT = {:.4} J); lower slope ω_min²/2 = {:.3} s⁻² at φ = {:.2}° (I_II = {:.6} kg·m², ΔT = {:.4} J); T₀ = {:.4} J",
        u.slope,
        u.phi.to_degrees(),
        u.inertia,
        u.energy,
        lo.slope,
        lo.phi.to_degrees(),
        lo.inertia,
        lo.energy,
        d.wittenbauer.energy_start
    );
    let ex = d.required.exact;
    let _ = writeln!(o, "  Constant inertia I_I required on the crank shaft:");
    let _ = writeln!(o, "    {:<14} {:>14} {:>16}", "method", "I_I, kg·m²", "vs exact, %");
    for (name, v) in [
        ("Mertsalov", d.required.mertsalov),
        ("Wittenbauer", d.required.wittenbauer),
        ("exact", ex),
    ] {
        let _ = writeln!(o, "    {:<14} {:>14.6} {:>+16.6}", name, v, pct(v, ex));
    }
    let g = &d.inertia_given;
    let _ = writeln!(
        o,
        "  given on the crank shaft: the crank {:.6} + other parts {:.6} + the motor shaft reduced (u²·J) {:.6} = {:.6} kg·m²",
        g.crank, g.crank_shaft, g.motor_shaft, g.total
    );
    match &d.flywheel {
        Some(f) => {
            let place = match sp.flywheel.place {
                FlywheelPlace::Crank => "crank shaft",
                FlywheelPlace::Motor => "motor shaft",
                FlywheelPlace::Shaft => "shaft",
            };
            let shape = match sp.flywheel.shape {
                FlywheelShape::Disc { width_ratio } => format!("disc, b/D = {}", sci(width_ratio)),
                FlywheelShape::Rim {
                    width_ratio,
                    thickness_ratio,
                } => format!("rim, b/D = {}, h/D = {}", sci(width_ratio), sci(thickness_ratio)),
            };
            let _ = writeln!(
                o,
                "  flywheel: {:.6} kg·m² reduced to the crank shaft = I_I,exact − I_I,given; {}",
                d.flywheel_inertia_crank,
                if sp.flywheel.place == FlywheelPlace::Motor {
                    format!(
                        "on the {place}, ÷ u² = {:.4}: J = {:.6} kg·m²",
                        d.flywheel_inertia_crank / d.flywheel_inertia,
                        d.flywheel_inertia
                    )
                } else if sp.flywheel.place == FlywheelPlace::Shaft {
                    format!(
                        "on the {place} turning {} times as fast as the crank, ÷ {}² = {:.6}: J = {:.6} kg·m²",
                        sci(sp.flywheel.speed_ratio),
                        sci(sp.flywheel.speed_ratio),
                        sp.flywheel.speed_ratio * sp.flywheel.speed_ratio,
                        d.flywheel_inertia
                    )
                } else {
                    format!("on the {place}: J = {:.6} kg·m²", d.flywheel_inertia)
                }
            );
            let _ = writeln!(
                o,
                "  flywheel size ({shape}, ρ = {} kg/m³): D = {:.1} mm, b = {:.1} mm{}, mass {:.2} kg",
                sci(sp.flywheel.density),
                f.diameter * 1e3,
                f.width * 1e3,
                if matches!(sp.flywheel.shape, FlywheelShape::Rim { .. }) {
                    format!(", rim thickness h = {:.1} mm", f.thickness * 1e3)
                } else {
                    String::new()
                },
                f.mass
            );
        }
        None => {
            let _ = writeln!(
                o,
                "  no flywheel: the inertia already on the shaft ({:.6} kg·m²) is at least the required {:.6} kg·m², so δ is smaller than asked{}",
                g.total,
                ex,
                if ex < 0.0 {
                    " (a negative requirement: the links of variable inertia alone hold the speed within δ)"
                } else {
                    ""
                }
            );
        }
    }
    let _ = writeln!(
        o,
        "  ω_max = {:.5} rad/s, ω_min = {:.5} rad/s, ω_m = {:.5} rad/s, δ achieved = {:.8}",
        mo.omega_max, mo.omega_min, mo.omega_mean, mo.delta
    );
    let _ = writeln!(
        o,
        "  cycle time {:.7} s; by time integration (Dormand–Prince 5(4)) over the whole {:.0}° cycle: {:.7} s, δ = {:.8}",
        mo.cycle_time,
        d.reducer.period.to_degrees(),
        d.simulated.period,
        d.simulated.delta
    );
    match (&d.runup, sp.driving) {
        (Some(r), DrivingMoment::Motor(m)) => {
            let _ = writeln!(
                o,
                "  run-up from rest with the motor (ω_s = {:.3} rad/s, ω_n = {:.3} rad/s, M_n = {:.3} N·m, u = {}): {:.4} s to within 1 % of the steady speed ({} cycles simulated); steady ω_m = {:.5} rad/s, δ = {:.6}",
                m.synchronous_speed,
                m.nominal_speed,
                m.nominal_torque,
                sci(m.ratio),
                r.time,
                r.cycles,
                r.steady.omega_mean,
                r.steady.delta
            );
        }
        (_, DrivingMoment::Engine) => {
            let _ = writeln!(
                o,
                "  run-up: none — with a constant resistance the engine's loads and the resistance do zero work over every cycle whatever the speed, so every speed is a steady one"
            );
        }
        _ => {
            let _ = writeln!(
                o,
                "  run-up: none — with a constant driving moment the drive and the loads do zero work over every cycle whatever the speed, so every speed is a steady one; give a motor ([dynamics.motor]) for the run-up"
            );
        }
    }
    o
}
