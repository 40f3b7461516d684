//! From a [`Job`] to a computed pair: the shifts as given, from a required
//! centre distance, or chosen by a criterion.

use tmm_gears::Pair;
use tmm_gears::centre::shift_sum_for_aw;
use tmm_gears::choose::{Criterion, choose};

use super::input::{Field, Job, Mode, Origin, gear_error};
use crate::Error;

/// The computed pair and how its shifts were obtained.
#[derive(Debug, Clone)]
pub struct Solved {
    /// The pair.
    pub pair: Pair,
    /// The criterion used to pick the shifts, if they were picked.
    pub criterion: Option<Criterion>,
    /// Why that criterion (when the user named none).
    pub reason: Option<String>,
    /// The required centre distance, when one was given.
    pub aw_required: Option<f64>,
    /// The cutter's tip fillet as fitted to the rack.
    pub fillet: tmm_gears::rack::FilletFit,
}

/// Compute the pair of a job.
pub fn solve(job: &Job, o: &Origin<'_>) -> Result<Solved, Error> {
    let (x_sum, aw_required) = match job.mode {
        Mode::Shifts => {
            let pair = Pair::new(&job.spec).map_err(|e| gear_error(o, &e))?;
            return Ok(Solved {
                pair,
                criterion: None,
                reason: None,
                aw_required: None,
                fillet: job.fillet,
            });
        }
        Mode::CentreDistance(aw) => {
            let s = &job.spec;
            let xs = shift_sum_for_aw(s.z1, s.z2, s.m, aw, &s.rack, s.kind).map_err(|e| gear_error(o, &e))?;
            (Some(xs), Some(aw))
        }
        Mode::Choose => (None, None),
    };
    let (crit, reason) = match job.criterion {
        Some(c) => (c, None),
        None => (Criterion::EqualSliding, Some(Criterion::DEFAULT_REASON.to_string())),
    };
    let c = choose(&job.spec, crit, x_sum, &job.limits).map_err(|e| {
        let f = if aw_required.is_some() { Field::Aw } else { Field::Criterion };
        o.err(f, &e).with_help(
            "try another criterion, relax sa_min or eps_min, or another centre distance; `tmm gear contour` shows the allowed region",
        )
    })?;
    Ok(Solved {
        pair: c.pair,
        criterion: Some(crit),
        reason,
        aw_required,
        fillet: job.fillet,
    })
}
