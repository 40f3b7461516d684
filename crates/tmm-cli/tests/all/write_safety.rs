//! Regression tests for file safety (issue 20, items 2, 3, 4 and 8): tmm
//! never deletes or replaces a file it did not write, races and signals
//! included; an interrupted or failed run leaves the old output or the new
//! one and nothing else; an existing empty folder is written in place; an
//! error that cannot be written to stderr is not a panic; output names of
//! up to 255 bytes work. Each test runs the `tmm` binary as a user would.
//! The tests that need root (a tmpfs mount, a second user) say so and skip
//! themselves without it; CI runs them as root.

use std::os::unix::fs::{MetadataExt, PermissionsExt};
use std::path::{Path, PathBuf};
use std::process::{Output, Stdio};
use std::time::{Duration, Instant};

use crate::common::{self, repo, tmm, tmm_in};

fn example(name: &str) -> String {
    repo().join("examples").join(name).to_string_lossy().into_owned()
}

fn tempdir(tag: &str) -> PathBuf {
    common::tmp("write-safety", tag)
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The fastest complete run: a planetary train, a few files.
const QUICK: &str = "planetary-int-int.toml";

fn is_root() -> bool {
    // SAFETY: geteuid has no preconditions.
    unsafe { libc::geteuid() == 0 }
}

/// The names in `dir` that are not `keep`: what a run left beside its output.
fn beside(dir: &Path, keep: &[&str]) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| !keep.contains(&n.as_str()))
        .collect();
    v.sort();
    v
}

/// Whether the tmm-made folder `out` is complete: every file its marker
/// lists is there.
fn complete(out: &Path) -> bool {
    let Ok(text) = std::fs::read_to_string(out.join(".tmm-out")) else {
        return false;
    };
    let files: Vec<&str> = text.lines().skip(1).filter(|l| !l.is_empty()).collect();
    !files.is_empty() && files.iter().all(|f| out.join(f).is_file())
}

/// `svg-overwrites-foreign`: `--svg DIR` refuses (exit 2, naming the file)
/// to replace a user's `positions.svg`, and keeps the user's other files.
#[test]
fn svg_dir_never_replaces_a_users_file() {
    let dir = tempdir("svg-foreign");
    let d = dir.join("d");
    std::fs::create_dir(&d).unwrap();
    std::fs::write(d.join("positions.svg"), "my precious drawing").unwrap();
    std::fs::write(d.join("notes.txt"), "mine").unwrap();
    let o = tmm_in(&dir, &["linkage", &example("seed-001-fourbar.toml"), "--svg", "d"]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("d/positions.svg") && err.contains("did not write"), "{err}");
    assert_eq!(std::fs::read_to_string(d.join("positions.svg")).unwrap(), "my precious drawing");
    assert_eq!(std::fs::read_to_string(d.join("notes.txt")).unwrap(), "mine");
    assert_eq!(beside(&d, &[]), ["notes.txt", "positions.svg"], "something was written");
    // without the clash the drawings are added, twice over (tmm replaces
    // what it wrote), and the user's file stays
    std::fs::remove_file(d.join("positions.svg")).unwrap();
    for _ in 0..2 {
        let o = tmm_in(&dir, &["linkage", &example("seed-001-fourbar.toml"), "--svg", "d"]);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    }
    assert!(d.join("positions.svg").is_file());
    assert_eq!(std::fs::read_to_string(d.join("notes.txt")).unwrap(), "mine");
    assert!(beside(&d, &[]).iter().all(|n| !n.contains(".tmm-tmp")), "{:?}", beside(&d, &[]));
}

