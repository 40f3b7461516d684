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
    let mut on_disk: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|n| n.ends_with(".toml"))
        .collect();
    on_disk.sort();
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
    assert_eq!(p.rerun, ["synthesis", "linkage", "forces", "dynamics", "gear", "planetary", "cam"]);
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
    assert_eq!(s.rerun.len(), 7);
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
