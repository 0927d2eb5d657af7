//! `stewart cue`: platform poses from vehicle motion by classical washout (the scenario's
//! `[cueing]` table), as a pose table that `solve --poses`, `check` and `link` take.

use std::fmt::Write as _;
use std::io::Write as _;
use std::process::ExitCode;

use anyhow::{Result, anyhow};
use stewart_kinematics::analysis::cueing::{CueError, VehicleMotion, cue_recording};

use crate::cli::CueArgs;
use crate::csv_io::{CsvText, read_input};
use crate::output;
use crate::source;
use crate::vehicle_table::{self, VehicleTable};

/// The pose table's columns.
const POSE_COLUMNS: [&str; 7] = ["t", "x", "y", "z", "roll_deg", "pitch_deg", "yaw_deg"];

/// Run the command.
pub(crate) fn run(args: &CueArgs) -> Result<ExitCode> {
    let mut inputs = source::inputs(&args.scenario);
    inputs.push(("the vehicle motion", &args.input));
    let out = output::destination(args.out.as_deref(), &inputs)?;
    let scenario = source::load(&args.scenario)?;
    let (VehicleTable { table, samples }, file) = read_input(&args.input, |r, name| {
        Ok((vehicle_table::read(r, name)?, name.to_owned()))
    })?;
    let cued = cue_recording(
        &scenario.geometry,
        &scenario.limits,
        &scenario.cueing,
        &samples,
    )
    .map_err(|e| match e {
        CueError::Time { index, .. } => {
            anyhow!("{file}, line {}, column `t`: {e}", table.line(index))
        }
        CueError::PoseOutside { index, .. } => {
            anyhow!("{file}, line {}: {e}", table.line(index))
        }
        other => anyhow!("{}: {other}", source::describe(&args.scenario)),
    })?;
    let mut csv = CsvText::with_header(&POSE_COLUMNS);
    for ((t, _), pose) in samples.iter().zip(&cued.poses) {
        csv.row(std::iter::once(*t).chain(pose.to_row()));
    }
    let text = csv.into_string();
    output::emit_with(out.as_ref(), |w| w.write_all(text.as_bytes()))?;
    let _ = std::io::stderr().write_all(summary(&samples, &cued.scales).as_bytes());
    Ok(ExitCode::SUCCESS)
}

/// One line on what was cued, and how much the limiter held back.
fn summary(samples: &[(f64, VehicleMotion)], scales: &[f64]) -> String {
    let span = samples.last().map_or(0.0, |l| l.0) - samples.first().map_or(0.0, |f| f.0);
    let mut s = format!("cue: {} poses over {span:.3} s", samples.len());
    let held = scales.iter().filter(|&&k| k < 1.0).count();
    if held > 0 {
        let least = scales.iter().copied().fold(1.0, f64::min);
        let _ = write!(
            s,
            "; the workspace limiter scaled the cue back at {held} of them (to {:.1} % at the least)",
            100.0 * least
        );
    }
    s.push('\n');
    s
}
