//! `stewart`: the Stewart-platform studio's one binary.
//!
//! Exit status: 0 success (and, for `check`, nothing found), 1 a check found a
//! problem, 2 unusable input or output (one sentence on standard error says which).

use std::io::Write as _;
use std::process::ExitCode;

use clap::Parser;
use stewart_app::cli::{Cli, Command};
use stewart_app::commands;

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Some(Command::Solve(args)) => commands::solve::run(&args),
        Some(Command::Check(args)) => commands::check::run(&args),
        Some(Command::Fk(args)) => commands::fk::run(&args),
        Some(Command::Workspace(args)) => commands::workspace::run(&args),
        Some(Command::Forces(args)) => commands::forces::run(&args),
        Some(Command::Render(args)) => commands::render::run(&args),
        Some(Command::Plot(args)) => commands::plot::run(&args),
        Some(Command::View(args)) => commands::view::run(&args),
        Some(Command::Settings(args)) => commands::settings::run(&args),
        None => commands::no_command(),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            // Standard error may itself be unwritable (a full disk): the status still says it.
            let _ = writeln!(std::io::stderr(), "error: {e:#}");
            ExitCode::from(2)
        }
    }
}
