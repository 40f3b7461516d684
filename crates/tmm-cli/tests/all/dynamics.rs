//! `tmm dynamics` and the `[dynamics]` section end to end: the JSON contract,
//! the energy equation of the machine re-derived from the printed arrays,
//! the flywheel's size from its inertia, the exact inertia against the core
//! on another grid, the kinetostatics with the true crank motion against the
//! crank shaft's equation of motion, `tmm run`, and every bad input reported
//! with its field and exit code 2.

use std::path::PathBuf;
use std::process::Output;

use crate::common::{self, json};

use serde_json::Value;
use tmm_testkit::examples;

fn tmm(args: &[&str]) -> Output {
    common::tmm_in(&common::repo(), args)
}

fn tmp(name: &str) -> PathBuf {
    common::tmp("dynamics", name)
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn arr(v: &Value) -> Vec<f64> {
    v.as_array().unwrap_or_else(|| panic!("not an array: {v}")).iter().map(f).collect()
}

fn seed001() -> Value {
    json(&tmm(&["dynamics", "examples/seed-001-fourbar.toml", "--json"]))
}

#[test]
fn json_contract_keys() {
    let d = seed001();
    let arrays = [
        "phi",
        "reduced_inertia_variable",
        "reduced_moment",
        "work",
        "kinetic_energy_change",
        "omega",
        "epsilon",
    ];
    let n = d["phi"].as_array().unwrap().len();
    assert_eq!(n, 361, "1° steps over the cycle with the default 3600 intervals");
    for k in arrays {
        assert_eq!(d[k].as_array().unwrap_or_else(|| panic!("{k}")).len(), n, "{k}");
    }
    for k in [
        "driving_moment",
        "inertia_constant_given",
        "flywheel_inertia",
        "omega_max",
        "omega_min",
        "delta",
        "cycle_time",
    ] {
        assert!(d[k].is_f64(), "{k}: {}", d[k]);
    }
    for k in ["mertsalov", "wittenbauer", "exact"] {
        assert!(d["required_inertia"][k].is_f64(), "{k}");
    }
    // the old misspelt keys are kept for one release, equal to the new ones
    assert_eq!(d["required_inertia"]["merkalov"], d["required_inertia"]["mertsalov"]);
    assert_eq!(d["merkalov"], d["mertsalov"]);
    assert!(d["mertsalov"]["energy_swing"].is_f64());
    for k in ["diameter", "width", "mass"] {
        assert!(d["flywheel"][k].is_f64(), "{k}");
    }
    // a constant driving moment has no run-up from rest (the JSON and the
    // text say why), and δ measured on the steady cycle integrated in time is
    // the requested one to 1e-4
    let r = &d["runup"];
    assert!(r["time"].is_null() && r["from_rest"] == false, "{r}");
    assert!((f(&r["delta"]) - 0.02).abs() < 1e-4, "{r}");
    assert!(r["why"].as_str().unwrap().contains("constant driving moment"), "{r}");
    let o = tmm(&["dynamics", "examples/seed-001-fourbar.toml"]);
    assert!(o.status.success());
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.contains("run-up: none") && text.contains("constant driving moment"), "{text}");
    // the 12 positions and the three methods side by side
    for w in ["Mertsalov", "Wittenbauer", "exact", "flywheel size", "δ achieved", "cycle time"] {
        assert!(text.contains(w), "{w}");
    }
}

/// δ in the JSON is the one asked for (the flywheel is sized for it).
#[test]
fn delta_is_the_requested_one() {
    let d = seed001();
    assert!((f(&d["delta"]) - 0.02).abs() < 1e-9, "{}", d["delta"]);
    assert!((f(&d["delta_requested"]) - 0.02).abs() < 1e-15);
    let d4 = json(&tmm(&["dynamics", "examples/seed-004-two-sliders.toml", "--json"]));
    assert!((f(&d4["delta"]) - 0.05).abs() < 1e-9, "{}", d4["delta"]);
    // and so are the extreme speeds about the nominal one, 900 rpm
    let wm = 900.0 * std::f64::consts::PI / 30.0;
    assert!((f(&d["omega_max"]) - wm * 1.01).abs() < 1e-9 * wm);
    assert!((f(&d["omega_min"]) - wm * 0.99).abs() < 1e-9 * wm);
}

