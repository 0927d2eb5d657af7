//! Playback: play/pause, step, scrub, speed, loop.

use crate::viewer::state::{MotionMode, ViewerState};

/// The panel.
pub fn show(ui: &mut egui::Ui, state: &mut ViewerState) {
    ui.heading("Playback");
    ui.horizontal(|ui| {
        let label = if state.playing { "Pause" } else { "Play" };
        if ui.button(label).on_hover_text("Space").clicked() {
            state.playing = !state.playing;
            state.mode = MotionMode::Trajectory;
        }
        if ui.button("Step back").on_hover_text("←").clicked() {
            state.step(-1.0);
        }
        if ui.button("Step").on_hover_text("→").clicked() {
            state.step(1.0);
        }
        if ui.button("Start").on_hover_text("Home").clicked() {
            state.time = 0.0;
        }
        ui.checkbox(&mut state.looping, "Loop");
    });
    let duration = state.duration();
    ui.add(egui::Slider::new(&mut state.time, 0.0..=duration).text("time (s)"));
    ui.add(
        egui::Slider::new(&mut state.speed, 0.1..=4.0)
            .logarithmic(true)
            .text("speed (×)"),
    );
}
