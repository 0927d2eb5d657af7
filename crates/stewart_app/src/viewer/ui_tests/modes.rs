//! Presentation mode, the manual-mode history and the view toolbar switches.

use crate::viewer::state::playback::MotionMode;
use egui::accesskit::Role;
use egui_kittest::kittest::Queryable;
use stewart_kinematics::io::settings;
use stewart_kinematics::solve::forward::assembly::same_placement;

use super::harness;

#[test]
fn p_enters_presentation_mode_and_escape_leaves_it() {
    let mut h = harness("seed");
    assert!(h.query_by_label("Playback").is_some());
    h.key_press(egui::Key::P);
    h.run();
    assert!(h.state().look.presentation);
    // Control panels are hidden, the plot stays, colours are light, text is larger.
    assert!(h.query_by_label("Playback").is_none());
    // The toolbar keeps play/pause, full screen and the way out on screen.
    assert!(h.query_by_label("Pause").is_some());
    assert!(h.query_by_label("Leave presentation").is_some());
    h.get_by_label("Full screen").click();
    h.run();
    assert!(h.state().look.fullscreen);
    h.key_press(egui::Key::F11);
    h.run();
    assert!(!h.state().look.fullscreen);
    h.get_by_label("Pause").click();
    h.run();
    assert!(!h.state().playback.playing);
    assert_eq!(
        h.state().theme().background,
        stewart_render::Theme::LIGHT.background
    );
    let size = h.ctx.global_style().text_styles[&egui::TextStyle::Body].size;
    assert!(size > 19.0, "{size}");
    h.key_press(egui::Key::Escape);
    h.run();
    assert!(!h.state().look.presentation);
    assert!(h.query_by_label("Playback").is_some());
    h.key_press(egui::Key::P);
    h.run();
    h.get_by_label("Leave presentation").click();
    h.run();
    assert!(!h.state().look.presentation);
}

#[test]
fn escape_closes_the_help_window_first_and_p_closes_it_for_the_audience() {
    let mut h = harness("seed");
    let help_open = |h: &egui_kittest::Harness<'static, crate::viewer::ViewerState>| {
        h.state().look.help && h.query_by_label("Help / keys").is_some()
    };
    h.key_press(egui::Key::F1);
    h.run();
    assert!(help_open(&h));
    // P: the audience sees the view, not the list of keys.
    h.key_press(egui::Key::P);
    h.run();
    assert!(h.state().look.presentation);
    assert!(!help_open(&h), "P left the keys over the presentation");
    h.key_press(egui::Key::F1);
    h.run();
    assert!(help_open(&h));
    // Esc: the window on top goes, nothing else.
    h.key_press(egui::Key::Escape);
    h.run();
    assert!(!help_open(&h), "Esc left the help open");
    assert!(h.state().look.presentation, "Esc closed the help and more");
    h.key_press(egui::Key::Escape);
    h.run();
    assert!(!h.state().look.presentation);
}

