//! Poses from a CSV table with columns `x,y,z,roll_deg,pitch_deg,yaw_deg` (metres and degrees),
//! and an optional `t` column (seconds).

use std::io::Read;

use crate::io::table::{NumericTable, TableError};
use crate::model::pose::Pose;
use crate::model::trajectory::keyframes::{Interpolation, Keyframe, Keyframes};
use crate::model::trajectory::{Motion, Sampling, Trajectory};

/// The pose columns, in order, with their units in the names.
pub const POSE_COLUMNS: [&str; 6] = ["x", "y", "z", "roll_deg", "pitch_deg", "yaw_deg"];

/// Poses read from a table, with the line each came from.
#[derive(Clone, Debug, PartialEq)]
pub struct PoseTable {
    /// The `t` column, when the table has one.
    pub times: Option<Vec<f64>>,
    /// The poses, in file order.
    pub poses: Vec<Pose>,
    /// The values as written: `x, y, z` (m), `roll, pitch, yaw` (degrees), in file order.
    pub values: Vec<[f64; 6]>,
    /// File line of each pose, from 1.
    pub lines: Vec<u64>,
}

/// Check a table's pose columns ([`POSE_COLUMNS`]) against the accepted ranges of
/// lengths and angles; the first value outside is an error naming its line.
pub fn check_pose_ranges(table: &NumericTable) -> Result<(), TableError> {
    table.check_ranges(&pose_range_checks())
}

/// Each pose column with its accepted range and unit.
fn pose_range_checks() -> Vec<(&'static str, std::ops::RangeInclusive<f64>, &'static str)> {
    use crate::ground::bounds::{POSE_ROW, POSE_ROW_UNITS, symmetric};
    POSE_COLUMNS
        .iter()
        .enumerate()
        .map(|(k, &name)| (name, symmetric(POSE_ROW[k]), POSE_ROW_UNITS[k]))
        .collect()
}

impl PoseTable {
    /// Read a pose table; `file` names the source in error messages.
    pub fn read(input: impl Read, file: &str) -> Result<Self, TableError> {
        Self::of_table(NumericTable::read(input, file, &POSE_COLUMNS, &["t"])?)
    }

    /// [`PoseTable::read`] of bytes already read (no copy of them is made).
    pub fn read_bytes(bytes: Vec<u8>, file: &str) -> Result<Self, TableError> {
        Self::of_table(NumericTable::read_bytes(
            bytes,
            file,
            &POSE_COLUMNS,
            &["t"],
        )?)
    }

    /// The poses of a table read with [`POSE_COLUMNS`] and `t`, checked.
    fn of_table(table: NumericTable) -> Result<Self, TableError> {
        use crate::ground::bounds::{TIME_S, symmetric};
        use rayon::prelude::*;
        // The pose columns, then `t`, each in one pass on all cores.
        let mut checks = pose_range_checks();
        checks.push(("t", symmetric(TIME_S), "s"));
        table.check_ranges(&checks)?;
        let t_index = table.index("t");
        let width = table.columns.len();
        let values: Vec<[f64; 6]> = table
            .values()
            .par_chunks_exact(width)
            .with_min_len(4096)
            .map(|v| [v[0], v[1], v[2], v[3], v[4], v[5]])
            .collect();
        let poses = values
            .par_iter()
            .with_min_len(4096)
            .map(|v| Pose::from_xyz_rpy_deg([v[0], v[1], v[2]], [v[3], v[4], v[5]]))
            .collect();
        let times = t_index.map(|i| {
            table
                .values()
                .par_chunks_exact(width)
                .with_min_len(4096)
                .map(|r| r[i])
                .collect()
        });
        let lines = table.into_lines();
        Ok(Self {
            times,
            poses,
            values,
            lines,
        })
    }

    /// The table as a keyframed motion; it must have a `t` column with increasing times.
    pub fn to_keyframes(
        &self,
        file: &str,
        interpolation: Interpolation,
    ) -> Result<Keyframes, TableError> {
        let Some(times) = &self.times else {
            return Err(TableError::MissingColumn {
                file: file.to_owned(),
                line: 1,
                column: "t".to_owned(),
                expected: format!("t,{}", POSE_COLUMNS.join(",")),
            });
        };
        for i in 1..times.len() {
            if times[i] <= times[i - 1] {
                return Err(TableError::BadValue {
                    file: file.to_owned(),
                    line: self.lines[i],
                    column: "t".to_owned(),
                    message: format!(
                        "time {} s is not after the previous row's {} s; times must increase",
                        times[i],
                        times[i - 1]
                    ),
                });
            }
        }
        let keys = times
            .iter()
            .zip(&self.poses)
            .map(|(&t, &pose)| Keyframe { t, pose })
            .collect();
        // Times increase and values are finite (checked above and by the reader).
        Keyframes::new(keys, interpolation).map_err(|e| TableError::BadValue {
            file: file.to_owned(),
            // The row of the key named (not the header).
            line: (e.index())
                .and_then(|i| self.lines.get(i - 1).copied())
                .unwrap_or(1),
            column: "t".to_owned(),
            message: e.to_string(),
        })
    }
}

