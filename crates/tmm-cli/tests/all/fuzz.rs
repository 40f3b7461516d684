//! A mutation fuzzer over every task file in `examples/`, the embedded
//! default task and the command-line options, run as an ordinary test with a
//! fixed seed.
//!
//! The corpus is every task under `examples/` (recursively), the default
//! task, and tasks written here for the fields no example uses: every
//! `[synthesis]` kind, `[dynamics]` with a motor, shaft inertias and both
//! flywheel shapes, and a `[project]` with every field. Each case mutates a
//! task (a line deleted or duplicated, a number replaced by 0, a negative, a
//! huge or a tiny value, units swapped, a quoted string replaced by markup,
//! control characters, other scripts or 301 letters, the text truncated, a
//! byte flipped) and runs it. The command-line cases cover every subcommand,
//! `tmm synth` of every kind with `--svg`, `--task` and `--sweep` included.
//! The test fails on any panic, a case slower than the time limit, a run
//! taking more than 1 GiB, a non-finite number in any output, a character
//! XML forbids in an SVG, files written by a run that failed, any file left
//! beside the outputs (temporary files or folders) or a change to the user's
//! own files in the folder, a number written in full in a message (more than
//! 17 digits and points in a row), or an exit code other than 0, 1 or 2.
//!
//! `TMM_FUZZ_CASES` sets the number of in-process cases (default 2000);
//! every 25th case also runs through the `tmm` binary (with the note and the
//! sheets typeset on every 250th), and so do the command-line option cases.
//! Every case draws from its own generator, seeded by the case number, and the
//! cases are shared out over the machine's cores. `TMM_FUZZ_SEED` changes the
//! seed; `TMM_FUZZ_FROM=K TMM_FUZZ_CASES=1` replays case K alone, and a long
//! run goes in chunks (`TMM_FUZZ_FROM=25000 TMM_FUZZ_CASES=25000`, …). A
//! watchdog names a case that runs past the time limit (20 s,
//! `TMM_FUZZ_TIME_LIMIT` seconds) and aborts: it measures wall time, so a run
//! paused (SIGSTOP) for longer than the limit reports the case it was in. The long run
//! is `TMM_FUZZ_CASES=1000000 cargo test --release -p tmm-cli --test all fuzz:: -- --nocapture`.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use tmm_report::TaskSource;
use tmm_report::run::{DEFAULT_TASK, run_task};

use crate::common::{longest_number, repo};

/// A small deterministic generator (xorshift64*).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
    fn pick<'a, T>(&mut self, xs: &'a [T]) -> &'a T {
        &xs[self.below(xs.len())]
    }
}

/// Every task file under `examples/` (recursively), the embedded default
/// task, and the tasks of [`EXTRA`]: the `[synthesis]` kinds no example
/// poses, `[dynamics]` with every sub-table, and a `[project]` with every
/// field, so that each section's fields are mutated too.
fn corpus() -> Vec<(String, String)> {
    let mut v = vec![("default".to_string(), DEFAULT_TASK.to_string())];
    let mut files = Vec::new();
    let mut stack = vec![repo().join("examples")];
    while let Some(dir) = stack.pop() {
        for e in std::fs::read_dir(&dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|e| e == "toml") {
                files.push(p);
            }
        }
    }
    files.sort();
    let root = repo().join("examples");
    for f in files {
        v.push((
            f.strip_prefix(&root).unwrap_or(&f).to_string_lossy().into_owned(),
            std::fs::read_to_string(&f).unwrap(),
        ));
    }
    for (name, text) in EXTRA {
        v.push((name.to_string(), text.to_string()));
    }
    v
}

