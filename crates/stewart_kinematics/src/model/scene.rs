//! What to draw for a pose: plain data the renderer consumes (joints, legs, plates,
//! per-leg state, and a rotary platform's servos). The kinematics decides what is over
//! the stroke or past a servo's range (`solve::scene_frame` builds a frame from a pose);
//! the renderer only chooses colours.

use nalgebra::{Matrix3, Vector3};

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

/// One servo of a rotary platform to draw: its shaft, horn and angle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ServoFrame {
    /// Shaft centre `B_i`, base frame, metres.
    pub shaft: Vector3<f64>,
    /// Unit direction of the shaft's axis (horizontal, perpendicular to the horn direction).
    pub axis: Vector3<f64>,
    /// Horn tip, base frame, metres: where the rod starts. When the servo cannot reach its
    /// joint, the tip of the horn turned as close to the joint as it goes.
    pub horn_tip: Vector3<f64>,
    /// Model angle θ, degrees (`None` when the servo cannot reach its joint).
    pub angle_deg: Option<f64>,
    /// Fraction of the servo range used (0 at `servo_min_deg`, 1 at `servo_max_deg`).
    pub range_usage: Option<f64>,
    /// Where the servo stands relative to its range (over when it cannot reach).
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
    /// Size of the base: the largest distance of a base joint from its origin (the
    /// circle's radius, for joints on a circle).
    pub base_radius: f64,
    /// Size of the platform, likewise.
    pub platform_radius: f64,
    /// The legs; for a rotary platform the rods, from horn tip to platform joint (their
    /// `stroke_usage` and `status` are the servo's).
    pub legs: [LegFrame; 6],
    /// A rotary platform's servos (`None` for linear legs).
    pub servos: Option<[ServoFrame; 6]>,
    /// The path traced by the platform centre so far (may be empty).
    pub path: Vec<Vector3<f64>>,
}

impl SceneFrame {
    /// The six actuator values this frame shows — leg lengths in metres, or servo model
    /// angles in degrees — or `None` when a servo cannot reach its joint.
    pub fn actuator_values(&self) -> Option<[f64; 6]> {
        match &self.servos {
            None => Some(self.legs.map(|l| l.length)),
            Some(servos) => {
                let mut values = [0.0; 6];
                for (value, servo) in values.iter_mut().zip(servos) {
                    *value = servo.angle_deg?;
                }
                Some(values)
            }
        }
    }
}
