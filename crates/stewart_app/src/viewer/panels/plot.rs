//! The live plot of leg lengths (or servo angles): the whole trajectory with a moving
//! time marker, or in manual mode the rolling history of the last seconds.

use egui::Color32;
use egui_plot::{HLine, Legend, Line, LineStyle, Plot, PlotPoints, VLine};

use crate::viewer::history::History;
use crate::viewer::playback::MotionMode;
use crate::viewer::state::ViewerState;

/// Leg `i`'s colour, as in exported plots.
pub fn leg_colour(i: usize) -> Color32 {
    let [r, g, b] = stewart_render::theme::SERIES_RGB[i % 6];
    Color32::from_rgb(r, g, b)
}

/// The panel. In trajectory mode, clicking or dragging on the plot scrubs the time (the
/// wheel still zooms, double-click resets the view).
pub fn show(ui: &mut egui::Ui, state: &mut ViewerState) {
    let geometry = &state.scenario().geometry;
    let quantity = geometry.quantity();
    let [min, max] = geometry.quantity_limits();
    let manual = state.playback.mode == MotionMode::Manual;
    let x_label = if manual {
        "seconds ago (manual pose history)"
    } else {
        "time (s)"
    };
    let mut plot = Plot::new(if manual { "leg history" } else { "leg lengths" })
        .allow_drag(manual)
        .legend(Legend::default())
        .x_axis_label(x_label)
        .y_axis_label(format!("{} ({})", quantity.name, quantity.unit));
    if manual {
        plot = plot.include_x(-History::WINDOW).include_x(0.0);
    }
    let shown = plot.show(ui, |plot| {
        for leg in 0..6 {
            let points: Vec<[f64; 2]> = if manual {
                state
                    .playback
                    .history
                    .entries()
                    .map(|(t, l)| [t - state.playback.clock, l[leg]])
                    .collect()
            } else {
                let (times, lengths) = state.plot_samples();
                times
                    .iter()
                    .zip(lengths)
                    .map(|(t, l)| [*t, l[leg]])
                    .collect()
            };
            // A servo out of reach has no angle: its curve breaks there.
            let name = format!("{}{}", quantity.symbol, leg + 1);
            for run in points.split(|p| p[1].is_nan()).filter(|r| !r.is_empty()) {
                let run: PlotPoints = run.iter().copied().collect();
                plot.line(Line::new(name.clone(), run).color(leg_colour(leg)));
            }
        }
        for (name, limit) in [("min", min), ("max", max)] {
            if let Some(v) = limit {
                plot.hline(
                    HLine::new(format!("{}{name}", quantity.symbol), v)
                        .style(LineStyle::dashed_loose())
                        .color(Color32::GRAY),
                );
            }
        }
        if !manual {
            let marker = if state.look.is_light() {
                Color32::BLACK
            } else {
                Color32::WHITE
            };
            let now = state.scenario().motion.sampling.start() + state.playback.time;
            plot.vline(VLine::new("now", now).color(marker));
        }
    });
    let response = &shown.response;
    if !manual
        && (response.clicked() || response.dragged_by(egui::PointerButton::Primary))
        && let Some(pointer) = response.interact_pointer_pos()
    {
        let t = shown.transform.value_from_position(pointer).x;
        let start = state.scenario().motion.sampling.start();
        state.playback.time = (t - start).clamp(0.0, state.duration());
        state.playback.playing = false;
    }
}
