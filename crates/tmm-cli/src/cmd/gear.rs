//! `tmm gear pair`, `tmm gear contour`: an involute spur pair with profile
//! shift — geometry, checks, specific sliding, the meshing drawing, generated
//! profiles — and the blocking contour with the chosen x1, x2.

// The shared `Error` carries the task text for located diagnostics, and the
// command is parsed once: size lints do not apply here.

use std::path::PathBuf;

use tmm_gears::contour::{ContourOptions, blocking_contour};
use tmm_report::Error;
use tmm_report::gear::input::{Field, Origin, Raw, gear_error};
use tmm_report::gear::{contour_plot, json, machine_mesh, mesh, profile, profiles, sliding_svg, solve, text};
use tmm_report::task::RawQty;

use tmm_report::output::num;

use super::common::{checked, json_text, print, write_named, written};

/// The gear subcommands.
#[derive(clap::Subcommand)]
// parsed once per run: the size of the variants does not matter
#[allow(clippy::large_enum_variant)]
pub enum GearCommand {
    /// One gear pair: geometry (GOST 16532-70), quality checks, specific sliding, meshing drawing, generated profiles.
    /// Give x1 and x2; or --aw to get the shift sum and split it; or neither to have both chosen.
    #[command(
        after_help = "Examples:\n  tmm gear pair --z1 15 --z2 20 --module \"5 mm\" --x1 0.2 --x2 0.85\n  tmm gear pair --z1 16 --z2 20 --module \"30 mm\" --aw \"560 mm\" --criterion balanced\n  tmm gear pair --z1 16 --z2 20 --module \"30 mm\" --svg mesh.svg --dxf mesh.dxf --json"
    )]
    Pair(PairArgs),
    /// The blocking contour of (z1, z2, basic rack) in the x1–x2 plane, with the point chosen by a criterion.
    #[command(after_help = "Example:\n  tmm gear contour --z1 16 --z2 20 --svg contour.svg")]
    Contour(ContourArgs),
}

/// The pair and its basic rack, shared by both subcommands.
#[derive(clap::Args, Clone)]
pub struct Common {
    /// Pinion tooth number z1
    #[arg(long)]
    pub z1: i64,
    /// Wheel tooth number z2 (the ring's with --internal)
    #[arg(long)]
    pub z2: i64,
    /// Profile angle of the basic rack α (plain number: degrees)
    #[arg(long, default_value = "20", allow_hyphen_values = true)]
    pub alpha: String,
    /// Addendum coefficient ha*
    #[arg(long, default_value = "1", allow_hyphen_values = true)]
    pub ha: String,
    /// Clearance coefficient c*
    #[arg(long, default_value = "0.25", allow_hyphen_values = true)]
    pub c: String,
    /// Boundary-height coefficient hl* (the straight flank of the rack spans hl*·m)
    #[arg(long, default_value = "2", allow_hyphen_values = true)]
    pub hl: String,
    /// Internal pair: wheel 2 is a ring
    #[arg(long)]
    pub internal: bool,
    /// Criterion for choosing x1, x2: equal-sliding (default), max-contact-ratio, balanced
    #[arg(long)]
    pub criterion: Option<String>,
    /// Least tip thickness as a fraction of m; the default 0.3 is GOST 16532-70's value for through-hardened teeth (use 0.4 for case-hardened)
    #[arg(long, default_value = "0.3", allow_hyphen_values = true)]
    pub sa_min: String,
    /// Least contact ratio εα
    #[arg(long, default_value = "1.2", allow_hyphen_values = true)]
    pub eps_min: String,
    /// Print one JSON document (SI, angles in rad) instead of the tables
    #[arg(long)]
    pub json: bool,
}