/// The energy equation (I_I + I_II)·ω²/2 = T₀ + ΔT, with ΔT = M_d·φ + A_c,
/// A_c = ∫M_c dφ and M_d = −A_c(2π)/2π, re-derived from the printed arrays
/// alone: it gives back the printed ω at every node, its extremes give δ,
/// and d(ω²/2)/dφ by central differences gives ε.
#[test]
fn energy_equation_from_the_json_arrays() {
    let d = seed001();
    let phi = arr(&d["phi"]);
    let ii = arr(&d["reduced_inertia_variable"]);
    let mc = arr(&d["reduced_moment"]);
    let ac = arr(&d["work"]);
    let dt = arr(&d["kinetic_energy_change"]);
    let w = arr(&d["omega"]);
    let e = arr(&d["epsilon"]);
    let md = f(&d["driving_moment"]);
    let n = phi.len() - 1;
    let tau = 2.0 * std::f64::consts::PI;
    assert!((phi[n] - tau).abs() < 1e-12);
    // M_d from the cycle work
    assert!((md + ac[n] / tau).abs() < 1e-12 * md.abs());
    // A_c by the trapezoid rule on the 1° grid (O(h²) and the kinks at the dead positions)
    let mut a = 0.0;
    let scale = ac.iter().fold(0.0f64, |s, x| s.max(x.abs()));
    for k in 1..=n {
        a += 0.5 * (mc[k] + mc[k - 1]) * (phi[k] - phi[k - 1]);
        assert!((a - ac[k]).abs() < 2e-4 * scale, "A_c at {k}: {a} vs {}", ac[k]);
    }
    for k in 0..=n {
        assert!((dt[k] - (md * phi[k] + ac[k])).abs() < 1e-9 * scale, "ΔT at {k}");
    }
    // the constant inertia the motion runs with: the exact requirement (the given one is less)
    let ic = f(&d["required_inertia"]["exact"]);
    assert!(f(&d["inertia_constant_given"]) < ic);
    let t0 = (ic + ii[0]) * w[0] * w[0] / 2.0 - dt[0];
    let om: Vec<f64> = (0..=n).map(|k| (2.0 * (t0 + dt[k]) / (ic + ii[k])).sqrt()).collect();
    for k in 0..=n {
        assert!((om[k] - w[k]).abs() < 1e-9 * w[k], "ω at {k}: {} vs {}", om[k], w[k]);
    }
    let (hi, lo) = om.iter().fold((0.0f64, f64::INFINITY), |(h, l), &x| (h.max(x), l.min(x)));
    let delta = (hi - lo) / (0.5 * (hi + lo));
    // the grid's extremes fall short of the true ones by O(h²)
    assert!((delta - 0.02).abs() < 1e-3 * 0.02, "δ from the arrays {delta}");
    assert!(hi <= f(&d["omega_max"]) * (1.0 + 1e-12) && lo >= f(&d["omega_min"]) * (1.0 - 1e-12));
    // ε = d(ω²/2)/dφ
    let emax = e.iter().fold(0.0f64, |s, x| s.max(x.abs()));
    for k in 1..n {
        let fd = (om[k + 1].powi(2) - om[k - 1].powi(2)) / 4.0 / (phi[k + 1] - phi[k]);
        assert!((fd - e[k]).abs() < 2e-2 * emax, "ε at {k}: {fd} vs {}", e[k]);
    }
    // Mertsalov's method from the arrays: ΔT_I = swing of ΔT − I_II·ω_m²/2
    let wm = 900.0 * std::f64::consts::PI / 30.0;
    let ti: Vec<f64> = (0..=n).map(|k| dt[k] - ii[k] * wm * wm / 2.0).collect();
    let swing = ti.iter().fold(f64::NEG_INFINITY, |s, &x| s.max(x)) - ti.iter().fold(f64::INFINITY, |s, &x| s.min(x));
    let im = swing / (0.02 * wm * wm);
    assert!((im / f(&d["required_inertia"]["mertsalov"]) - 1.0).abs() < 1e-3, "{im}");
}

