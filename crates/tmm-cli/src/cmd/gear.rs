//! `tmm gear pair`, `tmm gear contour`.

use tmm_report::Error;

/// The gear subcommands.
#[derive(clap::Subcommand)]
pub enum GearCommand {
    /// One gear pair: geometry and quality checks
    Pair,
}

/// Run the command.
pub fn run(a: &GearCommand) -> Result<(), Error> {
    let _ = a;
    Err(Error::input("gear", "not available yet"))
}
