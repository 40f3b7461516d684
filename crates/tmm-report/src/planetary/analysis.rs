//! Running the planetary core for a set of inputs: the search, then the
//! efficiency, the velocity picture and the planet angles of the best set.

use tmm_planetary::conditions::planet_positions;
use tmm_planetary::efficiency::{carrier_fixed, train_efficiency};
use tmm_planetary::picture::{AngularDiagram, VelocityPicture, angular_diagram, velocity_picture};
use tmm_planetary::scheme::centre_distance;
use tmm_planetary::{Candidate, Condition, Driver, PlanetaryError, Synthesis, synthesize};

use super::input::{Origin, Params, check_extra};
use crate::Error;

/// The result of a planetary run.
#[derive(Debug, Clone)]
pub struct Analysis {
    /// The inputs.
    pub params: Params,
    /// All candidates, best first, and the stage counts.
    pub synthesis: Synthesis,
    /// The best candidate.
    pub best: Candidate,
    /// The velocity picture of the best set (SI, at the given module and ω1).
    pub picture: VelocityPicture,
    /// The angular-velocity diagram (segments for a pole distance of 1).
    pub diagram: AngularDiagram,
    /// Centre distance of the planets, m.
    pub centre_distance: f64,
    /// The carrier-fixed efficiency η^H.
    pub eta_h: f64,
    /// The usual driving member of the scheme.
    pub driver: Driver,
    /// Efficiency with the usual driver.
    pub efficiency: f64,
    /// Efficiency with the other member driving.
    pub efficiency_reverse: f64,
    /// The carrier angles of the planets, rad (from the first planet).
    pub planet_angles: Vec<f64>,
}

/// The request field a failed condition points at.
fn condition_field(c: Condition) -> &'static str {
    match c {
        Condition::RatioCoaxiality => "ratio",
        Condition::Undercut => "zmin",
        Condition::InternalMesh => "ring_zmin",
        Condition::Assembly | Condition::Neighbour => "planets",
    }
}

/// A core error as a located input error.
pub fn core_error(e: PlanetaryError, o: &Origin) -> Error {
    match e {
        PlanetaryError::Invalid { field, message, help } => o.error(field, message, help),
        PlanetaryError::NoSolution { condition, message, help } => o.error(
            condition_field(condition),
            format!("no tooth-number set: the {condition} condition fails first — {message}"),
            help,
        ),
    }
}

/// Search and analyse.
pub fn analyse(params: &Params, o: &Origin) -> Result<Analysis, Error> {
    check_extra(params, o)?;
    let synthesis = synthesize(&params.request).map_err(|e| core_error(e, o))?;
    let best = *synthesis.best();
    let r = &params.request;
    let picture = velocity_picture(r.scheme, &best.teeth, best.modules, params.module, params.omega1);
    let diagram = angular_diagram(&picture, 1.0);
    let eta_h = carrier_fixed(r.scheme, params.efficiency);
    let driver = r.scheme.usual_driver();
    let other = if driver == Driver::Sun { Driver::Carrier } else { Driver::Sun };
    let u = best.ratio.value();
    let efficiency = train_efficiency(u, eta_h, driver);
    let efficiency_reverse = train_efficiency(u, eta_h, other);
    let planet_angles = planet_positions(best.positions, r.planets)
        .unwrap_or_default()
        .into_iter()
        .map(|p| 2.0 * std::f64::consts::PI * p as f64 / best.positions as f64)
        .collect();
    let a = Analysis {
        params: params.clone(),
        centre_distance: params.module * centre_distance(r.scheme, &best.teeth),
        synthesis,
        best,
        picture,
        diagram,
        eta_h,
        driver,
        efficiency,
        efficiency_reverse,
        planet_angles,
    };
    let p = &a.picture;
    let numbers = [
        p.a.v,
        p.b.v,
        p.omega1,
        p.omega_h,
        p.omega_planet,
        p.ratio,
        a.diagram.ratio,
        a.efficiency,
        a.efficiency_reverse,
        a.centre_distance,
    ];
    if numbers.iter().any(|x| !x.is_finite()) {
        return Err(o.error(
            "ratio",
            "the chosen set gives a non-finite velocity picture",
            "report this set as a bug",
        ));
    }
    Ok(a)
}
