//! `tmm synth KIND [options]`: metric synthesis of a lever mechanism (the
//! `[synthesis]` section on the command line). One subcommand per kind, the
//! options named after the course's quantities; `--task OUT.toml` writes a
//! task file with the request and the complete `[linkage]` of the result,
//! `--sweep PARAM=FROM..TO:N` prints the table of variants instead.

use std::fmt::Write as _;
use std::path::PathBuf;

use tmm_report::Error;
use tmm_report::synthesis::{self, Fields, RawField, task::spec};

use super::common::{checked, json_text, print, write_dir, write_named, written};

/// Options every kind takes.
#[derive(clap::Args)]
pub struct Common {
    /// Direction of the crank: ccw (counter-clockwise, the default) or cw
    #[arg(long, value_name = "DIR")]
    pub direction: Option<String>,
    /// Input speed of the generated [linkage] (e.g. "900 rpm"; default 1 rad/s)
    #[arg(long, value_name = "SPEED")]
    pub speed: Option<String>,
    /// Allowed pressure angle on the working stroke [ϑ]w (e.g. "30 deg")
    #[arg(long, value_name = "ANGLE")]
    pub pressure_working: Option<String>,
    /// Allowed pressure angle on the return stroke [ϑ]r (e.g. "45 deg")
    #[arg(long, value_name = "ANGLE")]
    pub pressure_return: Option<String>,
    /// Smallest allowed transmission angle [γ]min (e.g. "40 deg")
    #[arg(long, value_name = "ANGLE")]
    pub transmission_min: Option<String>,
    /// Variants: one number swept, PARAM=FROM..TO:N (e.g. lambda=2..6:9, "crank=80 mm..120 mm:5")
    #[arg(long, value_name = "PARAM=FROM..TO:N", allow_hyphen_values = true)]
    pub sweep: Option<String>,
    /// Print one JSON document (SI, angles in radians) instead of the tables
    #[arg(long)]
    pub json: bool,
    /// Write the construction and the pressure-angle curve as SVG into this folder
    #[arg(long, value_name = "DIR")]
    pub svg: Option<PathBuf>,
    /// Write a task file with the request and the [linkage] of the result
    #[arg(long, value_name = "OUT.toml")]
    pub task: Option<PathBuf>,
}

impl Common {
    fn fields(&self, v: &mut Vec<(String, RawField)>) {
        for (k, x) in [
            ("direction", &self.direction),
            ("speed", &self.speed),
            ("pressure_working", &self.pressure_working),
            ("pressure_return", &self.pressure_return),
            ("transmission_min", &self.transmission_min),
            ("sweep", &self.sweep),
        ] {
            if let Some(t) = x {
                v.push((k.to_string(), RawField::Text(t.clone())));
            }
        }
    }
}

/// A list given as "a, b" on the command line.
fn split(t: &str) -> RawField {
    RawField::List(t.split(',').map(|s| RawField::Text(s.trim().to_string())).collect())
}

