//! The Scenario panel: presets, opening and saving files, forgetting the saved session.

use egui::accesskit::Role;
use egui_kittest::kittest::Queryable;
use stewart_kinematics::Scenario;

use super::harness;

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
    // The session remembers the file, and at the next start it is the file open (Ctrl+S
    // saves it without asking where).
    let full = std::path::absolute(&path).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(h.state().session.origin, full.display().to_string());
    let mut next = crate::viewer::state::ViewerState::new(h.state().scenario().clone());
    next.remember_file(&h.state().session.origin);
    assert_eq!(next.files.current.as_deref(), Some(full.as_path()));
    next.remember_file("preset seed");
    assert_eq!(next.files.current.as_deref(), Some(full.as_path()));
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
    std::fs::write(crate::viewer::state::session::file_in(dir.path()), "{}")
        .unwrap_or_else(|e| panic!("{e}"));
    let mut state =
        crate::viewer::ViewerState::new(Scenario::preset("seed").unwrap_or_else(|e| panic!("{e}")));
    state.session.folder = Some(dir.path().to_path_buf());
    state.look.light_theme = true;
    state.look.labels = false;
    state.look.camera.azimuth_deg = 10.0;
    let mut h = super::harness_with(state, 800.0);
    h.get_by_label("Reset to defaults").click();
    h.run();
    assert!(!crate::viewer::state::session::file_in(dir.path()).exists());
    let look = &h.state().look;
    assert!(!look.light_theme && look.labels);
    assert_eq!(look.camera.azimuth_deg, 135.0);
    assert!(
        h.state().session.forgotten,
        "nothing is saved at exit after a reset"
    );
}

/// A file dropped on the window, as egui-winit hands it over.
#[derive(Debug)]
pub(crate) struct Dropped(std::path::PathBuf);

impl egui::DroppedFile for Dropped {
    fn path(&self) -> &std::path::Path {
        &self.0
    }

    fn bytes(&self) -> Result<Vec<u8>, String> {
        std::fs::read(&self.0).map_err(|e| e.to_string())
    }
}

pub(crate) fn drop_file(
    h: &mut egui_kittest::Harness<'_, crate::viewer::ViewerState>,
    path: &std::path::Path,
) {
    h.input_mut()
        .dropped_files
        .push(std::sync::Arc::new(Dropped(path.to_path_buf())));
    h.run();
}

