//! What to draw for a pose: plain data the renderer consumes (joints, legs, plates,
//! per-leg state). The kinematics decides what is over the stroke; the renderer only
//! chooses colours.

use nalgebra::{Matrix3, Vector3};

use crate::geometry::Geometry;
use crate::pose::Pose;

/// How a leg stands relative to its stroke.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LegStatus {
    /// Inside the stroke, away from its ends (or no stroke given).
    Normal,
    /// Within 5 % of the stroke of an end.
    NearLimit,
    /// Outside the stroke.
    OverLimit,
}

/// One leg to draw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LegFrame {
    /// Base joint, base frame, metres.
    pub base: Vector3<f64>,
    /// Platform joint, base frame, metres.
    pub top: Vector3<f64>,
    /// Current length, metres.
    pub length: f64,
    /// Fraction of the stroke used (0 at `leg_min`, 1 at `leg_max`), when both are given.
    pub stroke_usage: Option<f64>,
    /// Shortest length (the actuator body's length when drawn as body and rod), metres.
    pub min_length: Option<f64>,
    /// Where the leg stands relative to its stroke.
    pub status: LegStatus,
}

/// Everything the renderer needs for one frame, in the base frame (z up), metres.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneFrame {
    /// The six base joints.
    pub base_joints: [Vector3<f64>; 6],
    /// The six platform joints.
    pub platform_joints: [Vector3<f64>; 6],
    /// The platform centre.
    pub platform_centre: Vector3<f64>,
    /// The platform's orientation (its axes are the columns).
    pub platform_rotation: Matrix3<f64>,
    /// Radius of the base joint circle.
    pub base_radius: f64,
    /// Radius of the platform joint circle.
    pub platform_radius: f64,
    /// The legs.
    pub legs: [LegFrame; 6],
    /// The path traced by the platform centre so far (may be empty).
    pub path: Vec<Vector3<f64>>,
}

/// Fraction of the stroke near either end that counts as "near the limit".
const NEAR_LIMIT: f64 = 0.05;

impl Geometry {
    /// The scene for `pose`, with the platform-centre path `path` (already in metres).
    pub fn scene_frame(&self, pose: &Pose, path: Vec<Vector3<f64>>) -> SceneFrame {
        let solution = self.inverse(pose);
        let stroke = self.stroke();
        let legs = std::array::from_fn(|i| {
            let length = solution.lengths[i];
            let usage = stroke.usage(length);
            let status = if stroke.violation(length).is_some() {
                LegStatus::OverLimit
            } else if usage.is_some_and(|u| !(NEAR_LIMIT..=1.0 - NEAR_LIMIT).contains(&u)) {
                LegStatus::NearLimit
            } else {
                LegStatus::Normal
            };
            LegFrame {
                base: self.base_joints()[i],
                top: solution.platform_joints[i],
                length,
                stroke_usage: usage,
                min_length: stroke.min,
                status,
            }
        });
        SceneFrame {
            base_joints: *self.base_joints(),
            platform_joints: solution.platform_joints,
            platform_centre: self.platform_centre(pose),
            platform_rotation: pose.rotation(),
            base_radius: self.params().base_radius,
            platform_radius: self.params().platform_radius,
            legs,
            path,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{GeometryParams, StrokeLimits};

    #[test]
    fn leg_status_follows_the_stroke() {
        let mut p = GeometryParams::seed();
        // Home legs are 0.9802 m long.
        p.stroke = StrokeLimits::new(0.5, 0.97);
        let g = Geometry::new(p).unwrap_or_else(|e| panic!("{e}"));
        let frame = g.scene_frame(&g.home_pose(), Vec::new());
        assert!(frame.legs.iter().all(|l| l.status == LegStatus::OverLimit));
        let mut p = GeometryParams::seed();
        p.stroke = StrokeLimits::new(0.5, 0.99);
        let g = Geometry::new(p).unwrap_or_else(|e| panic!("{e}"));
        let frame = g.scene_frame(&g.home_pose(), Vec::new());
        assert!(frame.legs.iter().all(|l| l.status == LegStatus::NearLimit));
        let g = Geometry::seed();
        let frame = g.scene_frame(&g.home_pose(), Vec::new());
        assert!(
            frame
                .legs
                .iter()
                .all(|l| l.status == LegStatus::Normal && l.stroke_usage.is_none())
        );
        assert_eq!(frame.platform_centre, Vector3::new(0.0, 0.0, 0.8));
        assert_eq!(frame.legs[2].top, frame.platform_joints[2]);
    }
}
