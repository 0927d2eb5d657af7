//! Limits beyond the stroke: actuator speed, acceleration and jerk, joint cone angles, leg size.
//!
//! Every limit is optional; an absent limit is not checked.

use nalgebra::Vector3;
use serde::{Deserialize, Serialize};

use crate::model::angle::Angle;
use crate::model::leg_solution::LegSolution;
use crate::model::pose::Pose;

/// Optional limits of a platform's actuators and joints.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Limits {
    /// Largest leg speed |dL/dt|, m/s.
    pub leg_speed_max: Option<f64>,
    /// Largest leg acceleration |d²L/dt²|, m/s².
    pub leg_accel_max: Option<f64>,
    /// Largest leg jerk |d³L/dt³|, m/s³ (the link's trajectory generator keeps it too).
    #[serde(default)]
    pub leg_jerk_max: Option<f64>,
    /// Largest servo speed |dθ/dt| of a rotary platform, degrees per second.
    #[serde(default)]
    pub servo_speed_max: Option<f64>,
    /// Largest servo acceleration |d²θ/dt²| of a rotary platform, degrees per second squared.
    #[serde(default)]
    pub servo_accel_max: Option<f64>,
    /// Largest servo jerk |d³θ/dt³| of a rotary platform, degrees per second cubed.
    #[serde(default)]
    pub servo_jerk_max: Option<f64>,
    /// Largest angle between a leg and the base normal at its base joint.
    pub base_cone: Option<Angle>,
    /// Largest angle between a leg and the platform normal at its platform joint.
    pub platform_cone: Option<Angle>,
    /// Radius of a leg (or of a rotary platform's rod and horn) seen as a cylinder,
    /// metres (two legs collide when their axes come closer than twice this).
    pub leg_radius: Option<f64>,
}

impl Limits {
    /// Whether any limit that depends on the pose alone (cones, collisions) is set.
    pub fn has_pose_limits(&self) -> bool {
        self.base_cone.is_some() || self.platform_cone.is_some() || self.leg_radius.is_some()
    }

    /// Whether a solved pose respects the cone and collision limits.
    pub fn pose_allowed(&self, pose: &Pose, solution: &LegSolution) -> bool {
        let angles = joint_angles(pose, solution);
        // In degrees, as the check reports and judges them: the same test to the last bit
        // (in radians, an angle equal to the limit could read 45.00000000000001°).
        let cone_ok = |limit: Option<Angle>, k: usize| {
            limit.is_none_or(|max| angles.iter().all(|a| a[k].to_degrees() <= max.degrees()))
        };
        cone_ok(self.base_cone, 0)
            && cone_ok(self.platform_cone, 1)
            && self
                .leg_radius
                .is_none_or(|r| closest_legs(solution).distance >= 2.0 * r)
    }
}

/// For each leg, the angle (radians) between the leg and the base normal at its base
/// joint, and between the leg and the platform normal at its platform joint.
pub fn joint_angles(pose: &Pose, solution: &LegSolution) -> [[f64; 2]; 6] {
    let platform_normal = pose.rotation() * Vector3::z();
    std::array::from_fn(|i| {
        let u = solution.unit(i);
        [
            u.z.clamp(-1.0, 1.0).acos(),
            u.dot(&platform_normal).clamp(-1.0, 1.0).acos(),
        ]
    })
}

/// The two legs whose axes come closest, and how close.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClosestLegs {
    /// Leg numbers from 1.
    pub legs: (usize, usize),
    /// Distance between the two leg axes (segments), metres.
    pub distance: f64,
}

/// The fifteen pairs of legs `(i, j)`, `i < j`, numbered from 0.
pub const LEG_PAIRS: [(usize, usize); 15] = {
    let mut pairs = [(0, 0); 15];
    let mut k = 0;
    let mut i = 0;
    while i < 6 {
        let mut j = i + 1;
        while j < 6 {
            pairs[k] = (i, j);
            k += 1;
            j += 1;
        }
        i += 1;
    }
    pairs
};

/// The distance between the axes (segments, base joint to platform joint) of every pair
/// of legs, in the order of [`LEG_PAIRS`].
pub fn pair_distances(solution: &LegSolution) -> [f64; 15] {
    LEG_PAIRS.map(|(i, j)| {
        segment_distance(
            solution.platform_joints[i] - solution.legs[i],
            solution.platform_joints[i],
            solution.platform_joints[j] - solution.legs[j],
            solution.platform_joints[j],
        )
    })
}

/// The closest pair of leg segments (base joint to platform joint).
pub fn closest_legs(solution: &LegSolution) -> ClosestLegs {
    let mut best = ClosestLegs {
        legs: (1, 2),
        distance: f64::INFINITY,
    };
    for (&(i, j), &d) in LEG_PAIRS.iter().zip(&pair_distances(solution)) {
        if d < best.distance {
            best = ClosestLegs {
                legs: (i + 1, j + 1),
                distance: d,
            };
        }
    }
    best
}

