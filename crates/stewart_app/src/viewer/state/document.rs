//! The scenario being edited and what must change with it, as one part with its own
//! invariants: every change goes through [`Document::edit`] (on a copy, validated as files
//! are, recorded for undo, then everything derived rebuilt) or replaces the whole scenario
//! ([`Document::replace`], [`Document::undo`], [`Document::redo`]); the derived cache
//! (plot samples, layout, the pre-flight report) always belongs to the scenario shown; the
//! scenario as loaded or saved last tells whether titles say "edited".
//!
//! The viewer's other parts (playback, camera, link) react to a replaced scenario in
//! [`crate::viewer::state::ViewerState`]; panels that only edit the scenario can take this part
//! alone.

use stewart_kinematics::analysis::sound_layout;
use stewart_kinematics::io::settings::{self, Group, Setting, TrajectoryChoice};
use stewart_kinematics::model::link_settings::LinkSettings;
use stewart_kinematics::{CheckReport, GeometryParams, Scenario, model::layout::Layout};

use std::path::{Path, PathBuf};
use std::sync::Arc;

use stewart_render::appearance::parts::{PartSet, platform_size};

use crate::i18n::Lang;
use crate::viewer::error::ViewerError;
use crate::viewer::state::derived::Derived;
use crate::viewer::state::undo::Undo;
use crate::viewer::state::vehicle::VehicleSource;

/// The scenario, its undo history, what is derived from it, and the last refused edit.
pub(crate) struct Document {
    scenario: Scenario,
    /// The scenario as loaded (preset or file) or saved last.
    as_loaded: Scenario,
    derived: Derived,
    /// The edits that can be undone and redone.
    pub(crate) undo: Undo,
    /// Why the last edit was refused (the scenario then stayed as it was).
    pub(crate) edit_error: Option<(Group, ViewerError)>,
    /// The vehicle recording loaded last and the motion cued from it.
    vehicle: Option<VehicleSource>,
    /// The CAD parts the scenario's `[appearance]` names, those that read.
    parts: PartSet,
    /// Why a part the scenario names is not drawn (its file went missing, say), shown in
    /// the Appearance section until the parts read again.
    parts_error: Option<ViewerError>,
    /// The folder of the scenario's file (where the mesh dialog starts). The document
    /// names part files by their absolute paths: undo, and a scenario from another
    /// folder, name the same files.
    folder: PathBuf,
}

impl Document {
    /// A document showing `scenario`, as loaded, its part files named from `folder` (its
    /// file's).
    pub(crate) fn new(scenario: Scenario, folder: PathBuf) -> Self {
        let mut scenario = scenario;
        scenario.appearance = crate::appearance::anchored(&scenario.appearance, &folder);
        let mut doc = Self {
            derived: Derived::new(&scenario),
            as_loaded: scenario.clone(),
            scenario,
            undo: Undo::default(),
            edit_error: None,
            vehicle: None,
            parts: PartSet::none(),
            parts_error: None,
            folder,
        };
        doc.reload_parts();
        doc
    }

    /// The scenario is now the file in `folder` (saved there; its part files, named by
    /// their absolute paths here, stay the same files).
    pub(crate) fn moved_to(&mut self, folder: PathBuf) {
        self.folder = folder;
    }

    /// The folder of the scenario's file.
    pub(crate) fn folder(&self) -> &Path {
        &self.folder
    }

    /// The CAD parts read for the scenario shown.
    pub(crate) fn parts(&self) -> &PartSet {
        &self.parts
    }

    /// Why a part the scenario names is not drawn, if one is not.
    pub(crate) fn parts_error(&self) -> Option<&ViewerError> {
        self.parts_error.as_ref()
    }

