//! The library is built without a unit-test harness (`test = false` in its
//! Cargo.toml, so the test command compiles it once): a `#[cfg(test)]`
//! module inside it would never run. Its tests live here, in tests/all.

use std::path::Path;

fn rust_files(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for e in std::fs::read_dir(dir).expect("the source folder reads").flatten() {
        let p = e.path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// No source file of the library holds a test that cannot run.
#[test]
fn no_test_hides_in_the_library() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    assert!(files.len() > 20, "the library's sources are found");
    let hidden: Vec<String> = files
        .iter()
        .filter(|p| {
            let text = std::fs::read_to_string(p).unwrap_or_default();
            text.contains("#[cfg(test)]") || text.contains("#[test]")
        })
        .map(|p| p.display().to_string())
        .collect();
    assert!(
        hidden.is_empty(),
        "tests inside the library never run (test = false); move them to tests/all/units:\n{}",
        hidden.join("\n")
    );
}
