//! The repository's example tasks (примеры заданий), `examples/` and
//! `examples/textbook/`, found from this crate's own place in the
//! repository, so every crate's tests read the same files the same way.

use std::path::PathBuf;

/// The repository's `examples/` folder.
///
/// ```
/// assert!(tmm_testkit::examples::dir().join("textbook").is_dir());
/// ```
pub fn dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// The text of the example `name` (`"gear-seed001.toml"`,
/// `"textbook/p2-engine.toml"`); the test fails naming the file when it
/// cannot be read.
///
/// ```
/// let t = tmm_testkit::examples::text("textbook/p2-engine.toml");
/// assert!(t.contains("[linkage]"));
/// ```
pub fn text(name: &str) -> String {
    let path = dir().join(name);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// Every task file's name (`*.toml`) under `examples/` (sorted), then
/// under `examples/textbook/` (sorted, `textbook/` before each).
///
/// ```
/// let all = tmm_testkit::examples::names();
/// assert!(all.iter().any(|n| n == "gear-seed001.toml"));
/// let first_textbook = all.iter().position(|n| n.starts_with("textbook/")).unwrap();
/// assert!(all[first_textbook..].iter().all(|n| n.starts_with("textbook/")));
/// assert!(all[..first_textbook].is_sorted());
/// ```
pub fn names() -> Vec<String> {
    let mut out = Vec::new();
    for sub in ["", "textbook/"] {
        let d = dir().join(sub);
        let mut files: Vec<String> = std::fs::read_dir(&d)
            .unwrap_or_else(|e| panic!("{}: {e}", d.display()))
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .filter(|n| n.ends_with(".toml"))
            .map(|n| format!("{sub}{n}"))
            .collect();
        files.sort();
        out.extend(files);
    }
    out
}
