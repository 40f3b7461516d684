//! The machine meshing (станочное зацепление) of wheel 1 measured on its
//! drawing `gear/machine-mesh.svg`: the tool's reference line and the
//! machine pitch line are x₁·m apart on the paper at the printed scale,
//! and the tool's teeth repeat at the rack's pitch p = π·m. The module is
//! the task's; the shift is the task's x1 where it is given, the chosen one
//! (gear.json) where the task leaves it to a criterion.

use std::f64::consts::PI;

use crate::common::{repo, tmm_in, tmp};

/// The number after `attr="` in `text` from `at`.
fn attr(text: &str, at: usize, name: &str) -> f64 {
    let key = format!("{name}=\"");
    let i = text[at..].find(&key).unwrap() + at + key.len();
    let j = text[i..].find('"').unwrap() + i;
    text[i..j].parse().unwrap()
}

/// The paper y of the line in the group of class `class`.
fn line_y(svg: &str, class: &str) -> f64 {
    let at = svg.find(&format!("<g class=\"{class}\">")).unwrap_or_else(|| panic!("no {class}"));
    let (y1, y2) = (attr(svg, at, "y1"), attr(svg, at, "y2"));
    assert!((y1 - y2).abs() < 1e-9, "{class} is not horizontal");
    y1
}

fn check(example: &str, name: &str) {
    let d = tmp("machine_mesh", name);
    let o = tmm_in(&d, &["run", "--no-pdf", repo().join(example).to_str().unwrap(), "-o", "out"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let svg = std::fs::read_to_string(d.join("out/gear/machine-mesh.svg")).unwrap();
    let gear: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(d.join("out/gear/gear.json")).unwrap()).unwrap();
    let task = std::fs::read_to_string(repo().join(example)).unwrap();
    // the module of the task, mm
    let m: f64 = {
        let at = task.find("module = \"").unwrap() + 10;
        let v = &task[at..at + task[at..].find(' ').unwrap()];
        v.parse().unwrap()
    };
    let x = match task.lines().find_map(|l| l.strip_prefix("x1 = ")) {
        Some(v) => v.trim().parse().unwrap(),
        None => gear["x1"].as_f64().unwrap(),
    };
    // the printed scale n:k
    let i = svg.find("data-scale=\"").unwrap() + 12;
    let sc = &svg[i..i + svg[i..].find('"').unwrap()];
    let (a, b) = sc.split_once(':').unwrap();
    let f = a.replace(',', ".").parse::<f64>().unwrap() / b.replace(',', ".").parse::<f64>().unwrap();
    // the shift between the lines, measured: the tool's reference line lies
    // x·m farther from the wheel's centre (below, y down on paper)
    let gap = (line_y(&svg, "rack-reference-line") - line_y(&svg, "machine-pitch-line")) / f;
    assert!(
        (gap - x * m).abs() < 2e-3 / f,
        "{example}: lines {gap} mm apart, x·m = {} mm",
        x * m
    );
    // the tool's teeth: the tips are the outline's highest points (least paper y)
    let at = svg.find("<g class=\"rack-tool\">").unwrap();
    let end = svg[at..].find("</g>").unwrap() + at;
    let mut pts: Vec<(f64, f64)> = Vec::new();
    for pl in svg[at..end].split("points=\"").skip(1) {
        for p in pl[..pl.find('"').unwrap()].split_whitespace() {
            let (x, y) = p.split_once(',').unwrap();
            pts.push((x.parse().unwrap(), y.parse().unwrap()));
        }
    }
    let top = pts.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
    let mut tips: Vec<Vec<f64>> = Vec::new();
    for p in pts.iter().filter(|p| (p.1 - top).abs() < 1e-3) {
        match tips.last_mut() {
            Some(t) if (p.0 - t[t.len() - 1]).abs() < 0.5 * PI * m * f => t.push(p.0),
            _ => tips.push(vec![p.0]),
        }
    }
    let centres: Vec<f64> = tips.iter().map(|t| 0.5 * (t[0] + t[t.len() - 1])).collect();
    assert!(centres.len() >= 3, "{example}: {} tool teeth", centres.len());
    for w in centres.windows(2) {
        let pitch = (w[1] - w[0]) / f;
        assert!(
            (pitch - PI * m).abs() < 2e-3 / f,
            "{example}: tool teeth {pitch} mm apart, π·m = {} mm",
            PI * m
        );
    }
}

#[test]
fn seed001_lines_apart_by_x_m_and_tool_at_pi_m() {
    check("examples/gear-seed001.toml", "s1");
}

#[test]
fn seed003_lines_apart_by_x_m_and_tool_at_pi_m() {
    check("examples/gear-seed003.toml", "s3");
}

#[test]
fn internal_pair_pinion_lines_apart_by_x_m_and_tool_at_pi_m() {
    check("examples/gear-internal.toml", "int");
}
