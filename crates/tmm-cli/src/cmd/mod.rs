//! One file per subcommand; each has `Args` (clap) and `run`.

pub mod cam;
pub mod common;
pub mod cylinder;
pub mod dynamics;
pub mod forces;
pub mod gear;
pub mod linkage;
pub mod note;
pub mod planetary;
pub mod run;
pub mod synth;