/// The flywheel's size from its inertia: a steel disc of b = 0.2·D has
/// J = ρ·π·b·D⁴/32 and m = ρ·π·b·D²/4; its inertia is the exact requirement
/// less what the crank shaft already carries.
#[test]
fn flywheel_size_from_its_inertia() {
    let d = seed001();
    let j = f(&d["flywheel_inertia"]);
    assert!((j - (f(&d["required_inertia"]["exact"]) - f(&d["inertia_constant_given"]))).abs() < 1e-12);
    // the crank alone: J_S1 + m1·(l/2)² = 0.1·1.2·0.12² + 1.2·0.06²
    assert!((f(&d["inertia_constant_given"]) - (0.1 * 1.2 * 0.0144 + 1.2 * 0.0036)).abs() < 1e-12);
    let (dd, b, m) = (f(&d["flywheel"]["diameter"]), f(&d["flywheel"]["width"]), f(&d["flywheel"]["mass"]));
    let rho = 7850.0;
    let pi = std::f64::consts::PI;
    assert!((b - 0.2 * dd).abs() < 1e-12);
    assert!((rho * pi * b * dd.powi(4) / 32.0 / j - 1.0).abs() < 1e-10);
    assert!((rho * pi * b * dd * dd / 4.0 / m - 1.0).abs() < 1e-10);
}

/// The exact inertia does not depend on the grid: the printed value (3600
/// intervals) against the core called directly with 720 intervals.
#[test]
fn exact_inertia_against_the_core_on_another_grid() {
    let d = seed001();
    let src = tmm_report::TaskSource::new("seed-001.toml", examples::text("seed-001-fourbar.toml"));
    let (l, ft, mut dt) = tmm_report::dynamics::load(&src).unwrap().unwrap();
    dt.spec.points = 720;
    let core = tmm_linkage::dynamics::Dynamics::compute(&l.mech, &ft.loads, &dt.spec).unwrap();
    for k in ["exact", "wittenbauer", "mertsalov"] {
        let v = f(&d["required_inertia"][k]);
        let c = match k {
            "exact" => core.required.exact,
            "wittenbauer" => core.required.wittenbauer,
            _ => core.required.mertsalov,
        };
        assert!((v / c - 1.0).abs() < 1e-6, "{k}: {v} vs {c}");
    }
    // Wittenbauer's construction and the exact motion agree
    assert!((f(&d["required_inertia"]["wittenbauer"]) / f(&d["required_inertia"]["exact"]) - 1.0).abs() < 1e-6);
}

