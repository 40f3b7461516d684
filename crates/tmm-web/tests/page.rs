//! The page's module on the host: the replies the JavaScript reads.

use serde_json::Value;
use tmm_report::TaskSource;
use tmm_report::project::Language;
use tmm_report::run::DEFAULT_TASK;
use tmm_report::run::run_task_in;
use tmm_web::page::{Page, analyse_reply};

fn parse(s: &str) -> Value {
    serde_json::from_str(s).expect("replies are JSON")
}

#[test]
fn every_example_file_is_offered() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples");
    let list = |sub: &str| {
        let mut v: Vec<String> = std::fs::read_dir(format!("{dir}/{sub}"))
            .unwrap()
            .filter_map(|e| e.ok()?.file_name().into_string().ok())
            .filter(|n| n.ends_with(".toml"))
            .map(|n| format!("{sub}{n}"))
            .collect();
        v.sort();
        v
    };
    let mut on_disk = list("");
    on_disk.extend(list("textbook/"));
    let offered: Vec<String> = tmm_web::examples::EXAMPLES.iter().map(|(n, _)| n.to_string()).collect();
    assert_eq!(offered, on_disk);
    for (name, text) in tmm_web::examples::EXAMPLES {
        let disk = std::fs::read_to_string(format!("{dir}/{name}")).unwrap();
        assert_eq!(*text, disk, "{name} is embedded as it is on disk");
    }
}

#[test]
fn the_error_is_at_the_line_of_the_bad_value() {
    // put a negative coupler length on a line the test finds itself
    let bad = DEFAULT_TASK.replacen("length = \"480 mm\"", "length = \"-480 mm\"", 1);
    assert_ne!(bad, DEFAULT_TASK);
    let line = bad.lines().position(|l| l.contains("-480 mm")).unwrap() + 1;
    let (reply, page) = analyse_reply("task.toml", &bad, "");
    let v = parse(&reply);
    assert!(page.is_none());
    assert_eq!(v["ok"], false);
    assert_eq!(v["error"]["line"], line);
    let msg = v["error"]["message"].as_str().unwrap();
    assert!(msg.starts_with(&format!("task.toml:{line}:")), "{msg}");
}

#[test]
fn the_reply_and_the_files_are_those_of_tmm_run() {
    let (reply, page) = analyse_reply("t.toml", DEFAULT_TASK, "en");
    let v = parse(&reply);
    let page = page.unwrap();
    assert_eq!(v["ok"], true);
    let cli = run_task_in(&TaskSource::new("t.toml", DEFAULT_TASK), Some(Language::En)).unwrap();
    // the same numbers as `tmm run`'s report (both read back by one parser)
    assert!(v["report"] == parse(&cli.report.to_string()), "the reply's report is not tmm run's");
    assert!(page.report() == cli.report, "the page's report is not tmm run's");
    // each section lists its files, drawings made on asking, the CLI's bytes
    let mut listed = 0;
    for s in [
        "report",
        "synthesis",
        "linkage",
        "forces",
        "dynamics",
        "gear",
        "planetary",
        "cam",
        "sheets",
    ] {
        let l = page.files(s);
        assert_eq!(l["ok"], true);
        for f in l["files"].as_array().unwrap() {
            let path = f["path"].as_str().unwrap();
            let want = cli.docs.get(path).unwrap_or_else(|| panic!("{path} is not a file of tmm run"));
            let d = page.file(path).unwrap();
            assert_eq!(f["size"], d.bytes.len());
            assert!(d.bytes == want.bytes, "{path} differs from tmm run's");
            listed += 1;
        }
    }
    assert_eq!(listed, cli.docs.len());
}

