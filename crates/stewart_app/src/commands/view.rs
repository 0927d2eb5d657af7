//! `stewart view`: the interactive viewer.

use std::process::ExitCode;

use anyhow::Result;

use crate::cli::ViewArgs;
use crate::source;
use crate::viewer::{ViewOptions, ViewerState, run as run_viewer};

/// Run the command.
pub fn run(args: &ViewArgs) -> Result<ExitCode> {
    let scenario = source::load(&args.scenario)?;
    let mut state = ViewerState::new(scenario);
    state.look.light_theme = args.light;
    state.look.presentation = args.presentation;
    state.look.expand_panels = args.expand_panels;
    run_viewer(
        state,
        ViewOptions {
            screenshot: args.screenshot.clone(),
            frames: args.frames,
            stats: args.frame_stats,
            size: args.size,
        },
    )?;
    Ok(ExitCode::SUCCESS)
}
