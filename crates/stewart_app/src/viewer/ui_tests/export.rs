//! The Export panel: a background export with progress, and cancel.

use std::time::{Duration, Instant};

use crate::i18n::Lang;
use crate::viewer::state::ViewerState;
use crate::viewer::state::exports::ExportKind;
use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

use super::tall_harness;

/// Tall enough for the Export panel at the bottom of the controls.
const HEIGHT: f32 = 2400.0;

/// Step the UI until the export ends; the outcome shown.
fn finish(h: &mut Harness<'_, ViewerState>) -> Result<String, String> {
    let started = Instant::now();
    while h.state().exports.job.is_some() {
        assert!(
            started.elapsed() < Duration::from_secs(120),
            "export did not end"
        );
        std::thread::sleep(Duration::from_millis(20));
        h.run();
    }
    (h.state().exports.status.clone())
        .map(|s| s.map_err(|e| e.to_string()))
        .unwrap_or_else(|| Err("no outcome".to_owned()))
}

fn export_to(h: &mut Harness<'_, ViewerState>, kind: ExportKind, path: &std::path::Path) {
    h.get_by_label("Export…").click();
    h.run();
    export_again(h, kind, path);
}

/// [`export_to`] with the Export panel already open.
fn export_again(h: &mut Harness<'_, ViewerState>, kind: ExportKind, path: &std::path::Path) {
    h.get_by_role_and_label(Role::ComboBox, "What").click();
    h.run();
    h.get_by_label(kind.label(Lang::En)).click();
    h.run();
    h.state_mut().exports.form.path = path.display().to_string();
    h.run();
    h.get_by_role_and_label(Role::Button, "Export").click();
    h.run();
}

/// Nothing (no staged file, no partial output) is left in `dir`.
fn assert_nothing_left(dir: &std::path::Path) {
    let left: Vec<_> = std::fs::read_dir(dir)
        .map(|d| d.count())
        .into_iter()
        .collect();
    assert_eq!(left, vec![0], "files left behind");
}

/// The paired preset sampled six times, exported as CSV into `dir`: the viewer, the file
/// and the outcome shown.
fn six_poses_as_csv(
    dir: &std::path::Path,
) -> (
    Harness<'static, ViewerState>,
    std::path::PathBuf,
    Result<String, String>,
) {
    let mut h = tall_harness("paired", HEIGHT);
    h.get_by_role_and_label(Role::Slider, "samples")
        .set_value_accesskit(6.0);
    h.run();
    let csv = dir.join("legs.csv");
    export_to(&mut h, ExportKind::Csv, &csv);
    let outcome = finish(&mut h);
    (h, csv, outcome)
}

#[test]
fn the_csv_and_a_short_gif_are_written_in_the_background() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let (mut h, csv, outcome) = six_poses_as_csv(dir.path());
    assert!(
        outcome.as_ref().is_ok_and(|m| m.contains("Wrote 6 poses")),
        "{outcome:?}"
    );
    let text = std::fs::read_to_string(&csv).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(text.lines().count(), 7, "{text}");
    assert!(text.starts_with("t,x,y,z,roll_deg,pitch_deg,yaw_deg,L1"));

    let gif = dir.path().join("short.gif");
    h.state_mut().exports.form.size = (640, 360);
    h.state_mut().exports.form.fps = 0.0;
    h.get_by_role_and_label(Role::ComboBox, "What").click();
    h.run();
    h.get_by_label(ExportKind::Gif.label(Lang::En)).click();
    h.run();
    h.state_mut().exports.form.path = gif.display().to_string();
    h.run();
    // The format's own rate by default, as `stewart render` has it: the 10 s motion at
    // 25 frames/s.
    h.get_by_label("250 frames at 25 frames/s, playing 10.00 s");
    // A rate a GIF cannot play is rounded, and the panel says so.
    h.state_mut().exports.form.fps = 60.0;
    h.run();
    h.get_by_label("500 frames at 50 frames/s, playing 10.00 s");
    h.get_by_label_contains("60 frames/s becomes 50 frames/s (2 cs a frame)");
    // A short one to write: half a frame a second, 2 s a frame.
    h.state_mut().exports.form.fps = 0.5;
    h.run();
    h.get_by_label("5 frames at 0.5 frames/s, playing 10.00 s");
    h.get_by_role_and_label(Role::Button, "Export").click();
    h.run();
    let outcome = finish(&mut h);
    assert!(
        outcome.as_ref().is_ok_and(
            |m| m.contains("Wrote 5 frames") && m.contains("0.5 frames/s, plays 10.00 s")
        ),
        "{outcome:?}"
    );
    let file = std::fs::File::open(&gif).unwrap_or_else(|e| panic!("{e}"));
    let mut decoder = gif::DecodeOptions::new()
        .read_info(file)
        .unwrap_or_else(|e| panic!("{e}"));
    let mut delays = Vec::new();
    while let Some(f) = decoder.read_next_frame().unwrap_or_else(|e| panic!("{e}")) {
        delays.push(f.delay);
    }
    assert_eq!(delays, [200; 5]);
}

