//! In-text references to every figure and table (ссылки на рисунки и
//! таблицы, GOST 2.105): each unlabelled figure or table of the sections
//! gets a label and a sentence before it that names it by its number
//! ("На рисунке 2.1 — схема механизма…", "… приведены в таблице 3.2").
//! A run of figures, each with its sentence, is named in one paragraph
//! before them ("На рисунке 2.2 — схема механизма в 12 положениях; на
//! рисунке 2.3 — план скоростей; …"): the figures float away from their
//! sentences (template.typ), and one-line sentences left behind them would
//! stand as a column of short paragraphs.

use super::context::Ctx;
use crate::error::NoteError;
use crate::model::{Block, Lang, Section, Span, Text};

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

/// Joins the sentences of every run of two or more figures (a sentence
/// naming the figure after it, then the figure) in `sections` into one
/// paragraph before the run's figures: the sentences one after another,
/// parted by semicolons, the figures in their order. In Russian and
/// Ukrainian the joined sentences continue in lower case ("; на рисунке
/// 2.3 — …"); in English each keeps its capital ("; Figure 2.3: …"), glued
/// to the semicolon by a no-break space so no line begins with it.
pub(crate) fn join_figure_runs(lang: Lang, sections: &mut [Section]) {
    for s in sections {
        join_in(lang, &mut s.blocks);
        join_figure_runs(lang, &mut s.subsections);
    }
}

/// The sentence `b` names the figure `next` (its reference is the figure's
/// label).
fn names_figure(b: &Block, next: Option<&Block>) -> bool {
    match (b, next) {
        (Block::Paragraph(t), Some(Block::Figure { label: Some(l), .. })) => {
            t.0.iter().filter(|s| matches!(s, Span::Ref(_))).count() == 1 && t.0.iter().any(|s| matches!(s, Span::Ref(r) if r == l))
        }
        _ => false,
    }
}

fn join_in(lang: Lang, blocks: &mut Vec<Block>) {
    let old = std::mem::take(blocks);
    let mut i = 0;
    while i < old.len() {
        // the run of (sentence, figure) pairs from i
        let mut end = i;
        while end + 1 < old.len() && names_figure(&old[end], old.get(end + 1)) {
            end += 2;
        }
        let pairs = (end - i) / 2;
        if pairs < 2 {
            blocks.push(old[i].clone());
            i += 1;
            continue;
        }
        let mut joined: Vec<Span> = Vec::new();
        let mut figures = Vec::new();
        for k in 0..pairs {
            let (Block::Paragraph(t), f) = (&old[i + 2 * k], &old[i + 2 * k + 1]) else {
                unreachable!("a run holds sentences and figures")
            };
            let mut spans = t.0.clone();
            // the sentence's full stop: the run's last keeps it
            if k + 1 < pairs
                && let Some(Span::Plain(p)) = spans.last_mut()
            {
                let trimmed = p.trim_end().trim_end_matches('.').to_string();
                *p = format!("{trimmed};");
            }
            if k > 0 {
                match spans.first_mut() {
                    Some(Span::Plain(p)) if lang != Lang::En => {
                        *p = format!(" {}", lower_first(p));
                    }
                    Some(Span::Plain(p)) => *p = format!("\u{a0}{p}"),
                    _ => joined.push(Span::Plain(" ".into())),
                }
            }
            joined.extend(spans);
            figures.push(f.clone());
        }
        blocks.push(Block::Paragraph(Text(joined)));
        blocks.extend(figures);
        i = end;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sentence_for(l: &str) -> Block {
        Block::Paragraph(super::sentence("На рисунке {1} — {2}.", l, "План"))
    }
    fn figure(l: &str) -> Block {
        Block::Figure {
            caption: "План".into(),
            svg: String::new(),
            width_mm: 10.0,
            label: Some(l.into()),
        }
    }

    /// Two figures in a row, each after its sentence, are named in one
    /// paragraph, the second sentence in lower case after a semicolon; a
    /// lone figure keeps its sentence.
    #[test]
    fn a_run_of_figures_is_named_in_one_paragraph() {
        let mut s = Section::new("2.3");
        s.blocks = vec![
            sentence_for("f1"),
            figure("f1"),
            sentence_for("f2"),
            figure("f2"),
            Block::Paragraph(Text::plain("Текст.")),
            sentence_for("f3"),
            figure("f3"),
        ];
        join_figure_runs(Lang::Ru, std::slice::from_mut(&mut s));
        let kinds: Vec<&str> = s
            .blocks
            .iter()
            .map(|b| match b {
                Block::Paragraph(_) => "p",
                Block::Figure { .. } => "f",
                _ => "?",
            })
            .collect();
        assert_eq!(kinds, ["p", "f", "f", "p", "p", "f"]);
        let Block::Paragraph(t) = &s.blocks[0] else { unreachable!() };
        assert_eq!(
            t.0,
            vec![
                Span::Plain("На рисунке ".into()),
                Span::Ref("f1".into()),
                Span::Plain(" — план;".into()),
                Span::Plain(" на рисунке ".into()),
                Span::Ref("f2".into()),
                Span::Plain(" — план.".into()),
            ]
        );
        // English keeps the capital, glued to the semicolon
        let mut s = Section::new("2.3");
        s.blocks = vec![sentence_for("f1"), figure("f1"), sentence_for("f2"), figure("f2")];
        join_figure_runs(Lang::En, std::slice::from_mut(&mut s));
        let Block::Paragraph(t) = &s.blocks[0] else { unreachable!() };
        assert_eq!(t.0[3], Span::Plain("\u{a0}На рисунке ".into()));
    }
}