impl PoseTable {
    /// The table as a motion, as `kind = "pose_table"` makes it: the rows joined by straight
    /// lines, sampled at the rows' own times.
    pub fn to_motion(&self, file: &str) -> Result<Motion, TableError> {
        let keyframes = self.to_keyframes(file, Interpolation::Linear)?;
        let sampling = Sampling::at_keys(&keyframes).map_err(|e| TableError::BadValue {
            file: file.to_owned(),
            line: self.lines.first().copied().unwrap_or(1),
            column: "t".to_owned(),
            message: e.to_string(),
        })?;
        Ok(Motion {
            trajectory: Trajectory::Keyframes(keyframes),
            sampling,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_poses_in_degrees_and_builds_keyframes() {
        let text = "t,x,y,z,roll_deg,pitch_deg,yaw_deg\n0,0,0,0.8,0,0,0\n1,0.1,0,0.8,0,0,90\n";
        let table = PoseTable::read(text.as_bytes(), "p.csv").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(table.times, Some(vec![0.0, 1.0]));
        assert_eq!(table.poses[1].yaw.radians(), std::f64::consts::FRAC_PI_2);
        assert_eq!(table.lines, vec![2, 3]);
        let k = table
            .to_keyframes("p.csv", Interpolation::Linear)
            .unwrap_or_else(|e| panic!("{e}"));
        assert!((k.pose_at(0.5).position.x - 0.05).abs() < 1e-15);
    }

    #[test]
    fn a_trajectory_table_needs_increasing_times() {
        let text = "t,x,y,z,roll_deg,pitch_deg,yaw_deg\n0,0,0,0.8,0,0,0\n0,0,0,0.8,0,0,0\n";
        let table = PoseTable::read(text.as_bytes(), "p.csv").unwrap_or_else(|e| panic!("{e}"));
        let e = table
            .to_keyframes("p.csv", Interpolation::Linear)
            .unwrap_err();
        assert_eq!(
            e.to_string(),
            "p.csv, line 3, column `t`: time 0 s is not after the previous row's 0 s; times must increase"
        );
        let text = "x,y,z,roll_deg,pitch_deg,yaw_deg\n0,0,0.8,0,0,0\n";
        let table = PoseTable::read(text.as_bytes(), "p.csv").unwrap_or_else(|e| panic!("{e}"));
        assert!(
            table
                .to_keyframes("p.csv", Interpolation::Linear)
                .unwrap_err()
                .to_string()
                .contains("no `t` column")
        );
    }

    #[test]
    fn a_table_becomes_a_motion_through_every_row_at_its_time() {
        let text = "t,x,y,z,roll_deg,pitch_deg,yaw_deg\n2,0,0,1,0,0,0\n3,0.1,0,1,5,0,0\n5,0,0.2,1.1,0,0,-10\n";
        let table = PoseTable::read(text.as_bytes(), "p.csv").unwrap_or_else(|e| panic!("{e}"));
        let motion = table.to_motion("p.csv").unwrap_or_else(|e| panic!("{e}"));
        let times: Vec<f64> = motion.times().collect();
        // The rows' own times, not three even ones (2, 3.5, 5).
        assert_eq!(times, vec![2.0, 3.0, 5.0]);
        for (t, pose) in [2.0, 3.0, 5.0].iter().zip(&table.poses) {
            let at = motion.trajectory.pose_at(*t);
            assert!((at.position - pose.position).norm() < 1e-12);
            assert!((at.rotation() - pose.rotation()).norm() < 1e-12);
        }
        // Half way between rows 2 and 3 (times 3 and 5): half way between their positions.
        let mid = motion.trajectory.pose_at(4.0).position;
        assert!(
            (mid - nalgebra::Vector3::new(0.05, 0.1, 1.05)).norm() < 1e-12,
            "{mid}"
        );
        let untimed = PoseTable::read(
            "x,y,z,roll_deg,pitch_deg,yaw_deg\n0,0,1,0,0,0\n".as_bytes(),
            "q.csv",
        )
        .unwrap_or_else(|e| panic!("{e}"));
        let e = untimed
            .to_motion("q.csv")
            .map(|_| ())
            .unwrap_err()
            .to_string();
        assert!(e.contains("q.csv") && e.contains("`t`"), "{e}");
    }
}