#[test]
fn cancel_stops_an_export_and_leaves_nothing() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let mut h = tall_harness("seed", HEIGHT);
    let gif = dir.path().join("long.gif");
    h.state_mut().exports.form.size = (640, 360);
    h.state_mut().exports.form.fps = 0.0;
    let front = h.get_by_label("Front").rect();
    export_to(&mut h, ExportKind::Gif, &gif);
    assert!(h.state().exports.job.is_some());
    // "Exporting N %" in the toolbar moves nothing after it.
    h.run();
    assert!(h.query_by_label_contains("Exporting").is_some());
    assert_eq!(h.get_by_label("Front").rect(), front);
    assert!(
        h.query_by_label_contains("frames/s").is_some()
            || h.query_by_label_contains("working").is_some()
    );
    h.get_by_label("Cancel").click();
    h.run();
    let outcome = finish(&mut h);
    // The user's own choice, not an error: not shown in red.
    assert!(
        outcome
            .as_ref()
            .is_ok_and(|m| m.starts_with("Cancelled: nothing was written")),
        "{outcome:?}"
    );
    assert!(h.state().exports.written.is_none(), "no file to show");
    assert_nothing_left(dir.path());
}

#[test]
fn closing_with_an_export_running_cancels_it_and_leaves_nothing() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let mut h = tall_harness("seed", HEIGHT);
    h.state_mut().exports.form.size = (640, 360);
    h.state_mut().exports.form.fps = 0.0;
    export_to(&mut h, ExportKind::Frames, &dir.path().join("frames"));
    // Wait until frames are being written (staged next to the output).
    let started = Instant::now();
    while h
        .state()
        .exports
        .job
        .as_ref()
        .is_some_and(|j| j.fraction() == 0.0)
    {
        assert!(
            started.elapsed() < Duration::from_secs(60),
            "no frame written"
        );
        std::thread::sleep(Duration::from_millis(10));
        h.run();
    }
    assert!(
        h.state().exports.job.is_some(),
        "{:?}",
        h.state().exports.status
    );
    // The window closing drops the state: the export stops and cleans up first.
    drop(h.into_state());
    assert_nothing_left(dir.path());
}

