//! Checks over a whole sampled motion — the pre-flight report. Every finding is located
//! in leg(s) and time, with its worst value and margin.
//!
//! - [`rigid`]: the platform joints keep their mutual distances (the seed's self-consistency test);
//! - [`stroke`]: every leg stays within its stroke;
//! - [`rates`]: leg speed, acceleration and jerk limits;
//! - [`cones`]: the angle of each leg at its joints;
//! - [`collision`]: the distance between legs seen as cylinders;
//! - [`singularity`]: near-singular poses and architecture singularity;
//! - [`jumps`]: no leg length jumps between two samples;
//! - [`servos`]: for rotary platforms, reach, servo range and rates, the rods' joint
//!   angles, rod and horn clearance, and servo-angle jumps (instead of the leg checks).

pub mod collision;
pub mod cones;
pub mod document;
pub mod jumps;
pub mod rates;
pub mod rigid;
mod scan;
pub mod servos;
pub mod singularity;
pub mod stroke;
#[cfg(test)]
mod tests;

use serde::{Deserialize, Serialize};

use crate::analysis::architecture;
use crate::analysis::architecture::ArchitectureReport;
use crate::model::geometry::Geometry;
use crate::model::limits::Limits;
use crate::model::trajectory::Samples;

/// Thresholds of the checks. The defaults suit motions sampled at tens to thousands of hertz.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct CheckSettings {
    /// Largest change of a platform-joint distance accepted as rounding, metres.
    pub rigid_tolerance: f64,
    /// A step counts as a jump when it is this many times the typical neighbouring step …
    pub jump_ratio: f64,
    /// … and larger than this, metres (steps below it are never jumps).
    pub jump_floor: f64,
    /// A pose whose normalised condition number exceeds this is near-singular.
    pub condition_max: f64,
}

impl Default for CheckSettings {
    fn default() -> Self {
        Self {
            rigid_tolerance: 1e-9,
            jump_ratio: 5.0,
            jump_floor: 1e-4,
            condition_max: 30.0,
        }
    }
}

/// What a finding (or a limit summary) is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FindingKind {
    /// A leg longer than its maximum length.
    StrokeMax,
    /// A leg shorter than its minimum length.
    StrokeMin,
    /// A leg faster than the actuator's speed limit.
    LegSpeed,
    /// A leg accelerating beyond the actuator's limit.
    LegAccel,
    /// A leg whose acceleration changes faster than the actuator's jerk limit.
    LegJerk,
    /// A leg leaning beyond the base joint's cone.
    BaseCone,
    /// A leg leaning beyond the platform joint's cone.
    PlatformCone,
    /// Two legs closer than twice the leg radius.
    LegCollision,
    /// A pose whose normalised condition number exceeds the threshold (or is singular).
    NearSingular,
    /// The geometry is singular at every pose.
    ArchitectureSingular,
    /// A leg length changing abruptly between two samples.
    Jump,
    /// Platform joints whose mutual distances changed: the platform was not moved rigidly.
    RigidBody,
    /// A servo whose horn cannot reach its platform joint (rotary platforms).
    Unreachable,
    /// A servo past the top of its range.
    ServoMax,
    /// A servo past the bottom of its range.
    ServoMin,
    /// A servo turning faster than its speed limit.
    ServoSpeed,
    /// A servo accelerating beyond its limit.
    ServoAccel,
    /// A servo whose acceleration changes faster than its jerk limit.
    ServoJerk,
    /// A rod leaning beyond the cone of its ball joint on the horn (from the base normal).
    HornCone,
    /// A rod leaning beyond the cone of its platform joint.
    RodPlatformCone,
    /// Two rods closer than twice the rod radius.
    RodCollision,
    /// A rod closer than twice the radius to another servo's horn.
    RodHornCollision,
    /// A servo angle changing abruptly between two samples.
    ServoJump,
}

/// One problem, located: which leg(s), from when to when, how bad.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Finding {
    /// What kind of problem.
    pub kind: FindingKind,
    /// Leg numbers from 1 (one leg, two for a collision, none for whole-platform findings).
    pub legs: Vec<usize>,
    /// Time of the first sample concerned, seconds.
    pub first_time: f64,
    /// Time of the last sample concerned, seconds.
    pub last_time: f64,
    /// Number of samples (or sample steps, for jumps) concerned.
    pub count: usize,
    /// Time of the worst sample, seconds.
    pub worst_time: f64,
    /// The worst value, in `unit`.
    pub worst_value: f64,
    /// The limit that was passed, in `unit`.
    pub limit: f64,
    /// How far inside the limit the worst value is, in `unit`: negative for a violation.
    pub margin: f64,
    /// Unit of `worst_value`, `limit` and `margin`: `m`, `m/s`, `m/s²`, `deg` or `` (a ratio).
    pub unit: String,
}

