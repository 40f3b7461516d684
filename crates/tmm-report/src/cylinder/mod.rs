//! The `[cylinder]` section of a task file and `tmm cylinder`: a lever
//! driven by an oscillating cylinder, whose generalized coordinate is the
//! piston's travel s (the textbook's П5): the synthesis (П1.5), the
//! analogues d/ds, the reduced mass and force, the zero-work control
//! force, V(s), a(s), t(s), the kinetostatics at one s — as tables, one
//! JSON document and drawings under `cylinder/`. The computation is
//! `tmm_linkage::linear` (docs/dynamics.md, "A linear generalized
//! coordinate").
//!
//! | file | what |
//! | --- | --- |
//! | [`input`] | the section, located errors |
//! | [`text`] | human tables |
//! | [`json`] | the JSON document |
//! | [`draw`] | the mechanism in its three positions |

pub mod draw;
pub mod input;
pub mod json;
pub mod text;

use tmm_linkage::linear::{CylinderMotion, CylinderReactions, CylinderState, kinetostatics};

use crate::output::Documents;
use crate::{Error, SectionOutput, TaskSource};

pub use input::CylinderTask;

/// Tabulated positions: s = k·s_max/10, k = 0…10.
pub const TABLE_POSITIONS: usize = 10;

/// Everything the section reports.
#[derive(Debug, Clone)]
pub struct Analysis {
    /// The task as read.
    pub task: CylinderTask,
    /// The motion over the travel.
    pub motion: CylinderMotion,
    /// The mechanism at s = k·s_max/10 and at the kinetostatics' s.
    pub table: Vec<CylinderState>,
    /// The mechanism at the kinetostatics' s.
    pub at: CylinderState,
    /// The kinetostatics there.
    pub reactions: CylinderReactions,
    /// F_прДВ at the kinetostatics' s, N.
    pub control_at: f64,
}

/// Compute the section.
pub fn analyse(src: &TaskSource, t: CylinderTask) -> Result<Analysis, Error> {
    let motion = CylinderMotion::compute(&t.drive, &t.masses, t.switch, t.points).map_err(|e| t.located(src, e))?;
    let smax = t.drive.travel();
    let mut table = Vec::with_capacity(TABLE_POSITIONS + 1);
    for k in 0..=TABLE_POSITIONS {
        let mut st = CylinderState::default();
        t.drive
            .solve(smax * k as f64 / TABLE_POSITIONS as f64, &mut st)
            .map_err(|e| t.located(src, e))?;
        table.push(st);
    }
    let mut at = CylinderState::default();
    let (v, a) = motion.motion_at(t.at, &mut at).map_err(|e| t.located(src, e))?;
    let reactions = kinetostatics(&t.drive, &t.masses, &at, v, a).map_err(|e| t.located(src, e))?;
    let control_at = motion.control.force(t.at);
    Ok(Analysis {
        task: t,
        motion,
        table,
        at,
        reactions,
        control_at,
    })
}

/// The drawings (the mechanism, m_пр, V, a, t and the forces against s),
/// their paths under `prefix`.
pub fn drawings(
    a: &Analysis,
    prefix: &str,
    lang: crate::project::Language,
    sheet: crate::project::SheetFormat,
) -> Result<Documents, Error> {
    let mut docs = Documents::new();
    docs.add_text(format!("{prefix}mechanism.svg"), draw::mechanism(a, lang, sheet))?;
    crate::dynamics::draw::cylinder::draw_all(a, prefix, lang, sheet, &mut docs)?;
    Ok(docs)
}

/// Run the `[cylinder]` section of a task: documents under `cylinder/`.
/// Returns `None` when the task has no such section.
pub fn run_section(task: &TaskSource) -> Result<Option<SectionOutput>, Error> {
    let Some(t) = input::read(task)? else { return Ok(None) };
    let a = analyse(task, t)?;
    let text = text::report(&a);
    let json = json::document(&a);
    let mut docs = Documents::for_task(task);
    docs.add_json("cylinder/cylinder.json", &json)?;
    docs.add_text("cylinder/cylinder.txt", text.clone())?;
    docs.append(drawings(&a, "cylinder/", task.lang, task.sheet)?);
    Ok(Some(SectionOutput {
        section: "cylinder",
        text,
        json,
        docs,
    }))
}
