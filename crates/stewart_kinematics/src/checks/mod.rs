//! Checks over a whole sampled motion, each finding located in leg and time.
//!
//! - [`rigid`]: the platform joints keep their mutual distances (the seed's self-consistency test);
//! - [`stroke`]: every leg stays within its stroke;
//! - [`jumps`]: no leg length jumps between two samples.

pub mod jumps;
pub mod rigid;
pub mod stroke;

use std::fmt;

use serde::{Deserialize, Serialize};

use crate::geometry::Geometry;
use crate::trajectory::Samples;

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

/// What a finding is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FindingKind {
    /// A leg longer than its maximum length.
    StrokeMax,
    /// A leg shorter than its minimum length.
    StrokeMin,
    /// A leg length changing abruptly between two samples.
    Jump,
    /// Platform joints whose mutual distances changed: the platform was not moved rigidly.
    RigidBody,
}

/// One problem, located: which leg, from when to when, how bad.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Finding {
    /// What kind of problem.
    pub kind: FindingKind,
    /// Leg number from 1, when the finding concerns one leg.
    pub leg: Option<usize>,
    /// Time of the first sample concerned, seconds.
    pub first_time: f64,
    /// Time of the last sample concerned, seconds.
    pub last_time: f64,
    /// Number of samples (or sample steps, for jumps) concerned.
    pub count: usize,
    /// Time of the worst sample, seconds.
    pub worst_time: f64,
    /// The worst value: a leg length (stroke), a step (jump) or a distance change (rigid body), metres.
    pub worst_value: f64,
    /// The limit that was passed, metres.
    pub limit: f64,
    /// By how much the worst value passes the limit, metres (always positive).
    pub excess: f64,
}

impl fmt::Display for Finding {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let leg = self.leg.map(|l| format!("leg L{l}")).unwrap_or_default();
        let span = if self.count > 1 {
            format!(
                "from t = {:.3} s to t = {:.3} s ({} samples)",
                self.first_time, self.last_time, self.count
            )
        } else {
            format!("at t = {:.3} s", self.first_time)
        };
        match self.kind {
            FindingKind::StrokeMax => write!(
                f,
                "{leg} is longer than its maximum {:.4} m {span}; worst {:.4} m at t = {:.3} s, {:.1} mm over",
                self.limit,
                self.worst_value,
                self.worst_time,
                self.excess * 1e3
            ),
            FindingKind::StrokeMin => write!(
                f,
                "{leg} is shorter than its minimum {:.4} m {span}; worst {:.4} m at t = {:.3} s, {:.1} mm under",
                self.limit,
                self.worst_value,
                self.worst_time,
                self.excess * 1e3
            ),
            FindingKind::Jump => write!(
                f,
                "{leg} length jumps {span}; worst step {:.2} mm at t = {:.3} s, where the steps around it allow at most {:.3} mm",
                self.worst_value * 1e3,
                self.worst_time,
                self.limit * 1e3
            ),
            FindingKind::RigidBody => write!(
                f,
                "the platform does not move rigidly {span}: a distance between platform joints changed by {:.3e} m (tolerance {:.1e} m) at t = {:.3} s",
                self.worst_value, self.limit, self.worst_time
            ),
        }
    }
}

/// The outcome of every check over a motion.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CheckReport {
    /// Number of samples checked.
    pub samples: usize,
    /// Time of the first and last sample, seconds.
    pub time_span: [f64; 2],
    /// Shortest and longest length of each leg over the motion, metres.
    pub leg_ranges: [[f64; 2]; 6],
    /// Largest change of any platform-joint distance seen, metres (rounding only, if all is well).
    pub rigid_worst_deviation: f64,
    /// The problems found, in the order: rigid body, stroke, jumps.
    pub findings: Vec<Finding>,
}

impl CheckReport {
    /// Whether nothing was found.
    pub fn is_clean(&self) -> bool {
        self.findings.is_empty()
    }
}

/// Run every check over `samples` for `geometry`.
pub fn check_motion(
    geometry: &Geometry,
    samples: &Samples,
    settings: &CheckSettings,
) -> CheckReport {
    let solutions: Vec<_> = samples.poses.iter().map(|p| geometry.inverse(p)).collect();
    let lengths: Vec<[f64; 6]> = solutions.iter().map(|s| s.lengths).collect();
    let mut leg_ranges = [[f64::INFINITY, f64::NEG_INFINITY]; 6];
    for l in &lengths {
        for i in 0..6 {
            leg_ranges[i][0] = leg_ranges[i][0].min(l[i]);
            leg_ranges[i][1] = leg_ranges[i][1].max(l[i]);
        }
    }
    let (rigid_worst_deviation, mut findings) = rigid::check(
        geometry,
        &samples.times,
        &solutions,
        settings.rigid_tolerance,
    );
    findings.extend(stroke::check(&geometry.stroke(), &samples.times, &lengths));
    findings.extend(jumps::check(&samples.times, &lengths, settings));
    CheckReport {
        samples: samples.len(),
        time_span: [
            samples.times.first().copied().unwrap_or(0.0),
            samples.times.last().copied().unwrap_or(0.0),
        ],
        leg_ranges,
        rigid_worst_deviation,
        findings,
    }
}