/// `svg-overwrites-foreign`: `tmm note --out D` refuses to replace a
/// `note.pdf` tmm did not write, and replaces its own.
#[test]
fn note_out_never_replaces_a_users_note() {
    let dir = tempdir("note-foreign");
    let d = dir.join("d");
    std::fs::create_dir(&d).unwrap();
    std::fs::write(d.join("note.pdf"), "my own note").unwrap();
    let o = tmm_in(&dir, &["note", &example(QUICK), "--out", "d"]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("d/note.pdf"), "{err}");
    assert_eq!(std::fs::read_to_string(d.join("note.pdf")).unwrap(), "my own note");
    // the default, the current folder, twice: the second run replaces the
    // first one's note
    let here = dir.join("here");
    std::fs::create_dir(&here).unwrap();
    std::fs::write(here.join("task.toml"), std::fs::read(example(QUICK)).unwrap()).unwrap();
    for _ in 0..2 {
        let o = tmm_in(&here, &["note", "task.toml"]);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    }
    assert!(std::fs::read(here.join("note.pdf")).unwrap().starts_with(b"%PDF"));
}

/// `race-deletes-foreign`: files dropped into a tmm-made `--out` folder
/// while runs replace it are never deleted, and the folder is never
/// missing. Bounded: 12 s of runs (the old code lost about half the files
/// dropped in this pattern).
#[test]
fn a_file_dropped_in_while_a_run_replaces_the_folder_survives() {
    let dir = tempdir("race");
    let task = example(QUICK);
    let o = tmm_in(&dir, &["run", &task, "--out", "same", "--no-pdf"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let same = dir.join("same");
    let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    let runner = {
        let (stop, dir, task) = (stop.clone(), dir.clone(), task.clone());
        std::thread::spawn(move || {
            let mut codes = Vec::new();
            while !stop.load(std::sync::atomic::Ordering::Relaxed) {
                let o = tmm_in(&dir, &["run", &task, "--out", "same", "--no-pdf"]);
                codes.push(o.status.code());
            }
            codes
        })
    };
    let watcher = {
        let (stop, same) = (stop.clone(), same.clone());
        std::thread::spawn(move || {
            let mut missing = 0;
            while !stop.load(std::sync::atomic::Ordering::Relaxed) {
                if std::fs::symlink_metadata(&same).is_err() {
                    missing += 1;
                }
            }
            missing
        })
    };
    let (mut made, mut lost) = (0, Vec::new());
    let start = Instant::now();
    let mut step = 0u64;
    while start.elapsed() < Duration::from_secs(12) {
        // a pseudo-random pause of 0–30 ms, so the drop lands anywhere in a run
        step = step.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        std::thread::sleep(Duration::from_millis((step >> 33) % 31));
        let f = same.join(format!("user-{made}.txt"));
        if std::fs::write(&f, "user data").is_err() {
            continue;
        }
        made += 1;
        std::thread::sleep(Duration::from_millis(150));
        if !f.exists() {
            // a run may be moving it from the old folder into the new one
            std::thread::sleep(Duration::from_millis(100));
            if !f.exists() {
                lost.push(f);
                continue;
            }
        }
        std::fs::remove_file(&f).unwrap();
    }
    stop.store(true, std::sync::atomic::Ordering::Relaxed);
    let codes = runner.join().unwrap();
    let missing = watcher.join().unwrap();
    assert!(made >= 20, "only {made} files dropped in");
    assert!(lost.is_empty(), "{} of {made} user files deleted: {lost:?}", lost.len());
    assert_eq!(missing, 0, "the output folder was missing {missing} times while runs replaced it");
    assert!(codes.iter().all(|c| matches!(c, Some(0 | 2))), "{codes:?}");
    assert!(codes.contains(&Some(0)), "no run replaced the folder: {codes:?}");
    assert_eq!(beside(&dir, &["same"]), Vec::<String>::new());
}

/// `empty-out-replaced`: an existing empty folder is written in place,
/// keeping its inode, mode and owner, run after run.
#[test]
fn an_empty_out_folder_is_written_in_place() {
    let dir = tempdir("empty-in-place");
    let shared = dir.join("shared");
    std::fs::create_dir(&shared).unwrap();
    std::fs::set_permissions(&shared, std::fs::Permissions::from_mode(0o2777)).unwrap();
    if is_root() {
        // SAFETY: a valid NUL-terminated path; chown only reads it.
        let c = std::ffi::CString::new(shared.to_str().unwrap()).unwrap();
        assert_eq!(unsafe { libc::chown(c.as_ptr(), 65534, 65534) }, 0);
    }
    let before = std::fs::metadata(&shared).unwrap();
    for _ in 0..2 {
        let o = tmm_in(&dir, &["run", &example(QUICK), "--out", "shared", "--no-pdf"]);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        let after = std::fs::metadata(&shared).unwrap();
        assert_eq!(after.ino(), before.ino(), "the folder was replaced by a new one");
        assert_eq!(after.mode(), before.mode());
        assert_eq!((after.uid(), after.gid()), (before.uid(), before.gid()));
        assert!(complete(&shared));
    }
    assert_eq!(beside(&dir, &["shared"]), Vec::<String>::new());
    // `--out .` in an empty current folder
    let here = dir.join("here");
    std::fs::create_dir(&here).unwrap();
    for _ in 0..2 {
        let o = tmm_in(&here, &["run", &example(QUICK), "--out", ".", "--no-pdf"]);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        assert!(complete(&here));
    }
}

/// `empty-out-replaced`: an empty mount point is written in place (needs
/// root for the tmpfs mount; skipped without).
#[test]
fn an_empty_mount_point_is_written_in_place() {
    if !is_root() {
        eprintln!("skipped: needs root to mount a tmpfs");
        return;
    }
    let dir = tempdir("mount");
    let mnt = dir.join("mnt");
    std::fs::create_dir(&mnt).unwrap();
    let m = std::process::Command::new("mount")
        .args(["-t", "tmpfs", "tmpfs"])
        .arg(&mnt)
        .status();
    if !m.is_ok_and(|s| s.success()) {
        eprintln!("skipped: cannot mount a tmpfs here");
        return;
    }
    let runs: Vec<Output> = (0..2)
        .map(|_| tmm_in(&dir, &["run", &example(QUICK), "--out", "mnt", "--no-pdf"]))
        .collect();
    let whole = complete(&mnt);
    let _ = std::process::Command::new("umount").arg(&mnt).status();
    for o in &runs {
        assert_eq!(o.status.code(), Some(0), "{}", stderr(o));
    }
    assert!(whole);
}

/// `interrupt-leftovers`: runs replacing a good folder are interrupted by
/// SIGINT, SIGTERM or SIGKILL at 60–105 % of a run's time: `out/` is always
/// complete, SIGINT and SIGTERM leave nothing beside it, and what SIGKILL
/// leaves is removed by the next run. Bounded: 45 interrupted runs of a
/// quick task (the old code left a temporary folder after most of them).
#[test]
fn interrupted_runs_leave_the_old_output_or_the_new_and_nothing_else() {
    let dir = tempdir("signals");
    let task = example(QUICK);
    let args = ["run", task.as_str(), "--out", "out", "--no-pdf"];
    assert_eq!(tmm_in(&dir, &args).status.code(), Some(0));
    let t0 = Instant::now();
    assert_eq!(tmm_in(&dir, &args).status.code(), Some(0));
    let run = t0.elapsed().as_secs_f64();
    let mut step = 7u64;
    let mut after_soft = Vec::new();
    for i in 0..45 {
        step = step.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        let frac = 0.6 + 0.45 * ((step >> 11) as f64 / (1u64 << 53) as f64);
        let sig = [libc::SIGINT, libc::SIGTERM, libc::SIGKILL][i % 3];
        // what an earlier SIGKILL left (this run may be stopped before it
        // removes that)
        let before = beside(&dir, &["out"]);
        let mut child = tmm()
            .args(args)
            .current_dir(&dir)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(Duration::from_secs_f64(run * frac));
        // SAFETY: signalling our own child, which has not been waited for.
        unsafe { libc::kill(child.id() as libc::pid_t, sig) };
        child.wait().unwrap();
        assert!(complete(&dir.join("out")), "signal {sig}: out/ incomplete or missing");
        let mut left = beside(&dir, &["out"]);
        left.retain(|n| !before.contains(n));
        if sig != libc::SIGKILL && !left.is_empty() {
            after_soft.push((sig, left));
        }
    }
    assert!(after_soft.is_empty(), "left beside out/ after SIGINT/SIGTERM: {after_soft:?}");
    assert_eq!(tmm_in(&dir, &args).status.code(), Some(0));
    assert_eq!(beside(&dir, &["out"]), Vec::<String>::new(), "a killed run's leftovers stayed");
}

/// A pid that no process has (a child that has ended and been waited for).
fn dead_pid() -> u32 {
    let mut c = std::process::Command::new("true").spawn().unwrap();
    let pid = c.id();
    c.wait().unwrap();
    pid
}

/// `interrupt-leftovers`: what a killed run left (a half-built folder, an
/// old folder, a temporary file, in this and in the earlier naming) is
/// removed by the next run, except a file tmm did not write; a live
/// process's temporary folder is left alone.
#[test]
fn the_next_run_removes_a_killed_runs_leftovers() {
    let dir = tempdir("leftovers");
    let task = example(QUICK);
    let args = ["run", task.as_str(), "--out", "out", "--no-pdf"];
    assert_eq!(tmm_in(&dir, &args).status.code(), Some(0));
    let dead = dead_pid();
    let head = "# written by tmm; the next run replaces this folder and the files listed here\n";
    for name in [
        format!(".out.tmm-tmp-{dead}-0"),
        format!(".out.tmm-old-{dead}"),
        format!(".out.tmm-tmp-{dead}"),
    ] {
        let d = dir.join(&name);
        std::fs::create_dir_all(d.join("planetary")).unwrap();
        std::fs::write(d.join(".tmm-out"), format!("{head}report.json\nplanetary/a.svg\n")).unwrap();
        std::fs::write(d.join("report.json"), "{}").unwrap();
        std::fs::write(d.join("planetary/a.svg"), "<svg/>").unwrap();
    }
    std::fs::write(dir.join(format!(".report.json.tmm-tmp-{dead}-3")), "partial").unwrap();
    // a user's file inside a leftover folder stays
    let keep = dir.join(format!(".out.tmm-old-{dead}-1"));
    std::fs::create_dir(&keep).unwrap();
    std::fs::write(keep.join(".tmm-out"), format!("{head}report.json\n")).unwrap();
    std::fs::write(keep.join("report.json"), "{}").unwrap();
    std::fs::write(keep.join("mine.txt"), "user data").unwrap();
    // a running process's temporary folder stays
    let live = dir.join(format!(".out.tmm-tmp-{}-0", std::process::id()));
    std::fs::create_dir(&live).unwrap();
    let o = tmm_in(&dir, &args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let live_name = live.file_name().unwrap().to_string_lossy().into_owned();
    let keep_name = keep.file_name().unwrap().to_string_lossy().into_owned();
    let mut want = vec![keep_name, live_name];
    want.sort();
    assert_eq!(beside(&dir, &["out"]), want);
    assert_eq!(beside(&keep, &[]), ["mine.txt"]);
}

/// `fulldisk-leaves-temp`: on a full disk a single file's write fails with
/// exit 1 and leaves neither its partial temporary file nor the folder it
/// made (needs root for the small tmpfs; skipped without).
#[test]
fn a_full_disk_leaves_no_partial_file_and_no_made_folder() {
    if !is_root() {
        eprintln!("skipped: needs root to mount a small tmpfs");
        return;
    }
    let dir = tempdir("fulldisk");
    let m = std::process::Command::new("mount")
        .args(["-t", "tmpfs", "-o", "size=300k", "tmpfs"])
        .arg(&dir)
        .status();
    if !m.is_ok_and(|s| s.success()) {
        eprintln!("skipped: cannot mount a tmpfs here");
        return;
    }
    let note = tmm_in(&dir, &["note", &example("seed-001-fourbar.toml"), "--out", "nn"]);
    let left_note = beside(&dir, &[]);
    std::fs::write(dir.join("filler"), vec![0u8; 400 * 1024]).unwrap_or(());
    let synth = tmm_in(
        &dir,
        &[
            "synth",
            "crank-rocker",
            "--k",
            "1.28",
            "--swing",
            "60",
            "--rocker",
            "245 mm",
            "--crank",
            "100 mm",
            "--task",
            "t.toml",
        ],
    );
    let left_synth = beside(&dir, &["filler"]);
    let _ = std::process::Command::new("umount").arg(&dir).status();
    assert_eq!(note.status.code(), Some(1), "{}", stderr(&note));
    assert!(
        stderr(&note).contains("nn/note.pdf") && !stderr(&note).contains("tmm-tmp"),
        "{}",
        stderr(&note)
    );
    assert_eq!(left_note, Vec::<String>::new(), "left after the note");
    assert_eq!(synth.status.code(), Some(1), "{}", stderr(&synth));
    assert_eq!(left_synth, Vec::<String>::new(), "left after --task");
}

/// `readonly-out` (needs root to run tmm as another user; skipped
/// without): a tmm-made folder the user made read-only is refused, leaving
/// nothing beside it; an empty folder the user owns inside a parent they
/// cannot write is written in place; a folder that can only be made beside
/// is refused naming the user's folder and its parent.
#[test]
fn read_only_outputs_leave_nothing_and_messages_name_the_users_folder() {
    use std::os::unix::process::CommandExt;
    if !is_root() {
        eprintln!("skipped: needs root to run tmm as another user");
        return;
    }
    let dir = tempdir("readonly");
    std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o755)).unwrap();
    let chown = |p: &Path| {
        let c = std::ffi::CString::new(p.to_str().unwrap()).unwrap();
        // SAFETY: a valid NUL-terminated path; chown only reads it.
        assert_eq!(unsafe { libc::chown(c.as_ptr(), 65534, 65534) }, 0);
    };
    let task = dir.join("task.toml");
    std::fs::write(&task, std::fs::read(example(QUICK)).unwrap()).unwrap();
    std::fs::set_permissions(&task, std::fs::Permissions::from_mode(0o644)).unwrap();
    let as_user = |out: &str| {
        tmm()
            .args(["run", "task.toml", "--out", out, "--no-pdf"])
            .current_dir(&dir)
            .uid(65534)
            .gid(65534)
            .output()
            .unwrap()
    };
    let rw = dir.join("rw");
    std::fs::create_dir(&rw).unwrap();
    chown(&rw);
    assert_eq!(as_user("rw/out").status.code(), Some(0));
    std::fs::set_permissions(rw.join("out"), std::fs::Permissions::from_mode(0o555)).unwrap();
    let o = as_user("rw/out");
    let err = stderr(&o);
    assert_eq!(beside(&rw, &["out"]), Vec::<String>::new(), "left beside a read-only out: {err}");
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("rw/out") && err.contains("read-only"), "{err}");
    assert!(complete(&rw.join("out")));
    // an empty folder the user owns, in a parent they cannot write
    let ro2 = dir.join("ro2");
    std::fs::create_dir(&ro2).unwrap();
    chown(&ro2);
    let o = as_user("ro2");
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(complete(&ro2));
    // a tmm-made folder in a parent the user cannot write: replaced in
    // place? No: it is swapped, which needs the parent; the message says so
    let made = dir.join("made");
    assert_eq!(
        tmm_in(&dir, &["run", "task.toml", "--out", "made", "--no-pdf"]).status.code(),
        Some(0)
    );
    let o = std::process::Command::new("chown")
        .args(["-R", "65534:65534"])
        .arg(&made)
        .status()
        .unwrap();
    assert!(o.success());
    let o = as_user("made");
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains("made") && err.contains("must be writable") && !err.contains("tmm-tmp"),
        "{err}"
    );
    assert!(complete(&made));
    assert_eq!(beside(&dir, &["made", "ro2", "rw", "task.toml"]), Vec::<String>::new());
}

