//! In-text references to every figure and table (ссылки на рисунки и
//! таблицы, GOST 2.105): each unlabelled figure or table of the sections
//! gets a label and a sentence before it that names it by its number
//! ("На рисунке 2.1 — схема механизма…", "… приведены в таблице 3.2").

use super::context::Ctx;
use crate::error::NoteError;
use crate::model::{Block, Section, Span, Text};

/// Labels every figure and table of `sections` and puts a referring
/// sentence before each.
pub(crate) fn add(cx: &Ctx, sections: &mut [Section]) -> Result<(), NoteError> {
    let mut n = 0;
    let fig = cx.w("ref_figure")?;
    let tab = cx.w("ref_table")?;
    for s in sections {
        walk(s, &fig, &tab, &mut n);
    }
    Ok(())
}

fn walk(s: &mut Section, fig: &str, tab: &str, n: &mut usize) {
    let mut out = Vec::with_capacity(s.blocks.len() * 2);
    for mut b in std::mem::take(&mut s.blocks) {
        let target = match &mut b {
            Block::Figure { label, caption, .. } if label.is_none() => Some((label, caption.clone(), fig)),
            Block::Table { label, caption, .. } if label.is_none() => Some((label, caption.clone(), tab)),
            _ => None,
        };
        if let Some((label, caption, words)) = target {
            *n += 1;
            let l = format!("ref-{n}");
            *label = Some(l.clone());
            out.push(Block::Paragraph(sentence(words, &l, &caption)));
        }
        out.push(b);
    }
    s.blocks = out;
    for sub in &mut s.subsections {
        walk(sub, fig, tab, n);
    }
}

/// The words with `{1}` the reference and `{2}` the caption (its first
/// letter lowered, unless it starts a name or a symbol).
fn sentence(words: &str, label: &str, caption: &str) -> Text {
    let caption = lower_first(caption);
    let mut t = Text(Vec::new());
    let (a, rest) = words.split_once("{1}").unwrap_or((words, ""));
    t.0.push(Span::Plain(a.to_string()));
    t.0.push(Span::Ref(label.to_string()));
    t.0.push(Span::Plain(rest.replace("{2}", &caption)));
    t
}

fn lower_first(s: &str) -> String {
    let mut c = s.chars();
    match (c.next(), c.clone().next()) {
        // a word of capitals (ГОСТ, Zhukovsky's) or a symbol keeps its case
        (Some(f), Some(g)) if f.is_uppercase() && g.is_lowercase() && !s.starts_with("Zhukovsky") => f.to_lowercase().chain(c).collect(),
        _ => s.to_string(),
    }
}