/// Tasks written for the fuzzer: each section's less common fields.
const EXTRA: [(&str, &str); 9] = [
    (
        "extra: crank-slider synthesis",
        "[synthesis]\nkind = \"crank-slider\"\nk = 1.2\nstroke = \"300 mm\"\nmax_pressure = \"45 deg\"\nspeed = \"90 rpm\"\n",
    ),
    (
        "extra: crank-slider by positions",
        "[synthesis]\nkind = \"crank-slider-positions\"\nlambda = 4\nlambda_e = 0.1\nphi_start = \"30 deg\"\nphi_end = \"200 deg\"\ntravel = \"300 mm\"\n",
    ),
    (
        "extra: function generation",
        "[synthesis]\nkind = \"function-generation\"\npositions = [[30, 60], [60, 80], [90, 100]]\nframe = \"300 mm\"\n",
    ),
    (
        "extra: slotted lever",
        "[synthesis]\nkind = \"slotted-lever\"\nstroke = \"400 mm\"\nk = 1.5\npivots = \"50 mm\"\ncoupler_ratio = 3\nlever = \"oscillating\"\n",
    ),
    (
        "extra: six-bar by inversion",
        "[synthesis]\nkind = \"six-bar-inversion\"\nk = 1.15\ntravel = \"400 mm\"\nguide = \"-320 mm\"\nstart = \"180 mm\"\ncoupler = \"320 mm\"\nswing = \"70 deg\"\nlever = \"360 mm\"\n",
    ),
    (
        "extra: synthesis sweep",
        "[synthesis]\nkind = \"crank-rocker\"\nk = 1.28\nswing = \"60 deg\"\nrocker = \"245 mm\"\noptimum = true\nsweep = \"k=1.1..1.4:7\"\n",
    ),
    (
        "extra: dynamics with a motor and a rim",
        concat!(
            include_str!("../../../../examples/seed-001-fourbar.toml"),
            "\n[dynamics.motor]\nsynchronous_speed = \"1500 rpm\"\nnominal_speed = \"1430 rpm\"\n",
            "nominal_torque = \"200 N m\"\nratio = 1.6\n",
            "[dynamics.inertia]\ncrank_shaft = \"0.1 kg m^2\"\nmotor_shaft = \"0.015 kg m^2\"\n",
            "[dynamics.flywheel]\nplace = \"motor\"\ndensity = \"7.85 g/cm^3\"\nshape = \"rim\"\nthickness_ratio = 0.1\nwidth_ratio = 0.2\n",
        ),
    ),
    (
        "extra: dynamics with a disc",
        concat!(
            include_str!("../../../../examples/seed-004-two-sliders.toml"),
            "\n[dynamics.flywheel]\nplace = \"crank\"\nshape = \"disc\"\nwidth_ratio = 0.25\ndensity = \"7200 kg/m^3\"\n",
        ),
    ),
    (
        "extra: every project field",
        concat!(
            "title = \"Планетарная передача\"\n[project]\nuniversity = \"Харківський університет\"\n",
            "department = \"Кафедра ТММ\"\nstudent = \"Петренко П. П.\"\ngroup = \"М-21\"\nteacher = \"Іваненко І. І.\"\n",
            "variant = \"12б\"\ncity = \"Харків\"\nyear = 2026\ntitle = \"Проєктування планетарної передачі\"\n",
            "designation = \"ТММ.КП.012.00.000\"\nlang = \"uk\"\nframe = true\nsheet = \"A2\"\n",
            "[planetary]\nscheme = \"ext-int\"\nratio = 12\nplanets = 3\nmodule = \"2 mm\"\n",
        ),
    ),
];

/// Strings a user may type into a name or a title: empty, long, markup of
/// every output format, other scripts. (The words NaN and Infinity as user
/// text have their own tests; here the output scan would take them for
/// numbers.)
const STRINGS: [&str; 10] = [
    "",
    " ",
    "#read(\\\"/etc/passwd\\\") $x$ *b* _i_ // /* <x> @ref",
    "<svg onload='x'>&amp;&lt;]]>",
    "\\u0001",
    "שלום مرحبا 👍 e\u{301}",
    "trailing space ",
    "\\n\\t\\r",
    "%s %d {} {{}} \\\\",
    "a\\u0000b",
];