#[test]
fn play_and_export_are_in_the_toolbar_and_the_controls_scroll_bar_is_always_drawn() {
    let mut h = harness("seed");
    // Play/pause in the toolbar, whatever the side panel shows.
    h.get_by_label("Pause").click();
    h.run();
    assert!(!h.state().playback.playing);
    h.get_by_label("Play").click();
    h.run();
    assert!(h.state().playback.playing);
    // From manual mode, Play plays the trajectory.
    h.get_by_label("Manual pose").click();
    h.run();
    h.get_by_label("Play").click();
    h.run();
    assert!(h.state().playback.is_playing());
    // Export opens its window; closing it hides it again.
    assert!(h.query_by_label("What").is_none());
    h.get_by_label("Export…").click();
    h.run();
    assert!(h.state().exports.open);
    assert!(h.query_by_label("What").is_some());
    h.get_by_label("Export…").click();
    h.run();
    assert!(h.query_by_label("What").is_none());
    // A slow machine: the view's status line says frames are skipped, and the toolbar's
    // buttons stay where they were.
    let export_at = h.get_by_label("Export…").rect();
    let front_at = h.get_by_label("Front").rect();
    h.state_mut().playback.frame_rate = Some(4.0);
    h.run();
    let note = h
        .query_by_label("4 frames/s: frames skipped")
        .map(|n| n.rect())
        .unwrap_or_else(|| panic!("no note"));
    assert_eq!(h.get_by_label("Export…").rect(), export_at);
    assert_eq!(h.get_by_label("Front").rect(), front_at);
    assert!(
        note.top() > front_at.bottom() + 100.0,
        "the note is below the toolbar"
    );
    // Never in presentation mode.
    h.state_mut().look.presentation = true;
    h.run();
    assert!(h.query_by_label("4 frames/s: frames skipped").is_none());
    h.state_mut().look.presentation = false;
    h.run();
    // The frame-time readout takes its place when asked for (Advanced).
    h.state_mut().look.frame_times = true;
    h.state_mut().quality.record(21.5);
    h.run();
    assert!(
        h.query_by_label_contains("Frame 21.5 ms (95th percentile 21.5 ms) · 3D view: GPU")
            .is_some()
    );
    // Scroll bars are solid (drawn whether or not the pointer is over them).
    assert!(!h.ctx.global_style().spacing.scroll.floating);
}

#[test]
fn manual_mode_keeps_a_rolling_history_of_the_legs() {
    let mut h = harness("paired");
    h.get_by_label("Manual pose").click();
    h.run();
    assert_eq!(h.state().playback.mode, MotionMode::Manual);
    for (k, x) in [0.0, 0.05, 0.1].into_iter().enumerate() {
        h.get_by_role_and_label(Role::Slider, "x (m)")
            .set_value_accesskit(x);
        h.run();
        h.state_mut().advance(0.5 + k as f64);
    }
    let entries: Vec<(f64, [f64; 6])> = h.state().playback.history.entries().copied().collect();
    assert_eq!(entries.len(), 3);
    assert_ne!(entries[0].1, entries[2].1);
    // The history scrolls while recent, then the window goes idle.
    assert!(h.state().animating());
    h.state_mut().playback.clock += 20.0;
    assert!(!h.state().animating());
}

#[test]
fn the_view_toolbar_switches_leg_colours_and_labels() {
    let mut h = harness("seed");
    assert!(h.state().look.coloured_legs && h.state().look.labels);
    h.get_by_label("Leg colours").click();
    h.get_by_label("Labels").click();
    h.run();
    assert!(!h.state().look.coloured_legs && !h.state().look.labels);
}

#[test]
fn next_assembly_mode_steps_through_all_forty_of_dietmaiers_platform() {
    let mut h = super::tall_harness("dietmaier", 1000.0);
    // At home the legs are Dietmaier's.
    h.get_by_label("Manual pose").click();
    h.run();
    let start = h.state().pose();
    assert_eq!(start, h.state().scenario().geometry.home_pose());
    let legs = h.state().scenario().geometry.leg_lengths(&start);
    let mut seen: Vec<stewart_kinematics::Pose> = vec![start];
    for step in 1..=40 {
        h.get_by_label("Next assembly mode").click();
        h.run();
        assert_eq!(h.state().playback.mode, MotionMode::Manual);
        let pose = h.state().pose();
        let now = h.state().scenario().geometry.leg_lengths(&pose);
        for i in 0..6 {
            assert!(
                (now[i] - legs[i]).abs() < 1e-9,
                "step {step}: {now:?} vs {legs:?}"
            );
        }
        let (_, n) = h
            .state()
            .tools
            .assembly
            .shown
            .unwrap_or_else(|| panic!("no mode shown"));
        assert_eq!(n, 40);
        if step < 40 {
            assert!(
                !seen.iter().any(|p| same_placement(p, &pose)),
                "step {step} came back early"
            );
            seen.push(pose);
        } else {
            // Forty steps: every mode once, and back where it started.
            assert!(same_placement(&pose, &start));
        }
    }
    assert!(
        h.query_by_label_contains("of 40 with these legs").is_some(),
        "the count is shown"
    );
}

