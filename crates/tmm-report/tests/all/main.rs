//! The integration tests of tmm-report, linked into one test binary (one link of
//! the dependency graph instead of one per file). Each former test file is
//! a module here: run one with `cargo test --release -p tmm-report --test all <module>::`.

mod cam_diagrams;
mod cycle_marks;
mod drawings_cam_diagrams;
mod drawings_dynamics_synthesis;
mod drawings_gear_cam;
mod drawings_linkage;
mod drawings_structure;
mod dynamics_drawings;
mod figure_words;
mod flywheel_period;
mod force_polygons;
mod gear_indices;
mod hardening_examples;
mod label_clearance;
mod label_ink;
mod lever_drawing;
mod lever_virtual_power;
mod linkage_examples;
mod seg_index;
mod sheets;
mod sheets_dxf;
mod svg_read;
mod units;
mod xml;
