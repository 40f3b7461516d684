//! The page's messages in Russian and Ukrainian: every error a task can
//! give — each example with each of its values replaced by a bad one, bad
//! TOML, a mechanism that cannot be assembled, a gear pair that cannot be
//! cut, a drag too far — has its message and its help translated whole
//! (no English word left, by the rule the browser test applies to the
//! screen), with the place `file:line:col` and the field kept.

use serde_json::Value;
use tmm_report::project::Language;
use tmm_web::examples::EXAMPLES;
use tmm_web::messages::{has_prose, translate};
use tmm_web::page::{Page, analyse_reply};

/// The values put in place of each value of an example.
const BAD: &[&str] = &["-1", "\"abc\"", "1e9", "0", "\"5 kg\"", "[1, 2]"];

/// Every distinct (message, help) the edits of the examples give.
fn corpus() -> Vec<String> {
    let mut seen = std::collections::BTreeSet::new();
    let mut add = |v: &Value| {
        for k in ["message", "help"] {
            if let Some(t) = v["error"][k].as_str() {
                seen.insert(t.to_string());
            }
        }
    };
    let step: usize = std::env::var("TMM_MESSAGES_STEP").ok().and_then(|s| s.parse().ok()).unwrap_or(1);
    let mut n = 0usize;
    for (name, text) in EXAMPLES {
        let lines: Vec<&str> = text.split('\n').collect();
        for (i, l) in lines.iter().enumerate() {
            let t = l.trim_start();
            if t.starts_with('#') || t.starts_with('[') || !t.contains('=') {
                continue;
            }
            let key = l.split('=').next().unwrap_or_default();
            for bad in BAD {
                n += 1;
                if n % step != 0 {
                    continue;
                }
                let mut edited = lines.clone();
                let line = format!("{key}= {bad}");
                edited[i] = &line;
                let (r, _) = analyse_reply(name, &edited.join("\n"), "");
                let v: Value = serde_json::from_str(&r).unwrap();
                if v["ok"] == false {
                    add(&v);
                }
            }
        }
    }
    // bad TOML, an unknown section and field, a missing section's value
    let d = tmm_report::run::DEFAULT_TASK;
    for edited in [
        d.replacen("[gear]", "[gear", 1),
        d.replacen("[gear]", "[gear]\nz1 = 1\nz1 = 2", 1),
        d.replacen("[gear]", "[gear]\nwheel = 3", 1),
        d.replacen("[gear]", "[gears]", 1),
        d.replacen("[gear]", "[gear]\nmodule = \"5 mm", 1),
        d.replacen("[gear]", "[gear]\n= 3", 1),
        format!("{d}\n\u{7}"),
        "title = \"x\"\n[cam]\n".to_string(),
        "[linkage]\n".to_string(),
    ] {
        let (r, _) = analyse_reply("task.toml", &edited, "");
        add(&serde_json::from_str(&r).unwrap());
    }
    // a mechanism that cannot be assembled; a crank that cannot turn fully
    for (name, text) in EXAMPLES {
        for (from, to) in [
            ("\"480 mm\"", "\"40 mm\""),
            ("\"100 mm\"", "\"4000 mm\""),
            ("length = ", "length = 0.001 + "),
        ] {
            if text.contains(from) {
                let (r, _) = analyse_reply(name, &text.replacen(from, to, 1), "");
                if let Ok(v) = serde_json::from_str::<Value>(&r) {
                    add(&v);
                }
            }
        }
        if let Ok(p) = Page::new(name, text, None) {
            add(&serde_json::from_str(&tmm_web::angle::frames(&p, 36)).unwrap());
            // a gear pair picked far outside the contour, and inside it near its edges
            if p.has("gear") {
                for (x1, x2) in [(-2.0, -2.0), (3.0, 3.0), (-1.0, 0.0), (0.0, -1.0), (1.5, -0.5), (-0.5, 1.5)] {
                    add(&serde_json::from_str(&tmm_web::gear_pick::gear_at(&p, x1, x2)).unwrap());
                }
            }
            // a joint dragged far away
            if p.linkage.is_some() {
                for point in ["B", "C", "D"] {
                    if let Err(m) = tmm_web::drag::drag(&p, text, point, 50.0, 50.0, 0.3) {
                        add(&serde_json::json!({ "error": { "message": m } }));
                    }
                }
            }
        }
    }
    seen.into_iter().collect()
}

#[test]
fn every_message_a_task_gives_reads_in_russian_and_ukrainian() {
    let all = corpus();
    assert!(all.len() > 100, "only {} messages", all.len());
    let mut missing = Vec::new();
    for m in &all {
        for lang in [Language::Ru, Language::Uk] {
            match translate(m, lang) {
                // `abc` is the test's own bad value, a name the user typed
                Some(t) if has_prose(&t.replace("abc", "a1")) => missing.push(format!("{lang:?} left English: {t}\n  from {m}")),
                Some(_) => {}
                None => missing.push(format!("{lang:?}: {m}")),
            }
        }
    }
    if let Ok(out) = std::env::var("TMM_MESSAGES_DUMP") {
        std::fs::write(out, missing.join("\n")).unwrap();
    }
    assert!(
        missing.is_empty(),
        "{} of {} messages have no translation:\n{}",
        missing.len() / 2,
        all.len(),
        missing.join("\n")
    );
}

#[test]
fn the_place_and_the_field_stay_as_they_are() {
    let (r, _) = analyse_reply(
        "task.toml",
        &tmm_report::run::DEFAULT_TASK.replacen("length = ", "length = -1 # ", 1),
        "",
    );
    let v: Value = serde_json::from_str(&r).unwrap();
    let m = v["error"]["message"].as_str().unwrap();
    let ru = translate(m, Language::Ru).unwrap();
    let head = m.split(": ").take(2).collect::<Vec<_>>().join(": ");
    assert!(head.starts_with("task.toml:") && ru.starts_with(&head), "{ru}\n{m}");
    assert_ne!(ru, m);
}
