//! Scenario: presets, opening and saving TOML files, theme and presentation mode.

use std::path::{Path, PathBuf};

use stewart_kinematics::Scenario;
use stewart_kinematics::scenario::presets;

use super::widgets;
use crate::viewer::state::ViewerState;

/// The panel.
pub fn show(ui: &mut egui::Ui, state: &mut ViewerState) {
    ui.heading("Scenario");
    let current = state.scenario.name.clone();
    egui::ComboBox::from_label("Preset")
        .selected_text(&current)
        .show_ui(ui, |ui| {
            for name in presets::names() {
                if ui.selectable_label(current == name, name).clicked() {
                    match Scenario::preset(name) {
                        Ok(s) => {
                            state.load_scenario(s);
                            state.file_status = None;
                        }
                        Err(e) => state.file_status = Some(Err(e.to_string())),
                    }
                }
            }
        });
    if !state.scenario.description.is_empty() {
        ui.label(egui::RichText::new(&state.scenario.description).small());
    }
    ui.horizontal(|ui| {
        let label = ui.label("File");
        ui.add(
            egui::TextEdit::singleline(&mut state.file_path)
                .hint_text("scenario.toml")
                .desired_width(150.0),
        )
        .labelled_by(label.id);
        let path = PathBuf::from(state.file_path.trim());
        let has_path = !state.file_path.trim().is_empty();
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
            // Read only while the list is open.
            let here = scenario_files(Path::new("."));
            if here.is_empty() {
                ui.label("no scenario file (.toml with [geometry]) here");
            }
            for file in here {
                let name = file.display().to_string();
                if ui.selectable_label(false, &name).clicked() {
                    state.file_path = name;
                    state.open_file(&file);
                }
            }
        });
    widgets::status(ui, &state.file_status);
    ui.horizontal(|ui| {
        ui.checkbox(&mut state.light_theme, "Light theme");
        ui.checkbox(&mut state.presentation, "Presentation (P)")
            .on_hover_text("Light colours, large text, control panels hidden; P or Esc leaves");
    });
}

/// The `.toml` files of a folder that have a `[geometry]` table, sorted (at most 200).
fn scenario_files(dir: &Path) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut files: Vec<PathBuf> = entries
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| {
            p.extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("toml"))
        })
        .filter(|p| std::fs::read_to_string(p).is_ok_and(|t| t.contains("[geometry]")))
        .map(|p| p.strip_prefix(".").map(Path::to_path_buf).unwrap_or(p))
        .take(200)
        .collect();
    files.sort();
    files
}