/// Shortest distance between segments `[p0, p1]` and `[q0, q1]` (closest points with
/// both parameters clamped to the segments; Ericson, *Real-Time Collision Detection*, 5.1.9).
pub fn segment_distance(
    p0: Vector3<f64>,
    p1: Vector3<f64>,
    q0: Vector3<f64>,
    q1: Vector3<f64>,
) -> f64 {
    let d1 = p1 - p0;
    let d2 = q1 - q0;
    let r = p0 - q0;
    let a = d1.norm_squared();
    let e = d2.norm_squared();
    let f = d2.dot(&r);
    let (s, t) = if a <= f64::EPSILON && e <= f64::EPSILON {
        (0.0, 0.0)
    } else if a <= f64::EPSILON {
        (0.0, (f / e).clamp(0.0, 1.0))
    } else {
        let c = d1.dot(&r);
        if e <= f64::EPSILON {
            ((-c / a).clamp(0.0, 1.0), 0.0)
        } else {
            let b = d1.dot(&d2);
            let denom = a * e - b * b;
            let mut s = if denom > 0.0 {
                ((b * f - c * e) / denom).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let mut t = (b * s + f) / e;
            if t < 0.0 {
                t = 0.0;
                s = (-c / a).clamp(0.0, 1.0);
            } else if t > 1.0 {
                t = 1.0;
                s = ((b - c) / a).clamp(0.0, 1.0);
            }
            (s, t)
        }
    };
    ((p0 + d1 * s) - (q0 + d2 * t)).norm()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::geometry::Geometry;

    #[test]
    fn segment_distance_hand_cases() {
        let v = Vector3::new;
        for (what, [a, b, c, d], expected) in [
            (
                "crossing segments one above the other: the gap",
                [
                    v(-1.0, 0.0, 0.0),
                    v(1.0, 0.0, 0.0),
                    v(0.0, -1.0, 0.5),
                    v(0.0, 1.0, 0.5),
                ],
                0.5,
            ),
            (
                "parallel, overlapping: the offset",
                [
                    v(0.0, 0.0, 0.0),
                    v(2.0, 0.0, 0.0),
                    v(1.0, 0.3, 0.0),
                    v(3.0, 0.3, 0.0),
                ],
                0.3,
            ),
            (
                "collinear, apart: the gap between the nearest ends",
                [
                    v(0.0, 0.0, 0.0),
                    v(1.0, 0.0, 0.0),
                    v(3.0, 0.0, 0.0),
                    v(4.0, 0.0, 0.0),
                ],
                2.0,
            ),
            (
                "skew, closest points outside the segments: endpoint to segment",
                [
                    v(0.0, 0.0, 0.0),
                    v(1.0, 0.0, 0.0),
                    v(2.0, 1.0, 0.0),
                    v(2.0, 2.0, 0.0),
                ],
                2f64.sqrt(),
            ),
        ] {
            let got = segment_distance(a, b, c, d);
            assert!(
                (got - expected).abs() < 1e-15,
                "{what}: {got} vs {expected}"
            );
        }
    }

    #[test]
    fn seed_home_joint_angles_by_hand() {
        // At home every leg rises 0.8 m over a horizontal run of √(1.36 − 0.6√3) m, so its
        // angle to the vertical is atan(run / 0.8), the same at both ends (plates parallel).
        let g = Geometry::seed();
        let pose = g.home_pose();
        let angles = joint_angles(&pose, &g.inverse(&pose));
        let run = (1.36 - 0.6 * 3f64.sqrt()).sqrt();
        let expected = (run / 0.8).atan();
        for a in angles {
            assert!((a[0] - expected).abs() < 1e-12 && (a[1] - expected).abs() < 1e-12);
        }
        let limits = Limits {
            base_cone: Some(Angle::from_radians(expected + 0.01)),
            ..Limits::default()
        };
        assert!(limits.pose_allowed(&pose, &g.inverse(&pose)));
        let limits = Limits {
            platform_cone: Some(Angle::from_radians(expected - 0.01)),
            ..Limits::default()
        };
        assert!(!limits.pose_allowed(&pose, &g.inverse(&pose)));
    }

    #[test]
    fn closest_legs_of_the_paired_layout_are_a_pair() {
        let g = crate::test_support::paired_geometry();
        let pose = g.home_pose();
        let c = closest_legs(&g.inverse(&pose));
        // Legs 2k and 2k+1 share a platform pair: they are the close ones.
        assert!(matches!(c.legs, (1, 2) | (3, 4) | (5, 6)), "{c:?}");
        // Their platform joints are 2·0.6·sin(10°) apart; the axes come no closer than that... nor further.
        assert!(c.distance <= 1.2 * 10f64.to_radians().sin() + 1e-12);
        assert!(c.distance > 0.0);
    }
}
