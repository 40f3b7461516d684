//! The introduction (введение) and the conclusion (заключение) of the note:
//! the machine and the project's aims with the list of the parts the task
//! has, and the results of every part gathered from the sections'
//! conclusions.

use super::context::Ctx;
use crate::error::NoteError;
use crate::model::{Block, Section, Span, Text};

/// A part of the course project, as the note has it (one section each).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Part {
    /// Metric synthesis of the lever mechanism (метрический синтез).
    Synthesis,
    /// Structure and kinematics (структурный и кинематический анализ).
    Linkage,
    /// Kinetostatics (кинетостатический анализ).
    Forces,
    /// Steady motion and the flywheel (динамика, расчёт маховика).
    Dynamics,
    /// The unsteady single stroke (неустановившееся движение за цикл).
    Stroke,
    /// The involute gear pair (эвольвентное зацепление).
    Gear,
    /// The planetary train (планетарная передача).
    Planetary,
    /// The cam mechanism (кулачковый механизм).
    Cam,
    /// The drive by a cylinder (привод от цилиндра).
    Cylinder,
}

impl Part {
    /// The key of the part's aim in the words files (`intro_aim_…`).
    fn aim_key(self) -> &'static str {
        match self {
            Part::Synthesis => "intro_aim_synthesis",
            Part::Linkage => "intro_aim_linkage",
            Part::Forces => "intro_aim_forces",
            Part::Dynamics => "intro_aim_dynamics",
            Part::Stroke => "intro_aim_stroke",
            Part::Gear => "intro_aim_gear",
            Part::Planetary => "intro_aim_planetary",
            Part::Cam => "intro_aim_cam",
            Part::Cylinder => "intro_aim_cylinder",
        }
    }

    /// The key of the part's graphical constructions (`intro_build_…`),
    /// in the order the note draws them; the diagram-only parts share one.
    fn build_key(self) -> &'static str {
        match self {
            Part::Synthesis => "intro_build_synthesis",
            Part::Linkage => "intro_build_linkage",
            Part::Forces => "intro_build_forces",
            Part::Gear => "intro_build_gear",
            Part::Planetary => "intro_build_planetary",
            Part::Dynamics | Part::Stroke | Part::Cam | Part::Cylinder => "intro_build_diagrams",
        }
    }
}

/// The introduction: the course, the project's topic, its aims and parts.
/// The aims and the graphical constructions named are those of the parts
/// the note has (`parts`, one per section): a note without a synthesis
/// section never speaks of synthesis.
pub(crate) fn introduction(cx: &Ctx, title: &str, sections: &[Section], parts: &[Part]) -> Result<Option<Section>, NoteError> {
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
    let aims = parts.iter().map(|p| cx.w(p.aim_key())).collect::<Result<Vec<_>, _>>()?;
    s.blocks.push(Block::Paragraph(Text::plain(format!(
        "{} {}. {}",
        cx.w("intro_aims_lead")?,
        join_and(&aims, &cx.w("intro_and")?),
        cx.w("intro_sections")?
    ))));
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
    let mut builds: Vec<&str> = Vec::new();
    for p in parts {
        let k = p.build_key();
        if !builds.contains(&k) {
            builds.push(k);
        }
    }
    let builds = builds.iter().map(|k| cx.w(k)).collect::<Result<Vec<_>, _>>()?;
    s.blocks.push(cx.para("intro_methods_parts", &[builds.join(", ")])?);
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

/// `a, b and c`: the items with commas, the last one after `and`.
fn join_and(items: &[String], and: &str) -> String {
    match items {
        [] => String::new(),
        [one] => one.clone(),
        [head @ .., last] => format!("{} {and} {last}", head.join(", ")),
    }
}

/// A title with its first letter in lower case, for the middle of a sentence.
fn lower_first(s: &str) -> String {
    let mut c = s.chars();
    match c.next() {
        Some(f) => f.to_lowercase().chain(c).collect(),
        None => String::new(),
    }
}
