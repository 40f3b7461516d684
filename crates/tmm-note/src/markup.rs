//! The generated typst source `/main.typ` of a [`Note`].
//!
//! The layout lives in `template.typ`; this module only writes calls to it
//! and the content, with every caller string as a typst string literal
//! ([`crate::escape::string_literal`]). Before writing, the note is checked:
//! labels valid and unique, references and citations resolvable, numbers
//! finite, tables rectangular, figure widths sane — so a bad note is a typed
//! [`NoteError`], never a typst error message.

use std::collections::{HashMap, HashSet};
use std::fmt::Write as _;

use crate::error::NoteError;
use crate::escape::{check_label, check_math, string_literal};
use crate::model::{Block, Cell, Lang, Note, ProjectInfo, Section, Span, Text};
use crate::number::{format_number, push_unit};
use crate::numbering::{Counters, Object};
use crate::translation::Translation;

/// A table of at most this many rows is kept on one page: a row of 12 pt
/// text with its insets is about 6.6 mm high, so 16 rows with the header
/// and the caption take about 125 mm, under half the text area (243 mm
/// with the frame, 257 mm without), and moving such a table whole to the
/// next page leaves no page half empty. Only a longer table is split, and
/// its continuation is then most of a page of table (GOST 2.105-95, 4.4.9:
/// the part carried over stands under "Продолжение таблицы N" at the head
/// of the new page, not under figures set in the middle of it).
const SHORT_TABLE_ROWS: usize = 16;

/// The generated source and the virtual files it refers to.
#[derive(Debug, Clone, PartialEq)]
pub struct Generated {
    /// The text of `/main.typ`.
    pub main: String,
    /// The figures: (virtual path, SVG document).
    pub figures: Vec<(String, String)>,
}

/// Writes `/main.typ` for `note` with the words of `tr`.
///
/// # Errors
/// Any [`NoteError`] of the checks listed in the module's header.
pub fn generate(note: &Note, tr: &Translation) -> Result<Generated, NoteError> {
    let labels = collect_labels(note)?;
    let letters = tr.appendix_letters().len();
    if note.appendices.len() > letters {
        return Err(NoteError::TooManyAppendices {
            count: note.appendices.len(),
            letters,
        });
    }
    let mut w = Writer {
        lang: note.lang,
        labels: &labels,
        sources: note.sources.len(),
        out: String::new(),
        figures: Vec::new(),
        counters: Counters::new(),
        numbers: HashMap::new(),
        figure_word: tr.get("figure").to_owned(),
        table_word: tr.get("table").to_owned(),
        contents: Vec::new(),
    };
    w.out.push_str(
        "#import \"/template.typ\": note, sources, appendices, svg-figure, figure-row, float-side, table-continued, section-break, with-next, numbered-formula\n",
    );
    // the course's tangent in Russian and Ukrainian is tg (ctg), as the
    // where-lines and the textbooks write it; typst's math names it tan
    if matches!(note.lang, Lang::Ru | Lang::Uk) {
        w.out.push_str("#let tan = math.op(\"tg\")\n#let cot = math.op(\"ctg\")\n");
    }
    w.out.push_str("#let tr = (\n");
    for (k, v) in tr.iter() {
        let _ = writeln!(w.out, "  {k}: {},", string_literal(v));
    }
    w.out.push_str(")\n");
    w.out.push_str("#show: note.with(\n  tr: tr,\n");
    let _ = writeln!(w.out, "  lang: {},", string_literal(note.lang.code()));
    let _ = writeln!(w.out, "  frame: {},", note.frame);
    write_project(&mut w.out, &note.project);
    // the template's unnumbered level-1 headings: the technical
    // assignment, then the contents (each restarts the objects' numbers)
    w.counters.heading(1, false);
    if !note.assignment.is_empty() {
        w.out.push_str("  assignment: [\n");
        w.blocks(&note.assignment)?;
        w.out.push_str("  ],\n");
    }
    w.counters.heading(1, false);
    // the contents' lines for typst's first layout pass, filled in once
    // every heading is written
    let contents_at = w.out.len();
    w.out.push_str(")\n\n");
    if let Some(s) = &note.introduction {
        w.unnumbered(s)?;
    }
    for s in &note.sections {
        w.section(s, 1)?;
    }
    if let Some(s) = &note.conclusion {
        w.unnumbered(s)?;
    }
    if !note.sources.is_empty() {
        w.counters.heading(1, false);
        w.contents.push(format!("(1, none, {})", string_literal(tr.get("sources"))));
        w.out.push_str("#sources(tr, (\n");
        for s in &note.sources {
            let _ = writeln!(w.out, "  {},", string_literal(s));
        }
        w.out.push_str("))\n\n");
    }
    if !note.appendices.is_empty() {
        w.out.push_str("#show: appendices.with(tr)\n\n");
        w.counters.start_appendices(tr.get("appendix"), &tr.appendix_letters());
        for s in &note.appendices {
            w.section(s, 1)?;
        }
    }
    let mut contents = String::from("  contents: (\n");
    for line in &w.contents {
        let _ = writeln!(contents, "    {line},");
    }
    contents.push_str("  ),\n");
    w.out.insert_str(contents_at, &contents);
    let main = w.resolve_refs();
    Ok(Generated { main, figures: w.figures })
}

