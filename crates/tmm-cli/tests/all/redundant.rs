//! Redundant constraints written in a task file (issue 20, item 10): the
//! double parallelogram — three parallel cranks of 100 mm, the third on the
//! coupler's midpoint F — has Chebyshev's W = 3·4 − 2·6 = 0, yet moves with
//! mobility 1 because one constraint repeats the others (q = 1). The refusal
//! gives Chebyshev's count and must not blame the automatic centre of mass
//! `S4` as a point that "joins nothing".

use crate::common::{run, tmp};

const DOUBLE_PARALLELOGRAM: &str = r#"[linkage]
fixed = { A = [0, 0], D = ["300 mm", 0], E = ["150 mm", 0] }
input = { link = "1", speed = "10 rad/s" }
assembly = ["C above AD"]
[[linkage.links]]
name = "1"
joints = ["A", "B"]
length = "100 mm"
[[linkage.links]]
name = "2"
joints = ["B", "C"]
length = "300 mm"
points.F = { along = 0.5 }
[[linkage.links]]
name = "3"
joints = ["D", "C"]
length = "100 mm"
[[linkage.links]]
name = "4"
joints = ["E", "F"]
length = "100 mm"
"#;

#[test]
fn a_double_parallelogram_from_a_task_file_is_not_blamed_on_its_centre_of_mass() {
    let dir = tmp("redundant", "double_parallelogram");
    let f = dir.join("dp.toml");
    std::fs::write(&f, DOUBLE_PARALLELOGRAM).unwrap();
    let (code, _, err) = run(&["linkage", f.to_str().unwrap()]);
    assert_eq!(code, 2, "{err}");
    // Chebyshev: n = 4 moving links, p5 = 6 revolute pairs (A, B, C, D, E, F)
    assert!(err.contains("3·4 − 2·6 = 0"), "{err}");
    // yet it moves: AB ∥ DC ∥ EF and BC = AD make F (the coupler's middle)
    // keep |EF| = 0.1 m at every crank angle, so the rank of the 12 pair
    // equations in 12 coordinates is 11 — mobility 12 − 11 = 1, q = 12 − 11 = 1
    assert!(err.contains("mobility 1 with 1 redundant constraint"), "{err}");
    // the constraint left over is named: the third crank's
    assert!(err.contains("link `4` (E–F)"), "{err}");
    assert!(!err.contains("S4"), "the centre of mass is blamed: {err}");
    let _ = std::fs::remove_dir_all(&dir);
}