macro_rules! kind_args {
    ($(#[$m:meta])* $name:ident { $( $field:ident : $help:literal ),* $(,)? } flags { $( $flag:ident : $fhelp:literal ),* $(,)? }) => {
        $(#[$m])*
        #[derive(clap::Args)]
        pub struct $name {
            $(
                #[arg(long, help = $help, value_name = "VALUE", allow_hyphen_values = true)]
                pub $field: Option<String>,
            )*
            $(
                #[arg(long, help = $fhelp)]
                pub $flag: bool,
            )*
            #[command(flatten)]
            pub common: Common,
        }
        impl $name {
            fn fields(&self) -> Vec<(String, RawField)> {
                #[allow(unused_mut)]
                let mut v: Vec<(String, RawField)> = Vec::new();
                $(
                    if let Some(t) = &self.$field {
                        let key = stringify!($field);
                        v.push((key.to_string(), if key == "pivot_through" { split(t) } else { RawField::Text(t.clone()) }));
                    }
                )*
                $(
                    if self.$flag {
                        v.push((stringify!($flag).to_string(), RawField::Flag(true)));
                    }
                )*
                self.common.fields(&mut v);
                v
            }
        }
    };
}

kind_args! {
    /// Crank-slider by the stroke H and K, with λ2 = l2/l1, the offset e, the largest pressure angle or the optimum
    CrankSlider {
        stroke: "Stroke of the slider H (e.g. \"300 mm\")",
        mean_speed: "Mean speed of the slider instead of the stroke: H = v/(2 n1), with --speed",
        k: "Time ratio K = v_return/v_working ≥ 1",
        lambda: "λ2 = l2/l1",
        offset: "Offset e of the guide (e.g. \"40 mm\")",
        max_pressure: "Largest pressure angle over the cycle ϑmax (e.g. 40, \"40 deg\")",
    } flags {
        optimum: "The offset with the smallest largest pressure angle (or the best margin against the limits)",
    }
}

kind_args! {
    /// Crank-slider by two crank positions and the slider travel between them (seed 000 § 1.2.2)
    CrankSliderPositions {
        lambda: "λ2 = l2/l1",
        lambda_e: "λe = e/l1 (signed; default 0)",
        phi_start: "Initial crank angle φ1н",
        phi_end: "Final crank angle φ1к",
        travel: "Slider travel between them h_C (signed)",
    } flags {}
}

kind_args! {
    /// Crank-rocker four-bar by K, the rocker and its swing, with the crank, the frame, the frame's direction or the optimum
    CrankRocker {
        k: "Time ratio K = ω_return/ω_working ≥ 1",
        swing: "Swing of the rocker ψ (e.g. 60, \"60 deg\")",
        rocker: "Rocker length l_CB (e.g. \"245 mm\")",
        crank: "Crank length l_OA",
        frame: "Frame distance l_OC",
        frame_angle: "Angle from the frame line OC to the swing's bisector (90 deg: seed 002 ex. 1)",
    } flags {
        optimum: "The pivot with the largest smallest transmission angle (or the best margin against the limits)",
    }
}

/// Four-bar generating a function: the crank and rocker angles at three or more positions (Freudenstein)
#[derive(clap::Args)]
pub struct FunctionGeneration {
    /// A pair of crank and rocker angles from the frame line, "φ, ψ" (repeat: three or more)
    #[arg(long = "position", value_name = "PHI, PSI", allow_hyphen_values = true)]
    pub positions: Vec<String>,
    /// Frame length l_OC (the scale)
    #[arg(long, value_name = "VALUE")]
    pub frame: Option<String>,
    #[command(flatten)]
    pub common: Common,
}

impl FunctionGeneration {
    fn fields(&self) -> Vec<(String, RawField)> {
        let mut v = Vec::new();
        if !self.positions.is_empty() {
            v.push((
                "positions".to_string(),
                RawField::List(self.positions.iter().map(|p| split(p)).collect()),
            ));
        }
        if let Some(f) = &self.frame {
            v.push(("frame".to_string(), RawField::Text(f.clone())));
        }
        self.common.fields(&mut v);
        v
    }
}

kind_args! {
    /// Slotted-lever shaper by the ram's stroke, K and the distance between the pivots (seed 002 ex. 3)
    SlottedLever {
        stroke: "Stroke of the ram H",
        k: "Time ratio K > 1",
        pivots: "Distance l_OE between the crank pivot and the lever pivot",
        coupler: "Coupler length l_CD",
        coupler_ratio: "Coupler as l_CD / l_EC (seed 002 ex. 3: 3)",
        lever: "rotating (default) or oscillating",
    } flags {}
}

kind_args! {
    /// Crank-knee press by the slide's stroke, K, the knee's links and angle (seed 002 ex. 2)
    KneePress {
        stroke: "Stroke of the slide H_F",
        k: "Time ratio K ≥ 1",
        rocker: "Rocker l_CB",
        link: "Knee link l_BF",
        delta: "Angle δ of the rocker from the line CF at the bottom (> 0)",
        horizontal: "Horizontal distance of the crank pivot from C (seed 002: 0.28 m)",
        crank: "Crank length l_OA",
        frame: "Distance of the crank pivot from C",
    } flags {
        optimum: "The pivot with the best margin",
    }
}

kind_args! {
    /// Six-bar by kinematic inversion: the slider's travel and the lever's swing, then the four-bar by K (seed 002 ex. 4)
    SixBarInversion {
        k: "Time ratio K ≥ 1",
        travel: "Signed travel of the slider along +x from E′ to E″",
        guide: "Height of the slider's guide above the lever pivot O3 (negative: below)",
        start: "Abscissa of E′ from O3",
        coupler: "Coupler l_ED",
        swing: "Signed swing γ of the lever (positive counter-clockwise)",
        lever: "The lever's other arm l_O3B",
        crank: "Crank length of the four-bar",
        frame: "Frame distance of the four-bar",
        pivot_max_pressure: "Largest pressure angle of the four-bar over the cycle",
        extreme_pressure: "Pressure angle of the four-bar at an extreme position",
        pivot_through: "The crank pivot on a line through this point, \"x, y\" (seed 002: \"0 m, 0.2 m\")",
        pivot_angle: "Direction of that line (default 0 deg)",
    } flags {
        optimum: "The pivot with the best margin",
    }
}

kind_args! {
    /// Six-bar by the pressure angle: the lever's swing, its arms and the slider's guide (seed 003)
    SixBarPressure {
        k: "Time ratio K ≥ 1",
        swing: "Swing ψ of the lever",
        arm_b: "The lever's arm l_EB to the four-bar's coupler",
        arm_c: "The lever's arm l_EC to the slider's coupler",
        arm_angle: "Angle from EB to EC on the lever (default 180 deg)",
        guide: "Signed height of the slider's guide above E (seed 003: -0.2 m)",
        max_pressure: "Largest pressure angle allowed in the joints B and D",
        crank: "Crank length of the four-bar",
        frame: "Frame distance of the four-bar",
        pivot_max_pressure: "Largest pressure angle of the four-bar over the cycle",
        extreme_pressure: "Pressure angle of the four-bar at an extreme position (seed 003: 38 deg)",
        pivot_through: "The crank pivot on a line through this point, \"x, y\"",
        pivot_angle: "Direction of that line (default 0 deg)",
    } flags {
        optimum: "The pivot with the best margin",
    }
}

kind_args! {
    /// Crank-knee press with a bell-crank rocker B–C–D driving the knee C–D–F (seed 002 ex. 2 read literally)
    KneePressBellCrank {
        stroke: "Stroke of the slide H_F",
        k: "Time ratio K ≥ 1",
        knee: "The knee's arm l_CD of the bell crank",
        link: "The knee's link l_DF",
        arm: "The bell crank's arm l_CB to the coupler",
        chord: "The bell crank's side l_BD",
        arm_ratio: "l_CB / l_BD instead of --chord (seed 002: 2)",
        delta: "Angle δ of CD from the line CF at the bottom (> 0)",
        horizontal: "Horizontal distance of the crank pivot from C (seed 002: 0.28 m)",
        crank: "Crank length l_OA",
        frame: "Distance of the crank pivot from C",
    } flags {
        optimum: "The pivot with the best margin",
    }
}

kind_args! {
    /// Crank-rocker by the two extreme positions of its rocker with its pivot D given (textbook П1.2)
    RockerExtremes {
        frame_x: "Abscissa X_D of the rocker's pivot (the crank's pivot A at the origin)",
        frame_y: "Ordinate Y_D of the rocker's pivot",
        rocker: "Rocker length l_DC",
        gamma_start: "Rocker angle γн at the extended position (crank and coupler in line, B between A and C)",
        gamma_end: "Rocker angle γк at the folded position",
    } flags {}
}

kind_args! {
    /// Crank-rocker by the rocker's extreme positions and K, the abscissa X_D found (textbook П1.3)
    RockerExtremesK {
        k: "Time ratio Kω > 1 (θ = 180°·(K − 1)/(K + 1))",
        frame_y: "Ordinate Y_D of the rocker's pivot",
        rocker: "Rocker length l_DC",
        gamma_start: "Rocker angle γн at the extended position",
        gamma_end: "Rocker angle γк at the folded position",
    } flags {}
}

kind_args! {
    /// Four-bar through three positions, the rocker's pivot D and length given, the crank's start found (textbook П1.4)
    ThreePositions {
        frame_x: "Abscissa X_D of the rocker's pivot (the crank's pivot A at the origin)",
        frame_y: "Ordinate Y_D of the rocker's pivot",
        rocker: "Rocker length l_DC",
        gamma1: "Rocker angle γ1 in position 1",
        gamma2: "Rocker angle γ2 in position 2",
        gamma3: "Rocker angle γ3 in position 3",
        phi12: "Crank rotation φ12 from position 1 to 2 (counter-clockwise positive)",
        phi13: "Crank rotation φ13 from position 1 to 3",
    } flags {}
}

kind_args! {
    /// Lever OB driven by an oscillating cylinder pivoted at D, by the piston's travel and a pressure angle (textbook П1.5)
    OscillatingCylinder {
        h_min: "Distance h_min from D to the piston at the initial position",
        h_max: "Distance h_max at the final position",
        rod: "Piston rod l_шт (the book: 1.3·h_max)",
        swing: "Lever's turn β from the initial position to the final one",
        pressure_end: "Pressure angle θк at the final position (variants 1, 2)",
        pressure_start: "Pressure angle θн at the initial position (variant 3)",
        frame_y: "Ordinate Y_D of the cylinder's pivot: fixes the free turn about O (default: D on +x)",
    } flags {}
}

kind_args! {
    /// Shaper: crank OA, coupler AB, rocker C–B–D and the ram driven through a slider in its slot, by H, K, λ, l_BC and l_OC (textbook П3)
    Shaper {
        stroke: "Stroke of the ram H",
        k: "Time ratio K_V5 ≥ 1 (the working stroke the slower)",
        rocker: "Rocker arm l_BC from its pivot C to the coupler's joint B",
        lambda: "λ = l_CD / l_BC (the arm to the slider D over l_BC)",
        frame: "Distance l_OC between the crank's pivot O and the rocker's pivot C",
        ram_center: "The ram's centre of mass ahead of D along +X, l_S5 (default 0)",
        cutting_speed: "Cutting speed V_рез instead of --speed: ω1 = Δφ_PX·V_рез/H",
        design_position: "Design position: the crank's angle from the start of the working stroke (sets `at`)",
    } flags {}
}

/// The kinds.
#[derive(clap::Subcommand)]
pub enum SynthCommand {
    /// Crank-slider by the stroke and K (λ2, offset, largest pressure angle or optimum)
    CrankSlider(CrankSlider),
    /// Crank-slider by two crank positions and the travel
    CrankSliderPositions(CrankSliderPositions),
    /// Crank-rocker by K, rocker and swing (crank, frame, frame angle or optimum)
    CrankRocker(CrankRocker),
    /// Four-bar through given crank and rocker positions (Freudenstein)
    FunctionGeneration(FunctionGeneration),
    /// Slotted-lever shaper
    SlottedLever(SlottedLever),
    /// Crank-knee press
    KneePress(KneePress),
    /// Six-bar by kinematic inversion
    SixBarInversion(SixBarInversion),
    /// Six-bar by the pressure angle
    SixBarPressure(SixBarPressure),
    /// Crank-knee press with a bell-crank rocker (seed 002 ex. 2 read literally)
    KneePressBellCrank(KneePressBellCrank),
    /// Crank-rocker by the rocker's extreme positions, its pivot D given (textbook П1.2)
    RockerExtremes(RockerExtremes),
    /// Crank-rocker by the rocker's extreme positions and K, X_D found (textbook П1.3)
    RockerExtremesK(RockerExtremesK),
    /// Four-bar through three positions, D and the rocker given (textbook П1.4)
    ThreePositions(ThreePositions),
    /// Lever driven by an oscillating cylinder (textbook П1.5)
    OscillatingCylinder(OscillatingCylinder),
    /// Shaper by H, K, λ, l_BC and l_OC (textbook П3)
    Shaper(Shaper),
}

impl SynthCommand {
    fn parts(&self) -> (&'static str, Vec<(String, RawField)>, &Common) {
        match self {
            SynthCommand::CrankSlider(a) => ("crank-slider", a.fields(), &a.common),
            SynthCommand::CrankSliderPositions(a) => ("crank-slider-positions", a.fields(), &a.common),
            SynthCommand::CrankRocker(a) => ("crank-rocker", a.fields(), &a.common),
            SynthCommand::FunctionGeneration(a) => ("function-generation", a.fields(), &a.common),
            SynthCommand::SlottedLever(a) => ("slotted-lever", a.fields(), &a.common),
            SynthCommand::KneePress(a) => ("knee-press", a.fields(), &a.common),
            SynthCommand::SixBarInversion(a) => ("six-bar-inversion", a.fields(), &a.common),
            SynthCommand::SixBarPressure(a) => ("six-bar-pressure", a.fields(), &a.common),
            SynthCommand::KneePressBellCrank(a) => ("knee-press-bell-crank", a.fields(), &a.common),
            SynthCommand::RockerExtremes(a) => ("rocker-extremes", a.fields(), &a.common),
            SynthCommand::RockerExtremesK(a) => ("rocker-extremes-k", a.fields(), &a.common),
            SynthCommand::ThreePositions(a) => ("three-positions", a.fields(), &a.common),
            SynthCommand::OscillatingCylinder(a) => ("oscillating-cylinder", a.fields(), &a.common),
            SynthCommand::Shaper(a) => ("shaper", a.fields(), &a.common),
        }
    }
}

/// A field's value as TOML.
fn toml_value(v: &RawField) -> String {
    match v {
        RawField::Flag(b) => b.to_string(),
        RawField::Num(x) => format!("{x:?}"),
        RawField::Text(t) => toml::Value::String(t.clone()).to_string(),
        RawField::List(l) => format!("[{}]", l.iter().map(toml_value).collect::<Vec<_>>().join(", ")),
    }
}

/// The task file of `--task`: the request as a `[synthesis]` section, the
/// `[linkage]` of the result, and placeholder loads for `tmm forces` (none
/// for a crank that does not turn fully).
fn task_file(kind: &str, fields: &[(String, RawField)], linkage: &str) -> String {
    let mut t = String::new();
    let _ = writeln!(t, "# Metric synthesis of a {kind} (tmm synth {kind}).");
    t.push_str("# `tmm run` on this file repeats the synthesis and analyses the [linkage] below,\n");
    t.push_str("# which wins over the synthesis when both are present.\n");
    let _ = writeln!(t, "title = {}\n", toml::Value::String(format!("Synthesised {kind}")));
    t.push_str("[synthesis]\n");
    for (k, v) in fields {
        let _ = writeln!(t, "{k} = {}", toml_value(v));
    }
    t.push('\n');
    t.push_str(linkage);
    // a crank that does not turn fully (`range = "partial"`) has no cycle to
    // find the forces over: `tmm forces` refuses such a [linkage]
    if linkage.contains("\nrange = \"partial\"\n") {
        t.push_str(
            "\n# The crank does not turn fully: the [linkage] is analysed over the crank angles\n# where it assembles (range = \"partial\"); [forces] and [dynamics] need a full turn.\n",
        );
        return t;
    }
    t.push_str(
        "\n# Loads for `tmm forces`: placeholders (10 kg per metre of link, J_S = 0.1·m·l²,\n# no useful resistance); replace them with the task's own.\n[forces]\nmass_per_length = \"10 kg/m\"\nk = 0.1\n",
    );
    t
}

/// Run the command.
pub fn run(cmd: &SynthCommand) -> Result<(), Error> {
    let (kind, mut fields, common) = cmd.parts();
    fields.insert(0, ("kind".to_string(), RawField::Text(kind.to_string())));
    let f = Fields::options(fields.clone());
    let sp = spec(&f)?;
    if let Some(sw) = &sp.sweep {
        for (given, opt) in [(common.task.is_some(), "--task"), (common.svg.is_some(), "--svg")] {
            if given {
                return Err(Error::input(opt, "a sweep gives a table of variants, not one mechanism")
                    .with_help("run once more without --sweep, with the value chosen from the table"));
            }
        }
        let v = synthesis::variants(&sp, &f, sw)?;
        let out = if common.json {
            json_text(&synthesis::variants_json(&sp, &v))?
        } else {
            checked(synthesis::variants_table(&sp, &v))?
        };
        return print(&out);
    }
    let s = synthesis::solve(&f)?;
    let out = if common.json {
        json_text(&synthesis::json_document(&s, None, None))?
    } else {
        checked(synthesis::text_report(&s, None, None))?
    };
    let mut files = Vec::new();
    if let Some(dir) = &common.svg {
        files.extend(write_dir(
            dir,
            &synthesis::drawings(
                &s,
                tmm_report::project::Language::default(),
                tmm_report::project::SheetFormat::default(),
            )?,
        )?);
    }
    if let Some(path) = &common.task {
        let keep: Vec<(String, RawField)> = fields.into_iter().filter(|(k, _)| k != "sweep").collect();
        let text = checked(task_file(kind, &keep, &s.linkage))?;
        files.extend(write_named(&[(path.clone(), text.into_bytes())])?);
    }
    print(&if common.json { out } else { out + &written(&files) })
}
