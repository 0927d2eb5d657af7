//! The viewer's state: the scenario and what is derived from it, playback, the look of
//! the view, the file and export panels. The panels edit it; time is injected
//! (`advance`).
//!
//! The scenario is changed only through [`ViewerState::edit`] (and the named edits built
//! on it): the change is made on a copy, validated as files are (constructors, accepted
//! ranges), and either replaces the scenario and rebuilds everything derived from it, or
//! is refused with its reason and changes nothing.

pub(crate) mod derived;
pub(crate) mod document;
pub(crate) mod editor;
pub(crate) mod export_job;
mod export_start;
pub(crate) mod exports;
mod file_actions;
pub(crate) mod files;
pub(crate) mod gamepad;
pub(crate) mod history;
pub(crate) mod live_link;
pub(crate) mod look;
pub(crate) mod playback;
pub(crate) mod plot_memory;
pub(crate) mod session;
pub(crate) mod teleop;
pub(crate) mod undo;
pub(crate) mod vehicle;

use nalgebra::Vector3;

use stewart_kinematics::{Pose, Scenario};
use stewart_render::{OrbitCamera, Theme};

use crate::export::frames::default_camera;
use crate::link_plan::Drive;
use crate::viewer::error::ViewerError;
use crate::viewer::state::document::Document;
use crate::viewer::state::editor::Editor;
use crate::viewer::state::exports::Exports;
use crate::viewer::state::files::Files;
use crate::viewer::state::live_link::LiveLink;
use crate::viewer::state::look::Look;
use crate::viewer::state::playback::{MotionMode, Playback};
use crate::viewer::state::teleop::{PadState, Rates, TeleopCommand};

/// Everything the viewer shows.
pub struct ViewerState {
    /// The scenario, its undo history, what is derived from it and the last refused edit.
    pub(crate) doc: Document,
    /// Playback and the manual pose.
    pub(crate) playback: Playback,
    /// Camera, colours, presentation mode, overlays.
    pub look: Look,
    /// The Scenario panel's file path and status.
    pub(crate) files: Files,
    /// The Export panel.
    pub(crate) exports: Exports,
    /// The link to hardware.
    pub(crate) link: LiveLink,
    /// Why the last edit of `[link]` was refused.
    pub(crate) link_error: Option<ViewerError>,
    /// Keyboard and gamepad moves of the manual pose.
    pub(crate) teleop: Teleop,
    /// What is remembered between runs.
    pub(crate) session: SessionState,
    /// Screenshots.
    pub(crate) shots: crate::viewer::view3d::shots::Shots,
    /// The background tools: design search, workspace, assembly modes, reach, the
    /// mode viewer.
    pub tools: crate::viewer::tools::Tools,
    /// The 3D view's quality (adapted to the frame time on a software rasteriser) and the
    /// frame times.
    pub(crate) quality: crate::viewer::view3d::quality::Quality,
    /// Ctrl+Q was pressed: the window closes as by its close button.
    pub(crate) quit_asked: bool,
}

/// The saved session's state in this run.
#[derive(Clone, Debug, Default)]
pub(crate) struct SessionState {
    /// Where sessions are kept; `None`: this run neither reads nor writes one (screenshots,
    /// tests, `--fresh`).
    pub(crate) folder: Option<std::path::PathBuf>,
    /// Where the scenario came from, in words (a preset, a file).
    pub(crate) origin: String,
    /// What happened to the saved session at start (broken, too old), shown once.
    pub(crate) note: Option<String>,
    /// *Reset to defaults* was pressed: nothing is saved when the window closes.
    pub(crate) forgotten: bool,
    /// egui's memory from the saved session, applied at the first frame.
    pub(crate) panels: Option<String>,
}

/// Teleoperation's state.
#[derive(Clone, Debug)]
pub(crate) struct Teleop {
    /// How fast a full command moves.
    pub(crate) rates: Rates,
    /// Why the last move stopped at the edge of the reachable set.
    pub(crate) blocked: Option<teleop::ReachEdge>,
    /// Whether input is moving the platform (the window keeps drawing).
    pub(crate) moving: bool,
    /// The gamepad's state this frame (set by the window; `None` without one).
    pub(crate) pad: Option<PadState>,
    /// The gamepad's name, or why there is none.
    pub(crate) pad_words: Option<String>,
}

