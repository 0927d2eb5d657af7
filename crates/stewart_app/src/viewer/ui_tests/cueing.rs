//! The Motion cueing panel: a vehicle recording dropped on the window plays through the
//! washout, the panel plots what the platform makes felt, and its settings cue it again.

use egui_kittest::kittest::Queryable;
use stewart_kinematics::analysis::cueing::{VehicleMotion, cue_recording};
use stewart_kinematics::io::settings;

use super::files::drop_file;

/// Braking at 5 m/s² from 1 to 3 s with a turn, every 20 ms for 5 s.
fn braking() -> (String, Vec<(f64, VehicleMotion)>) {
    let mut text = String::from("t,ax,ay,az,wx,wy,wz\n");
    let mut samples = Vec::new();
    for k in 0..=250 {
        let t = f64::from(k) * 0.02;
        let ax = if (1.0..3.0).contains(&t) { -5.0 } else { 0.0 };
        let wz = if (2.0..4.0).contains(&t) { 15.0 } else { 0.0 };
        text.push_str(&format!("{t},{ax},0,0,0,0,{wz}\n"));
        let motion = VehicleMotion {
            accel: [ax, 0.0, 0.0],
            rates_deg_s: [0.0, 0.0, wz],
        };
        samples.push((t, motion));
    }
    (text, samples)
}

#[test]
fn a_vehicle_recording_plays_through_the_washout_and_follows_its_settings() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let path = dir.path().join("braking.csv");
    let (text, samples) = braking();
    std::fs::write(&path, text).unwrap_or_else(|e| panic!("{e}"));
    let mut h = super::tall_harness("seed", 2400.0);
    let before = h.state().scenario().clone();
    drop_file(&mut h, &path);
    assert!(
        h.query_by_label_contains("Cued 251 samples of vehicle motion over 5.00 s")
            .is_some(),
        "{:?}",
        h.state().files.status
    );
    // The motion is the poses `stewart cue` computes, through the samples' times.
    let scenario = h.state().scenario().clone();
    let times: Vec<f64> = samples.iter().map(|s| s.0).collect();
    let cue = |s: &stewart_kinematics::Scenario| {
        cue_recording(&s.geometry, &s.limits, &s.checks, &s.cueing, &samples)
            .map(|c| c.to_motion(&times, "x").unwrap_or_else(|e| panic!("{e}")))
            .unwrap_or_else(|e| panic!("{e}"))
    };
    assert_eq!(scenario.motion.trajectory, cue(&scenario).trajectory);
    assert_eq!(scenario.motion.sampling.len(), 251);
    // The panel, opened: the recording and its plots.
    h.get_by_label("Motion cueing").click();
    h.run();
    super::look(&mut h, "cueing.png");
    assert!(
        h.query_by_label_contains("Playing braking.csv: 251 samples")
            .is_some()
    );
    // A washout setting cues it again, as one edit.
    let scale = settings::find("cueing.translation_scale").unwrap_or_else(|e| panic!("{e}"));
    h.state_mut().editor().apply(scale, Some(1.0));
    h.run();
    let edited = h.state().scenario().clone();
    assert_eq!(edited.cueing.translation_scale, 1.0);
    assert_ne!(edited.motion, scenario.motion);
    assert_eq!(edited.motion.trajectory, cue(&edited).trajectory);
    // Undo: the scale and the motion come back together, and the recording with them
    // (it once vanished: the panel asked for a CSV and edits no longer cued it); redo
    // likewise; once more undone: the seed's motion.
    h.state_mut().undo_edit();
    h.run();
    assert_eq!(h.state().scenario(), &scenario);
    assert!(
        h.state().doc.cued_vehicle().is_some(),
        "undo dropped the recording"
    );
    assert!(
        h.query_by_label_contains("Playing braking.csv: 251 samples")
            .is_some()
    );
    h.state_mut().redo_edit();
    h.run();
    assert_eq!(h.state().scenario(), &edited);
    assert!(
        h.state().doc.cued_vehicle().is_some(),
        "redo dropped the recording"
    );
    h.state_mut().undo_edit();
    h.run();
    assert!(h.state().doc.cued_vehicle().is_some());
    h.state_mut().undo_edit();
    h.run();
    assert_eq!(h.state().scenario(), &before);
    // With another motion playing, a washout edit leaves the motion alone.
    h.state_mut().editor().apply(scale, Some(0.8));
    assert_eq!(h.state().scenario().motion, before.motion);
}

