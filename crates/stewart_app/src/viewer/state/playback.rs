//! What moves the platform in the viewer: the trajectory played back, or a manual pose,
//! and the wall clock that drives the manual-mode history.

use stewart_kinematics::Pose;

use crate::viewer::state::history::History;

/// What drives the platform.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum MotionMode {
    /// The scenario's trajectory, played back.
    Trajectory,
    /// Six sliders.
    Manual,
}

/// Playback and the manual pose.
#[derive(Clone, Debug)]
pub(crate) struct Playback {
    /// What drives the platform.
    pub(crate) mode: MotionMode,
    /// The pose of manual mode.
    pub(crate) manual: Pose,
    /// Playback time, seconds from the trajectory's start.
    pub(crate) time: f64,
    /// Whether playback runs.
    pub(crate) playing: bool,
    /// Playback speed factor.
    pub(crate) speed: f64,
    /// Start again at the end.
    pub(crate) looping: bool,
    /// Wall-clock seconds since the viewer started (drives the manual-mode history).
    pub(crate) clock: f64,
    /// Leg lengths of manual mode over the last seconds.
    pub(crate) history: History,
    /// Frames drawn per second of wall time while playing, smoothed over about a second
    /// (`None` until measured).
    pub(crate) frame_rate: Option<f64>,
}

/// The longest step of time one frame makes, seconds: a longer stall (the machine slept,
/// the window was dragged) is not played through.
pub(crate) const MAX_FRAME_STEP_S: f64 = 1.0;

/// The time a frame moves playback on: the wall time since the last frame, whole (a slow
/// machine skips frames, it does not play slower), when the last frame left something
/// moving; zero after an idle wait, so that the time the window sat paused is not played
/// through when Play is pressed.
pub(crate) fn frame_step(since_last_frame_s: f64, was_moving: bool) -> f64 {
    if was_moving && since_last_frame_s.is_finite() {
        since_last_frame_s.clamp(0.0, MAX_FRAME_STEP_S)
    } else {
        0.0
    }
}

/// Below this many frames a second, the viewer says that it skips frames to keep time.
pub(crate) const SMOOTH_FRAME_RATE: f64 = 20.0;

impl Playback {
    /// Playing the trajectory from its start; the manual pose at `home`.
    pub(crate) fn new(home: Pose) -> Self {
        Self {
            mode: MotionMode::Trajectory,
            manual: home,
            time: 0.0,
            playing: true,
            speed: 1.0,
            looping: true,
            clock: 0.0,
            history: History::default(),
            frame_rate: None,
        }
    }

    /// Move playback on by `dt` seconds of wall time over a trajectory `duration` long
    /// (the whole `dt` however long a frame took: playback keeps true time and skips
    /// frames when drawing is slow); returns whether the time moved.
    pub(crate) fn play(&mut self, dt: f64, duration: f64) -> bool {
        if !self.is_playing() {
            self.frame_rate = None;
            return false;
        }
        if dt > 0.0 {
            // An exponential average whose weight spans about a second of frames.
            let rate = 1.0 / dt;
            let weight = dt.min(1.0);
            self.frame_rate = Some(match self.frame_rate {
                Some(r) => r + weight * (rate - r),
                None => rate,
            });
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

    /// Whether the trajectory is playing (not paused, not in manual mode).
    pub(crate) fn is_playing(&self) -> bool {
        self.playing && self.mode == MotionMode::Trajectory
    }

    /// Play or pause the trajectory (from manual mode: play it).
    pub(crate) fn toggle(&mut self) {
        self.playing = !self.is_playing();
        self.mode = MotionMode::Trajectory;
    }

    /// The measured frame rate when it is too low for smooth playback: frames are being
    /// skipped to keep time.
    pub(crate) fn skipping_frames(&self) -> Option<f64> {
        self.frame_rate
            .filter(|r| self.is_playing() && *r < SMOOTH_FRAME_RATE)
    }

    /// Show the trajectory paused at `time` seconds from its start, within `[0, duration]`.
    pub(crate) fn pause_at(&mut self, time: f64, duration: f64) {
        self.mode = MotionMode::Trajectory;
        self.playing = false;
        self.time = time.clamp(0.0, duration);
    }

    /// Stop and step by `step` seconds (one sample, signed), within `[0, duration]`.
    pub(crate) fn step(&mut self, step: f64, duration: f64) {
        self.playing = false;
        self.time = (self.time + step).clamp(0.0, duration);
    }

    /// Whether the window must keep drawing for playback or the history.
    pub(crate) fn animating(&self) -> bool {
        match self.mode {
            MotionMode::Trajectory => self.playing,
            MotionMode::Manual => self.history.recently_changed(self.clock),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_slow_machine_plays_in_true_time_and_says_it_skips_frames() {
        let mut p = Playback::new(Pose::from_xyz_rpy_deg([0.0, 0.0, 1.0], [0.0; 3]));
        // Four frames a second for ten seconds of wall time: ten seconds played (the step
        // used to be capped at 0.1 s a frame, half speed on this machine).
        for _ in 0..40 {
            p.play(frame_step(0.25, true), 100.0);
        }
        assert!((p.time - 10.0).abs() < 1e-9, "{}", p.time);
        let rate = p.skipping_frames().unwrap_or_default();
        assert!((rate - 4.0).abs() < 1e-6, "{rate}");
        // Sixty frames a second: smooth, nothing said.
        for _ in 0..120 {
            p.play(frame_step(1.0 / 60.0, true), 100.0);
        }
        assert_eq!(p.skipping_frames(), None);
        assert!((p.time - 12.0).abs() < 1e-9, "{}", p.time);
        // Paused: no rate, nothing said.
        p.toggle();
        p.play(frame_step(0.25, true), 100.0);
        assert_eq!(p.skipping_frames(), None);
    }

    #[test]
    fn an_idle_wait_or_a_stall_is_not_played_through() {
        assert_eq!(frame_step(30.0, false), 0.0);
        assert_eq!(frame_step(30.0, true), MAX_FRAME_STEP_S);
        assert_eq!(frame_step(f64::NAN, true), 0.0);
        assert_eq!(frame_step(-1.0, true), 0.0);
    }
}