/// The links are rigid: at every frame each drawn segment of the default
/// four-bar keeps the length the task gives it (120, 480, 380 mm).
#[test]
fn frames_keep_the_link_lengths() {
    let p = Page::new("t.toml", DEFAULT_TASK, None).unwrap();
    let v = parse(&tmm_web::angle::frames(&p, 72));
    let xy = v["xy"].as_array().unwrap();
    assert_eq!(xy.len(), 72);
    let segs = v["segments"].as_array().unwrap();
    assert_eq!(segs.len(), 3);
    let pt = |f: &Value, i: &Value| {
        let q = &f[i.as_u64().unwrap() as usize];
        (q[0].as_f64().unwrap(), q[1].as_f64().unwrap())
    };
    let mut lengths: Vec<f64> = segs
        .iter()
        .map(|s| {
            let (a, b) = (pt(&xy[0], &s[0]), pt(&xy[0], &s[1]));
            (a.0 - b.0).hypot(a.1 - b.1)
        })
        .collect();
    for f in xy {
        for (s, l0) in segs.iter().zip(&lengths) {
            let (a, b) = (pt(f, &s[0]), pt(f, &s[1]));
            assert!(((a.0 - b.0).hypot(a.1 - b.1) - l0).abs() < 1e-9);
        }
    }
    lengths.sort_by(f64::total_cmp);
    for (l, want) in lengths.iter().zip([0.120, 0.380, 0.480]) {
        assert!((l - want).abs() < 1e-9, "{l} vs {want}");
    }
    // the crank pin turns a full revolution about the pivot
    let (pivot, pin) = (&v["pivot"], &v["pin"]);
    let angle = |f: &Value| {
        let (o, a) = (pt(f, pivot), pt(f, pin));
        (a.1 - o.1).atan2(a.0 - o.0)
    };
    let turn: f64 = (0..72)
        .map(|k| {
            let d = angle(&xy[(k + 1) % 72]) - angle(&xy[k]);
            d.sin().atan2(d.cos())
        })
        .sum();
    assert!((turn.abs() - std::f64::consts::TAU).abs() < 1e-9);
}

#[test]
fn plans_follow_the_angle() {
    let p = Page::new("t.toml", DEFAULT_TASK, None).unwrap();
    let a = parse(&tmm_web::angle::at_angle(&p, 0.3, true));
    let b = parse(&tmm_web::angle::at_angle(&p, 1.3, false));
    assert_eq!(a["ok"], true);
    assert!((a["phi"].as_f64().unwrap() - 0.3).abs() < 1e-12);
    assert_ne!(a["velocity_plan"], b["velocity_plan"]);
    assert!(a["velocity_plan"].as_str().unwrap().starts_with("<?xml"));
    // the two force methods agree at any angle (virtual power)
    let (mb, mz) = (
        a["forces"]["balancing_moment"].as_f64().unwrap(),
        a["forces"]["zhukovsky_moment"].as_f64().unwrap(),
    );
    assert!((mb - mz).abs() <= 1e-6 * mb.abs().max(1.0), "{mb} vs {mz}");
    assert!(b["forces"].is_null());
    assert_eq!(parse(&tmm_web::angle::at_angle(&p, f64::NAN, true))["ok"], false);
}

#[test]
fn a_picked_point_becomes_the_pairs_shifts() {
    let p = Page::new("t.toml", DEFAULT_TASK, None).unwrap();
    let v = parse(&tmm_web::gear_pick::gear_at(&p, 0.3, 0.6));
    assert_eq!(v["ok"], true, "{v}");
    assert_eq!(v["gear"]["x1"], 0.3);
    assert_eq!(v["gear"]["x2"], 0.6);
    // the working pressure angle follows from x1 + x2 (GOST 16532 inv αw formula)
    let g = &v["gear"];
    let (z1, z2, alpha) = (15.0, 20.0, 20f64.to_radians());
    let inv = |a: f64| a.tan() - a;
    let inv_w = inv(alpha) + 2.0 * (0.3 + 0.6) * alpha.tan() / (z1 + z2);
    assert!((inv(g["alpha_w"].as_f64().unwrap()) - inv_w).abs() < 1e-10);
    assert!(v["files"]["gear/contour.svg"].is_string());
    // the axes map the drawing back to shifts linearly
    let a = tmm_web::gear_pick::axes(&p.task).unwrap().unwrap();
    let (u, v2) = (a.origin.0 + a.scale * 0.3, a.origin.1 - a.scale * 0.6);
    let (x1, x2) = a.shifts(u, v2);
    assert!((x1 - 0.3).abs() < 1e-12 && (x2 - 0.6).abs() < 1e-12);
    assert!(a.x1.0 < 0.3 && 0.3 < a.x1.1);
}

/// Every number and every file of `a` equals that of `b`.
fn same_run(a: &Page, b: &Page) {
    assert!(a.report() == b.report(), "the reports differ");
    let (pa, pb) = (a.docs().unwrap(), b.docs().unwrap());
    assert_eq!(pa.len(), pb.len());
    for (x, y) in pa.iter().zip(&pb) {
        assert_eq!(x.path, y.path);
        assert!(x.bytes == y.bytes, "{} differs from a fresh run", x.path);
    }
}

