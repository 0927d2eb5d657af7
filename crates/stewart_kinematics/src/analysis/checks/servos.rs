//! The checks of a rotary platform: reach, servo range, servo speed and acceleration,
//! the rods' angles at their ball joints, rod-to-rod and rod-to-horn clearance, and jumps
//! of a servo angle.
//!
//! A sample where a servo cannot reach its joint has no angle and no horn tip for that
//! servo: it is reported once, by the reach check, and left out of every other check of
//! that servo (its values are NaN, which the scans skip).

use nalgebra::Vector3;

use super::scan::{Bound, Collected, scan_columns, scan_legs};
use super::{CheckSettings, FindingKind, jumps};
use crate::analysis::differences::{first_difference, second_difference, third_difference};
use crate::model::geometry::Geometry;
use crate::model::leg_solution::LegSolution;
use crate::model::limits::{LEG_PAIRS, Limits, segment_distance};
use crate::model::pose::Pose;
use crate::model::rotary::RotaryActuators;
use crate::solve::servo_closure;

/// The servo side of every sample of a motion.
pub struct ServoMotion {
    /// `|L| / √(M² + N²)` of each servo: above 1 where it cannot reach its joint.
    pub reach: Vec<[f64; 6]>,
    /// Model angle θ of each servo, degrees (NaN where it cannot reach).
    pub angles_deg: Vec<[f64; 6]>,
    /// Horn tips in the base frame, metres (NaN where the servo cannot reach).
    pub tips: Vec<[Vector3<f64>; 6]>,
}

impl ServoMotion {
    /// Solve every servo of every sample (`solutions` are the platform joints of each
    /// sample's pose).
    pub fn solve(geometry: &Geometry, servos: &RotaryActuators, solutions: &[LegSolution]) -> Self {
        let bases = geometry.base_joints();
        let missing = Vector3::repeat(f64::NAN);
        let mut reach = Vec::with_capacity(solutions.len());
        let mut angles_deg = Vec::with_capacity(solutions.len());
        let mut tips = Vec::with_capacity(solutions.len());
        for s in solutions {
            let mut r = [0.0; 6];
            let mut a = [f64::NAN; 6];
            let mut t = [missing; 6];
            for i in 0..6 {
                r[i] = servo_closure::reach_ratio(servos, i, &bases[i], &s.platform_joints[i]);
                if let Ok(theta) =
                    servo_closure::servo_angle(servos, i, &bases[i], &s.platform_joints[i])
                {
                    a[i] = theta.degrees();
                    t[i] = servos.horn_tip(i, &bases[i], theta);
                }
            }
            reach.push(r);
            angles_deg.push(a);
            tips.push(t);
        }
        Self {
            reach,
            angles_deg,
            tips,
        }
    }

    /// Smallest and largest angle of each servo over the samples it reaches, degrees
    /// (NaN for a servo that reaches none).
    pub fn ranges(&self) -> [[f64; 2]; 6] {
        let mut ranges = [[f64::NAN; 2]; 6];
        for row in &self.angles_deg {
            for (range, &v) in ranges.iter_mut().zip(row) {
                if v.is_nan() {
                    continue;
                }
                range[0] = if range[0].is_nan() {
                    v
                } else {
                    range[0].min(v)
                };
                range[1] = if range[1].is_nan() {
                    v
                } else {
                    range[1].max(v)
                };
            }
        }
        ranges
    }
}

/// Every servo check over a motion; `motion` comes from [`ServoMotion::solve`].
#[allow(clippy::too_many_arguments)]
pub(crate) fn check(
    geometry: &Geometry,
    servos: &RotaryActuators,
    limits: &Limits,
    settings: &CheckSettings,
    times: &[f64],
    poses: &[Pose],
    solutions: &[LegSolution],
    motion: &ServoMotion,
    out: &mut Collected,
) {
    scan_legs(
        FindingKind::Unreachable,
        "",
        Bound::AtMost(1.0),
        times,
        &motion.reach,
        out,
    );
    if let Some((min, max)) = servos.range() {
        for (kind, bound) in [
            (FindingKind::ServoMax, Bound::AtMost(max.degrees())),
            (FindingKind::ServoMin, Bound::AtLeast(min.degrees())),
        ] {
            scan_legs(kind, "deg", bound, times, &motion.angles_deg, out);
        }
    }
    rates(limits, times, &motion.angles_deg, out);
    cones(limits, times, poses, solutions, motion, out);
    clearance(geometry, limits, times, solutions, motion, out);
    // A jump of the horn tip by the floor's length counts as a jump of its angle.
    let floor_deg = (settings.jump_floor / servos.horn_length()).to_degrees();
    out.findings.extend(jumps::check_series(
        FindingKind::ServoJump,
        "deg",
        times,
        &motion.angles_deg,
        settings.jump_ratio,
        floor_deg,
    ));
}

/// Servo speed, acceleration and jerk (finite differences of the angles, degrees).
fn rates(limits: &Limits, times: &[f64], angles_deg: &[[f64; 6]], out: &mut Collected) {
    let rules: [(Option<f64>, FindingKind, &str, super::rates::Difference); 3] = [
        (
            limits.servo_speed_max,
            FindingKind::ServoSpeed,
            "deg/s",
            first_difference,
        ),
        (
            limits.servo_accel_max,
            FindingKind::ServoAccel,
            "deg/s²",
            second_difference,
        ),
        (
            limits.servo_jerk_max,
            FindingKind::ServoJerk,
            "deg/s³",
            third_difference,
        ),
    ];
    super::rates::scan_rates(&rules, times, angles_deg, out);
}