    /// Read the scenario's parts (files read before and unchanged are kept); those that
    /// fail are not drawn, the first one's reason kept for the Appearance section.
    fn reload_parts(&mut self) {
        let (parts, errors) =
            crate::appearance::read(&self.scenario, &self.folder, Some(&self.parts));
        self.parts = parts;
        self.parts_error = errors
            .into_iter()
            .next()
            .map(|e| ViewerError::Part(Arc::new(e)));
    }

    /// The scenario shown.
    pub(crate) fn scenario(&self) -> &Scenario {
        &self.scenario
    }

    /// Change the scenario: `change` works on a copy; when it succeeds and every value
    /// lies in its accepted range, the copy replaces the scenario (one undo step) and
    /// everything derived is rebuilt; otherwise the reason is recorded under `group` and
    /// nothing changes. Returns whether the change was applied.
    pub(crate) fn edit(
        &mut self,
        group: Group,
        change: impl FnOnce(&mut Scenario) -> Result<(), ViewerError>,
    ) -> bool {
        self.try_edit(group, change).is_ok()
    }

    /// [`Document::edit`], returning why a refused change was refused.
    pub(crate) fn try_edit(
        &mut self,
        group: Group,
        change: impl FnOnce(&mut Scenario) -> Result<(), ViewerError>,
    ) -> Result<(), ViewerError> {
        let mut edited = self.scenario.clone();
        let mut recued = None;
        let mut parts = None;
        let checked = change(&mut edited)
            .and_then(|()| match settings::out_of_range(&edited) {
                Some((setting, reason)) => Err(ViewerError::OutOfRange {
                    key: setting.key.to_owned(),
                    reason,
                }),
                None => Ok(()),
            })
            .and_then(|()| {
                // A motion cued from a vehicle recording is cued again for the edited
                // scenario (not after an edit of the motion itself).
                if let Some(v) = self.cued_vehicle().filter(|_| group != Group::Trajectory) {
                    let again = v.recue(&edited)?;
                    edited.motion = again.motion.clone();
                    recued = Some(again);
                }
                Ok(())
            })
            .and_then(|()| {
                // New part files or another actuator kind: the parts are read (and
                // judged) before the edit is kept. A part this edit changed that fails
                // refuses it (the picture stays); one that failed before does not.
                let kind = |s: &Scenario| s.geometry.actuator().kind();
                if edited.appearance != self.scenario.appearance
                    || kind(&edited) != kind(&self.scenario)
                {
                    let (read, mut errors) =
                        crate::appearance::read(&edited, &self.folder, Some(&self.parts));
                    let changed = |e: &stewart_render::appearance::parts::PartError| {
                        edited.appearance.part(e.part) != self.scenario.appearance.part(e.part)
                    };
                    if let Some(k) = errors.iter().position(changed) {
                        return Err(ViewerError::Part(Arc::new(errors.swap_remove(k))));
                    }
                    let first = errors.into_iter().next();
                    parts = Some((read, first.map(|e| ViewerError::Part(Arc::new(e)))));
                } else if edited.appearance.parts().next().is_some()
                    && platform_size(&edited.geometry) != platform_size(&self.scenario.geometry)
                {
                    // A platform of another size judges its parts' sizes again (a part
                    // now absurd is left out and said, the edit kept).
                    let (read, errors) =
                        crate::appearance::read(&edited, &self.folder, Some(&self.parts));
                    let first = errors.into_iter().next();
                    parts = Some((read, first.map(|e| ViewerError::Part(Arc::new(e)))));
                }
                Ok(())
            });
        match checked {
            Ok(()) => {
                self.undo.record(&self.scenario);
                self.scenario = edited;
                self.edit_error = None;
                if recued.is_some() {
                    self.vehicle = recued;
                }
                if let Some((read, error)) = parts {
                    self.parts = read;
                    self.parts_error = error;
                }
                self.derived.rebuild(&self.scenario);
                Ok(())
            }
            Err(reason) => {
                self.edit_error = Some((group, reason.clone()));
                Err(reason)
            }
        }
    }

