//! `tmm` — the Theory of Mechanisms and Machines (ТММ) on the command line.
//!
//! Each subcommand lives in its own file under `cmd/`; this file only parses
//! the command line and turns errors into messages and exit codes
//! (2: bad input, 1: a failed write).

use std::process::ExitCode;

use clap::{Parser, Subcommand};

mod cmd;
mod write;

/// tmm: the Theory of Mechanisms and Machines (ТММ) course project and everyday
/// mechanism calculations — lever mechanisms, forces, gears, planetary trains, cams.
#[derive(Parser)]
#[command(name = "tmm", version, about, long_about = None, after_help = AFTER_HELP)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

const AFTER_HELP: &str = "Units: values take units (\"120 mm\", \"900 rpm\", \"15 deg\", \"3 kN\"); a plain number is SI, except angles (degrees).\nJSON output (--json) is SI with angles in radians.\nExit codes: 0 done, 2 bad input, 1 a file could not be written.\nExamples:\n  tmm run                                   the embedded default course project into ./tmm-out/\n  tmm run examples/seed-001-fourbar.toml    every section of a task file\n  tmm note examples/seed-001-fourbar.toml --lang uk   the explanatory note as ./note.pdf\n  tmm linkage examples/seed-001-fourbar.toml --at 15\n  tmm synth crank-rocker --k 1.28 --swing 60 --rocker \"245 mm\" --crank \"100 mm\" --task t.toml";

#[derive(Subcommand)]
enum Command {
    /// Run every section of a task file (or, with no file, the embedded default course project) into an output folder
    Run(cmd::run::Args),
    /// The explanatory note of a task file (or of the embedded default course project) as note.pdf
    Note(cmd::note::Args),
    /// Metric synthesis of a lever mechanism: lengths and frame from K, the stroke or swing, the pressure angles
    #[command(subcommand)]
    Synth(cmd::synth::SynthCommand),
    /// Lever mechanism: structure (Assur groups) and kinematics (12 positions, plans, diagrams)
    Linkage(cmd::linkage::Args),
    /// Kinetostatics: inertia loads, reactions, balancing torque, Zhukovsky's lever, strength of a link
    Forces(cmd::forces::Args),
    /// Dynamics of the machine: reduced inertia and moments, the flywheel (Mertsalov, Wittenbauer, exact), true ω1(φ), run-up; the unsteady single stroke with a Kloss motor
    Dynamics(cmd::dynamics::Args),
    /// Involute spur gear pair with profile shift: geometry, checks, blocking contour, meshing drawing
    #[command(subcommand)]
    Gear(cmd::gear::GearCommand),
    /// Planetary gear train: tooth numbers for a ratio and number of planets
    Planetary(cmd::planetary::Args),
    /// Cam mechanism: motion law, minimum size, profile
    Cam(cmd::cam::Args),
    /// A mechanism driven by a cylinder, the piston's travel s as its coordinate: analogues d/ds, reduced mass, the zero-work control force, V(s), a(s), t(s), kinetostatics
    Cylinder(cmd::cylinder::Args),
}

fn main() -> ExitCode {
    // Messages are read in terminals and in logs: never break a field name.
    let _ = miette::set_hook(Box::new(|_| Box::new(miette::MietteHandlerOpts::new().wrap_lines(false).build())));
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            // --help and --version go to standard output: a failed write
            // (>/dev/full) exits 1 like every failed write; a usage error goes
            // to standard error with exit code 2, dropped if it cannot be written
            use std::io::Write;
            let printed = e.print().and_then(|()| std::io::stdout().flush());
            return match (e.use_stderr(), printed) {
                (true, _) => ExitCode::from(2),
                (false, Ok(())) => ExitCode::SUCCESS,
                (false, Err(_)) => ExitCode::from(1),
            };
        }
    };
    write::clean_up_on_signals();
    let result = match &cli.command {
        Command::Run(a) => cmd::run::run(a),
        Command::Note(a) => cmd::note::run(a),
        Command::Synth(a) => cmd::synth::run(a),
        Command::Linkage(a) => cmd::linkage::run(a),
        Command::Forces(a) => cmd::forces::run(a),
        Command::Dynamics(a) => cmd::dynamics::run(a),
        Command::Gear(a) => cmd::gear::run(a),
        Command::Planetary(a) => cmd::planetary::run(a),
        Command::Cam(a) => cmd::cam::run(a),
        Command::Cylinder(a) => cmd::cylinder::run(a),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            let code = e.exit_code();
            // A message that cannot be written (2>/dev/full) is dropped; the
            // exit code still tells the error.
            write::print_error(&format!("{:?}\n", miette::Report::new(e)));
            ExitCode::from(code as u8)
        }
    }
}
