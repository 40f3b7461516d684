//! The ESKD frame of the note (`frame = true`) read back from the PDF's
//! drawing: on every page after the title page and the technical
//! assignment, the frame's four sides 20 mm from the left edge and 5 mm
//! from the others (GOST 2.104); title block form 2 (185 × 40 mm) on the
//! first framed page, form 2a (185 × 15 mm) on the following ones; the
//! designation in its field and the page's number in the sheet cell, found
//! by the glyphs' positions, not by the text alone; graph 26 (70 × 14 mm,
//! the designation turned by 180°) in the frame's top-left corner. Checked
//! on the sample note and on the note composed from a run of the default
//! task.

use crate::common;

use common::sample_note;
use pdf_extract::{ColorSpace, MediaBox, OutputDev, OutputError, Path, PathOp, Transform};
use tmm_note::{Lang, compose, typeset_with_warnings};
use tmm_report::TaskSource;
use tmm_report::run::{DEFAULT_TASK, run_task};

/// PostScript points per millimetre.
const PT: f64 = 72.0 / 25.4;

/// One page read back: glyphs (origin in mm from the page's bottom-left
/// corner, the character), apart the glyphs turned upside down (their
/// text matrix's both diagonal terms negative), and stroked straight
/// pieces (mm, y up).
#[derive(Debug, Default)]
struct Page {
    glyphs: Vec<(f64, f64, String)>,
    turned: Vec<(f64, f64, String)>,
    segments: Vec<[f64; 4]>,
}

#[derive(Default)]
struct Reader {
    pages: Vec<Page>,
}

fn apply(m: &Transform, x: f64, y: f64) -> (f64, f64) {
    ((m.m11 * x + m.m21 * y + m.m31) / PT, (m.m12 * x + m.m22 * y + m.m32) / PT)
}

impl OutputDev for Reader {
    fn begin_page(&mut self, _: u32, _: &MediaBox, _: Option<(f64, f64, f64, f64)>) -> Result<(), OutputError> {
        self.pages.push(Page::default());
        Ok(())
    }
    fn end_page(&mut self) -> Result<(), OutputError> {
        Ok(())
    }
    fn output_character(&mut self, trm: &Transform, _: f64, _: f64, _: f64, ch: &str) -> Result<(), OutputError> {
        if let Some(p) = self.pages.last_mut() {
            let g = (trm.m31 / PT, trm.m32 / PT, ch.to_string());
            if trm.m11 < 0.0 && trm.m22 < 0.0 {
                p.turned.push(g);
            } else {
                p.glyphs.push(g);
            }
        }
        Ok(())
    }
    fn begin_word(&mut self) -> Result<(), OutputError> {
        Ok(())
    }
    fn end_word(&mut self) -> Result<(), OutputError> {
        Ok(())
    }
    fn end_line(&mut self) -> Result<(), OutputError> {
        Ok(())
    }
    fn stroke(&mut self, ctm: &Transform, _: &ColorSpace, _: &[f64], path: &Path) -> Result<(), OutputError> {
        let Some(page) = self.pages.last_mut() else { return Ok(()) };
        let (mut start, mut at) = ((0.0, 0.0), (0.0, 0.0));
        for op in &path.ops {
            match *op {
                PathOp::MoveTo(x, y) => {
                    at = apply(ctm, x, y);
                    start = at;
                }
                PathOp::LineTo(x, y) => {
                    let to = apply(ctm, x, y);
                    page.segments.push([at.0, at.1, to.0, to.1]);
                    at = to;
                }
                PathOp::CurveTo(_, _, _, _, x, y) => at = apply(ctm, x, y),
                PathOp::Rect(x, y, w, h) => {
                    let c = [
                        apply(ctm, x, y),
                        apply(ctm, x + w, y),
                        apply(ctm, x + w, y + h),
                        apply(ctm, x, y + h),
                    ];
                    for i in 0..4 {
                        let (a, b) = (c[i], c[(i + 1) % 4]);
                        page.segments.push([a.0, a.1, b.0, b.1]);
                    }
                }
                PathOp::Close => {
                    page.segments.push([at.0, at.1, start.0, start.1]);
                    at = start;
                }
            }
        }
        Ok(())
    }
}

fn read(pdf: &[u8]) -> Vec<Page> {
    let doc = pdf_extract::Document::load_mem(pdf).expect("the PDF loads");
    let mut r = Reader::default();
    pdf_extract::output_doc(&doc, &mut r).expect("the PDF's pages read");
    r.pages
}