/// The rods' angles (degrees) at the horn joint, from the base normal as at a linear
/// leg's base joint (`[0]`), and at the platform joint, from the platform normal (`[1]`).
pub fn rod_cone_angles(
    pose: &Pose,
    joints: &[Vector3<f64>; 6],
    tips: &[Vector3<f64>; 6],
) -> [[f64; 6]; 2] {
    let angle = |u: Vector3<f64>, n: Vector3<f64>| u.dot(&n).clamp(-1.0, 1.0).acos().to_degrees();
    let platform_normal = pose.rotation() * Vector3::z();
    let rods: [Vector3<f64>; 6] = std::array::from_fn(|i| (joints[i] - tips[i]).normalize());
    [
        rods.map(|u| angle(u, Vector3::z())),
        rods.map(|u| angle(u, platform_normal)),
    ]
}

/// Cone limits on the rods' ball joints (see [`rod_cone_angles`]).
fn cones(
    limits: &Limits,
    times: &[f64],
    poses: &[Pose],
    solutions: &[LegSolution],
    motion: &ServoMotion,
    out: &mut Collected,
) {
    if limits.base_cone.is_none() && limits.platform_cone.is_none() {
        return;
    }
    let angles: Vec<[[f64; 6]; 2]> = poses
        .iter()
        .zip(solutions)
        .zip(&motion.tips)
        .map(|((pose, s), tips)| rod_cone_angles(pose, &s.platform_joints, tips))
        .collect();
    for (k, kind, limit) in [
        (0, FindingKind::HornCone, limits.base_cone),
        (1, FindingKind::RodPlatformCone, limits.platform_cone),
    ] {
        if let Some(max) = limit {
            let series: Vec<[f64; 6]> = angles.iter().map(|a| a[k]).collect();
            scan_legs(
                kind,
                "deg",
                Bound::AtMost(max.degrees()),
                times,
                &series,
                out,
            );
        }
    }
}

/// The thirty (rod, other servo's horn) pairs `(i, j)`, `i ≠ j`, numbered from 0.
pub const ROD_HORN_PAIRS: [(usize, usize); 30] = {
    let mut pairs = [(0, 0); 30];
    let mut k = 0;
    let mut i = 0;
    while i < 6 {
        let mut j = 0;
        while j < 6 {
            if i != j {
                pairs[k] = (i, j);
                k += 1;
            }
            j += 1;
        }
        i += 1;
    }
    pairs
};

/// Distances between every pair of rods (in the order of [`LEG_PAIRS`]) and between every
/// rod and every other servo's horn (in the order of [`ROD_HORN_PAIRS`]), metres.
pub fn rod_distances(
    bases: &[Vector3<f64>; 6],
    joints: &[Vector3<f64>; 6],
    tips: &[Vector3<f64>; 6],
) -> ([f64; 15], [f64; 30]) {
    (
        LEG_PAIRS.map(|(i, j)| segment_distance(tips[i], joints[i], tips[j], joints[j])),
        ROD_HORN_PAIRS.map(|(i, j)| segment_distance(tips[i], joints[i], bases[j], tips[j])),
    )
}

/// Whether a pose whose servos all reach (horn tips `tips`) respects the cone and
/// clearance limits, as [`Limits::pose_allowed`] does for legs.
pub fn rods_allowed(
    limits: &Limits,
    pose: &Pose,
    bases: &[Vector3<f64>; 6],
    joints: &[Vector3<f64>; 6],
    tips: &[Vector3<f64>; 6],
) -> bool {
    let angles = rod_cone_angles(pose, joints, tips);
    let cone_ok = |limit: Option<crate::model::angle::Angle>, k: usize| {
        limit.is_none_or(|max| angles[k].iter().all(|&a| a <= max.degrees()))
    };
    cone_ok(limits.base_cone, 0)
        && cone_ok(limits.platform_cone, 1)
        && limits.leg_radius.is_none_or(|r| {
            let (rods, horns) = rod_distances(bases, joints, tips);
            rods.iter().chain(&horns).all(|&d| d >= 2.0 * r)
        })
}

/// Rods (horn tip to platform joint) and horns (shaft centre to horn tip) as cylinders of
/// the leg radius: every pair of rods, and every rod with another servo's horn, must stay
/// twice the radius apart.
fn clearance(
    geometry: &Geometry,
    limits: &Limits,
    times: &[f64],
    solutions: &[LegSolution],
    motion: &ServoMotion,
    out: &mut Collected,
) {
    let Some(radius) = limits.leg_radius else {
        return;
    };
    let bases = geometry.base_joints();
    let (rods, horns): (Vec<[f64; 15]>, Vec<[f64; 30]>) = solutions
        .iter()
        .zip(&motion.tips)
        .map(|(s, tips)| rod_distances(bases, &s.platform_joints, tips))
        .unzip();
    scan_columns(
        FindingKind::RodCollision,
        "m",
        Bound::AtLeast(2.0 * radius),
        times,
        &rods,
        |pair| {
            let (i, j) = LEG_PAIRS[pair];
            vec![i + 1, j + 1]
        },
        out,
    );
    scan_columns(
        FindingKind::RodHornCollision,
        "m",
        Bound::AtLeast(2.0 * radius),
        times,
        &horns,
        |pair| {
            let (i, j) = ROD_HORN_PAIRS[pair];
            vec![i + 1, j + 1]
        },
        out,
    );
}
