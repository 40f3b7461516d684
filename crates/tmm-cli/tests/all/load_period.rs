//! The period of the summed loads: the textbook's П2 (two four-stroke
//! cylinders on cranks at 180°, the second a half cycle later) is found to
//! repeat every turn of its 720° cycle, as the book says and uses
//! (Chernaya & Timofeev 2019, П2: the dynamics over [0, 2π]); one of its
//! cylinders alone repeats only every 720°. The flywheel over the first
//! turn is the one over the cycle: the swing of Mertsalov's T_I and the
//! work over 0…360° are recomputed here from the tables of the run.

use std::f64::consts::PI;

use crate::common::{json, repo, tmm_in, tmp};

fn dynamics(dir: &std::path::Path, file: &str) -> serde_json::Value {
    let o = tmm_in(dir, &["dynamics", file, "--json"]);
    json(&o)
}

fn arr(v: &serde_json::Value, key: &str) -> Vec<f64> {
    v[key].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect()
}

#[test]
fn p2_summed_loads_repeat_every_turn_and_give_the_same_flywheel() {
    let d = &dynamics(&repo(), "examples/textbook/p2-engine.toml");

    assert!((d["cycle_period"].as_f64().unwrap() - 4.0 * PI).abs() < 1e-12);
    assert!(
        (d["load_period"].as_f64().unwrap() - 2.0 * PI).abs() < 1e-12,
        "{}",
        d["load_period"]
    );
    let phi = arr(d, "phi");
    let n = phi.len() - 1;
    assert_eq!(n % 2, 0);
    let half = n / 2;
    assert!((phi[half] - 2.0 * PI).abs() < 1e-9);
    // the work of the loads over the first turn is half that over the cycle
    let work = arr(d, "work");
    assert!(
        (work[half] - 0.5 * work[n]).abs() < 1e-9 * work[n].abs(),
        "{} {}",
        work[half],
        work[n]
    );
    // Mertsalov's swing over the first turn: T_I = ΔT − I_II·ω_m²/2
    let (de, ii) = (arr(d, "kinetic_energy_change"), arr(d, "reduced_inertia_variable"));
    let w = d["omega_nominal"].as_f64().unwrap();
    let swing_over = |to: usize| {
        let t: Vec<f64> = (0..=to).map(|k| de[k] - 0.5 * ii[k] * w * w).collect();
        t.iter().cloned().fold(f64::MIN, f64::max) - t.iter().cloned().fold(f64::MAX, f64::min)
    };
    let (first, all) = (swing_over(half), swing_over(n));
    assert!((first - all).abs() < 1e-9 * all, "first turn {first}, whole cycle {all}");
    // and the run's swing, refined between the nodes, is within the
    // tables' spacing of it
    let whole = d["mertsalov"]["energy_swing"].as_f64().unwrap();
    assert!((first / whole - 1.0).abs() < 1e-3, "first turn {first}, the run's {whole}");
    // the extremes given within the first turn, in the book's ranges:
    // ω_max (T_I max) in 140°…180°, ω_min (T_I min) in 0°…30°
    let deg = |p: &str| d.pointer(p).unwrap().as_f64().unwrap().to_degrees();
    let (mx, mn) = (deg("/mertsalov/phi_max"), deg("/mertsalov/phi_min"));
    assert!((140.0..=180.0).contains(&mx), "T_I max at {mx}°");
    assert!((0.0..=30.0).contains(&mn), "T_I min at {mn}°");
    // and the exact method's Φ_A (ω_max), Φ_B (ω_min) in the book's ranges
    let (fa, fb) = (deg("/exact/phi_max"), deg("/exact/phi_min"));
    assert!((140.0..=180.0).contains(&fa), "Φ_A = {fa}°");
    assert!((0.0..=30.0).contains(&fb), "Φ_B = {fb}°");
}

#[test]
fn one_cylinder_alone_repeats_only_every_720_degrees() {
    let text = std::fs::read_to_string(repo().join("examples/textbook/p2-engine.toml")).unwrap();
    // drop the second cylinder: from its header to the dynamics
    let a = text.match_indices("[[forces.cylinders]]").nth(1).unwrap().0;
    let b = text.find("# Dynamics:").unwrap();
    let one = format!("{}{}", &text[..a], &text[b..]);
    let dir = tmp("load_period", "one");
    std::fs::write(dir.join("task.toml"), one).unwrap();
    let d = &dynamics(&dir, "task.toml");

    assert!(
        (d["load_period"].as_f64().unwrap() - 4.0 * PI).abs() < 1e-12,
        "{}",
        d["load_period"]
    );
}

#[test]
fn p2_text_says_the_summed_loads_repeat_every_turn() {
    let o = tmm_in(&repo(), &["dynamics", "examples/textbook/p2-engine.toml"]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success());
    assert!(out.contains("The summed loads repeat every 360° of the 720° cycle"), "{out}");
}