/// The narrower text width of the note's page, mm: 165 mm with the GOST
/// 7.32 margins (175 mm inside the frame).
const TEXT_WIDTH_MM: f64 = 165.0;
/// The gap between the figures of a row, mm.
const ROW_GAP_MM: f64 = 8.0;

/// A figure's printed width, mm (at most the text's), if its SVG states its
/// size in mm.
fn figure_width(b: &Block) -> Option<f64> {
    let Block::Figure { svg, width_mm, .. } = b else {
        return None;
    };
    let root = &svg[svg.find("<svg")?..];
    let root = &root[..root.find('>')?];
    let attr = |name: &str| -> Option<f64> {
        let key = format!(" {name}=\"");
        let v = &root[root.find(&key)? + key.len()..];
        v[..v.find('"')?].strip_suffix("mm")?.parse().ok()
    };
    let (w, h) = (attr("width")?, attr("height")?);
    if !(w > 0.0 && h > 0.0) {
        return None;
    }
    let printed = width_mm.min(TEXT_WIDTH_MM);
    Some(printed)
}

/// The rows among `bs`' figures, by the index of their first block: how
/// many figures stand side by side. Only figures standing next to each
/// other are grouped, as many as fit the text width with the gaps between
/// (pieces narrower than half of it). Figures are not stacked as one float
/// (the two plans of one position): a pair too tall for the foot of a page
/// under the section's last text would leave that foot empty, where the
/// first plan alone fits; the plans' μ lets them share a page instead.
fn figure_rows(bs: &[Block]) -> HashMap<usize, usize> {
    let mut out = HashMap::new();
    let mut i = 0;
    while i < bs.len() {
        let Some(w) = figure_width(&bs[i]) else {
            i += 1;
            continue;
        };
        let mut n = 1;
        let mut width = w;
        while let Some(w2) = bs.get(i + n).and_then(figure_width) {
            if width + ROW_GAP_MM + w2 > TEXT_WIDTH_MM {
                break;
            }
            width += ROW_GAP_MM + w2;
            n += 1;
        }
        if n > 1 {
            out.insert(i, n);
        }
        i += n;
    }
    out
}

/// The mark standing for a reference's number until the whole note is
/// numbered (a reference may name a later object). NUL is in no label (they
/// are checked, [`check_label`]) and in no caller text (string literals
/// escape control characters).
const REF_MARK: char = '\0';

fn write_project(out: &mut String, p: &ProjectInfo) {
    out.push_str("  project: (\n");
    let fields = [
        ("university", &p.university),
        ("department", &p.department),
        ("student", &p.student),
        ("group", &p.group),
        ("teacher", &p.teacher),
        ("variant", &p.variant),
        ("city", &p.city),
        ("year", &p.year),
        ("title", &p.title),
        ("designation", &p.designation),
    ];
    for (k, v) in fields {
        let _ = writeln!(out, "    {k}: {},", string_literal(v));
    }
    out.push_str("  ),\n");
}

