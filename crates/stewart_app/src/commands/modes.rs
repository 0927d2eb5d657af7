//! `stewart modes`: the Cartesian stiffness, the mass matrix and the natural modes at a
//! pose, from the scenario's `[payload]` and `[dynamics]`; text for people, JSON for
//! programs.

use std::fmt::Write as _;
use std::process::ExitCode;
use stewart_kinematics::analysis::dynamics;

use anyhow::{Result, anyhow};
use nalgebra::{Matrix6, Vector6};
use serde::Serialize;
use stewart_kinematics::analysis::dynamics::{
    AXES, LowestMode, Modes, dominant, lowest_mode_along,
};
use stewart_kinematics::model::trajectory::Samples;
use stewart_kinematics::{Pose, Scenario};

use crate::cli::{ModesArgs, ReportFormat};
use crate::commands::design::pose_words;
use crate::long_work::{self, PROBE_SAMPLES};
use crate::output;
use crate::source;

/// A pose as JSON.
#[derive(Serialize)]
struct JsonPose {
    x: f64,
    y: f64,
    z: f64,
    roll_deg: f64,
    pitch_deg: f64,
    yaw_deg: f64,
}

impl JsonPose {
    fn of(p: &[f64; 6]) -> Self {
        Self {
            x: p[0],
            y: p[1],
            z: p[2],
            roll_deg: p[3],
            pitch_deg: p[4],
            yaw_deg: p[5],
        }
    }
}

/// Where the lowest frequency over the motion occurs, as JSON.
#[derive(Serialize)]
struct JsonLowest {
    time_s: f64,
    pose: JsonPose,
    frequency_hz: f64,
    mode: [f64; 6],
}

/// The JSON document.
#[derive(Serialize)]
struct JsonReport<'a> {
    scenario: &'a str,
    pose: JsonPose,
    /// Rows and columns of both matrices and the components of the modes.
    axes: [&'static str; 6],
    reference: &'static str,
    stiffness: [[f64; 6]; 6],
    mass_matrix: [[f64; 6]; 6],
    frequencies_hz: [f64; 6],
    modes: [[f64; 6]; 6],
    #[serde(skip_serializing_if = "Option::is_none")]
    lowest_along_trajectory: Option<JsonLowest>,
}

fn rows(m: &Matrix6<f64>) -> [[f64; 6]; 6] {
    std::array::from_fn(|i| std::array::from_fn(|j| m[(i, j)]))
}

fn components(v: &Vector6<f64>) -> [f64; 6] {
    std::array::from_fn(|i| v[i])
}

/// Run the command.
pub(crate) fn run(args: &ModesArgs) -> Result<ExitCode> {
    let scenario = source::load(&args.scenario)?;
    let g = &scenario.geometry;
    let payload = scenario.payload.ok_or_else(|| {
        anyhow!(
            "scenario `{}` has no [payload] table: the modes need the moving mass and its inertia (mass_kg, com_m, inertia_kg_m2)",
            scenario.name
        )
    })?;
    let pose = args
        .pose
        .map_or_else(|| g.home_pose(), |p| Pose::from_row(&p));
    let at = pose_words(&pose.to_row());
    let modes = dynamics::modes(g, &pose, &payload, &scenario.dynamics)
        .map_err(|e| anyhow!("at {at}: {e}"))?;
    let lowest = if args.along_trajectory {
        let samples = scenario.motion.sample();
        // The modes cost microseconds a sample: a long motion says so before it starts.
        long_work::over_samples(
            &format!("modes: {} samples along the trajectory", samples.len()),
            &samples,
            PROBE_SAMPLES / 10,
            |samples: &Samples| lowest_mode_along(g, samples, &payload, &scenario.dynamics),
        )
        .map_err(|(t, e)| anyhow!("along the trajectory at t = {t} s: {e}"))?
    } else {
        None
    };
    let text = match args.format {
        ReportFormat::Text => text(&scenario, &at, &modes, lowest.as_ref()),
        ReportFormat::Json => {
            let json = JsonReport {
                scenario: &scenario.name,
                pose: JsonPose::of(&pose.to_row()),
                axes: AXES,
                reference: "the platform frame's origin, base-frame axes; SI units",
                stiffness: rows(&modes.stiffness),
                mass_matrix: rows(&modes.mass_matrix),
                frequencies_hz: modes.frequencies_hz,
                modes: modes.modes.map(|v| components(&v)),
                lowest_along_trajectory: lowest.as_ref().map(|l| JsonLowest {
                    time_s: l.time,
                    pose: JsonPose::of(&l.pose.to_row()),
                    frequency_hz: l.frequency_hz,
                    mode: components(&l.mode),
                }),
            };
            serde_json::to_string_pretty(&json)? + "\n"
        }
    };
    output::stdout(text.as_bytes())?;
    Ok(ExitCode::SUCCESS)
}

/// A mode's motion in words: its largest components, `rz 0.98, x −0.20`.
fn motion_words(v: &Vector6<f64>) -> String {
    dominant(v)
        .iter()
        .map(|(axis, c)| format!("{axis} {c:+.2}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The report in words.
fn text(scenario: &Scenario, at: &str, modes: &Modes, lowest: Option<&LowestMode>) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "Natural modes of `{}` at {at} (about the platform frame's origin; mode vectors in m and rad):",
        scenario.name
    );
    for (k, f) in modes.frequencies_hz.iter().enumerate() {
        let _ = writeln!(
            out,
            "  mode {}: {:>10} Hz   {}",
            k + 1,
            hz(*f),
            motion_words(&modes.modes[k])
        );
    }
    let lost = (0..6).filter(|&k| modes.without_stiffness(k)).count();
    if lost > 0 {
        let _ = writeln!(
            out,
            "The pose is singular: {lost} direction(s) have no stiffness there (frequency 0)."
        );
    }
    if let Some(l) = lowest {
        let _ = writeln!(
            out,
            "Lowest over the trajectory: {} Hz at t = {} s ({}), {}",
            hz(l.frequency_hz),
            l.time,
            pose_words(&l.pose.to_row()),
            motion_words(&l.mode)
        );
    }
    out
}

/// A frequency for reading: three decimals, or in scientific notation from 10 MHz on
/// (where the decimals of an absurdly light payload's mode ran to a hundred digits).
fn hz(f: f64) -> String {
    if f < 1e7 {
        format!("{f:.3}")
    } else {
        format!("{f:.3e}")
    }
}