#[test]
fn an_architecturally_singular_platform_has_no_modes_to_step_through() {
    let mut h = harness("seed");
    h.get_by_label("Next assembly mode").click();
    h.run();
    assert!(h.state().tools.assembly_error.is_some());
    assert!(
        h.query_by_label_contains("architecturally singular: the legs do not determine")
            .is_some()
    );
    assert_eq!(h.state().playback.mode, MotionMode::Trajectory);
}

#[test]
fn the_plot_is_taller_after_dragging_its_top_edge_up() {
    let mut h = harness("seed");
    let before = h.state().look.plot_height;
    assert!(before > 100.0, "{before}");
    // The plot's splitter (the horizontal one; the controls' is vertical), grabbed just
    // above its line: the 3D view there used to take that drag and orbit the camera.
    let camera = h.state().look.camera;
    drag_plot_edge(&mut h, -80.0);
    let after = h.state().look.plot_height;
    assert!((after - before - 80.0).abs() < 6.0, "{before} → {after}");
    assert_eq!(h.state().look.camera, camera);
    // Dragged further, it stops at two fifths of the window (800 points high).
    drag_plot_edge(&mut h, -240.0);
    let most = h.state().look.plot_height;
    assert!((most - 320.0).abs() < 2.0, "{most}");
}

#[test]
fn ctrl_z_undoes_scenario_edits_and_ctrl_shift_z_redoes_them() {
    let mut h = harness("paired");
    let first = h.state().scenario().clone();
    h.get_by_role_and_label(Role::Slider, "samples")
        .set_value_accesskit(301.0);
    h.run();
    h.get_by_role_and_label(Role::Slider, "duration (s)")
        .set_value_accesskit(12.0);
    h.run();
    let edited = h.state().scenario().clone();
    assert_ne!(edited, first);
    let ctrl = egui::Modifiers::COMMAND;
    h.key_press_modifiers(ctrl, egui::Key::Z);
    h.run();
    assert_eq!(h.state().scenario().motion.sampling.len(), 301);
    assert_ne!(h.state().scenario(), &edited);
    h.key_press_modifiers(ctrl, egui::Key::Z);
    h.run();
    assert_eq!(h.state().scenario(), &first);
    // Nothing more to undo: the button is off, the key does nothing.
    h.key_press_modifiers(ctrl, egui::Key::Z);
    h.run();
    assert_eq!(h.state().scenario(), &first);
    h.key_press_modifiers(ctrl | egui::Modifiers::SHIFT, egui::Key::Z);
    h.key_press_modifiers(ctrl, egui::Key::Y);
    h.run();
    assert_eq!(h.state().scenario(), &edited);
    // The buttons do the same; loading a preset is a step too.
    h.get_by_label("Undo").click();
    h.run();
    assert_eq!(h.state().scenario().motion.sampling.len(), 301);
    h.get_by_label("Redo").click();
    h.run();
    assert_eq!(h.state().scenario(), &edited);
    h.state_mut().load_scenario(
        stewart_kinematics::Scenario::preset("seed").unwrap_or_else(|e| panic!("{e}")),
        std::path::PathBuf::from("."),
    );
    h.run();
    h.get_by_label("Undo").click();
    h.run();
    assert_eq!(h.state().scenario(), &edited);
}

#[test]
fn one_slider_drag_is_one_undo_step() {
    let mut h = harness("paired");
    let first = h.state().scenario().clone();
    let rect = h.get_by_role_and_label(Role::Slider, "duration (s)").rect();
    let y = rect.center().y;
    h.hover_at(egui::pos2(rect.left() + 10.0, y));
    h.run();
    h.drag_at(egui::pos2(rect.left() + 10.0, y));
    h.run();
    for dx in [20.0, 40.0, 60.0] {
        h.hover_at(egui::pos2(rect.left() + 10.0 + dx, y));
        h.run();
    }
    h.drop_at(egui::pos2(rect.left() + 70.0, y));
    h.run();
    assert_ne!(h.state().scenario(), &first);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    h.run();
    assert_eq!(h.state().scenario(), &first);
}