#[test]
fn the_cueing_plots_read_with_a_legend_below_and_the_wheel_over_them_scrolls_the_panel() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let path = dir.path().join("braking.csv");
    std::fs::write(&path, braking().0).unwrap_or_else(|e| panic!("{e}"));
    // A window of ordinary height: the side panel scrolls.
    let mut h = super::harness("seed");
    drop_file(&mut h, &path);
    // Scroll the side panel down (the wheel over its words, which no longer includes a
    // table that scrolls on its own) until the Motion cueing header is in sight, open it,
    // and scroll on until the force plot's legend is in sight.
    for _ in 0..40 {
        let header = h.query_by_label("Motion cueing").map(|n| n.rect());
        if header.is_some_and(|r| r.bottom() < 700.0) {
            break;
        }
        wheel(&mut h, egui::pos2(150.0, 400.0), -100.0);
    }
    h.get_by_label("Motion cueing").click();
    h.run();
    for _ in 0..40 {
        if h.query_by_label("vehicle x").is_some() {
            break;
        }
        wheel(&mut h, egui::pos2(150.0, 400.0), -100.0);
    }
    // Then a little further, so that the force plot is wholly in sight.
    wheel(&mut h, egui::pos2(150.0, 400.0), -150.0);
    super::look(&mut h, "cueing-scrolled.png");
    // Which line is which, said below the data.
    assert!(
        h.query_by_label_contains("Dashed: the vehicle's specific force")
            .is_some()
    );
    let legend = h.get_by_label("vehicle x").rect();
    for words in ["platform x", "vehicle y", "platform y"] {
        let r = h.get_by_label(words).rect();
        assert!((r.center().y - legend.center().y).abs() < 30.0, "{words}");
    }
    // The wheel over the force plot (just above its legend) scrolls the side panel.
    let header = h.get_by_label("Motion cueing").rect();
    let over_plot = egui::pos2(legend.left() + 120.0, legend.top() - 80.0);
    wheel(&mut h, over_plot, -120.0);
    let moved = h.get_by_label("Motion cueing").rect();
    assert!(
        moved.top() < header.top() - 40.0,
        "the panel did not scroll: {header:?} → {moved:?}"
    );
    super::look(&mut h, "cueing-legend.png");
}

/// Turn the wheel by `dy` points at `at` and draw until the smooth scroll has settled.
fn wheel(
    h: &mut egui_kittest::Harness<'static, crate::viewer::state::ViewerState>,
    at: egui::Pos2,
    dy: f32,
) {
    h.hover_at(at);
    h.event(egui::Event::MouseWheel {
        unit: egui::MouseWheelUnit::Point,
        delta: egui::vec2(0.0, dy),
        phase: egui::TouchPhase::Move,
        source: egui::MouseWheelSource::Wheel,
        modifiers: egui::Modifiers::NONE,
    });
    for _ in 0..30 {
        h.step();
    }
    h.run();
}

#[test]
fn the_planner_is_chosen_in_the_panel_cues_the_recording_and_is_compared_with_the_washout() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let path = dir.path().join("braking.csv");
    let (text, samples) = braking();
    std::fs::write(&path, text).unwrap_or_else(|e| panic!("{e}"));
    let mut h = super::tall_harness("seed", 2600.0);
    drop_file(&mut h, &path);
    h.get_by_label("Motion cueing").click();
    h.run();
    // The panel's settings, opened (the last "Settings" header: the panel's own).
    let headers: Vec<_> = h.query_all_by_label("Settings").collect();
    assert!(!headers.is_empty());
    headers[headers.len() - 1].click();
    h.run();
    // The washout's filters are offered, the planner's weights are not.
    assert!(
        h.query_all_by_label_contains("translation high-pass ω")
            .next()
            .is_some()
    );
    assert!(
        h.query_all_by_label_contains("MPC force weight")
            .next()
            .is_none()
    );
    h.get_by_label("Model-predictive (MPC)").click();
    h.run();
    let s = h.state().scenario().clone();
    assert_eq!(
        s.cueing.algorithm,
        stewart_kinematics::model::cueing_settings::CueingAlgorithm::Mpc
    );
    // The recording is cued again by the planner, as `stewart cue` would.
    let times: Vec<f64> = samples.iter().map(|s| s.0).collect();
    let planned = cue_recording(&s.geometry, &s.limits, &s.checks, &s.cueing, &samples)
        .map(|c| c.to_motion(&times, "x").unwrap_or_else(|e| panic!("{e}")))
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.motion.trajectory, planned.trajectory);
    // Its weights are offered now, the washout's filters not.
    assert!(
        h.query_all_by_label_contains("MPC force weight")
            .next()
            .is_some()
    );
    assert!(
        h.query_all_by_label_contains("translation high-pass ω")
            .next()
            .is_none()
    );
    // Both algorithms measured on the recording, the planner first.
    let v = h
        .state()
        .doc
        .cued_vehicle()
        .unwrap_or_else(|| panic!("a recording"));
    let [mpc, washout] = &v.compared[..] else {
        panic!("both algorithms compared")
    };
    assert!(mpc.measures.force_rmse_xy < washout.measures.force_rmse_xy);
    for words in [
        "Model-predictive (MPC): felt-force error in surge and sway",
        "Classical washout: felt-force error in surge and sway",
    ] {
        assert!(h.query_by_label_contains(words).is_some(), "{words}");
    }
    // The planner has no limiter: its line does not speak of one.
    let planner = h
        .get_by_label_contains("Model-predictive (MPC): felt-force error")
        .value()
        .unwrap_or_default();
    assert!(!planner.contains("limiter"), "{planner}");
    super::look(&mut h, "cueing-mpc.png");
    // One edit: undone, the washout again.
    h.state_mut().undo_edit();
    h.run();
    assert_eq!(
        h.state().scenario().cueing.algorithm,
        stewart_kinematics::model::cueing_settings::CueingAlgorithm::Washout
    );
}

