//! One module per subcommand.

pub mod check;
pub mod fk;
pub mod forces;
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
    view::run(&crate::cli::ViewArgs::default())
}
