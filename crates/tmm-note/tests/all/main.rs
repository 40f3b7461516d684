//! The integration tests of tmm-note, linked into one test binary (one link of
//! the dependency graph instead of one per file). Each former test file is
//! a module here: run one with `cargo test --release -p tmm-note --test all <module>::`.

mod appendices;
mod assignment_givens;
mod checklist;
#[path = "../common/mod.rs"]
mod common;
mod compose;
mod cylinder_note;
mod figure_fill;
mod figure_fit;
mod figure_numbers;
mod figure_titles;
mod figures_pdf;
mod fixtures;
mod flywheel_text;
mod fonts_pdf;
mod formulas;
mod frame;
mod intro_parts;
mod kinematic_equations;
mod notation;
mod pdf_read;
mod prose_numbers;
mod raw_words;
mod scales_pdf;
mod sheets_dxf_pdf;
mod sheets_pdf;
mod teacher_marks;
mod typeset;
mod where_lines;
