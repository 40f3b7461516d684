//! The textbook's П2 engine as a task file: it runs, and each kind of bad
//! input of the engine's loads is refused with exit code 2 and a message
//! naming the field at its place in the file.

use crate::common::{repo, tmm_in, tmp};

fn p2() -> String {
    std::fs::read_to_string(repo().join("examples/textbook/p2-engine.toml")).unwrap()
}

/// Run `text` as `task.toml`: (exit code, stdout, stderr).
fn run_text(name: &str, text: &str) -> (i32, String, String) {
    let d = tmp("engine", name);
    std::fs::write(d.join("task.toml"), text).unwrap();
    let o = tmm_in(&d, &["run", "--no-pdf", "task.toml", "-o", "out"]);
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

/// The 1-based line of the first occurrence of `needle` in `text`.
fn line_of(text: &str, needle: &str) -> usize {
    let at = text.find(needle).unwrap_or_else(|| panic!("`{needle}` not in the task"));
    text[..at].matches('\n').count() + 1
}

/// Replace the first occurrence of `from` (which must be there).
fn first(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "`{from}` not in the task");
    text.replacen(from, to, 1)
}

fn refused(name: &str, text: &str, field: &str, line: usize, what: &str) {
    let (code, _, err) = run_text(name, text);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains(field), "no `{field}` in: {err}");
    assert!(err.contains(&format!("task.toml:{line}:")), "not located at line {line}: {err}");
    assert!(err.contains(what), "no `{what}` in: {err}");
}

#[test]
fn p2_runs_over_the_720_degree_cycle() {
    let (code, out, err) = run_text("runs", &p2());
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("resistance moment of the driven machine M_d = -17.511"), "{out}");
    assert!(out.contains("Balancing torque at the 24 positions"), "{out}");
    assert!(out.contains("Reactions over the cycle"), "{out}");
    // the mean balancing torque over the cycle is the constant resistance
    assert!(out.contains("mean 17.5110 N·m"), "{out}");
}

#[test]
fn a_bore_of_zero_is_refused() {
    let t = first(&p2(), "bore = \"78 mm\"", "bore = \"0 mm\"");
    refused(
        "bore",
        &t,
        "forces.cylinders[0].bore",
        line_of(&t, "bore = \"0 mm\""),
        "must be > 0",
    );
}

#[test]
fn travel_that_does_not_increase_is_refused() {
    let from = "travel = [0, 0.025, 0.05, 0.1, 0.2, 0.3, 0.4,";
    let t = first(&p2(), from, "travel = [0, 0.025, 0.05, 0.1, 0.2, 0.3, 0.3,");
    let line = line_of(&t, "travel = [0, 0.025, 0.05, 0.1, 0.2, 0.3, 0.3,");
    refused(
        "increase",
        &t,
        "forces.cylinders[0].tables.compression.travel[6]",
        line,
        "must increase",
    );
}

#[test]
fn a_table_short_of_the_stroke_is_refused() {
    let t = first(&p2(), "travel = [0, 0.9, 1]", "travel = [0, 0.9, 0.95]");
    let line = line_of(&t, "[forces.cylinders.tables.exhaust]");
    refused("cover", &t, "forces.cylinders[0].tables.exhaust", line, "the whole stroke");
}

#[test]
fn a_process_without_its_table_is_refused() {
    let from = "processes = [\"intake\", \"compression\", \"expansion\", \"exhaust\"]";
    let to = "processes = [\"intake\", \"compression\", \"expansion\", \"outlet\"]";
    let t = first(&p2(), from, to);
    refused(
        "process",
        &t,
        "forces.cylinders[0].processes",
        line_of(&t, to),
        "`outlet` has no pressure table",
    );
}

#[test]
fn bounds_that_do_not_fit_the_cycle_are_refused() {
    let from = "processes = [\"intake\", \"compression\", \"expansion\", \"exhaust\"]\n";
    let bad = "bounds = [\"0 deg\", \"180 deg\", \"360 deg\", \"540 deg\", \"700 deg\"]\n";
    let t = first(&p2(), from, &format!("{from}{bad}"));
    refused("bounds", &t, "forces.cylinders[0].bounds", line_of(&t, bad), "to the cycle's 720°");
}

#[test]
fn a_cycle_of_three_turns_is_refused() {
    let t = first(&p2(), "turns = 2", "turns = 3");
    refused(
        "turns",
        &t,
        "forces.cycle.turns",
        line_of(&t, "turns = 3"),
        "1 turn of the crank (360°) or 2",
    );
}

#[test]
fn a_table_for_no_process_is_refused() {
    let from = "[forces.cylinders.tables.exhaust]\n";
    let stray = "[forces.cylinders.tables.scavenge]\n";
    let t = first(&p2(), from, &format!("{stray}travel = [0, 1]\npressure = [0, 0]\n\n{from}"));
    refused(
        "stray",
        &t,
        "forces.cylinders[0].tables.scavenge",
        line_of(&t, stray),
        "the table `scavenge` is for no process of the cylinder",
    );
}

