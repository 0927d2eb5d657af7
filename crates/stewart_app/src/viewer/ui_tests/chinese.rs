//! The Chinese interface: every word a person reads comes from the Chinese catalogue (the
//! accessibility tree of every panel, opened, holds no English word), its font is loaded
//! (the snapshot shows characters, not boxes), and the language switch changes it at once.
//!
//! `UPDATE_SNAPSHOTS=1 cargo test -p stewart_app --lib ui_tests::chinese` re-blesses the image.

use crate::i18n::Lang;
use crate::viewer::state::ViewerState;
use crate::viewer::state::playback::MotionMode;
use egui_kittest::kittest::{NodeT, Queryable};
use egui_kittest::{Harness, SnapshotOptions};
use stewart_kinematics::Scenario;

/// Latin words a Chinese interface keeps: units, file types, key names, protocols, the
/// names of languages and of mathematical functions, and the inertia tensor's entries
/// (Ixx … Iyz, written so in Chinese textbooks too).
const KEPT: [&str; 36] = [
    "PNG", "GIF", "MP4", "SVG", "PDF", "CSV", "dpi", "UDP", "Hz", "Esc", "Shift", "Home",
    "English", "sin", "cos", "FIFO", "mm", "toml", "geometry", "µs", "ms", "ch", "CRC", "rad",
    "Ixx", "Iyy", "Izz", "Ixy", "Ixz", "Iyz", "CAD", "STL", "OBJ", "glTF", "GLB", "MPC",
];

/// The viewer on `preset` in Chinese with every section open.
fn chinese(preset: &str) -> Harness<'static, ViewerState> {
    let mut state = ViewerState::new(Scenario::preset(preset).unwrap_or_else(|e| panic!("{e}")));
    state.look.lang = Lang::Zh;
    state.look.expand_panels = true;
    // The Workspace panel's numbers and slice too (coarse: a debug build).
    state.tools.workspace =
        crate::viewer::tools::workspace::WorkspaceTool::with_resolutions(16, 48);
    state.tools.workspace.show = true;
    let mut h = super::harness_with(state, 4200.0);
    h.state_mut().settle_workspace();
    h.state_mut()
        .tools
        .workspace
        .wait(std::time::Duration::from_secs(120));
    h.run();
    h
}

/// Words that are the user's own, shown as written: the scenario's name and description.
fn own_words(state: &ViewerState) -> Vec<String> {
    let s = state.scenario();
    vec![s.name.clone(), s.description.clone()]
}

/// English words (three letters or more, not in [`KEPT`]) in the labels and values of
/// the accessibility tree, except `allowed` texts (the scenario's own name and notes).
fn english_words(h: &Harness<'static, ViewerState>, allowed: &[String]) -> Vec<String> {
    let mut found = Vec::new();
    for node in h.root().children_recursive() {
        let a = node.accesskit_node();
        for text in [a.label(), a.value()].into_iter().flatten() {
            let text = text.to_string();
            // egui's own accessibility names (never drawn) and the scenario's own words.
            if text == "Resize panel"
                || allowed
                    .iter()
                    .any(|s| !s.is_empty() && (text.contains(s) || s.contains(text.trim())))
            {
                continue;
            }
            let english = text
                .split(|c: char| !c.is_ascii_alphabetic())
                .any(|w| w.len() >= 3 && !KEPT.contains(&w));
            if english {
                found.push(text);
            }
        }
    }
    found
}

#[test]
fn every_panel_reads_in_chinese() {
    for preset in ["seed", "paired", "servo-desk", "keyframes", "circle"] {
        let h = chinese(preset);
        let english = english_words(&h, &own_words(h.state()));
        assert!(
            english.is_empty(),
            "{preset}: English left in the Chinese interface: {english:#?}"
        );
        // And it is the Chinese interface, not an empty one.
        assert!(h.query_by_label("场景").is_some());
        assert!(h.query_by_label("诊断").is_some());
    }
}

