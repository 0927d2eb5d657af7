//! Scenario: presets, opening and saving TOML files, theme and presentation mode.

use std::path::PathBuf;

use stewart_kinematics::Scenario;
use stewart_kinematics::scenario::presets;

use super::widgets;
use crate::viewer::state::ViewerState;

/// The panel.
pub fn show(ui: &mut egui::Ui, state: &mut ViewerState) {
    ui.heading("Scenario");
    let current = state.scenario().name.clone();
    egui::ComboBox::from_label("Preset")
        .selected_text(&current)
        .show_ui(ui, |ui| {
            for name in presets::names() {
                if ui.selectable_label(current == name, name).clicked() {
                    match Scenario::preset(name) {
                        Ok(s) => {
                            state.load_scenario(s);
                            state.session.origin = format!("preset {name}");
                            state.files.status = None;
                        }
                        Err(e) => state.files.status = Some(Err(e.to_string())),
                    }
                }
            }
        });
    if !state.scenario().description.is_empty() {
        ui.label(egui::RichText::new(&state.scenario().description).small());
    }
    ui.horizontal(|ui| {
        let label = ui.label("File");
        ui.add(
            egui::TextEdit::singleline(&mut state.files.path)
                .hint_text("scenario.toml")
                .desired_width(150.0),
        )
        .labelled_by(label.id);
        let path = PathBuf::from(state.files.path.trim());
        let has_path = !state.files.path.trim().is_empty();
        if ui
            .add_enabled(has_path, egui::Button::new("Open"))
            .clicked()
        {
            state.open_file(&path);
        }
        if ui
            .add_enabled(has_path, egui::Button::new("Save"))
            .clicked()
        {
            state.save_file(&path);
        }
    });
    egui::ComboBox::from_label("Scenarios in this folder")
        .selected_text("choose…")
        .show_ui(ui, |ui| {
            // Read while the list is open, at most once a second.
            let here = state.files.scenario_files().to_vec();
            if here.is_empty() {
                ui.label("no scenario file (.toml with [geometry]) here");
            }
            for file in here {
                let name = file.display().to_string();
                if ui.selectable_label(false, &name).clicked() {
                    state.files.path = name;
                    state.open_file(&file);
                }
            }
        });
    widgets::status(ui, &state.files.status);
    ui.horizontal(|ui| {
        ui.checkbox(&mut state.look.light_theme, "Light theme");
        ui.checkbox(&mut state.look.presentation, "Presentation (P)")
            .on_hover_text("Light colours, large text, control panels hidden; P or Esc leaves");
    });
    if state.session.folder.is_some()
        && ui
            .button("Reset to defaults")
            .on_hover_text(
                "Forget the saved session (scenario, camera, panels, theme, window size) and return the look to its defaults",
            )
            .clicked()
    {
        state.reset_to_defaults();
        ui.ctx().memory_mut(|m| *m = egui::Memory::default());
    }
    if let Some(note) = &state.session.note {
        ui.label(egui::RichText::new(note).color(widgets::WARNING).small());
    }
}
