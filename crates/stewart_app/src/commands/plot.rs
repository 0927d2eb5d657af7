//! `stewart plot`: the leg-length plot (or, with `--forces`, the actuator forces) as SVG,
//! PDF or PNG.

use std::process::ExitCode;

use anyhow::Result;

use crate::cli::PlotArgs;
use crate::export::plot::plot_file;
use crate::output;
use crate::source;

/// Run the command.
pub(crate) fn run(args: &PlotArgs) -> Result<ExitCode> {
    let scenario = source::load(&args.scenario)?;
    let out = output::Destination::new(&args.out, &source::inputs(&args.scenario, &scenario))?;
    out.require_file()?;
    let lang = crate::i18n::for_command(args.lang, "plot");
    let bytes = plot_file(&scenario, &args.out, lang, args.forces)?;
    out.write_bytes(&bytes)?;
    Ok(ExitCode::SUCCESS)
}