#[test]
fn an_edit_reruns_only_the_sections_that_read_the_edited_table() {
    let p = Page::new("t.toml", DEFAULT_TASK, None).unwrap();
    assert_eq!(
        p.rerun,
        ["synthesis", "linkage", "forces", "dynamics", "gear", "planetary", "cam", "cylinder"]
    );
    // the coupler: the linkage and everything that reads it
    let coupler = DEFAULT_TASK.replacen("length = \"480 mm\"", "length = \"470 mm\"", 1);
    assert_ne!(coupler, DEFAULT_TASK);
    let q = Page::after(Some(&p), "t.toml", &coupler, None).unwrap();
    assert_eq!(q.rerun, ["synthesis", "linkage", "forces", "dynamics"]);
    assert_ne!(q.report()["linkage"], p.report()["linkage"]);
    same_run(&q, &Page::new("t.toml", &coupler, None).unwrap());
    // the gear's module: the gear only; the kept sections equal a fresh run
    let at = coupler.find("[gear]").unwrap();
    let gear = format!(
        "{}{}",
        &coupler[..at],
        coupler[at..].replacen("module = \"5 mm\"", "module = \"6 mm\"", 1)
    );
    assert_ne!(gear, coupler);
    let r = Page::after(Some(&q), "t.toml", &gear, None).unwrap();
    assert_eq!(r.rerun, ["gear"]);
    same_run(&r, &Page::new("t.toml", &gear, None).unwrap());
    // another language redraws every section
    let s = Page::after(Some(&r), "t.toml", &gear, Some(tmm_report::project::Language::En)).unwrap();
    assert_eq!(s.rerun.len(), 8);
    // a failed run leaves the kept outputs of the last good one usable
    assert!(Page::after(Some(&r), "t.toml", &gear.replacen("470 mm", "-470 mm", 1), None).is_err());
}

/// The animation's plan vectors: the crank pin's velocity is ω·AB across
/// the crank (900 rpm, 120 mm), and the images of B and C are the central
/// differences of their positions over the crank angle times ω.
#[test]
fn the_frames_plan_vectors_are_the_velocities() {
    let p = Page::new("t.toml", DEFAULT_TASK, None).unwrap();
    let omega = 900.0 * std::f64::consts::TAU / 60.0;
    let phi = 0.7;
    let v = parse(&tmm_web::angle::plan_vectors(&p, phi));
    assert_eq!(v["ok"], true);
    let image = |name: &str| -> [f64; 2] {
        let x = v["velocity"]
            .as_array()
            .unwrap()
            .iter()
            .find(|x| x["label"] == format!("V_{name}"))
            .unwrap();
        [x["to"][0].as_f64().unwrap(), x["to"][1].as_f64().unwrap()]
    };
    let m = &p.linkage.as_ref().unwrap().mech;
    let at = |phi: f64, name: &str| {
        let mut sol = m.solution();
        m.solve(phi, &mut sol).unwrap();
        let i = m.points.iter().position(|q| q.name == name).unwrap();
        [sol.points[i].p.x, sol.points[i].p.y]
    };
    let vb = image("B");
    assert!((vb[0].hypot(vb[1]) - omega * 0.120).abs() < 1e-9 * omega);
    let h = 1e-6;
    for name in ["B", "C"] {
        let (a, b) = (at(phi + h, name), at(phi - h, name));
        let fd = [(a[0] - b[0]) / (2.0 * h) * omega, (a[1] - b[1]) / (2.0 * h) * omega];
        let im = image(name);
        assert!((fd[0] - im[0]).hypot(fd[1] - im[1]) < 1e-5 * omega, "{name}: {fd:?} vs {im:?}");
    }
    assert_eq!(parse(&tmm_web::angle::plan_vectors(&p, f64::INFINITY))["ok"], false);
}

/// The linear fit `a + b·t` of the pairs `(t, value)`.
fn line_fit(p: &[(f64, f64)]) -> (f64, f64) {
    let n = p.len() as f64;
    let (mx, my) = (p.iter().map(|q| q.0).sum::<f64>() / n, p.iter().map(|q| q.1).sum::<f64>() / n);
    let b = p.iter().map(|q| (q.0 - mx) * (q.1 - my)).sum::<f64>() / p.iter().map(|q| (q.0 - mx).powi(2)).sum::<f64>();
    (my - b * mx, b)
}

