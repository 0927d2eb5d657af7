//! The viewer's panels driven through their accessibility labels (egui_kittest): each
//! test changes something as a user would and checks the state it edits.

mod appearance;
mod chinese;
mod cueing;
mod design;
mod dynamics;
mod export;
mod files;
mod legs;
mod link;
mod modes;
mod plot_fit;
mod reach;
mod rotary;
mod shots;
mod sidebar;
mod sliders;
mod snapshots;
mod state_helpers;
mod teleop;
mod trajectory;
mod workspace;

use crate::viewer::panels::viewer_ui;
use crate::viewer::state::ViewerState;
use crate::viewer::state::playback::MotionMode;
use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use stewart_kinematics::Scenario;

/// The viewer on a preset, 1280×800 logical pixels.
pub(crate) fn harness(scenario: &str) -> Harness<'static, ViewerState> {
    tall_harness(scenario, 800.0)
}

/// The viewer on a preset in a window `height` logical pixels high (widgets scrolled out
/// of sight have no accessibility node, so panels low in the list need a tall window).
pub(crate) fn tall_harness(scenario: &str, height: f32) -> Harness<'static, ViewerState> {
    let state = ViewerState::new(Scenario::preset(scenario).unwrap_or_else(|e| panic!("{e}")));
    harness_with(state, height)
}

/// The viewer on `state` in a window `height` logical pixels high.
pub(crate) fn harness_with(state: ViewerState, height: f32) -> Harness<'static, ViewerState> {
    sized_harness(state, egui::vec2(1280.0, height))
}

/// The viewer on `state` in a window of `size` logical pixels.
pub(crate) fn sized_harness(state: ViewerState, size: egui::Vec2) -> Harness<'static, ViewerState> {
    built_harness(state, size, true)
}

/// The viewer on `state`, with kittest's check that every widget has an accessible name on
/// or off (off only where a widget that is not ours lacks one: the file dialog's fields).
pub(crate) fn built_harness(
    state: ViewerState,
    size: egui::Vec2,
    accessibility_check: bool,
) -> Harness<'static, ViewerState> {
    // The system's Chinese font as the window loads it; kittest panics on a glyph no font
    // has, so no test passes with boxes for characters.
    // Up to eight frames to settle: a tall window with every section open lays out new
    // rows (a search result, a reach map) over a few passes.
    let mut h = Harness::builder()
        .renderer(egui_kittest::LazyRenderer::new(
            renderer_on_the_shared_device,
        ))
        .with_size(size)
        .with_max_steps(8)
        .with_accessibility_check(accessibility_check)
        .with_context_setup(|ctx| {
            crate::viewer::window::fonts::install(ctx);
        })
        // Each frame starts from a settled report (the check runs on a background job;
        // its arrival changes what the panels show): frames, and so where a click lands,
        // do not depend on the build's speed or the machine's load.
        .build_ui_state(
            |ui, state: &mut ViewerState| {
                state.wait_for_report();
                viewer_ui(ui, state);
            },
            state,
        );
    settle(&mut h);
    h
}

/// kittest's renderer on the process's one device ([`stewart_render::Gpu::shared`], the
/// device shots and exports use): a harness that rendered on a device of its own would
/// open and drop a device per test, which deadlocks some drivers when tests run on
/// several threads.
fn renderer_on_the_shared_device() -> egui_kittest::wgpu::WgpuTestRenderer {
    let gpu = stewart_render::Gpu::shared().unwrap_or_else(|e| panic!("{e}"));
    egui_kittest::wgpu::WgpuTestRenderer::from_setup(egui_wgpu::WgpuSetup::Existing(
        egui_wgpu::WgpuSetupExisting {
            instance: gpu.instance,
            adapter: gpu.adapter,
            device: gpu.device,
            queue: gpu.queue,
        },
    ))
}

/// With `STEWART_LOOK_DIR` set, the window as it is now, saved there as `name` to be
/// looked at.
pub(crate) fn look(h: &mut Harness<'_, ViewerState>, name: &str) {
    if let Some(dir) = std::env::var_os("STEWART_LOOK_DIR") {
        let image = h.render().unwrap_or_else(|e| panic!("{e}"));
        image
            .save(std::path::Path::new(&dir).join(name))
            .unwrap_or_else(|e| panic!("{e}"));
    }
}

/// Wait for the background report of the current scenario and draw again, so that the
/// panels show a settled state (the report is computed off the UI thread).
pub(crate) fn settle(h: &mut Harness<'static, ViewerState>) {
    h.state_mut().wait_for_report();
    h.run();
}