#[test]
fn a_second_cylinder_on_one_piston_is_refused() {
    // more cylinders (phases) than pistons on their cranks
    let t = first(&p2(), "link = \"5\"\nbore", "link = \"3\"\nbore");
    let at = t.match_indices("[[forces.cylinders]]").nth(1).unwrap().0;
    let line = t[..at].matches('\n').count() + 2;
    refused(
        "piston",
        &t,
        "forces.cylinders[1].link",
        line,
        "the piston `3` already has its cylinder (forces.cylinders[0])",
    );
}

#[test]
fn a_pressure_that_is_not_a_number_is_refused() {
    let t = first(&p2(), "pressure = [0.08, 0.08, 0.05]", "pressure = [0.08, nan, 0.05]");
    refused(
        "nan",
        &t,
        "forces.cylinders[0].tables.exhaust.pressure[1]",
        line_of(&t, "pressure = [0.08, nan, 0.05]"),
        "must be finite, not NaN",
    );
}

#[test]
fn a_shift_outside_the_cycle_is_refused() {
    let t = first(&p2(), "shift = \"360 deg\"", "shift = \"720 deg\"");
    refused(
        "shift",
        &t,
        "forces.cylinders[1].shift",
        line_of(&t, "shift = \"720 deg\""),
        "the shift must be in [0°, 720°)",
    );
}

/// The flywheel's weight at O (the book's G_1Y = −m_M·g in R_10): the
/// massless crank's own balance, R_10 + R_12 + R_14 + G = 0, with
/// R_12 = −R_21, R_14 = −R_41 read from the same position, and G from the
/// disc's mass in the dynamics.
#[test]
fn the_flywheel_weight_is_in_the_frame_reaction_on_the_crank() {
    let d = tmp("engine", "flywheel_weight");
    std::fs::write(d.join("task.toml"), p2()).unwrap();
    let o = tmm_in(&d, &["run", "--no-pdf", "task.toml", "-o", "out"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let read = |f: &str| -> serde_json::Value { serde_json::from_str(&std::fs::read_to_string(d.join("out").join(f)).unwrap()).unwrap() };
    let (f, dy) = (read("forces/forces.json"), read("dynamics/dynamics.json"));
    let g = dy["flywheel"]["mass"].as_f64().unwrap() * 9.81;
    assert!(
        (f["flywheel_weight"].as_f64().unwrap() - g).abs() < 1e-9 * g,
        "{}",
        f["flywheel_weight"]
    );
    let r = f["detail"]["reactions"].as_array().unwrap();
    let get = |from: &str, on: &str| {
        let x = r.iter().find(|x| x["from"] == from && x["on"] == on).unwrap();
        (x["fx"].as_f64().unwrap(), x["fy"].as_f64().unwrap())
    };
    let (r10, r21, r41) = (get("frame", "1"), get("1", "2"), get("1", "4"));
    let sum = (r10.0 - r21.0 - r41.0, r10.1 - r21.1 - r41.1 - g);
    let scale = r10.0.hypot(r10.1);
    assert!(
        sum.0.abs() < 1e-9 * scale && sum.1.abs() < 1e-9 * scale,
        "ΣF on the crank = {sum:?}"
    );
}

/// `--at` takes any angle of the 720° cycle: 420° is the second turn's
/// position of 60°, with the crank in the same place but the second
/// turn's gas forces. The reference is the cycle's own table, computed
/// position by position along the cycle (a different path from the
/// detailed position): the detail at 420° must carry the loads of the
/// table's row at the same cycle angle, and 60° those of the row one turn
/// earlier.
#[test]
fn at_takes_an_angle_of_the_second_turn() {
    let d = tmp("engine", "at-420");
    std::fs::write(d.join("task.toml"), p2()).unwrap();
    let json = |at: &str| -> serde_json::Value {
        let o = tmm_in(&d, &["forces", "task.toml", "--at", at, "--json"]);
        assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
        serde_json::from_slice(&o.stdout).unwrap()
    };
    let (a, b) = (json("60 deg"), json("420 deg"));
    let psi = |j: &serde_json::Value| j["detail"]["psi"].as_f64().unwrap();
    let turn = 2.0 * std::f64::consts::PI;
    assert!((psi(&b) - psi(&a) - turn).abs() < 1e-9, "{} {}", psi(&a), psi(&b));
    let fx = |row: &serde_json::Value, link: &str| row["loads"][link]["external_force"][0].as_f64().unwrap();
    for (j, p) in [(&a, psi(&a)), (&b, psi(&b))] {
        let rows = j["positions"].as_array().unwrap();
        let row = rows
            .iter()
            .find(|r| (r["psi"].as_f64().unwrap() - p).abs() < 1e-9)
            .unwrap_or_else(|| panic!("no row of the cycle at ψ = {p}"));
        for link in ["3", "5"] {
            let (x, y) = (fx(&j["detail"], link), fx(row, link));
            assert!(
                (x - y).abs() <= 1e-9 * y.abs().max(1.0),
                "link {link} at ψ = {p}: detail {x}, table {y}"
            );
        }
    }
    // the two turns' gas forces differ (the cylinders' phases swap)
    assert!((fx(&a["detail"], "3") - fx(&b["detail"], "3")).abs() > 100.0);
}