impl ViewerState {
    /// The viewer on `scenario`, playing its trajectory from the start (its part files
    /// named from the working folder).
    pub fn new(scenario: Scenario) -> Self {
        Self::new_in(scenario, std::path::PathBuf::from("."))
    }

    /// The viewer on `scenario` whose file is in `folder` (its part files named from there).
    pub(crate) fn new_in(scenario: Scenario, folder: std::path::PathBuf) -> Self {
        Self {
            playback: Playback::new(scenario.geometry.home_pose()),
            look: Look::new(default_camera(&scenario)),
            files: Files::default(),
            exports: Exports::default(),
            link: LiveLink::default(),
            link_error: None,
            teleop: Teleop {
                rates: Rates::for_geometry(&scenario.geometry),
                blocked: None,
                moving: false,
                pad: None,
                pad_words: None,
            },
            session: SessionState {
                origin: format!("preset {}", scenario.name),
                ..SessionState::default()
            },
            shots: crate::viewer::view3d::shots::Shots::default(),
            tools: crate::viewer::tools::Tools::default(),
            quality: crate::viewer::view3d::quality::Quality::default(),
            quit_asked: false,
            doc: Document::new(scenario, folder),
        }
    }

    /// The scenario's name for what the audience sees (exported plots and videos, the
    /// glTF animation, readouts, shots): the name alone, never an edit mark.
    pub(crate) fn title(&self) -> String {
        self.scenario().name.clone()
    }

    /// The window's title: the program and the scenario's name, marked as edited (in the
    /// interface's language) when the scenario differs from the preset or file it came
    /// from; the one place the mark is shown.
    pub(crate) fn window_title(&self) -> String {
        let name = self.doc.marked_name(self.look.lang);
        self.look.lang.fmt("window.title", &[("name", &name)])
    }

    /// Show the interface in `lang`. The status lines of files, exports and screenshots were
    /// written in the other language: they are cleared rather than left in it (the link's
    /// outcome stays: where an emergency stop left the platform is not to be lost).
    pub(crate) fn set_language(&mut self, lang: crate::i18n::Lang) {
        self.look.lang = lang;
        self.files.status = None;
        self.exports.status = None;
        self.shots.status = None;
    }

    /// Move the manual pose by a velocity command for `dt` seconds (keyboard and gamepad),
    /// stopping at the edge of the reachable set. Only in manual mode.
    pub(crate) fn teleoperate(&mut self, command: TeleopCommand, dt: f64) {
        self.teleop.moving = command.moving() && self.playback.mode == MotionMode::Manual;
        if !self.teleop.moving {
            return;
        }
        let (pose, blocked) = teleop::step(
            &self.doc.scenario().geometry,
            &self.playback.manual,
            &command,
            self.teleop.rates,
            dt,
        );
        self.playback.manual = pose;
        self.teleop.blocked = blocked;
    }

    /// What the 3D view draws now in `theme`: the platform at the pose shown, the path so
    /// far, the switches of the look and, when on, the readout. The view and its
    /// screenshots draw the same list.
    pub(crate) fn draw_list(&self, theme: &Theme) -> stewart_render::DrawList {
        // A software rasteriser draws heavy CAD parts' stand-ins to stay interactive, and
        // lighter ones while the view moves (unless this frame is the full picture a
        // window shot is taken of).
        let moving = self.animating() && !self.quality.full_asked();
        self.scene_list(theme, part_detail(self.quality.software, moving))
    }