/// Positions of the quoted strings in a text (inside the quotes): (start, end).
fn string_spans(t: &str) -> Vec<(usize, usize)> {
    let b = t.as_bytes();
    let mut v = Vec::new();
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'"' {
            let s = i + 1;
            i += 1;
            while i < b.len() && b[i] != b'"' && b[i] != b'\n' {
                i += if b[i] == b'\\' { 2 } else { 1 };
            }
            if i < b.len() && b[i] == b'"' {
                v.push((s, i));
            }
        }
        i += 1;
    }
    v
}

const NUMBERS: [&str; 14] = [
    "0",
    "-1",
    "-120",
    "1e300",
    "1e-300",
    "1e160",
    "1e9",
    "-0",
    "0.0000001",
    "nan",
    "inf",
    "100000",
    "3",
    "1e6",
];
const UNIT_SWAPS: [(&str, &str); 10] = [
    ("mm", "m"),
    (" m\"", " mm\""),
    ("deg", "rad"),
    ("rpm", "rad/s"),
    ("rad/s", "rpm"),
    ("kg", "N"),
    (" N\"", " kN\""),
    ("N·m", "mm"),
    ("°", " rpm"),
    ("MPa", "kg"),
];

/// Positions of the numbers in a text: (start, end).
fn number_spans(t: &str) -> Vec<(usize, usize)> {
    let b = t.as_bytes();
    let mut v = Vec::new();
    let mut i = 0;
    while i < b.len() {
        if b[i].is_ascii_digit() && (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_')) {
            let s = i;
            while i < b.len() && (b[i].is_ascii_digit() || b[i] == b'.' || b[i] == b'e' || b[i] == b'-') {
                i += 1;
            }
            v.push((s, i));
        } else {
            i += 1;
        }
    }
    v
}

/// One mutation of `t` (the result may not be valid UTF-8 only for byte flips,
/// which are returned as bytes).
fn mutate(rng: &mut Rng, t: &str) -> Vec<u8> {
    let lines: Vec<&str> = t.lines().collect();
    let rounds = 1 + rng.below(3);
    let mut text = t.to_string();
    for _ in 0..rounds {
        match rng.below(9) {
            0 if !lines.is_empty() => {
                let mut l: Vec<&str> = text.lines().collect();
                if !l.is_empty() {
                    let i = rng.below(l.len());
                    l.remove(i);
                }
                text = l.join("\n");
            }
            1 => {
                let mut l: Vec<String> = text.lines().map(str::to_string).collect();
                if !l.is_empty() {
                    let i = rng.below(l.len());
                    let dup = l[i].clone();
                    l.insert(i, dup);
                }
                text = l.join("\n");
            }
            2..=4 => {
                let spans = number_spans(&text);
                if !spans.is_empty() {
                    let (s, e) = *rng.pick(&spans);
                    let v: &str = NUMBERS[rng.below(NUMBERS.len())];
                    text.replace_range(s..e, v);
                }
            }
            5 => {
                let (a, b) = *rng.pick(&UNIT_SWAPS);
                let hits: Vec<usize> = text.match_indices(a).map(|m| m.0).collect();
                if !hits.is_empty() {
                    let at = *rng.pick(&hits);
                    text.replace_range(at..at + a.len(), b);
                }
            }
            7 => {
                let spans = string_spans(&text);
                if !spans.is_empty() {
                    let (s, e) = *rng.pick(&spans);
                    // one in eleven: past the 300-character limit of a name
                    let v = match rng.below(STRINGS.len() + 1) {
                        i if i < STRINGS.len() => STRINGS[i].to_string(),
                        _ => "Ж".repeat(301),
                    };
                    text.replace_range(s..e, &v);
                }
            }
            6 => {
                let mut cut = rng.below(text.len() + 1);
                while !text.is_char_boundary(cut) {
                    cut -= 1;
                }
                text.truncate(cut);
            }
            _ => {
                let mut bytes = text.into_bytes();
                if !bytes.is_empty() {
                    let i = rng.below(bytes.len());
                    bytes[i] ^= 1 << rng.below(8);
                }
                return bytes;
            }
        }
    }
    text.into_bytes()
}

