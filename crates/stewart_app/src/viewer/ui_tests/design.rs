//! The Design panel: an envelope in, the stroke it needs out, and into the limits.

use crate::viewer::state::ViewerState;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use stewart_kinematics::Scenario;

/// The viewer on the seed preset with every section open.
fn seed_with_panels_open() -> Harness<'static, ViewerState> {
    let mut state = ViewerState::new(Scenario::preset("seed").unwrap_or_else(|e| panic!("{e}")));
    state.look.expand_panels = true;
    super::harness_with(state, 3600.0)
}

#[test]
fn the_stroke_an_envelope_needs_goes_into_the_limits() {
    let mut h = seed_with_panels_open();
    // z 0.7 .. 0.9 about the seed's home height 0.8 (the others at their defaults).
    h.state_mut().tools.design.spans[2] = [-0.1, 0.1];
    h.run();
    h.get_by_label("Compute").click();
    // The search runs on its own thread; the panel keeps drawing meanwhile.
    h.step();
    h.state_mut().tools.design.wait();
    h.run();
    assert!(h.query_by_label("Needed: 0.6551 .. 1.3520 m").is_some());
    super::look(&mut h, "design-panel.png");
    assert!(
        h.query_by_label("It does not fit the current limits.")
            .is_some()
    );
    h.get_by_label("Use as limits").click();
    h.run();
    let stroke = h.state().scenario().geometry.stroke();
    assert!(
        (stroke.min.unwrap_or(0.0) - 0.6551).abs() < 1e-4,
        "{stroke:?}"
    );
    assert!(
        (stroke.max.unwrap_or(0.0) - 1.3520).abs() < 1e-4,
        "{stroke:?}"
    );
    assert!(h.query_by_label("It fits the current limits.").is_some());
}

#[test]
fn a_bad_envelope_says_why() {
    let mut h = seed_with_panels_open();
    h.state_mut().tools.design.spans = [[0.0; 2]; 6];
    h.run();
    h.get_by_label("Compute").click();
    h.run();
    assert!(
        h.query_by_label_contains("the envelope is empty").is_some(),
        "the reason is shown"
    );
    assert!(!h.state().tools.design.busy());
}
