//! The JSON document of the single stroke (SI, angles in radians): the
//! motor, the motor-driven stroke (`motor_driven`: the cycle time, the
//! breakdown-speed crossings, the energy balance, the check by a second
//! integrator, and the arrays over the output angles) and the
//! constant-moment stroke (`constant_moment`). The arrays share the
//! angles `phi` of the rows: uniform over the cycle, with the design
//! position inserted when it falls between them.

use serde_json::{Value, json};
use tmm_linkage::dynamics::{EnergyRow, SingleStroke, StrokeRow};

use crate::linkage::Loaded;
use crate::output::num;

fn col<T>(rows: &[T], f: impl Fn(&T) -> f64) -> Value {
    Value::Array(rows.iter().map(|r| num(f(r))).collect())
}

fn row(r: &StrokeRow) -> Value {
    json!({
        "phi": num(r.phi), "crank_angle": num(r.crank_angle), "travel": num(r.travel),
        "inertia_variable": num(r.inertia_variable), "inertia_total": num(r.inertia_total),
        "moment_loads": num(r.moment_loads), "moment_motor": num(r.moment_motor),
        "omega": num(r.omega), "epsilon": num(r.epsilon), "time": num(r.time),
    })
}

fn energy_row(r: &EnergyRow) -> Value {
    json!({
        "phi": num(r.phi), "travel": num(r.travel), "work_total": num(r.work_total),
        "omega": num(r.omega), "epsilon": num(r.epsilon), "time": num(r.time),
    })
}

/// The whole document.
pub fn document(l: &Loaded, s: &SingleStroke) -> Value {
    let sp = &s.spec;
    let mo = &sp.motor;
    let m = &s.motor;
    let e = &s.energy;
    let r = &m.rows;
    let red = &s.reducer;
    json!({
        "motion": "single-stroke",
        "formula": l.mech.structure.formula,
        "cycle_start": num(red.phi_start),
        "direction": if red.dir > 0.0 { "ccw" } else { "cw" },
        "inertia_constant": num(s.inertia_constant),
        "start_speed": num(sp.start_speed),
        "time_constant": num(sp.time_constant),
        "design_angle": sp.design_angle.map_or(Value::Null, num),
        "motor": {
            "model": "kloss",
            "synchronous_speed": num(mo.synchronous_speed),
            "breakdown_speed": num(mo.breakdown_speed),
            "breakdown_torque": num(mo.breakdown_torque),
            "breakdown_slip": num(mo.breakdown_slip()),
            "ratio": num(mo.ratio),
            "crank_synchronous_speed": num(mo.crank_synchronous_speed()),
            "crank_breakdown_speed": num(mo.crank_breakdown_speed()),
            "crank_breakdown_moment": num(mo.ratio * mo.breakdown_torque),
        },
        "motor_driven": {
            "cycle_time": num(m.cycle_time),
            "omega_end": num(m.omega_end),
            "omega_min": num(m.omega_min),
            "phi_omega_min": num(m.phi_omega_min),
            "time_omega_min": num(m.time_omega_min),
            "torque_max": num(m.torque_max),
            "breakdown_crossings": m.crossings.iter().map(|c| json!({
                "time": num(c.time), "phi": num(c.phi), "travel": num(c.travel),
                "direction": if c.falling { "below" } else { "above" },
            })).collect::<Vec<_>>(),
            "time_below_breakdown": num(m.time_below_breakdown),
            "energy_balance": {
                "motor_work": num(m.balance.motor_work),
                "loads_work": num(m.balance.loads_work),
                "kinetic_start": num(m.balance.kinetic_start),
                "kinetic_end": num(m.balance.kinetic_end),
                "residual": num(m.balance.residual),
            },
            "steps": { "accepted": m.steps.0, "rejected": m.steps.1 },
            "check": s.check.as_ref().map_or(Value::Null, |c| json!({
                "method": "RK4 in the crank angle on the energy equation",
                "steps": c.steps,
                "cycle_time": num(c.cycle_time),
                "omega_end": num(c.omega_end),
                "motor_work": num(c.motor_work),
            })),
            "design": m.design.as_ref().map_or(Value::Null, row),
            "phi": col(r, |x| x.phi),
            "travel": col(r, |x| x.travel),
            "inertia_variable": col(r, |x| x.inertia_variable),
            "inertia_derivative": col(r, |x| x.inertia_derivative),
            "inertia_total": col(r, |x| x.inertia_total),
            "moment_loads": col(r, |x| x.moment_loads),
            "moment_motor": col(r, |x| x.moment_motor),
            "omega": col(r, |x| x.omega),
            "epsilon": col(r, |x| x.epsilon),
            "time": col(r, |x| x.time),
            "motor_speed": col(r, |x| x.motor_speed),
            "motor_work": col(r, |x| x.motor_work),
        },
        "constant_moment": {
            "driving_moment": num(e.driving_moment),
            "work_end": num(e.work_end),
            "omega_end": num(e.omega_end),
            "time_end": num(e.time_end),
            "omega_min": num(e.omega_min),
            "design": e.design.as_ref().map_or(Value::Null, energy_row),
            "phi": col(&e.rows, |x| x.phi),
            "work_loads": col(&e.rows, |x| x.work_loads),
            "work_total": col(&e.rows, |x| x.work_total),
            "omega": col(&e.rows, |x| x.omega),
            "epsilon": col(&e.rows, |x| x.epsilon),
            "time": col(&e.rows, |x| x.time),
        },
    })
}
