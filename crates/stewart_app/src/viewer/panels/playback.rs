//! Playback: play/pause, step, scrub, speed, loop.

use crate::viewer::playback::MotionMode;
use crate::viewer::state::ViewerState;

/// The panel.
pub fn show(ui: &mut egui::Ui, state: &mut ViewerState) {
    let t = state.look.lang;
    ui.heading(t.tr("playback.heading"));
    ui.horizontal(|ui| {
        let label = if state.playback.playing {
            t.tr("playback.pause")
        } else {
            t.tr("playback.play")
        };
        if ui
            .button(label)
            .on_hover_text(t.tr("playback.key_space"))
            .clicked()
        {
            state.playback.playing = !state.playback.playing;
            state.playback.mode = MotionMode::Trajectory;
        }
        if ui
            .button(t.tr("playback.step_back"))
            .on_hover_text("←")
            .clicked()
        {
            state.step(-1.0);
        }
        if ui
            .button(t.tr("playback.step"))
            .on_hover_text("→")
            .clicked()
        {
            state.step(1.0);
        }
        if ui
            .button(t.tr("playback.start"))
            .on_hover_text(t.tr("playback.key_home"))
            .clicked()
        {
            state.playback.time = 0.0;
        }
        ui.checkbox(&mut state.playback.looping, t.tr("playback.loop"));
    });
    let duration = state.duration();
    ui.add(egui::Slider::new(&mut state.playback.time, 0.0..=duration).text(t.tr("playback.time")));
    ui.add(
        egui::Slider::new(&mut state.playback.speed, 0.1..=4.0)
            .logarithmic(true)
            .text(t.tr("playback.speed")),
    );
}
