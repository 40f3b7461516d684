//! What the tests share: a task by name (the embedded default project or a
//! file under examples/), every task, the note's sections, blocks and
//! figures in order, a text outside its math.

use tmm_note::notation::{MATH_CLOSE, MATH_OPEN};
use tmm_note::{Block, Note, Section};
use tmm_report::TaskSource;
use tmm_report::run::{DEFAULT_TASK, Run};

/// The drawing sheets of a run (`sheets/sheet-N.svg`): each one's path and
/// SVG text.
pub fn sheet_svgs(run: &Run) -> Vec<(&str, &str)> {
    run.docs
        .iter()
        .filter(|d| d.path.starts_with("sheets/") && d.path.ends_with(".svg"))
        .map(|d| (d.path.as_str(), d.as_text().expect("a sheet is text")))
        .collect()
}

/// The task `name`: "default" for the embedded default project, else a
/// file under examples/.
pub fn task(name: &str) -> TaskSource {
    if name == "default" {
        return TaskSource::new("default.toml", DEFAULT_TASK);
    }
    let path = format!("{}/../../examples/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).expect("the example reads");
    TaskSource::new(path, text)
}

/// The default project and every task file under examples/ and
/// examples/textbook/, in the order of their paths.
pub fn all_tasks() -> Vec<TaskSource> {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut out = vec![task("default")];
    for dir in [root.clone(), root.join("textbook")] {
        let mut paths: Vec<_> = std::fs::read_dir(&dir)
            .expect("the examples read")
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "toml"))
            .collect();
        paths.sort();
        for p in paths {
            let text = std::fs::read_to_string(&p).expect("the example reads");
            out.push(TaskSource::new(p.display().to_string(), text));
        }
    }
    out
}

/// The text of `s` outside its math runs (the markers `notation` sets).
pub fn outside_math(s: &str) -> String {
    let mut out = String::new();
    let mut depth = 0_i32;
    for ch in s.chars() {
        match ch {
            MATH_OPEN => depth += 1,
            MATH_CLOSE => depth -= 1,
            _ if depth == 0 => out.push(ch),
            _ => {}
        }
    }
    out
}

/// A section and its subsections, depth first, in the order printed.
pub fn sections_in(s: &Section) -> Vec<&Section> {
    let mut out = vec![s];
    for sub in &s.subsections {
        out.extend(sections_in(sub));
    }
    out
}

/// Every section of the note (the introduction's, the sections', the
/// conclusion's and the appendices', with their subsections) in order.
pub fn note_sections(note: &Note) -> Vec<&Section> {
    note.introduction
        .iter()
        .chain(&note.sections)
        .chain(&note.conclusion)
        .chain(&note.appendices)
        .flat_map(sections_in)
        .collect()
}

/// The blocks of a section and its subsections, in order.
pub fn section_blocks(s: &Section) -> Vec<&Block> {
    sections_in(s).into_iter().flat_map(|s| &s.blocks).collect()
}

/// Every block of the note in the order printed: the assignment's, then
/// the sections' (see [`note_sections`]).
pub fn note_blocks(note: &Note) -> Vec<&Block> {
    note.assignment
        .iter()
        .chain(note_sections(note).into_iter().flat_map(|s| &s.blocks))
        .collect()
}

/// Every figure block of the note, in the order printed: the assignment's,
/// then the introduction's, the sections', the conclusion's and the
/// appendices'.
pub fn note_figures(note: &Note) -> Vec<&Block> {
    note_blocks(note)
        .into_iter()
        .filter(|b| matches!(b, Block::Figure { .. }))
        .collect()
}