    /// Play the motion cued from a vehicle recording (`samples`, from the file `name`),
    /// one edit; refused with the reason when the scenario cannot cue it.
    pub(crate) fn play_vehicle(
        &mut self,
        name: &str,
        samples: Arc<Vec<(f64, stewart_kinematics::analysis::cueing::VehicleMotion)>>,
    ) -> Result<(), ViewerError> {
        let source = VehicleSource::new(name, samples, &self.scenario)?;
        let motion = source.motion.clone();
        self.try_edit(Group::Trajectory, |s| {
            s.motion = motion;
            Ok(())
        })?;
        self.vehicle = Some(source);
        Ok(())
    }

    /// The vehicle recording whose cued motion is the scenario's now (`None` when the
    /// motion is another: none was loaded, or an undo brought another motion back).
    pub(crate) fn cued_vehicle(&self) -> Option<&VehicleSource> {
        self.vehicle
            .as_ref()
            .filter(|v| v.motion == self.scenario.motion)
    }

    /// Change the `[link]` table: `change` works on a copy, kept only when the table is
    /// sound (else the reason, naming the key). A kept change is an undo step with nothing
    /// derived to rebuild (nothing depends on `[link]`); the same table records nothing.
    pub(crate) fn edit_link(
        &mut self,
        change: impl FnOnce(&mut LinkSettings),
    ) -> Result<(), ViewerError> {
        let mut link = self.scenario.link.clone();
        change(&mut link);
        if let Some(p) = link.problem() {
            return Err(ViewerError::OutOfRange {
                key: p.key,
                reason: p.reason,
            });
        }
        if link != self.scenario.link {
            self.undo.record(&self.scenario);
            self.scenario.link = link;
        }
        Ok(())
    }

    /// Write one setting (`None`: switch an optional one off).
    pub(crate) fn apply(&mut self, setting: &Setting, value: Option<f64>) -> bool {
        self.edit(setting.group, |s| Ok(setting.set(s, value)?))
    }

    /// Replace the geometry's numbers.
    pub(crate) fn set_geometry(&mut self, params: GeometryParams) -> bool {
        self.edit(Group::Geometry, |s| {
            s.geometry = stewart_kinematics::Geometry::new(params)?;
            Ok(())
        })
    }

    /// Rewrite all twelve joint angles from a named layout (a plate given as coordinates
    /// goes back to a circle of its size).
    pub(crate) fn set_layout(&mut self, layout: Layout) -> bool {
        let params = sound_layout::params_with_layout(&self.scenario.geometry, layout);
        self.set_geometry(params)
    }

    /// Switch to another kind of trajectory with its default numbers.
    pub(crate) fn switch_trajectory(&mut self, choice: TrajectoryChoice) -> bool {
        self.edit(Group::Trajectory, |s| {
            settings::switch_trajectory(s, choice);
            Ok(())
        })
    }

    /// Show another scenario (a preset or file loaded), its part files named from
    /// `folder`: one undo step of its own.
    pub(crate) fn replace(&mut self, scenario: Scenario, folder: PathBuf) {
        let mut scenario = scenario;
        scenario.appearance = crate::appearance::anchored(&scenario.appearance, &folder);
        self.undo.record(&self.scenario);
        self.undo.seal();
        self.as_loaded = scenario.clone();
        self.folder = folder;
        self.put(scenario);
        self.reload_parts();
    }

    /// Go back one edit; the scenario it left, or `None` when there was none.
    pub(crate) fn undo(&mut self) -> Option<Scenario> {
        let before = self.undo.undo(&self.scenario)?;
        Some(self.put(before))
    }

    /// Do again the edit undone last; the scenario it left, or `None` when there was none.
    pub(crate) fn redo(&mut self) -> Option<Scenario> {
        let after = self.undo.redo(&self.scenario)?;
        Some(self.put(after))
    }

