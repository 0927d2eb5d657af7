//! The setting sliders: a range of the platform's size, fine drags with Shift, reset by
//! right-click without the knob jumping, a tooltip naming the file key.

use egui::accesskit::Role;
use egui_kittest::kittest::{NodeT as _, Queryable};
use stewart_kinematics::io::settings;

use super::harness;

/// Drag from `from` by `dx` points, with `modifiers` held until the button is released.
fn drag(
    h: &mut egui_kittest::Harness<'static, crate::viewer::ViewerState>,
    from: egui::Pos2,
    dx: f32,
    modifiers: egui::Modifiers,
) {
    drag_letting_go(h, from, dx, modifiers, false);
}

/// [`drag`], letting the modifiers go before the button when `early` (in the same frame,
/// as a hand lets go of both at once).
fn drag_letting_go(
    h: &mut egui_kittest::Harness<'static, crate::viewer::ViewerState>,
    from: egui::Pos2,
    dx: f32,
    modifiers: egui::Modifiers,
    early: bool,
) {
    h.event(egui::Event::ModifiersChanged(modifiers));
    h.hover_at(from);
    h.run();
    h.event(egui::Event::PointerButton {
        pos: from,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers,
    });
    h.run();
    for k in 1..=4 {
        h.hover_at(from + egui::vec2(dx * k as f32 / 4.0, 0.0));
        h.run();
    }
    if early {
        h.event(egui::Event::ModifiersChanged(egui::Modifiers::NONE));
    }
    h.event(egui::Event::PointerButton {
        pos: from + egui::vec2(dx, 0.0),
        button: egui::PointerButton::Primary,
        pressed: false,
        modifiers: if early {
            egui::Modifiers::NONE
        } else {
            modifiers
        },
    });
    h.event(egui::Event::ModifiersChanged(egui::Modifiers::NONE));
    h.run();
}

fn duration(h: &egui_kittest::Harness<'static, crate::viewer::ViewerState>) -> f64 {
    h.state().scenario().motion.sampling.duration()
}

#[test]
fn right_click_opens_the_reset_menu_without_moving_the_knob() {
    let mut h = harness("paired");
    h.get_by_role_and_label(Role::Slider, "duration (s)")
        .set_value_accesskit(30.0);
    h.run();
    assert_eq!(duration(&h), 30.0);
    // The right button pressed away from the knob: the value stays (it used to jump to
    // the pointer before the menu opened).
    h.get_by_role_and_label(Role::Slider, "duration (s)")
        .click_secondary();
    h.run();
    assert_eq!(duration(&h), 30.0);
    h.get_by_label_contains("Reset to").click();
    h.run();
    let default = settings::all()
        .iter()
        .find(|s| s.key == "trajectory.duration_s")
        .and_then(|s| s.default_for(h.state().scenario()))
        .unwrap_or_default();
    assert_eq!(duration(&h), default);
}

#[test]
fn shift_drags_move_a_tenth_as_far() {
    let mut h = harness("paired");
    let before = duration(&h);
    let setting = settings::all()
        .iter()
        .find(|s| s.key == "trajectory.duration_s")
        .unwrap_or_else(|| panic!("no setting"));
    let range = setting.range_for(h.state().scenario());
    let width = f64::from(h.ctx.global_style().spacing.slider_width);
    let rect = h.get_by_role_and_label(Role::Slider, "duration (s)").rect();
    // Grabbed anywhere on the slider, Shift held: the value does not jump to the pointer,
    // it moves a tenth of the plain drag's rate (40 points of a linear slider).
    let grab = egui::pos2(rect.left() + 10.0, rect.center().y);
    drag(&mut h, grab, 40.0, egui::Modifiers::SHIFT);
    let moved = duration(&h) - before;
    let expected = 0.1 * 40.0 / width * (range.end() - range.start());
    assert!(
        (moved - expected).abs() < 0.15 * expected,
        "{moved} vs {expected}"
    );
    // Without Shift, the same drag goes ten times as far per point.
    let at = duration(&h);
    drag(
        &mut h,
        grab + egui::vec2(0.0, 0.0),
        40.0,
        egui::Modifiers::NONE,
    );
    assert!(
        (duration(&h) - at).abs() > 3.0 * moved.abs(),
        "{} vs {at}",
        duration(&h)
    );
}

