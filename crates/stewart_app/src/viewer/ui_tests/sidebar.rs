//! The controls' panel keeps the width the user gave it: nothing it shows widens it (it
//! grew from 320 to 416 points in one session and kept that at the next start), its
//! sliders leave their labels room, and a drag of its edge is what changes it.

use egui::accesskit::Role;
use egui_kittest::kittest::{NodeT as _, Queryable};
use stewart_kinematics::Scenario;

use crate::i18n::Lang;
use crate::viewer::panels::side_panel::DEFAULT_WIDTH;
use crate::viewer::state::ViewerState;

#[test]
fn the_sidebar_keeps_its_width_and_everything_in_it_fits() {
    for lang in [Lang::En, Lang::Zh] {
        for preset in ["paired", "crank-rig"] {
            let mut state =
                ViewerState::new(Scenario::preset(preset).unwrap_or_else(|e| panic!("{e}")));
            state.look.lang = lang;
            state.look.expand_panels = true;
            let mut h = super::harness_with(state, 4200.0);
            for _ in 0..3 {
                h.run();
            }
            let width = h.state().look.side_width;
            assert!(
                (width - DEFAULT_WIDTH).abs() <= 1.0,
                "{preset} in {lang:?}: the panel is {width} wide"
            );
            let mut rows = 0;
            for node in h.get_all_by_role(Role::Slider) {
                let r = node.rect();
                if r.left() < width {
                    rows += 1;
                    assert!(
                        r.right() <= width + 0.5,
                        "{preset} in {lang:?}: {:?} runs to {}",
                        node.accesskit_node().label(),
                        r.right()
                    );
                }
            }
            assert!(rows > 20, "{rows} sliders");
            // Nothing runs past the panel's edge (a wrapped label, a row of values).
            let cut: Vec<String> = h
                .query_all(egui_kittest::kittest::by())
                .filter(|n| n.accesskit_node().bounding_box().is_some())
                .filter(|n| n.rect().left() < width && n.rect().right() > width + 0.5)
                .map(|n| {
                    format!(
                        "{:?}{:?} to {}",
                        n.accesskit_node().label(),
                        n.value(),
                        n.rect().right()
                    )
                })
                .collect();
            assert!(
                cut.is_empty(),
                "{preset} in {lang:?}: cut at the panel's edge: {cut:#?}"
            );
            super::look(&mut h, &format!("sidebar-{preset}-{lang:?}.png"));
        }
    }
}

#[test]
fn a_drag_of_its_edge_is_what_widens_the_sidebar() {
    let mut h = super::harness("paired");
    h.run();
    let edge = h
        .get_all_by_role(Role::Splitter)
        .map(|n| n.rect())
        .find(|r| r.height() > r.width())
        .unwrap_or_else(|| panic!("no splitter beside the panel"))
        .center();
    h.hover_at(edge);
    h.run();
    h.drag_at(edge);
    h.run();
    h.hover_at(edge + egui::vec2(80.0, 0.0));
    h.run();
    h.drop_at(edge + egui::vec2(80.0, 0.0));
    h.run();
    h.run();
    let width = h.state().look.side_width;
    assert!((width - DEFAULT_WIDTH - 80.0).abs() <= 2.0, "{width}");
}
