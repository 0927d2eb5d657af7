//! The Scenario panel: presets, opening and saving files, forgetting the saved session.

use egui::accesskit::Role;
use egui_kittest::kittest::Queryable;
use stewart_kinematics::Scenario;

use crate::harness;

fn tempdir() -> tempfile::TempDir {
    tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn choosing_a_preset_loads_it() {
    let mut h = harness("seed");
    h.get_by_role_and_label(Role::ComboBox, "Preset").click();
    h.run();
    h.get_by_label("figure8").click();
    h.run();
    let expected = Scenario::preset("figure8").unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(h.state().scenario(), &expected);
    assert_eq!(h.state().playback.time, 0.0);
    assert_eq!(
        h.state().plot_samples().0.len(),
        expected.motion.sampling.len()
    );
    // The motion panel now offers the figure-eight's own numbers.
    assert!(
        h.query_by_role_and_label(Role::Slider, "x half-width (m)")
            .is_some()
    );
    assert!(
        h.query_by_role_and_label(Role::Slider, "x amplitude (m)")
            .is_none()
    );
}

#[test]
fn a_broken_file_shows_its_error_and_changes_nothing() {
    let dir = tempdir();
    let path = dir.path().join("broken.toml");
    std::fs::write(
        &path,
        "[geometry]\nbase_radius = -1.0\nplatform_radius = 0.6\nhome_height = 0.8\n\
         base_angles_deg = [0, 60, 120, 180, 240, 300]\nplatform_angles_deg = [30, 90, 150, 210, 270, 330]\n",
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let mut h = harness("paired");
    h.state_mut().playback.time = 3.0;
    h.run();
    let before = h.state().scenario().clone();
    let field = h.get_by_role_and_label(Role::TextInput, "File");
    field.focus();
    field.type_text(&path.display().to_string());
    h.run();
    h.get_by_label("Open").click();
    h.run();
    assert_eq!(h.state().scenario(), &before);
    assert_eq!(h.state().playback.time, 3.0);
    let message = format!(
        "{}, line 2, column 15: `base_radius` must be positive, got -1",
        path.display()
    );
    assert!(
        h.query_by_label_contains(&message).is_some(),
        "no `{message}` shown"
    );
    // A file that does not exist says so, and still changes nothing.
    h.state_mut().files.path = dir.path().join("missing.toml").display().to_string();
    h.run();
    h.get_by_label("Open").click();
    h.run();
    assert_eq!(h.state().scenario(), &before);
    assert!(h.query_by_label_contains("missing.toml").is_some());
}

#[test]
fn a_saved_scenario_opens_as_it_was() {
    let dir = tempdir();
    let path = dir.path().join("mine.toml");
    let mut h = harness("paired");
    h.get_by_label("Geometry").click();
    h.run();
    h.get_by_role_and_label(Role::Slider, "home height (m)")
        .set_value_accesskit(0.9);
    h.run();
    h.state_mut().files.path = path.display().to_string();
    h.run();
    h.get_by_label("Save").click();
    h.run();
    assert!(h.query_by_label_contains("Saved to").is_some());
    let saved = h.state().scenario().clone();
    h.get_by_role_and_label(Role::ComboBox, "Preset").click();
    h.run();
    h.get_by_label("seed").click();
    h.run();
    assert_ne!(h.state().scenario().geometry, saved.geometry);
    h.get_by_label("Open").click();
    h.run();
    assert_eq!(h.state().scenario().geometry, saved.geometry);
    assert_eq!(h.state().scenario().geometry.home_height(), 0.9);
    assert_eq!(h.state().scenario().motion, saved.motion);
}

#[test]
fn reset_to_defaults_forgets_the_saved_session_and_the_look() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    std::fs::write(stewart_app::viewer::session::file_in(dir.path()), "{}")
        .unwrap_or_else(|e| panic!("{e}"));
    let mut state = stewart_app::viewer::ViewerState::new(
        Scenario::preset("seed").unwrap_or_else(|e| panic!("{e}")),
    );
    state.session.folder = Some(dir.path().to_path_buf());
    state.look.light_theme = true;
    state.look.labels = false;
    state.look.camera.azimuth_deg = 10.0;
    let mut h = crate::harness_with(state, 800.0);
    h.get_by_label("Reset to defaults").click();
    h.run();
    assert!(!stewart_app::viewer::session::file_in(dir.path()).exists());
    let look = &h.state().look;
    assert!(!look.light_theme && look.labels);
    assert_eq!(look.camera.azimuth_deg, 135.0);
    assert!(
        h.state().session.forgotten,
        "nothing is saved at exit after a reset"
    );
}