#[test]
fn the_workspace_figure_surface_and_view_are_exported() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    // The seed: stroke limits only, so its 512² workspace is quick even in a debug build.
    let mut h = tall_harness("seed", 3000.0);
    let svg = dir.path().join("ws.svg");
    export_to(&mut h, ExportKind::WorkspaceSvg, &svg);
    let outcome = finish(&mut h);
    assert!(
        outcome
            .as_ref()
            .is_ok_and(|m| m.contains("workspace slices")),
        "{outcome:?}"
    );
    let text = std::fs::read_to_string(&svg).unwrap_or_default();
    assert_eq!(text.matches(r#"class="boundary""#).count(), 2, "two slices");
    let ply = dir.path().join("ws.ply");
    export_again(&mut h, ExportKind::SurfacePly, &ply);
    let outcome = finish(&mut h);
    assert!(
        outcome.as_ref().is_ok_and(|m| m.contains("triangles")),
        "{outcome:?}"
    );
    let bytes = std::fs::read(&ply).unwrap_or_default();
    assert!(bytes.starts_with(b"ply\nformat binary_little_endian 1.0\n"));
    let png = dir.path().join("view.png");
    h.state_mut().exports.form.size = (640, 360);
    export_again(&mut h, ExportKind::SurfacePng, &png);
    let outcome = finish(&mut h);
    // Without a GPU adapter the render fails with its reason; with one it writes the image.
    match outcome {
        Ok(m) => {
            assert!(m.contains("640 × 360"), "{m}");
            let image = image::open(&png).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!((image.width(), image.height()), (640, 360));
        }
        Err(e) => assert!(!png.exists(), "{e}"),
    }
    // An orientation nothing reaches (the paired platform rolled 80°): one error, nothing
    // written. (The seed, without joint-cone limits, reaches any roll near its base.)
    let mut h = tall_harness("paired", 3000.0);
    h.get_by_label("Export…").click();
    h.run();
    h.state_mut().tools.workspace.follow_pose = false;
    h.state_mut().tools.workspace.orientation_deg = [80.0, 0.0, 0.0];
    let empty = dir.path().join("empty.ply");
    export_again(&mut h, ExportKind::SurfacePly, &empty);
    let outcome = finish(&mut h);
    assert!(
        outcome
            .as_ref()
            .is_err_and(|e| e.contains("nothing to write")),
        "{outcome:?}"
    );
    assert!(!empty.exists());
}

#[test]
fn an_export_names_its_full_path_offers_its_folder_and_asks_before_replacing() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let (mut h, csv, outcome) = six_poses_as_csv(dir.path());
    assert!(
        outcome
            .as_ref()
            .is_ok_and(|m| m.contains(&csv.display().to_string())),
        "{outcome:?}"
    );
    assert_eq!(h.state().exports.written.as_deref(), Some(csv.as_path()));
    assert!(h.query_by_label("Show in folder").is_some());
    // The same path again: a question first (before: replaced without one).
    std::fs::write(&csv, "mine\n").unwrap_or_else(|e| panic!("{e}"));
    h.get_by_role_and_label(Role::Button, "Export").click();
    h.run();
    let question = format!("{} exists. Replace it?", csv.display());
    assert!(h.query_by_label(&question).is_some());
    assert!(h.state().exports.job.is_none());
    h.get_by_label("Cancel").click();
    h.run();
    assert!(h.state().exports.job.is_none());
    assert_eq!(std::fs::read_to_string(&csv).unwrap_or_default(), "mine\n");
    h.get_by_role_and_label(Role::Button, "Export").click();
    h.run();
    h.get_by_label("Replace").click();
    h.run();
    assert!(finish(&mut h).is_ok());
    let text = std::fs::read_to_string(&csv).unwrap_or_default();
    assert!(text.starts_with("t,x,y,z"), "{text}");
}

/// What the audience sees carries the scenario's name alone: an exported plot after an
/// edit, the readout; the edit mark is the window title's (it once reached export titles,
/// the glTF animation's name and the presentation readout). Default export names have no
/// spaces.
#[test]
fn an_edit_marks_the_window_title_only() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let mut h = tall_harness("paired", HEIGHT);
    h.get_by_role_and_label(Role::Slider, "samples")
        .set_value_accesskit(60.0);
    h.run();
    assert!(h.state().window_title().contains("paired (edited)"));
    let edited = dir.path().join("edited.svg");
    export_to(&mut h, ExportKind::PlotSvg, &edited);
    assert!(finish(&mut h).is_ok());
    let text = std::fs::read_to_string(&edited).unwrap_or_default();
    assert!(
        text.contains("paired") && !text.contains("edited"),
        "an edit mark exported"
    );
    h.state_mut().look.readouts = true;
    let list = h.state().draw_list(&h.state().theme());
    let readout = list
        .texts
        .last()
        .map(|t| t.text.clone())
        .unwrap_or_default();
    assert!(
        readout.contains("paired") && !readout.contains("edited"),
        "{readout}"
    );
    // Undone back to the preset, the window's title is plain again.
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    h.run();
    assert!(!h.state().window_title().contains("edited"));
    // A name with spaces gives a default export name without them.
    let mut scenario =
        stewart_kinematics::Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
    scenario.name = "My rig (v2)".to_owned();
    let mut h = super::harness_with(ViewerState::new(scenario), HEIGHT);
    h.get_by_label("Export…").click();
    h.run();
    let path = h.state().exports.form.path.clone();
    assert!(
        path.starts_with("My-rig-v2") && !path.contains(' '),
        "{path}"
    );
}

