//! The geometry as analysed and the periods in the outputs: every link's
//! lengths in the linkage JSON (against the textbook's design rules worked
//! here: П2's l_OA = H/2 with H = V_Bср·T/2, l_AB = 3.8·l_OA; П3's rocker
//! l_CB = 0.5 m, l_CD = 1.4·l_CB), the time of one turn T = 60/n1 and the
//! machine's cycle time (two turns for П2's four-stroke engine) in the
//! linkage and dynamics JSON and in the tables.

use std::f64::consts::PI;

use crate::common::{json, number, repo, tmm_in};

fn doc(cmd: &str, file: &str) -> serde_json::Value {
    let o = tmm_in(&repo(), &[cmd, file, "--json"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    json(&o)
}

#[test]
fn p2_link_lengths_and_periods() {
    let l = doc("linkage", "examples/textbook/p2-engine.toml");
    // the book's design rules: T = 60/n1, H = V·T/2, l_OA = H/2, l_AB = 3.8 l_OA
    let t = 60.0 / 1300.0;
    let l_oa = 5.0 * t / 2.0 / 2.0;
    let g = |p: &str| number(&l, p);
    assert!(
        (g("/geometry/links/1/lengths/OA") - l_oa).abs() < 1e-12,
        "{}",
        g("/geometry/links/1/lengths/OA")
    );
    assert!((g("/geometry/links/1/lengths/OD") - l_oa).abs() < 1e-12);
    assert!((g("/geometry/links/1/lengths/AD") - 2.0 * l_oa).abs() < 1e-12);
    assert!((g("/geometry/links/2/lengths/AB") - 3.8 * l_oa).abs() < 1e-12);
    assert!((g("/geometry/links/4/lengths/DF") - 3.8 * l_oa).abs() < 1e-12);
    assert!((g("/input/revolution_time") - t).abs() < 1e-12);
    let d = doc("dynamics", "examples/textbook/p2-engine.toml");
    let n = |p: &str| number(&d, p);
    assert!((n("/revolution_time") - t).abs() < 1e-12, "{}", n("/revolution_time"));
    // the four-stroke cycle: two turns
    assert!((n("/cycle_time_nominal") - 2.0 * t).abs() < 1e-12);
    assert!((n("/cycle_period") - 4.0 * PI).abs() < 1e-12);
    // and the tables say both
    let o = tmm_in(&repo(), &["dynamics", "examples/textbook/p2-engine.toml"]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("Time of one turn T = 60/n1 = 0.046154 s"), "{text}");
    assert!(text.contains("cycle of 720° at the nominal speed 0.092308 s"), "{text}");
    let o = tmm_in(&repo(), &["linkage", "examples/textbook/p2-engine.toml"]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("n1 = 1300.0000 rpm, one turn T = 60/n1 = 0.046154 s"), "{text}");
}

#[test]
fn p3_rocker_lengths_of_the_synthesised_linkage() {
    let l = doc("linkage", "examples/textbook/p3-shaper.toml");
    let g = |p: &str| number(&l, p);
    assert!((g("/geometry/links/3/lengths/CB") - 0.5).abs() < 1e-12);
    assert!((g("/geometry/links/3/lengths/CD") - 0.7).abs() < 1e-12);
    assert!((g("/geometry/links/3/lengths/BD") - 0.2).abs() < 1e-12);
    // |OC| = l_OC, the synthesis' given (the frame's points by name: C, O)
    assert!((g("/geometry/frame_lengths/CO") - 0.3).abs() < 1e-12);
    // ω1 = Δφ_PX·V_рез/H: one turn takes 2π/ω1
    let w = (7.0 * PI / 6.0) * 0.5 / 0.3;
    assert!((g("/input/revolution_time") - 2.0 * PI / w).abs() < 1e-12);
}
