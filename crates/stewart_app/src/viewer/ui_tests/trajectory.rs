//! The Motion panel's trajectory mode: kind, sampling and the kind's numbers.

use egui::accesskit::Role;
use egui_kittest::kittest::Queryable;
use stewart_kinematics::model::trajectory::Trajectory;
use stewart_kinematics::model::trajectory::keyframes::KeyframeError;

use crate::viewer::error::ViewerError;

use super::harness;

#[test]
fn switching_the_kind_and_moving_its_sliders_changes_the_motion() {
    let mut h = harness("paired");
    h.get_by_role_and_label(Role::ComboBox, "Kind").click();
    h.run();
    h.get_by_label("Circle").click();
    h.run();
    assert!(matches!(
        h.state().scenario().motion.trajectory,
        Trajectory::Circle(_)
    ));
    h.get_by_role_and_label(Role::Slider, "radius (m)")
        .set_value_accesskit(0.05);
    h.run();
    // Every plotted sample now lies 5 cm from the axis: legs re-solved for the new circle.
    let Trajectory::Circle(c) = h.state().scenario().motion.trajectory else {
        panic!("not a circle");
    };
    assert_eq!(c.radius, 0.05);
    let p = h
        .state()
        .scenario()
        .motion
        .trajectory
        .pose_at(1.234)
        .position;
    assert!((p.xy().norm() - 0.05).abs() < 1e-12);
    h.get_by_role_and_label(Role::Slider, "samples")
        .set_value_accesskit(101.0);
    h.run();
    assert_eq!(h.state().plot_samples().0.len(), 101);
    assert_eq!(h.state().plot_samples().1.len(), 101);
}

#[test]
fn sinusoid_channels_have_every_number() {
    let mut h = harness("seed");
    h.get_by_label("pitch channel").click();
    h.run();
    for label in [
        "pitch amplitude (°)",
        "pitch frequency (Hz)",
        "pitch phase (°)",
        "pitch offset (°)",
    ] {
        assert!(
            h.query_by_role_and_label(Role::Slider, label).is_some(),
            "{label}"
        );
    }
    h.get_by_role_and_label(Role::Slider, "pitch phase (°)")
        .set_value_accesskit(0.0);
    h.run();
    let Trajectory::Sinusoid(s) = h.state().scenario().motion.trajectory else {
        panic!("not a sinusoid");
    };
    assert_eq!(s.pitch_deg.phase.degrees(), 0.0);
    assert_eq!(
        h.state()
            .scenario()
            .motion
            .trajectory
            .pose_at(0.0)
            .pitch
            .degrees(),
        0.0
    );
}

#[test]
fn keyframes_are_edited_in_a_table_and_bad_times_refused() {
    let mut h = harness("keyframes");
    let keys = |h: &egui_kittest::Harness<'_, crate::viewer::ViewerState>| match &h
        .state()
        .scenario()
        .motion
        .trajectory
    {
        Trajectory::Keyframes(k) => k.keys().len(),
        _ => 0,
    };
    assert_eq!(keys(&h), 5);
    h.get_by_label("Add key").click();
    h.run();
    assert_eq!(keys(&h), 6);
    h.get_by_label("Remove last key").click();
    h.run();
    assert_eq!(keys(&h), 5);
    h.get_by_label("linear").click();
    h.run();
    let Trajectory::Keyframes(k) = &h.state().scenario().motion.trajectory else {
        panic!("not keyframes");
    };
    assert_eq!(
        k.interpolation(),
        stewart_kinematics::model::trajectory::Interpolation::Linear
    );
    // A key moved before its predecessor is refused: the keys stay, the reason shows.
    let before = h.state().scenario().clone();
    let times: Vec<f64> = k.keys().iter().map(|k| k.t).collect();
    let third = h
        .get_all_by_role_and_label(Role::SpinButton, "t (s)")
        .nth(2)
        .unwrap_or_else(|| panic!("no time cell of the third key"));
    third.set_value_accesskit(times[0] - 1.0);
    h.run();
    assert_eq!(h.state().scenario(), &before);
    assert!(
        h.state()
            .doc
            .edit_error
            .as_ref()
            .is_some_and(|(_, e)| matches!(
                e,
                ViewerError::Keyframes(KeyframeError::NotIncreasing { index: 3, .. })
            )),
        "{:?}",
        h.state().doc.edit_error
    );
    assert!(h.query_by_label_contains("times must increase").is_some());
}

/// Press and release the primary button at `pos`.
fn click_at(h: &mut egui_kittest::Harness<'_, crate::viewer::ViewerState>, pos: egui::Pos2) {
    h.event(egui::Event::PointerMoved(pos));
    h.run();
    for pressed in [true, false] {
        h.event(egui::Event::PointerButton {
            pos,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: egui::Modifiers::NONE,
        });
        h.run();
    }
}

#[test]
fn clicking_on_the_plot_scrubs_the_time() {
    let mut h = harness("seed");
    assert!(h.state().playback.playing);
    // The plot fills the bottom panel right of the controls (1280 × 800 window).
    click_at(&mut h, egui::pos2(600.0, 700.0));
    let left = h.state().playback.time;
    assert!(!h.state().playback.playing);
    click_at(&mut h, egui::pos2(1100.0, 700.0));
    let right = h.state().playback.time;
    assert!(
        0.0 < left && left < right && right <= 10.0,
        "{left} {right}"
    );
    // 500 px of a plot about 850 px wide spanning a little over 10 s.
    assert!(right - left > 4.0, "{left} {right}");
}
