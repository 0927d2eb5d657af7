//! `stewart plot`: the leg-length plot as SVG, PDF or PNG.

use std::process::ExitCode;

use anyhow::{Result, bail};

use crate::cli::PlotArgs;
use crate::export::plot::scenario_svg;
use crate::export::vector;
use crate::output;
use crate::source;

/// Run the command.
pub fn run(args: &PlotArgs) -> Result<ExitCode> {
    let scenario = source::load(&args.scenario)?;
    let (_, text) = scenario_svg(&scenario);
    let bytes = match args
        .out
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .as_deref()
    {
        Some("svg") => text.into_bytes(),
        Some("pdf") => vector::pdf(&text)?,
        // 3.125 × 96 dpi = 300 dpi.
        Some("png") => vector::png(&text, 3.125)?,
        _ => bail!(
            "`{}`: the plot file must end in .svg, .pdf or .png",
            args.out.display()
        ),
    };
    output::write_atomically(&args.out, &bytes)?;
    Ok(ExitCode::SUCCESS)
}
