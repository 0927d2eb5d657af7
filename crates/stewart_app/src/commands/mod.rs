//! One module per subcommand.

pub mod check;
pub mod fk;
pub mod forces;
pub mod plot;
pub mod render;
pub mod solve;
pub mod workspace;

use std::process::ExitCode;

use anyhow::Result;
use clap::CommandFactory;

/// `stewart` with no subcommand. The interactive viewer is a later milestone; until it
/// exists, say so and show what the command line can do.
pub fn no_command() -> Result<ExitCode> {
    let mut cmd = crate::cli::Cli::command();
    println!(
        "The interactive viewer is not part of this build yet; the command line works without a display.\n"
    );
    cmd.print_help()?;
    Ok(ExitCode::SUCCESS)
}
