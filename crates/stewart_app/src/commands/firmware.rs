//! `stewart firmware`: the scenario's geometry as a C header.

use std::process::ExitCode;

use anyhow::Result;

use crate::cli::FirmwareArgs;
use crate::export::firmware;
use crate::output;
use crate::source;

/// Run the command.
pub(crate) fn run(args: &FirmwareArgs) -> Result<ExitCode> {
    let scenario = source::load(&args.scenario)?;
    let inputs = source::inputs(&args.scenario, &scenario);
    let out = output::destination(args.out.as_deref(), &inputs)?;
    let text = firmware::header(&scenario);
    output::emit_with(out.as_ref(), |w| w.write_all(text.as_bytes()))?;
    Ok(ExitCode::SUCCESS)
}