/// `tmm gear pair`.
#[derive(clap::Args)]
pub struct PairArgs {
    #[command(flatten)]
    pub common: Common,
    /// Module m ("5 mm"; a plain number is metres)
    #[arg(long)]
    pub module: String,
    /// Shift coefficient of the pinion x1
    #[arg(long, allow_hyphen_values = true)]
    pub x1: Option<String>,
    /// Shift coefficient of the wheel x2
    #[arg(long, allow_hyphen_values = true)]
    pub x2: Option<String>,
    /// Required centre distance aw instead of the shifts ("560 mm")
    #[arg(long)]
    pub aw: Option<String>,
    /// Write the meshing drawing (SVG) to this file
    #[arg(long)]
    pub svg: Option<PathBuf>,
    /// Write the meshing drawing (DXF, layers, mm) to this file
    #[arg(long)]
    pub dxf: Option<PathBuf>,
    /// Write the generated tooth profiles as CSV points to this file
    #[arg(long)]
    pub profiles: Option<PathBuf>,
    /// Write the generated tooth profiles as SVG polylines to this file
    #[arg(long)]
    pub profiles_svg: Option<PathBuf>,
    /// Write the generated tooth profiles as DXF polylines to this file
    #[arg(long)]
    pub profiles_dxf: Option<PathBuf>,
    /// Write the specific-sliding diagram (SVG) to this file
    #[arg(long)]
    pub sliding_svg: Option<PathBuf>,
    /// Write the machine meshing of wheel 1 with the rack-type tool (SVG) to this file
    #[arg(long)]
    pub machine_mesh_svg: Option<PathBuf>,
    /// Include one generated tooth of each wheel in the JSON
    #[arg(long)]
    pub with_profiles: bool,
}

/// `tmm gear contour`.
#[derive(clap::Args)]
pub struct ContourArgs {
    #[command(flatten)]
    pub common: Common,
    /// Write the contour (SVG, A4) to this file
    #[arg(long)]
    pub svg: Option<PathBuf>,
    /// Grid nodes per side (the boundaries are refined to 1e-10 on the grid edges)
    #[arg(long, default_value_t = 121)]
    pub n: usize,
}

fn raw(c: &Common, module: Option<&str>) -> Raw {
    let t = |s: &str| Some(RawQty::Text(s.to_string()));
    Raw {
        z1: Some(c.z1),
        z2: Some(c.z2),
        module: module.and_then(t),
        alpha: t(&c.alpha),
        ha: t(&c.ha),
        c: t(&c.c),
        hl: t(&c.hl),
        internal: c.internal,
        criterion: c.criterion.clone(),
        sa_min: t(&c.sa_min),
        eps_min: t(&c.eps_min),
        ..Default::default()
    }
}

/// Run the command.
pub fn run(a: &GearCommand) -> Result<(), Error> {
    match a {
        GearCommand::Pair(p) => pair(p),
        GearCommand::Contour(c) => contour(c),
    }
}

fn pair(a: &PairArgs) -> Result<(), Error> {
    let o = Origin::Cli;
    let mut r = raw(&a.common, Some(&a.module));
    let t = |s: &Option<String>| s.as_ref().map(|v| RawQty::Text(v.clone()));
    r.x1 = t(&a.x1);
    r.x2 = t(&a.x2);
    r.aw = t(&a.aw);
    let job = r.job(&o, true)?;
    let solved = solve::solve(&job, &o)?;
    let pair = &solved.pair;
    let (t1, t2) = profiles(pair, &o)?;
    let out = if a.common.json {
        json_text(&json::pair_json(&solved, &job.limits, a.with_profiles.then_some((&t1, &t2))))?
    } else {
        checked(text::pair_text(&solved, &job.limits))?
    };
    let mut files: Vec<(PathBuf, Vec<u8>)> = Vec::new();
    if let Some(p) = &a.svg {
        files.push((
            p.clone(),
            mesh::mesh_svg(pair, &t1, &t2, Default::default(), Default::default()).into_bytes(),
        ));
    }
    if let Some(p) = &a.dxf {
        files.push((p.clone(), mesh::mesh_dxf(pair, &t1, &t2).to_bytes()?));
    }
    if let Some(p) = &a.profiles {
        files.push((p.clone(), profile::profiles_csv(&t1, &t2).into_bytes()));
    }
    if let Some(p) = &a.profiles_svg {
        files.push((p.clone(), profile::profiles_svg(&t1, &t2, Default::default()).into_bytes()));
    }
    if let Some(p) = &a.profiles_dxf {
        files.push((p.clone(), profile::profiles_dxf(&t1, &t2).to_bytes()?));
    }
    if let Some(p) = &a.sliding_svg {
        files.push((p.clone(), sliding_svg(pair, Default::default(), Default::default()).into_bytes()));
    }
    if let Some(p) = &a.machine_mesh_svg {
        files.push((
            p.clone(),
            machine_mesh::machine_mesh_svg(pair, &t1, Default::default(), Default::default()).into_bytes(),
        ));
    }
    let files = write_named(&files)?;
    print(&if a.common.json { out } else { out + &written(&files) })
}

