//! `stewart solve`: leg lengths as CSV.

use std::fmt::Write as _;
use std::process::ExitCode;

use anyhow::{Context, Result};
use stewart_kinematics::trajectory::{POSE_COLUMNS, PoseTable};
use stewart_kinematics::{Geometry, Pose};

use crate::cli::SolveArgs;
use crate::output;
use crate::source;

/// Run the command.
pub fn run(args: &SolveArgs) -> Result<ExitCode> {
    let scenario = source::load(&args.scenario)?;
    let csv = match &args.poses {
        Some(path) => {
            let table = read_poses(path)?;
            poses_csv(&scenario.geometry, &table)
        }
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
            let printed: Vec<Pose> = values
                .iter()
                .map(|v| Pose::from_xyz_rpy_deg([v[0], v[1], v[2]], [v[3], v[4], v[5]]))
                .collect();
            table_csv(&scenario.geometry, Some(&samples.times), &values, &printed)
        }
    };
    output::emit(args.out.as_deref(), csv.as_bytes())?;
    Ok(ExitCode::SUCCESS)
}

fn read_poses(path: &std::path::Path) -> Result<PoseTable> {
    if path.as_os_str() == "-" {
        return Ok(PoseTable::read(std::io::stdin().lock(), "standard input")?);
    }
    let name = path.display().to_string();
    let file = std::fs::File::open(path).with_context(|| format!("cannot read `{name}`"))?;
    Ok(PoseTable::read(file, &name)?)
}

fn poses_csv(geometry: &Geometry, table: &PoseTable) -> String {
    table_csv(
        geometry,
        table.times.as_deref(),
        &table.values,
        &table.poses,
    )
}

/// The CSV: `[t,]x,y,z,roll_deg,pitch_deg,yaw_deg,L1..L6`, numbers in the shortest form
/// that reads back to the same f64.
fn table_csv(
    geometry: &Geometry,
    times: Option<&[f64]>,
    values: &[[f64; 6]],
    poses: &[Pose],
) -> String {
    let lengths = geometry.leg_lengths_batch(poses);
    let mut out = String::with_capacity(poses.len() * 200 + 100);
    if times.is_some() {
        out.push_str("t,");
    }
    out.push_str(&POSE_COLUMNS.join(","));
    out.push_str(",L1,L2,L3,L4,L5,L6\n");
    for (k, (v, l)) in values.iter().zip(&lengths).enumerate() {
        if let Some(t) = times {
            // Writing to a String cannot fail.
            write_number(&mut out, t[k]);
        }
        for &x in v.iter().chain(l.iter()) {
            write_number(&mut out, x);
        }
        out.pop();
        out.push('\n');
    }
    out
}

/// Append `x` and a comma, in the shortest form that reads back to the same f64: plain
/// decimals for ordinary magnitudes, exponent form for tiny or huge ones.
fn write_number(out: &mut String, x: f64) {
    let a = x.abs();
    // Writing to a String cannot fail.
    let _ = if a == 0.0 || (1e-5..1e16).contains(&a) {
        write!(out, "{x},")
    } else {
        write!(out, "{x:e},")
    };
}

#[cfg(test)]
mod tests {
    use super::write_number;

    #[test]
    fn numbers_are_short_and_read_back_exactly() {
        for x in [
            0.0,
            -0.0,
            1.0,
            0.1,
            1.0 / 3.0,
            -5.878304635907295e-17,
            1e-5,
            9.99e-6,
            1e300,
            123456.789,
            f64::MIN_POSITIVE,
        ] {
            let mut s = String::new();
            write_number(&mut s, x);
            let text = s.trim_end_matches(',');
            assert_eq!(text.parse::<f64>().ok(), Some(x), "{text}");
            assert!(text.len() <= 24, "{text}");
        }
        let mut s = String::new();
        write_number(&mut s, -5.878304635907295e-17);
        assert_eq!(s, "-5.878304635907295e-17,");
    }
}