#[test]
fn a_finding_is_a_link_to_its_worst_moment_and_the_plot_marks_what_is_beyond() {
    let mut h = super::tall_harness("paired", 1600.0);
    let setting = settings::all()
        .iter()
        .find(|s| s.key == "geometry.leg_max")
        .unwrap_or_else(|| panic!("no leg_max"));
    h.state_mut().apply(setting, Some(1.1));
    super::settle(&mut h);
    let worst = h
        .state()
        .report()
        .and_then(|r| r.findings.first().map(|f| f.worst_time))
        .unwrap_or_else(|| panic!("no finding"));
    assert!(h.state().playback.playing);
    let first = h
        .get_all_by_label_contains("• ")
        .next()
        .unwrap_or_else(|| panic!("no finding listed"));
    first.click();
    h.run();
    let start = h.state().scenario().motion.sampling.start();
    assert!(!h.state().playback.playing);
    assert!((h.state().playback.time + start - worst).abs() < 1e-9);
    // The legend explains the mark over the stretches past the stroke.
    assert!(h.query_by_label("beyond a limit").is_some());
}

/// Entering presentation mode frames the whole motion in the larger view, from the angles
/// the user chose; leaving it brings their camera back (before: the scene kept the camera
/// framed for the smaller view beside the controls).
#[test]
fn presentation_mode_frames_the_motion_in_its_larger_view_and_gives_the_camera_back() {
    let mut h = harness("seed");
    h.state_mut().look.camera.orbit(20.0, -5.0);
    h.state_mut().look.camera.zoom(2.5);
    h.run();
    let before = h.state().look.camera;
    h.key_press(egui::Key::P);
    h.run();
    let framed = h.state().look.camera;
    assert_eq!(
        (framed.azimuth_deg, framed.elevation_deg),
        (before.azimuth_deg, before.elevation_deg)
    );
    // Every solid of every sampled pose projects inside the view, and the motion fills a
    // good share of it.
    let aspect = h.state().look.view_aspect;
    let matrix = framed.view_proj(aspect);
    let scenario = h.state().scenario().clone();
    let (mut lo, mut hi) = (glam::Vec2::splat(f32::MAX), glam::Vec2::splat(f32::MIN));
    for t in scenario.motion.sampling.times().step_by(10) {
        let frame = scenario
            .geometry
            .scene_frame(&scenario.motion.trajectory.pose_at(t), Vec::new());
        let mut points = Vec::new();
        let solids = stewart_render::Overlays {
            grid: false,
            path: false,
            labels: false,
            ..stewart_render::Overlays::default()
        };
        stewart_render::DrawList::build(&frame, &stewart_render::Theme::LIGHT, &solids)
            .solid_extent(&mut points);
        for p in points {
            let clip = matrix * p.extend(1.0);
            let ndc = glam::Vec2::new(clip.x, clip.y) / clip.w;
            lo = lo.min(ndc);
            hi = hi.max(ndc);
        }
    }
    assert!(
        lo.cmpge(glam::Vec2::splat(-1.0)).all() && hi.cmple(glam::Vec2::splat(1.0)).all(),
        "{lo} … {hi}"
    );
    let share = ((hi - lo) / 2.0).max_element();
    assert!(share > 0.75, "the motion fills {share} of the view");
    h.key_press(egui::Key::P);
    h.run();
    assert_eq!(h.state().look.camera, before);
}

/// No text the viewer draws is smaller than 11 points (egui's small style, 9 points, read
/// as about 8 px: the descriptions, notes and hex dump).
#[test]
fn no_text_style_is_smaller_than_eleven_points() {
    let h = harness("seed");
    let style = h.ctx.global_style();
    for (name, font) in &style.text_styles {
        assert!(font.size >= 11.0, "{name:?} is {} pt", font.size);
    }
}

