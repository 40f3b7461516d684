//! Every shipped example runs whole: `tmm run` WITH the note's PDF on every
//! file under `examples/` (recursively, so a new subfolder is covered
//! without a change here) and on every whole task written in a ```toml
//! block of `docs/*.md` and `README.md` (a block whose first line begins
//! `# an excerpt` lists keys and is not a task). Each run must exit 0 and
//! write `note.pdf` and the sheets (SVG, DXF and PDF).
//!
//! The runs are separate processes, run by as many threads as the machine
//! has cores; the test prints how long they took.

use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use crate::common::{repo, tmm, tmp};

/// The files under `dir`, recursively, sorted.
fn files_under(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("read {}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            files_under(&p, out);
        } else if p.extension().is_some_and(|e| e == "toml") {
            out.push(p);
        }
    }
}

/// The ```toml blocks of a Markdown text, each as (first line number, text).
pub fn toml_blocks(md: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    let mut cur: Option<(usize, String)> = None;
    for (i, line) in md.lines().enumerate() {
        match &mut cur {
            None if line.trim_start().starts_with("```toml") => cur = Some((i + 2, String::new())),
            Some(_) if line.trim_start().starts_with("```") => out.extend(cur.take()),
            Some((_, text)) => {
                text.push_str(line);
                text.push('\n');
            }
            None => {}
        }
    }
    out
}

/// The whole tasks written in the docs, as (name for messages, text).
fn doc_tasks() -> Vec<(String, String)> {
    let root = repo();
    let mut mds = vec![root.join("README.md")];
    let mut docs: Vec<PathBuf> = std::fs::read_dir(root.join("docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    docs.sort();
    mds.extend(docs);
    let mut out = Vec::new();
    for md in mds {
        let text = std::fs::read_to_string(&md).unwrap();
        for (line, block) in toml_blocks(&text) {
            if block.trim_start().starts_with("# an excerpt") {
                continue;
            }
            let name = md.file_name().unwrap().to_string_lossy().into_owned();
            out.push((format!("{name}:{line}"), block));
        }
    }
    out
}

/// What one run must leave: exit 0, `note.pdf`, and each sheet as SVG, DXF
/// and PDF. Returns the failure, if any.
fn check_run(name: &str, task: &Path, out: &Path) -> Option<String> {
    let o = tmm().arg("run").arg(task).arg("--out").arg(out).output().expect("run tmm");
    if !o.status.success() {
        return Some(format!(
            "{name}: exit {:?}\n{}",
            o.status.code(),
            String::from_utf8_lossy(&o.stderr)
        ));
    }
    let note = out.join("note.pdf");
    match std::fs::read(&note) {
        Ok(b) if b.starts_with(b"%PDF-") => {}
        _ => return Some(format!("{name}: no note.pdf in {}", out.display())),
    }
    let sheets: Vec<String> = std::fs::read_dir(out.join("sheets"))
        .map(|d| d.map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect())
        .unwrap_or_default();
    let svgs: Vec<&String> = sheets.iter().filter(|s| s.ends_with(".svg")).collect();
    if svgs.is_empty() {
        return Some(format!("{name}: no sheets/*.svg"));
    }
    for svg in svgs {
        for ext in ["dxf", "pdf"] {
            let other = svg.replace(".svg", &format!(".{ext}"));
            if !sheets.contains(&other) {
                return Some(format!("{name}: {svg} has no {other}"));
            }
        }
    }
    None
}

#[test]
fn every_example_and_doc_task_runs_with_the_note() {
    let root = repo();
    let dir = tmp("every_example", "all");
    let mut jobs: Vec<(String, PathBuf)> = Vec::new();
    let mut examples = Vec::new();
    files_under(&root.join("examples"), &mut examples);
    assert!(examples.len() >= 20, "examples/ holds {} task files", examples.len());
    for p in examples {
        let name = p.strip_prefix(&root).unwrap().to_string_lossy().into_owned();
        jobs.push((name, p));
    }
    let docs = doc_tasks();
    assert!(!docs.is_empty(), "no whole task in the docs' ```toml blocks");
    for (i, (name, text)) in docs.into_iter().enumerate() {
        let p = dir.join(format!("doc-{i}.toml"));
        std::fs::write(&p, text).unwrap();
        jobs.push((name, p));
    }
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    let next = AtomicUsize::new(0);
    let failures = Mutex::new(Vec::new());
    let start = Instant::now();
    std::thread::scope(|s| {
        for _ in 0..threads {
            s.spawn(|| {
                loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some((name, task)) = jobs.get(i) else { break };
                    if let Some(f) = check_run(name, task, &dir.join(format!("out-{i}"))) {
                        failures.lock().unwrap().push(f);
                    }
                }
            });
        }
    });
    eprintln!(
        "every_example: {} runs with the note on {threads} threads in {:.1} s",
        jobs.len(),
        start.elapsed().as_secs_f64()
    );
    let failures = failures.into_inner().unwrap();
    assert!(
        failures.is_empty(),
        "{} of {} runs failed:\n{}",
        failures.len(),
        jobs.len(),
        failures.join("\n")
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn doc_blocks_are_found_and_excerpts_skipped() {
    let md = "text\n```toml\n# an excerpt: keys\na = 1\n```\n```toml\n[x]\nb = 2\n```\n```sh\ntmm\n```\n";
    let b = toml_blocks(md);
    assert_eq!(b.len(), 2);
    assert_eq!(b[1], (7, "[x]\nb = 2\n".to_string()));
    assert!(b[0].1.starts_with("# an excerpt"));
}

/// The language a task's note is written in: `[project] lang`, else ru.
fn note_language(task: &toml::Table) -> String {
    task.get("project")
        .and_then(|p| p.get("lang"))
        .and_then(|l| l.as_str())
        .unwrap_or("ru")
        .to_string()
}

/// No example's title is in another language than its note: a Russian or
/// Ukrainian note is not headed by an English title (a teacher returned
/// "Seed 003: six-bar…" on a Russian note), nor an English note by a
/// Cyrillic one. The book's appendix numbers (П2) are names and pass.
#[test]
fn every_examples_title_is_in_its_notes_language() {
    let mut files = Vec::new();
    files_under(&repo().join("examples"), &mut files);
    let mut wrong = Vec::new();
    for f in &files {
        let text = std::fs::read_to_string(f).unwrap();
        let task: toml::Table = toml::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", f.display()));
        let Some(title) = task.get("title").and_then(|t| t.as_str()) else {
            continue;
        };
        // the words of the title, its appendix numbers (П1.1, П2) left out
        let words: String = title
            .split_whitespace()
            .filter(|w| !(w.starts_with('П') && w[2..].starts_with(|c: char| c.is_ascii_digit())))
            .collect::<Vec<_>>()
            .join(" ");
        let cyrillic = words.chars().filter(|c| ('\u{400}'..='\u{4ff}').contains(c)).count();
        let latin = words.chars().filter(|c| c.is_ascii_alphabetic()).count();
        let lang = note_language(&task);
        let ok = match lang.as_str() {
            "en" => cyrillic == 0,
            // symbols such as m, a_w or K may stand in a Russian title
            _ => cyrillic > 0 && cyrillic >= 2 * latin,
        };
        if !ok {
            wrong.push(format!("{}: title \"{title}\" on a note in `{lang}`", f.display()));
        }
    }
    assert!(wrong.is_empty(), "titles in another language than the note:\n{}", wrong.join("\n"));
}
