//! The integration tests of tmm-cams, linked into one test binary (one link of
//! the dependency graph instead of one per file). Each former test file is
//! a module here: run one with `cargo test --release -p tmm-cams --test all <module>::`.

mod extreme;
mod hardening;
mod laws;
mod profile;
mod random;
mod sizing;
mod textbook_p6;
