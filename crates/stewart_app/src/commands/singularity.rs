//! `stewart singularity`: how near a pose is to singularity (sampled: the conditioning
//! there), and with `--certify --free COORDINATE` the widest range about it proven free of
//! singularity by interval arithmetic.

use std::process::ExitCode;

use anyhow::Result;
use serde::Serialize;
use stewart_kinematics::Pose;
use stewart_kinematics::analysis::certified::free::{Search, free_ball, free_range};

use crate::cli::{FreeCoordinate, ReportFormat, SingularityArgs};
use crate::commands::design::pose_words;
use crate::output;
use crate::source;

/// The JSON document of a certification.
#[derive(Serialize)]
struct Certified<'a> {
    scenario: &'a str,
    /// The pose: x, y, z (m), roll, pitch, yaw (°).
    pose: [f64; 6],
    free: &'static str,
    /// The freed coordinate's index in `pose`.
    #[serde(skip)]
    index: usize,
    /// `deg` or `m`.
    unit: &'static str,
    /// The proven range (a coordinate), or null.
    #[serde(skip_serializing_if = "Option::is_none")]
    interval: Option<Option<[f64; 2]>>,
    /// The proven ball's radius (the position), or null.
    #[serde(skip_serializing_if = "Option::is_none")]
    radius_m: Option<Option<f64>>,
    /// How far the search looked on each side (the same unit).
    reach: f64,
    boxes: usize,
    /// Whether the box budget or Ctrl-C ended it before its tolerance.
    cut_short: bool,
}

/// Run the command.
pub(crate) fn run(args: &SingularityArgs) -> Result<ExitCode> {
    let scenario = source::load(&args.scenario)?;
    let g = &scenario.geometry;
    let pose = args
        .pose
        .map_or_else(|| g.home_pose(), |p| Pose::from_row(&p));
    let row = pose.to_row();
    let Some(free) = args.free.filter(|_| args.certify) else {
        return conditioning(&scenario, &pose, args.format);
    };
    crate::interrupt::flag();
    let stop = crate::interrupt::requested;
    let search = Search {
        budget: usize::try_from(args.budget).unwrap_or(usize::MAX),
        stop: &stop,
    };
    let size = g.characteristic_length();
    let mut doc = Certified {
        scenario: &scenario.name,
        pose: row,
        free: name_of(free),
        index: index(free),
        unit: "m",
        interval: None,
        radius_m: None,
        reach: 2.0 * size,
        boxes: 0,
        cut_short: false,
    };
    let found = match free {
        FreeCoordinate::Position => {
            let ball = free_ball(g, &pose, doc.reach, search);
            doc.radius_m = Some(ball.radius);
            doc.boxes = ball.boxes;
            doc.cut_short = ball.cut_short;
            ball.radius.is_some()
        }
        _ => {
            let k = doc.index;
            let angle = k >= 3;
            let reach = if angle {
                std::f64::consts::PI
            } else {
                doc.reach
            };
            let range = free_range(g, &pose, k, reach, search);
            let shown = |v: f64| if angle { v.to_degrees() } else { v };
            doc.unit = if angle { "deg" } else { "m" };
            doc.reach = shown(reach);
            doc.interval = Some(range.interval.map(|r| r.map(shown)));
            doc.boxes = range.boxes;
            doc.cut_short = range.cut_short;
            range.interval.is_some()
        }
    };
    let text = match args.format {
        ReportFormat::Json => serde_json::to_string_pretty(&doc)? + "\n",
        ReportFormat::Text => words(&doc, &pose_words(&row)),
    };
    output::stdout(text.as_bytes())?;
    Ok(if found {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// The pose coordinate's index: x, y, z, roll, pitch, yaw.
fn index(free: FreeCoordinate) -> usize {
    match free {
        FreeCoordinate::X => 0,
        FreeCoordinate::Y => 1,
        FreeCoordinate::Z => 2,
        FreeCoordinate::Roll => 3,
        FreeCoordinate::Pitch => 4,
        FreeCoordinate::Yaw | FreeCoordinate::Position => 5,
    }
}

/// The coordinate's name as the option spells it.
fn name_of(free: FreeCoordinate) -> &'static str {
    match free {
        FreeCoordinate::X => "x",
        FreeCoordinate::Y => "y",
        FreeCoordinate::Z => "z",
        FreeCoordinate::Roll => "roll",
        FreeCoordinate::Pitch => "pitch",
        FreeCoordinate::Yaw => "yaw",
        FreeCoordinate::Position => "position",
    }
}

/// The certification in sentences.
fn words(doc: &Certified, at: &str) -> String {
    let name = doc.free;
    let unit = if doc.unit == "deg" { "°" } else { " m" };
    let mut text = match (doc.interval, doc.radius_m) {
        (Some(Some([lo, hi])), _) => {
            let mut t = format!(
                "Proven free of singularity: {name} from {lo:.6}{unit} to {hi:.6}{unit} about {at} \
                 (the other coordinates held; {} boxes, each proven by interval arithmetic).\n",
                doc.boxes
            );
            for (end, side) in [(lo, "lower"), (hi, "upper")] {
                let pose_value = doc.pose[doc.index];
                if ((end - pose_value).abs() - doc.reach).abs() < 1e-9 * doc.reach.max(1.0) {
                    t.push_str(&format!(
                        "The {side} end is the search's reach (±{:.6}{unit}): the free range may go on.\n",
                        doc.reach
                    ));
                }
            }
            t
        }
        (_, Some(Some(r))) => format!(
            "Proven free of singularity: every position within {r:.6} m of {at} at its orientation \
             ({} boxes, each proven by interval arithmetic).\n",
            doc.boxes
        ),
        _ => format!(
            "Nothing proven free of singularity at {at}: the pose itself cannot be proven regular \
             (a singular pose, or one so near that no box about it passes).\n"
        ),
    };
    if doc.cut_short {
        text.push_str(
            "The search stopped early (its box budget, --budget, or Ctrl-C): this is what was proven so far.\n",
        );
    }
    text
}

/// The sampled answer: the conditioning at the pose.
fn conditioning(
    scenario: &stewart_kinematics::Scenario,
    pose: &Pose,
    format: ReportFormat,
) -> Result<ExitCode> {
    let c = scenario.geometry.conditioning(pose);
    let text = match format {
        ReportFormat::Json => serde_json::to_string_pretty(&c)? + "\n",
        ReportFormat::Text => {
            let values: Vec<String> = c
                .singular_values
                .iter()
                .map(|v| format!("{v:.6}"))
                .collect();
            format!(
                "At {}: condition number {} (the normalised Jacobian's; singular values {}). \
                 This is one pose; `--certify --free COORDINATE` proves a range about it.\n",
                pose_words(&pose.to_row()),
                c.condition_number
                    .map_or_else(|| "none: singular".to_owned(), |n| format!("{n:.3}")),
                values.join(", ")
            )
        }
    };
    output::stdout(text.as_bytes())?;
    Ok(ExitCode::SUCCESS)
}