/// A word `NaN`, `inf` or `Infinity` standing alone: written independently of
/// the check inside tmm, so that the two do not share a mistake.
fn has_nonfinite(s: &str) -> bool {
    let word = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
    let b = s.as_bytes();
    let mut i = 0;
    while i < b.len() {
        if !word(b[i]) {
            i += 1;
            continue;
        }
        let start = i;
        while i < b.len() && word(b[i]) {
            i += 1;
        }
        if matches!(&b[start..i], b"NaN" | b"inf" | b"Infinity") {
            return true;
        }
    }
    false
}

/// Marks a fuzz worker idle when dropped.
struct Idle<'a>(&'a AtomicUsize);

impl Drop for Idle<'_> {
    fn drop(&mut self) {
        self.0.store(0, Ordering::Relaxed);
    }
}

/// [`has_nonfinite`] on `s` with the user's own strings of the task (a
/// title "pair inf/60", a link `NaN`, as written, escaped for XML or for
/// JSON) taken out first: those are words the user wrote, not numbers.
fn has_nonfinite_beyond(s: &str, task: &TaskSource) -> bool {
    let mut rest = s.to_string();
    for u in tmm_report::user_text::excused(task) {
        let json = serde_json::to_string(&u).unwrap_or_default();
        for form in [json.trim_matches('"').to_string(), u] {
            if !form.is_empty() {
                rest = rest.replace(&form, " ");
            }
        }
    }
    has_nonfinite(&rest)
}

/// A character XML 1.0 forbids in a document (§ 2.2 Char): control
/// characters other than tab, line feed and carriage return, surrogates,
/// U+FFFE and U+FFFF. An SVG holding one is refused by browsers and CAD.
fn not_xml_char(c: char) -> bool {
    matches!(c, '\u{0}'..='\u{8}' | '\u{b}' | '\u{c}' | '\u{e}'..='\u{1f}' | '\u{fffe}' | '\u{ffff}')
}

/// A message may hold a 12-digit number with a sign, a point and 4 decimals at most.
const LONGEST_NUMBER: usize = 17;

#[test]
fn the_number_check_measures_runs_of_digits() {
    assert_eq!(longest_number("got 1e300 mm, z1 = 4294967295"), 10);
    assert_eq!(longest_number(&format!("the sum {:.4}", 1e300)), 306);
    assert_eq!(longest_number("no digits"), 0);
}

#[test]
fn the_nonfinite_check_finds_whole_words_only() {
    for bad in ["x=\"NaN\"", "NaN", "1, inf]", "-Infinity", "ω=inf рад/с", "(NaN)"] {
        assert!(has_nonfinite(bad), "{bad}");
    }
    for good in ["info", "NaNo", "Infinityx", "_inf", "inflate", "", "значение"] {
        assert!(!has_nonfinite(good), "{good}");
    }
}

/// The time a case may take (20 s; `TMM_FUZZ_TIME_LIMIT` in seconds for a
/// long run beside other work at low priority, where a case may wait).
fn time_limit() -> Duration {
    let secs = std::env::var("TMM_FUZZ_TIME_LIMIT").ok().and_then(|v| v.parse().ok()).unwrap_or(20);
    Duration::from_secs(secs)
}

fn tmm() -> PathBuf {
    PathBuf::from(env!("CARGO_BIN_EXE_tmm"))
}

