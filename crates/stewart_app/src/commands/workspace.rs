//! `stewart workspace`: reachable positions at a fixed orientation, orientation ranges.

use std::fmt::Write as _;
use std::process::ExitCode;

use anyhow::{Result, anyhow};
use nalgebra::Vector3;
use stewart_kinematics::workspace::{Axis, ConstantOrientationWorkspace};
use stewart_kinematics::{Angle, Pose};

use crate::cli::WorkspaceArgs;
use crate::csv_io::CsvText;
use crate::output;
use crate::source;

/// Run the command.
pub fn run(args: &WorkspaceArgs) -> Result<ExitCode> {
    let out = output::destination(args.out.as_deref(), &source::inputs(&args.scenario))?;
    let scenario = source::load(&args.scenario)?;
    let g = &scenario.geometry;
    let orientation = args.orientation.map(Angle::from_degrees);
    let ws = g.constant_orientation_workspace(
        &scenario.limits,
        orientation,
        usize::from(args.resolution),
    )?;
    let [r, p, y] = args.orientation;
    let mut s = String::new();
    // Writing to a String cannot fail.
    let _ = writeln!(
        s,
        "Workspace of `{}` at roll {r}°, pitch {p}°, yaw {y}°:",
        scenario.name
    );
    let n = ws.resolution;
    let method = if scenario.limits.has_pose_limits() {
        format!(
            "stroke intervals exact per column, then sampled every {:.2} mm in z for the cone and clearance limits; error estimate one sample per interval end",
            ws.cell * 1e3
        )
    } else {
        format!(
            "reachable heights exact per column; error bound from the {} × {} grid",
            n / 2,
            n / 2
        )
    };
    let _ = writeln!(
        s,
        "  volume {:.6} m³ ± {:.6} m³ ({n} × {n} columns of {:.2} mm; {method})",
        ws.volume,
        ws.volume_error,
        ws.cell * 1e3
    );
    match ws.extent {
        Some([ex, ey, ez]) => {
            let _ = writeln!(
                s,
                "  extent x {:.4} … {:.4} m, y {:.4} … {:.4} m, z {:.4} … {:.4} m",
                ex[0], ex[1], ey[0], ey[1], ez[0], ez[1]
            );
        }
        None => {
            let _ = writeln!(s, "  no position is reachable at this orientation");
        }
    }
    let position = args.position.unwrap_or([0.0, 0.0, g.home_height()]);
    let pose = Pose::new(
        Vector3::from(position),
        orientation[0],
        orientation[1],
        orientation[2],
    );
    let _ = writeln!(
        s,
        "Orientation range at ({}, {}, {}) m, each angle alone from the orientation above:",
        position[0], position[1], position[2]
    );
    let step = Angle::from_degrees(0.5);
    for (axis, name, span) in [
        (Axis::Roll, "roll", 90.0),
        (Axis::Pitch, "pitch", 90.0),
        (Axis::Yaw, "yaw", 180.0),
    ] {
        let line = match g.orientation_range(
            &scenario.limits,
            &pose,
            axis,
            Angle::from_degrees(span),
            step,
        ) {
            Some([lo, hi]) => format!("{:.3}° … {:.3}°", lo.degrees(), hi.degrees()),
            None => "the position is not reachable at this orientation".to_owned(),
        };
        let _ = writeln!(s, "  {name:<5} {line}");
    }
    if let Some(out) = &out {
        let path = out.shown();
        let text = points_file(path, &ws)?;
        out.write_bytes(text.as_bytes())?;
        let _ = writeln!(
            s,
            "Wrote {} boundary points to {}.",
            2 * ws.spans.len(),
            path.display()
        );
    }
    output::stdout(s.as_bytes())?;
    Ok(ExitCode::SUCCESS)
}

/// The boundary points (bottom and top of every reachable span) as CSV or PLY.
fn points_file(path: &std::path::Path, ws: &ConstantOrientationWorkspace) -> Result<String> {
    let points = ws
        .spans
        .iter()
        .flat_map(|s| [[s[0], s[1], s[2]], [s[0], s[1], s[3]]]);
    match path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .as_deref()
    {
        Some("csv") => {
            let mut csv = CsvText::with_header(&["x", "y", "z"]);
            for p in points {
                csv.row(p);
            }
            Ok(csv.into_string())
        }
        Some("ply") => {
            let mut s = format!(
                "ply\nformat ascii 1.0\ncomment Stewart platform workspace boundary, metres\nelement vertex {}\nproperty double x\nproperty double y\nproperty double z\nend_header\n",
                2 * ws.spans.len()
            );
            for [x, y, z] in points {
                // Writing to a String cannot fail.
                let _ = writeln!(s, "{x} {y} {z}");
            }
            Ok(s)
        }
        _ => Err(anyhow!(
            "`{}`: the points file must end in .csv or .ply",
            path.display()
        )),
    }
}