/// The attribute `name` of an SVG element's text.
fn attr(el: &str, name: &str) -> Option<f64> {
    let k = el.find(&format!(" {name}=\""))? + name.len() + 3;
    el[k..].split('"').next()?.parse().ok()
}

#[test]
fn the_contour_axes_are_those_of_the_drawing() {
    // The drawing's own axes: its grey grid lines and the numbers written
    // at them, fitted by least squares, for every sheet format.
    for sheet in ["A1", "A2"] {
        let text = DEFAULT_TASK.replace("sheet = \"A1\"", &format!("sheet = \"{sheet}\""));
        let p = Page::new("t.toml", &text, None).unwrap();
        let svg = p.file("gear/contour.svg").unwrap().as_text().unwrap().to_string();
        let lines: Vec<&str> = svg.split("<line").skip(1).filter(|l| l.contains("#bbbbbb")).collect();
        let vx: Vec<f64> = lines
            .iter()
            .filter(|l| attr(l, "x1") == attr(l, "x2"))
            .filter_map(|l| attr(l, "x1"))
            .collect();
        let hy: Vec<f64> = lines
            .iter()
            .filter(|l| attr(l, "y1") == attr(l, "y2"))
            .filter_map(|l| attr(l, "y1"))
            .collect();
        let near = |a: &[f64], v: f64| {
            a.iter()
                .copied()
                .fold(f64::INFINITY, |b, x| if (x - v).abs() < (b - v).abs() { x } else { b })
        };
        let (bottom, left) = (
            hy.iter().copied().fold(f64::MIN, f64::max),
            vx.iter().copied().fold(f64::MAX, f64::min),
        );
        let (mut xs, mut ys) = (Vec::new(), Vec::new());
        for t in svg.split("<text ").skip(1) {
            let Some(body) = t
                .split("<tspan")
                .nth(1)
                .and_then(|s| s.split('>').nth(1))
                .and_then(|s| s.split('<').next())
            else {
                continue;
            };
            let Ok(v) = body.replace(',', ".").parse::<f64>() else { continue };
            let (x, y) = (attr(t, "x").unwrap(), attr(t, "y").unwrap());
            // x1 under the plot, from its left edge on; x2 left of the plot
            if y > bottom && x >= left - 0.5 {
                xs.push((v, near(&vx, x)));
            } else if x < left - 0.5 && y <= bottom + 2.0 {
                ys.push((v, near(&hy, y)));
            }
        }
        // at 2.5 mm lettering the A2 contour numbers every other x tick, so
        // three numbers may be all there is on x1: enough for the line's fit
        assert!(xs.len() >= 3 && ys.len() >= 4, "{sheet}: {} and {} ticks", xs.len(), ys.len());
        let (ax, bx) = line_fit(&xs);
        let (ay, by) = line_fit(&ys);
        let a = tmm_web::gear_pick::axes(&p.task).unwrap().unwrap();
        assert!(
            (a.origin.0 - ax).abs() < 2e-3 && (a.origin.1 - ay).abs() < 2e-3,
            "{sheet}: origin {:?}, drawing ({ax}, {ay})",
            a.origin
        );
        assert!(
            (a.scale - bx).abs() < 1e-3 * bx && (a.scale + by).abs() < 1e-3 * bx,
            "{sheet}: scale {}, drawing {bx}, {by}",
            a.scale
        );
    }
}

#[test]
fn the_nodes_marked_passing_pass_every_check() {
    let p = Page::new("t.toml", DEFAULT_TASK, None).unwrap();
    let a = tmm_web::gear_pick::axes(&p.task).unwrap().unwrap();
    let n = a.n;
    let node = |i: usize, j: usize| {
        (
            a.x1.0 + (a.x1.1 - a.x1.0) * i as f64 / (n - 1) as f64,
            a.x2.0 + (a.x2.1 - a.x2.0) * j as f64 / (n - 1) as f64,
        )
    };
    assert!(a.passes.iter().filter(|&&b| b).count() > 10);
    // a sample of nodes of both kinds, run as whole tasks with those shifts
    let mut seen = [0, 0];
    for k in (0..n * n).step_by(997) {
        let (i, j) = (k % n, k / n);
        if !a.feasible[k] {
            continue;
        }
        let (x1, x2) = node(i, j);
        let v = parse(&tmm_web::gear_pick::gear_at(&p, x1, x2));
        let all = v["ok"] == true && v["gear"]["all_checks_pass"] == true;
        assert_eq!(a.passes[k], all, "node ({x1}, {x2}): {v}");
        seen[usize::from(all)] += 1;
    }
    assert!(seen[0] > 0 && seen[1] > 0, "{seen:?}");
    // the task's own pair passes every check (its report says so)
    let (i, j) = (
        ((0.2 - a.x1.0) / (a.x1.1 - a.x1.0) * (n - 1) as f64).round() as usize,
        ((0.85 - a.x2.0) / (a.x2.1 - a.x2.0) * (n - 1) as f64).round() as usize,
    );
    assert!(a.feasible[j * n + i]);
}

