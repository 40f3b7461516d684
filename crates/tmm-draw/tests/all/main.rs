//! The tests of tmm-draw, one module per concept.

mod annotations;
mod dxf_file;
mod lettering;
mod lines;
mod scales;
mod sheet_frame;
mod svg_file;
