//! The edge between tmm's core crates and its users: task files (TOML) with
//! located errors, human tables, JSON documents, SVG and DXF drawings.
//!
//! One folder per area of the course project; each reads its own section of
//! the task file and writes its own outputs:
//!
//! | module | section | core crate |
//! | --- | --- | --- |
//! | [`synthesis`] | `[synthesis]` | `tmm-linkage` (metric synthesis) |
//! | [`linkage`] | `[linkage]` | `tmm-linkage` (structure, kinematics) |
//! | [`forces`] | `[forces]` | `tmm-linkage` (kinetostatics, strength) |
//! | [`dynamics`] | `[dynamics]` | `tmm-linkage` (flywheel, true motion, run-up) |
//! | [`gear`] | `[gear]` | `tmm-gears` |
//! | [`planetary`] | `[planetary]` | `tmm-planetary` |
//! | [`cam`] | `[cam]` | `tmm-cams` |
//!
//! [`project`] reads `[project]` (title page, title block, language,
//! sheet format), [`words`] the drawings' words in ru/uk/en, [`paper`] the drawings'
//! slots on the sheets, standard scales and round μ. Shared pieces: [`error`] (the one error type, exit codes), [`task`]
//! (sources, quantities with units), [`user_text`] (names and titles: length,
//! control characters), [`svg`] (a canvas and a plotter), [`picture`] (a
//! drawing's typed elements, rendered to SVG and to a `tmm_draw` scene),
//! [`dxf_out`] (DXF with layers), [`output`], [`run`] (the whole task).

pub mod cam;
pub mod crop;
pub mod cylinder;
pub mod dxf_out;
pub mod dynamics;
pub mod error;
pub mod forces;
pub mod gear;
pub mod labels;
pub mod line_grid;
pub mod linkage;
pub mod message_numbers;
pub mod output;
pub mod paper;
pub mod picture;
pub mod planetary;
pub mod project;
pub mod run;
pub mod seg_index;
pub mod sheets;
pub mod svg;
pub mod synthesis;
pub mod task;
pub mod user_text;
pub mod words;

pub use error::Error;
pub use output::SectionOutput;
pub use task::TaskSource;
