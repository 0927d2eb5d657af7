//! Rotary servos in the viewer: the actuator switch, the servo sliders (declared settings),
//! the level home height, the servo panel and the plot in degrees.

use egui::accesskit::Role;
use egui_kittest::kittest::Queryable;

use super::{settle, tall_harness};

#[test]
fn legs_switch_to_servos_whose_sliders_edit_the_scenario() {
    let mut h = tall_harness("paired", 1400.0);
    h.get_by_label("Geometry").click();
    h.run();
    assert!(
        h.query_by_role_and_label(Role::Slider, "leg max (m)")
            .is_some()
    );
    h.get_by_label("Rotary servos").click();
    h.run();
    settle(&mut h);
    let servos = h
        .state()
        .scenario()
        .geometry
        .rotary()
        .cloned()
        .unwrap_or_else(|| panic!("the switch made no servos"));
    assert!((servos.horn_length() - 0.3).abs() < 1e-12);
    // Leg sliders gone, servo sliders there; the panel lists servos in degrees.
    assert!(
        h.query_by_role_and_label(Role::Slider, "leg max (m)")
            .is_none()
    );
    assert!(h.query_by_label("Servos").is_some());
    assert!(h.query_by_label("S1").is_some() && h.query_by_label("L1").is_none());
    let shown = h
        .state()
        .scenario()
        .geometry
        .servo_angles(&h.state().pose())
        .and_then(Result::ok)
        .unwrap_or_else(|| panic!("reachable"));
    assert!(
        h.query_by_label(&format!("{:+.2}°", shown[0].degrees()))
            .is_some()
    );
    h.get_by_role_and_label(Role::Slider, "horn length (m)")
        .set_value_accesskit(0.25);
    h.run();
    let r = h.state().scenario().geometry.rotary().cloned();
    assert_eq!(r.map(|r| r.horn_length()), Some(0.25));
    // A horn as long as the rod is refused, with the reason, and changes nothing.
    let rod = h
        .state()
        .scenario()
        .geometry
        .rotary()
        .map_or(0.0, |r| r.rod_length());
    h.get_by_role_and_label(Role::Slider, "horn length (m)")
        .set_value_accesskit(rod + 0.01);
    h.run();
    let r = h.state().scenario().geometry.rotary().cloned();
    assert_eq!(r.map(|r| r.horn_length()), Some(0.25));
    assert!(h.query_by_label_contains("must be shorter than").is_some());
    // The servo range and the level home height.
    h.get_by_role_and_label(Role::Slider, "horn length (m)")
        .set_value_accesskit(0.3);
    h.run();
    let level = h
        .state()
        .scenario()
        .geometry
        .servo_home_height()
        .unwrap_or_else(|| panic!("a level height"));
    h.get_by_label_contains("Level home height").click();
    h.run();
    assert!((h.state().scenario().geometry.home_height() - level).abs() < 1e-12);
    // Back to legs: no servos, the stroke offered again (off until switched on).
    h.get_by_label("Linear legs").click();
    h.run();
    assert!(h.state().scenario().geometry.rotary().is_none());
    assert!(h.query_by_label("leg max (m): off").is_some());
    assert!(
        h.query_by_role_and_label(Role::Slider, "horn length (m)")
            .is_none()
    );
}

#[test]
fn a_rotary_preset_shows_servo_angles_and_their_range() {
    let mut h = tall_harness("servo-desk", 1400.0);
    settle(&mut h);
    assert!(h.query_by_label("Servos").is_some());
    let frame = h
        .state()
        .scenario()
        .geometry
        .scene_frame(&h.state().pose(), Vec::new());
    let servos = frame.servos.unwrap_or_else(|| panic!("rotary scene"));
    let first = servos[0].angle_deg.unwrap_or_else(|| panic!("reachable"));
    assert!(h.query_by_label(&format!("{first:+.2}°")).is_some());
    // The report is the rotary one: servo ranges, clean.
    let report = h.state().report().cloned();
    assert!(report.is_some_and(|r| r.servo_ranges_deg.is_some() && r.is_clean()));
}
