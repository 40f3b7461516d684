//! `tmm planetary`: tooth numbers of a 2K-H planetary train for a ratio and a
//! number of planets, with every condition, the efficiency and the velocity
//! pictures.

// The edge's one error type (`crate::Error`, with the task source for
// located messages) is large by design; `run_section` must return it.

use std::path::PathBuf;

use tmm_geom::units::Dim;
use tmm_planetary::Request;
use tmm_report::planetary::input::{SCHEMES_HELP, scheme_named, whole};
use tmm_report::planetary::{Origin, Params, analyse, drawing, json, text};
use tmm_report::task::arg_qty;
use tmm_report::{Error, TaskSource};

use super::common::{checked, json_text, print, read_task, write_named, written};

const AFTER: &str = "Schemes (wheel 3 is fixed in all four; the ratio is u_1H = ω1/ωH,
wheel 1 to the carrier H, by Willis' method):
  sun-planet-ring  single-row planets: 1–2 external, 2–3 internal
                   u_1H = 1 + z3/z1             z = [z1, z2, z3]
  ext-int          double planet 2–2′: 1–2 external, 2′–3 internal
                   u_1H = 1 + z2·z3/(z1·z2′)    z = [z1, z2, z2′, z3]
  ext-ext          double planet 2–2′: 1–2 external, 2′–3 external
                   u_1H = 1 − z2·z3/(z1·z2′)    z = [z1, z2, z2′, z3]
  int-int          double planet 2–2′: 1–2 internal, 2′–3 internal
                   u_1H = 1 − z2·z3/(z1·z2′)    z = [z1, z2, z2′, z3]
In ext-ext and int-int the carrier usually drives: give u_1H = 1/u_H1,
e.g. --ratio 1/50 for a 50:1 reducer driven from the carrier.

Conditions: the ratio within --tolerance; coaxiality; assembly with k
equally spaced planets (else the unequal spacing is offered); neighbour
(tip circles); no undercut of external wheels (z >= --zmin, 17 for
ha* = 1, α = 20°); internal meshes: ring z >= --ring-zmin (85) and
ring − planet >= --min-difference (8). Ranked by radial size (in modules),
then by ratio error. Sources and derivations: docs/planetary.md.

Examples:
  tmm planetary --scheme sun-planet-ring --ratio 4 --planets 3
  tmm planetary --scheme ext-int --ratio 12.5 --planets 3 --tolerance 0.01 --svg p.svg
  tmm planetary examples/planetary-ext-int.toml --json";

/// Arguments of `tmm planetary`.
#[derive(clap::Args)]
#[command(after_help = AFTER)]
pub struct Args {
    /// A task file with a [planetary] section (options given here override it)
    pub file: Option<PathBuf>,
    /// The scheme: sun-planet-ring, ext-int, ext-ext or int-int
    #[arg(long)]
    pub scheme: Option<String>,
    /// The ratio u_1H = ω1/ωH (wheel 3 fixed): a number or a fraction such as 1/50
    #[arg(long, allow_hyphen_values = true)]
    pub ratio: Option<String>,
    /// The number of planets k
    #[arg(long)]
    pub planets: Option<i64>,
    /// Relative tolerance of the ratio (0 = exact; "2 %" or 0.02)
    #[arg(long, allow_hyphen_values = true)]
    pub tolerance: Option<String>,
    /// Smallest tooth number of an external wheel (no undercut) [default: 17]
    #[arg(long)]
    pub zmin: Option<i64>,
    /// Largest tooth number considered [default: 200]
    #[arg(long)]
    pub zmax: Option<i64>,
    /// Smallest tooth number of a ring [default: 85]
    #[arg(long)]
    pub ring_zmin: Option<i64>,
    /// Smallest ring − planet tooth difference in an internal mesh [default: 8]
    #[arg(long)]
    pub min_difference: Option<i64>,
    /// Allow the two rows of a double planet different standard modules (GOST 9563)
    #[arg(long)]
    pub two_modules: bool,
    /// Module of row I for dimensions and the picture [default: 1 mm]
    #[arg(long, allow_hyphen_values = true)]
    pub module: Option<String>,
    /// Angular velocity of wheel 1 for the picture ("1450 rpm", "150 rad/s") [default: 1 rad/s]
    #[arg(long, allow_hyphen_values = true)]
    pub omega1: Option<String>,
    /// Efficiency of an external mesh [default: 0.99]
    #[arg(long)]
    pub eta_external: Option<f64>,
    /// Efficiency of an internal mesh [default: 0.995]
    #[arg(long)]
    pub eta_internal: Option<f64>,
    /// How many candidates to list [default: 10]
    #[arg(long)]
    pub top: Option<i64>,
    /// Print one JSON document (SI) instead of the tables
    #[arg(long)]
    pub json: bool,
    /// Write the sheet (scheme, velocity picture, angular-velocity diagram) to this SVG file
    #[arg(long)]
    pub svg: Option<PathBuf>,
}