/// With `crank_motion = "dynamics"` the kinetostatics uses the true ω₁, ε₁;
/// the crank shaft's own equation of motion then says the balancing torque
/// is the constant driving moment less the inertia torque of the constant
/// masses on the shaft other than the crank: M_b = M_d − (I_I − I_crank)·ε₁.
#[test]
fn kinetostatics_with_the_true_crank_motion() {
    let text = examples::text("seed-001-fourbar.toml").replace(
        "at = \"15 deg\"\n\n[[forces.resistance]]",
        "at = \"15 deg\"\ncrank_motion = \"dynamics\"\n\n[[forces.resistance]]",
    );
    assert!(text.contains("crank_motion"));
    let dir = tmp("crank-motion");
    let p = dir.join("task.toml");
    std::fs::write(&p, text).unwrap();
    let fo = json(&tmm(&["forces", p.to_str().unwrap(), "--json"]));
    let dy = json(&tmm(&["dynamics", p.to_str().unwrap(), "--json"]));
    assert_eq!(fo["crank_motion"], "dynamics");
    let md = f(&dy["driving_moment"]); // ccw crank: signed as the crank turns
    let extra = f(&dy["required_inertia"]["exact"]) - f(&dy["inertia_given"]["crank"]);
    let positions = fo["positions"].as_array().unwrap();
    assert!(positions.len() >= 12);
    let mut varied = 0.0f64;
    for r in positions {
        let (w, e) = (f(&r["omega1"]), f(&r["epsilon1"]));
        varied = varied.max(e.abs());
        let expect = md - extra * e;
        assert!(
            (f(&r["balancing_moment"]) - expect).abs() < 1e-6 * md.abs(),
            "{} vs {expect}",
            r["balancing_moment"]
        );
        assert!(w > f(&dy["omega_min"]) * (1.0 - 1e-9) && w < f(&dy["omega_max"]) * (1.0 + 1e-9));
    }
    assert!(varied > 10.0, "the crank does accelerate");
    // the default is the constant speed
    let fc = json(&tmm(&["forces", "examples/seed-001-fourbar.toml", "--json"]));
    assert_eq!(fc["crank_motion"], "constant");
    assert!(fc["positions"].as_array().unwrap().iter().all(|r| f(&r["epsilon1"]) == 0.0));
}

