//! `stewart solve`: leg lengths as CSV.

use std::process::ExitCode;

use anyhow::Result;
use stewart_kinematics::trajectory::{POSE_COLUMNS, PoseTable};
use stewart_kinematics::{Geometry, Pose};

use crate::cli::SolveArgs;
use crate::csv_io::{CsvText, read_input};
use crate::output;
use crate::source;

/// Run the command.
pub fn run(args: &SolveArgs) -> Result<ExitCode> {
    let scenario = source::load(&args.scenario)?;
    let table = match &args.poses {
        Some(path) => read_input(path, |r, name| Ok(PoseTable::read(r, name)?))?,
        None => {
            let samples = scenario.motion.sample();
            let values: Vec<[f64; 6]> = samples
                .poses
                .iter()
                .map(|p| {
                    let [r, pi, y] = p.rpy_degrees();
                    [p.position.x, p.position.y, p.position.z, r, pi, y]
                })
                .collect();
            // Solve the poses exactly as printed (angles in degrees), so that every row is a
            // consistent record that `--poses` reproduces bit for bit.
            let poses = values
                .iter()
                .map(|v| Pose::from_xyz_rpy_deg([v[0], v[1], v[2]], [v[3], v[4], v[5]]))
                .collect();
            PoseTable {
                times: Some(samples.times),
                lines: Vec::new(),
                poses,
                values,
            }
        }
    };
    let csv = legs_csv(&scenario.geometry, &table);
    output::emit(args.out.as_deref(), csv.as_bytes())?;
    Ok(ExitCode::SUCCESS)
}

/// `[t,]x,y,z,roll_deg,pitch_deg,yaw_deg,L1..L6`.
fn legs_csv(geometry: &Geometry, table: &PoseTable) -> String {
    let lengths = geometry.leg_lengths_batch(&table.poses);
    let mut header: Vec<&str> = Vec::new();
    if table.times.is_some() {
        header.push("t");
    }
    header.extend(POSE_COLUMNS);
    header.extend(["L1", "L2", "L3", "L4", "L5", "L6"]);
    let mut csv = CsvText::with_header(&header);
    for (k, (v, l)) in table.values.iter().zip(&lengths).enumerate() {
        let t = table.times.as_ref().map(|t| t[k]);
        csv.row(
            t.into_iter()
                .chain(v.iter().copied())
                .chain(l.iter().copied()),
        );
    }
    csv.into_string()
}
