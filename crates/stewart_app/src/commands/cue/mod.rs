//! `stewart cue`: platform poses from vehicle motion by classical washout (the scenario's
//! `[cueing]` table), as a pose table that `solve --poses`, `check` and `link` take. The
//! motion is a CSV recording or a packet capture of a game's telemetry (told apart by the
//! file's first bytes). `--compare` runs both algorithms and reports how each reproduces
//! what is felt ([`comparison`]); `--omct` runs the Objective Motion Cueing Test instead
//! ([`omct`]).

mod comparison;
mod omct;

use std::fmt::Write as _;
use std::io::Write as _;
use std::process::ExitCode;

use anyhow::{Result, anyhow};
use stewart_kinematics::analysis::checks::{FindingKind, check_motion};
use stewart_kinematics::analysis::cueing::compare::compare;
use stewart_kinematics::analysis::cueing::{CueError, VehicleMotion, cue_recording};
use stewart_kinematics::model::actuator::ActuatorKind;
use stewart_kinematics::model::trajectory::Samples;
use stewart_kinematics::{Pose, Scenario};

use crate::cli::{CueArgs, ReportFormat};
use crate::csv_io::{CsvText, read_input_bytes};
use crate::output;
use crate::source;
use crate::vehicle_in::capture::{self, CapturedMotion};
use crate::vehicle_in::table::{self, VehicleTable};

/// The pose table's columns.
const POSE_COLUMNS: [&str; 7] = ["t", "x", "y", "z", "roll_deg", "pitch_deg", "yaw_deg"];

/// Run the command.
pub(crate) fn run(args: &CueArgs) -> Result<ExitCode> {
    let scenario = source::load(&args.scenario)?;
    if args.omct {
        return omct::run(args, &scenario);
    }
    for (given, option) in [
        (args.amplitude_scale.is_some(), "--amplitude-scale"),
        (args.frequencies.is_some(), "--frequencies"),
        (args.latency_ms.is_some(), "--latency-ms"),
        (args.plot.is_some(), "--plot"),
    ] {
        if given {
            anyhow::bail!("{option} belongs to the motion cueing test: add --omct");
        }
    }
    if args.format == ReportFormat::Json && !args.compare {
        anyhow::bail!("--format json is the report of --compare or --omct; the poses are a CSV");
    }
    let input = args
        .input
        .clone()
        .ok_or_else(|| anyhow!("--input names the vehicle motion (or --omct tests the cueing)"))?;
    let mut inputs = source::inputs(&args.scenario, &scenario);
    inputs.push(("the vehicle motion", input.clone()));
    let out = output::destination(args.out.as_deref(), &inputs)?;
    let (bytes, file) = read_input_bytes(&input, stewart_kinematics::io::file::FileKind::Table)?;
    let recording = if capture::is_capture(&bytes) {
        Recording::Capture(Box::new(capture::read(
            &bytes,
            &file,
            args.port,
            scenario.cueing.stall_s,
        )?))
    } else {
        Recording::Table(table::read(&mut bytes.as_slice(), &file)?)
    };
    let samples = recording.samples();
    let place = |e: CueError| match e {
        CueError::Time { index, .. } => anyhow!("{file}, {}: {e}", recording.place(index, "t")),
        CueError::PoseOutside { index, .. } => {
            anyhow!("{file}, {}: {e}", recording.place(index, ""))
        }
        CueError::TooShort { .. } | CueError::OneSample { .. } | CueError::TimesTooFine { .. } => {
            anyhow!("{file}: {e}")
        }
        other => anyhow!("{}: {other}", source::describe(&args.scenario)),
    };
    if args.compare {
        let both = compare(
            &scenario.geometry,
            &scenario.limits,
            &scenario.checks,
            &scenario.cueing,
            samples,
        )
        .map_err(place)?;
        let measures = both.map(|(m, _)| m);
        let text = match args.format {
            ReportFormat::Text => comparison::table(&measures),
            ReportFormat::Json => comparison::json(&measures, &file),
        };
        output::emit_with(out.as_ref(), |w| w.write_all(text.as_bytes()))?;
        return Ok(ExitCode::SUCCESS);
    }
    let cued = cue_recording(
        &scenario.geometry,
        &scenario.limits,
        &scenario.checks,
        &scenario.cueing,
        samples,
    )
    .map_err(place)?;
    let text = pose_table(samples, &cued.poses);
    output::emit_with(out.as_ref(), |w| w.write_all(text.as_bytes()))?;
    let mut said = summary(samples, &cued.scales);
    if let Some(p) = cued
        .planner
        .filter(|p| p.guarded + p.guard_stops + p.guard_jumps_left > 0)
    {
        said.push_str(&guard_note(&p, cued.poses.len()));
    }
    if let Some(p) = cued.planner.filter(|p| p.stops > 0) {
        said.push_str(&held_note(samples, &cued.poses, p.stops));
    }
    said.push_str(&output_notes(
        &scenario,
        samples,
        &cued.poses,
        cued.planner.is_some(),
    ));
    if let Recording::Capture(c) = &recording {
        said.push_str(&format!("cue: read from {file}: {}\n", c.contents()));
    }
    let _ = std::io::stderr().write_all(said.as_bytes());
    Ok(ExitCode::SUCCESS)
}

