//! The integration tests of tmm-linkage, linked into one test binary (one link of
//! the dependency graph instead of one per file). Each former test file is
//! a module here: run one with `cargo test --release -p tmm-linkage --test all <module>::`.

#[path = "../common/mod.rs"]
mod common;
mod cost_bounds;
mod dynamics;
mod engine;
mod forces;
mod fourbar_closed_form;
mod hardening;
mod linear;
mod properties;
mod shaper;
mod single_stroke;
mod slider_input;
mod synthesis_crank_rocker;
mod synthesis_crank_slider;
mod synthesis_kinds;
mod synthesis_nearest;
mod synthesis_proptest;
mod synthesis_seeds;
mod synthesis_textbook;