/// The checks' own thresholds sit behind "Advanced" in the limits section; the limits do
/// not.
#[test]
fn check_thresholds_are_behind_advanced() {
    let mut h = super::tall_harness("paired", 2400.0);
    h.get_by_label("Limits and check thresholds").click();
    h.run();
    assert!(
        h.query_all_by_label_contains("max leg speed")
            .next()
            .is_some()
    );
    assert!(
        h.query_all_by_label_contains("rigid-body tolerance")
            .next()
            .is_none()
    );
    h.get_by_label("Advanced: check thresholds").click();
    h.run();
    assert!(
        h.query_all_by_label_contains("rigid-body tolerance")
            .next()
            .is_some()
    );
    assert!(h.query_all_by_label_contains("jump ratio").next().is_some());
}

/// Buttons say what they do when hovered (before: the standard views, reset, the layout
/// and actuator choices had no tooltip).
#[test]
fn buttons_explain_themselves_on_hover() {
    let mut state = crate::viewer::ViewerState::new(
        stewart_kinematics::Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}")),
    );
    state.look.expand_panels = true;
    state.playback.playing = false;
    let mut h = super::harness_with(state, 3600.0);
    for (button, tip) in [
        ("Iso", "Look from this standard direction"),
        ("Reset view", "The seed's view"),
        ("Linear legs", "Legs that change length"),
        ("Paired", "Joints in three pairs"),
        ("Compute", "Search the smallest and largest actuator value"),
    ] {
        h.get_by_label(button).hover();
        // Tooltips wait for the pointer to rest.
        for _ in 0..40 {
            h.step();
            if h.query_all_by_label_contains(tip).next().is_some() {
                break;
            }
            std::thread::sleep(std::time::Duration::from_millis(10));
        }
        assert!(
            h.query_all_by_label_contains(tip).next().is_some(),
            "no tooltip on `{button}`"
        );
    }
}

/// Presentation mode in the default window: the plot takes at most a third of the height
/// (G hides it and shows it again), the readout is as large as the interface's text, and
/// leaving gives back the plot's height and the camera exactly.
#[test]
fn presentation_enters_and_leaves_exactly_with_the_plot_a_third_at_most() {
    let mut h = harness("seed");
    h.state_mut().look.readouts = true;
    // The user's own plot height: dragged up to 420 points (more than a third of 800).
    drag_plot_edge(&mut h, -200.0);
    let plot_before = h.state().look.plot_height;
    assert!(plot_before > 800.0 / 3.0, "{plot_before}");
    let camera_before = h.state().look.camera;
    let readout_size = |h: &egui_kittest::Harness<'static, crate::viewer::ViewerState>| {
        let s = h.state();
        let list = s.draw_list(&s.theme());
        let view = s.look.view_px.map(|v| v as f32);
        list.texts
            .last()
            .map(|t| t.size.px(view) / view[0].min(view[1]))
            .unwrap_or_else(|| panic!("no readout"))
    };
    let readout = readout_size(&h);
    h.key_press(egui::Key::P);
    h.run();
    h.run();
    assert!(h.state().look.presentation);
    let plot = h.state().look.plot_height;
    assert!(plot <= 800.0 / 3.0 + 1.0, "{plot}");
    assert!(
        (readout_size(&h) / readout - 1.5).abs() < 1e-3,
        "the readout grows with the text"
    );
    // G: the view alone, then the plot again.
    h.key_press(egui::Key::G);
    h.run();
    assert_eq!(h.state().look.plot_height, 0.0);
    assert!(h.query_by_label("time (s)").is_none(), "the plot is hidden");
    h.key_press(egui::Key::G);
    h.run();
    assert!(h.state().look.plot_height > 0.0);
    // Leaving: exactly as before.
    h.key_press(egui::Key::P);
    h.run();
    h.run();
    assert!(!h.state().look.presentation);
    assert_eq!(h.state().look.camera, camera_before);
    let plot_after = h.state().look.plot_height;
    assert!(
        (plot_after - plot_before).abs() < 1.0,
        "{plot_before} → {plot_after}"
    );
}