#[test]
fn manual_mode_and_the_link_read_in_chinese_too() {
    let mut h = chinese("seed");
    h.state_mut().playback.mode = MotionMode::Manual;
    h.run();
    h.state_mut().connect_link();
    h.run();
    h.run();
    let english = english_words(&h, &own_words(h.state()));
    assert!(english.is_empty(), "{english:#?}");
    assert!(
        h.query_all_by_label("未使能").count() >= 2,
        "the link's state in Chinese, in the panel and on the badge"
    );
    h.state_mut().link.disconnect();
}

#[test]
fn the_english_interface_is_english() {
    // The same scan finds English where there is English: it would catch a bypass.
    let mut state = ViewerState::new(Scenario::seed());
    state.look.expand_panels = true;
    let h = super::harness_with(state, 3600.0);
    assert!(english_words(&h, &[]).len() > 50);
}

#[test]
fn the_language_switch_changes_the_interface_at_once() {
    let mut state = ViewerState::new(Scenario::seed());
    state.look.lang = Lang::En;
    let mut h = super::harness_with(state, 1600.0);
    assert!(h.query_by_label("Scenario").is_some());
    // A status line written in English does not stay English after the switch.
    h.state_mut().files.status = Some(Ok("Saved to /tmp/x.toml.".to_owned()));
    h.run();
    assert!(h.query_by_label("Saved to /tmp/x.toml.").is_some());
    h.get_by_label("中文").click();
    h.run();
    assert_eq!(h.state().look.lang, Lang::Zh);
    assert!(h.query_by_label("场景").is_some() && h.query_by_label("Scenario").is_none());
    assert!(h.query_by_label("Saved to /tmp/x.toml.").is_none());
    h.get_by_label("English").click();
    h.run();
    assert_eq!(h.state().look.lang, Lang::En);
}

#[test]
fn a_refusal_reads_in_the_language_shown_and_follows_a_switch() {
    // The error is kept typed and worded where it is shown: a file that cannot be read
    // and an envelope with no range read in Chinese, and in English after the switch.
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let missing = dir.path().join("no-such-poses.csv");
    let mut state = ViewerState::new(Scenario::seed());
    state.look.lang = Lang::Zh;
    state.look.expand_panels = true;
    state.open_path(&missing);
    state.tools.design.spans = [[0.0; 2]; 6];
    state.tools.design.start(&Scenario::seed().geometry);
    let mut h = super::harness_with(state, 3600.0);
    h.run();
    let shown = |h: &Harness<'static, ViewerState>, words: &str| {
        h.query_all_by_label_contains(words).next().is_some()
    };
    let path = missing.display().to_string();
    assert!(
        shown(&h, &format!("{path}：无法读取")),
        "the file's error in Chinese"
    );
    assert!(shown(&h, "包络为空"), "the envelope's refusal in Chinese");
    assert!(!shown(&h, "cannot be read") && !shown(&h, "envelope is empty"));
    h.state_mut().look.lang = Lang::En;
    h.run();
    assert!(shown(&h, &format!("{path}: cannot be read")));
    assert!(shown(&h, "Not applied: the envelope is empty"));
}

#[test]
fn the_chinese_interface_looks_right() {
    let mut state = ViewerState::new(Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}")));
    state.look.lang = Lang::Zh;
    state.playback.playing = false;
    state.playback.time = 2.5;
    let mut h = super::sized_harness(state, egui::vec2(1100.0, 760.0));
    h.run();
    h.snapshot_options(
        "chinese-interface",
        &SnapshotOptions::new()
            .output_path("tests/snapshots")
            .max_failed_pixels(8),
    );
}

#[test]
fn the_file_dialog_and_help_read_in_chinese() {
    let mut state = ViewerState::new(Scenario::seed());
    state.look.lang = Lang::Zh;
    state.choose_file(crate::viewer::state::files::Purpose::Open);
    state.look.help = true;
    // The dialog's fields are egui_file's own, without accessible names.
    let mut h = super::built_harness(state, egui::vec2(1280.0, 900.0), false);
    h.run();
    for words in ["新建文件夹", "显示隐藏文件", "帮助 / 按键", "车辆运动记录"]
    {
        assert!(h.query_by_label_contains(words).is_some(), "{words}");
    }
    // The dialog's own English words are gone (key names and file names stay as written).
    for words in ["New Folder", "Show Hidden", "Cancel", "Open"] {
        assert!(h.query_by_label(words).is_none(), "{words}");
    }
}