/// `readonly-out`: `--out /` is refused at once as a folder holding files
/// tmm did not write (exit 2), not after walking the whole tree.
#[test]
fn out_root_is_refused_as_holding_other_files() {
    let o = tmm().args(["run", &example(QUICK), "--out", "/", "--no-pdf"]).output().unwrap();
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("already holds files tmm did not write"), "{err}");
}

/// `long-out-name`: output names of 241–255 bytes work (new, existing and
/// empty, Cyrillic, a `--task` file); a longer one is refused as too long,
/// naming it.
#[test]
fn output_names_up_to_255_bytes_work() {
    let dir = tempdir("long-names");
    let task = example(QUICK);
    let latin = "o".repeat(250);
    let cyrillic = "п".repeat(121); // 242 bytes
    let full = "x".repeat(255);
    for name in [&latin, &cyrillic, &full] {
        for _ in 0..2 {
            let o = tmm_in(&dir, &["run", &task, "--out", name, "--no-pdf"]);
            assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
            assert!(complete(&dir.join(name)));
        }
    }
    let empty = "e".repeat(250);
    std::fs::create_dir(dir.join(&empty)).unwrap();
    let o = tmm_in(&dir, &["run", &task, "--out", &empty, "--no-pdf"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let t = format!("{}.toml", "t".repeat(250));
    let synth = [
        "synth",
        "crank-rocker",
        "--k",
        "1.28",
        "--swing",
        "60",
        "--rocker",
        "245 mm",
        "--crank",
        "100 mm",
        "--task",
        &t,
    ];
    let o = tmm_in(&dir, &synth);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(dir.join(&t).is_file());
    let mut names = beside(&dir, &[]);
    names.retain(|n| n.contains("tmm-"));
    assert!(names.is_empty(), "{names:?}");
    let too_long = "y".repeat(256);
    let o = tmm_in(&dir, &["run", &task, "--out", &too_long, "--no-pdf"]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("too long") && err.contains(&too_long) && !err.contains("tmm-tmp"),
        "{err}"
    );
}

/// `stderr-full-panic`: an error message that cannot be written (a full
/// stderr, a closed pipe) ends with the error's own exit code, no panic.
#[test]
fn an_unwritable_stderr_is_not_a_panic() {
    let full = std::fs::File::create("/dev/full").unwrap();
    let o = tmm().args(["linkage", "nonexist.toml"]).stderr(full).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    let full = std::fs::File::create("/dev/full").unwrap();
    let o = tmm()
        .args([
            "synth",
            "crank-rocker",
            "--k",
            "0.5",
            "--swing",
            "60",
            "--rocker",
            "1",
            "--crank",
            "0.1",
        ])
        .stderr(full)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    // a pipe whose reader has gone
    let mut fds = [0; 2];
    // SAFETY: `fds` has room for the two descriptors pipe writes.
    assert_eq!(unsafe { libc::pipe(fds.as_mut_ptr()) }, 0);
    // SAFETY: closing the read end we own; the write end is handed over below.
    unsafe { libc::close(fds[0]) };
    // SAFETY: fds[1] is an open descriptor owned by nothing else.
    let w = unsafe { <std::fs::File as std::os::fd::FromRawFd>::from_raw_fd(fds[1]) };
    let o = tmm().args(["linkage", "nonexist.toml"]).stderr(w).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
}

/// `--help` and `--version` written to a full device are failed writes
/// (exit 1), not a success; a usage error whose message cannot be written
/// keeps its exit code 2.
#[test]
fn help_on_a_full_device_is_a_failed_write() {
    for args in [&["--help"][..], &["--version"], &["run", "--help"]] {
        let full = std::fs::File::create("/dev/full").unwrap();
        let o = tmm().args(args).stdout(full).output().unwrap();
        assert_eq!(o.status.code(), Some(1), "{args:?}");
        let o = tmm().args(args).output().unwrap();
        assert_eq!(o.status.code(), Some(0), "{args:?}");
        assert!(!o.stdout.is_empty());
    }
    let full = std::fs::File::create("/dev/full").unwrap();
    let o = tmm().args(["--no-such-option"]).stderr(full).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
}
