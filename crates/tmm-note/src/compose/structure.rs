//! The structural analysis of the linkage (структурный анализ): the table
//! of kinematic pairs (pair, links, kind, class), the Assur groups with
//! their class and order, as the report's `/linkage/structure` gives them
//! (the decomposition of `tmm-linkage::structure`, Artobolevsky 1988,
//! §§ 5–6).

use serde_json::Value;

use super::context::{Ctx, text};
use crate::error::NoteError;
use crate::model::{Block, Cell, Span, Text};

/// A link's name as the note prints it: the frame is link 0.
fn link(name: &str) -> String {
    if name == "frame" { "0".to_string() } else { name.to_string() }
}

/// The blocks of the structural analysis, empty if the report has no pairs.
pub(crate) fn blocks(cx: &Ctx) -> Result<Vec<Block>, NoteError> {
    let mut out = Vec::new();
    let Some(pairs) = cx.report.pointer("/linkage/structure/pairs").and_then(Value::as_array) else {
        return Ok(out);
    };
    let mut rows = Vec::new();
    for p in pairs {
        let point = p.get("point").and_then(Value::as_str).unwrap_or("");
        let links: Vec<String> = p
            .get("links")
            .and_then(Value::as_array)
            .map(|a| a.iter().filter_map(Value::as_str).map(link).collect())
            .unwrap_or_default();
        let kind = match p.get("kind").and_then(Value::as_str) {
            Some("P") => cx.w("pair_prismatic")?,
            _ => cx.w("pair_revolute")?,
        };
        let class = p.get("class").and_then(Value::as_u64).unwrap_or(5);
        rows.push(vec![
            text(point),
            text(links.join("–")),
            text(kind),
            Cell::Text(Text::plain(format!("{class}"))),
            text(if class == 5 { "1" } else { "2" }),
        ]);
    }
    if let Some(f) = cx.figure("linkage/structure.svg", "fig_structure")? {
        out.push(f);
    }
    out.push(para_ref(cx, "st_pairs", "tab-pairs")?);
    let mut table = cx.table(
        "tab_pairs",
        &[
            ("col_pair", ""),
            ("col_links", ""),
            ("col_pair_kind", ""),
            ("col_pair_class", ""),
            ("col_pair_freedom", ""),
        ],
        rows,
    )?;
    if let Block::Table { label, .. } = &mut table {
        *label = Some("tab-pairs".into());
    }
    out.push(table);
    let groups = cx
        .report
        .pointer("/linkage/structure/groups")
        .and_then(Value::as_array)
        .cloned()
        .unwrap_or_default();
    if !groups.is_empty() {
        let list = |g: &Value, k: &str, f: fn(&str) -> String| -> String {
            g.get(k)
                .and_then(Value::as_array)
                .map(|a| a.iter().filter_map(Value::as_str).map(f).collect::<Vec<_>>().join(", "))
                .unwrap_or_default()
        };
        let input = cx.s("/linkage/input/link").unwrap_or("1");
        // the input pair: the one joining the crank to the frame
        let input_pair = pairs
            .iter()
            .find(|p| {
                let l: Vec<&str> = p
                    .get("links")
                    .and_then(Value::as_array)
                    .map(|a| a.iter().filter_map(Value::as_str).collect())
                    .unwrap_or_default();
                l.contains(&"frame") && l.contains(&input)
            })
            .and_then(|p| p.get("point").and_then(Value::as_str))
            .unwrap_or("");
        let mut rows = vec![vec![
            text(cx.w("st_input_group")?),
            text(format!("0, {input}")),
            text(input_pair),
            text(""),
            text("I"),
            text(""),
        ]];
        for (i, g) in groups.iter().enumerate() {
            let n = |k: &str| g.get(k).and_then(Value::as_u64).unwrap_or(0);
            rows.push(vec![
                text(format!("{} {}", cx.w("st_group")?, i + 1)),
                text(list(g, "links", link)),
                text(list(g, "pairs", str::to_string)),
                text(g.get("kind").and_then(Value::as_str).unwrap_or("")),
                text(roman(n("class"))),
                text(format!("{}", n("order"))),
            ]);
        }
        out.push(para_ref(cx, "st_groups", "tab-groups")?);
        let mut table = cx.table(
            "tab_groups",
            &[
                ("col_group", ""),
                ("col_links", ""),
                ("col_pairs", ""),
                ("col_group_kind", ""),
                ("col_group_class", ""),
                ("col_group_order", ""),
            ],
            rows,
        )?;
        if let Block::Table { label, .. } = &mut table {
            *label = Some("tab-groups".into());
        }
        out.push(table);
    }
    Ok(out)
}

/// A paragraph of a words key whose `{1}` is a reference to `label`.
fn para_ref(cx: &Ctx, key: &str, label: &str) -> Result<Block, NoteError> {
    let w = cx.w(key)?;
    let (a, b) = w.split_once("{1}").unwrap_or((&w, ""));
    Ok(Block::Paragraph(
        Text::plain(a).with(Span::Ref(label.into())).with(Span::Plain(b.into())),
    ))
}

/// A class as the course writes it: I, II, III, IV.
pub(crate) fn roman(n: u64) -> String {
    ["0", "I", "II", "III", "IV", "V", "VI"]
        .get(n as usize)
        .map_or_else(|| n.to_string(), |s| s.to_string())
}
