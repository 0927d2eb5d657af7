//! Reference images of the panels (egui rendered with wgpu on lavapipe). The 3D view is
//! drawn by the renderer's own tests: kittest's render pass has no depth buffer, so the
//! view's area shows the message that no renderer is attached.
//!
//! `UPDATE_SNAPSHOTS=1 cargo test -p stewart_app --lib ui_tests::snapshots` re-blesses them.

use crate::viewer::state::ViewerState;
use crate::viewer::state::playback::MotionMode;
use egui_kittest::SnapshotOptions;
use stewart_kinematics::{Pose, Scenario};

/// Where the reference images live (relative to the app crate, where tests run).
const OUTPUT: &str = "tests/snapshots";

fn options() -> SnapshotOptions {
    // The default per-pixel colour tolerance; a handful of pixels may differ between
    // lavapipe versions in glyph anti-aliasing.
    SnapshotOptions::new()
        .output_path(OUTPUT)
        .max_failed_pixels(8)
}

#[test]
fn over_stroke_legs_take_their_3d_warning_colour_and_the_history_shows_them_leaving_the_stroke() {
    let state = ViewerState::new(Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}")));
    let mut h = super::sized_harness(state, egui::vec2(960.0, 600.0));
    h.state_mut().playback.playing = false;
    h.state_mut().playback.mode = MotionMode::Manual;
    // Move x out to 0.26 m and yaw to −41° over 3 s of (simulated) wall time.
    for k in 0..=60 {
        let s = f64::from(k) / 60.0;
        h.state_mut().playback.manual =
            Pose::from_xyz_rpy_deg([0.26 * s, 0.0, 0.8], [0.0, 0.0, -41.0 * s]);
        h.state_mut().advance(0.05);
    }
    h.run();
    let legs = h.state().legs().lengths;
    assert!(legs.iter().filter(|&&l| l > 1.30).count() == 2, "{legs:?}");
    h.snapshot_options("manual-over-stroke", &options());
}
