//! The integration tests of tmm-cli, linked into one test binary (one link of
//! the dependency graph instead of one per file). Each former test file is
//! a module here: run one with `cargo test --release -p tmm-cli --test all <module>::`.

mod cam;
mod common;
mod compressor;
mod cost_bounds;
mod cylinder;
mod dynamics;
mod engine;
mod every_example;
mod fg_partial;
mod forces;
mod fuzz;
mod gear;
mod hardening;
mod indicator_drawing;
mod input_limits;
mod linkage;
mod load_period;
mod machine_mesh;
mod note;
mod periods;
mod planetary_cli;
mod redundant;
mod seed_003_direction;
mod shaper;
mod single_stroke;
mod slider_input;
mod synth;
mod textbook_cams;
mod textbook_synthesis;
mod write_safety;