    /// [`ViewerState::draw_list`] with CAD parts drawn from their meshes of `detail` (the
    /// files in full for screenshots and exports).
    pub(crate) fn scene_list(
        &self,
        theme: &Theme,
        detail: stewart_render::draw_list::PartDetail,
    ) -> stewart_render::DrawList {
        // Live vehicle motion has no trajectory time nor path.
        let trajectory = self.playback.mode == MotionMode::Trajectory && !self.link.cueing_live();
        let path = if self.look.show_path && trajectory {
            self.path_until_now()
        } else {
            Vec::new()
        };
        let shown = self
            .tools
            .modes
            .shown_pose(self.doc.scenario(), self.pose());
        let frame = self.doc.scenario().geometry.scene_frame(&shown, path);
        let overlays = stewart_render::Overlays {
            platform_axes: self.look.platform_axes,
            path: self.look.show_path,
            coloured_legs: self.look.coloured_legs,
            labels: self.look.labels,
            label_scale: if self.look.presentation { 1.6 } else { 1.0 },
            part_detail: detail,
            ..stewart_render::Overlays::default()
        };
        let mut list =
            stewart_render::DrawList::build_with_parts(&frame, theme, &overlays, self.doc.parts());
        if let Some(measured) = self.link.measured_pose() {
            let ghost = self
                .doc
                .scenario()
                .geometry
                .scene_frame(&measured, Vec::new());
            list.ghost(&ghost, theme);
        }
        if self.tools.workspace.show
            && let Some(outcome) = &self.tools.workspace.latest
        {
            list.analysis.push(outcome.surface.clone());
            if let Some(slice) = outcome
                .slice
                .as_ref()
                .filter(|_| self.tools.workspace.show_slice)
            {
                list.analysis.push(slice.mesh.clone());
            }
        }
        if self.look.readouts {
            let start = self.doc.scenario().motion.sampling.start();
            let time = trajectory.then_some(start + self.playback.time);
            let text = crate::readout::lines(
                self.look.lang,
                &self.title(),
                &self.doc.scenario().geometry,
                time,
                &self.pose(),
                None,
            );
            let scale = if self.look.presentation {
                look::PRESENTATION_TEXT_SCALE
            } else {
                1.0
            };
            list.texts
                .push(crate::readout::item_scaled(text, theme, scale));
        }
        list
    }

    /// Take a screenshot as the Screenshot menu says (F12): the 3D view rendered again off
    /// screen on a thread of its own, or the whole window at the next frame. Playback goes
    /// on; the outcome shows in the menu.
    pub(crate) fn take_screenshot(&mut self) {
        use crate::viewer::view3d::shots::{ShotKind, next_path};
        let path = next_path(&self.shots.folder, &self.doc.scenario().name);
        match self.shots.kind {
            ShotKind::Window => self.shots.window_request = Some((path, self.shots.scale)),
            ShotKind::View => {
                let theme = self.theme();
                let list = self.scene_list(&theme, Default::default());
                let size = self.shots.scale.size(self.look.view_px);
                let camera = self.look.camera;
                self.shots
                    .start_view(list, camera, theme, size, path, self.look.lang);
            }
        }
    }

    /// What drives the platform, for the link's sender.
    pub(crate) fn drive(&self) -> Drive {
        if self.playback.mode == MotionMode::Trajectory && self.playback.playing {
            Drive::Playing {
                time: self.playback.time,
                anchor: std::time::Instant::now(),
                speed: self.playback.speed,
            }
        } else {
            Drive::Still(self.played_pose())
        }
    }

    /// Start the link to hardware from the `[link]` table, following what the viewer shows.
    pub(crate) fn connect_link(&mut self) {
        let drive = self.drive();
        let looping = self.playback.looping;
        self.link.connect(self.doc.scenario(), drive, looping);
    }

    /// The scenario shown.
    pub(crate) fn scenario(&self) -> &Scenario {
        self.doc.scenario()
    }

