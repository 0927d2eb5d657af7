//! Playback: play/pause, step, scrub, speed, loop.

use stewart_kinematics::Sampling;

use crate::i18n::Lang;
use crate::viewer::state::playback::Playback;

/// Play or pause the trajectory (the toolbar's first button; Space does the same).
pub(super) fn play_button(ui: &mut egui::Ui, playback: &mut Playback, t: Lang) {
    let label = if playback.is_playing() {
        t.tr("playback.pause")
    } else {
        t.tr("playback.play")
    };
    // As wide as the wider of its two words: the toolbar does not move when it changes.
    let width =
        super::widgets::button_width_for(ui, &[t.tr("playback.play"), t.tr("playback.pause")]);
    if ui
        .add(egui::Button::new(label).min_size(egui::vec2(width, 0.0)))
        .on_hover_text(t.tr("playback.key_space"))
        .clicked()
    {
        playback.toggle();
    }
}

/// The panel: playback alone, stepping through `sampling`'s samples.
pub(crate) fn show(ui: &mut egui::Ui, playback: &mut Playback, sampling: &Sampling, t: Lang) {
    let duration = sampling.duration();
    ui.heading(t.tr("playback.heading"));
    ui.horizontal(|ui| {
        if ui
            .button(t.tr("playback.step_back"))
            .on_hover_text("←")
            .clicked()
        {
            playback.step(-sampling.step(), duration);
        }
        if ui
            .button(t.tr("playback.step"))
            .on_hover_text("→")
            .clicked()
        {
            playback.step(sampling.step(), duration);
        }
        if ui
            .button(t.tr("playback.start"))
            .on_hover_text(t.tr("playback.key_home"))
            .clicked()
        {
            playback.time = 0.0;
        }
        ui.checkbox(&mut playback.looping, t.tr("playback.loop"));
    });
    ui.add(egui::Slider::new(&mut playback.time, 0.0..=duration).text(t.tr("playback.time")));
    ui.add(
        egui::Slider::new(&mut playback.speed, 0.1..=4.0)
            .logarithmic(true)
            .text(t.tr("playback.speed")),
    );
}
