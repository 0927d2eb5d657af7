//! The viewer's state: the scenario, what moves the platform, playback and camera. Plain
//! core types: the panels edit it, the 3D view reads it. Time is injected (`advance`).

use std::path::Path;

use nalgebra::Vector3;

use stewart_kinematics::settings::{self, Group, Setting, TrajectoryChoice};
use stewart_kinematics::{
    CheckReport, Geometry, GeometryParams, Layout, LegSolution, Pose, Scenario, check_motion,
};
use stewart_render::{OrbitCamera, Theme};

use super::export_job::ExportJob;
use super::history::History;
use crate::export::frames::default_camera;

/// What the export panel will write.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ExportKind {
    /// Animated GIF.
    Gif,
    /// H.264 MP4 (needs ffmpeg).
    Mp4,
    /// A folder of numbered PNG frames.
    Frames,
    /// The leg-length plot as SVG.
    PlotSvg,
    /// The leg-length plot as PDF.
    PlotPdf,
    /// The leg-length plot as a 300 dpi PNG.
    PlotPng,
    /// Poses and leg lengths, CSV.
    Csv,
}

impl ExportKind {
    /// Every kind, in menu order.
    pub const ALL: [ExportKind; 7] = [
        ExportKind::Gif,
        ExportKind::Mp4,
        ExportKind::Frames,
        ExportKind::PlotSvg,
        ExportKind::PlotPdf,
        ExportKind::PlotPng,
        ExportKind::Csv,
    ];

    /// Words for the menu.
    pub fn label(self) -> &'static str {
        match self {
            ExportKind::Gif => "Video: GIF",
            ExportKind::Mp4 => "Video: MP4",
            ExportKind::Frames => "Frames: PNG folder",
            ExportKind::PlotSvg => "Plot: SVG",
            ExportKind::PlotPdf => "Plot: PDF",
            ExportKind::PlotPng => "Plot: PNG (300 dpi)",
            ExportKind::Csv => "Poses and legs: CSV",
        }
    }

    /// What the output's name ends in (`""` for a folder).
    pub fn extension(self) -> &'static str {
        match self {
            ExportKind::Gif => ".gif",
            ExportKind::Mp4 => ".mp4",
            ExportKind::Frames => "",
            ExportKind::PlotSvg => ".svg",
            ExportKind::PlotPdf => ".pdf",
            ExportKind::PlotPng => ".png",
            ExportKind::Csv => ".csv",
        }
    }

    /// Whether it renders frames (and so has size, rate and theme).
    pub fn is_video(self) -> bool {
        matches!(self, ExportKind::Gif | ExportKind::Mp4 | ExportKind::Frames)
    }
}

/// The export panel's choices.
#[derive(Clone, Debug, PartialEq)]
pub struct ExportForm {
    /// What to write.
    pub kind: ExportKind,
    /// Where.
    pub path: String,
    /// Frame size, pixels.
    pub size: (u32, u32),
    /// Frames per second; 0: one frame per trajectory sample.
    pub fps: f64,
    /// Light colours.
    pub light: bool,
    /// The plot beside the 3D view.
    pub composite: bool,
}

impl Default for ExportForm {
    fn default() -> Self {
        Self {
            kind: ExportKind::Gif,
            path: String::new(),
            size: (1280, 720),
            fps: 30.0,
            light: false,
            composite: false,
        }
    }
}