#[test]
fn a_written_pick_runs_as_those_shifts() {
    let t = tmm_web::gear_pick::write_shifts(DEFAULT_TASK, 0.3, 0.6999999).unwrap();
    assert!(t.contains("\nx1 = 0.3\nx2 = 0.7\n"));
    assert_eq!(t.matches("\nx1 =").count(), 1);
    let p = Page::new("t.toml", &t, None).unwrap();
    let g = &p.report()["gear"];
    assert_eq!((g["x1"].as_f64(), g["x2"].as_f64()), (Some(0.3), Some(0.7)));
    // every other line kept
    let kept = |s: &str| {
        s.lines()
            .filter(|l| !l.starts_with("x1 =") && !l.starts_with("x2 ="))
            .map(str::to_string)
            .collect::<Vec<_>>()
    };
    assert_eq!(kept(&t), kept(DEFAULT_TASK));
    assert!(tmm_web::gear_pick::write_shifts("[cam]\n", 0.1, 0.1).is_err());
}

#[test]
fn dragging_a_joint_sets_its_links_to_the_distances() {
    let p = Page::new("t.toml", DEFAULT_TASK, None).unwrap();
    let phi = 0.7f64;
    // the crank pin of the default four-bar in closed form: A = (0, 0), AB = 120 mm
    let b = (0.12 * phi.cos(), 0.12 * phi.sin());
    let (x, y) = (0.30, -0.25);
    let t = tmm_web::drag::drag(&p, DEFAULT_TASK, "C", x, y, phi).unwrap();
    let bc = ((x - b.0).hypot(y - b.1) * 1000.0).round();
    let dc = ((x - 0.51f64).hypot(y) * 1000.0).round();
    assert!(t.contains(&format!("length = \"{bc} mm\"")), "BC {bc}");
    assert!(t.contains(&format!("length = \"{dc} mm\"")), "DC {dc}");
    assert!(t.contains("length = \"120 mm\""));
    assert!(t.contains("assembly = [\"C below AD\"]"));
    // a fixed point moves, rounded to whole millimetres
    let t = tmm_web::drag::drag(&p, DEFAULT_TASK, "D", 0.5004, -0.0206, phi).unwrap();
    assert!(t.contains("D = [\"500 mm\", \"-21 mm\"]"), "{}", &t[..400]);
    // a text other than the page's is refused, as are non-finite places
    assert!(tmm_web::drag::drag(&p, "[linkage]\n", "C", x, y, phi).is_err());
    assert!(tmm_web::drag::drag(&p, DEFAULT_TASK, "C", f64::NAN, y, phi).is_err());
}

#[test]
fn every_word_the_page_asks_for_is_in_every_language() {
    let js = include_str!("../../../web/app.js");
    let html = include_str!("../../../web/index.html");
    let mut asked: Vec<String> = Vec::new();
    for (src, pat) in [(js, "W(\""), (html, "data-w=\""), (html, "data-w-aria=\"")] {
        for part in src.split(pat).skip(1) {
            asked.push(part.split('"').next().unwrap().to_string());
        }
    }
    for part in js.split("[\"k_").skip(1) {
        asked.push(format!("k_{}", part.split('"').next().unwrap()));
    }
    asked.retain(|k| !k.ends_with('_'));
    assert!(asked.len() > 40, "{}", asked.len());
    for lang in ["ru", "uk", "en"] {
        let v = parse(&tmm_web::ui_words::json(lang));
        for k in &asked {
            assert!(v["words"][k].is_string(), "{lang}: no word {k}");
        }
    }
}