/// Every label of the note, checked for validity and uniqueness.
fn collect_labels(note: &Note) -> Result<HashSet<String>, NoteError> {
    fn blocks(bs: &[Block], set: &mut HashSet<String>) -> Result<(), NoteError> {
        for b in bs {
            let label = match b {
                Block::Formula { label, .. } | Block::Table { label, .. } | Block::Figure { label, .. } => label,
                _ => &None,
            };
            if let Some(l) = label {
                check_label(l)?;
                if !set.insert(l.clone()) {
                    return Err(NoteError::DuplicateLabel { label: l.clone() });
                }
            }
        }
        Ok(())
    }
    fn sections(ss: &[Section], set: &mut HashSet<String>) -> Result<(), NoteError> {
        for s in ss {
            blocks(&s.blocks, set)?;
            sections(&s.subsections, set)?;
        }
        Ok(())
    }
    let mut set = HashSet::new();
    blocks(&note.assignment, &mut set)?;
    for s in note.introduction.iter().chain(&note.conclusion) {
        sections(std::slice::from_ref(s), &mut set)?;
    }
    sections(&note.sections, &mut set)?;
    sections(&note.appendices, &mut set)?;
    Ok(set)
}

struct Writer<'a> {
    lang: Lang,
    labels: &'a HashSet<String>,
    sources: usize,
    out: String,
    figures: Vec<(String, String)>,
    /// The running numbers of headings, figures, tables and formulas.
    counters: Counters,
    /// The number of each label written so far ("1.2", "(1.3)").
    numbers: HashMap<String, String>,
    /// The words before a figure's and a table's number.
    figure_word: String,
    table_word: String,
    /// The contents' lines (level, number or none, title) as typst arrays,
    /// in order.
    contents: Vec<String>,
}