/// The cued poses as a pose table, each at its sample's time.
fn pose_table(samples: &[(f64, VehicleMotion)], poses: &[Pose]) -> String {
    let mut csv = CsvText::with_header(&POSE_COLUMNS);
    for ((t, _), pose) in samples.iter().zip(poses) {
        csv.row(std::iter::once(*t).chain(pose.to_row()));
    }
    csv.into_string()
}

/// What the actuator guard did, in one sentence, of `poses` poses.
fn guard_note(p: &stewart_kinematics::analysis::cueing::mpc::MpcCounts, poses: usize) -> String {
    format!(
        "cue: the actuator guard changed {} of {} poses to keep the actuators' range, speed and acceleration, the joint cones, the clearances and the condition number as `check` judges them (where the plan broke one, and on the way back to it){}{}{}\n",
        p.guarded + p.guard_stops,
        poses,
        match p.guard_rewinds {
            0 => String::new(),
            n => format!("; it went back {n} times to brake earlier"),
        },
        match p.guard_stops {
            0 => String::new(),
            n => format!(
                "; at {n} of them no pose near the plan kept every limit and the last pose was given again"
            ),
        },
        match p.guard_jumps_left {
            0 => String::new(),
            n => format!("; {n} steps would still read as jumps to `check` (run it on the output)"),
        }
    )
}

/// The planner held the last good pose `stops` times (its plan gave a pose the exact
/// check refused): said, with the longest stretch the platform stands still.
fn held_note(samples: &[(f64, VehicleMotion)], poses: &[Pose], stops: u64) -> String {
    let (mut longest, mut from) = (0.0, 0.0);
    let mut start = 0;
    for k in 1..=poses.len() {
        if k == poses.len() || poses[k] != poses[k - 1] {
            let still = samples[k - 1].0 - samples[start].0;
            if still > longest {
                (longest, from) = (still, samples[start].0);
            }
            start = k;
        }
    }
    let stretch = if longest > 0.0 {
        format!(
            "; the platform stands still for {longest:.2} s at most, from t = {} s",
            crate::i18n::words::time_text(from)
        )
    } else {
        String::new()
    };
    format!(
        "cue: at {stops} poses the planner's plan broke a limit it could not see and the platform held the last good pose{stretch}\n"
    )
}

