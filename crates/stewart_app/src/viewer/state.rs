//! The viewer's state: the scenario, what moves the platform, playback and camera. Plain
//! core types: the panels edit it, the 3D view reads it. Time is injected (`advance`).

use stewart_kinematics::{
    CheckReport, Geometry, GeometryParams, LegSolution, Pose, Scenario, check_motion,
};
use stewart_render::{OrbitCamera, Theme};

use crate::export::frames::default_camera;

/// What drives the platform.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MotionMode {
    /// The scenario's trajectory, played back.
    Trajectory,
    /// Six sliders.
    Manual,
}

/// Everything the viewer shows.
pub struct ViewerState {
    /// The scenario.
    pub scenario: Scenario,
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
    /// The camera.
    pub camera: OrbitCamera,
    /// Light (presentation) or dark colours.
    pub light_theme: bool,
    /// Sample times and leg lengths of the trajectory, for the plot.
    pub samples: (Vec<f64>, Vec<[f64; 6]>),
    /// The pre-flight report of the trajectory (made by `resample`).
    pub report: Option<CheckReport>,
    /// Why the last geometry edit was refused (the geometry then stays as it was).
    pub geometry_error: Option<String>,
}

impl ViewerState {
    /// The viewer on `scenario`, playing its trajectory from the start.
    pub fn new(scenario: Scenario) -> Self {
        let camera = default_camera(&scenario);
        let manual = scenario.geometry.home_pose();
        let mut s = Self {
            scenario,
            mode: MotionMode::Trajectory,
            manual,
            time: 0.0,
            playing: true,
            speed: 1.0,
            looping: true,
            camera,
            light_theme: false,
            samples: (Vec::new(), Vec::new()),
            report: None,
            geometry_error: None,
        };
        s.resample();
        s
    }

    /// Recompute the plotted samples after the scenario changed.
    pub fn resample(&mut self) {
        let samples = self.scenario.motion.sample();
        let lengths = self.scenario.geometry.leg_lengths_batch(&samples.poses);
        self.report = Some(check_motion(
            &self.scenario.geometry,
            &self.scenario.limits,
            &samples,
            &self.scenario.checks,
        ));
        self.samples = (samples.times, lengths);
        self.time = self.time.clamp(0.0, self.duration());
    }

    /// Replace the geometry after validating it; a refused geometry leaves everything as it
    /// was and records why.
    pub fn set_geometry(&mut self, params: GeometryParams) {
        match Geometry::new(params) {
            Ok(g) => {
                self.scenario.geometry = g;
                self.geometry_error = None;
                self.resample();
            }
            Err(e) => self.geometry_error = Some(e.to_string()),
        }
    }

    /// Duration of the trajectory, seconds.
    pub fn duration(&self) -> f64 {
        self.scenario.motion.sampling.duration()
    }

    /// The pose shown now.
    pub fn pose(&self) -> Pose {
        match self.mode {
            MotionMode::Manual => self.manual,
            MotionMode::Trajectory => {
                let start = self.scenario.motion.sampling.start();
                self.scenario.motion.trajectory.pose_at(start + self.time)
            }
        }
    }

    /// Legs of the pose shown now.
    pub fn legs(&self) -> LegSolution {
        self.scenario.geometry.inverse(&self.pose())
    }

    /// The colour theme.
    pub fn theme(&self) -> Theme {
        if self.light_theme {
            Theme::LIGHT
        } else {
            Theme::DARK
        }
    }

    /// Move playback on by `dt` seconds of wall time. Returns whether anything moved.
    pub fn advance(&mut self, dt: f64) -> bool {
        if !self.playing || self.mode != MotionMode::Trajectory {
            return false;
        }
        let duration = self.duration();
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

    /// Look from a standard direction (azimuth, elevation in degrees), keeping the framing.
    pub fn look_from(&mut self, azimuth_deg: f32, elevation_deg: f32) {
        let framed = default_camera(&self.scenario);
        self.camera = OrbitCamera {
            azimuth_deg,
            elevation_deg,
            ..framed
        };
    }

    /// Step playback by one trajectory sample (`direction` ±1).
    pub fn step(&mut self, direction: f64) {
        self.playing = false;
        let step = self.scenario.motion.sampling.step();
        self.time = (self.time + direction * step).clamp(0.0, self.duration());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn playback_loops_and_stops() {
        let mut s = ViewerState::new(Scenario::seed());
        assert!(s.advance(4.0));
        assert!((s.time - 4.0).abs() < 1e-12);
        s.advance(7.0);
        assert!((s.time - 1.0).abs() < 1e-9, "{}", s.time);
        s.looping = false;
        s.advance(20.0);
        assert_eq!(s.time, 10.0);
        assert!(!s.playing);
        assert!(!s.advance(1.0));
        s.step(-1.0);
        assert!((s.time - 9.99).abs() < 1e-12);
    }

    #[test]
    fn the_pose_follows_the_mode() {
        let mut s = ViewerState::new(Scenario::seed());
        s.time = 2.5;
        assert_eq!(s.pose(), s.scenario.motion.trajectory.pose_at(2.5));
        s.mode = MotionMode::Manual;
        s.manual.position.z = 0.9;
        assert_eq!(s.pose().position.z, 0.9);
        assert_eq!(s.samples.0.len(), 1001);
    }
}
