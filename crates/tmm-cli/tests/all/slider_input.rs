//! A linkage driven by a slider (examples/slider-input.toml) end to end: the
//! JSON's positions against the rocker's angle found here in closed form
//! (two circles' intersection) and its velocity analogue against the
//! closed form's central difference; `tmm run` whole with the note; the
//! crank-only sections refused at the input; every bad input located with
//! exit code 2.

use std::process::Output;

use crate::common::{self, json};

const EXAMPLE: &str = "examples/slider-input.toml";

fn tmm(args: &[&str]) -> Output {
    common::tmm_in(&common::repo(), args)
}

/// The rocker DC's angle with the slider B at (s, 0), derived here: C is on
/// the circles |BC| = 0.25 m about B and |DC| = 0.15 m about D = (0.15, 0.2),
/// on the left of B → D (above the line BD).
fn rocker_angle(s: f64) -> f64 {
    let (bx, by, dx, dy, l2, l3) = (s, 0.0, 0.15, 0.2, 0.25, 0.15);
    let (ex, ey) = (dx - bx, dy - by);
    let d = ex.hypot(ey);
    // the foot of C on BD at distance a from B, and its height h
    let a = (l2 * l2 - l3 * l3 + d * d) / (2.0 * d);
    let h = (l2 * l2 - a * a).sqrt();
    let (ux, uy) = (ex / d, ey / d);
    let (cx, cy) = (bx + a * ux - h * uy, by + a * uy + h * ux);
    (cy - dy).atan2(cx - dx)
}

#[test]
fn positions_and_analogues_match_the_closed_form() {
    let d = json(&tmm(&["linkage", EXAMPLE, "--json"]));
    assert_eq!(d["input"]["kind"], "slider");
    assert_eq!(common::number(&d, "/input/speed"), 0.5);
    assert_eq!(d["structure"]["formula"], "I(0,1) → II(2,3)");
    let rows = d["positions"].as_array().unwrap();
    assert_eq!(rows.len(), 13, "12 equal steps over the travel, both ends");
    let th0 = rocker_angle(0.0);
    let mut worst = (0.0f64, 0.0f64, 0.0f64);
    for r in rows {
        let s = common::number(r, "/s");
        let x = common::number(r, "/output/x");
        let xp = common::number(r, "/output/dx_ds");
        let omega = common::number(r, "/links/3/omega");
        let h = 1e-6;
        let fd = tmm_geom::angle::diff(rocker_angle(s - h), rocker_angle(s + h)) / (2.0 * h);
        worst.0 = worst.0.max(tmm_geom::angle::diff(th0 + x, rocker_angle(s)).abs());
        worst.1 = worst.1.max((xp - fd).abs());
        // ω3 = dθ3/ds · v
        worst.2 = worst.2.max((omega - xp * 0.5).abs());
    }
    assert!(worst.0 < 1e-12 && worst.1 < 1e-7 && worst.2 < 1e-12, "{worst:?}");
    // the plans at s = 40 mm: the slider's velocity image is v along the guide
    assert_eq!(common::number(&d, "/plans/s"), 0.04);
    let vb = d["plans"]["velocity"]
        .as_array()
        .unwrap()
        .iter()
        .find(|v| v["label"] == "V_B")
        .unwrap();
    assert!((common::number(vb, "/to/0") - 0.5).abs() < 1e-15 && common::number(vb, "/to/1").abs() < 1e-15);
}