/// A part of the motion, a title, a 4:3 or typed size: as `stewart render` has them.
#[test]
fn a_part_of_the_motion_under_a_title_at_a_four_by_three_size() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let gif = dir.path().join("part.gif");
    let mut h = tall_harness("seed", HEIGHT);
    h.get_by_label("Export…").click();
    h.run();
    h.get_by_role_and_label(Role::ComboBox, "What").click();
    h.run();
    h.get_by_label(ExportKind::Gif.label(Lang::En)).click();
    h.run();
    h.state_mut().exports.form.path = gif.display().to_string();
    h.get_by_label("Only part of the motion").click();
    h.run();
    assert_eq!(h.state().exports.form.span_s, Some([0.0, 10.0]));
    // 2 s to 3 s at the GIF's 25 frames/s: frames 50 to 75, 26 of them.
    h.state_mut().exports.form.span_s = Some([2.0, 3.0]);
    h.state_mut().exports.form.size = (320, 240);
    h.state_mut().exports.form.title = "Defence, figure 3".to_owned();
    h.run();
    h.get_by_label("26 frames at 25 frames/s, playing 1.04 s");
    // A title that is not one line is refused before anything runs.
    h.state_mut().exports.form.title = "two\nlines".to_owned();
    h.run();
    assert!(h.query_by_label_contains("must be one line").is_some());
    h.get_by_role_and_label(Role::Button, "Export").click();
    h.run();
    assert!(h.state().exports.job.is_none(), "exported with a bad title");
    h.state_mut().exports.form.title = "Defence, figure 3".to_owned();
    h.run();
    h.get_by_role_and_label(Role::Button, "Export").click();
    h.run();
    let outcome = finish(&mut h);
    assert!(
        outcome
            .as_ref()
            .is_ok_and(|m| m.contains("Wrote 26 frames")),
        "{outcome:?}"
    );
    let file = std::fs::File::open(&gif).unwrap_or_else(|e| panic!("{e}"));
    let decoder = gif::DecodeOptions::new()
        .read_info(file)
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!((decoder.width(), decoder.height()), (320, 240));
}

#[test]
fn the_3d_animation_is_written_as_glb_with_the_cad_parts_shown() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let mut h = tall_harness("seed", HEIGHT);
    let examples = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/cad");
    h.state_mut().open_file(&examples.join("seed-cad.toml"));
    h.run();
    let glb = dir.path().join("seed.glb");
    export_to(&mut h, ExportKind::Gltf, &glb);
    let outcome = finish(&mut h);
    assert!(
        outcome
            .as_ref()
            .is_ok_and(|m| m.contains("Wrote a glTF animation of 1001 keys")),
        "{outcome:?}"
    );
    // Read back by the `gltf` crate: the animation, and the base drawn from base.stl
    // (1608 triangles) rather than the studio's plate.
    let bytes = std::fs::read(&glb).unwrap_or_else(|e| panic!("{e}"));
    let gltf = gltf::Gltf::from_slice(&bytes).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(gltf.document.animations().count(), 1);
    let base = gltf
        .document
        .nodes()
        .find(|n| n.name() == Some("base"))
        .and_then(|n| n.mesh())
        .unwrap_or_else(|| panic!("no base mesh"));
    let first = base
        .primitives()
        .next()
        .and_then(|p| p.indices())
        .map(|a| a.count());
    assert_eq!(first, Some(3 * 1608));
}
