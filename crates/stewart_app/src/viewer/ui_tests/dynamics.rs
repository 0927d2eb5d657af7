//! The Dynamics panel: a payload added, the actuators' stiffness and parts set, the modes
//! at the pose shown, one of them swinging in the 3D view, and the plot switched to the
//! actuator forces.

use egui_kittest::kittest::Queryable;
use stewart_kinematics::io::settings;

#[test]
fn a_payload_and_a_stiffness_give_six_modes_and_the_view_swings_along_one() {
    let mut h = super::tall_harness("paired", 2600.0);
    h.get_by_label("Dynamics and modes").click();
    h.run();
    // The preset's own payload, removed.
    h.get_by_label("Remove the payload").click();
    h.run();
    assert_eq!(h.state().scenario().payload, None);
    assert!(h.query_by_label_contains("No payload").is_some());
    assert!(
        h.query_by_label("forces").is_none(),
        "no forces to plot without a payload"
    );
    h.get_by_label("Add a payload").click();
    h.run();
    let payload = h
        .state()
        .scenario()
        .payload
        .unwrap_or_else(|| panic!("no payload"));
    // In proportion to the platform: 50 kg on the seed-sized platform.
    assert!(
        (payload.mass
            - 50.0 * (h.state().scenario().geometry.characteristic_length() / 0.6).powi(3))
        .abs()
            < 1e-9
    );
    // No stiffness yet: the panel says what is missing, naming the control as it reads.
    assert!(
        h.query_by_label_contains("switch on *actuator stiffness* under Actuators and legs")
            .is_some()
    );
    assert!(h.query_by_label("actuator stiffness (N/m): off").is_some());
    // Switched on, it starts at a typical actuator's stiffness, not the slider's top.
    let stiffness = settings::find("dynamics.actuator_stiffness").unwrap_or_else(|e| panic!("{e}"));
    let switch = h
        .query_by_label("actuator stiffness (N/m): off")
        .map(|n| n.rect())
        .unwrap_or_else(|| panic!("no switch"));
    let left = egui::pos2(switch.left() - 12.0, switch.center().y);
    h.hover_at(left);
    h.event(egui::Event::PointerButton {
        pos: left,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: egui::Modifiers::NONE,
    });
    h.event(egui::Event::PointerButton {
        pos: left,
        button: egui::PointerButton::Primary,
        pressed: false,
        modifiers: egui::Modifiers::NONE,
    });
    h.run();
    assert_eq!(stiffness.get(h.state().scenario()), Some(2.0e7));
    h.state_mut().doc.apply(stiffness, Some(1e7));
    h.run();
    let modes = (1..=6)
        .filter(|k| h.query_by_label(&k.to_string()).is_some())
        .count();
    assert_eq!(modes, 6, "six modes to choose from");
    assert!(h.query_all_by_label_contains(" Hz").count() >= 6);
    // The slider shows the unit of linear legs.
    assert!(
        h.query_all_by_label_contains("actuator stiffness (N/m)")
            .next()
            .is_some()
    );
    h.get_by_label("3").click();
    h.get_by_label("Swing the 3D view along the chosen mode")
        .click();
    h.run();
    assert!(h.state().tools.modes.animate && h.state().tools.modes.mode == 2);
    assert!(
        h.state().animating(),
        "the window keeps drawing while a mode swings"
    );
    h.state_mut().advance(0.25);
    h.run();
    super::look(&mut h, "dynamics.png");
    assert!(h.query_by_label_contains("Mode 3 (").is_some());
    // The picture swings; the pose the link would send does not.
    let state = h.state();
    let pose = state.pose();
    let shown = state.tools.modes.shown_pose(state.scenario(), pose);
    assert!(
        (shown.position - pose.position).norm() > 1e-3,
        "{shown:?} vs {pose:?}"
    );
    let list = state.draw_list(&state.theme());
    let unswung = {
        let mut still = state.tools.modes.clone();
        still.animate = false;
        let frame = state
            .scenario()
            .geometry
            .scene_frame(&still.shown_pose(state.scenario(), pose), Vec::new());
        stewart_render::DrawList::build(
            &frame,
            &state.theme(),
            &stewart_render::Overlays::default(),
        )
    };
    assert_ne!(
        list.spheres, unswung.spheres,
        "the joints drawn move with the mode"
    );
}

#[test]
fn the_plot_switches_to_the_actuator_forces() {
    let mut h = super::tall_harness("paired", 2600.0);
    h.get_by_label("Dynamics and modes").click();
    h.run();
    h.get_by_label("Remove the payload").click();
    h.run();
    h.get_by_label("Add a payload").click();
    h.run();
    h.get_by_label("forces").click();
    h.run();
    assert!(h.state().look.plot_efforts);
    super::look(&mut h, "forces_plot.png");
    let (times, efforts) = h
        .state()
        .doc
        .plot_efforts()
        .unwrap_or_else(|| panic!("no efforts"));
    assert_eq!(times.len(), efforts.len());
    // The payload's weight pushes every leg (compression), about a sixth of it each.
    let weight = h.state().scenario().payload.map_or(0.0, |p| p.mass) * 9.80665;
    for f in efforts[0] {
        assert!(
            f > 0.05 * weight && f < 0.5 * weight,
            "{f} for a weight of {weight}"
        );
    }
    h.get_by_label("values").click();
    h.run();
    assert!(!h.state().look.plot_efforts);
}

#[test]
fn the_modes_of_a_singular_pose_say_which_directions_have_no_stiffness() {
    // The seed's staggered hexagons are singular at home: three directions are free.
    let mut h = super::tall_harness("seed", 2600.0);
    h.state_mut().playback.mode = crate::viewer::state::playback::MotionMode::Manual;
    h.run();
    h.get_by_label("Dynamics and modes").click();
    h.run();
    if h.state().scenario().payload.is_none() {
        h.get_by_label("Add a payload").click();
        h.run();
    }
    let stiffness = settings::find("dynamics.actuator_stiffness").unwrap_or_else(|e| panic!("{e}"));
    h.state_mut().doc.apply(stiffness, Some(2e7));
    h.run();
    h.run();
    assert_eq!(h.query_all_by_label("no stiffness").count(), 3);
    assert!(
        h.query_by_label("0.00 Hz").is_none(),
        "no frequency of 0 shown"
    );
    // Those cannot be chosen to swing; the choice moved to the first mode with stiffness.
    assert_eq!(h.state().tools.modes.mode, 3);
    h.get_by_label("1").click();
    h.run();
    assert_eq!(h.state().tools.modes.mode, 3, "mode 1 cannot be chosen");
    h.get_by_label("5").click();
    h.run();
    assert_eq!(h.state().tools.modes.mode, 4);
    super::look(&mut h, "modes-singular.png");
}