#[test]
fn runs_whole_with_its_note() {
    let dir = common::tmp("slider_input", "run");
    let o = tmm(&["run", EXAMPLE, "--out", dir.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for f in [
        "note.pdf",
        "linkage/positions.svg",
        "linkage/velocity-plan.svg",
        "linkage/diagram-ds.svg",
    ] {
        assert!(dir.join(f).is_file(), "{f}");
    }
    let svg = std::fs::read_to_string(dir.join("linkage/positions.svg")).unwrap();
    // the travel's ends are marked with their s
    assert!(svg.contains("s = 0 мм") && svg.contains("s = 120 мм"), "the travel's ends");
    // the linkage subcommand's help says how to give a slider input
    let (code, help, _) = common::run(&["linkage", "--help"]);
    assert_eq!(code, 0);
    assert!(help.contains("slider") && help.contains("travel"), "{help}");
}

/// `tmm linkage` on the example edited: refused with its message.
fn bad(name: &str, from: &str, to: &str) -> String {
    common::refused_edit("slider_input", EXAMPLE, "linkage", name, from, to)
}

#[test]
fn bad_inputs_exit_2_naming_the_field() {
    let e = bad("decreasing", "travel = [\"0 mm\", \"120 mm\"]", "travel = [\"120 mm\", \"0 mm\"]");
    assert!(
        e.contains("task.toml:12:") && e.contains("linkage.travel: the travel must increase"),
        "{e}"
    );
    let e = bad("zero", "speed = \"0.5 m/s\"", "speed = \"0 m/s\"");
    assert!(
        e.contains("task.toml:11:") && e.contains("linkage.input.speed") && e.contains("must move"),
        "{e}"
    );
    let e = bad("unlisted", "slider = \"1\"", "slider = \"7\"");
    assert!(e.contains("linkage.input.slider: unknown link `7`"), "{e}");
    let e = bad("not a slider", "slider = \"1\"", "slider = \"3\"");
    assert!(e.contains("linkage.input.slider") && e.contains("slides on no guide"), "{e}");
    // the driving slider on a moving guide (the rocker)
    let e = bad(
        "moving guide",
        "guide = { link = \"frame\", through = \"O\", angle = \"0 deg\" }",
        "guide = { link = \"3\", through = [\"0 mm\", \"0 mm\"], angle = \"0 deg\" }",
    );
    assert!(e.contains("linkage.input.slider") && e.contains("guide fixed to the frame"), "{e}");
    let e = bad("no travel", "travel = [\"0 mm\", \"120 mm\"]\n", "");
    assert!(e.contains("linkage.travel") && e.contains("needs its travel"), "{e}");
    let e = bad("at", "at = \"40 mm\"", "at = \"200 mm\"");
    assert!(
        e.contains("task.toml:13:") && e.contains("linkage.at") && e.contains("outside the travel"),
        "{e}"
    );
    let e = bad("crank key", "speed = \"0.5 m/s\"", "speed = \"0.5 m/s\", direction = \"cw\"");
    assert!(e.contains("linkage.input.direction") && e.contains("belongs to a crank"), "{e}");
    let e = bad("unit", "speed = \"0.5 m/s\"", "speed = \"0.5 rad/s\"");
    assert!(e.contains("linkage.input.speed"), "{e}");
    // a travel past the rocker's reach: where it stops assembling
    let e = bad("reach", "\"120 mm\"]", "\"600 mm\"]");
    assert!(
        e.contains("task.toml:12:") && e.contains("does not assemble over the whole travel") && e.contains("only up to s = 496.4"),
        "{e}"
    );
}

#[test]
fn sections_that_need_a_crank_refuse_the_slider() {
    let text = std::fs::read_to_string(common::repo().join(EXAMPLE)).unwrap();
    let dir = common::tmp("slider_input", "forces");
    let p = dir.join("task.toml");
    std::fs::write(
        &p,
        format!("{text}\n[forces]\ngravity = \"9.81 m/s^2\"\n[forces.links.2]\nmass = \"3 kg\"\ninertia = \"0.02 kg m^2\"\n"),
    )
    .unwrap();
    let o = tmm(&["run", p.to_str().unwrap(), "--out", dir.join("out").to_str().unwrap(), "--no-pdf"]);
    assert_eq!(o.status.code(), Some(2));
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        e.contains("task.toml:11:") && e.contains("linkage.input.slider: [forces] needs a crank"),
        "{e}"
    );
}
