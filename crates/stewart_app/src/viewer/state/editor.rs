//! The scenario's one edit path as the panels receive it: the document (validation, undo,
//! what is derived from the scenario) with the playback, whose time an edit that shortens
//! the trajectory brings back within it, and the language and panel state the controls
//! are drawn in. A panel that edits the scenario takes an [`Editor`], not the whole
//! viewer state.

use stewart_kinematics::io::settings::{Group, Setting, TrajectoryChoice};
use stewart_kinematics::{Scenario, model::layout::Layout};

use crate::i18n::Lang;
use crate::viewer::error::ViewerError;
use crate::viewer::state::document::Document;
use crate::viewer::state::playback::Playback;

/// The parts of the viewer a scenario edit touches.
pub(crate) struct Editor<'a> {
    /// The scenario, its history, what is derived from it and the last refused edit.
    pub(crate) doc: &'a mut Document,
    /// Kept within the trajectory after each edit.
    playback: &'a mut Playback,
    /// The interface's language.
    pub(crate) lang: Lang,
    /// Whether collapsible parts start open (`--expand-panels`).
    pub(crate) expand: bool,
}

impl<'a> Editor<'a> {
    /// An editor of `doc` that keeps `playback` within the trajectory.
    pub(crate) fn new(
        doc: &'a mut Document,
        playback: &'a mut Playback,
        lang: Lang,
        expand: bool,
    ) -> Self {
        Self {
            doc,
            playback,
            lang,
            expand,
        }
    }

    /// The scenario edited.
    pub(crate) fn scenario(&self) -> &Scenario {
        self.doc.scenario()
    }

    /// Change the scenario through the document's one edit path ([`Document::edit`]);
    /// playback stays within the new duration. Returns whether the change was applied.
    pub(crate) fn edit(
        &mut self,
        group: Group,
        change: impl FnOnce(&mut Scenario) -> Result<(), ViewerError>,
    ) -> bool {
        let applied = self.doc.edit(group, change);
        self.keep_time_in_range();
        applied
    }

    /// Write one setting (`None`: switch an optional one off).
    pub(crate) fn apply(&mut self, setting: &Setting, value: Option<f64>) {
        self.doc.apply(setting, value);
        self.keep_time_in_range();
    }

    /// Switch to another kind of trajectory with its default numbers.
    pub(crate) fn switch_trajectory(&mut self, choice: TrajectoryChoice) {
        self.doc.switch_trajectory(choice);
        self.keep_time_in_range();
    }

    /// Rewrite all twelve joint angles from a named layout.
    pub(crate) fn set_layout(&mut self, layout: Layout) {
        self.doc.set_layout(layout);
    }

    /// Playback time within the trajectory's duration.
    pub(crate) fn keep_time_in_range(&mut self) {
        let duration = self.doc.scenario().motion.sampling.duration();
        self.playback.time = self.playback.time.clamp(0.0, duration);
    }
}
