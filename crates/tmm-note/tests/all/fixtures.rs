//! What the PDF read-back tests share: a task by name (the embedded default
//! project or a file under examples/) and the note's figures in order.

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

fn blocks<'a>(bs: &'a [Block], out: &mut Vec<&'a Block>) {
    out.extend(bs.iter().filter(|b| matches!(b, Block::Figure { .. })));
}

fn section<'a>(s: &'a Section, out: &mut Vec<&'a Block>) {
    blocks(&s.blocks, out);
    for sub in &s.subsections {
        section(sub, out);
    }
}

/// Every figure block of the note, in the order printed: the assignment's,
/// then the introduction's, the sections', the conclusion's and the
/// appendices'.
pub fn note_figures(note: &Note) -> Vec<&Block> {
    let mut out = Vec::new();
    blocks(&note.assignment, &mut out);
    for s in note
        .introduction
        .iter()
        .chain(&note.sections)
        .chain(&note.conclusion)
        .chain(&note.appendices)
    {
        section(s, &mut out);
    }
    out
}
