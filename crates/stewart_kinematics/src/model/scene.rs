//! What to draw for a pose: plain data the renderer consumes (joints, legs, plates,
//! per-leg state, and a rotary platform's servos). The kinematics decides what is over
//! the stroke or past a servo's range (`solve::scene_frame` builds a frame from a pose);
//! the renderer only chooses colours.

use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};

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

/// Where a part's frame stands (see [`crate::model::appearance::Part`] for each part's):
/// its origin and orientation in the base frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    /// The frame's origin, base frame, metres.
    pub origin: Vector3<f64>,
    /// The frame's orientation: its axes in the base frame.
    pub rotation: UnitQuaternion<f64>,
}

impl SceneFrame {
    /// The platform frame: its origin (the pose's position) and axes.
    pub fn platform_placement(&self) -> Placement {
        Placement {
            origin: self.platform_centre,
            rotation: UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(
                self.platform_rotation,
            )),
        }
    }

    /// Leg `k`'s two moving parts: the body at the base joint and the rod at the
    /// platform joint (for servos, the rod at the horn tip), each turned so its +y runs
    /// along the leg from base (horn tip) to platform joint.
    pub fn leg_placements(&self, k: usize) -> [Placement; 2] {
        let leg = &self.legs[k];
        let rotation = along_y(&(leg.top - leg.base));
        [
            Placement {
                origin: leg.base,
                rotation,
            },
            Placement {
                origin: leg.top,
                rotation,
            },
        ]
    }

    /// Servo `k`'s horn (`None` for linear legs): origin on the shaft's centre, +x along
    /// the horn to its tip, +z along the shaft (the opposite of [`ServoFrame::axis`]) so
    /// that the servo angle turns the horn about +z, +y up at angle 0.
    pub fn horn_placement(&self, k: usize) -> Option<Placement> {
        let servo = self.servos.as_ref()?.get(k)?;
        let x = (servo.horn_tip - servo.shaft)
            .try_normalize(0.0)
            .unwrap_or_else(|| servo.axis.cross(&Vector3::z()));
        let z = -servo.axis;
        let y = z.cross(&x);
        let axes = Matrix3::from_columns(&[x, y, z]);
        Some(Placement {
            origin: servo.shaft,
            rotation: UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(axes)),
        })
    }

    /// Actuator `k`'s rod: of a linear leg at the platform joint, of a servo at the horn
    /// tip; +y along the leg towards the platform joint either way.
    pub fn rod_placement(&self, k: usize) -> Placement {
        let [start, end] = self.leg_placements(k);
        if self.servos.is_some() { start } else { end }
    }
}

/// The shortest rotation taking +y onto `d` (half a turn about z when `d` points along −y;
/// no turn when `d` is zero).
fn along_y(d: &Vector3<f64>) -> UnitQuaternion<f64> {
    if d.norm() == 0.0 || !d.iter().all(|v| v.is_finite()) {
        return UnitQuaternion::identity();
    }
    UnitQuaternion::rotation_between(&Vector3::y(), d).unwrap_or_else(|| {
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::PI)
    })
}
