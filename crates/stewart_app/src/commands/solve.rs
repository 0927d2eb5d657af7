//! `stewart solve`: leg lengths as CSV.

use std::process::ExitCode;

use anyhow::Result;
use stewart_kinematics::trajectory::PoseTable;

use crate::cli::SolveArgs;
use crate::csv_io::read_input;
use crate::export::tables::{legs_csv, trajectory_table};
use crate::output;
use crate::source;

/// Run the command.
pub fn run(args: &SolveArgs) -> Result<ExitCode> {
    let scenario = source::load(&args.scenario)?;
    let table = match &args.poses {
        Some(path) => read_input(path, |r, name| Ok(PoseTable::read(r, name)?))?,
        None => trajectory_table(&scenario),
    };
    let csv = legs_csv(&scenario.geometry, &table);
    output::emit(args.out.as_deref(), csv.as_bytes())?;
    Ok(ExitCode::SUCCESS)
}