impl Writer<'_> {
    /// The source with every reference's mark replaced by its label's
    /// number (every referenced label was checked to exist, so each has
    /// one).
    fn resolve_refs(&self) -> String {
        let mut out = String::with_capacity(self.out.len());
        let mut parts = self.out.split(REF_MARK);
        out.push_str(parts.next().unwrap_or(""));
        while let (Some(label), Some(rest)) = (parts.next(), parts.next()) {
            let number = self.numbers.get(label).map_or("", String::as_str);
            out.push_str(&string_literal(number));
            out.push_str(rest);
        }
        out
    }

    /// Numbers the next object of `kind` and remembers it under `label`.
    fn number_object(&mut self, kind: Object, label: &Option<String>) -> String {
        let number = self.counters.object(kind);
        if let Some(l) = label {
            self.numbers.insert(l.clone(), number.clone());
        }
        number
    }

    /// A caption with its number before it, as typst's figure would print
    /// it: "Рисунок 1.2 – …" (the word and the number joined by a no-break
    /// space, the separator of template.typ, a no-break space, the en dash
    /// and a space).
    fn caption(word: &str, number: &str, caption: &str) -> String {
        let head = string_literal(&format!("{word}\u{a0}{number}\u{a0}\u{2013} "));
        let body = content_arg(caption);
        format!("[#{head}#{body}]")
    }

    fn section(&mut self, s: &Section, level: usize) -> Result<(), NoteError> {
        if level == 1 {
            self.out.push_str("#section-break()\n");
        }
        let number = self.counters.heading(level, true).unwrap_or_default();
        self.contents
            .push(format!("({level}, {}, {})", string_literal(&number), content_arg(&s.title)));
        let _ = writeln!(
            self.out,
            "#heading(level: {level}, numbering: (..n) => {}, {})\n",
            string_literal(&number),
            content_arg(&s.title)
        );
        self.blocks(&s.blocks)?;
        for sub in &s.subsections {
            self.section(sub, level + 1)?;
        }
        Ok(())
    }

    /// An unnumbered level-1 section (the introduction, the conclusion),
    /// listed in the contents.
    fn unnumbered(&mut self, s: &Section) -> Result<(), NoteError> {
        self.out.push_str("#section-break()\n");
        self.counters.heading(1, false);
        self.contents.push(format!("(1, none, {})", content_arg(&s.title)));
        let _ = writeln!(self.out, "#heading(level: 1, numbering: none, {})\n", content_arg(&s.title));
        self.blocks(&s.blocks)?;
        for sub in &s.subsections {
            self.section(sub, 2)?;
        }
        Ok(())
    }

    /// The blocks in order. A paragraph that names the table right after
    /// it ("Значения сведены в таблицу 3.2.") is kept with that table
    /// (template.typ, `with-next`): when the table moves to the next page
    /// whole, its sentence goes with it instead of standing a page and two
    /// figures before it. So is a sentence ending with a colon with the
    /// formula it introduces.
    fn blocks(&mut self, bs: &[Block]) -> Result<(), NoteError> {
        let rows = figure_rows(bs);
        let mut skip = 0;
        for (i, b) in bs.iter().enumerate() {
            if skip > 0 {
                skip -= 1;
                continue;
            }
            if let Some(n) = rows.get(&i) {
                self.figure_row(&bs[i..i + n])?;
                skip = n - 1;
                continue;
            }
            let names_next = match (b, bs.get(i + 1)) {
                (Block::Paragraph(t), Some(Block::Table { label: Some(l), .. })) => t.0.iter().any(|s| matches!(s, Span::Ref(r) if r == l)),
                // a sentence ending with a colon introduces the formula
                // after it ("… по формуле Чебышёва:")
                (Block::Paragraph(t), Some(Block::Formula { .. } | Block::Calculation(_))) => {
                    matches!(t.0.last(), Some(Span::Plain(p)) if p.trim_end().ends_with(':'))
                }
                _ => false,
            };
            if names_next {
                // a paragraph of its own inside the block (`par`), so it
                // keeps the first-line indent of every body paragraph
                self.out.push_str("#with-next(par[");
                if let Block::Paragraph(t) = b {
                    self.text(t)?;
                }
                self.out.push_str("])\n\n");
            } else {
                self.block(b)?;
            }
        }
        Ok(())
    }

    fn label(&mut self, label: &Option<String>) {
        if let Some(l) = label {
            let _ = write!(self.out, " <{l}>");
        }
        self.out.push_str("\n\n");
    }

    fn block(&mut self, b: &Block) -> Result<(), NoteError> {
        match b {
            Block::Paragraph(t) => {
                self.text(t)?;
                self.out.push_str("\n\n");
            }
            Block::Formula { typst_math, label } => {
                check_math(typst_math)?;
                let number = self.number_object(Object::Equation, label);
                let _ = write!(self.out, "#numbered-formula({})[$ {} $", string_literal(&number), typst_math.trim());
                if let Some(l) = label {
                    let _ = write!(self.out, " <{l}>");
                }
                self.out.push_str("]\n\n");
            }
            Block::Table {
                caption,
                header,
                rows,
                units,
                label,
            } => {
                let number = self.number_object(Object::Table, label);
                self.table(caption, header, rows, units, &number)?;
                if rows.len() <= SHORT_TABLE_ROWS {
                    if let Some(l) = label {
                        let _ = write!(self.out, " <{l}>");
                    }
                    self.out.push_str("]\n\n");
                } else {
                    self.label(label);
                }
            }
            Block::Figure { .. } => {
                // made inside a context, which chooses the side the k-th
                // figure floats to (template.typ, `float-side`), the label
                // on the figure
                let side = format!("float-side({})", self.figures.len());
                self.out.push_str("#context [");
                self.figure(b, &side)?;
                self.out.push_str("]\n\n");
            }
            Block::Calculation(c) => {
                let m = c.typst(self.lang)?;
                check_math(&m)?;
                let number = self.number_object(Object::Equation, &None);
                let _ = write!(self.out, "#numbered-formula({})[$ {m} $]\n\n", string_literal(&number));
            }
            Block::List(items) => {
                self.out.push_str("#list(\n");
                for item in items {
                    self.out.push_str("  [");
                    self.text(item)?;
                    self.out.push_str("],\n");
                }
                self.out.push_str(")\n\n");
            }
        }
        Ok(())
    }

    /// A figure (`svg-figure`) placed at `placement` (a typst expression:
    /// `float-side(k)` for a figure that floats, `none` for one inside a
    /// group), its label on it.
    fn figure(&mut self, b: &Block, placement: &str) -> Result<(), NoteError> {
        let Block::Figure {
            caption,
            svg,
            width_mm,
            label,
        } = b
        else {
            return Ok(());
        };
        if !(width_mm.is_finite() && (1.0..=1000.0).contains(width_mm)) {
            return Err(NoteError::FigureWidth {
                caption: caption.clone(),
                width_mm: *width_mm,
            });
        }
        let path = format!("/fig-{}.svg", self.figures.len() + 1);
        let number = self.number_object(Object::Figure, label);
        let _ = write!(
            self.out,
            "#svg-figure({}, {}mm, {}, {placement})",
            string_literal(&path),
            width_mm,
            Self::caption(&self.figure_word, &number, caption),
        );
        self.figures.push((path, svg.clone()));
        if let Some(l) = label {
            let _ = write!(self.out, " <{l}>");
        }
        Ok(())
    }

    /// Figures side by side that float as one (template.typ,
    /// `figure-row`): each with its own caption and number (GOST 2.105-95,
    /// 4.3.1), the row floating to the side its first figure's place
    /// chooses.
    fn figure_row(&mut self, figs: &[Block]) -> Result<(), NoteError> {
        let first = self.figures.len();
        let widths: Vec<String> = figs
            .iter()
            .map(|f| match f {
                Block::Figure { width_mm, .. } => format!("{}mm", width_mm.min(TEXT_WIDTH_MM)),
                _ => "auto".into(),
            })
            .collect();
        let _ = write!(self.out, "#context figure-row(float-side({first}), ({},), (", widths.join(", "));
        for f in figs {
            self.out.push('[');
            self.figure(f, "none")?;
            self.out.push_str("], ");
        }
        self.out.push_str("))\n\n");
        Ok(())
    }

    fn table(&mut self, caption: &str, header: &[String], rows: &[Vec<Cell>], units: &[String], number: &str) -> Result<(), NoteError> {
        let n = header.len();
        let shape = |what: String, found: usize| NoteError::TableShape {
            caption: caption.to_owned(),
            what,
            found,
            expected: n,
        };
        if !units.is_empty() && units.len() != n {
            return Err(shape("units".into(), units.len()));
        }
        if let Some((i, r)) = rows.iter().enumerate().find(|(_, r)| r.len() != n) {
            return Err(shape(format!("row {}", i + 1), r.len()));
        }
        // a short table is not split: it moves to the next page whole
        // (a long one is carried over under "Продолжение таблицы N", its
        // header repeated: template.typ, `table-continued`)
        let short = rows.len() <= SHORT_TABLE_ROWS;
        if short {
            self.out.push_str("#block(breakable: false)[");
        }
        // the line "Продолжение таблицы N" over a carried-over part; a
        // short table is never carried over and its line is always empty
        let continued = if short {
            "[]".to_owned()
        } else {
            format!("table-continued(tr, {})", string_literal(number))
        };
        let _ = write!(
            self.out,
            "#figure(kind: table, numbering: none, caption: {}, table(columns: {n},\n  table.header(repeat: true,\n    \
             table.cell(colspan: {n}, stroke: none, inset: 0pt, align: left, {continued}),\n    ",
            Self::caption(&self.table_word, number, caption)
        );
        for (i, h) in header.iter().enumerate() {
            let mut head = h.clone();
            if let Some(u) = units.get(i).filter(|u| !u.is_empty()) {
                head.push_str(", ");
                head.push_str(u);
            }
            let _ = write!(self.out, "{}, ", content_arg(&head));
        }
        self.out.push_str("),\n");
        // a number under the resolution of its column's largest is the
        // noise of a zero and prints 0 (`number::zero_noise`)
        let mut scales = vec![0.0_f64; n];
        for row in rows {
            for (i, c) in row.iter().enumerate() {
                if let Cell::Number { value, .. } = c {
                    scales[i] = scales[i].max(value.abs());
                }
            }
        }
        for row in rows {
            self.out.push_str("  ");
            for (i, c) in row.iter().enumerate() {
                match c {
                    Cell::Text(t) => {
                        self.out.push('[');
                        self.text(t)?;
                        self.out.push_str("], ");
                    }
                    Cell::Number { value, digits } => {
                        self.out.push('[');
                        self.number(crate::number::zero_noise(*value, scales[i]), *digits, "")?;
                        self.out.push_str("], ");
                    }
                    Cell::Empty => self.out.push_str("[], "),
                }
            }
            self.out.push('\n');
        }
        self.out.push_str("))");
        Ok(())
    }

    fn number(&mut self, value: f64, digits: u8, unit: &str) -> Result<(), NoteError> {
        let f = format_number(value, digits, self.lang)?;
        let mut tail = String::new();
        push_unit(&mut tail, unit);
        match f.exponent {
            None => {
                let _ = write!(self.out, "#{}", string_literal(&(f.mantissa + &tail)));
            }
            Some(e) => {
                let exp = e.to_string().replace('-', "\u{2212}");
                let _ = write!(
                    self.out,
                    "#{}#super({})#{}",
                    string_literal(&(f.mantissa + "·10")),
                    string_literal(&exp),
                    string_literal(&tail)
                );
            }
        }
        Ok(())
    }

    fn text(&mut self, t: &Text) -> Result<(), NoteError> {
        for span in &t.0 {
            match span {
                Span::Plain(s) => self.out.push_str(&content_markup(s)),
                Span::Strong(s) => {
                    let _ = write!(self.out, "#strong({})", content_arg(s));
                }
                Span::Emph(s) => {
                    let _ = write!(self.out, "#emph({})", content_arg(s));
                }
                Span::Math(m) => {
                    check_math(m)?;
                    let m = m.trim();
                    if !m.is_empty() {
                        let _ = write!(self.out, "${m}$");
                    }
                }
                Span::Number { value, digits, unit } => self.number(*value, *digits, unit)?,
                Span::Ref(l) => {
                    check_label(l)?;
                    if !self.labels.contains(l) {
                        return Err(NoteError::UnknownLabel { label: l.clone() });
                    }
                    // its number, filled in once every object is numbered
                    // (`resolve_refs`)
                    let _ = write!(self.out, "#{REF_MARK}{l}{REF_MARK}");
                }
                Span::Cite(k) => {
                    if *k == 0 || *k > self.sources {
                        return Err(NoteError::UnknownSource {
                            number: *k,
                            count: self.sources,
                        });
                    }
                    let _ = write!(self.out, "#\"[{k}]\"");
                }
            }
        }
        Ok(())
    }
}