impl Page {
    /// Whether a stroked piece covers the straight line from (x1, y1) to
    /// (x2, y2) (mm, y up), to 0.2 mm.
    fn has_line(&self, x1: f64, y1: f64, x2: f64, y2: f64) -> bool {
        let tol = 0.2;
        self.segments.iter().any(|s| {
            let horizontal = (y1 - y2).abs() < 1e-9;
            if horizontal {
                (s[1] - y1).abs() < tol
                    && (s[3] - y1).abs() < tol
                    && s[0].min(s[2]) <= x1.min(x2) + tol
                    && s[0].max(s[2]) >= x1.max(x2) - tol
            } else {
                (s[0] - x1).abs() < tol
                    && (s[2] - x1).abs() < tol
                    && s[1].min(s[3]) <= y1.min(y2) + tol
                    && s[1].max(s[3]) >= y1.max(y2) - tol
            }
        })
    }

    /// The frame of GOST 2.104 on A4: 20 mm from the left, 5 mm from the
    /// other edges (210 × 297 mm).
    fn has_frame(&self) -> bool {
        self.has_line(20.0, 5.0, 20.0, 292.0)
            && self.has_line(205.0, 5.0, 205.0, 292.0)
            && self.has_line(20.0, 5.0, 205.0, 5.0)
            && self.has_line(20.0, 292.0, 205.0, 292.0)
    }

    /// The characters whose origin lies in the box [x0, x1] × [y0, y1]
    /// (mm, y up), in reading order: lines (baselines within 1 mm of the
    /// line's first) from the top, each from left to right.
    fn text_in(&self, x0: f64, x1: f64, y0: f64, y1: f64) -> String {
        let mut g: Vec<&(f64, f64, String)> = self
            .glyphs
            .iter()
            .filter(|(x, y, _)| (x0..=x1).contains(x) && (y0..=y1).contains(y))
            .collect();
        g.sort_by(|a, b| b.1.total_cmp(&a.1));
        let mut lines: Vec<Vec<&(f64, f64, String)>> = Vec::new();
        for c in g {
            match lines.last_mut() {
                Some(l) if (l[0].1 - c.1).abs() < 1.0 => l.push(c),
                _ => lines.push(vec![c]),
            }
        }
        let mut out = String::new();
        for mut l in lines {
            l.sort_by(|a, b| a.0.total_cmp(&b.0));
            out.extend(l.iter().map(|c| c.2.as_str()));
            out.push(' ');
        }
        out.split_whitespace().collect::<Vec<_>>().join(" ")
    }
}

/// Graph 26 of GOST 2.104-2006 on a framed A4 page: 70 × 14 mm in the
/// frame's top-left corner (x 20 … 90, y 278 … 292 mm, y up), its right
/// and bottom sides drawn; every glyph of the designation turned by 180°
/// inside it (read from the right, as it stands upside down), none of the
/// page's upright text in it or within 3 mm under it; no turned glyph
/// anywhere else. `want`: the designation without spaces.
fn check_graph_26(page: &Page, want: &str, what: &str) {
    assert!(page.has_line(90.0, 278.0, 90.0, 292.0), "{what}: no right side of graph 26");
    assert!(page.has_line(20.0, 278.0, 90.0, 278.0), "{what}: no bottom of graph 26");
    // a turned glyph's origin is its baseline's right end, its letter
    // hanging below it on the paper: every origin inside the box, 1 mm clear
    let inside = |g: &(f64, f64, String)| (21.0..=89.0).contains(&g.0) && (279.0..=291.0).contains(&g.1);
    assert!(
        page.turned.iter().all(inside),
        "{what}: a turned glyph outside graph 26: {:?}",
        page.turned
    );
    let mut g: Vec<&(f64, f64, String)> = page.turned.iter().collect();
    g.sort_by(|a, b| b.0.total_cmp(&a.0));
    let read: String = g.iter().flat_map(|c| c.2.chars()).filter(|c| !c.is_whitespace()).collect();
    assert_eq!(read, want, "{what}: graph 26");
    // one baseline: the glyphs' origins within 0.5 mm in height
    let (lo, hi) = g
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), c| (lo.min(c.1), hi.max(c.1)));
    assert!(hi - lo < 0.5, "{what}: graph 26's baseline from {lo} to {hi} mm");
    assert!(
        page.text_in(20.0, 90.0, 275.0, 297.0).is_empty(),
        "{what}: upright text in or under graph 26: {}",
        page.text_in(20.0, 90.0, 275.0, 297.0)
    );
}

