//! The JSON document of the `[dynamics]` section (SI, angles in radians).
//!
//! The arrays are over the cycle, φ being the crank angle turned in the
//! direction of rotation from the start of the working stroke (or from crank
//! angle 0 when the output has no dead positions): every node of the core's
//! grid when it has at most 720 intervals, else every k-th node, k the
//! largest divisor of the interval count that keeps at least 360 intervals
//! (1° with the default 3600). The scalars are exact, not read off the grid.

use serde_json::{Value, json};
use tmm_linkage::dynamics::{Dynamics, FlywheelPlace, FlywheelShape, Tangent};

use crate::linkage::Loaded;
use crate::output::num;

/// The stride through the core's grid of `n` intervals for the arrays.
#[doc(hidden)]
pub fn stride(n: usize) -> usize {
    if n <= 720 {
        return 1;
    }
    (1..=n / 360).rev().find(|s| n % s == 0).unwrap_or(1)
}

fn arr(v: &[f64], s: usize) -> Value {
    Value::Array(v.iter().step_by(s).map(|&x| num(x)).collect())
}

fn tangent(t: &Tangent) -> Value {
    json!({
        "slope": num(t.slope), "intercept": num(t.intercept),
        "phi": num(t.phi), "inertia": num(t.inertia), "energy": num(t.energy),
    })
}