fn contour(a: &ContourArgs) -> Result<(), Error> {
    let o = Origin::Cli;
    let r = raw(&a.common, None);
    let job = r.job(&o, false)?;
    if !(8..=1001).contains(&a.n) {
        return Err(Error::input("--n", format!("must lie in 8..=1001, got {}", a.n)).with_help("121 is fine for an A4 plot"));
    }
    let c = blocking_contour(
        &job.spec,
        &ContourOptions {
            n: a.n,
            ..Default::default()
        },
    )
    .map_err(|e| gear_error(&o, &e))?;
    let solved = solve::solve(
        &tmm_report::gear::input::Job {
            mode: tmm_report::gear::input::Mode::Choose,
            ..job
        },
        &o,
    );
    let chosen = solved.as_ref().ok().map(|s| {
        (
            (s.pair.w1.x, s.pair.w2.x),
            s.criterion.map_or("chosen".into(), |c| c.name().to_string()),
        )
    });
    let svg_file: Vec<(PathBuf, Vec<u8>)> = a
        .svg
        .iter()
        .map(|p| {
            (
                p.clone(),
                contour_plot::contour_svg(&c, chosen.clone(), Default::default(), Default::default()).into_bytes(),
            )
        })
        .collect();
    let out = if a.common.json {
        let lines: Vec<serde_json::Value> = c
            .lines
            .iter()
            .map(|l| {
                serde_json::json!({
                    "boundary": l.boundary.key(),
                    "label": l.boundary.label(),
                    "blocking": l.boundary.is_blocking(),
                    "polylines": l.polylines.iter().map(|pl| pl.iter().map(|&(x, y)| [num(x), num(y)]).collect::<Vec<_>>()).collect::<Vec<_>>(),
                })
            })
            .collect();
        let mut doc = serde_json::json!({
            "units": "SI",
            "z1": job.spec.z1,
            "z2": job.spec.z2,
            "kind": if job.spec.kind == tmm_gears::Kind::Internal { "internal" } else { "external" },
            "x1_range": [num(c.x1.0), num(c.x1.1)],
            "x2_range": [num(c.x2.0), num(c.x2.1)],
            "n": c.n,
            "lines": lines,
        });
        match &solved {
            Ok(s) => {
                doc["chosen"] = serde_json::json!({"x1": num(s.pair.w1.x), "x2": num(s.pair.w2.x), "criterion": s.criterion.map(|c| c.name()), "reason": s.reason, "eps_alpha": num(s.pair.eps_alpha), "theta1_max": s.pair.theta1_max().map(num), "theta2_max": s.pair.theta2_max().map(num)});
            }
            Err(e) => doc["chosen"] = serde_json::json!({"error": e.to_string()}),
        }
        json_text(&doc)?
    } else {
        checked(contour_text(&job.spec, &c, &solved))?
    };
    let files = write_named(&svg_file)?;
    let _ = Field::Section;
    print(&if a.common.json { out } else { out + &written(&files) })
}

/// The contour's summary table.
fn contour_text(spec: &tmm_gears::PairSpec, c: &tmm_gears::contour::Contour, solved: &Result<solve::Solved, Error>) -> String {
    let mut out = format!(
        "Blocking contour z1 = {}, z2 = {}: x1 in [{:.3}, {:.3}], x2 in [{:.3}, {:.3}], {}×{} grid\n",
        spec.z1, spec.z2, c.x1.0, c.x1.1, c.x2.0, c.x2.1, c.n, c.n
    );
    for l in &c.lines {
        let pts: usize = l.polylines.iter().map(|p| p.len()).sum();
        out += &format!(
            "  {:<22} {} polyline(s), {pts} points{}\n",
            l.boundary.label(),
            l.polylines.len(),
            if l.boundary.is_blocking() { " (blocking)" } else { "" }
        );
    }
    let opt = |v: Option<f64>| v.map_or("-".to_string(), |v| format!("{v:.4}"));
    match solved {
        Ok(s) => {
            out += &format!(
                "Chosen by {}: x1 = {:.4}, x2 = {:.4} (εα = {:.4}, ϑ1max = {}, ϑ2max = {})\n",
                s.criterion.map_or("-", |c| c.name()),
                s.pair.w1.x,
                s.pair.w2.x,
                s.pair.eps_alpha,
                opt(s.pair.theta1_max()),
                opt(s.pair.theta2_max())
            );
            if let Some(r) = &s.reason {
                out += &format!("  ({r})\n");
            }
        }
        Err(e) => out += &format!("No point chosen: {e}\n"),
    }
    out
}
