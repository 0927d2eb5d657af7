//! The Stewart-platform studio's program: command-line definitions, one module per command,
//! exports, the viewer, the link to hardware. Everything is the crate's own
//! (`pub(crate)`) but a small façade:
//!
//! - [`main`]: the `stewart` program (the binary calls only this);
//! - for the benchmarks: the export pipeline (`export::encode::{export, FrameSink}`,
//!   `export::frames::{FrameJob, FrameSource, default_camera}`), the pose tables
//!   (`export::tables`), the viewer's state and its frame (`viewer::ViewerState`,
//!   `viewer::panels::viewer_ui`), the link's plan and a live cue (`link_plan::LinkPlan`,
//!   `vehicle_in::live_cue::LiveCue`), and the interface's language (`i18n::Lang`).
//!
//! The viewer's egui_kittest tests live inside it (`viewer/ui_tests`), so they may reach
//! what the façade does not show.

pub(crate) mod cli;
pub(crate) mod commands;
pub(crate) mod csv_io;
pub mod export;

pub(crate) mod appearance;
pub mod i18n;
pub(crate) mod interrupt;
pub mod link_plan;
pub(crate) mod long_work;
pub(crate) mod output;
pub(crate) mod readout;
pub(crate) mod shot_scale;
pub(crate) mod source;
pub mod vehicle_in;
pub mod viewer;
pub(crate) mod volume_text;

use std::io::Write as _;
use std::process::ExitCode;

use clap::Parser;

use cli::{Cli, Command};

/// The `stewart` program: parse the command line, run the command, say what went wrong in
/// one line on standard error. Exit status: 0 success (and, for `check`, nothing found),
/// 1 a check found a problem, 2 unusable input or output.
pub fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) if e.use_stderr() => {
            // One line, like every other error: clap's first paragraph names the option
            // and why; its own indented continuation (`[possible values: …]`) joins the
            // line, and a value with line breaks in it shows them as `\n`.
            let text = e.render().to_string();
            let first = text
                .split("\n\n")
                .next()
                .map(|p| p.trim_end().replace("\n  ", " ").replace('\n', "\\n"))
                .filter(|p| !p.is_empty())
                .unwrap_or_else(|| "error: bad arguments".to_owned());
            let _ = writeln!(std::io::stderr(), "{first}");
            return ExitCode::from(2);
        }
        // --help and --version go to standard output; a closed pipe ends quietly, a full
        // disk is an error.
        Err(e) => {
            let text = e.render().to_string();
            return match output::stdout(text.as_bytes()) {
                Ok(()) => ExitCode::SUCCESS,
                Err(err) => {
                    let _ = writeln!(std::io::stderr(), "error: {err:#}");
                    ExitCode::from(2)
                }
            };
        }
    };
    let result = match cli.command {
        Some(Command::Solve(args)) => commands::solve::run(&args),
        Some(Command::Check(args)) => commands::check::run(&args),
        Some(Command::Cue(args)) => commands::cue::run(&args),
        Some(Command::Fk(args)) => commands::fk::run(&args),
        Some(Command::Calibrate(args)) => commands::calibrate::run(&args),
        Some(Command::Workspace(args)) => commands::workspace::run(&args),
        Some(Command::Forces(args)) => commands::forces::run(&args),
        Some(Command::Modes(args)) => commands::modes::run(&args),
        Some(Command::Design(args)) => commands::design::run(&args),
        Some(Command::Render(args)) => commands::render::run(&args),
        Some(Command::Plot(args)) => commands::plot::run(&args),
        Some(Command::Robot(args)) => commands::robot::run(&args),
        Some(Command::Singularity(args)) => commands::singularity::run(&args),
        Some(Command::View(args)) => commands::view::run(&args),
        Some(Command::Settings(args)) => commands::settings::run(&args),
        Some(Command::Firmware(args)) => commands::firmware::run(&args),
        Some(Command::Link(args)) => commands::link::run(&args),
        Some(Command::DeviceSim(args)) => commands::device_sim::run(&args),
        Some(Command::Telemetry(args)) => commands::telemetry::run(&args),
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
