//! What the tests ask of the state in one call beyond what the panels do (edits a panel
//! makes through its parts, reads of what is derived): an `impl` kept with the tests, so
//! the state itself has no test-only methods.

use stewart_kinematics::io::settings::Setting;
use stewart_kinematics::model::layout::Layout;
use stewart_kinematics::model::leg_solution::LegSolution;
use stewart_kinematics::model::link_settings::LinkSettings;
use stewart_kinematics::{CheckReport, GeometryParams};

use crate::viewer::state::ViewerState;

impl ViewerState {
    /// Change the `[link]` table: `change` works on a copy, kept only when the table is
    /// sound (else the reason shows in the Link panel).
    pub(crate) fn edit_link(&mut self, change: impl FnOnce(&mut LinkSettings)) {
        self.link_error = self.doc.edit_link(change).err();
    }

    /// [`Editor::apply`]: write one setting (`None`: switch an optional one off).
    pub(crate) fn apply(&mut self, setting: &Setting, value: Option<f64>) {
        self.editor().apply(setting, value);
    }

    /// Replace the geometry's numbers.
    pub(crate) fn set_geometry(&mut self, params: GeometryParams) {
        self.doc.set_geometry(params);
    }

    /// Rewrite all twelve joint angles from a named layout.
    pub(crate) fn set_layout(&mut self, layout: Layout) {
        self.doc.set_layout(layout);
    }

    /// The named layout of the joint angles, `None` when they were edited one by one
    /// into no named layout.
    pub(crate) fn layout(&self) -> Option<Layout> {
        self.doc.layout()
    }

    /// Times and leg lengths for the plot.
    pub(crate) fn plot_samples(&self) -> (&[f64], &[[f64; 6]]) {
        self.doc.plot_samples()
    }

    /// The pre-flight report of the trajectory, once computed (off the UI thread).
    pub(crate) fn report(&self) -> Option<&CheckReport> {
        self.doc.report()
    }

    /// Each manual-pose coordinate's reachable interval within its slider's `bounds` (pose
    /// coordinates: metres, radians), the others held.
    pub(crate) fn slider_reach(&mut self, bounds: [[f64; 2]; 6]) -> [Option<[f64; 2]>; 6] {
        let pose = self.pose();
        self.tools.reach.sliders(
            &self.doc.scenario().geometry,
            &self.doc.scenario().limits,
            &pose,
            bounds,
        )
    }

    /// Legs of the pose shown now.
    pub(crate) fn legs(&self) -> LegSolution {
        self.doc.scenario().geometry.inverse(&self.pose())
    }
}
