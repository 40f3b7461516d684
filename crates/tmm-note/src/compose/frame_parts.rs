//! The introduction (введение) and the conclusion (заключение) of the note:
//! the machine and the project's aims with the list of the parts the task
//! has, and the results of every part gathered from the sections'
//! conclusions.

use super::context::Ctx;
use crate::error::NoteError;
use crate::model::{Block, Section, Span, Text};

/// The introduction: the course, the project's topic, its aims and parts.
pub(crate) fn introduction(cx: &Ctx, title: &str, sections: &[Section]) -> Result<Option<Section>, NoteError> {
    if sections.is_empty() {
        return Ok(None);
    }
    let topic = if title.is_empty() {
        cx.w("intro_default_topic")?
    } else {
        title.to_string()
    };
    let mut s = Section::new(cx.w("intro_title")?);
    s.blocks.push(cx.para("intro_course", &[topic])?);
    s.blocks.push(cx.para("intro_aims", &[])?);
    s.blocks.push(Block::List(
        sections
            .iter()
            .enumerate()
            .map(|(i, sec)| {
                let end = if i + 1 == sections.len() { "." } else { ";" };
                Text::plain(format!("{} {}{end}", i + 1, sec.title))
            })
            .collect(),
    ));
    s.blocks.push(cx.para("intro_methods", &[])?);
    Ok(Some(s))
}

/// The conclusion: for every section, its title and its conclusions.
pub(crate) fn conclusion(cx: &Ctx, sections: &[Section]) -> Result<Option<Section>, NoteError> {
    if sections.is_empty() {
        return Ok(None);
    }
    let conclusions_title = cx.w("sub_conclusions")?;
    let mut items = Vec::new();
    for sec in sections {
        let mut t = Text(vec![Span::Plain(format!("{}: ", lower_first(&sec.title)))]);
        let mut any = false;
        for sub in sec.subsections.iter().filter(|s| s.title == conclusions_title) {
            for b in &sub.blocks {
                if let Block::Paragraph(p) = b {
                    if any {
                        t.0.push(Span::Plain(" ".into()));
                        t.0.extend(p.0.iter().cloned());
                    } else {
                        // after the colon the first sentence goes on in lower case
                        let mut spans = p.0.clone();
                        if let Some(Span::Plain(first)) = spans.first_mut() {
                            let mut c = first.chars();
                            // a word ("В положении") or a one-letter
                            // Cyrillic preposition ("У положенні"), not a
                            // symbol ("W = 1")
                            if let (Some(a), Some(b)) = (c.next(), c.next())
                                && a.is_uppercase()
                                && (b.is_lowercase() || (b.is_whitespace() && "ВСКУОИАЯЗ".contains(a)))
                            {
                                *first = lower_first(first);
                            }
                        }
                        t.0.extend(spans);
                    }
                    any = true;
                }
            }
        }
        if any {
            items.push(t);
        }
    }
    if items.is_empty() {
        return Ok(None);
    }
    let mut s = Section::new(cx.w("conclusion_title")?);
    s.blocks.push(cx.para("conclusion_lead", &[])?);
    s.blocks.push(Block::List(items));
    Ok(Some(s))
}

/// A title with its first letter in lower case, for the middle of a sentence.
fn lower_first(s: &str) -> String {
    let mut c = s.chars();
    match c.next() {
        Some(f) => f.to_lowercase().chain(c).collect(),
        None => String::new(),
    }
}
