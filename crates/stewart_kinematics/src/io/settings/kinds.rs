//! The trajectory kinds a user can switch between, and the motion each starts from.

use super::target::{SettingTarget, ShapeKey};
use crate::model::angle::Angle;
use crate::model::pose::Pose;
use crate::model::trajectory::{
    Circle, FigureEight, Helix, Interpolation, Keyframe, Keyframes, Sinusoid, Sway, Trajectory,
};

/// The kinds of trajectory, as offered in the viewer and named in files.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TrajectoryChoice {
    /// Six sinusoids.
    Sinusoid,
    /// Level circle.
    Circle,
    /// Level figure-eight.
    FigureEight,
    /// Rising helix.
    Helix,
    /// Banked circle.
    Sway,
    /// Keyframes.
    Keyframes,
}

impl TrajectoryChoice {
    /// Every kind.
    pub const ALL: [TrajectoryChoice; 6] = [
        TrajectoryChoice::Sinusoid,
        TrajectoryChoice::Circle,
        TrajectoryChoice::FigureEight,
        TrajectoryChoice::Helix,
        TrajectoryChoice::Sway,
        TrajectoryChoice::Keyframes,
    ];

    /// The kind of a trajectory.
    pub fn of(trajectory: &Trajectory) -> Self {
        match trajectory {
            Trajectory::Sinusoid(_) => TrajectoryChoice::Sinusoid,
            Trajectory::Circle(_) => TrajectoryChoice::Circle,
            Trajectory::FigureEight(_) => TrajectoryChoice::FigureEight,
            Trajectory::Helix(_) => TrajectoryChoice::Helix,
            Trajectory::Sway(_) => TrajectoryChoice::Sway,
            Trajectory::Keyframes(_) => TrajectoryChoice::Keyframes,
        }
    }

    /// Words for people.
    pub fn label(self) -> &'static str {
        match self {
            TrajectoryChoice::Sinusoid => "Sinusoids (seed)",
            TrajectoryChoice::Circle => "Circle",
            TrajectoryChoice::FigureEight => "Figure-eight",
            TrajectoryChoice::Helix => "Helix",
            TrajectoryChoice::Sway => "Banked circle (sway)",
            TrajectoryChoice::Keyframes => "Keyframes",
        }
    }
}

/// A trajectory of `choice` built from the settings' defaults for a platform whose home
/// height is `home_height`, lasting `duration` seconds (the helix climbs over it and the
/// keyframes span it).
pub fn default_trajectory(choice: TrajectoryChoice, home_height: f64, duration: f64) -> Trajectory {
    let shape = |key| {
        super::of(SettingTarget::Shape(key))
            .default
            .resolve(home_height)
            .unwrap_or(0.0)
    };
    match choice {
        TrajectoryChoice::Sinusoid => Trajectory::Sinusoid(Sinusoid::seed(home_height)),
        TrajectoryChoice::Circle => Trajectory::Circle(Circle {
            radius: shape(ShapeKey::Radius),
            frequency_hz: shape(ShapeKey::Frequency),
            z: shape(ShapeKey::Z),
        }),
        TrajectoryChoice::FigureEight => Trajectory::FigureEight(FigureEight {
            amplitude_x: shape(ShapeKey::AmplitudeX),
            amplitude_y: shape(ShapeKey::AmplitudeY),
            frequency_hz: shape(ShapeKey::Frequency),
            z: shape(ShapeKey::Z),
        }),
        TrajectoryChoice::Helix => Trajectory::Helix(Helix {
            radius: shape(ShapeKey::Radius),
            frequency_hz: shape(ShapeKey::Frequency),
            z_start: shape(ShapeKey::ZStart),
            z_end: shape(ShapeKey::ZEnd),
            duration,
        }),
        TrajectoryChoice::Sway => Trajectory::Sway(Sway {
            radius: shape(ShapeKey::Radius),
            frequency_hz: shape(ShapeKey::Frequency),
            tilt: Angle::from_degrees(shape(ShapeKey::Tilt)),
            z: shape(ShapeKey::Z),
        }),
        TrajectoryChoice::Keyframes => Trajectory::Keyframes(pick_and_place(home_height, duration)),
    }
}

/// Home, a lifted and turned pose, a lowered and tilted one, and home again, evenly
/// spread over `duration` and joined by a natural cubic spline.
fn pick_and_place(h: f64, duration: f64) -> Keyframes {
    let poses = [
        Pose::from_xyz_rpy_deg([0.0, 0.0, h], [0.0, 0.0, 0.0]),
        Pose::from_xyz_rpy_deg([0.1, 0.05, h + 0.05], [3.0, 0.0, 10.0]),
        Pose::from_xyz_rpy_deg([0.0, 0.12, h - 0.05], [0.0, -4.0, 0.0]),
        Pose::from_xyz_rpy_deg([0.0, 0.0, h], [0.0, 0.0, 0.0]),
    ];
    let step = duration / (poses.len() - 1) as f64;
    let keys = poses
        .iter()
        .enumerate()
        .map(|(i, &pose)| Keyframe {
            t: i as f64 * step,
            pose,
        })
        .collect();
    Keyframes::new(keys, Interpolation::Cubic)
        .unwrap_or_else(|e| unreachable!("four finite keys at increasing times: {e}"))
}

/// Switch `scenario` to a trajectory of `choice` with its default numbers, keeping the
/// duration and sample count and starting at t = 0. Switching to the kind it already
/// has changes nothing.
pub fn switch_trajectory(scenario: &mut crate::io::scenario::Scenario, choice: TrajectoryChoice) {
    if TrajectoryChoice::of(&scenario.motion.trajectory) == choice {
        return;
    }
    let sampling = scenario.motion.sampling;
    scenario.motion.trajectory =
        default_trajectory(choice, scenario.geometry.home_height(), sampling.duration());
    scenario.motion.sampling = crate::model::trajectory::Sampling::with_start(
        0.0,
        sampling.duration(),
        sampling.len() as u64,
    )
    .unwrap_or(sampling);
}