/// A text of the note's words in markup mode: its plain runs as string
/// literals, its notation runs ([`crate::notation`]) as inline math.
///
/// A symbol and the text touching it stay on one line: where a plain run
/// meets a math run with no space between (`s–ds/dφ`, `R^n,`, `M_ур).`),
/// the symbol and the characters glued to it (up to the nearest space) are
/// set in one box, so the line never breaks between a symbol and its
/// punctuation or dash (typst treats an inline formula as an object a line
/// may break before and after). A box adds no character to the text, so
/// the PDF's text copies as written (a word joiner U+2060 at the seam,
/// which did the same, came out in the copied text).
fn content_markup(s: &str) -> String {
    let runs = crate::notation::runs(s);
    let math_at = |i: usize| runs.get(i).is_some_and(|(m, r)| *m && check_math(r).is_ok());
    let mut out = String::new();
    // the pieces glued together, waiting for their box
    let mut glued: Vec<String> = Vec::new();
    let flush = |glued: &mut Vec<String>, out: &mut String| {
        match glued.len() {
            0 => {}
            1 => out.push_str(&glued[0]),
            _ => {
                let _ = write!(out, "#box[{}]", glued.concat());
            }
        }
        glued.clear();
    };
    for (i, (_, run)) in runs.iter().enumerate() {
        if math_at(i) {
            glued.push(format!("${run}$"));
            continue;
        }
        let text = keep_equals(run);
        let glue_before = i > 0 && math_at(i - 1);
        let glue_after = math_at(i + 1);
        // the characters touching the symbol before (no space between)
        let head_end = if glue_before {
            text.find(char::is_whitespace).unwrap_or(text.len())
        } else {
            0
        };
        if head_end > 0 {
            glued.push(format!("#{}", string_literal(&text[..head_end])));
        }
        if head_end == text.len() && glue_before {
            // the whole run is glued: to the next symbol too, or it closes
            if !glue_after {
                flush(&mut glued, &mut out);
            }
            continue;
        }
        flush(&mut glued, &mut out);
        let rest = &text[head_end..];
        // the characters touching the symbol after
        let tail_start = if glue_after {
            rest.rfind(char::is_whitespace)
                .map_or(0, |j| j + rest[j..].chars().next().map_or(1, char::len_utf8))
        } else {
            rest.len()
        };
        if tail_start > 0 {
            let _ = write!(out, "#{}", string_literal(&rest[..tail_start]));
        }
        if tail_start < rest.len() {
            glued.push(format!("#{}", string_literal(&rest[tail_start..])));
        }
    }
    flush(&mut glued, &mut out);
    out
}

