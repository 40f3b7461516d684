//! `tmm cam`: a cam mechanism from a compact command line (or the `[cam]`
//! section of a task file): motion law, smallest size, profile, drawings.

// The shared `Error` is large by design (it carries the task file for located messages).

use std::path::PathBuf;

use tmm_report::cam as cam_report;
use tmm_report::cam::input::{self, Field, Raw};
use tmm_report::output::Documents;
use tmm_report::task::RawQty;
use tmm_report::{Error, TaskSource};

use super::common::{checked, json_text, print, read_task, write_dir, write_named, written};

/// Arguments of `tmm cam`.
#[derive(clap::Args)]
#[command(
    after_help = "Example (seed 001, MADI variant 17):\n  tmm cam --follower translating-roller --stroke \"13 mm\" \\\n    --phases \"rise 108 const-accel(u=1/3); dwell 15; return 108 const-accel(u=1/3); dwell 129\" \\\n    --min-transmission \"rise 75, return 60\" --omega \"200 rad/s\" --svg out/\nLaws: const-accel(u=1/3), cosine, sine, linear-decreasing, trapezoid, mod-trapezoid, mod-sine, poly345, poly4567, table(a0, a1, …), const-velocity, accel(sine 1, sine -3) (pieces of the acceleration analogue: const or sine, amplitude, optional angle; the textbook's П6)\nThe textbook's П6 (BMSTU 2019) with its constructions beside tmm's sizing:\n  tmm cam --follower translating-roller --stroke \"80 mm\" --rotation cw --roller \"20 mm\" \\\n    --phases \"rise 120 accel(sine 1, sine -3); dwell 30; return 180 accel(const -1, const 2.5); dwell 30\" \\\n    --max-pressure \"rise 30, return 50\" --book-methods"
)]
pub struct Args {
    /// A task file whose [cam] section to run (instead of the options below)
    pub file: Option<PathBuf>,
    /// Follower: translating-roller (a knife edge is --roller 0), translating-flat, oscillating-roller, oscillating-flat
    #[arg(long)]
    pub follower: Option<String>,
    /// Stroke: a length ("13 mm"), or the swing angle ("20 deg") of an oscillating follower
    #[arg(long, allow_hyphen_values = true)]
    pub stroke: Option<String>,
    /// Phases from cam angle 0, summing to 360°: "rise 108 const-accel(u=1/3); dwell 15; return 108 cosine; dwell 129"
    #[arg(long)]
    pub phases: Option<String>,
    /// Allowed pressure angles: "rise 15, return 30", or one value for both (degrees)
    #[arg(long)]
    pub max_pressure: Option<String>,
    /// Allowed transmission angles γ = 90° − ϑ: "rise 75, return 60"
    #[arg(long)]
    pub min_transmission: Option<String>,
    /// Roller radius (default: min(0.4·r0, 0.7·ρmin of the pitch curve))
    #[arg(long, allow_hyphen_values = true)]
    pub roller: Option<String>,
    /// Offset e of a translating follower, or "auto" (the best one; default)
    #[arg(long, allow_hyphen_values = true)]
    pub offset: Option<String>,
    /// Smallest radius of curvature of the working profile (flat faces: default 10 mm)
    #[arg(long, allow_hyphen_values = true)]
    pub min_curvature: Option<String>,
    /// Sense of the cam's rotation: ccw (default) or cw
    #[arg(long)]
    pub rotation: Option<String>,
    /// Cam speed |ω| for the follower's v, a over time (default 1 rad/s)
    #[arg(long, allow_hyphen_values = true)]
    pub omega: Option<String>,
    /// Arm length of an oscillating follower
    #[arg(long, allow_hyphen_values = true)]
    pub arm: Option<String>,
    /// Pivot distance OA of an oscillating follower (oscillating-roller: default the one giving the smallest r0)
    #[arg(long, allow_hyphen_values = true)]
    pub pivot: Option<String>,
    /// Margin added to a flat face's contact extremes (default 5 mm)
    #[arg(long, allow_hyphen_values = true)]
    pub face_margin: Option<String>,
    /// Profile points over one turn (default 720)
    #[arg(long, allow_hyphen_values = true)]
    pub points: Option<String>,
    /// Analyse a given cam: its base (prime) circle radius r0, e.g. "2 in" (with --offset for a translating follower, --pivot for an oscillating one), instead of sizing the smallest cam
    #[arg(long, allow_hyphen_values = true)]
    pub r0: Option<String>,
    /// Also give the textbook's constructions (BMSTU 2019, appendix П6): the tangent methods of a translating follower, the level lines of an oscillating one, the roller rules, each checked against tmm's design
    #[arg(long)]
    pub book_methods: bool,
    /// Step of the position table, degrees
    #[arg(long, default_value_t = 15)]
    pub step: usize,
    /// Print one JSON document (SI, angles in rad) instead of the tables
    #[arg(long)]
    pub json: bool,
    /// Write the SVG drawings into this folder
    #[arg(long)]
    pub svg: Option<PathBuf>,
    /// Write the working profile as DXF (mm)
    #[arg(long)]
    pub dxf: Option<PathBuf>,
    /// Write the profile points as CSV (mm)
    #[arg(long)]
    pub csv: Option<PathBuf>,
}