#[test]
fn a_pose_table_or_a_scenario_dropped_on_the_window_opens() {
    let dir = tempdir();
    let poses = dir.path().join("poses.csv");
    std::fs::write(
        &poses,
        "t,x,y,z,roll_deg,pitch_deg,yaw_deg\n0,0,0,0.8,0,0,0\n1,0.05,0,0.82,3,0,0\n2.5,0,0.04,0.8,0,-2,5\n",
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let mut h = harness("paired");
    let before = h.state().scenario().clone();
    // While a file hovers, the window says what dropping it does.
    h.input_mut().hovered_files.push(egui::HoveredFile {
        path: Some(poses.clone()),
        mime: String::new(),
    });
    // (egui repaints while files hover: one frame, not run until settled.)
    h.step();
    super::look(&mut h, "drop-note.png");
    h.input_mut().hovered_files.clear();
    // Before: a dropped file did nothing.
    drop_file(&mut h, &poses);
    let motion = &h.state().scenario().motion;
    assert_eq!(motion.sampling.len(), 3);
    assert_eq!(motion.sampling.duration(), 2.5);
    assert_eq!(h.state().scenario().geometry, before.geometry);
    assert!(
        h.query_by_label_contains("Playing 3 poses over 2.50 s from")
            .is_some(),
        "{:?}",
        h.state().files.status
    );
    // One Ctrl+Z takes it back.
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    h.run();
    assert_eq!(h.state().scenario(), &before);

    // A scenario replaces the platform.
    let file = dir.path().join("figure.toml");
    let figure = Scenario::preset("figure8").unwrap_or_else(|e| panic!("{e}"));
    std::fs::write(&file, figure.to_toml()).unwrap_or_else(|e| panic!("{e}"));
    drop_file(&mut h, &file);
    assert_eq!(h.state().scenario().geometry, figure.geometry);
    assert_eq!(h.state().files.current.as_deref(), Some(file.as_path()));

    // Anything else is refused with a note, and changes nothing.
    let notes = dir.path().join("notes.txt");
    std::fs::write(&notes, "hello").unwrap_or_else(|e| panic!("{e}"));
    let now = h.state().scenario().clone();
    drop_file(&mut h, &notes);
    assert_eq!(h.state().scenario(), &now);
    assert!(
        h.query_by_label_contains("not a file the viewer opens")
            .is_some()
    );
}

#[test]
fn saving_over_another_file_asks_first_and_ctrl_s_saves_the_open_file() {
    let dir = tempdir();
    let other = dir.path().join("other.toml");
    std::fs::write(&other, "# someone else's\n").unwrap_or_else(|e| panic!("{e}"));
    let mut h = harness("paired");
    h.state_mut().files.path = other.display().to_string();
    h.run();
    h.get_by_label("Save").click();
    h.run();
    // Before: it was replaced at once.
    let question = format!("{} exists. Replace it?", other.display());
    assert!(h.query_by_label(&question).is_some(), "no question");
    super::look(&mut h, "replace-question.png");
    h.get_by_label("Cancel").click();
    h.run();
    assert!(h.query_by_label(&question).is_none());
    assert_eq!(
        std::fs::read_to_string(&other).unwrap_or_default(),
        "# someone else's\n"
    );
    h.get_by_label("Save").click();
    h.run();
    h.get_by_label("Replace").click();
    h.run();
    let saved = std::fs::read_to_string(&other).unwrap_or_default();
    assert!(saved.contains("[geometry]"), "{saved}");
    assert_eq!(h.state().files.current.as_deref(), Some(other.as_path()));
    // Now it is the open file: Ctrl+S writes there without a question.
    let mut params = h.state().scenario().geometry.params().clone();
    params.home_height = 0.95;
    h.state_mut().set_geometry(params);
    h.run();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::S);
    h.run();
    assert!(h.query_by_label_contains("exists. Replace it?").is_none());
    let again = Scenario::load(&other).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(again.geometry.home_height(), 0.95);
}

#[test]
fn ctrl_o_shows_the_file_dialog_and_its_choice_opens() {
    let dir = tempdir();
    let file = dir.path().join("mine.toml");
    let figure = Scenario::preset("figure8").unwrap_or_else(|e| panic!("{e}"));
    std::fs::write(&file, figure.to_toml()).unwrap_or_else(|e| panic!("{e}"));
    // The dialog's two path fields (egui_file's own) carry no accessible name.
    let state = crate::viewer::ViewerState::new(
        Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}")),
    );
    let mut h = super::built_harness(state, egui::vec2(1280.0, 800.0), false);
    // Start the dialog in the temporary folder: the file open now is there.
    h.state_mut().files.current = Some(dir.path().join("start.toml"));
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::O);
    h.run();
    // The title whole, inside the dialog.
    let title = h
        .get_by_label_contains("Open a scenario, a pose table or a vehicle motion recording")
        .rect();
    let dialog = h
        .get_all_by_role(Role::Window)
        .map(|n| n.rect())
        .find(|r| r.contains_rect(title.shrink(1.0)) || r.intersects(title))
        .unwrap_or_else(|| panic!("no dialog window"));
    assert!(
        dialog.right() >= title.right(),
        "title {title:?} cut by {dialog:?}"
    );
    h.get_by_label_contains("mine.toml").click();
    h.run();
    super::look(&mut h, "file-dialog.png");
    // The dialog's own Open button comes after the Scenario panel's.
    h.get_all_by_role_and_label(Role::Button, "Open")
        .last()
        .unwrap_or_else(|| panic!("no Open button"))
        .click();
    h.run();
    assert_eq!(h.state().scenario().geometry, figure.geometry);
    assert!(h.state().files.picker.is_none());
    assert!(
        h.query_by_label_contains("Open a scenario, a pose table or a vehicle motion recording")
            .is_none()
    );
}

