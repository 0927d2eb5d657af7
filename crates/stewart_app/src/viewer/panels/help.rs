//! *Help / keys* (F1 or ?): every key and mouse gesture of the viewer in one window, in
//! the language shown.

use crate::i18n::Lang;
use crate::viewer::state::teleop::KEYS;

/// The keys and gestures, each with the locale key of what it does.
const ROWS: [(&str, &str); 21] = [
    ("Space", "help.play"),
    ("← / →", "help.step"),
    ("Home", "help.start"),
    ("P, F5", "help.presentation"),
    ("G", "help.plot"),
    ("F11", "help.fullscreen"),
    ("F12", "help.screenshot"),
    ("Esc", "help.escape"),
    ("Ctrl+Z", "help.undo"),
    ("Ctrl+Shift+Z, Ctrl+Y", "help.redo"),
    ("Ctrl+O", "help.open"),
    ("Ctrl+S", "help.save"),
    ("Ctrl+Shift+S", "help.save_as"),
    ("Ctrl+Q", "help.quit"),
    ("F1, ?", "help.help"),
    ("help.left_drag", "help.orbit"),
    ("help.right_drag", "help.pan"),
    ("help.wheel", "help.zoom"),
    ("help.ctrl_wheel", "help.zoom_plot"),
    ("help.double_click", "help.restore_plot"),
    ("Shift", "help.fine"),
];

/// The window, while `open`; its close button closes it.
pub(crate) fn show(ctx: &egui::Context, t: Lang, open: &mut bool) {
    egui::Window::new(t.tr("help.title"))
        .open(open)
        .collapsible(false)
        .resizable(false)
        .anchor(egui::Align2::CENTER_CENTER, egui::Vec2::ZERO)
        .show(ctx, |ui| {
            egui::Grid::new("help keys")
                .num_columns(2)
                .striped(true)
                .show(ui, |ui| {
                    for (keys, what) in ROWS {
                        // Gestures are words, keys are keys.
                        let keys = if keys.starts_with("help.") {
                            t.tr(keys)
                        } else {
                            keys
                        };
                        ui.label(egui::RichText::new(keys).strong());
                        ui.label(t.tr(what));
                        ui.end_row();
                    }
                    let letters: Vec<String> = KEYS
                        .iter()
                        .map(|(up, down)| format!("{}/{}", up.name(), down.name()))
                        .collect();
                    ui.label(egui::RichText::new(letters.join(" ")).strong());
                    ui.label(t.tr("help.teleop"));
                    ui.end_row();
                });
        });
}