/// The outcome of the last file or export action, shown until the next one.
pub type Status = Option<Result<String, String>>;

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
    /// The layout the Geometry panel's layout controls edit.
    pub layout: Layout,
    /// Why the last edit was refused (the scenario then stays as it was).
    pub edit_error: Option<(Group, String)>,
    /// The scenario file path in the Scenario panel.
    pub file_path: String,
    /// What the last open or save did.
    pub file_status: Status,
    /// Presentation mode: light colours, large text, control panels hidden.
    pub presentation: bool,
    /// Open every collapsible section at start (for screenshots of everything).
    pub expand_panels: bool,
    /// Draw the path the platform centre has traced.
    pub show_path: bool,
    /// Draw the platform's own axes.
    pub platform_axes: bool,
    /// Platform-centre positions at the sample times, for the traced path.
    pub centres: Vec<Vector3<f64>>,
    /// Wall-clock seconds since the viewer started (drives the manual-mode history).
    pub clock: f64,
    /// Leg lengths of manual mode over the last seconds.
    pub history: History,
    /// The export panel's choices.
    pub export: ExportForm,
    /// The export running or last run.
    pub export_job: Option<ExportJob>,
    /// What the last export did.
    pub export_status: Status,
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
            edit_error: None,
            layout: Layout::paired(20.0),
            file_path: String::new(),
            file_status: None,
            presentation: false,
            expand_panels: false,
            show_path: true,
            platform_axes: false,
            centres: Vec::new(),
            clock: 0.0,
            history: History::default(),
            export: ExportForm::default(),
            export_job: None,
            export_status: None,
        };
        s.resample();
        s
    }

    /// Recompute the plotted samples (and the layout the controls show) after the
    /// scenario changed.
    pub fn resample(&mut self) {
        let params = self.scenario.geometry.params();
        if let Some(layout) = Layout::recognise(&params.base_angles, &params.platform_angles) {
            self.layout = layout;
        }
        let samples = self.scenario.motion.sample();
        let lengths = self.scenario.geometry.leg_lengths_batch(&samples.poses);
        let g = &self.scenario.geometry;
        self.centres = samples.poses.iter().map(|p| g.platform_centre(p)).collect();
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
                self.edit_error = None;
                self.resample();
            }
            Err(e) => self.edit_error = Some((Group::Geometry, e.to_string())),
        }
    }

    /// Write one setting (`None`: switch an optional one off); a refused value leaves the
    /// scenario as it was and records why.
    pub fn apply(&mut self, setting: &Setting, value: Option<f64>) {
        match setting.set(&mut self.scenario, value) {
            Ok(()) => {
                self.edit_error = None;
                self.resample();
            }
            Err(e) => self.edit_error = Some((setting.group, e.to_string())),
        }
    }

    /// Switch to another kind of trajectory with its default numbers.
    pub fn switch_trajectory(&mut self, choice: TrajectoryChoice) {
        settings::switch_trajectory(&mut self.scenario, choice);
        self.edit_error = None;
        self.resample();
    }

    /// Show another scenario from its start, keeping the viewer's own choices (theme,
    /// presentation, file path, export settings).
    pub fn load_scenario(&mut self, scenario: Scenario) {
        self.camera = default_camera(&scenario);
        self.manual = scenario.geometry.home_pose();
        self.scenario = scenario;
        self.time = 0.0;
        self.edit_error = None;
        self.history.clear();
        self.resample();
    }

    /// Open a scenario file. A file that cannot be read or is invalid leaves the current
    /// scenario untouched; either way the outcome is shown in the Scenario panel.
    pub fn open_file(&mut self, path: &Path) {
        self.file_status = Some(match Scenario::load(path) {
            Ok(s) => {
                let name = s.name.clone();
                self.load_scenario(s);
                Ok(format!("Opened `{name}` from {}.", path.display()))
            }
            Err(e) => Err(e.to_string()),
        });
    }

    /// Save the scenario as TOML (whole or not at all).
    pub fn save_file(&mut self, path: &Path) {
        let text = self.scenario.to_toml();
        self.file_status = Some(
            crate::output::write_atomically(path, text.as_bytes())
                .map(|()| format!("Saved to {}.", path.display()))
                .map_err(|e| format!("{e:#}")),
        );
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

    /// The platform centre's path from the start of the trajectory up to now.
    pub fn path_until_now(&self) -> Vec<Vector3<f64>> {
        let now = self.scenario.motion.sampling.start() + self.time;
        let done = self.samples.0.partition_point(|&t| t <= now);
        self.centres[..done.min(self.centres.len())].to_vec()
    }

    /// Legs of the pose shown now.
    pub fn legs(&self) -> LegSolution {
        self.scenario.geometry.inverse(&self.pose())
    }

    /// Whether colours are light (the light theme, or presentation mode).
    pub fn is_light(&self) -> bool {
        self.light_theme || self.presentation
    }

    /// The colour theme (presentation mode is always light).
    pub fn theme(&self) -> Theme {
        if self.is_light() {
            Theme::LIGHT
        } else {
            Theme::DARK
        }
    }

    /// Collect the outcome of a finished export.
    pub fn poll_export(&mut self) {
        if let Some(job) = &mut self.export_job
            && let Some(outcome) = job.poll()
        {
            self.export_status = Some(outcome);
            self.export_job = None;
        }
    }

    /// Whether the window must keep drawing: playback runs, the manual-mode history is
    /// still scrolling, or an export is running.
    pub fn animating(&self) -> bool {
        let playing = self.playing && self.mode == MotionMode::Trajectory;
        let scrolling =
            self.mode == MotionMode::Manual && self.history.recently_changed(self.clock);
        playing || scrolling || self.export_job.is_some()
    }

    /// Move on by `dt` seconds of wall time: playback, and in manual mode the history.
    /// Returns whether playback moved.
    pub fn advance(&mut self, dt: f64) -> bool {
        self.clock += dt;
        if self.mode == MotionMode::Manual {
            let lengths = self.legs().lengths;
            self.history.push(self.clock, lengths);
            return false;
        }
        if !self.playing {
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
