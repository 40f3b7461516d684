//! The `[cam]` section of a task file and `tmm cam`: reading the task,
//! designing the cam with `tmm-cams`, and its outputs — tables, one JSON
//! document, SVG drawings, DXF and CSV of the working profile.
//!
//! | file | concept |
//! | --- | --- |
//! | [`input`] | the section / options → a `CamTask`, located errors |
//! | [`text`] | human tables |
//! | [`json`] | the JSON document (SI, rad) |
//! | [`draw`] | SVG: diagrams, sizing diagram, the cam and follower |
//! | [`cad`] | DXF and CSV of the working profile |

// The shared `Error` carries the source text for located messages; it is
// large by design and returned only on the cold path.

pub mod cad;
pub mod draw;
pub mod input;
pub mod json;
pub mod text;

use std::path::{Path, PathBuf};

use tmm_cams::design::{CamDesign, CamTask};

use crate::output::{ensure_dir, write_file};
use crate::{Error, SectionOutput, TaskSource};
use input::Locate;

/// Design the cam, turning a core error into a located input error.
pub fn solve(task: &CamTask, loc: &Locate<'_>) -> Result<CamDesign, Error> {
    task.solve().map_err(|e| input::cam_error(e, loc))
}

/// Where to write the drawings and the profile files (None: not written).
#[derive(Debug, Clone, Default)]
pub struct Targets {
    /// Folder for the SVG drawings.
    pub svg_dir: Option<PathBuf>,
    /// DXF file of the profile.
    pub dxf: Option<PathBuf>,
    /// CSV file of the profile.
    pub csv: Option<PathBuf>,
}

/// Write the requested files; return their paths.
pub fn write_outputs(task: &CamTask, d: &CamDesign, t: &Targets) -> Result<Vec<PathBuf>, Error> {
    let mut files = Vec::new();
    if let Some(dir) = &t.svg_dir {
        ensure_dir(dir)?;
        write_file(&dir.join("cam.svg"), &draw::cam(task, d), &mut files)?;
        write_file(&dir.join("cam-analogs.svg"), &draw::analogs(task, d), &mut files)?;
        write_file(&dir.join("cam-motion.svg"), &draw::motion(task, d), &mut files)?;
        write_file(&dir.join("cam-pressure.svg"), &draw::pressure(task, d), &mut files)?;
        write_file(&dir.join("cam-sizing.svg"), &draw::sizing_diagram(task, d), &mut files)?;
    }
    if let Some(p) = &t.dxf {
        if let Some(dir) = p.parent().filter(|d| !d.as_os_str().is_empty()) {
            ensure_dir(dir)?;
        }
        cad::dxf(d).save(p)?;
        files.push(p.clone());
    }
    if let Some(p) = &t.csv {
        write_file(p, &cad::csv(d)?, &mut files)?;
    }
    Ok(files)
}

/// Run the `[cam]` section of a task, writing files under `out/cam/`.
/// Returns `None` when the task has no such section.
pub fn run_section(task: &TaskSource, out: &Path) -> Result<Option<SectionOutput>, Error> {
    let Some((sec, span)) = input::read_section(task)? else {
        return Ok(None);
    };
    let loc = input::file_locator(task, &sec, span);
    let cam = input::build(&sec.raw(), &loc)?;
    let d = solve(&cam, &loc)?;
    let dir = out.join("cam");
    let targets = Targets {
        svg_dir: Some(dir.clone()),
        dxf: Some(dir.join("cam-profile.dxf")),
        csv: Some(dir.join("cam-profile.csv")),
    };
    let mut files = write_outputs(&cam, &d, &targets)?;
    let json = json::document(&cam, &d);
    let text = text::tables(&cam, &d, 15);
    let body = serde_json::to_string_pretty(&json).map_err(|e| Error::Io(e.to_string()))?;
    write_file(&dir.join("cam.json"), &body, &mut files)?;
    write_file(&dir.join("cam.txt"), &text, &mut files)?;
    Ok(Some(SectionOutput {
        section: "cam",
        text,
        json,
        files,
    }))
}
