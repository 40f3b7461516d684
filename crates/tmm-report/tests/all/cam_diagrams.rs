//! The cam's time diagrams mark the jumps of acceleration as impulses of
//! jerk (the course's "soft impacts"), with the sizes of the constant-
//! acceleration law derived here; each panel of the diagrams has its own
//! title, and a rocker's panels its own symbols (ψ, ω, ε).

use std::path::Path;

use tmm_report::TaskSource;
use tmm_report::run::run_task;

#[test]
fn constant_acceleration_jumps_are_marked_as_jerk_impulses() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/cam-seed-001-roller.toml");
    let run = run_task(&TaskSource::new("cam.toml", std::fs::read_to_string(path).unwrap())).unwrap();
    let svg = run.docs.get("cam/cam-motion.svg").unwrap().as_text().unwrap();
    let labels: Vec<f64> = svg
        .lines()
        .filter_map(|l| {
            // a label's words end its line: `Δa = −1317,175 м/с²` (the
            // minus sign in a tspan of its own font)
            let t = &l[..l.find("</tspan></text>")?];
            let mut plain = String::new();
            let mut in_tag = false;
            for c in t.chars() {
                match c {
                    '<' => in_tag = true,
                    '>' => in_tag = false,
                    c if !in_tag => plain.push(c),
                    _ => {}
                }
            }
            let t = &plain[plain.rfind("Δa = ")?..];
            t.strip_prefix("Δa = ")?
                .strip_suffix(" м/с²")?
                .replace('−', "-")
                .replace(',', ".")
                .parse()
                .ok()
        })
        .collect();
    // Constant acceleration a1 over u·β, −a2 over the rest: continuity of
    // velocity gives a2 = a1·u/(1 − u); the stroke h = a1·β²·u/2, so
    // a1 = 2h/(u·β²) per rad², times ω² in time.
    let (h, beta, u, w) = (0.013f64, 108f64.to_radians(), 1.0 / 3.0, 200.0f64);
    let a1 = 2.0 * h / (u * beta * beta) * w * w;
    let a2 = a1 * u / (1.0 - u);
    let mut want = vec![a1, -(a1 + a2), a2, -a1, a1 + a2, -a2];
    let mut got = labels.clone();
    want.sort_by(f64::total_cmp);
    got.sort_by(f64::total_cmp);
    assert_eq!(got.len(), 6, "{labels:?}");
    for (g, w) in got.iter().zip(&want) {
        assert!((g - w).abs() < 1e-3 * a1, "{got:?} vs {want:?}");
    }
}

/// The shown text of every `<text>` of `svg` whose font size is `size`, in
/// the file's order (the tspans' markup dropped).
fn texts_of_size(svg: &str, size: &str) -> Vec<String> {
    svg.lines()
        .filter(|l| l.starts_with("<text") && l.contains(&format!("font-size=\"{size}\"")))
        .map(|l| {
            let mut shown = String::new();
            let mut tag = false;
            for ch in l[l.find('>').unwrap() + 1..].chars() {
                match ch {
                    '<' => tag = true,
                    '>' => tag = false,
                    c if !tag => shown.push(c),
                    _ => {}
                }
            }
            shown
        })
        .collect()
}

#[test]
fn each_motion_panel_has_its_own_title_and_the_follower_its_own_symbols() {
    use tmm_report::project::Language;
    use tmm_report::words::word;
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    // a translating follower moves by s at v with a; a rocker turns by ψ at ω with ε
    let cases = [
        (
            "cam-seed-001-roller.toml",
            ["cam.analog_s", "cam.analog_ds", "cam.analog_dds"],
            ["cam.motion_s", "cam.motion_v", "cam.motion_a", "cam.motion_j"],
            ["s", "v", "a", "j"],
        ),
        (
            "cam-oscillating-roller.toml",
            ["cam.analog_psi", "cam.analog_dpsi", "cam.analog_ddpsi"],
            ["cam.motion_psi", "cam.motion_omega", "cam.motion_eps", "cam.motion_jerk_osc"],
            ["ψ", "ω", "ε", "j"],
        ),
    ];
    for (file, analog, motion, syms) in cases {
        let text = std::fs::read_to_string(dir.join(file)).unwrap();
        for lang in [Language::Ru, Language::Uk, Language::En] {
            let run = tmm_report::run::run_task_in(&TaskSource::new(file, text.clone()), Some(lang)).unwrap();
            for (path, keys) in [("cam/cam-analogs.svg", &analog[..]), ("cam/cam-motion.svg", &motion[..])] {
                let svg = run.docs.get(path).unwrap().as_text().unwrap();
                // the panel titles: 5 mm lettering, one per panel, in order
                // (the drawing's own name, its `title` group, is no panel's)
                let body = match svg.find("<g class=\"title\">") {
                    Some(i) => {
                        let j = i + svg[i..].find("</g>").unwrap() + 4;
                        format!("{}{}", &svg[..i], &svg[j..])
                    }
                    None => svg.to_string(),
                };
                let titles = texts_of_size(&body, "5.00");
                let want: Vec<&str> = keys.iter().map(|k| word(lang, k)).collect();
                assert_eq!(titles, want, "{file} {path} {lang:?}");
                for (i, t) in want.iter().enumerate() {
                    assert!(!t.starts_with("cam."), "{lang:?}: no word for {}", keys[i]);
                    assert!(!want[..i].contains(t), "{file} {path} {lang:?}: «{t}» twice");
                }
            }
            // the time diagrams' axes carry the follower's own symbols
            let svg = run.docs.get("cam/cam-motion.svg").unwrap().as_text().unwrap();
            // (3 mm asked, written raised to the lettering floor)
            let axes: Vec<String> = texts_of_size(svg, &format!("{:.2}", tmm_report::picture::em(3.0)));
            for s in syms {
                assert!(
                    axes.iter().any(|a| a.starts_with(&format!("{s}, "))),
                    "{file} {lang:?}: no axis «{s}, …» among {axes:?}"
                );
            }
            if file.contains("oscillating") {
                assert!(!axes.iter().any(|a| a.starts_with("v, ")), "{lang:?}: v over an ω axis");
            }
        }
    }
}
