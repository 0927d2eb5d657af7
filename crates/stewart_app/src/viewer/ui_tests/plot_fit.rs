//! The live plot fits its panel at projector sizes, in presentation mode (text half as
//! large again) and out of it: both limit lines and their labels inside the plot's frame,
//! every legend row and the values/forces toggle inside the panel.

use crate::viewer::panels::plot_ticks::{MIN_TIME_LABELS, TIME_LABEL_SPACING};
use crate::viewer::state::ViewerState;
use stewart_kinematics::Scenario;

use super::sized_harness;

/// Whether `inner` lies within `outer` (to half a point).
fn inside(inner: egui::Rect, outer: egui::Rect) -> bool {
    outer.expand(0.5).contains_rect(inner)
}

#[test]
fn the_plot_shows_its_limits_and_whole_legend_at_projector_sizes() {
    for preset in ["seed", "paired"] {
        for (w, h) in [(1024.0, 768.0), (1280.0, 720.0), (1088.0, 612.0)] {
            // Out of presentation mode, entered with P, and started in it (`view
            // --presentation`, where the plot starts a quarter of the window high).
            for (presentation, started) in [(true, false), (false, false), (true, true)] {
                let case = format!(
                    "{preset} at {w}×{h}, presentation {presentation} (started so: {started})"
                );
                let scenario = Scenario::preset(preset).unwrap_or_else(|e| panic!("{e}"));
                let mut state = ViewerState::new(scenario);
                state.look.presentation = started;
                let mut harness = sized_harness(state, egui::vec2(w, h));
                if presentation && !started {
                    harness.key_press(egui::Key::P);
                    harness.run();
                    harness.run();
                }
                let look = &harness.state().look;
                assert_eq!(look.presentation, presentation, "{case}");
                let placed =
                    (look.plot_placement.clone()).unwrap_or_else(|| panic!("{case}: no plot"));
                let window = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(w, h));
                let panel = placed.space;
                assert!(inside(panel, window), "{case}: the plot's space {panel:?}");
                let frame = placed.frame;
                assert!(inside(frame, panel), "{case}: frame {frame:?} in {panel:?}");
                assert_eq!(placed.limits.len(), 2, "{case}: both limits drawn");
                // The vertical axis's label, centred on the frame, is not cut at its ends.
                assert!(
                    placed.y_label_length <= frame.height() + 0.5,
                    "{case}: a label {} long beside a frame {} high",
                    placed.y_label_length,
                    frame.height()
                );
                for (y, label) in &placed.limits {
                    assert!(
                        (frame.top() - 0.5..=frame.bottom() + 0.5).contains(y),
                        "{case}: a limit line at {y} outside the frame {frame:?}"
                    );
                    assert!(
                        inside(*label, frame),
                        "{case}: label {label:?} outside {frame:?}"
                    );
                }
                // Six curves, two limits and the time marker at least.
                assert!(
                    placed.legend.len() >= 9,
                    "{case}: {} rows",
                    placed.legend.len()
                );
                for row in &placed.legend {
                    assert!(
                        inside(*row, panel),
                        "{case}: legend row {row:?} outside {panel:?}"
                    );
                }
                if let Some(toggle) = placed.toggle {
                    assert!(
                        inside(toggle, frame),
                        "{case}: toggle {toggle:?} outside {frame:?}"
                    );
                }
                assert_eq!(placed.toggle.is_some(), preset == "paired", "{case}");
                // Five time labels at least, as far apart as egui_plot needs to draw them.
                let [lo, hi] = placed.times;
                let step = stewart_render::ticks::largest_step_with(lo, hi, MIN_TIME_LABELS)
                    .unwrap_or_else(|| panic!("{case}: no step for {lo}..{hi}"));
                let apart = f64::from(frame.width()) * step / (hi - lo);
                assert!(
                    apart > f64::from(*TIME_LABEL_SPACING.start()),
                    "{case}: time labels {apart} points apart"
                );
                let labels = ((hi / step).floor() - (lo / step).ceil()) as usize + 1;
                assert!(labels >= MIN_TIME_LABELS, "{case}: {labels} time labels");
            }
        }
    }
}
