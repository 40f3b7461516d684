//! The tests' own measuring tools (средства измерения для тестов), shared by
//! the integration tests of `tmm-report`, `tmm-note` and `tmm-cli` as a
//! dev-dependency and never by the shipped crates.
//!
//! A test that checks where a drawing put its labels must not measure with
//! the placement code it checks (`tmm_report::labels`, `svg::Rect`): a
//! fault shared by both would pass unseen. So this crate depends on no tmm
//! crate, and its geometry is written and tested here on its own:
//!
//! - [`plane`]: distances between points, segments and axis-aligned boxes
//!   on the paper, and whether a segment meets or enters a box;
//! - [`examples`]: the repository's example tasks, read by name or all;
//! - [`svg`]: the attributes, numbers, `viewBox` and shown text of the SVG
//!   tags tmm writes, read as text.

pub mod examples;
pub mod plane;
pub mod svg;
