//! The drawing sheets as printed, read back from their PDFs (`pdf_read`):
//! on every sheet of the default project, of seed 003
//! (`examples/seed-003-sixbar.toml`) and of one example of each section,
//! every text — the drawings' labels and their indices, the titles, the
//! tables, the frame and the title block — has capitals at least 2.5 mm
//! high at print size (GOST 2.304's smallest size). The height is the
//! font's own `/CapHeight` times the size the PDF shows it at, through
//! every matrix, so it is measured on the paper, independently of the
//! sizes the drawing code asks for.

use tmm_report::TaskSource;
use tmm_report::run::{DEFAULT_TASK, run_task};

use super::fixtures::{sheet_svgs, task};
use super::pdf_read::read;

/// GOST 2.304's smallest letter height, mm, less the rounding of the
/// PDF's numbers (a few thousandths of a millimetre; 0.2 %).
const MIN_CAP_MM: f64 = 2.5 - 0.005;

/// Every sheet of `name` typeset to PDF and read back, its smallest
/// capital printed; the sheets with a text under [`MIN_CAP_MM`].
fn sheets_under(name: &str) -> Vec<String> {
    let task = task(name);
    let run = run_task(&task).expect("the task runs");
    let mut sheets = 0;
    let mut under = Vec::new();
    for (path, svg) in sheet_svgs(&run) {
        let pdf = tmm_note::sheet_pdf(svg).expect("the sheet typesets");
        let r = read(&pdf);
        let low = r
            .texts
            .iter()
            .min_by(|a, b| a.cap_mm.total_cmp(&b.cap_mm))
            .expect("a sheet has lettering");
        let n_small = r.texts.iter().filter(|t| t.cap_mm < MIN_CAP_MM).count();
        eprintln!(
            "{name}: {path} — {} texts, smallest capital {:.3} mm (font {}), {n_small} under 2.5 mm",
            r.texts.len(),
            low.cap_mm,
            low.font
        );
        if n_small > 0 {
            under.push(format!("{name}: {path}: {n_small} texts, the smallest {:.3} mm", low.cap_mm));
        }
        sheets += 1;
    }
    assert!(sheets > 0, "{name}: the run has sheets");
    under
}

/// Every sheet of every task of `names`: no capital under 2.5 mm.
fn check(names: &[&str]) {
    let under: Vec<String> = names.iter().flat_map(|n| sheets_under(n)).collect();
    assert!(under.is_empty(), "capitals under 2.5 mm on\n{}", under.join("\n"));
}

#[test]
fn default_project_sheets_letter_at_2_5_mm_or_more() {
    check(&["default"]);
}

#[test]
fn seed_003_sheets_letter_at_2_5_mm_or_more() {
    check(&["seed-003-sixbar.toml"]);
}

#[test]
fn synthesis_and_linkage_examples_sheets_letter_at_2_5_mm_or_more() {
    check(&["synth-seed-003-six-bar.toml", "class3-triad.toml"]);
}

#[test]
fn forces_and_dynamics_examples_sheets_letter_at_2_5_mm_or_more() {
    check(&["seed-004-two-sliders.toml", "textbook/p4-press.toml"]);
}

#[test]
fn gear_and_planetary_examples_sheets_letter_at_2_5_mm_or_more() {
    check(&["gear-internal.toml", "planetary-ext-int.toml"]);
}

#[test]
fn cam_and_cylinder_examples_sheets_letter_at_2_5_mm_or_more() {
    check(&["cam-oscillating-roller.toml", "textbook/p5-pneumatic-cylinder.toml"]);
}

/// Every sheet's PDF declares the project's language (`/Lang` in its
/// catalog, read by screen readers and by a PDF viewer's hyphenation and
/// search), not typst's default English: Russian by default, Ukrainian
/// when `[project] lang = "uk"`.
#[test]
fn sheets_declare_the_projects_language() {
    let uk = DEFAULT_TASK.replacen("\nlang = \"ru\"\n", "\nlang = \"uk\"\n", 1);
    assert_ne!(uk, DEFAULT_TASK, "the default task is in Russian");
    for (text, code) in [(DEFAULT_TASK.to_string(), "ru"), (uk, "uk")] {
        let run = run_task(&TaskSource::new("default.toml", text)).expect("the task runs");
        let mut n = 0;
        for (path, svg) in sheet_svgs(&run) {
            let pdf = tmm_note::sheet_pdf(svg).expect("the sheet typesets");
            let want = format!("/Lang({code})");
            assert!(
                pdf.windows(want.len()).any(|w| w == want.as_bytes()),
                "{path}: the PDF does not declare {want}"
            );
            n += 1;
        }
        assert!(n >= 4, "{code}: four sheets at least, got {n}");
    }
}