#[test]
fn motor_run_up() {
    let d = json(&tmm(&["dynamics", "examples/seed-003-sixbar.toml", "--json"]));
    let r = &d["runup"];
    assert!(f(&r["time"]) > 0.0 && f(&r["delta"]) > 0.0 && r["from_rest"] == true, "{r}");
    assert!((f(&d["delta"]) - 0.05).abs() < 1e-9);
    // the rim: J = ρπb(D⁴ − d⁴)/32 with d = D − 2h, h = 0.1·D, b = 0.2·D
    let (dd, b, h) = (
        f(&d["flywheel"]["diameter"]),
        f(&d["flywheel"]["width"]),
        f(&d["flywheel"]["thickness"]),
    );
    assert!((b - 0.2 * dd).abs() < 1e-12 && (h - 0.1 * dd).abs() < 1e-12);
    let di = dd - 2.0 * h;
    let j = 7200.0 * std::f64::consts::PI * b * (dd.powi(4) - di.powi(4)) / 32.0;
    assert!((j / f(&d["flywheel_inertia"]) - 1.0).abs() < 1e-10);
    let dir = tmp("svg");
    let o = tmm(&["dynamics", "examples/seed-003-sixbar.toml", "--svg", dir.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for s in [
        "moments",
        "work",
        "inertia",
        "energy-constant",
        "wittenbauer",
        "omega",
        "epsilon",
        "runup",
    ] {
        assert!(dir.join(format!("{s}.svg")).exists(), "{s}");
    }
}

#[test]
fn tmm_run_on_the_default_task_writes_dynamics() {
    let dir = tmp("run");
    let o = tmm(&["run", "--no-pdf", "-o", dir.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for f in [
        "dynamics/dynamics.json",
        "dynamics/dynamics.txt",
        "dynamics/omega.svg",
        "dynamics/wittenbauer.svg",
    ] {
        assert!(dir.join(f).exists(), "{f}");
    }
    let rep: Value = serde_json::from_str(&std::fs::read_to_string(dir.join("report.json")).unwrap()).unwrap();
    assert!((f(&rep["dynamics"]["delta"]) - 0.02).abs() < 1e-9);
    assert!(!dir.join("dynamics/runup.svg").exists());
}

/// A task from seed 001 with its `[dynamics]` replaced by `dynamics`; the
/// error message of `tmm dynamics`.
fn bad(name: &str, dynamics: &str) -> String {
    let base = examples::text("seed-001-fourbar.toml");
    let cut = base.find("\n[dynamics]").unwrap();
    bad_text(name, &format!("{}\n{dynamics}", &base[..cut]), "dynamics")
}

fn bad_text(name: &str, text: &str, cmd: &str) -> String {
    let dir = tmp(name);
    let p = dir.join("task.toml");
    std::fs::write(&p, text).unwrap();
    let o = tmm(&[cmd, p.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2), "{name}: stdout {}", String::from_utf8_lossy(&o.stdout));
    assert!(o.stdout.is_empty());
    String::from_utf8_lossy(&o.stderr).to_string()
}

#[test]
fn bad_inputs_exit_2_naming_the_field() {
    let e = bad("zero", "[dynamics]\ndelta = 0\n");
    assert!(e.contains("dynamics.delta") && e.contains("(0, 1)"), "{e}");
    let e = bad("one", "[dynamics]\ndelta = 1\n");
    assert!(e.contains("dynamics.delta"), "{e}");
    let e = bad("missing", "[dynamics]\ndriving = \"constant\"\n");
    assert!(e.contains("dynamics.delta"), "{e}");
    let e = bad("unknown", "[dynamics]\ndelta = 0.02\nflywheel_mass = 3\n");
    assert!(e.contains("flywheel_mass"), "{e}");
    // 1000 rpm through u = 2 turns the crank at most at 500 rpm < 900 rpm
    let e = bad(
        "slow-motor",
        "[dynamics]\ndelta = 0.02\n[dynamics.motor]\nsynchronous_speed = \"1000 rpm\"\nnominal_speed = \"950 rpm\"\nnominal_torque = \"100 N m\"\nratio = 2\n",
    );
    assert!(e.contains("dynamics.motor.synchronous_speed") && e.contains("too slow"), "{e}");
    // M_d = 81.4 N·m on the crank, 81.4/1.5 = 54 N·m on the motor shaft > 20 N·m
    let e = bad(
        "weak-motor",
        "[dynamics]\ndelta = 0.02\n[dynamics.motor]\nsynchronous_speed = \"1500 rpm\"\nnominal_speed = \"1400 rpm\"\nnominal_torque = \"20 N m\"\nratio = 1.5\n",
    );
    assert!(e.contains("dynamics.motor.nominal_torque") && e.contains("too weak"), "{e}");
    let e = bad(
        "rim",
        "[dynamics]\ndelta = 0.02\n[dynamics.flywheel]\nshape = \"rim\"\nthickness_ratio = 0.7\n",
    );
    assert!(e.contains("dynamics.flywheel.thickness_ratio"), "{e}");
    let e = bad("place", "[dynamics]\ndelta = 0.02\n[dynamics.flywheel]\nplace = \"motor\"\n");
    assert!(e.contains("dynamics.flywheel.place"), "{e}");
    // the place in the file: line and column of the value
    let base = examples::text("seed-001-fourbar.toml");
    let cut = base.find("\n[dynamics]").unwrap();
    let line = base[..cut].matches('\n').count() + 3;
    let e = bad("located", "[dynamics]\ndelta = -0.5\n");
    assert!(e.contains(&format!("task.toml:{line}:9: dynamics.delta")), "{e}");
    // no [forces]: the loads are missing
    let base = examples::text("seed-001-fourbar.toml");
    let (a, b) = (base.find("\n[forces]").unwrap(), base.find("\n[dynamics]").unwrap());
    let e = bad_text("no-forces", &format!("{}{}", &base[..a], &base[b..]), "dynamics");
    assert!(e.contains("[forces]") && e.contains("dynamics"), "{e}");
    // crank_motion = "dynamics" without [dynamics]
    let text = base[..b].replace(
        "at = \"15 deg\"\n\n[[forces.resistance]]",
        "at = \"15 deg\"\ncrank_motion = \"dynamics\"\n\n[[forces.resistance]]",
    );
    let e = bad_text("no-dynamics", &text, "forces");
    assert!(e.contains("forces.crank_motion") && e.contains("[dynamics]"), "{e}");
    let text = base.replace(
        "at = \"15 deg\"\n\n[[forces.resistance]]",
        "at = \"15 deg\"\ncrank_motion = \"true\"\n\n[[forces.resistance]]",
    );
    let e = bad_text("bad-crank-motion", &text, "forces");
    assert!(e.contains("forces.crank_motion"), "{e}");
    // and `tmm run` refuses the whole run
    let e = bad_text("run", &format!("{}\n[dynamics]\ndelta = 2\n", &base[..b]), "run");
    assert!(e.contains("dynamics.delta"), "{e}");
}

/// Extreme values through the command line: each refused with exit code 2
/// and a message naming the field in a readable form (no three-hundred-digit
/// numbers, no NaN), or computed with every number finite.
#[test]
fn extreme_inputs_exit_2_or_finite_results() {
    let refused = [
        ("neg", "[dynamics]\ndelta = -0.1\n", "dynamics.delta"),
        ("huge-delta", "[dynamics]\ndelta = 1e300\n", "not 1e300"),
        (
            "huge-inertia",
            "[dynamics]\ndelta = 0.02\n[dynamics.inertia]\ncrank_shaft = \"1e306 kg m^2\"\n",
            "dynamics.inertia.crank_shaft",
        ),
        (
            "huge-motor",
            "[dynamics]\ndelta = 0.02\n[dynamics.motor]\nsynchronous_speed = \"1e300 rpm\"\nnominal_speed = \"1400 rpm\"\nnominal_torque = \"60 N m\"\nratio = 1e290\n",
            "dynamics.motor.synchronous_speed",
        ),
        // 1400 rpm / 1.6 = 875 rpm nominal: under the seed's 81.4 N·m the crank settles near 884 rpm < ω_min = 891 rpm
        (
            "slower-than-needed",
            "[dynamics]\ndelta = 0.02\n[dynamics.motor]\nsynchronous_speed = \"1500 rpm\"\nnominal_speed = \"1400 rpm\"\nnominal_torque = \"60 N m\"\nratio = 1.6\n",
            "dynamics.motor.ratio: the motor is slower than the crank needs",
        ),
    ];
    for (name, dynamics, want) in refused {
        let e = bad(name, dynamics);
        assert!(e.contains(want), "{name}: {e}");
        assert!(
            !e.contains("0000000000") && !e.contains("NaN") && !e.contains("panicked"),
            "{name}: {e}"
        );
    }
    // [forces] without the useful resistance: no loads to drive
    let base = examples::text("seed-001-fourbar.toml");
    let (a, b) = (base.find("[[forces.resistance]]").unwrap(), base.find("[forces.strength]").unwrap());
    let e = bad_text("no-loads", &format!("{}{}", &base[..a], &base[b..]), "dynamics");
    assert!(e.contains("forces") && e.contains("no resisting work"), "{e}");
    // a tiny δ needs a huge flywheel, still finite and exact
    let cut = base.find("\n[dynamics]").unwrap();
    for (name, delta) in [("tiny", "1e-9"), ("large", "0.5")] {
        let dir = tmp(name);
        let p = dir.join("task.toml");
        std::fs::write(&p, format!("{}\n[dynamics]\ndelta = {delta}\n", &base[..cut])).unwrap();
        let o = tmm(&["dynamics", p.to_str().unwrap(), "--json"]);
        let text = String::from_utf8_lossy(&o.stdout).to_string();
        assert!(!text.contains("NaN") && !text.contains("non-finite"), "{name}");
        let d = json(&o);
        let want: f64 = delta.parse().unwrap();
        assert!((f(&d["delta"]) / want - 1.0).abs() < 1e-6, "{name}: {}", d["delta"]);
        let r = &d["required_inertia"];
        assert!((f(&r["wittenbauer"]) / f(&r["exact"]) - 1.0).abs() < 1e-6, "{name}: {r}");
    }
}
