//! The trajectory as a CSV of poses and leg lengths (what `solve` prints and the viewer
//! exports).

use stewart_kinematics::model::trajectory::{POSE_COLUMNS, PoseTable};
use stewart_kinematics::{Geometry, Pose, Scenario};

use std::io::Write;

use crate::csv_io::write_table;

/// The sampled trajectory as a pose table. Angles are rounded through degrees as printed,
/// and the legs are solved for those printed poses, so that every row is a consistent
/// record that `solve --poses` reproduces bit for bit.
pub fn trajectory_table(scenario: &Scenario) -> PoseTable {
    let samples = scenario.motion.sample();
    let values: Vec<[f64; 6]> = samples.poses.iter().map(Pose::to_row).collect();
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

/// What each pose needs from the actuators: six leg lengths (m) or six servo angles (°).
pub struct Solved {
    /// `L1..L6` or `theta1..theta6`.
    pub(crate) columns: [&'static str; 6],
    /// One row of six values per pose.
    pub(crate) values: Vec<[f64; 6]>,
}

/// Leg lengths (linear legs, on all cores) or servo angles (rotary servos) of every pose
/// of `table`. A pose no servo angle reaches is an error located by `locate(k)` (a file
/// and line, or a time); then nothing is written.
pub fn solve_table(
    geometry: &Geometry,
    table: &PoseTable,
    locate: impl Fn(usize) -> String,
) -> anyhow::Result<Solved> {
    let values = geometry
        .actuator_values_batch(&table.poses)
        .map_err(|(k, e)| anyhow::anyhow!("{}: {e}", locate(k)))?;
    Ok(Solved {
        columns: geometry.quantity().columns,
        values,
    })
}

/// Write `[t,]x,y,z,roll_deg,pitch_deg,yaw_deg` and the six solved columns to `out`.
pub fn write_solved_csv(
    out: &mut dyn Write,
    table: &PoseTable,
    solved: &Solved,
) -> std::io::Result<()> {
    let mut header: Vec<&str> = Vec::new();
    if table.times.is_some() {
        header.push("t");
    }
    header.extend(POSE_COLUMNS);
    header.extend(solved.columns);
    write_table(out, &header, table.values.len(), |k| {
        let t = table.times.as_ref().map(|t| t[k]);
        t.into_iter()
            .chain(table.values[k].iter().copied())
            .chain(solved.values[k].iter().copied())
    })
}

/// Where pose `k` of the scenario's own trajectory is, for messages.
pub(crate) fn trajectory_place(table: &PoseTable, k: usize) -> String {
    match table.times.as_ref().and_then(|t| t.get(k)) {
        Some(t) => format!("the trajectory at t = {t} s"),
        None => format!("pose {}", k + 1),
    }
}