    /// The scenario's edit path for a panel: the document, with playback kept within the
    /// trajectory.
    pub(crate) fn editor(&mut self) -> Editor<'_> {
        Editor::new(
            &mut self.doc,
            &mut self.playback,
            self.look.lang,
            self.look.expand_panels,
        )
    }

    /// Show another scenario from its start, keeping the viewer's own choices (theme,
    /// presentation, file path, export settings), its part files named from `folder`. A
    /// running link is stopped first: it was built for the other platform.
    pub(crate) fn load_scenario(&mut self, scenario: Scenario, folder: std::path::PathBuf) {
        self.link.disconnect();
        self.teleop.rates = Rates::for_geometry(&scenario.geometry);
        self.teleop.blocked = None;
        self.look.camera = default_camera(&scenario);
        self.playback.manual = scenario.geometry.home_pose();
        self.playback.time = 0.0;
        self.playback.history.clear();
        self.doc.replace(scenario, folder);
        self.editor().keep_time_in_range();
    }

    /// Forget the saved session and return the look, camera and panels to their defaults
    /// (the scenario stays); nothing is saved at exit.
    pub(crate) fn reset_to_defaults(&mut self) {
        if let Some(folder) = &self.session.folder
            && let Err(e) = session::forget(folder)
        {
            self.session.note = Some(e.words(self.look.lang));
        }
        self.session.forgotten = true;
        let missing = self.look.renderer_missing.take();
        self.look = Look::new(default_camera(self.doc.scenario()));
        self.look.renderer_missing = missing;
    }

    /// Go back one edit (Ctrl+Z); returns whether there was one.
    pub(crate) fn undo_edit(&mut self) -> bool {
        let Some(left) = self.doc.undo() else {
            return false;
        };
        self.after_restore(&left);
        true
    }

    /// Do again the edit undone last (Ctrl+Shift+Z, Ctrl+Y); returns whether there was one.
    pub(crate) fn redo_edit(&mut self) -> bool {
        let Some(left) = self.doc.redo() else {
            return false;
        };
        self.after_restore(&left);
        true
    }

    /// After undo or redo put a scenario back (leaving `left`): as an edit (playback and
    /// camera stay), unless it is another platform (a preset or file loaded), which is
    /// shown from its start.
    fn after_restore(&mut self, left: &Scenario) {
        let scenario = self.doc.scenario();
        if scenario.name != left.name {
            self.link.disconnect();
            self.look.camera = default_camera(scenario);
            self.playback.manual = scenario.geometry.home_pose();
            self.playback.time = 0.0;
            self.playback.history.clear();
        }
        self.teleop.rates = Rates::for_geometry(&self.doc.scenario().geometry);
        self.editor().keep_time_in_range();
    }

    /// Whether the report is still being computed.
    pub(crate) fn report_pending(&self) -> bool {
        self.doc.report_pending()
    }

    /// Block until the report is in (screenshots and tests want a settled picture).
    pub(crate) fn wait_for_report(&mut self) {
        self.doc.wait_for_report();
    }

    /// Collect what background work has finished: the report, an export. Never blocks.
    pub(crate) fn poll(&mut self) {
        self.doc.poll();
        self.exports.poll();
        self.link.lang = self.look.lang;
        self.link.poll();
        self.link.follow(self.drive(), self.playback.looping);
        self.shots.poll();
        self.tools.design.poll();
        if self.tools.workspace.show {
            let request = self.workspace_request();
            self.tools.workspace.request(request);
        }
        self.tools.workspace.poll();
        self.tools.omct.poll();
    }

    /// When the workspace is shown, wait (at most thirty seconds) for its refinement at the
    /// pose shown (screenshots and tests want a settled picture).
    pub(crate) fn settle_workspace(&mut self) {
        if self.tools.workspace.show {
            let request = self.workspace_request();
            self.tools.workspace.request(request);
            self.tools
                .workspace
                .wait(std::time::Duration::from_secs(30));
        }
    }

    /// Roll, pitch, yaw alone and the roll–pitch map at the pose shown.
    pub(crate) fn orientation_reach(&mut self) -> crate::viewer::tools::reach::OrientationReach {
        let pose = self.pose();
        self.tools
            .reach
            .orientation(
                &self.doc.scenario().geometry,
                &self.doc.scenario().limits,
                &pose,
            )
            .clone()
    }

    /// The orientation the workspace is shown at: the pose's, or the one chosen.
    pub(crate) fn workspace_orientation(&self) -> [stewart_kinematics::Angle; 3] {
        self.tools.workspace.orientation_at(&self.pose())
    }

    /// The platform centre of the pose shown, metres.
    pub(crate) fn centre(&self) -> Vector3<f64> {
        self.doc.scenario().geometry.platform_centre(&self.pose())
    }

    /// What the workspace is computed for now.
    pub(crate) fn workspace_request(&self) -> crate::viewer::tools::workspace::Request {
        let w = &self.tools.workspace;
        let slice_at = w.show_slice.then(|| {
            if w.slice_follows {
                self.centre().z
            } else {
                w.slice_height
            }
        });
        crate::viewer::tools::workspace::Request {
            geometry: self.doc.scenario().geometry.clone(),
            limits: self.doc.scenario().limits,
            orientation: self.workspace_orientation(),
            slice_at,
            condition_max: self.doc.scenario().checks.condition_max,
            slice_stiffness: w.slice_by_stiffness.then(|| {
                self.doc
                    .scenario()
                    .dynamics
                    .actuator_stiffness
                    .unwrap_or(1.0)
            }),
            colour: stewart_render::theme::linear(self.theme().workspace),
        }
    }

    /// Duration of the trajectory, seconds.
    pub(crate) fn duration(&self) -> f64 {
        self.doc.scenario().motion.sampling.duration()
    }

    /// The pose shown now: while the link drives the platform, the pose it commands (what
    /// goes to the hardware, whatever the source); otherwise the one played or set.
    pub(crate) fn pose(&self) -> Pose {
        self.link
            .commanded_pose()
            .unwrap_or_else(|| self.played_pose())
    }

    /// The pose the viewer itself plays or holds (the trajectory at the playback time, or
    /// the manual pose): what the link follows unless it cues live vehicle motion.
    pub(crate) fn played_pose(&self) -> Pose {
        match self.playback.mode {
            MotionMode::Manual => self.playback.manual,
            MotionMode::Trajectory => {
                let start = self.doc.scenario().motion.sampling.start();
                self.doc
                    .scenario()
                    .motion
                    .trajectory
                    .pose_at(start + self.playback.time)
            }
        }
    }

    /// Show the next assembly mode of the legs (or servo angles) shown now: the platform
    /// in another pose with the same actuators, in manual mode.
    pub(crate) fn next_assembly_mode(&mut self) {
        let pose = self.pose();
        match self
            .tools
            .assembly
            .next(&self.doc.scenario().geometry, &pose)
        {
            Ok(next) => {
                self.playback.mode = MotionMode::Manual;
                self.playback.manual = next;
                self.tools.assembly_error = None;
            }
            Err(why) => {
                self.tools.assembly.shown = None;
                self.tools.assembly_error = Some(why);
            }
        }
    }

    /// The platform centre's path from the start of the trajectory up to now.
    pub(crate) fn path_until_now(&self) -> Vec<Vector3<f64>> {
        let now = self.doc.scenario().motion.sampling.start() + self.playback.time;
        self.doc.path_until(now)
    }

    /// The colour theme (presentation mode is always light).
    pub(crate) fn theme(&self) -> Theme {
        self.look.theme()
    }

    /// Whether the window must keep drawing: playback runs, the manual-mode history is
    /// still scrolling, an export runs, a report is being computed, or the link streams
    /// (its state is shown live).
    pub(crate) fn animating(&self) -> bool {
        self.playback.animating()
            || self.teleop.moving
            || self.exports.job.is_some()
            || self.report_pending()
            || self.link.connected()
            || self.shots.busy()
            || (self.tools.workspace.show && self.tools.workspace.busy())
            || self.tools.modes.animate
    }

    /// Whether the plot shows the rolling history of the values shown (manual mode, or
    /// the link following live vehicle motion) rather than the trajectory's.
    pub(crate) fn plot_rolls(&self) -> bool {
        self.playback.mode == MotionMode::Manual || self.link.cueing_live()
    }

    /// Move on by `dt` seconds of wall time: playback, and in manual mode (or while the
    /// link cues live vehicle motion) the history. Returns whether playback moved.
    pub fn advance(&mut self, dt: f64) -> bool {
        self.playback.clock += dt;
        self.tools.modes.advance(dt);
        if self.plot_rolls() {
            let pose = self.pose();
            let values = self.doc.scenario().geometry.actuator_values(&[pose]);
            let clock = self.playback.clock;
            self.playback.history.push(clock, values[0]);
        }
        if self.playback.mode == MotionMode::Manual {
            return false;
        }
        let duration = self.duration();
        self.playback.play(dt, duration)
    }

    /// Look from a standard direction (azimuth, elevation in degrees), keeping the framing.
    pub(crate) fn look_from(&mut self, azimuth_deg: f32, elevation_deg: f32) {
        let framed = default_camera(self.doc.scenario());
        self.look.camera = OrbitCamera {
            azimuth_deg,
            elevation_deg,
            ..framed
        };
    }

    /// Presentation mode's framing, called by the view with its `aspect` (width / height)
    /// each frame: on entering, the camera (its angles kept) is fitted to everything the
    /// motion sweeps (the pose shown, in manual mode) with the controls hidden, and fitted
    /// again while the layout settles or the window changes, as long as nobody moved it;
    /// on leaving, the camera and the plot's height from before come back.
    pub(crate) fn frame_for_presentation(&mut self, aspect: f32) {
        match (self.look.presentation, self.look.camera_before_presentation) {
            (true, None) => {
                self.look.camera_before_presentation = Some(self.look.camera);
                self.frame_presented(aspect);
            }
            (true, Some(_)) => {
                let refit = self
                    .look
                    .presentation_framed
                    .is_some_and(|(camera, framed)| {
                        camera == self.look.camera && (aspect / framed - 1.0).abs() > 0.01
                    });
                if refit {
                    self.frame_presented(aspect);
                }
            }
            (false, Some(before)) => {
                self.look.camera = before;
                self.look.camera_before_presentation = None;
                self.look.presentation_framed = None;
                self.look.plot_height_to_restore = self.look.plot_height_before_presentation.take();
            }
            (false, None) => {}
        }
    }

    /// Fit the camera, its angles kept, to the motion (or the pose shown) in a view of
    /// `aspect`, with the workspace when it is shown.
    fn frame_presented(&mut self, aspect: f32) {
        let before = self.look.camera;
        let times: Vec<f64> = self.doc.scenario().motion.times().collect();
        let overlays = stewart_render::Overlays {
            platform_axes: self.look.platform_axes,
            ..stewart_render::Overlays::default()
        };
        let angles = [before.azimuth_deg, before.elevation_deg];
        let mut camera = match self.playback.mode {
            MotionMode::Trajectory => crate::export::frames::motion_camera_from(
                self.doc.scenario(),
                &times,
                (&overlays, self.doc.parts()),
                aspect,
                0.0,
                angles,
            ),
            MotionMode::Manual => crate::export::frames::poses_camera(
                self.doc.scenario(),
                std::iter::once(self.pose()),
                (&overlays, self.doc.parts()),
                aspect,
                0.0,
                angles,
            ),
        };
        // The workspace's surface, when shown, is in the picture too.
        if self.tools.workspace.show
            && let Some(outcome) = &self.tools.workspace.latest
        {
            let points: Vec<glam::Vec3> = outcome
                .surface
                .vertices
                .iter()
                .map(|v| glam::Vec3::from(v.position))
                .collect();
            if let Some(wide) = OrbitCamera::fitting_points(
                angles[0],
                angles[1],
                &points,
                aspect,
                crate::export::frames::MOTION_MARGIN,
                0.0,
            ) && wide.distance > camera.distance
            {
                camera = wide;
            }
        }
        self.look.camera = camera;
        self.look.presentation_framed = Some((camera, aspect));
    }

    /// The platform's solids at the pose shown, as points for framing.
    fn scene_points(&self) -> Vec<glam::Vec3> {
        let frame = self
            .doc
            .scenario()
            .geometry
            .scene_frame(&self.pose(), Vec::new());
        let solids = stewart_render::Overlays {
            grid: false,
            path: false,
            labels: false,
            platform_axes: self.look.platform_axes,
            ..stewart_render::Overlays::default()
        };
        let mut points = Vec::new();
        stewart_render::DrawList::build(&frame, &self.theme(), &solids).solid_extent(&mut points);
        points
    }

    /// Fit the camera, its angles kept, to the platform at the pose shown in a view of
    /// `aspect` (the toolbar's *Fit*).
    pub(crate) fn fit_camera(&mut self, aspect: f32) {
        let c = self.look.camera;
        if let Some(fitted) = OrbitCamera::fitting_points(
            c.azimuth_deg,
            c.elevation_deg,
            &self.scene_points(),
            aspect,
            crate::export::frames::MOTION_MARGIN,
            0.0,
        ) {
            self.look.camera = fitted;
        }
    }

    /// Whether every solid of the platform at the pose shown projects inside a view of
    /// `aspect`.
    pub(crate) fn scene_in_view(&self, aspect: f32) -> bool {
        let matrix = self.look.camera.fitted_to(aspect).view_proj(aspect);
        self.scene_points().iter().all(|p| {
            let ndc = matrix.project_point3(*p);
            ndc.x.abs() <= 1.0 && ndc.y.abs() <= 1.0
        })
    }

    /// Called by the view each frame: after an edit of the platform (another geometry
    /// than the one last checked), a scene that left the view is fitted again.
    pub(crate) fn follow_geometry(&mut self, aspect: f32) {
        let params = self.doc.scenario().geometry.params();
        if self.look.geometry_seen.as_ref() == Some(params) {
            return;
        }
        let edited = self.look.geometry_seen.is_some();
        self.look.geometry_seen = Some(params.clone());
        if edited && !self.scene_in_view(aspect) {
            self.fit_camera(aspect);
        }
    }

    /// Step playback by one trajectory sample (`direction` ±1).
    pub(crate) fn step(&mut self, direction: f64) {
        let step = direction * self.doc.scenario().motion.sampling.step();
        let duration = self.duration();
        self.playback.step(step, duration);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use stewart_kinematics::model::geometry::PlateJoints;
    use stewart_kinematics::model::layout::Layout;

    #[test]
    fn playback_loops_and_stops() {
        let mut s = ViewerState::new(Scenario::seed());
        assert!(s.advance(4.0));
        assert!((s.playback.time - 4.0).abs() < 1e-12);
        s.advance(7.0);
        assert!((s.playback.time - 1.0).abs() < 1e-9, "{}", s.playback.time);
        s.playback.looping = false;
        s.advance(20.0);
        assert_eq!(s.playback.time, 10.0);
        assert!(!s.playback.playing);
        assert!(!s.advance(1.0));
        s.step(-1.0);
        assert!((s.playback.time - 9.99).abs() < 1e-12);
    }

    #[test]
    fn the_pose_follows_the_mode() {
        let mut s = ViewerState::new(Scenario::seed());
        s.playback.time = 2.5;
        assert_eq!(s.pose(), s.scenario().motion.trajectory.pose_at(2.5));
        s.playback.mode = MotionMode::Manual;
        s.playback.manual.position.z = 0.9;
        assert_eq!(s.pose().position.z, 0.9);
        assert_eq!(s.plot_samples().0.len(), 1001);
    }

    #[test]
    fn a_refused_edit_changes_nothing_and_says_why() {
        let mut s = ViewerState::new(Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}")));
        let before = s.scenario().clone();
        let layout = s.layout();
        // Two joints on one spot: the geometry constructor refuses it.
        let mut params = before.geometry.params().clone();
        let mut points = params.base.points();
        points[1] = points[0];
        params.base = PlateJoints::Points(points);
        s.set_geometry(params);
        assert_eq!(s.scenario(), &before);
        assert_eq!(
            s.layout(),
            layout,
            "the layout controls still show the geometry"
        );
        assert!(
            s.doc
                .edit_error
                .as_ref()
                .is_some_and(|(g, _)| *g == stewart_kinematics::io::settings::Group::Geometry)
        );
    }

    #[test]
    fn joint_angles_edited_one_by_one_leave_no_stale_layout() {
        let mut s = ViewerState::new(Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}")));
        assert!(matches!(s.layout(), Some(Layout::Paired { .. })));
        let key = stewart_kinematics::io::settings::find("geometry.base_angles_deg[0]")
            .unwrap_or_else(|e| panic!("{e}"));
        let now = key.get(s.scenario()).unwrap_or(0.0);
        s.apply(key, Some(now + 7.0));
        assert!(s.doc.edit_error.is_none());
        assert_eq!(
            s.layout(),
            None,
            "the angles follow no named layout any more"
        );
        s.set_layout(Layout::seed());
        assert_eq!(s.layout(), Some(Layout::seed()));
    }

    #[test]
    fn the_report_follows_the_scenario() {
        let mut s = ViewerState::new(Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}")));
        s.wait_for_report();
        assert!(s.report().is_some_and(|r| !r.architecture.singular));
        s.set_layout(Layout::seed());
        s.wait_for_report();
        assert!(s.report().is_some_and(|r| r.architecture.singular));
    }
}

/// The CAD parts' meshes a view draws: the files on a GPU; on a software rasteriser the
/// stand-ins, lighter while the view moves.
fn part_detail(software: bool, moving: bool) -> stewart_render::draw_list::PartDetail {
    use stewart_render::draw_list::PartDetail;
    match (software, moving) {
        (false, _) => PartDetail::File,
        (true, true) => PartDetail::Moving,
        (true, false) => PartDetail::Preview,
    }
}

#[cfg(test)]
mod part_detail_tests {
    use stewart_render::draw_list::PartDetail;

    #[test]
    fn a_moving_view_on_a_software_rasteriser_draws_the_lighter_stand_ins() {
        assert_eq!(super::part_detail(false, true), PartDetail::File);
        assert_eq!(super::part_detail(false, false), PartDetail::File);
        assert_eq!(super::part_detail(true, false), PartDetail::Preview);
        assert_eq!(super::part_detail(true, true), PartDetail::Moving);
    }
}
