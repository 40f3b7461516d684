//! Names, titles and other user text at the edge (issue "Hardening II",
//! items 4, 6, 7 and 8): a long name is refused at its place before the
//! typesetter sees it, control characters are refused, the output guard
//! tells a user's word `inf` from a non-finite number, no ∞ is printed for a
//! number, and messages name the field or option and its place.

use std::path::{Path, PathBuf};

use crate::common::{self, run, tmm_in};
use tmm_testkit::examples;

/// A task file `name` with `text` in a fresh folder; (folder, file).
fn task(tag: &str, name: &str, text: &[u8]) -> (PathBuf, String) {
    let d = common::tmp("input-limits", tag);
    let f = d.join(name);
    std::fs::write(&f, text).unwrap();
    (d, f.to_string_lossy().into_owned())
}

/// (exit code, stdout, stderr) of `tmm args` in `dir`.
fn run_in(dir: &Path, args: &[&str]) -> (i32, String, String) {
    let o = tmm_in(dir, args);
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

const PLANETARY: &str = "[planetary]\nscheme = \"sun-planet-ring\"\nratio = 6\nplanets = 3\n";

/// `panic-long-title`: a 64 KiB title panicked the PDF writer (exit 101);
/// now it is refused at its place, naming the limit, before any typesetting.
#[test]
fn long_title_is_refused_at_its_place() {
    let text = format!("title = \"{}\"\n{PLANETARY}", "Ж".repeat(32_767));
    let (d, f) = task("long-title", "task.toml", text.as_bytes());
    let (code, _, err) = run_in(&d, &["note", &f, "--out", "o"]);
    assert_eq!(code, 2, "{}", &err[..err.len().min(2000)]);
    assert!(
        err.contains("task.toml:1:9: title: the text is 32767 characters long"),
        "{}",
        &err[..2000]
    );
    assert!(err.contains("limited to 300 characters"));
    assert!(!d.join("o").exists());
}

/// `slow-long-name`, `panic-long-title/link-name.toml`: a joint or link name
/// of 100 000 characters took 87 s and 2.3 GB to typeset (or panicked);
/// now every name is limited like the `[project]` fields.
#[test]
fn long_names_are_refused_at_their_place() {
    let src = examples::text("seed-001-fourbar.toml");
    let joint = src.replacen("\"B\"", &format!("\"{}\"", "a".repeat(100_000)), 1);
    let (d, f) = task("long-joint", "task.toml", joint.as_bytes());
    let (code, _, err) = run_in(&d, &["run", &f, "--out", "o"]);
    assert_eq!(code, 2);
    let line = src[..src.find("\"B\"").unwrap()].matches('\n').count() + 1;
    assert!(err.contains(&format!("task.toml:{line}:")), "{}", &err[..2000]);
    assert!(
        err.contains("].joints[") && err.contains("100000 characters long"),
        "{}",
        &err[..2000]
    );
    let link = src.replacen("name = \"2\"", &format!("name = \"{}\"", "Ж".repeat(32_767)), 1);
    let (d, f) = task("long-link", "task.toml", link.as_bytes());
    let (code, _, err) = run_in(&d, &["run", &f, "--out", "o"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("linkage.links[2].name: the text is 32767 characters long"),
        "{}",
        &err[..2000]
    );
    // 300 characters are still a name
    let ok = src.replacen("name = \"2\"", &format!("name = \"{}\"", "Ж".repeat(300)), 1);
    let (d, f) = task("name-300", "task.toml", ok.as_bytes());
    let (code, _, err) = run_in(&d, &["linkage", &f]);
    assert_eq!(code, 0, "{err}");
}

/// `word-infinity-refused`: a title "Infinity gear", a student "Infinity"
/// and a link named `inf`, `NaN` or `Infinity` are the user's words and
/// are printed as given; the output guard refused them as non-finite numbers.
#[test]
fn words_like_infinity_are_printed_as_given() {
    for title in ["Infinity gear", "NaN", "inf", "Planetary gear for -inf"] {
        let (d, f) = task("title", "task.toml", format!("title = \"{title}\"\n{PLANETARY}").as_bytes());
        let (code, _, err) = run_in(&d, &["run", &f, "--out", "o", "--no-pdf"]);
        assert_eq!(code, 0, "{title}: {err}");
        let report = std::fs::read_to_string(d.join("o/report.json")).unwrap();
        assert!(report.contains(&format!("\"title\": \"{title}\"")), "{title}");
    }
    let (d, f) = task(
        "student",
        "task.toml",
        format!("[project]\nstudent = \"Infinity\"\n{PLANETARY}").as_bytes(),
    );
    let (code, _, err) = run_in(&d, &["run", &f, "--out", "o", "--no-pdf"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        std::fs::read_to_string(d.join("o/sheets/sheet-1.svg"))
            .unwrap()
            .contains("Infinity")
    );
    let src = examples::text("class3-triad.toml");
    for name in ["inf", "NaN", "Infinity"] {
        let t = src.replacen("name = \"5\"", &format!("name = \"{name}\""), 1);
        assert_ne!(t, src);
        let (d, f) = task("link", "task.toml", t.as_bytes());
        let (code, out, err) = run_in(&d, &["linkage", &f]);
        assert_eq!(code, 0, "{name}: {err}");
        assert!(out.contains(&format!("III(2,3,4,{name})")), "{name}: {out}");
        let (code, _, err) = run_in(&d, &["run", &f, "--out", "o", "--no-pdf"]);
        assert_eq!(code, 0, "{name}: {err}");
    }
}

/// `project-control-char`: a control character in a `[project]` field made
/// the sheet SVG invalid XML; now it (and every character XML forbids) is
/// refused at its place.
#[test]
fn control_characters_are_refused() {
    for esc in ["\\u0001", "\\u0000", "\\u001b", "\\ufffe", "\\uffff", "\\t", "\\u0085"] {
        let text = format!("title = \"x\"\n[project]\nstudent = \"A{esc}B\"\n{PLANETARY}");
        let (d, f) = task("control", "task.toml", text.as_bytes());
        let (code, _, err) = run_in(&d, &["run", &f, "--out", "o", "--no-pdf"]);
        assert_eq!(code, 2, "{esc}: {err}");
        assert!(
            err.contains("task.toml:3:11: project.student: control characters are not allowed"),
            "{esc}: {err}"
        );
        assert!(!d.join("o").exists());
    }
    // in a name too
    let src = examples::text("seed-001-fourbar.toml").replacen("name = \"2\"", "name = \"2\\u0007\"", 1);
    let (d, f) = task("control-name", "task.toml", src.as_bytes());
    let (code, _, err) = run_in(&d, &["linkage", &f]);
    assert_eq!(code, 2);
    assert!(err.contains("linkage.links[2].name: control characters are not allowed"), "{err}");
}

/// `cam-huge-stroke-infinity`: a stroke of 1e12 m was taken and printed
/// ρ = ∞; now the stroke is range-checked like the linkage's lengths.
#[test]
fn cam_stroke_is_range_checked() {
    let src = examples::text("cam-seed-001-flat.toml");
    for (stroke, ok) in [("1e12 m", false), ("99999999999999999999 mm", false), ("13 mm", true)] {
        let t = src.replacen("stroke = \"13 mm\"", &format!("stroke = \"{stroke}\""), 1);
        let (d, f) = task("cam", "task.toml", t.as_bytes());
        let (code, out, err) = run_in(&d, &["cam", &f]);
        assert!(!out.contains('∞'), "{stroke}");
        if ok {
            assert_eq!(code, 0, "{err}");
        } else {
            assert_eq!(code, 2, "{stroke}: {out}");
            assert!(err.contains("task.toml:10:10: cam.stroke:") && err.contains("1e4 m"), "{err}");
        }
    }
    let (code, _, err) = run(&[
        "cam",
        "--follower",
        "translating-roller",
        "--stroke",
        "1e12 m",
        "--phases",
        "rise 108 const-accel(u=1/3); dwell 15; return 108 const-accel(u=1/3); dwell 129",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("--stroke"), "{err}");
}

/// `gear-sliding-infinity`: where the contact reaches N2 the specific
/// sliding is unbounded; it is said in words, never printed as ∞.
#[test]
fn unbounded_sliding_is_said_in_words() {
    let d = common::tmp("input-limits", "gear");
    let args = [
        "gear", "pair", "--z1", "15", "--z2", "20", "--module", "5 mm", "--x1", "0.2", "--x2", "-0.85",
    ];
    let mut with_svg = args.to_vec();
    with_svg.extend(["--svg", "gm.svg"]);
    let (code, out, err) = run_in(&d, &with_svg);
    assert_eq!(code, 0, "{err}");
    assert!(!out.contains('∞') && out.contains("unbounded (contact reaches N2)"), "{out}");
    let svg = std::fs::read_to_string(d.join("gm.svg")).unwrap();
    assert!(!svg.contains('∞') && svg.contains("контакт доходит до N2"));
    let mut json = args.to_vec();
    json.push("--json");
    let o = tmm_in(&d, &json);
    let j = common::json(&o);
    assert!(j["theta2_max"].is_null() && j["theta2_unbounded"] == true && j["theta1_unbounded"] == false);
}

/// `bad-utf8-unlocated`: a byte that is not UTF-8 is located at its line
/// and column; the other file-level messages carry a place too.
#[test]
fn file_level_messages_are_located() {
    let src = examples::text("seed-001-fourbar.toml");
    let at = src.find("length = \"120 mm\"").unwrap() + "length = \"1".len();
    let mut bytes = src.into_bytes();
    bytes[at] = 0xff;
    let (d, f) = task("utf8", "task.toml", &bytes);
    let (code, _, err) = run_in(&d, &["linkage", &f]);
    assert_eq!(code, 2);
    assert!(
        err.contains("task.toml:17:12: the task file is not UTF-8 text: the byte 0xFF"),
        "{err}"
    );
    let (d, f) = task("nothing", "task.toml", b"title = \"x\"\n[project]\nstudent = \"A\"\n");
    let (code, _, err) = run_in(&d, &["run", &f, "--out", "o"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("task.toml:4:1: task file: the task file has no section to run"),
        "{err}"
    );
    let (code, _, err) = run_in(&d, &["linkage", &f]);
    assert_eq!(code, 2);
    assert!(err.contains("task.toml:4:1: linkage: the file has no [linkage] section"), "{err}");
    let long = format!("[project]\nstudent = \"{}\"\n{PLANETARY}", "a".repeat(301));
    let (d, f) = task("project-long", "task.toml", long.as_bytes());
    let (code, _, err) = run_in(&d, &["run", &f, "--out", "o"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("task.toml:2:11: project.student: the text is 301 characters long"),
        "{err}"
    );
}

/// `synth-unnamed-field`, `synth-huge-values-messages`: every refusal of a
/// synthesis names the option (or the task file's field at its line), huge
/// and tiny sizes are range-checked, and no NaN, inf or internal coordinate
/// is shown.
#[test]
fn synthesis_refusals_name_the_option() {
    let pos = ["--position", "30, 60", "--position", "60, 80", "--position", "90, 100"];
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec![
                "slotted-lever",
                "--stroke",
                "400 mm",
                "--k",
                "1.5",
                "--pivots",
                "50 mm",
                "--coupler-ratio",
                "0",
            ],
            "--coupler-ratio:",
        ),
        ([&["function-generation"][..], &pos, &["--frame", "0"]].concat(), "--frame:"),
        ([&["function-generation"][..], &pos, &["--frame", "1e300"]].concat(), "--frame:"),
        (
            vec!["crank-slider", "--k", "1.2", "--max-pressure", "45", "--stroke", "1e-9"],
            "--stroke:",
        ),
        (
            vec!["crank-slider", "--stroke", "1e300", "--k", "1.2", "--max-pressure", "45"],
            "--stroke:",
        ),
        (
            vec!["crank-slider", "--stroke", "1e300", "--k", "1.2", "--lambda", "4"],
            "--stroke:",
        ),
        (
            vec!["crank-slider", "--stroke", "9000 m", "--k", "1.2", "--lambda", "4"],
            "--stroke:",
        ),
        (
            vec![
                "six-bar-inversion",
                "--k",
                "1.15",
                "--travel",
                "1e300",
                "--guide",
                "-320 mm",
                "--start",
                "180 mm",
                "--coupler",
                "320 mm",
                "--swing",
                "70",
                "--lever",
                "360 mm",
            ],
            "--travel:",
        ),
    ];
    for (args, named) in cases {
        let mut a = vec!["synth"];
        a.extend(&args);
        let (code, _, err) = run(&a);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains(named), "{args:?}: {err}");
        for bad in ["NaN", "inf m", "links.", "degrees of freedom"] {
            assert!(!err.contains(bad), "{args:?}: {err}");
        }
    }
    let src = examples::text("synth-seed-002-ex3-shaper.toml");
    let line = src.lines().position(|l| l.starts_with("coupler_ratio")).unwrap() + 1;
    let t = src
        .lines()
        .map(|l| if l.starts_with("coupler_ratio") { "coupler_ratio = 0" } else { l })
        .collect::<Vec<_>>()
        .join("\n");
    let (d, f) = task("synth-file", "task.toml", t.as_bytes());
    let (code, _, err) = run_in(&d, &["run", &f, "--out", "o", "--no-pdf"]);
    assert_eq!(code, 2);
    assert!(err.contains(&format!("task.toml:{line}:17: synthesis.coupler_ratio:")), "{err}");
}

/// `dyn-rim-thin`: a flywheel ratio or density near zero gave a flywheel of
/// no finite size, reported without the field; now each is refused at its
/// place with its range.
#[test]
fn flywheel_ratios_are_range_checked() {
    let cases = [
        ("shape = \"rim\"\nthickness_ratio = 1e-300\n", "thickness_ratio"),
        ("width_ratio = \"1e-320\"\n", "width_ratio"),
        ("density = \"1e-320 g/cm^3\"\n", "density"),
    ];
    for (lines, field) in cases {
        let text = format!("{}\n[dynamics.flywheel]\n{lines}", tmm_report::run::DEFAULT_TASK);
        let (d, f) = task("flywheel", "task.toml", text.as_bytes());
        let (code, _, err) = run_in(&d, &["dynamics", &f, "--json"]);
        assert_eq!(code, 2, "{field}");
        assert!(
            err.contains(&format!("dynamics.flywheel.{field}: ")) && err.contains("outside the accepted range"),
            "{err}"
        );
    }
}

/// A header nested past the TOML reader's recursion limit came without a
/// place (`dotted.toml: task file: recursion limit`); it is located at the
/// line nested deepest and said in words.
#[test]
fn a_header_nested_too_deep_is_located() {
    let header = format!("[linkage{}]", ".a".repeat(99));
    let text = format!("{PLANETARY}\n{header}\nx = 1\n");
    let (d, f) = task("deep", "dotted.toml", text.as_bytes());
    for args in [vec!["run", "--no-pdf", f.as_str(), "-o", "o"], vec!["linkage", f.as_str()]] {
        let (code, _, err) = run_in(&d, &args);
        assert_eq!(code, 2, "{err}");
        // the header is on line 6 (the planetary section takes four lines and a blank one)
        assert!(err.contains("dotted.toml:6:1"), "{err}");
        assert!(err.contains("nested too deep"), "{err}");
    }
}
