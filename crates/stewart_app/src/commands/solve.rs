//! `stewart solve`: leg lengths as CSV.

use std::process::ExitCode;

use anyhow::Result;
use stewart_kinematics::trajectory::PoseTable;

use crate::cli::SolveArgs;
use crate::csv_io::read_input;
use crate::export::tables::{trajectory_table, write_legs_csv};
use crate::output;
use crate::source;

/// Run the command.
pub fn run(args: &SolveArgs) -> Result<ExitCode> {
    let mut inputs = source::inputs(&args.scenario);
    if let Some(p) = &args.poses {
        inputs.push(("the pose table", p));
    }
    let out = output::destination(args.out.as_deref(), &inputs)?;
    let scenario = source::load(&args.scenario)?;
    let table = match &args.poses {
        Some(path) => read_input(path, |r, name| Ok(PoseTable::read(r, name)?))?,
        None => trajectory_table(&scenario),
    };
    output::emit_with(out.as_ref(), |w| {
        write_legs_csv(w, &scenario.geometry, &table)
    })?;
    Ok(ExitCode::SUCCESS)
}
