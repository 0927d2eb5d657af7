//! The background computations the panels ask for: one [`job`] runner (newest request
//! wins, the work in flight cancelled), the [`workspace`] surface and slice and its
//! [`certified`] bracket, the [`design`] search, [`reach`] at the pose shown, the Dynamics
//! panel's [`mode_view`], the Motion cueing panel's [`omct`] test, and the [`assembly`]
//! modes of the legs shown.

pub(crate) mod assembly;
pub(crate) mod certified;
pub(crate) mod design;
pub(crate) mod job;
pub(crate) mod mode_view;
pub(crate) mod omct;
pub(crate) mod reach;
pub(crate) mod workspace;

/// The background tools of one viewer, a part of its state.
#[derive(Default)]
pub struct Tools {
    /// The stroke an envelope of poses needs.
    pub(crate) design: design::DesignTool,
    /// The workspace surface and the conditioning slice in the 3D view.
    pub workspace: workspace::WorkspaceTool,
    /// The assembly modes of the legs shown, stepped through one by one.
    pub(crate) assembly: assembly::AssemblyBrowser,
    /// Why the last step to another assembly mode found none.
    pub(crate) assembly_error: Option<assembly::NoMode>,
    /// Reach at the pose shown (orientation panel, manual sliders), cached.
    pub(crate) reach: reach::ReachCache,
    /// The Dynamics panel's mode viewer (the 3D view swinging along a mode).
    pub(crate) modes: mode_view::ModeView,
    /// The Motion cueing panel's objective test of the cueing shown.
    pub(crate) omct: omct::OmctTool,
}
