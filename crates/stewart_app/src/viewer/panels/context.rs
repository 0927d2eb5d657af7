//! What every panel may read and none may change in one frame (as rerun's views get a
//! `ViewContext`): built once by [`super::viewer_ui`] from the state, handed to the panels
//! beside the parts each one edits.

use stewart_kinematics::Pose;

use crate::i18n::Lang;
use crate::viewer::state::ViewerState;

/// The frame's read-only context for the panels.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PanelContext {
    /// The interface's language.
    pub(crate) lang: Lang,
    /// Whether collapsible sections start open.
    pub(crate) expand: bool,
    /// The pose shown.
    pub(crate) pose: Pose,
    /// The stream time shown: the trajectory's start plus the playback time, seconds.
    pub(crate) now: f64,
}

impl PanelContext {
    /// The context of the frame `state` shows now.
    pub(crate) fn of(state: &ViewerState) -> Self {
        Self {
            lang: state.look.lang,
            expand: state.look.expand_panels,
            pose: state.pose(),
            now: state.doc.scenario().motion.sampling.start() + state.playback.time,
        }
    }
}
