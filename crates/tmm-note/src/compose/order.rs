//! Where the figures stand in the text: the figures of a subsection, each
//! with the sentence that names it (`references.rs`), move up to just
//! before the subsection's first table (before that table's own sentence),
//! keeping their order. The paragraphs and worked formulas before the
//! first table stay as they are, so a sentence ending with a colon keeps
//! the formula it introduces.
//!
//! A figure floats (template.typ): it is set at the foot of the page of its
//! sentence when it fits there, else at the head of the next page, and the
//! text after it fills the rest. Named before the tables, a subsection's
//! figures find room between its tables and paragraphs; named last, they
//! would wait until the text has run out and leave its last text page half
//! empty in the section's middle (GOST 2.105-95, 4.3.1 asks only that a
//! figure stand after the text that first names it or on the next page).

use crate::model::{Block, Section};

/// Moves the figures of every subsection of `sections` (and of the
/// sections themselves) to their heads.
pub(crate) fn figures_early(sections: &mut [Section]) {
    for s in sections {
        early(s);
    }
}

fn early(s: &mut Section) {
    let first_figure = s.blocks.iter().position(|b| matches!(b, Block::Figure { .. }));
    let first_table = s.blocks.iter().position(|b| matches!(b, Block::Table { .. }));
    if let (Some(f), Some(t)) = (first_figure, first_table)
        && t < f
    {
        // before the table's own sentence, if it has one
        let at = if t > 0 && matches!(s.blocks[t - 1], Block::Paragraph(_)) {
            t - 1
        } else {
            t
        };
        let blocks = std::mem::take(&mut s.blocks);
        let mut figures = Vec::new();
        let mut rest = Vec::new();
        let mut it = blocks.into_iter().enumerate().peekable();
        while let Some((i, b)) = it.next() {
            // a referring sentence followed by its figure travel together
            if i >= at && matches!(b, Block::Paragraph(_)) && matches!(it.peek(), Some((_, Block::Figure { .. }))) {
                figures.push(b);
                figures.extend(it.next().map(|(_, f)| f));
            } else if i >= at && matches!(b, Block::Figure { .. }) {
                figures.push(b);
            } else {
                rest.push(b);
            }
        }
        let tail = rest.split_off(at);
        rest.extend(figures);
        rest.extend(tail);
        s.blocks = rest;
    }
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
    fn figures_with_their_sentences_move_up_before_the_first_table() {
        let mut s = Section::new("3.3");
        s.blocks = vec![
            para("formula follows:"),
            Block::Formula {
                typst_math: "x = 1".into(),
                label: None,
            },
            para("table text"),
            Block::Table {
                caption: "t".into(),
                header: vec!["a".into()],
                rows: vec![],
                units: vec![],
                label: None,
            },
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
                Block::Formula { .. } => "formula".into(),
                Block::Table { .. } => "table".into(),
                _ => String::new(),
            })
            .collect();
        assert!(order[0].contains("formula follows") && order[1] == "formula", "{order:?}");
        assert!(order[2].contains("see fig 1") && order[3] == "fig 1", "{order:?}");
        assert!(order[4].contains("see fig 2") && order[5] == "fig 2", "{order:?}");
        assert!(
            order[6].contains("table text") && order[7] == "table" && order[8].contains("more"),
            "{order:?}"
        );
    }

    #[test]
    fn without_a_table_before_them_the_figures_stay() {
        let mut s = Section::new("2.3");
        s.blocks = vec![para("a:"), para("see fig 1"), fig("1"), para("b")];
        let before = format!("{:?}", s.blocks);
        figures_early(std::slice::from_mut(&mut s));
        assert_eq!(format!("{:?}", s.blocks), before);
    }
}
