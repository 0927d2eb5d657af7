//! The scenario file format, as serde structs that mirror the TOML tables.
//!
//! Every number is wrapped in [`Spanned`] so that a value refused after parsing (a
//! negative radius, a NaN, a key a trajectory kind does not use) is reported at its
//! own line. Units are part of every key's name (`_m`, `_deg`, `_hz`, `_s`), except in
//! `[geometry]`, whose keys are fixed by the product (lengths there are in metres).

use serde::{Deserialize, Serialize};
use toml::Spanned;

use crate::model::trajectory::{Interpolation, Wave};

/// A whole scenario file.
#[derive(Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct ScenarioFile {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub description: Option<String>,
    pub geometry: Spanned<GeometryFile>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub actuator: Option<Spanned<ActuatorFile>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pivot: Option<PivotFile>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub trajectory: Option<Spanned<TrajectoryFile>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub limits: Option<LimitsFile>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub payload: Option<Spanned<PayloadFile>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub checks: Option<ChecksFile>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub link: Option<Spanned<crate::model::link_settings::LinkSettings>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cueing: Option<Spanned<crate::model::cueing_settings::CueingSettings>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dynamics: Option<Spanned<crate::model::dynamics_settings::DynamicsSettings>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub appearance: Option<Spanned<crate::model::appearance::AppearanceSettings>>,
}

/// `[payload]`: the moving mass (platform and load).
#[derive(Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct PayloadFile {
    pub mass_kg: f64,
    #[serde(default, deserialize_with = "crate::ground::text::exactly")]
    pub com_m: [f64; 3],
    /// Three principal moments (Ixx, Iyy, Izz) or the whole tensor (Ixx, Iyy, Izz, Ixy,
    /// Ixz, Iyz); none: zero.
    #[serde(default)]
    pub inertia_kg_m2: Vec<f64>,
}

/// `[limits]`: actuator and joint limits beyond the stroke.
#[derive(Debug, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct LimitsFile {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub leg_speed_max_m_s: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub leg_accel_max_m_s2: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub leg_jerk_max_m_s3: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub servo_speed_max_deg_s: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub servo_accel_max_deg_s2: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub servo_jerk_max_deg_s3: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub base_cone_deg: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub platform_cone_deg: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub leg_radius_m: Option<Spanned<f64>>,
}

/// Six joints as `[[x, y, z], …]`, each point with its own place in the file.
pub(crate) type PointsFile = Spanned<Vec<Spanned<Vec<Spanned<f64>>>>>;

/// `[geometry]`: each plate's joints either on a circle (`*_radius` and `*_angles_deg`)
/// or as coordinates (`*_joints_m`), the home height and the stroke.
#[derive(Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct GeometryFile {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub base_radius: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub platform_radius: Option<Spanned<f64>>,
    pub home_height: Spanned<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub base_angles_deg: Option<Spanned<Vec<f64>>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub platform_angles_deg: Option<Spanned<Vec<f64>>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub base_joints_m: Option<PointsFile>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub platform_joints_m: Option<PointsFile>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub leg_min: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub leg_max: Option<Spanned<f64>>,
}

/// `[pivot]`: the rotation centre in the platform frame.
/// `[actuator]`: absent means linear legs.
#[derive(Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct ActuatorFile {
    pub kind: Spanned<ActuatorKind>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub horn_length_m: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rod_length_m: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub horn_angles_deg: Option<Spanned<Vec<f64>>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub servo_min_deg: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub servo_max_deg: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub servo_reversed: Option<Spanned<Vec<bool>>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub servo_trim_deg: Option<Spanned<Vec<f64>>>,
}

pub(crate) use crate::model::actuator::ActuatorKind;

#[derive(Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct PivotFile {
    #[serde(deserialize_with = "crate::ground::text::exactly_spanned")]
    pub offset_m: Spanned<[f64; 3]>,
}

/// The trajectory kinds, as spelled in files.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub(crate) enum TrajectoryKind {
    Sinusoid,
    Circle,
    #[serde(rename = "figure8")]
    FigureEight,
    Helix,
    Sway,
    Keyframes,
    PoseTable,
}

impl TrajectoryKind {
    pub fn name(self) -> &'static str {
        match self {
            TrajectoryKind::Sinusoid => "sinusoid",
            TrajectoryKind::Circle => "circle",
            TrajectoryKind::FigureEight => "figure8",
            TrajectoryKind::Helix => "helix",
            TrajectoryKind::Sway => "sway",
            TrajectoryKind::Keyframes => "keyframes",
            TrajectoryKind::PoseTable => "pose_table",
        }
    }
}

/// `[trajectory]`: one flat table; which keys apply depends on `kind`.
#[derive(Debug, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct TrajectoryFile {
    pub kind: Option<Spanned<TrajectoryKind>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub start_s: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub duration_s: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub samples: Option<Spanned<i64>>,
    /// Keyframes and pose tables: sampled at the keys' own times (a table's default).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub at_keys: Option<Spanned<bool>>,
    // Sinusoid channels.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub x: Option<Spanned<LinearChannelFile>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub y: Option<Spanned<LinearChannelFile>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub z: Option<Spanned<LinearChannelFile>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub roll: Option<Spanned<AngularChannelFile>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pitch: Option<Spanned<AngularChannelFile>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub yaw: Option<Spanned<AngularChannelFile>>,
    // Shapes.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub radius_m: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub frequency_hz: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub z_m: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub amplitude_x_m: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub amplitude_y_m: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub z_start_m: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub z_end_m: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tilt_deg: Option<Spanned<f64>>,
    // Keyframes and pose tables.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub interpolation: Option<Spanned<Interpolation>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub keys: Option<Spanned<Vec<Spanned<KeyFile>>>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub file: Option<Spanned<String>>,
}

/// A sinusoid channel in metres.
#[derive(Debug, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct LinearChannelFile {
    #[serde(default)]
    pub amplitude_m: f64,
    #[serde(default)]
    pub frequency_hz: f64,
    #[serde(default)]
    pub phase_deg: f64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub offset_m: Option<f64>,
    #[serde(default)]
    pub wave: Wave,
}

/// A sinusoid channel in degrees.
#[derive(Debug, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct AngularChannelFile {
    #[serde(default)]
    pub amplitude_deg: f64,
    #[serde(default)]
    pub frequency_hz: f64,
    #[serde(default)]
    pub phase_deg: f64,
    #[serde(default)]
    pub offset_deg: f64,
    #[serde(default)]
    pub wave: Wave,
}

/// One keyframe.
#[derive(Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct KeyFile {
    pub t_s: f64,
    #[serde(default)]
    pub x_m: f64,
    #[serde(default)]
    pub y_m: f64,
    pub z_m: f64,
    #[serde(default)]
    pub roll_deg: f64,
    #[serde(default)]
    pub pitch_deg: f64,
    #[serde(default)]
    pub yaw_deg: f64,
}

/// `[checks]`: thresholds of the trajectory checks.
#[derive(Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct ChecksFile {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rigid_tolerance_m: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub jump_ratio: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub jump_floor_m: Option<Spanned<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub condition_max: Option<Spanned<f64>>,
}
