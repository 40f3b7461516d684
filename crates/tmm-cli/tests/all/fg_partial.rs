//! Function generation whose crank does not turn fully (the reproducer
//! `fg-task-not-runnable`): the construction is drawn, and the `--task`
//! file it writes runs through `tmm linkage` and `tmm run` (with the note),
//! analysed over the crank angles where the four-bar assembles.

use crate::common::{tmm_in, tmp};

const POSITIONS: [&str; 6] = ["--position", "30, 60", "--position", "60, 80", "--position", "90, 100"];

/// The link lengths `[[linkage.links]]` of a written task, by name.
fn lengths(task: &toml::Table) -> Vec<f64> {
    task["linkage"]["links"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l["length"].as_float().unwrap())
        .collect()
}

#[test]
fn a_function_generator_that_does_not_turn_fully_is_drawn_and_its_task_runs() {
    let dir = tmp("fg_partial", "svg_task");
    let mut args = vec!["synth", "function-generation"];
    args.extend(POSITIONS);
    args.extend(["--frame", "300 mm", "--svg", "d", "--task", "g.toml"]);
    let o = tmm_in(&dir, &args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for f in ["d/synthesis/construction.svg", "d/synthesis/pressure.svg"] {
        let svg = std::fs::read_to_string(dir.join(f)).unwrap_or_else(|e| panic!("{f}: {e}"));
        assert!(svg.starts_with("<svg") || svg.starts_with("<?xml"), "{f}");
    }
    let text = std::fs::read_to_string(dir.join("g.toml")).unwrap();
    let task: toml::Table = toml::from_str(&text).unwrap();
    // the four-bar is not of Grashof's kind (s + l > p + q, Grashof 1883):
    // no link turns fully against the frame, so the range must be partial
    let mut l = lengths(&task);
    l.push(0.3);
    l.sort_by(f64::total_cmp);
    assert!(l[0] + l[3] > l[1] + l[2], "lengths {l:?}");
    assert_eq!(task["linkage"]["range"].as_str(), Some("partial"), "{text}");
    assert!(task.get("forces").is_none(), "[forces] needs a full turn: {text}");
    let o = tmm_in(&dir, &["linkage", "g.toml"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = tmm_in(&dir, &["run", "g.toml", "--out", "o"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for f in ["o/note.pdf", "o/synthesis/construction.svg", "o/linkage/positions.svg"] {
        assert!(dir.join(f).is_file(), "{f} missing");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
