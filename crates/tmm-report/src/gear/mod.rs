//! The `[gear]` section of a task file and the `tmm gear` commands: reading the
//! input ([`input`]), computing the pair ([`solve`]), tables ([`text`]), JSON
//! ([`json`]), the meshing drawing ([`mesh`]), the machine meshing of wheel 1
//! with the rack-type tool ([`machine_mesh`]), the blocking contour plot
//! ([`contour_plot`]), the sliding diagram ([`sliding_plot`]) and the
//! generated profiles ([`profile`]).

// The shared `Error` carries the task text for located diagnostics; it is large by design.

pub mod contour_plot;
pub mod input;
pub mod json;
pub mod machine_mesh;
pub mod mesh;
pub mod profile;
pub mod sliding_plot;
pub mod solve;
pub mod text;

use tmm_gears::contour::{ContourOptions, blocking_contour};
use tmm_gears::generate::{ToothProfile, generate, ring_profile};
use tmm_gears::{Kind, Pair};

use crate::output::Documents;
use crate::{Error, SectionOutput, TaskSource};
use input::{Field, Origin, Raw, gear_error};
pub use sliding_plot::sliding_svg;

/// Points per cutter part when generating a profile.
pub const PROFILE_SAMPLES: usize = 60;

/// Both wheels' generated tooth profiles (a ring is drawn from its involute).
pub fn profiles(pair: &Pair, o: &Origin<'_>) -> Result<(ToothProfile, ToothProfile), Error> {
    let s = &pair.spec;
    let t1 = generate(s.z1, s.m, s.x1, &s.rack, pair.w1.da / 2.0, PROFILE_SAMPLES).map_err(|e| gear_error(o, &e))?;
    let t2 = match s.kind {
        Kind::External => generate(s.z2, s.m, s.x2, &s.rack, pair.w2.da / 2.0, PROFILE_SAMPLES).map_err(|e| gear_error(o, &e))?,
        Kind::Internal => {
            let rb2 = pair.w2.db / 2.0;
            let r_form = (rb2 * rb2 + pair.w2.rho_l * pair.w2.rho_l).sqrt();
            ring_profile(
                s.z2,
                s.m,
                pair.w2.s,
                &s.rack,
                pair.w2.da / 2.0,
                pair.w2.df / 2.0,
                r_form,
                PROFILE_SAMPLES,
            )
        }
    };
    Ok((t1, t2))
}

/// What the `[gear]` section computes from its job before it draws: the
/// solved pair, both wheels' generated profiles and the blocking contour.
struct Computed {
    solved: solve::Solved,
    t1: ToothProfile,
    t2: ToothProfile,
    contour: tmm_gears::contour::Contour,
}

/// The last job computed and its result. A run with the note asks for the
/// section twice with the same job — for the sheets (A1/A2) and for the
/// note's page (A4, [`crate::run::note_figures`]) — and only the drawings
/// differ; the second call draws from the first one's numbers instead of
/// computing the pair, its profiles and its blocking contour again. The key
/// is the whole job (a `NaN` in it never matches, so it is computed anew).
static LAST: std::sync::Mutex<Option<(input::Job, std::sync::Arc<Computed>)>> = std::sync::Mutex::new(None);

/// The section's numbers for `job`: from [`LAST`] when it holds the same
/// job, else computed (and kept there).
fn computed(job: &input::Job, origin: &Origin<'_>) -> Result<std::sync::Arc<Computed>, Error> {
    if let Ok(last) = LAST.lock()
        && let Some((j, c)) = last.as_ref()
        && j == job
    {
        return Ok(c.clone());
    }
    let solved = solve::solve(job, origin)?;
    let (t1, t2) = profiles(&solved.pair, origin)?;
    let contour = blocking_contour(&job.spec, &ContourOptions::default()).map_err(|e| gear_error(origin, &e))?;
    let c = std::sync::Arc::new(Computed { solved, t1, t2, contour });
    if let Ok(mut last) = LAST.lock() {
        *last = Some((*job, c.clone()));
    }
    Ok(c)
}

/// Run the `[gear]` section of a task: documents under `gear/`.
/// Returns `None` when the task has no such section. For the note's page
/// ([`SheetFormat::A4`](crate::project::SheetFormat::A4)) only the
/// drawings (SVG) are made: the DXF and CSV files belong to the sheets' run.
pub fn run_section(task: &TaskSource) -> Result<Option<SectionOutput>, Error> {
    let Some((raw, origin)) = Raw::from_task(task)? else {
        return Ok(None);
    };
    let job = raw.job(&origin, true)?;
    let computed = computed(&job, &origin)?;
    let Computed {
        solved,
        t1,
        t2,
        contour: c,
    } = &*computed;
    let pair = &solved.pair;
    let files = task.sheet != crate::project::SheetFormat::A4;
    let mut docs = Documents::for_task(task);
    docs.add_text("gear/mesh.svg", mesh::mesh_svg(pair, t1, t2, task.lang, task.sheet))?;
    if files {
        docs.add_bytes("gear/mesh.dxf", mesh::mesh_dxf(pair, t1, t2).to_bytes()?)?;
    }
    // wheel 1 is cut by the rack-type tool in either kind of pair
    docs.add_text(
        "gear/machine-mesh.svg",
        machine_mesh::machine_mesh_svg(pair, t1, task.lang, task.sheet),
    )?;
    docs.add_text("gear/sliding.svg", sliding_svg(pair, task.lang, task.sheet))?;
    if files {
        docs.add_text("gear/profiles.csv", profile::profiles_csv(t1, t2))?;
    }
    docs.add_text("gear/profiles.svg", profile::profiles_svg(t1, t2, task.lang))?;
    if files {
        docs.add_bytes("gear/profiles.dxf", profile::profiles_dxf(t1, t2).to_bytes()?)?;
    }
    let label = solved.criterion.map_or("given".to_string(), |c| c.name().to_string());
    docs.add_text(
        "gear/contour.svg",
        contour_plot::contour_svg(c, Some(((pair.w1.x, pair.w2.x), label)), task.lang, task.sheet),
    )?;
    let text = text::pair_text(solved, &job.limits);
    let json = json::pair_json(solved, &job.limits, None);
    docs.add_json("gear/gear.json", &json)?;
    docs.add_text("gear/gear.txt", text.clone())?;
    let _ = Field::Section;
    Ok(Some(SectionOutput {
        section: "gear",
        text,
        json,
        docs,
    }))
}