/// The whole document.
pub fn document(l: &Loaded, d: &Dynamics) -> Value {
    let c = &d.cycle;
    let s = stride(c.len());
    let sp = &d.spec;
    // `runup.delta` is δ measured on the simulated steady cycle either way:
    // the run-up's last cycle with a motor; with a constant driving moment,
    // which has no run-up from rest (every speed is a steady one, see
    // docs/dynamics.md), the steady cycle re-integrated from the exact start,
    // and `time` is null.
    let runup = match &d.runup {
        Some(r) => json!({"from_rest": true, "time": num(r.time), "delta": num(r.steady.delta), "cycles": r.cycles,
            "omega_mean": num(r.steady.omega_mean), "omega_max": num(r.steady.omega_max), "omega_min": num(r.steady.omega_min)}),
        None => {
            let s = &d.simulated;
            json!({"from_rest": false, "time": Value::Null, "delta": num(s.delta), "cycles": 0,
                "omega_mean": num(s.omega_mean), "omega_max": num(s.omega_max), "omega_min": num(s.omega_min),
                "why": "a constant driving moment has no run-up from rest: the drive and the loads do zero work over every cycle whatever the speed, so every speed is a steady one; delta is measured on the steady cycle integrated in time from the exact start; give [dynamics.motor] for the run-up"})
        }
    };
    let flywheel = d.flywheel.map(|f| {
        json!({
            "place": match sp.flywheel.place { FlywheelPlace::Crank => "crank", FlywheelPlace::Motor => "motor", FlywheelPlace::Shaft => "shaft" },
            "speed_ratio": num(match sp.flywheel.place { FlywheelPlace::Crank => 1.0, FlywheelPlace::Motor => d.flywheel_inertia_crank / d.flywheel_inertia, FlywheelPlace::Shaft => sp.flywheel.speed_ratio }),
            "shape": match sp.flywheel.shape { FlywheelShape::Disc { .. } => "disc", FlywheelShape::Rim { .. } => "rim" },
            "density": num(sp.flywheel.density),
            "inertia": num(d.flywheel_inertia),
            "diameter": num(f.diameter), "width": num(f.width), "thickness": num(f.thickness), "mass": num(f.mass),
        })
    });
    let motor = sp.motor().map(|m| {
        json!({"synchronous_speed": num(m.synchronous_speed), "nominal_speed": num(m.nominal_speed),
            "nominal_torque": num(m.nominal_torque), "ratio": num(m.ratio)})
    });
    let mo = &d.motion;
    let positions: Vec<Value> = d
        .positions
        .iter()
        .map(|p| {
            json!({
                "index": p.index, "phi": num(p.phi), "crank_angle": num(p.crank_angle),
                "reduced_inertia_variable": num(p.inertia), "reduced_moment": num(p.moment),
                "work": num(p.work_loads), "work_driving": num(p.work_driving),
                "kinetic_energy_change": num(p.energy), "energy_constant_part": num(p.energy_constant),
                "omega": num(p.omega), "epsilon": num(p.epsilon),
            })
        })
        .collect();
    let mut doc = json!({
        "units": "SI",
        "assumptions": "rigid links, friction neglected; the driving moment on the crank constant over the cycle (zero work over the steady cycle) for the flywheel; the nominal crank speed ω_m = (ω_max + ω_min)/2 is the [linkage] input speed",
        "structure": l.mech.structure.formula,
        "delta_requested": num(sp.delta),
        "omega_nominal": num(d.omega_nominal),
        "crank_angle_start": num(d.reducer.phi_start),
        "direction": if d.reducer.dir > 0.0 { "ccw" } else { "cw" },
        "driving": if motor.is_some() { "motor" } else { "constant" },
        "motor": motor,
        "phi": arr(&c.phi, s),
        "reduced_inertia_variable": arr(&c.inertia, s),
        "reduced_inertia_derivative": arr(&c.inertia_derivative, s),
        "reduced_moment": arr(&c.moment, s),
        "driving_moment": num(c.driving_moment),
        "cycle_period": num(d.reducer.period),
        // T = 2π/ω_m = 60/n1 and the cycle's time Φ/ω_m at the nominal speed, s
        // (`cycle_time` below is the true motion's ∫dφ/ω)
        "revolution_time": num(if d.omega_nominal > 0.0 { std::f64::consts::TAU / d.omega_nominal } else { 0.0 }),
        "cycle_time_nominal": num(if d.omega_nominal > 0.0 { d.reducer.period / d.omega_nominal } else { 0.0 }),
        "load_period": num(d.load_period),
        // the part of the cycle from its start over which Mertsalov's,
        // Wittenbauer's and the exact method searched their extremes: the
        // period of the summed loads (their angles are given within it)
        "flywheel_span": num(d.load_period),
        "work": arr(&c.work_loads, s),
        "work_driving": arr(&c.work_driving, s),
        "kinetic_energy_change": arr(&c.energy, s),
        "energy_constant_part": arr(&d.mertsalov.energy_constant, s),
    });
    let mertsalov = json!({"energy_swing": num(d.mertsalov.energy_swing), "energy_max": num(d.mertsalov.energy_max),
        "phi_max": num(d.mertsalov.phi_max), "energy_min": num(d.mertsalov.energy_min), "phi_min": num(d.mertsalov.phi_min)});
    let rest = json!({
        "inertia_constant_given": num(d.inertia_given.total),
        "inertia_given": {"crank": num(d.inertia_given.crank), "crank_shaft": num(d.inertia_given.crank_shaft), "motor_shaft_reduced": num(d.inertia_given.motor_shaft)},
        // `merkalov` (a misspelling of Мерцалов) is kept beside `mertsalov`
        // for one release, so that readers of the old key go on working
        // (docs/dynamics.md, "JSON")
        "required_inertia": {"mertsalov": num(d.required.mertsalov), "merkalov": num(d.required.mertsalov),
            "wittenbauer": num(d.required.wittenbauer), "exact": num(d.required.exact)},
        "mertsalov": mertsalov.clone(),
        "merkalov": mertsalov,
        "wittenbauer": {"upper": tangent(&d.wittenbauer.upper), "lower": tangent(&d.wittenbauer.lower), "energy_start": num(d.wittenbauer.energy_start)},
        // the exact method's positions of ω_max and ω_min (П2, П3: Φ_A, Φ_B)
        "exact": {"inertia": num(d.exact.inertia), "phi_max": num(d.exact.phi_max), "phi_min": num(d.exact.phi_min),
            "omega_max": num(d.exact.omega_max), "omega_min": num(d.exact.omega_min)},
        "inertia_constant": num(mo.inertia_constant),
        "energy_start": num(mo.energy_start),
        "flywheel_inertia": num(d.flywheel_inertia),
        "flywheel_inertia_crank": num(d.flywheel_inertia_crank),
        "flywheel": flywheel,
        "omega": arr(&mo.omega, s),
        "epsilon": arr(&mo.epsilon, s),
        "time": arr(&mo.time, s),
        "omega_max": num(mo.omega_max),
        "omega_min": num(mo.omega_min),
        "omega_mean": num(mo.omega_mean),
        "delta": num(mo.delta),
        "cycle_time": num(mo.cycle_time),
        "simulated": {"delta": num(d.simulated.delta), "period": num(d.simulated.period), "omega_max": num(d.simulated.omega_max), "omega_min": num(d.simulated.omega_min)},
        "runup": runup,
        "positions": positions,
    });
    if let (Some(a), Value::Object(b)) = (doc.as_object_mut(), rest) {
        a.extend(b);
    }
    doc
}
