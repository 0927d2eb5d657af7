//! `stewart solve`: leg lengths as CSV.

use std::process::ExitCode;

use anyhow::Result;
use stewart_kinematics::model::trajectory::PoseTable;

use crate::cli::SolveArgs;
use crate::csv_io::read_input_bytes;
use crate::export::tables::{
    Solved, solve_table, trajectory_place, trajectory_table, write_solved_csv,
};
use crate::output;
use crate::source;
use stewart_kinematics::io::file::FileKind;

/// Run the command.
pub(crate) fn run(args: &SolveArgs) -> Result<ExitCode> {
    let scenario = source::load(&args.scenario)?;
    let mut inputs = source::inputs(&args.scenario, &scenario);
    if let Some(p) = &args.poses {
        inputs.push(("the pose table", p.clone()));
    }
    let out = output::destination(args.out.as_deref(), &inputs)?;
    let (table, file) = match &args.poses {
        Some(path) => {
            // The file's bytes as read, parsed in place (a table of 1 M rows is 250 MB).
            let (bytes, name) = read_input_bytes(path, FileKind::Table)?;
            (PoseTable::read_bytes(bytes, &name)?, Some(name))
        }
        None => (trajectory_table(&scenario), None),
    };
    let solved = solve_table(&scenario.geometry, &table, |k| match &file {
        Some(name) => format!("{name}, line {}", table.lines.get(k).copied().unwrap_or(0)),
        None => format!(
            "{}: {}",
            source::describe(&args.scenario),
            trajectory_place(&table, k)
        ),
    })?;
    let solved = if args.commanded {
        commanded(&scenario, solved)?
    } else {
        solved
    };
    output::emit_with(out.as_ref(), |w| write_solved_csv(w, &table, &solved))?;
    Ok(ExitCode::SUCCESS)
}

/// Model servo angles (degrees) turned into the angles the servos are commanded.
fn commanded(scenario: &stewart_kinematics::Scenario, solved: Solved) -> Result<Solved> {
    let actuator = scenario.geometry.actuator();
    // Kinds without a commanded form give none for any values.
    if actuator.commanded_values(&[0.0; 6]).is_none() {
        anyhow::bail!(
            "--commanded applies to rotary servo platforms; scenario `{}` has {}",
            scenario.name,
            scenario.geometry.quantity().kind
        );
    }
    let values = solved
        .values
        .iter()
        .filter_map(|row| actuator.commanded_values(row))
        .collect();
    Ok(Solved {
        columns: ["cmd1", "cmd2", "cmd3", "cmd4", "cmd5", "cmd6"],
        values,
    })
}
