//! The library's own tests: they reach its internals through items marked
//! `#[doc(hidden)]`, so that the library is not compiled a second time as a
//! test harness.

mod dynamics_draw;
mod dynamics_json;
mod dynamics_task;
mod gear_mesh;
mod gear_section;
mod label_ink;
mod labels;
mod library_tests;
mod message_numbers;
mod nonfinite_scan;
mod output;
mod planetary;
mod planetary_drawing;
mod sheets;
mod sheets_layout;
mod svg;
mod synthesis;
mod synthesis_toml_out;
mod words;
