//! The trajectory as a CSV of poses and leg lengths (what `solve` prints and the viewer
//! exports).

use stewart_kinematics::trajectory::{POSE_COLUMNS, PoseTable};
use stewart_kinematics::{Geometry, Pose, Scenario};

use std::io::Write;

use crate::csv_io::write_table;

/// The sampled trajectory as a pose table. Angles are rounded through degrees as printed,
/// and the legs are solved for those printed poses, so that every row is a consistent
/// record that `solve --poses` reproduces bit for bit.
pub fn trajectory_table(scenario: &Scenario) -> PoseTable {
    let samples = scenario.motion.sample();
    let values: Vec<[f64; 6]> = samples
        .poses
        .iter()
        .map(|p| {
            let [r, pi, y] = p.rpy_degrees();
            [p.position.x, p.position.y, p.position.z, r, pi, y]
        })
        .collect();
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

/// Write `[t,]x,y,z,roll_deg,pitch_deg,yaw_deg,L1..L6` to `out`, row by row.
pub fn write_legs_csv(
    out: &mut dyn Write,
    geometry: &Geometry,
    table: &PoseTable,
) -> std::io::Result<()> {
    let lengths = geometry.leg_lengths_batch(&table.poses);
    let mut header: Vec<&str> = Vec::new();
    if table.times.is_some() {
        header.push("t");
    }
    header.extend(POSE_COLUMNS);
    header.extend(["L1", "L2", "L3", "L4", "L5", "L6"]);
    write_table(out, &header, table.values.len(), |k| {
        let t = table.times.as_ref().map(|t| t[k]);
        t.into_iter()
            .chain(table.values[k].iter().copied())
            .chain(lengths[k].iter().copied())
    })
}