/// What `check` of the output finds that the cue did not keep, said: cueing keeps no jerk
/// limit (see [`cue_recording`]), so with one set, the samples where the cue breaks it;
/// and, after the model-predictive planner (`planned`), whatever else its guard could not
/// keep (none is known: a safety net), besides the jumps it counts itself and the seed's
/// singular layout. Empty when there is nothing to say.
fn output_notes(
    scenario: &Scenario,
    samples: &[(f64, VehicleMotion)],
    poses: &[Pose],
    planned: bool,
) -> String {
    let limits = &scenario.limits;
    let jerk_key = match scenario.geometry.actuator().kind() {
        ActuatorKind::Linear if limits.leg_jerk_max.is_some() => Some("limits.leg_jerk_max_m_s3"),
        ActuatorKind::Rotary if limits.servo_jerk_max.is_some() => {
            Some("limits.servo_jerk_max_deg_s3")
        }
        _ => None,
    };
    if jerk_key.is_none() && !planned {
        return String::new();
    }
    let cued = Samples {
        times: samples.iter().map(|(t, _)| *t).collect(),
        poses: poses.to_vec(),
    };
    let report = check_motion(&scenario.geometry, limits, &cued, &scenario.checks);
    let jerk = |f: &&stewart_kinematics::analysis::checks::Finding| {
        matches!(f.kind, FindingKind::LegJerk | FindingKind::ServoJerk)
    };
    let mut said = String::new();
    let over: usize = report.findings.iter().filter(jerk).map(|f| f.count).sum();
    if let Some(key) = jerk_key
        && over > 0
    {
        said.push_str(&format!(
            "cue: cueing does not limit jerk: an actuator's jerk is above `{key}` at {over} actuator samples (summed over the six; `check` of the output lists them)\n"
        ));
    }
    let unkept: Vec<_> = (report.findings.iter())
        .filter(|f| {
            !jerk(f)
                && !matches!(
                    f.kind,
                    FindingKind::Jump | FindingKind::ServoJump | FindingKind::ArchitectureSingular
                )
        })
        .collect();
    if planned && let Some(first) = unkept.first() {
        said.push_str(&format!(
            "cue: the guard could not keep every limit: `check` of the output finds {} problem(s), the first: {}\n",
            unkept.len(),
            crate::i18n::words::finding(crate::i18n::Lang::En, first)
        ));
    }
    said
}

/// The vehicle motion read: a CSV table or a packet capture.
enum Recording {
    Table(VehicleTable),
    Capture(Box<CapturedMotion>),
}

impl Recording {
    /// Time and motion of each sample.
    fn samples(&self) -> &[(f64, VehicleMotion)] {
        match self {
            Recording::Table(t) => &t.samples,
            Recording::Capture(c) => &c.samples,
        }
    }

    /// Where sample `index` came from: the table's line (and `column`, when one is
    /// named), or the capture's packet.
    fn place(&self, index: usize, column: &str) -> String {
        match self {
            Recording::Table(t) if column.is_empty() => format!("line {}", t.table.line(index)),
            Recording::Table(t) => format!("line {}, column `{column}`", t.table.line(index)),
            Recording::Capture(c) => {
                let packet = c.packets.get(index).copied().unwrap_or_default();
                format!("packet {packet}")
            }
        }
    }
}

/// One line on what was cued, and how much the limiter held back.
fn summary(samples: &[(f64, VehicleMotion)], scales: &[f64]) -> String {
    let span = samples.last().map_or(0.0, |l| l.0) - samples.first().map_or(0.0, |f| f.0);
    let mut s = format!(
        "cue: {} poses over {} s",
        samples.len(),
        crate::i18n::words::time_text(span)
    );
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn what_check_finds_in_a_planned_output_is_said_with_its_first_finding() {
        // The guard keeps every limit on every rig and input known; should an output still
        // break one, the cue says so, naming what `check` names first. A platform that
        // rises 10 cm in 10 ms breaks the paired rig's leg speed (0.5 m/s).
        let scenario = Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
        let home = scenario.geometry.home_pose();
        let risen = home.with_position(home.position + nalgebra::Vector3::new(0.0, 0.0, 0.1));
        let samples: Vec<(f64, VehicleMotion)> = (0..20)
            .map(|k| (f64::from(k) * 0.01, VehicleMotion::default()))
            .collect();
        let poses: Vec<Pose> = (0..20).map(|k| if k < 10 { home } else { risen }).collect();
        let said = output_notes(&scenario, &samples, &poses, true);
        assert!(
            said.starts_with("cue: the guard could not keep every limit"),
            "{said}"
        );
        assert!(said.contains("moves faster than 0.5 m/s"), "{said}");
        // Without the planner (and no jerk limit) `check` is the user's to run.
        assert_eq!(output_notes(&scenario, &samples, &poses, false), "");
        // A motion within the limits: nothing to say.
        let still = vec![home; 20];
        assert_eq!(output_notes(&scenario, &samples, &still, true), "");
    }

    #[test]
    fn a_recording_shorter_than_a_millisecond_is_told_its_length() {
        // 299 samples 1 µs apart once read "over 0.000 s".
        let samples: Vec<(f64, VehicleMotion)> = (0..299)
            .map(|k| (f64::from(k) * 1e-6, VehicleMotion::default()))
            .collect();
        let said = summary(&samples, &[1.0; 299]);
        assert!(said.starts_with("cue: 299 poses over 0.000298 s"), "{said}");
    }
}
