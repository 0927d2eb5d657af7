//! A stream that follows the viewer: the trajectory at the playback time, extrapolated on
//! the sender's clock between frames, or a pose held (paused, manual, teleoperated). The
//! viewer says what drives it; the sender's thread samples it.

use std::time::Instant;

use stewart_kinematics::{Geometry, Pose, Trajectory};
use stewart_link::target::{Sample, TargetError};

use super::moving_sample;

/// What drives the platform, as the sender sees it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Drive {
    /// The trajectory playing: at `anchor` it was at playback time `time`, moving at `speed`.
    Playing {
        /// Playback time at the anchor, seconds.
        time: f64,
        /// Wall-clock instant of the anchor.
        anchor: Instant,
        /// Playback speed.
        speed: f64,
    },
    /// A pose held (paused playback, manual mode, teleoperation).
    Still(Pose),
}

/// What a stream that follows the viewer samples: the platform and its motion, and what
/// drives it now — shared between the viewer (which says what drives it, every frame) and
/// the sender's thread (which samples it at each tick).
pub(crate) struct Followed {
    geometry: Geometry,
    trajectory: Trajectory,
    start: f64,
    /// The motion's length, seconds.
    pub(crate) duration: f64,
    /// Whether playback wraps at the end.
    pub(crate) looping: bool,
    /// What drives the platform now.
    pub(crate) drive: Drive,
}

impl Followed {
    /// The platform, its motion from `span.0` lasting `span.1` seconds, and what drives it.
    pub(super) fn new(
        geometry: Geometry,
        trajectory: Trajectory,
        span: (f64, f64),
        looping: bool,
        drive: Drive,
    ) -> Self {
        Self {
            geometry,
            trajectory,
            start: span.0,
            duration: span.1,
            looping,
            drive,
        }
    }

    /// The target now: a still pose's values, or the playing trajectory's with their
    /// velocity and acceleration on the wall clock (at rest past either end).
    pub(crate) fn sample(&self) -> Result<Sample, TargetError> {
        match self.drive {
            Drive::Still(pose) => self
                .geometry
                .actuator_values_at(&pose)
                .map(Sample::At)
                .map_err(TargetError::source),
            Drive::Playing {
                time,
                anchor,
                speed,
            } => {
                let t = time + anchor.elapsed().as_secs_f64() * speed;
                let (t, speed) = if self.looping && self.duration > 0.0 {
                    (t.rem_euclid(self.duration), speed)
                } else if (0.0..self.duration).contains(&t) {
                    (t, speed)
                } else {
                    (t.clamp(0.0, self.duration), 0.0)
                };
                moving_sample(
                    &self.geometry,
                    |tau| self.trajectory.pose_at(self.start + tau),
                    t,
                    speed,
                )
            }
        }
    }
}