/// Checks a framed note: returns the number of the first framed page.
fn check_framed(pdf: &[u8], pages: usize, designation: &str, student: &str, what: &str) -> usize {
    let p = read(pdf);
    assert_eq!(p.len(), pages, "{what}: pages read");
    assert!(!p[0].has_frame(), "{what}: the title page has no frame");
    let first = p
        .iter()
        .position(Page::has_frame)
        .unwrap_or_else(|| panic!("{what}: no page has the frame"));
    assert!(first >= 1);
    let packed = |s: &str| s.chars().filter(|c| !c.is_whitespace()).collect::<String>();
    let want = packed(designation);
    for (i, page) in p.iter().enumerate() {
        let n = i + 1;
        if i < first {
            assert!(!page.has_frame(), "{what}: page {n} before the contents framed");
            continue;
        }
        assert!(page.has_frame(), "{what}: page {n} has no frame");
        if i == first {
            // form 2: 185 × 40 mm on the frame's bottom, its top line at
            // 5 + 40 mm; the designation field 120 × 15 mm at its top right
            // (x 85 … 205, y 30 … 45), Лист and Листов values in the row
            // 20 … 25 mm from the top of the block (y 20 … 25), at x 170 …
            // 185 and 185 … 205; Разраб. with the student's name in the
            // fourth row (y 20 … 25, x 37 … 60)
            assert!(page.has_line(20.0, 45.0, 205.0, 45.0), "{what}: page {n}: no top of form 2");
            assert!(page.has_line(85.0, 30.0, 205.0, 30.0), "{what}: page {n}: no designation field");
            assert_eq!(packed(&page.text_in(85.0, 205.0, 30.0, 45.0)), want, "{what}: page {n}");
            assert_eq!(page.text_in(170.0, 185.0, 19.5, 25.0), n.to_string(), "{what}: page {n}: Лист");
            assert_eq!(
                page.text_in(185.0, 205.0, 19.5, 25.0),
                pages.to_string(),
                "{what}: page {n}: Листов"
            );
            // (a name too long for its cell is narrowed; the extractor may
            // then give its glyphs out of order: compare them as a set)
            let sorted = |s: &str| {
                let mut v: Vec<char> = packed(s).chars().collect();
                v.sort_unstable();
                v
            };
            assert_eq!(
                sorted(&page.text_in(37.0, 60.0, 24.5, 30.0)),
                sorted(student),
                "{what}: page {n}: Разраб."
            );
        } else {
            // form 2a: 185 × 15 mm, its top line at 5 + 15 mm; the
            // designation field 110 mm wide (x 85 … 195), the sheet number
            // in the lower 8 mm of the last 10 mm column (x 195 … 205, y 5 … 13)
            assert!(page.has_line(20.0, 20.0, 205.0, 20.0), "{what}: page {n}: no top of form 2a");
            assert!(!page.has_line(20.0, 45.0, 205.0, 45.0), "{what}: page {n}: form 2 again");
            assert!(page.has_line(195.0, 5.0, 195.0, 20.0), "{what}: page {n}: no sheet column");
            assert_eq!(packed(&page.text_in(85.0, 195.0, 5.0, 20.0)), want, "{what}: page {n}");
            assert_eq!(page.text_in(195.0, 205.0, 5.0, 13.0), n.to_string(), "{what}: page {n}: Лист");
        }
        // the body keeps off the title block: no glyph of the page's text
        // between the block's top and 5 mm above it
        let top = if i == first { 45.0 } else { 20.0 };
        assert!(
            page.text_in(20.0, 205.0, top + 0.5, top + 5.0).is_empty(),
            "{what}: page {n}: text on the title block"
        );
        check_graph_26(page, &want, &format!("{what}: page {n}"));
    }
    first
}

#[test]
fn every_page_after_the_front_matter_has_the_frame_and_its_numbered_block() {
    for lang in [Lang::Ru, Lang::Uk, Lang::En] {
        let note = sample_note(lang, true, 2);
        let t = typeset_with_warnings(&note).unwrap();
        assert!(t.warnings.is_empty(), "{:#?}", t.warnings);
        assert!(t.pages >= 6, "{} pages", t.pages);
        let first = check_framed(
            &t.pdf,
            t.pages,
            &note.project.designation,
            &note.project.student,
            &format!("sample {lang:?}"),
        );
        // the first framed page is the contents, after the title page and the assignment
        let pages = pdf_extract::extract_text_from_mem_by_pages(&t.pdf).unwrap();
        let words = tmm_note::Translation::load(lang).unwrap();
        let contents = words.get("contents");
        assert!(pages[first].contains(contents), "{lang:?}: page {} is not the contents", first + 1);
    }
    // without the option: no frame anywhere
    let t = typeset_with_warnings(&sample_note(Lang::Ru, false, 1)).unwrap();
    assert!(read(&t.pdf).iter().all(|p| !p.has_frame()));
}

#[test]
fn the_composed_note_honours_frame_true() {
    let text = DEFAULT_TASK.replacen("[project]", "[project]\nframe = true", 1);
    let task = TaskSource::new("default.toml", text);
    let run = run_task(&task).unwrap();
    assert!(run.project.frame);
    let note = compose(&run, &task).unwrap();
    assert!(note.frame);
    let t = typeset_with_warnings(&note).unwrap();
    assert!(t.warnings.is_empty(), "{:#?}", t.warnings);
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("note-samples");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("note-default-frame.pdf"), &t.pdf).unwrap();
    check_framed(&t.pdf, t.pages, "ТММ.КП.017.00.000 ПЗ", "Иванов И. И.", "default task");
}
