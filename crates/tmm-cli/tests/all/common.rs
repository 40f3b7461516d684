//! What the CLI tests share: the built `tmm` (stdin closed), run in a given
//! folder; a fresh temporary folder per test; the repository's root; one JSON
//! document read off a successful run's stdout and a number in it; an example
//! edited into bad input and refused; the longest number in a message.

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

/// The number at the JSON pointer `p` of `v` (the test fails naming `p`
/// when there is none).
pub fn number(v: &serde_json::Value, p: &str) -> f64 {
    v.pointer(p)
        .and_then(serde_json::Value::as_f64)
        .unwrap_or_else(|| panic!("no number {p}"))
}

/// `tmm cmd FILE` on the repository's `example` with `from` replaced by `to`
/// (in a fresh folder of `module`'s, as `task.toml`): it must exit with code 2,
/// print nothing on stdout and locate its message in the file. The message.
pub fn refused_edit(module: &str, example: &str, cmd: &str, name: &str, from: &str, to: &str) -> String {
    let text = std::fs::read_to_string(repo().join(example)).unwrap();
    assert!(text.contains(from), "{from}");
    let dir = tmp(module, name);
    let p = dir.join("task.toml");
    std::fs::write(&p, text.replacen(from, to, 1)).unwrap();
    let o = tmm_in(&repo(), &[cmd, p.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2), "{name}: stdout {}", String::from_utf8_lossy(&o.stdout));
    assert!(o.stdout.is_empty());
    let e = String::from_utf8_lossy(&o.stderr).to_string();
    assert!(e.contains("task.toml:"), "{name}: not located: {e}");
    e
}
