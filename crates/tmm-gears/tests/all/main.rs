//! The integration tests of tmm-gears, linked into one test binary (one link of
//! the dependency graph instead of one per file). Each former test file is
//! a module here: run one with `cargo test --release -p tmm-gears --test all <module>::`.

mod contour;
mod extreme;
mod generate;
mod hardening;
mod internal;
mod pair;
mod trimming;