/// The inputs from the file (if any) with the options over them.
fn params(a: &Args) -> Result<(Params, Origin), Error> {
    let from_file = match &a.file {
        Some(path) => {
            let task: TaskSource = read_task(path)?;
            let got = tmm_report::planetary::input::from_task(&task)?;
            Some(got.ok_or_else(|| {
                task.missing("planetary", "the task file has no [planetary] section")
                    .with_help("add a [planetary] section or give --scheme, --ratio and --planets")
            })?)
        }
        None => None,
    };
    let (mut p, mut o) = match from_file {
        Some(x) => x,
        None => {
            let missing = |opt: &str| {
                Error::input(opt, "is required without a task file")
                    .with_help("tmm planetary --scheme sun-planet-ring --ratio 4 --planets 3")
            };
            if a.scheme.is_none() {
                return Err(missing("--scheme"));
            }
            if a.ratio.is_none() {
                return Err(missing("--ratio"));
            }
            if a.planets.is_none() {
                return Err(missing("--planets"));
            }
            (
                Params::new(Request::new(tmm_planetary::Scheme::SunPlanetRing, 2.0, 1)),
                Origin::cli(),
            )
        }
    };
    if let Some(s) = &a.scheme {
        o.set_cli("scheme");
        p.request.scheme = scheme_named(s).map_err(|m| Error::input("--scheme", m).with_help(SCHEMES_HELP))?;
    }
    if let Some(u) = &a.ratio {
        o.set_cli("ratio");
        p.request.ratio = arg_qty("--ratio", u, Dim::Ratio)?;
    }
    if let Some(k) = a.planets {
        o.set_cli("planets");
        p.request.planets = whole(&o, "planets", k, "the number of planets k is 1 to 64 (usually 3)")?;
    }
    if let Some(t) = &a.tolerance {
        o.set_cli("tolerance");
        p.request.tolerance = arg_qty("--tolerance", t, Dim::Ratio)?;
    }
    let l = &mut p.request.limits;
    for (f, v, slot) in [
        ("zmin", a.zmin, &mut l.zmin),
        ("zmax", a.zmax, &mut l.zmax),
        ("ring_zmin", a.ring_zmin, &mut l.ring_zmin),
        ("min_difference", a.min_difference, &mut l.min_difference),
    ] {
        if let Some(v) = v {
            o.set_cli(f);
            *slot = whole(&o, f, v, "a whole number of teeth")?;
        }
    }
    if a.two_modules {
        p.request.two_modules = true;
    }
    if let Some(m) = &a.module {
        o.set_cli("module");
        p.module = arg_qty("--module", m, Dim::Length)?;
    }
    if let Some(w) = &a.omega1 {
        o.set_cli("omega1");
        p.omega1 = arg_qty("--omega1", w, Dim::AngularVelocity)?;
    }
    if let Some(e) = a.eta_external {
        o.set_cli("efficiency_external");
        p.efficiency.external = e;
    }
    if let Some(e) = a.eta_internal {
        o.set_cli("efficiency_internal");
        p.efficiency.internal = e;
    }
    if let Some(n) = a.top {
        o.set_cli("top");
        p.top = whole(&o, "top", n, "how many candidates to list, e.g. 10")? as usize;
    }
    Ok((p, o))
}

/// Run the command.
pub fn run(a: &Args) -> Result<(), Error> {
    let (p, o) = params(a)?;
    let an = analyse(&p, &o)?;
    let out = if a.json {
        json_text(&json::document(&an))?
    } else {
        checked(text::report(&an))?
    };
    let svg: Vec<(PathBuf, Vec<u8>)> = a
        .svg
        .iter()
        .map(|p| {
            (
                p.clone(),
                drawing::sheet(&an, Default::default(), Default::default()).svg.into_bytes(),
            )
        })
        .collect();
    let files = write_named(&svg)?;
    print(&if a.json { out } else { out + &written(&files) })
}