/// Hostile files opened or dropped: a FIFO (it would block), a folder, an empty table, NaN
/// and 1e300, a missing file. Each is one error shown and the scenario stays as it was;
/// none hangs or panics.
#[test]
fn hostile_files_are_refused_and_change_nothing() {
    let dir = tempdir();
    let fifo = dir.path().join("pipe.csv");
    let made = std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .is_ok_and(|s| s.success());
    let header = "t,x,y,z,roll_deg,pitch_deg,yaw_deg\n";
    let write = |name: &str, text: &str| {
        let path = dir.path().join(name);
        std::fs::write(&path, text).unwrap_or_else(|e| panic!("{e}"));
        path
    };
    let mut cases = vec![
        (write("empty.csv", ""), "empty.csv"),
        (
            write(
                "nan.csv",
                &format!("{header}0,NaN,0,0.8,0,0,0\n1,0,0,0.8,0,0,0\n"),
            ),
            "nan.csv",
        ),
        (
            write(
                "huge.csv",
                &format!("{header}0,1e300,0,0.8,0,0,0\n1,0,0,0.8,0,0,0\n"),
            ),
            "huge.csv",
        ),
        (write("empty.toml", ""), "empty.toml"),
        (dir.path().join("missing.toml"), "missing.toml"),
        (
            {
                let folder = dir.path().join("folder.toml");
                std::fs::create_dir(&folder).unwrap_or_else(|e| panic!("{e}"));
                folder
            },
            "not a regular file",
        ),
    ];
    if made {
        cases.push((fifo, "not a regular file"));
    }
    let mut state = crate::viewer::ViewerState::new(
        Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}")),
    );
    let before = state.scenario().clone();
    for (path, words) in cases {
        state.open_path(&path);
        let status = state.files.status.clone();
        assert!(
            status
                .as_ref()
                .is_some_and(|s| s.as_ref().is_err_and(|e| e.to_string().contains(words))),
            "{}: {status:?}",
            path.display()
        );
        assert_eq!(state.scenario(), &before, "{}", path.display());
    }
}

#[test]
fn a_long_status_line_wraps_and_the_side_panel_keeps_its_width() {
    let mut h = harness("seed");
    let pause_at = h.get_by_label("Pause").rect().left();
    let long = format!(
        "Opened /home/someone/{}/scenario.toml: every word of this line is long enough to \
         widen a panel that follows its content",
        "a-very-long-folder-name".repeat(6)
    );
    h.state_mut().files.status = Some(Ok(long));
    for _ in 0..5 {
        h.run();
    }
    // The 3D view's toolbar did not move: the panel did not grow.
    let now = h.get_by_label("Pause").rect().left();
    assert!((now - pause_at).abs() < 1.0, "{pause_at} → {now}");
    // Nor can it be dragged wider than its cap (480 points at most; the width is saved in
    // the session, so it only ever grew).
    let grip = egui::pos2(now - 12.0, 400.0);
    h.hover_at(grip);
    h.run();
    h.event(egui::Event::PointerButton {
        pos: grip,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: egui::Modifiers::NONE,
    });
    h.run();
    for x in [500.0, 700.0, 900.0] {
        h.hover_at(egui::pos2(x, 400.0));
        h.run();
    }
    h.event(egui::Event::PointerButton {
        pos: egui::pos2(900.0, 400.0),
        button: egui::PointerButton::Primary,
        pressed: false,
        modifiers: egui::Modifiers::NONE,
    });
    h.run();
    let dragged = h.get_by_label("Pause").rect().left();
    assert!(
        dragged > now + 50.0,
        "the edge was not dragged: {now} → {dragged}"
    );
    assert!(dragged < 500.0, "{dragged}");
}

#[test]
fn files_opened_or_saved_are_offered_again_newest_first() {
    let dir = tempdir();
    let (a, b) = (dir.path().join("a.toml"), dir.path().join("b.toml"));
    let mut h = harness("paired");
    assert!(h.query_by_label("Recent files").is_none(), "nothing yet");
    h.state_mut().save_file(&a);
    h.state_mut().save_file(&b);
    h.state_mut().open_file(&a);
    h.run();
    let recent: Vec<_> = h.state().files.recent.clone();
    assert_eq!(recent, [a.clone(), b.clone()], "newest first, each once");
    // Chosen from the list, b opens.
    h.get_by_label("Recent files").click();
    h.run();
    h.get_by_label("b.toml").click();
    h.run();
    assert_eq!(h.state().files.current.as_deref(), Some(b.as_path()));
    assert_eq!(h.state().files.recent[0], b);
}
