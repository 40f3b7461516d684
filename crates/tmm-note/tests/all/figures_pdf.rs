//! The drawings as printed, read back from the PDFs (`pdf_read`): in the
//! note of the default project and of seed 003 (`examples/seed-003-sixbar.toml`)
//! every text of every figure has capitals at least 2.5 mm high (GOST
//! 2.304's smallest size; the sheets' smallest is printed and checked by
//! `sheets_pdf`), and every figure is
//! printed at its own size, so the scale and μ written on it are the
//! page's: the width of the figure measured on the page equals the width
//! of the paper it was drawn for (the length every drawing's scale is laid
//! out on; the report's tests check each drawing's known lengths against
//! its scale on that paper).

use tmm_note::{Block, Note};
use tmm_report::run::run_task;

use super::fixtures::{sheet_svgs, task};
use super::pdf_read::{Read, read};

/// GOST 2.304's smallest letter height, mm, less the rounding of the
/// PDF's numbers (a few thousandths of a millimetre).
const MIN_CAP_MM: f64 = 2.5 - 0.005;

/// Each figure of the note: its caption and the width it is set at.
fn note_figures(note: &Note) -> Vec<(&str, f64)> {
    super::fixtures::note_figures(note)
        .into_iter()
        .filter_map(|b| match b {
            Block::Figure { caption, width_mm, .. } => Some((caption.as_str(), *width_mm)),
            _ => None,
        })
        .collect()
}

fn smallest(r: &Read, figure_texts_only: bool) -> Option<&super::pdf_read::Shown> {
    r.texts
        .iter()
        .filter(|t| !figure_texts_only || t.in_figure)
        .min_by(|a, b| a.cap_mm.total_cmp(&b.cap_mm))
}

fn check(name: &str) {
    let task = task(name);
    let run = run_task(&task).expect("the task runs");
    let note = tmm_note::compose(&run, &task).expect("the note composes");
    let pdf = tmm_note::typeset(&note).expect("the note typesets");
    let r = read(&pdf);
    // every figure at its own size: one drawing per figure, in order, as
    // wide on the page as its paper, one of its millimetres one on the page
    let figs = note_figures(&note);
    assert!(!figs.is_empty(), "{name}: the note has figures");
    assert_eq!(r.forms.len(), figs.len(), "{name}: one drawing per figure: {:?}", r.forms);
    let mut worst = 0.0f64;
    let mut wrong = Vec::new();
    for ((caption, w), f) in figs.iter().zip(&r.forms) {
        let (ux, uy) = f.unit_mm.expect("a drawing's paper has a matrix");
        let err = ((f.size_mm.0 - w).abs() / w).max((ux - 1.0).abs()).max((uy - 1.0).abs());
        worst = worst.max(err);
        if err >= 1e-3 {
            wrong.push(format!(
                "\"{caption}\" (page {}) is {:.2} mm wide on the page, drawn for {w} mm; one mm of it prints as {ux:.4} × {uy:.4} mm",
                f.page, f.size_mm.0
            ));
        }
    }
    assert!(wrong.is_empty(), "{name}: figures not at their own size:\n{}", wrong.join("\n"));
    let low = smallest(&r, true).expect("the figures have lettering");
    eprintln!(
        "{name}: {} figures, widths and mm on the page within {:.4} %; smallest figure capital {:.3} mm (page {}, font {})",
        figs.len(),
        worst * 100.0,
        low.cap_mm,
        low.page,
        low.font
    );
    let small: Vec<_> = r.texts.iter().filter(|t| t.in_figure && t.cap_mm < MIN_CAP_MM).collect();
    assert!(
        small.is_empty(),
        "{name}: {} figure texts under 2.5 mm, e.g. {:?}",
        small.len(),
        &small[..small.len().min(5)]
    );
    // every sheet, every text: measured and shown (held to 2.5 mm, with
    // the examples of every section, by `sheets_pdf`)
    let mut sheets = 0;
    for (path, svg) in sheet_svgs(&run) {
        let pdf = tmm_note::sheet_pdf(svg).expect("the sheet typesets");
        let r = read(&pdf);
        let low = smallest(&r, false).expect("a sheet has lettering");
        eprintln!("{name}: {path} smallest capital {:.3} mm (font {})", low.cap_mm, low.font);
        sheets += 1;
    }
    assert!(sheets > 0, "{name}: the run has sheets");
}

#[test]
fn default_project_prints_true_size_figures_and_lettering_of_2_5_mm() {
    check("default");
}

#[test]
fn seed_003_prints_true_size_figures_and_lettering_of_2_5_mm() {
    check("seed-003-sixbar.toml");
}
