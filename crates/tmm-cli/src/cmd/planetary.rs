//! `tmm planetary`.

use std::path::PathBuf;

use tmm_report::Error;

/// Arguments of `tmm planetary`.
#[derive(clap::Args)]
pub struct Args {
    /// The task file (TOML)
    pub file: Option<PathBuf>,
}

/// Run the command.
pub fn run(a: &Args) -> Result<(), Error> {
    let _ = a;
    Err(Error::input("planetary", "not available yet"))
}
