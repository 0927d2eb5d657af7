//! Playback: play/pause, step, scrub, speed, loop.

use crate::viewer::state::ViewerState;

/// Play or pause the trajectory (the toolbar's first button; Space does the same).
pub(super) fn play_button(ui: &mut egui::Ui, state: &mut ViewerState) {
    let t = state.look.lang;
    let label = if state.playback.is_playing() {
        t.tr("playback.pause")
    } else {
        t.tr("playback.play")
    };
    if ui
        .button(label)
        .on_hover_text(t.tr("playback.key_space"))
        .clicked()
    {
        state.playback.toggle();
    }
    if let Some(rate) = state.playback.skipping_frames() {
        ui.label(
            egui::RichText::new(t.fmt("playback.skipping", &[("fps", &format!("{rate:.0}"))]))
                .color(ui.visuals().warn_fg_color),
        )
        .on_hover_text(t.tr("playback.skipping_tip"));
    }
}

/// The panel.
pub fn show(ui: &mut egui::Ui, state: &mut ViewerState) {
    let t = state.look.lang;
    ui.heading(t.tr("playback.heading"));
    ui.horizontal(|ui| {
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