impl Args {
    fn raw(&self) -> Result<Raw, Error> {
        let t = |s: &Option<String>| s.as_ref().map(|v| RawQty::Text(v.clone()));
        let points = match &self.points {
            None => None,
            Some(p) => Some(
                p.trim()
                    .parse::<i64>()
                    .map_err(|_| Error::input("--points", format!("`{p}` is not a whole number")).with_help("e.g. --points 3600"))?,
            ),
        };
        Ok(Raw {
            follower: self.follower.clone(),
            stroke: t(&self.stroke),
            phases: self.phases.clone(),
            max_pressure: t(&self.max_pressure),
            min_transmission: t(&self.min_transmission),
            omega: t(&self.omega),
            offset: t(&self.offset),
            roller: t(&self.roller),
            min_curvature: t(&self.min_curvature),
            rotation: self.rotation.clone(),
            arm: t(&self.arm),
            pivot: t(&self.pivot),
            face_margin: t(&self.face_margin),
            points,
            r0: t(&self.r0),
            book_methods: self.book_methods,
        })
    }

    fn any_task_option(&self) -> Option<&'static str> {
        [
            (self.follower.is_some(), "--follower"),
            (self.stroke.is_some(), "--stroke"),
            (self.phases.is_some(), "--phases"),
            (self.max_pressure.is_some(), "--max-pressure"),
            (self.min_transmission.is_some(), "--min-transmission"),
            (self.roller.is_some(), "--roller"),
            (self.offset.is_some(), "--offset"),
            (self.min_curvature.is_some(), "--min-curvature"),
            (self.rotation.is_some(), "--rotation"),
            (self.omega.is_some(), "--omega"),
            (self.arm.is_some(), "--arm"),
            (self.pivot.is_some(), "--pivot"),
            (self.face_margin.is_some(), "--face-margin"),
            (self.points.is_some(), "--points"),
            (self.r0.is_some(), "--r0"),
            (self.book_methods, "--book-methods"),
        ]
        .into_iter()
        .find(|x| x.0)
        .map(|x| x.1)
    }
}

/// Run the command.
pub fn run(a: &Args) -> Result<(), Error> {
    let (task, design, book) = match &a.file {
        Some(path) => {
            if let Some(opt) = a.any_task_option() {
                return Err(Error::input(opt, "cannot be combined with a task file")
                    .with_help("give either a task file with a [cam] section or the options"));
            }
            let src: TaskSource = read_task(path)?;
            let Some((sec, span)) = input::read_section(&src)? else {
                return Err(src
                    .missing("cam", "the task file has no [cam] section")
                    .with_help("add a [cam] section (see `tmm run --print-default`) or give the options"));
            };
            let loc = input::file_locator(&src, &sec, span);
            let raw = sec.raw();
            let task = input::build(&raw, &loc)?;
            let d = cam_report::solve(&task, input::given_r0(&raw, &loc)?, &loc)?;
            let b = cam_report::book_methods(&task, &d, &raw, &loc)?;
            (task, d, b)
        }
        None => {
            let raw = a.raw()?;
            if raw.follower.is_none() && raw.phases.is_none() && raw.stroke.is_none() {
                return Err(Error::input("tmm cam", "give the follower, the stroke and the phases (or a task file)")
                    .with_help("e.g. tmm cam --follower translating-roller --stroke \"13 mm\" --phases \"rise 108 cosine; dwell 15; return 108 cosine; dwell 129\" --max-pressure 30"));
            }
            let loc = |f: Field, m: String| input::cli_locator(f, m);
            let task = input::build(&raw, &loc)?;
            let d = cam_report::solve(&task, input::given_r0(&raw, &loc)?, &loc)?;
            let b = cam_report::book_methods(&task, &d, &raw, &loc)?;
            (task, d, b)
        }
    };
    let (json, text) = cam_report::outputs(&task, &design, book.as_ref(), a.step);
    let out = if a.json { json_text(&json)? } else { checked(text)? };
    let mut single: Vec<(PathBuf, Vec<u8>)> = Vec::new();
    if let Some(p) = &a.dxf {
        single.push((p.clone(), cam_report::profile_dxf(&design)?));
    }
    if let Some(p) = &a.csv {
        single.push((p.clone(), cam_report::profile_csv(&design)?.into_bytes()));
    }
    let svgs = match &a.svg {
        Some(_) => {
            let mut docs = Documents::new();
            cam_report::drawings(&task, &design, "", &mut docs, Default::default(), Default::default())?;
            Some(docs)
        }
        None => None,
    };
    let mut files = write_named(&single)?;
    if let (Some(dir), Some(docs)) = (&a.svg, &svgs) {
        files.extend(write_dir(dir, docs)?);
    }
    print(&if a.json { out } else { out + &written(&files) })
}
