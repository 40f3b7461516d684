//! What the CLI tests share: the built `tmm` (stdin closed), run in a given
//! folder; a fresh temporary folder per test; the repository's root; one JSON
//! document read off a successful run's stdout; the longest number in a
//! message.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

/// The repository's root, where `examples/` is.
pub fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The built `tmm` with its stdin closed.
pub fn tmm() -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_tmm"));
    c.stdin(Stdio::null());
    c
}

/// `tmm args` run in the folder `dir`.
pub fn tmm_in(dir: &Path, args: &[&str]) -> Output {
    tmm().args(args).current_dir(dir).output().expect("run tmm")
}

/// (exit code, stdout, stderr) of `tmm args`, run in the test's own folder.
pub fn run(args: &[&str]) -> (i32, String, String) {
    let o = tmm().args(args).output().expect("run tmm");
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

/// A fresh, empty folder for one test, `tmm-<module>-<pid>-<name>` in the
/// system's temporary folder (what an earlier run left there is removed).
pub fn tmp(module: &str, name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("tmm-{module}-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The stdout of a run that succeeded, as exactly one JSON document.
pub fn json(o: &Output) -> serde_json::Value {
    assert!(o.status.success(), "stderr: {}", String::from_utf8_lossy(&o.stderr));
    let s = String::from_utf8(o.stdout.clone()).unwrap();
    serde_json::from_str(&s).expect("stdout is exactly one JSON document")
}

/// The longest run of digits and points in `s`: a number written in full
/// (`1e300` as 301 digits) in a message. Written here, apart from tmm's own
/// tidying of message numbers.
pub fn longest_number(s: &str) -> usize {
    s.split(|c: char| !(c.is_ascii_digit() || c == '.'))
        .map(str::len)
        .max()
        .unwrap_or(0)
}