/// Opening a recording brings its plots into sight (the keyframe table it lays out above
/// pushed them two screens down), and the legend wraps between entries, never between a
/// swatch and its words, in either language.
#[test]
fn an_opened_recording_shows_its_plots_and_legend_entries_stay_whole() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let path = dir.path().join("braking.csv");
    std::fs::write(&path, braking().0).unwrap_or_else(|e| panic!("{e}"));
    for lang in [crate::i18n::Lang::En, crate::i18n::Lang::Zh] {
        let mut state = crate::viewer::ViewerState::new(
            stewart_kinematics::Scenario::preset("seed").unwrap_or_else(|e| panic!("{e}")),
        );
        state.look.expand_panels = true;
        state.look.lang = lang;
        let mut h = super::harness_with(state, 800.0);
        drop_file(&mut h, &path);
        for _ in 0..4 {
            h.run();
        }
        let playing = lang.fmt(
            "cueing.playing",
            &[("name", &"braking.csv"), ("count", &251)],
        );
        let shown = h.query_by_label(&playing).map(|n| n.rect());
        let shown = shown.unwrap_or_else(|| panic!("{lang:?}: the plots are out of sight"));
        assert!(
            (0.0..800.0).contains(&shown.top()),
            "{lang:?}: {shown:?} out of the window"
        );
        // Each legend word right of its swatch: none starts a row on its own.
        let words: Vec<&str> = ["cueing.vehicle_x", "cueing.platform_x", "cueing.vehicle_y"]
            .into_iter()
            .chain(["cueing.platform_y"])
            .map(|k| lang.tr(k))
            .collect();
        let first = h.get_by_label(words[0]).rect().left();
        for w in &words {
            let left = h.get_by_label(w).rect().left();
            assert!(
                left >= first - 0.5,
                "{lang:?}: `{w}` starts a row at {left} (first {first})"
            );
        }
    }
}

#[test]
fn the_cueing_test_tab_runs_the_omct_of_the_settings_shown_and_says_when_it_is_stale() {
    use stewart_kinematics::analysis::cueing::omct::{OmctOptions, omct};
    let mut h = super::tall_harness("paired", 2400.0);
    h.get_by_label("Motion cueing").click();
    h.run();
    h.get_by_label("Cueing test (OMCT)").click();
    h.run();
    h.get_by_label("Run the test").click();
    // One frame takes the click (a spinner then turns while it runs).
    h.step();
    h.state_mut().tools.omct.wait();
    h.run();
    super::look(&mut h, "cueing-omct.png");
    // The report shown is the command line's, number for number.
    let s = stewart_kinematics::Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
    let never = || false;
    let direct = omct(
        &s.geometry,
        &s.limits,
        &s.cueing,
        &OmctOptions::default(),
        &never,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let shown = h
        .state()
        .tools
        .omct
        .latest
        .as_ref()
        .and_then(|o| o.report.as_ref().ok())
        .cloned()
        .unwrap_or_else(|| panic!("no report"));
    assert_eq!(shown.tests[0].gain, direct.tests[0].gain);
    // The default tilt rate limit (3°/s) clips surge and sway around 2.5 rad/s.
    assert!(
        h.query_by_label_contains("Distorted (harmonics over 5 %")
            .is_some()
    );
    assert!(h.query_by_label_contains("surge 2.51").is_some());
    // Other settings: the test shown is no longer theirs.
    let scale = settings::find("cueing.translation_scale").unwrap_or_else(|e| panic!("{e}"));
    h.state_mut().editor().apply(scale, Some(0.3));
    h.run();
    assert!(h.query_by_label_contains("run it again").is_some());
}