/// A text whose `=`, `≈` and `≤`, `≥` stay on the line of the symbol before
/// them: the space before each made a no-break space, so a line never ends
/// with a lone symbol (`K_v` | `= 1,106`). The line may still break after
/// the sign (GOST 2.105, 4.2.15: a formula is broken after a sign), except
/// before a short value (at most 8 characters to the next space, `0;`,
/// `1,106`), which never stands alone at the head of a line
/// (`p_4 =` | `0;`).
fn keep_equals(s: &str) -> String {
    let s = s
        .replace(" =", "\u{a0}=")
        .replace(" ≈", "\u{a0}≈")
        .replace(" ≤", "\u{a0}≤")
        .replace(" ≥", "\u{a0}≥");
    let mut out = String::with_capacity(s.len());
    let mut rest = s.as_str();
    while let Some(i) = rest.find(['=', '≈', '≤', '≥']) {
        let sign = rest[i..].chars().next().map_or(1, char::len_utf8);
        out.push_str(&rest[..i + sign]);
        rest = &rest[i + sign..];
        if let Some(after) = rest.strip_prefix(' ') {
            let word = after.split(' ').next().unwrap_or("");
            if !word.is_empty() && word.chars().count() <= 8 {
                out.push('\u{a0}');
                rest = after;
            }
        }
    }
    out.push_str(rest);
    out
}