/// For one limit, the worst value over the whole motion and its margin, violated or not.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LimitSummary {
    /// Which limit.
    pub kind: FindingKind,
    /// Leg(s) where the worst value occurs.
    pub legs: Vec<usize>,
    /// The worst value, in `unit`.
    pub worst_value: f64,
    /// When it occurs, seconds.
    pub worst_time: f64,
    /// The limit, in `unit`.
    pub limit: f64,
    /// How far inside the limit the worst value is (negative: violated), in `unit`.
    pub margin: f64,
    /// Unit of the values.
    pub unit: String,
}

/// The outcome of every check over a motion.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CheckReport {
    /// Number of samples checked.
    pub samples: usize,
    /// Time of the first and last sample, seconds.
    pub time_span: [f64; 2],
    /// Shortest and longest length of each leg over the motion, metres (for a rotary
    /// platform: the distance from each servo's shaft centre to its platform joint).
    pub leg_ranges: [[f64; 2]; 6],
    /// For a rotary platform, the smallest and largest model angle of each servo over the
    /// samples it reaches, degrees (NaN, written `null`, for a servo that reaches none).
    #[serde(skip_serializing_if = "Option::is_none", default)]
    pub servo_ranges_deg: Option<[[f64; 2]; 6]>,
    /// Largest change of any platform-joint distance seen, metres (rounding only, if all is well).
    pub rigid_worst_deviation: f64,
    /// Every limit that applies, with its worst value and margin.
    pub limits: Vec<LimitSummary>,
    /// Whether the geometry is singular everywhere, and why.
    pub architecture: ArchitectureReport,
    /// The problems found.
    pub findings: Vec<Finding>,
}

impl CheckReport {
    /// Whether nothing was found.
    pub fn is_clean(&self) -> bool {
        self.findings.is_empty()
    }
}

/// Run every check over `samples` for `geometry` under `limits`.
pub fn check_motion(
    geometry: &Geometry,
    limits: &Limits,
    samples: &Samples,
    settings: &CheckSettings,
) -> CheckReport {
    let times = &samples.times;
    let solutions: Vec<_> = samples.poses.iter().map(|p| geometry.inverse(p)).collect();
    let lengths: Vec<[f64; 6]> = solutions.iter().map(|s| s.lengths).collect();
    let mut leg_ranges = [[f64::INFINITY, f64::NEG_INFINITY]; 6];
    for l in &lengths {
        for (range, &value) in leg_ranges.iter_mut().zip(l) {
            range[0] = range[0].min(value);
            range[1] = range[1].max(value);
        }
    }
    let mut out = scan::Collected::default();
    let (rigid_worst_deviation, rigid) =
        rigid::check(geometry, times, &solutions, settings.rigid_tolerance);
    out.findings.extend(rigid);
    let servo_ranges_deg = match geometry.rotary() {
        None => {
            stroke::check(&geometry.stroke(), times, &lengths, &mut out);
            rates::check(limits, times, &lengths, &mut out);
            cones::check(limits, times, &samples.poses, &solutions, &mut out);
            collision::check(limits, times, &solutions, &mut out);
            None
        }
        Some(servos) => {
            let motion = servos::ServoMotion::solve(geometry, servos, &solutions);
            servos::check(
                geometry,
                servos,
                limits,
                settings,
                times,
                &samples.poses,
                &solutions,
                &motion,
                &mut out,
            );
            Some(motion.ranges())
        }
    };
    let architecture = architecture::architecture(geometry);
    singularity::check(
        geometry,
        &architecture,
        times,
        &samples.poses,
        settings,
        &mut out,
    );
    if geometry.rotary().is_none() {
        out.findings.extend(jumps::check(times, &lengths, settings));
    }
    CheckReport {
        samples: samples.len(),
        time_span: [
            times.first().copied().unwrap_or(0.0),
            times.last().copied().unwrap_or(0.0),
        ],
        leg_ranges,
        servo_ranges_deg,
        rigid_worst_deviation,
        limits: out.limits,
        architecture,
        findings: out.findings,
    }
}
