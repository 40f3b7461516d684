//! Where the figures stand in the text: each figure of a subsection, with
//! the sentence that names it (`references.rs`), is moved up to the head of
//! its subsection — after the subsection's first paragraph — keeping the
//! figures' order.
//!
//! A figure floats (template.typ): it is set at the foot of the page of its
//! sentence when it fits there, else at the head of the next page, and the
//! text after it fills the rest. Named early, a subsection's figures find
//! room between its tables and paragraphs; named last, they would wait
//! until the text has run out and leave its last text page half empty in
//! the section's middle (GOST 2.105-95, 4.3.1 asks only that a figure
//! stand after the text that first names it or on the next page).

use crate::model::{Block, Section};

/// Moves the figures of every subsection of `sections` (and of the
/// sections themselves) to their heads.
pub(crate) fn figures_early(sections: &mut [Section]) {
    for s in sections {
        early(s);
    }
}

fn early(s: &mut Section) {
    let blocks = std::mem::take(&mut s.blocks);
    let mut head = Vec::new();
    let mut figures = Vec::new();
    let mut rest = Vec::new();
    let mut it = blocks.into_iter().peekable();
    // the subsection's first paragraph stays first
    if matches!(it.peek(), Some(Block::Paragraph(_))) {
        head.extend(it.next());
    }
    while let Some(b) = it.next() {
        // a referring sentence followed by its figure travel together
        if matches!(b, Block::Paragraph(_)) && matches!(it.peek(), Some(Block::Figure { .. })) {
            figures.push(b);
            figures.extend(it.next());
        } else if matches!(b, Block::Figure { .. }) {
            figures.push(b);
        } else {
            rest.push(b);
        }
    }
    head.extend(figures);
    head.extend(rest);
    s.blocks = head;
    for sub in &mut s.subsections {
        early(sub);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Text;

    fn para(s: &str) -> Block {
        Block::Paragraph(Text::plain(s))
    }
    fn fig(c: &str) -> Block {
        Block::Figure {
            caption: c.into(),
            svg: String::new(),
            width_mm: 10.0,
            label: None,
        }
    }

    #[test]
    fn figures_with_their_sentences_move_up_in_order() {
        let mut s = Section::new("3.3");
        s.blocks = vec![
            para("intro"),
            para("table text"),
            para("see fig 1"),
            fig("1"),
            para("more"),
            para("see fig 2"),
            fig("2"),
        ];
        figures_early(std::slice::from_mut(&mut s));
        let order: Vec<String> = s
            .blocks
            .iter()
            .map(|b| match b {
                Block::Paragraph(t) => format!("{t:?}"),
                Block::Figure { caption, .. } => format!("fig {caption}"),
                _ => String::new(),
            })
            .collect();
        assert!(order[0].contains("intro"), "{order:?}");
        assert!(order[1].contains("see fig 1") && order[2] == "fig 1", "{order:?}");
        assert!(order[3].contains("see fig 2") && order[4] == "fig 2", "{order:?}");
        assert!(order[5].contains("table text") && order[6].contains("more"), "{order:?}");
    }
}
