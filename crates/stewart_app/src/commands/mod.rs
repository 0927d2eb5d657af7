//! One module per subcommand.

pub mod calibrate;
pub mod check;
pub mod cue;
pub mod design;
pub mod device_sim;
pub mod firmware;
pub mod fk;
pub mod forces;
pub mod link;
pub mod modes;
pub mod plot;
pub mod render;
pub mod settings;
pub mod solve;
pub mod view;
pub mod workspace;

use std::process::ExitCode;

use anyhow::Result;

/// `stewart` with no subcommand: the viewer on the seed scenario.
pub fn no_command() -> Result<ExitCode> {
    use clap::Parser;
    let cli = crate::cli::Cli::parse_from(["stewart", "view"]);
    match cli.command {
        Some(crate::cli::Command::View(args)) => view::run(&args),
        _ => unreachable!("`stewart view` parses as the view command"),
    }
}