    /// Show `scenario` (derived rebuilt, no refusal pending); the one it replaced. A
    /// vehicle recording stays with the motion cued from it: when the scenario an undo
    /// or redo brings back plays the recording as its own settings cue it, the recording
    /// plays on (and later edits cue it again).
    fn put(&mut self, scenario: Scenario) -> Scenario {
        let old = std::mem::replace(&mut self.scenario, scenario);
        self.edit_error = None;
        if let Some(v) = &self.vehicle
            && v.motion != self.scenario.motion
            // Cheap first: a motion cued from it has one sample per recorded sample.
            && v.motion.sampling == self.scenario.motion.sampling
            && let Ok(again) =
                VehicleSource::new(&v.name, Arc::clone(&v.samples), &self.scenario)
            && again.motion == self.scenario.motion
        {
            self.vehicle = Some(again);
        }
        if old.appearance != self.scenario.appearance
            || old.geometry.actuator().kind() != self.scenario.geometry.actuator().kind()
        {
            self.reload_parts();
        }
        self.derived.rebuild(&self.scenario);
        old
    }

    /// The scenario's name marked as edited (in `lang`) when the scenario differs from the
    /// preset or file it came from (the window's title).
    pub(crate) fn marked_name(&self, lang: Lang) -> String {
        if self.scenario == self.as_loaded {
            self.scenario.name.clone()
        } else {
            lang.fmt("scenario.edited_name", &[("name", &self.scenario.name)])
        }
    }

    /// What was saved is now what the scenario came from (its title loses "edited").
    pub(crate) fn mark_saved(&mut self) {
        self.as_loaded = self.scenario.clone();
    }

    /// The nearest layout that is not architecturally singular (see
    /// [`stewart_kinematics::analysis::sound_layout`]): the layout and the largest joint move, degrees.
    pub(crate) fn sound_layout(&mut self) -> Option<(Layout, f64)> {
        self.derived
            .sound_layout(&self.scenario)
            .map(|s| (s.layout, s.moved_deg))
    }

    /// Whether some plotted value of the trajectory lies beyond a stroke or servo limit.
    pub(crate) fn beyond_limits(&self) -> bool {
        self.derived.beyond_limits
    }

    /// The named layout of the joint angles, `None` when they were edited one by one
    /// into no named layout.
    pub(crate) fn layout(&self) -> Option<Layout> {
        self.derived.layout
    }

    /// Times and leg lengths for the plot (thinned to at most
    /// [`crate::viewer::state::derived::PLOT_SAMPLES`]).
    pub(crate) fn plot_samples(&self) -> (&[f64], &[[f64; 6]]) {
        (&self.derived.times, &self.derived.lengths)
    }

    /// The actuator efforts at the plotted times (N or N·m), when there is a payload.
    pub(crate) fn plot_efforts(&self) -> Option<(&[f64], &[[f64; 6]])> {
        let efforts = self.derived.efforts.as_ref()?;
        Some((&self.derived.times, efforts))
    }

    /// The pre-flight report of the trajectory, once computed (off the UI thread).
    pub(crate) fn report(&self) -> Option<&CheckReport> {
        self.derived.report()
    }

    /// Whether the report is still being computed.
    pub(crate) fn report_pending(&self) -> bool {
        self.derived.report_pending()
    }

    /// Block until the report is in (screenshots and tests want a settled picture).
    pub(crate) fn wait_for_report(&mut self) {
        self.derived.wait_for_report();
    }

    /// The platform centre's path over the sampled trajectory up to time `now`.
    pub(crate) fn path_until(&self, now: f64) -> Vec<nalgebra::Vector3<f64>> {
        let done = self.derived.times.partition_point(|&t| t <= now);
        self.derived.centres[..done.min(self.derived.centres.len())].to_vec()
    }

    /// Collect a finished report; never blocks.
    pub(crate) fn poll(&mut self) {
        self.derived.poll();
    }
}