#[test]
fn manual_mode_sliders_move_the_pose_and_the_legs() {
    let mut h = harness("paired");
    h.get_by_label("Manual pose").click();
    h.run();
    assert_eq!(h.state().playback.mode, MotionMode::Manual);
    let before = h.state().legs().lengths;
    h.get_by_role_and_label(Role::Slider, "x (m)")
        .set_value_accesskit(0.12);
    h.get_by_role_and_label(Role::Slider, "yaw (°)")
        .set_value_accesskit(10.0);
    h.run();
    let pose = h.state().pose();
    assert!((pose.position.x - 0.12).abs() < 1e-9, "{pose:?}");
    assert!((pose.yaw.degrees() - 10.0).abs() < 1e-9);
    assert_ne!(h.state().legs().lengths, before);
    h.get_by_label("Home").click();
    h.run();
    assert_eq!(h.state().pose(), h.state().scenario().geometry.home_pose());
}

#[test]
fn keyboard_and_buttons_drive_playback() {
    let mut h = harness("seed");
    h.state_mut().playback.playing = false;
    h.state_mut().playback.time = 5.0;
    h.run();
    h.key_press(egui::Key::Space);
    h.run();
    assert!(h.state().playback.playing);
    h.key_press(egui::Key::ArrowRight);
    h.run();
    assert!(!h.state().playback.playing);
    assert!(
        (h.state().playback.time - 5.01).abs() < 1e-9,
        "{}",
        h.state().playback.time
    );
    h.key_press(egui::Key::Home);
    h.run();
    assert_eq!(h.state().playback.time, 0.0);
    h.get_by_label("Play").click();
    h.run();
    assert!(h.state().playback.playing);
    h.get_by_label("Top").click();
    h.run();
    assert_eq!(h.state().look.camera.elevation_deg, 89.5);
}

#[test]
fn the_diagnostics_say_when_the_geometry_is_singular() {
    let mut h = tall_harness("seed", 1600.0);
    // One line; the projective geometry on demand.
    const LINE: &str = "Singular at every pose: this layout's legs never determine the platform.";
    assert!(h.query_by_label(LINE).is_some());
    assert!(
        h.query_by_label_contains("This geometry is architecturally singular")
            .is_none()
    );
    h.get_by_label("Why").click();
    h.run();
    assert!(
        h.query_by_label_contains("This geometry is architecturally singular")
            .is_some()
    );
    // The button moves to the nearest sound layout: no longer singular, radii kept.
    let radius = h
        .state()
        .scenario()
        .geometry
        .plate_radius(stewart_kinematics::model::geometry::Plate::Base);
    h.get_by_label("Use the nearest sound layout (pairs 60° / 115°)")
        .click();
    h.run();
    settle(&mut h);
    assert!(h.state().report().is_some_and(|r| !r.architecture.singular));
    assert!(h.query_by_label(LINE).is_none());
    assert_eq!(
        h.state()
            .scenario()
            .geometry
            .plate_radius(stewart_kinematics::model::geometry::Plate::Base),
        radius
    );
    let h = harness("paired");
    assert!(h.query_by_label(LINE).is_none());
    assert!(
        h.query_by_label("No problem found along the trajectory.")
            .is_some()
    );
}

#[test]
fn geometry_edits_apply_or_are_refused_with_a_reason() {
    let mut h = harness("paired");
    h.get_by_label("Geometry").click();
    h.run();
    h.get_by_role_and_label(Role::Slider, "base radius (m)")
        .set_value_accesskit(1.2);
    h.run();
    assert_eq!(
        h.state()
            .scenario()
            .geometry
            .plate_radius(stewart_kinematics::model::geometry::Plate::Base),
        1.2
    );
    assert!((h.state().scenario().geometry.base_joints()[0].norm() - 1.2).abs() < 1e-12);
    // A maximum below the minimum is refused: the geometry stays, the reason is shown.
    h.get_by_role_and_label(Role::Slider, "leg max (m)")
        .set_value_accesskit(0.5);
    h.run();
    assert_eq!(h.state().scenario().geometry.stroke().max, Some(1.30));
    assert!(
        h.query_by_label_contains(
            "Not applied: `geometry.leg_max` = 0.5 refused: `leg_min` (0.55 m) must be less than `leg_max` (0.5 m)"
        )
        .is_some()
    );
    // The seed's staggered layout makes the geometry architecturally singular: the banner says so.
    h.get_by_label("Staggered (seed)").click();
    h.run();
    settle(&mut h);
    assert!(h.state().report().is_some_and(|r| r.architecture.singular));
    assert!(
        h.query_by_label_contains("Singular at every pose")
            .is_some()
    );
}
