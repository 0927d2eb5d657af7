//! The Legs panel's distance-to-singularity gauge.

use crate::viewer::state::ViewerState;
use crate::viewer::state::playback::MotionMode;
use egui_kittest::kittest::Queryable;
use stewart_kinematics::{Pose, Scenario};

#[test]
fn the_gauge_shows_the_inverse_condition_number_and_falls_toward_a_singularity() {
    let state = ViewerState::new(Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}")));
    let mut h = super::harness_with(state, 1600.0);
    h.state_mut().playback.mode = MotionMode::Manual;
    let gauge = |h: &mut egui_kittest::Harness<'static, ViewerState>, pose: Pose| {
        h.state_mut().playback.manual = pose;
        h.run();
        let g = &h.state().scenario().geometry;
        let k = g
            .actuated_conditioning(&pose)
            .and_then(|c| c.condition_number)
            .unwrap_or_else(|| panic!("singular"));
        let text = format!("1/κ = {:.3}", 1.0 / k);
        assert!(
            h.query_by_label_contains(&text).is_some(),
            "no gauge reading {text}"
        );
        1.0 / k
    };
    assert!(h.query_by_label("Distance to singularity").is_some());
    let home = gauge(&mut h, Pose::from_xyz_rpy_deg([0.0, 0.0, 0.8], [0.0; 3]));
    // A large yaw twists the paired legs toward a singular configuration.
    let twisted = gauge(
        &mut h,
        Pose::from_xyz_rpy_deg([0.0, 0.0, 0.8], [0.0, 0.0, 55.0]),
    );
    assert!(twisted < home, "{twisted} vs {home}");
}