/// Run the binary with a time limit; (exit code, stdout, stderr).
fn run_bin(args: &[&str], dir: &Path) -> (i32, String, String) {
    let mut child = Command::new(tmm())
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // read both pipes while waiting, or a large output would block the child
    let mut so = child.stdout.take().unwrap();
    let mut se = child.stderr.take().unwrap();
    let to = std::thread::spawn(move || {
        let mut b = Vec::new();
        std::io::Read::read_to_end(&mut so, &mut b).ok();
        b
    });
    let te = std::thread::spawn(move || {
        let mut b = Vec::new();
        std::io::Read::read_to_end(&mut se, &mut b).ok();
        b
    });
    let start = Instant::now();
    let status_file = PathBuf::from(format!("/proc/{}/status", child.id()));
    let mut peak_kib = 0;
    let status = loop {
        if let Some(st) = child.try_wait().unwrap() {
            break st;
        }
        peak_kib = peak_kib.max(peak_memory_kib(&status_file));
        if start.elapsed() > time_limit() {
            let _ = child.kill();
            panic!("timeout: tmm {}", args.join(" "));
        }
        std::thread::sleep(Duration::from_millis(2));
    };
    assert!(
        peak_kib <= MEMORY_LIMIT_KIB,
        "tmm {} took {peak_kib} KiB of memory (the bound is {MEMORY_LIMIT_KIB} KiB)",
        args.join(" ")
    );
    (
        status.code().unwrap_or(-1),
        String::from_utf8_lossy(&to.join().unwrap()).into_owned(),
        String::from_utf8_lossy(&te.join().unwrap()).into_owned(),
    )
}

/// The memory a run may take: 1 GiB (issue: a small input finishes in
/// 10 s and 1 GB, or is refused at once).
const MEMORY_LIMIT_KIB: u64 = 1 << 20;

/// The peak resident size of a running process (`VmHWM` in
/// `/proc/PID/status`, Linux), 0 where it cannot be read (another system,
/// or the process has just ended). Sampled while the run goes, so a peak
/// shorter than the sampling step may be missed; the bound is for inputs
/// that grow memory over seconds.
fn peak_memory_kib(status: &Path) -> u64 {
    std::fs::read_to_string(status)
        .ok()
        .and_then(|s| {
            s.lines()
                .find_map(|l| l.strip_prefix("VmHWM:"))
                .and_then(|v| v.trim().trim_end_matches("kB").trim().parse().ok())
        })
        .unwrap_or(0)
}

/// The user's own files in a fuzz case's folder, which no run may touch.
const USER_FILES: [(&str, &str); 2] = [("mine.txt", "the user's notes\n"), ("keep/positions.svg", "<svg/>\n")];

/// Put the user's own files into a case's folder.
fn plant_user_files(work: &Path) {
    for (name, text) in USER_FILES {
        let p = work.join(name);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, text).unwrap();
    }
}

/// After a run in `work`: the user's files are as they were and nothing
/// but `expected` (the task, the outputs of a run that succeeded) was added
/// beside them — no temporary file or folder of a failed or finished run.
fn check_folder(work: &Path, expected: &[&str], what: &str) {
    for (name, text) in USER_FILES {
        let got = std::fs::read_to_string(work.join(name)).unwrap_or_default();
        assert_eq!(got, text, "{what}: the user's file {name} was changed or removed");
    }
    for e in std::fs::read_dir(work).unwrap() {
        let name = e.unwrap().file_name().to_string_lossy().into_owned();
        assert!(
            name == "mine.txt" || name == "keep" || expected.contains(&name.as_str()),
            "{what}: `{name}` was left in the folder"
        );
    }
    let keep: Vec<_> = std::fs::read_dir(work.join("keep")).unwrap().collect();
    assert_eq!(keep.len(), 1, "{what}: files were added to the user's folder keep/");
}

fn check_bin(args: &[&str], dir: &Path, what: &str) -> i32 {
    check_bin_full(args, dir, what).0
}

/// [`check_bin`] that also returns stdout and stderr.
fn check_bin_full(args: &[&str], dir: &Path, what: &str) -> (i32, String, String) {
    let (code, out, err) = run_bin(args, dir);
    assert!(matches!(code, 0..=2), "{what}: exit code {code}\nargs: {args:?}\nstderr: {err}");
    assert!(!err.contains("panicked"), "{what}: panic\nargs: {args:?}\n{err}");
    assert!(!has_nonfinite(&out), "{what}: non-finite number on stdout\nargs: {args:?}");
    (code, out, err)
}

