//! What moves the platform in the viewer: the trajectory played back, or a manual pose,
//! and the wall clock that drives the manual-mode history.

use stewart_kinematics::Pose;

use super::history::History;

/// What drives the platform.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MotionMode {
    /// The scenario's trajectory, played back.
    Trajectory,
    /// Six sliders.
    Manual,
}

/// Playback and the manual pose.
#[derive(Clone, Debug)]
pub struct Playback {
    /// What drives the platform.
    pub mode: MotionMode,
    /// The pose of manual mode.
    pub manual: Pose,
    /// Playback time, seconds from the trajectory's start.
    pub time: f64,
    /// Whether playback runs.
    pub playing: bool,
    /// Playback speed factor.
    pub speed: f64,
    /// Start again at the end.
    pub looping: bool,
    /// Wall-clock seconds since the viewer started (drives the manual-mode history).
    pub clock: f64,
    /// Leg lengths of manual mode over the last seconds.
    pub history: History,
}

impl Playback {
    /// Playing the trajectory from its start; the manual pose at `home`.
    pub fn new(home: Pose) -> Self {
        Self {
            mode: MotionMode::Trajectory,
            manual: home,
            time: 0.0,
            playing: true,
            speed: 1.0,
            looping: true,
            clock: 0.0,
            history: History::default(),
        }
    }

    /// Move playback on by `dt` seconds of wall time over a trajectory `duration` long;
    /// returns whether the time moved.
    pub fn play(&mut self, dt: f64, duration: f64) -> bool {
        if self.mode != MotionMode::Trajectory || !self.playing {
            return false;
        }
        self.time += dt * self.speed;
        if self.time > duration {
            if self.looping {
                self.time = self.time.rem_euclid(duration);
            } else {
                self.time = duration;
                self.playing = false;
            }
        }
        true
    }

    /// Stop and step by `step` seconds (one sample, signed), within `[0, duration]`.
    pub fn step(&mut self, step: f64, duration: f64) {
        self.playing = false;
        self.time = (self.time + step).clamp(0.0, duration);
    }

    /// Whether the window must keep drawing for playback or the history.
    pub fn animating(&self) -> bool {
        match self.mode {
            MotionMode::Trajectory => self.playing,
            MotionMode::Manual => self.history.recently_changed(self.clock),
        }
    }
}