/// A text as a typst argument: a string literal, or a content block when
/// it holds notation runs.
fn content_arg(s: &str) -> String {
    if crate::notation::has_math(s) {
        format!("[{}]", content_markup(s))
    } else {
        string_literal(&keep_equals(s))
    }
}

#[cfg(test)]
mod keep_equals_tests {
    #[test]
    fn the_sign_stays_with_the_symbol_before_it() {
        assert_eq!(super::keep_equals("W = 1, θ ≈ 9°"), "W\u{a0}=\u{a0}1, θ\u{a0}≈\u{a0}9°");
        assert_eq!(super::keep_equals(" = 1,106"), "\u{a0}=\u{a0}1,106");
        assert_eq!(super::keep_equals("a=b"), "a=b");
        // a long value may still go to the next line after the sign
        assert_eq!(super::keep_equals("M = 12345,678901 Н"), "M\u{a0}= 12345,678901 Н");
    }
}

#[cfg(test)]
mod glue_tests {
    #[test]
    fn a_symbol_and_the_characters_touching_it_are_one_box() {
        let marked = |s: &str| crate::notation::notation_with(s, true);
        let m = super::content_markup(&marked("момент (M_ур). Далее"));
        assert!(!m.contains('\u{2060}'), "{m}");
        assert!(m.contains("#box[#\"(\"$M_\"ур\"$#\").\"]"), "{m}");
        // a symbol between spaces stands alone
        let m = super::content_markup(&marked("звено K_v и"));
        assert!(!m.contains("#box"), "{m}");
        // a chain symbol–text–symbol glued throughout is one box
        let m = super::content_markup(&marked("a s–ds/dφ b"));
        assert_eq!(m.matches("#box[").count(), 1, "{m}");
    }
}

#[cfg(test)]
mod numbering_tests {
    use crate::model::{Block, Lang, Note, Section, Span, Text};
    use crate::translation::Translation;

