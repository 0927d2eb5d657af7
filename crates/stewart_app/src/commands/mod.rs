//! One module per subcommand.

pub(crate) mod calibrate;
pub(crate) mod check;
pub(crate) mod cue;
pub(crate) mod design;
pub(crate) mod device_sim;
pub(crate) mod firmware;
pub(crate) mod fk;
pub(crate) mod forces;
pub(crate) mod link;
pub(crate) mod modes;
pub(crate) mod plot;
pub(crate) mod render;
pub(crate) mod robot;
pub(crate) mod settings;
pub(crate) mod singularity;
pub(crate) mod solve;
pub(crate) mod telemetry;
pub(crate) mod view;
pub(crate) mod workspace;

use std::process::ExitCode;

use anyhow::Result;

/// `stewart` with no subcommand: the viewer on the seed scenario.
pub(crate) fn no_command() -> Result<ExitCode> {
    use clap::Parser;
    let cli = crate::cli::Cli::parse_from(["stewart", "view"]);
    match cli.command {
        Some(crate::cli::Command::View(args)) => view::run(&args),
        _ => unreachable!("`stewart view` parses as the view command"),
    }
}
