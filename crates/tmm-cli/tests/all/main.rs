//! The integration tests of tmm-cli, linked into one test binary (one link of
//! the dependency graph instead of one per file). Each former test file is
//! a module here: run one with `cargo test --release -p tmm-cli --test all <module>::`.

mod cam;
mod common;
mod dynamics;
mod engine;
mod forces;
mod fuzz;
mod gear;
mod hardening;
mod linkage;
mod note;
mod planetary_cli;
mod synth;