fn cases() -> usize {
    std::env::var("TMM_FUZZ_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(2000)
}

fn seed() -> u64 {
    std::env::var("TMM_FUZZ_SEED")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(0x5eed_7a5c_0ffe_e001)
}

/// What one worker saw: cases run, refused, and the slowest in-process run.
#[derive(Default)]
struct Tally {
    ok: usize,
    refused: usize,
    slowest: Duration,
}

/// The generator of case `case`: every case has its own stream, so a case is
/// reproduced by its number alone and the workers may share the cases out.
fn case_rng(case: usize) -> Rng {
    // splitmix64 of the case number, mixed with the seed (never zero)
    let mut z = (case as u64).wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    Rng((seed() ^ z ^ (z >> 31)) | 1)
}

/// One case: mutate, run in process, and every 25th through the binary.
fn fuzz_case(case: usize, corpus: &[(String, String)], work: &Path, tally: &mut Tally) {
    let mut rng = case_rng(case);
    let (name, text) = rng.pick(corpus);
    let bytes = mutate(&mut rng, text);
    let what = format!("case {case} (from {name})");
    if let Ok(text) = std::str::from_utf8(&bytes) {
        let src = TaskSource::new("task.toml", text);
        let t0 = Instant::now();
        let r = std::panic::catch_unwind(|| run_task(&src));
        let dt = t0.elapsed();
        tally.slowest = tally.slowest.max(dt);
        let Ok(r) = r else {
            panic!("{what}: panic on this task:\n{text}");
        };
        assert!(dt < time_limit(), "{what}: {dt:?}\n{text}");
        match r {
            Ok(run) => {
                tally.ok += 1;
                for d in &run.docs {
                    if let Some(t) = d.as_text() {
                        assert!(!has_nonfinite_beyond(t, &src), "{what}: non-finite number in {}\n{text}", d.path);
                        if d.path.ends_with(".svg") {
                            assert!(
                                !t.chars().any(not_xml_char),
                                "{what}: a character XML forbids in {}\n{text}",
                                d.path
                            );
                        }
                    }
                }
                for o in &run.sections {
                    assert!(
                        !has_nonfinite_beyond(&o.text, &src),
                        "{what}: non-finite number in the {} tables\n{text}",
                        o.section
                    );
                }
            }
            Err(e) => {
                tally.refused += 1;
                assert!(matches!(e.exit_code(), 1 | 2), "{what}: exit code {}", e.exit_code());
                let msg = e.to_string();
                assert!(!msg.is_empty());
                assert!(
                    longest_number(&msg) <= LONGEST_NUMBER,
                    "{what}: a number written in full in the message: {msg}"
                );
                for leak in ["Vec2 {", "Some(", "RawQty", "untagged enum"] {
                    assert!(!msg.contains(leak), "{what}: debug output in the message: {msg}");
                }
            }
        }
    }
    if case % 25 == 0 {
        let file = work.join("task.toml");
        std::fs::write(&file, &bytes).unwrap();
        let out = work.join("out");
        let _ = std::fs::remove_dir_all(&out);
        // the note and the sheets' PDF are typeset on every 250th case only:
        // typesetting takes most of a run's time
        let args: &[&str] = if case % 250 == 0 {
            &["run", "task.toml", "--out", "out"]
        } else {
            &["run", "task.toml", "--out", "out", "--no-pdf"]
        };
        let code = check_bin(args, work, &what);
        if code == 0 {
            assert!(out.join(".tmm-out").exists(), "{what}: no marker");
            check_folder(work, &["task.toml", "out"], &what);
        } else {
            assert!(!out.exists(), "{what}: a failed run left files");
            check_folder(work, &["task.toml"], &what);
        }
    }
}

#[test]
fn mutated_task_files() {
    let corpus = corpus();
    let n = cases();
    // `TMM_FUZZ_FROM` starts at a later case (to replay one, with TMM_FUZZ_CASES=1)
    let from: usize = std::env::var("TMM_FUZZ_FROM").ok().and_then(|v| v.parse().ok()).unwrap_or(0);
    let workers = std::thread::available_parallelism().map_or(1, |n| n.get()).min(8);
    let done = AtomicUsize::new(0);
    // what each worker runs now (case number + 1, 0 when idle) and since when
    let running: Vec<(AtomicUsize, Mutex<Instant>)> = (0..workers).map(|_| (AtomicUsize::new(0), Mutex::new(Instant::now()))).collect();
    let finished = AtomicBool::new(false);
    let started = Instant::now();
    let tallies: Vec<Tally> = std::thread::scope(|s| {
        // the watchdog: a case that runs past the time limit is a hang, which
        // no check after the run could see; name it and stop the process
        s.spawn(|| {
            while !finished.load(Ordering::Relaxed) {
                std::thread::sleep(Duration::from_millis(200));
                for (case, since) in &running {
                    let c = case.load(Ordering::Relaxed);
                    let t = *since.lock().unwrap_or_else(|e| e.into_inner());
                    if c > 0 && t.elapsed() > time_limit() {
                        let case = c - 1;
                        let mut rng = case_rng(case);
                        let (name, text) = rng.pick(&corpus);
                        let bytes = mutate(&mut rng, text);
                        eprintln!(
                            "fuzz: case {case} (from {name}) runs past {:?}: a hang; the task:\n{}",
                            time_limit(),
                            String::from_utf8_lossy(&bytes)
                        );
                        std::process::abort();
                    }
                }
            }
        });
        let handles: Vec<_> = (0..workers)
            .map(|w| {
                let (corpus, done, slot) = (&corpus, &done, &running[w]);
                s.spawn(move || {
                    let work = std::env::temp_dir().join(format!("tmm-fuzz-{}-{w}", std::process::id()));
                    let _ = std::fs::remove_dir_all(&work);
                    std::fs::create_dir_all(&work).unwrap();
                    plant_user_files(&work);
                    let mut tally = Tally::default();
                    for case in (from + w..from + n).step_by(workers) {
                        *slot.1.lock().unwrap_or_else(|e| e.into_inner()) = Instant::now();
                        slot.0.store(case + 1, Ordering::Relaxed);
                        // the slot is cleared when the case ends, by a panic
                        // (a failed check) too, so the watchdog never takes a
                        // failed case for a hang
                        let _idle = Idle(&slot.0);
                        fuzz_case(case, corpus, &work, &mut tally);
                        let d = done.fetch_add(1, Ordering::Relaxed) + 1;
                        if d % 10_000 == 0 {
                            eprintln!("fuzz: {d} cases in {:.1} s", started.elapsed().as_secs_f64());
                        }
                    }
                    let _ = std::fs::remove_dir_all(&work);
                    tally
                })
            })
            .collect();
        // a worker's panic (a failed case) fails the test with its message
        let joined: Vec<_> = handles.into_iter().map(|h| h.join()).collect();
        finished.store(true, Ordering::Relaxed);
        joined
            .into_iter()
            .map(|r| r.unwrap_or_else(|e| std::panic::resume_unwind(e)))
            .collect()
    });
    let ok: usize = tallies.iter().map(|t| t.ok).sum();
    let refused: usize = tallies.iter().map(|t| t.refused).sum();
    let slowest = tallies.iter().map(|t| t.slowest).max().unwrap_or_default();
    eprintln!(
        "fuzz: {n} cases (from case {from}, seed {:#x}, {workers} workers) in {:.1} s: \
         {ok} ran, {refused} refused with a message, slowest {slowest:?}",
        seed(),
        started.elapsed().as_secs_f64()
    );
}

#[test]
fn mutated_command_lines() {
    let mut rng = Rng(seed() ^ 0xabcdef);
    let work = std::env::temp_dir().join(format!("tmm-fuzz-cli-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&work);
    std::fs::create_dir_all(&work).unwrap();
    let ex = repo().join("examples");
    let ex = ex.to_string_lossy();
    let base: Vec<Vec<String>> = [
        "linkage {ex}/seed-001-fourbar.toml --at 15",
        "linkage {ex}/seed-003-sixbar.toml --positions 24 --json",
        "forces {ex}/seed-001-fourbar.toml --at 15 --json",
        "forces {ex}/seed-004-two-sliders.toml --at 40",
        "gear pair --z1 15 --z2 20 --module 5mm --x1 0.2 --x2 0.85",
        "gear pair --z1 16 --z2 20 --module 30mm --aw 560mm --json",
        "gear contour --z1 16 --z2 20 --n 41",
        "planetary --scheme sun-planet-ring --ratio 6 --planets 3",
        "planetary --scheme ext-int --ratio 12 --planets 3 --json",
        "cam --follower translating-roller --stroke 13mm --phases rise_108_cosine;dwell_15;return_108_cosine;dwell_129 --max-pressure 30",
        "dynamics {ex}/seed-001-fourbar.toml --json",
        "linkage {ex}/seed-002-shaper.toml --svg d",
        "synth crank-rocker --k 1.28 --swing 60 --rocker 245mm --crank 100mm --task t.toml",
        "synth crank-slider --stroke 300mm --k 1.2 --max-pressure 45 --svg d",
        "synth crank-slider --stroke 300mm --k 1.2 --sweep lambda=2..6:9 --json",
        "synth crank-slider-positions --lambda 4 --phi-start 30 --phi-end 200 --travel 300mm",
        "synth function-generation --position 30,_60 --position 60,_80 --position 90,_100 --frame 300mm --task t.toml",
        "synth slotted-lever --stroke 400mm --k 1.5 --pivots 50mm --coupler-ratio 3",
        "synth knee-press --stroke 90mm --k 1.12 --rocker 220mm --link 220mm --delta 10 --optimum --json",
        "synth six-bar-inversion --k 1.15 --travel 400mm --guide -320mm --start 180mm --coupler 320mm --swing 70 --lever 360mm",
        "synth six-bar-pressure --k 1.07 --swing 55 --arm-b 0.6m --arm-c 0.6m --guide -0.2m --max-pressure 38 --svg d",
    ]
    .iter()
    .map(|s| s.replace("{ex}", &ex).split(' ').map(|w| w.replace('_', " ")).collect())
    .collect();
    plant_user_files(&work);
    let n = (cases() / 10).max(100);
    for case in 0..n {
        let mut args = rng.pick(&base).clone();
        for _ in 0..1 + rng.below(2) {
            let i = rng.below(args.len());
            let v = &args[i];
            args[i] = match rng.below(6) {
                0 => rng.pick(&NUMBERS).to_string(),
                1 => format!("{}{}", rng.pick(&NUMBERS), rng.pick(&[" mm", " m", " deg", " rpm", "", " kN"])),
                2 => String::new(),
                3 => v.chars().rev().collect(),
                4 => "--positions".to_string(),
                _ => format!("{v}{v}"),
            };
        }
        let refs: Vec<&str> = args.iter().map(String::as_str).collect();
        let what = format!("command-line case {case}");
        let (code, _, err) = check_bin_full(&refs, &work, &what);
        // the outputs a command names (`--svg d`, `--task t.toml`) exist only
        // after a run that succeeded; nothing else is left beside them
        let named: Vec<&str> = args
            .windows(2)
            .filter(|w| matches!(w[0].as_str(), "--svg" | "--task" | "--out" | "--dxf" | "--csv"))
            .map(|w| w[1].as_str())
            .collect();
        check_folder(&work, if code == 0 { &named } else { &[] }, &what);
        for name in named.iter().filter(|n| !n.is_empty() && !n.contains("..")) {
            let p = work.join(name);
            let _ = std::fs::remove_dir_all(&p);
            let _ = std::fs::remove_file(&p);
        }
        // the message may quote the arguments themselves, but nothing longer
        let given = args.iter().map(|a| longest_number(a)).max().unwrap_or(0);
        if code == 2 {
            assert!(
                longest_number(&err) <= LONGEST_NUMBER.max(given),
                "{what}: a number written in full in the message\nargs: {args:?}\n{err}"
            );
        }
    }
    let _ = std::fs::remove_dir_all(&work);
}
