//! The integration tests of tmm-planetary, linked into one test binary (one link of
//! the dependency graph instead of one per file). Each former test file is
//! a module here: run one with `cargo test --release -p tmm-planetary --test all <module>::`.

mod brute_force;
mod hand_cases;
