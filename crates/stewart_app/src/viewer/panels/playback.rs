//! Playback: play/pause, step, scrub, speed, loop.

use crate::viewer::playback::MotionMode;
use crate::viewer::state::ViewerState;

/// The panel.
pub fn show(ui: &mut egui::Ui, state: &mut ViewerState) {
    ui.heading("Playback");
    ui.horizontal(|ui| {
        let label = if state.playback.playing {
            "Pause"
        } else {
            "Play"
        };
        if ui.button(label).on_hover_text("Space").clicked() {
            state.playback.playing = !state.playback.playing;
            state.playback.mode = MotionMode::Trajectory;
        }
        if ui.button("Step back").on_hover_text("←").clicked() {
            state.step(-1.0);
        }
        if ui.button("Step").on_hover_text("→").clicked() {
            state.step(1.0);
        }
        if ui.button("Start").on_hover_text("Home").clicked() {
            state.playback.time = 0.0;
        }
        ui.checkbox(&mut state.playback.looping, "Loop");
    });
    let duration = state.duration();
    ui.add(egui::Slider::new(&mut state.playback.time, 0.0..=duration).text("time (s)"));
    ui.add(
        egui::Slider::new(&mut state.playback.speed, 0.1..=4.0)
            .logarithmic(true)
            .text("speed (×)"),
    );
}
