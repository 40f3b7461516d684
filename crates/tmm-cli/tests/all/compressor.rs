//! The two-stage V-compressor example (`examples/compressor-two-stage.toml`):
//! a working machine whose resistance is the gas forces of two cylinders on
//! one crank pin. Its constant driving moment must equal the indicator work
//! of both stages over one turn divided by 2π, the work of the ideal
//! polytropic cycle integrated in closed form here — not the tables' splines
//! that the task file samples from it.

use crate::common::{json, repo, tmm_in};
use std::f64::consts::PI;

fn tmm_json(args: &[&str]) -> serde_json::Value {
    let o = tmm_in(&repo(), args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    json(&o)
}

/// Work done on the gas per cycle of one stage, J: the closed cycle
/// compression (polytrope) → delivery (p_d) → re-expansion (polytrope) →
/// suction (p_s), ∮p dV with ∫p dV = (p₂V₂ − p₁V₁)/(n − 1) on a polytrope
/// p·Vⁿ = const. The atmosphere's constant pressure on the piston's other
/// face does no work over a closed cycle, so gauge and absolute agree.
fn stage_work(clearance: f64, n: f64, p_s: f64, p_d: f64, bore: f64, stroke: f64) -> f64 {
    let v_h = PI * bore * bore / 4.0 * stroke;
    let v1 = (1.0 + clearance) * v_h; // bottom dead centre, suction pressure
    let v2 = v1 * (p_s / p_d).powf(1.0 / n); // compression reaches p_d
    let v3 = clearance * v_h; // top dead centre
    let v4 = v3 * (p_d / p_s).powf(1.0 / n); // re-expansion reaches p_s
    let compression = (p_d * v2 - p_s * v1) / (n - 1.0);
    let delivery = p_d * (v2 - v3);
    let re_expansion = (p_d * v3 - p_s * v4) / (n - 1.0);
    let suction = p_s * (v1 - v4);
    compression + delivery - re_expansion - suction
}

#[test]
fn the_driving_moment_is_the_indicator_work_of_both_stages() {
    let d = tmm_json(&["dynamics", "examples/compressor-two-stage.toml", "--json"]);
    let m_d = d["driving_moment"].as_f64().expect("driving_moment");
    // the givens of the example's header: stroke 2·60 mm, n = 1.3
    let w1 = stage_work(0.05, 1.3, 0.09e6, 0.32e6, 0.18, 0.12);
    let w2 = stage_work(0.06, 1.3, 0.30e6, 0.90e6, 0.10, 0.12);
    let expect = (w1 + w2) / (2.0 * PI);
    // the task's tables sample the polytropes at 12 nodes and its process
    // bounds are rounded to 0.01°: 0.1 % covers both
    assert!(
        ((m_d - expect) / expect).abs() < 1e-3,
        "M_d = {m_d} N·m, the polytropic cycles give {expect} N·m"
    );
    // gravity does no work over a cycle, the gas forces all of it: the
    // work of the loads over the turn is −2π·M_d
    let work = d["work"].as_array().expect("work");
    let last = work.last().and_then(|v| v.as_f64()).expect("work at 2π");
    assert!((last + 2.0 * PI * m_d).abs() < 1e-9 * last.abs().max(1.0));
}

/// One stage's gauge pressure (Pa) at its own cycle angle θ from its outer
/// dead centre, from the polytropes of the example's header and the
/// slider-crank's closed-form travel s(θ) = [r(1 − cos θ) + l(1 − √(1 − λ² sin² θ))]/(2r).
fn stage_pressure(theta: f64, clearance: f64, n: f64, p_s: f64, p_d: f64, bounds: [f64; 2]) -> f64 {
    let (r, l) = (0.06, 0.25);
    let lam = r / l;
    let s = (r * (1.0 - theta.cos()) + l * (1.0 - (1.0 - (lam * theta.sin()).powi(2)).sqrt())) / (2.0 * r);
    let deg = theta.to_degrees();
    let abs = if deg < bounds[0] {
        p_d * (clearance / (clearance + s)).powf(n) // re-expansion
    } else if deg < 180.0 {
        p_s // suction
    } else if deg < bounds[1] {
        p_s * ((clearance + 1.0) / (clearance + s)).powf(n) // compression
    } else {
        p_d // delivery
    };
    abs - 0.1e6
}

#[test]
fn the_gas_forces_follow_the_polytropes_and_the_torque_averages_to_the_drive() {
    let f = tmm_json(&["forces", "examples/compressor-two-stage.toml", "--json"]);
    assert_eq!(f["crank_motion"], "dynamics");
    let positions = f["positions"].as_array().expect("positions");
    assert_eq!(positions.len(), 12);
    // (axis angle, shift, clearance, p_s, p_d, bore, process bounds) of each stage
    let stages = [
        (135.0_f64, 0.0_f64, 0.05, 0.09e6, 0.32e6, 0.18, [30.12, 294.18]),
        (45.0, 270.0, 0.06, 0.30e6, 0.90e6, 0.10, [29.55, 288.58]),
    ];
    for p in positions {
        let cycle = p["cycle_angle"].as_f64().unwrap();
        let forces = p["slider_forces"].as_array().unwrap();
        for (k, &(axis, shift, c, p_s, p_d, bore, bounds)) in stages.iter().enumerate() {
            let theta = (cycle - shift.to_radians()).rem_euclid(2.0 * PI);
            let pressure = stage_pressure(theta, c, 1.3, p_s, p_d, bounds);
            // the force pushes the piston from its head towards the shaft
            let f_abs = pressure * PI * bore * bore / 4.0;
            let (ux, uy) = (axis.to_radians().cos(), axis.to_radians().sin());
            let got = (forces[k][0].as_f64().unwrap(), forces[k][1].as_f64().unwrap());
            let scale = (p_d - 0.1e6) * PI * bore * bore / 4.0;
            // the splines sample the polytropes at 12 nodes: 1 % of the largest force
            assert!(
                (got.0 + f_abs * ux).abs() < 0.01 * scale && (got.1 + f_abs * uy).abs() < 0.01 * scale,
                "stage {} at cycle angle {:.1}°: {got:?} against {:.1} N along the axis",
                k + 1,
                cycle.to_degrees(),
                -f_abs
            );
        }
    }
    // over a steady cycle the links' kinetic energy returns to its value, so
    // the balancing torque's mean is the constant driving moment
    let d = tmm_json(&["dynamics", "examples/compressor-two-stage.toml", "--json"]);
    let m_d = d["driving_moment"].as_f64().unwrap();
    let cycle = f["cycle"].as_array().expect("cycle");
    let n = cycle.len() - 1; // the last sample repeats the first
    let mean = cycle[..n].iter().map(|c| c["balancing_moment"].as_f64().unwrap()).sum::<f64>() / n as f64;
    assert!(((mean - m_d) / m_d).abs() < 5e-3, "mean M_b {mean} N·m, M_d {m_d} N·m");
}