/// A geometry edit that takes the platform out of the view fits the camera to it again;
/// *Fit* does it when asked.
#[test]
fn the_camera_follows_a_geometry_edit_that_leaves_the_view_and_fit_frames_the_platform() {
    let mut h = harness("seed");
    let aspect = h.state().look.view_aspect;
    assert!(h.state().scene_in_view(aspect));
    let before = h.state().look.camera;
    for (key, value) in [
        ("geometry.base_radius", 3.0),
        ("geometry.platform_radius", 2.0),
    ] {
        let setting = settings::find(key).unwrap_or_else(|e| panic!("{e}"));
        h.state_mut().apply(setting, Some(value));
    }
    h.run();
    assert!(h.state().scene_in_view(aspect), "the scene left the view");
    let after = h.state().look.camera;
    assert!(after.distance > before.distance, "{after:?}");
    assert_eq!(
        (after.azimuth_deg, after.elevation_deg),
        (before.azimuth_deg, before.elevation_deg)
    );
    // Zoomed far in, the platform leaves the view until Fit.
    h.state_mut().look.camera.zoom(0.2);
    h.run();
    assert!(!h.state().scene_in_view(aspect));
    h.get_by_label("Fit").click();
    h.run();
    assert!(h.state().scene_in_view(aspect));
}

/// F1 (or ?) opens *Help / keys* listing every key; Ctrl+Q asks the window to close.
#[test]
fn f1_lists_every_key_and_ctrl_q_quits() {
    let mut h = harness("seed");
    assert!(h.query_by_label("Help / keys").is_none());
    h.key_press(egui::Key::F1);
    h.run();
    assert!(h.query_by_label("Help / keys").is_some());
    for keys in [
        "Space",
        "F12",
        "Ctrl+Q",
        "Esc",
        "G",
        "W/S A/D R/F L/J I/K Q/E",
    ] {
        assert!(h.query_by_label(keys).is_some(), "{keys} is not listed");
    }
    super::look(&mut h, "help.png");
    h.key_press(egui::Key::F1);
    h.run();
    assert!(h.query_by_label("Help / keys").is_none());
    assert!(!h.state().quit_asked);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Q);
    h.run();
    assert!(h.state().quit_asked);
}

/// Drag the plot's top edge (the horizontal splitter, grabbed just above its line) by
/// `dy` points (negative: up).
fn drag_plot_edge(h: &mut egui_kittest::Harness<'static, crate::viewer::ViewerState>, dy: f32) {
    let edge = h
        .get_all_by_role(Role::Splitter)
        .map(|n| n.rect())
        .find(|r| r.width() > r.height())
        .unwrap_or_else(|| panic!("no splitter under the view"))
        .center()
        - egui::vec2(0.0, 5.0);
    let by = egui::vec2(0.0, dy);
    h.hover_at(edge);
    h.run();
    h.drag_at(edge);
    h.run();
    h.hover_at(edge + by);
    h.run();
    h.drop_at(edge + by);
    h.run();
}

/// The toolbar stays put: Play and Pause are one width, and a shot's line is said over
/// the view instead of pushing it down.
#[test]
fn the_toolbar_does_not_move_when_play_turns_pause_or_a_shot_is_said() {
    let mut h = harness("seed");
    let pause = h.get_by_label("Pause").rect();
    let view = h.state().look.view_px;
    h.get_by_label("Pause").click();
    h.run();
    let play = h.get_by_label("Play").rect();
    assert!(
        (play.width() - pause.width()).abs() < 0.5,
        "{play:?} vs {pause:?}"
    );
    let export = h.get_by_label("Export…").rect();
    h.state_mut().shots.say(Some(Ok(
        "Saved the view to /a/long/path/shot.png.".to_owned()
    )));
    h.run();
    h.run();
    assert!(
        h.query_by_label("Saved the view to /a/long/path/shot.png.")
            .is_some()
    );
    assert_eq!(h.state().look.view_px, view, "the view was pushed down");
    assert_eq!(h.get_by_label("Export…").rect(), export);
}