    fn figure(label: &str) -> Block {
        Block::Figure {
            caption: "Схема".into(),
            svg: "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10\" height=\"10\"/>".into(),
            width_mm: 50.0,
            label: Some(label.into()),
        }
    }

    /// A reference names its object's number as literal text, also an
    /// object written after it, and the source asks typst for no counter.
    #[test]
    fn references_are_the_literal_numbers_of_their_objects() {
        let mut s1 = Section::new("Первый");
        s1.blocks.push(Block::Formula {
            typst_math: "x = 1".into(),
            label: Some("eq-x".into()),
        });
        let mut s2 = Section::new("Второй");
        s2.blocks.push(Block::Paragraph(
            Text::plain("См. рисунок ")
                .with(Span::Ref("fig-b".into()))
                .with(Span::Plain(" и формулу ".into()))
                .with(Span::Ref("eq-x".into())),
        ));
        s2.blocks.push(figure("fig-a"));
        s2.blocks.push(figure("fig-b"));
        let note = Note {
            lang: Lang::Ru,
            sections: vec![s1, s2],
            ..Note::default()
        };
        let g = super::generate(&note, &Translation::load(Lang::Ru).unwrap()).unwrap();
        // GOST 2.105-95, numbering within the section: the second figure
        // of section 2 is 2.2, the first formula of section 1 is (1.1)
        assert!(g.main.contains("См. рисунок \"#\"2.2\"#\" и формулу \"#\"(1.1)\""), "{}", g.main);
        assert!(g.main.contains("\"Рисунок\u{a0}2.1\u{a0}– \""), "{}", g.main);
        assert!(g.main.contains("#numbered-formula(\"(1.1)\")"), "{}", g.main);
        assert!(!g.main.contains("#ref(") && !g.main.contains("counter("), "{}", g.main);
        assert!(!g.main.contains('\0'));
    }
}

#[cfg(test)]
mod row_tests {
    use crate::model::{Block, Section, Text};

    fn figure(label: &str, width: f64) -> Block {
        Block::Figure {
            caption: format!("Деталь {label}"),
            svg: format!("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width}mm\" height=\"40mm\" viewBox=\"0 0 {width} 40\"/>"),
            width_mm: width,
            label: Some(label.into()),
        }
    }

    /// Figures next to each other stand in one row while their widths and
    /// the 8 mm gaps fit the 165 mm text: 70 + 8 + 70 = 148 mm do, a third
    /// of 70 mm does not, nor a figure of 120 mm; a paragraph parts them.
    #[test]
    fn narrow_figures_next_to_each_other_stand_in_a_row() {
        let bs = vec![
            figure("a", 70.0),
            figure("b", 70.0),
            figure("c", 70.0),
            figure("d", 120.0),
            Block::Paragraph(Text::plain("Текст.")),
            figure("e", 60.0),
            Block::Paragraph(Text::plain("Текст.")),
            figure("f", 60.0),
            figure("g", 90.0),
        ];
        let rows = super::figure_rows(&bs);
        let mut got: Vec<(usize, usize)> = rows.into_iter().collect();
        got.sort();
        assert_eq!(got, vec![(0, 2), (7, 2)]);
        // in the source: two rows, each figure with its own caption and
        // number, in order
        let mut note = crate::model::Note::default();
        let mut s = Section::new("Раздел");
        s.blocks = bs;
        note.sections.push(s);
        let tr = crate::translation::Translation::load(note.lang).unwrap();
        let main = super::generate(&note, &tr).unwrap().main;
        assert_eq!(main.matches("figure-row(").count(), 2, "{main}");
        let at = |l: &str| main.find(&format!(" <{l}>")).unwrap_or_else(|| panic!("no figure {l}: {main}"));
        let row = main.find("figure-row(").unwrap();
        let row_end = row + main[row..].find("\n").unwrap();
        assert!(
            row < at("a") && at("a") < at("b") && at("b") < row_end && row_end < at("c"),
            "{main}"
        );
        assert!(
            at("c") < at("d") && at("d") < at("e") && at("e") < at("f") && at("f") < at("g"),
            "{main}"
        );
    }
}