#[test]
fn a_fine_drag_keeps_its_value_when_shift_is_let_go_with_the_button_and_is_one_undo_step() {
    let mut h = harness("paired");
    let before = duration(&h);
    let rect = h.get_by_role_and_label(Role::Slider, "duration (s)").rect();
    let grab = egui::pos2(rect.left() + 10.0, rect.center().y);
    drag_letting_go(&mut h, grab, 40.0, egui::Modifiers::SHIFT, true);
    let moved = duration(&h) - before;
    // A fine step (the plain slider would have jumped to the pointer near the left end).
    let setting = settings::find("trajectory.duration_s").unwrap_or_else(|e| panic!("{e}"));
    let range = setting.range_for(h.state().scenario());
    let width = f64::from(h.ctx.global_style().spacing.slider_width);
    let expected = 0.1 * 40.0 / width * (range.end() - range.start());
    assert!(
        (moved - expected).abs() < 0.15 * expected,
        "{moved} vs {expected}"
    );
    // One gesture, one undo step.
    assert!(h.state_mut().undo_edit());
    assert_eq!(duration(&h), before);
    assert!(!h.state_mut().undo_edit(), "a second undo step");
}

#[test]
fn a_desk_platforms_radius_slider_is_not_pinned_at_its_left_end() {
    let mut h = super::tall_harness("servo-desk", 1600.0);
    h.get_by_label("Geometry").click();
    h.run();
    let node = h.get_by_role_and_label(Role::Slider, "base radius (m)");
    let value = node.value().unwrap_or_default();
    let setting = settings::all()
        .iter()
        .find(|s| s.key == "geometry.base_radius")
        .unwrap_or_else(|| panic!("no setting"));
    let range = setting.range_for(h.state().scenario());
    let v = setting.get(h.state().scenario()).unwrap_or_default();
    let share = (v - range.start()) / (range.end() - range.start());
    assert!((0.1..0.9).contains(&share), "{v} in {range:?} ({value})");
    // The tooltip names the key in scenario files.
    node.hover();
    h.run();
    assert!(
        h.query_by_label_contains("`geometry.base_radius` in scenario files")
            .is_some()
    );
}

#[test]
fn a_fine_drag_shows_the_value_applied_while_it_goes_on() {
    let mut h = harness("paired");
    let rect = h.get_by_role_and_label(Role::Slider, "duration (s)").rect();
    let grab = egui::pos2(rect.left() + 10.0, rect.center().y);
    h.event(egui::Event::ModifiersChanged(egui::Modifiers::SHIFT));
    h.hover_at(grab);
    h.run();
    h.event(egui::Event::PointerButton {
        pos: grab,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: egui::Modifiers::SHIFT,
    });
    h.run();
    for k in 1..=4 {
        h.hover_at(grab + egui::vec2(10.0 * k as f32, 0.0));
        h.run();
        // The slider reads what is applied (not where the pointer would put a plain drag).
        let node = h.get_by_role_and_label(Role::Slider, "duration (s)");
        let shown = (node.accesskit_node().numeric_value()).unwrap_or_else(|| panic!("no value"));
        let applied = duration(&h);
        assert!(
            (shown - applied).abs() < 0.01,
            "step {k}: the slider shows {shown}, {applied} is applied"
        );
    }
    h.event(egui::Event::PointerButton {
        pos: grab + egui::vec2(40.0, 0.0),
        button: egui::PointerButton::Primary,
        pressed: false,
        modifiers: egui::Modifiers::SHIFT,
    });
    h.event(egui::Event::ModifiersChanged(egui::Modifiers::NONE));
    h.run();
}
