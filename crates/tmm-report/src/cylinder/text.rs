//! The human tables of `[cylinder]`: the geometry (the synthesis when it
//! was made), the analogues d/ds at every tenth of the travel, the reduced
//! model and the motion there, the control force, how the end is reached,
//! and the kinetostatics' nine unknowns with the check F_ур = F_прДВ.

use std::fmt::Write;

use tmm_linkage::linear::EndReached;

use super::Analysis;

fn deg(x: f64) -> f64 {
    x.to_degrees()
}

/// The whole report.
pub fn report(a: &Analysis) -> String {
    let mut o = String::new();
    let t = &a.task;
    let d = &t.drive;
    let m = &t.masses;
    let mo = &a.motion;
    let c = &mo.control;
    let _ = writeln!(
        o,
        "Lever driven by an oscillating cylinder, coordinate: the piston's travel s in the cylinder"
    );
    if let Some(s) = &t.synthesis {
        let ang = |n: &str| s.angles.iter().find(|(k, _)| k == n).map_or(0.0, |x| x.1);
        let _ = writeln!(
            o,
            "Synthesis (П1.5): X_D = {:.6} m, Y_D = {:.6} m, l_AB = {:.6} m, φ1н = {:.4}°, φ3н = {:.4}°, φ3к = {:.4}°, θн = {:.4}°, θк = {:.4}°",
            d.d.x,
            d.d.y,
            d.lever,
            deg(ang("phi1")),
            deg(ang("phi3_start")),
            deg(ang("phi3_end")),
            deg(ang("theta_start")),
            deg(ang("theta_end"))
        );
    } else {
        let _ = writeln!(o, "Geometry given: D = ({:.6}, {:.6}) m, l_AB = {:.6} m", d.d.x, d.d.y, d.lever);
    }
    let _ = writeln!(
        o,
        "h_min = {:.4} m, h_max = {:.4} m, l_шт = {:.4} m, l_CS2 = {:.4} m, l_AK = {:.4} m, α = {:.3}°; travel s_max = {:.4} m; the lever turns by {:.4}°",
        d.h_min,
        d.h_max,
        d.rod,
        d.rod_center,
        d.load_arm,
        deg(d.load_angle),
        d.travel(),
        deg(t.swing)
    );
    let _ = writeln!(
        o,
        "Masses: m1 = {} kg, I1S = {} kg·m²; m2 = {} kg, I2S = {} kg·m²; m3 = {} kg, I3S = {} kg·m²; load M = {} kg; g = {} m/s²",
        m.lever_mass, m.lever_inertia, m.piston_mass, m.piston_inertia, m.cylinder_mass, m.cylinder_inertia, m.load_mass, m.gravity
    );
    let _ = writeln!(
        o,
        "\nAnalogues (d/ds): angles in degrees, ω_q in rad/m, ε_q in rad/m², V_q dimensionless, a_q in 1/m"
    );
    let _ = writeln!(
        o,
        "{:>8} {:>9} {:>9} {:>9} {:>9} {:>10} {:>10} {:>8} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9}",
        "s, m", "φ1", "φ3", "ω_q1", "ω_q3", "ε_q1", "ε_q3", "θ", "V_qS2x", "V_qS2y", "V_qKx", "V_qKy", "a_qKx", "a_qKy"
    );
    for st in a.table.iter().chain([&a.at]) {
        let _ = writeln!(
            o,
            "{:>8.4} {:>9.4} {:>9.4} {:>9.5} {:>9.5} {:>10.5} {:>10.5} {:>8.3} {:>9.5} {:>9.5} {:>9.5} {:>9.5} {:>9.4} {:>9.4}",
            st.s,
            deg(st.phi1),
            deg(st.phi3),
            st.omega_q1,
            st.omega_q3,
            st.eps_q1,
            st.eps_q3,
            deg(st.pressure_angle),
            st.s2.v.x,
            st.s2.v.y,
            st.k.v.x,
            st.k.v.y,
            st.k.a.x,
            st.k.a.y
        );
    }
    let _ = writeln!(o, "  (the last row is the kinetostatics' position s = {:.4} m)", t.at);
    let _ = writeln!(
        o,
        "\nControl force: A_C = {:.4} J (the resistance's work over the travel), F_K = |F_прC(s_max)| = {:.4} N, F_H = {:.4} N from zero work, switch s_c = {:.4} m",
        mo.resistance_work, c.end, c.start, c.switch
    );
    let _ = writeln!(
        o,
        "\nMotion (energy equation in s, from rest): m_пр in kg, m′_пр in kg/m, forces in N, work in J, V in m/s, a in m/s², t in s"
    );
    let _ = writeln!(
        o,
        "{:>8} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10} {:>9} {:>10} {:>10}",
        "s, m", "m_пр", "m′_пр", "F_прC", "F_прДВ", "F_прΣ", "A_C", "A_Σ", "V", "a", "t"
    );
    let n = mo.rows.len() - 1;
    for k in 0..=super::TABLE_POSITIONS {
        let r = &mo.rows[k * n / super::TABLE_POSITIONS];
        let time = r.time.map_or_else(|| "→ ∞".to_string(), |t| format!("{t:.5}"));
        let _ = writeln!(
            o,
            "{:>8.4} {:>10.4} {:>10.4} {:>10.3} {:>10.3} {:>10.3} {:>10.4} {:>10.4} {:>9.5} {:>10.4} {:>10}",
            r.reduced.s,
            r.reduced.mass,
            r.reduced.mass_derivative,
            r.reduced.force,
            r.control,
            r.total,
            r.work_resistance,
            r.work_total,
            r.speed,
            r.accel,
            time
        );
    }
    match mo.end {
        EndReached::Asymptotic { time_constant } => {
            let _ = writeln!(
                o,
                "The end s_max is reached only asymptotically: V(s_max) = 0 and F_прΣ(s_max) = 0, so t(s) → ∞ as s → s_max{}; t({:.4} m) = {:.5} s at the last node before it.",
                time_constant.map_or(String::new(), |tau| format!(
                    " (the remaining travel decays as e^(−t/τ), τ = {tau:.5} s)"
                )),
                mo.rows[n - 1].reduced.s,
                mo.rows[n - 1].time.unwrap_or(0.0)
            );
        }
        EndReached::Finite { time } => {
            let _ = writeln!(o, "The end s_max is reached at t = {time:.5} s.");
        }
    }
    let k = &a.reactions;
    let _ = writeln!(
        o,
        "\nKinetostatics at s = {:.4} m: V = {:.5} m/s, a = {:.5} m/s², ε1 = {:.5} rad/s², ε2 = ε3 = {:.5} rad/s²",
        k.s, k.speed, k.accel, k.eps1, k.eps3
    );
    let _ = writeln!(o, "  φ1 = {:.4}°, φ3 = {:.4}°", deg(a.at.phi1), deg(a.at.phi3));
    let _ = writeln!(
        o,
        "  inertia: Φ2 = ({:.4}, {:.4}) N, Φ (load) = ({:.4}, {:.4}) N, MΦ1 = {:.4} N·m, MΦ2 = {:.4} N·m, MΦ3 = {:.4} N·m",
        k.inertia_piston.x,
        k.inertia_piston.y,
        k.inertia_load.x,
        k.inertia_load.y,
        k.inertia_moments[0],
        k.inertia_moments[1],
        k.inertia_moments[2]
    );
    let names = [
        "R_AX, N",
        "R_AY, N",
        "R_BX, N",
        "R_BY, N",
        "R_32, N",
        "M_32, N·m",
        "R_DX, N",
        "R_DY, N",
        "F_ур, N",
    ];
    for (nm, v) in names.iter().zip(k.unknowns()) {
        let _ = writeln!(o, "  {nm:<10} {v:>14.4}");
    }
    let _ = writeln!(
        o,
        "  check: F_ур = {:.6} N, F_прДВ(s) = {:.6} N, difference {:.2e} N",
        k.balancing,
        a.control_at,
        k.balancing - a.control_at
    );
    o
}
