//! Scenario: presets, opening and saving TOML files, theme and presentation mode.

use std::path::PathBuf;

use stewart_kinematics::Scenario;
use stewart_kinematics::io::scenario::presets;

use super::widgets;
use crate::i18n::Lang;
use crate::viewer::state::ViewerState;
use crate::viewer::state::files::Purpose;

/// The panel.
pub fn show(ui: &mut egui::Ui, state: &mut ViewerState) {
    let t = state.look.lang;
    heading(ui, state);
    preset_choice(ui, state);
    if !state.scenario().description.is_empty() {
        let words = crate::i18n::words::description(
            t,
            &state.scenario().name,
            &state.scenario().description,
        );
        ui.label(egui::RichText::new(words).small());
    }
    file_rows(ui, state);
    folder_choice(ui, state);
    recent_choice(ui, state);
    widgets::status(ui, &state.files.status);
    ui.horizontal(|ui| {
        ui.checkbox(&mut state.look.light_theme, t.tr("scenario.light_theme"));
        ui.checkbox(&mut state.look.presentation, t.tr("scenario.presentation"))
            .on_hover_text(t.tr("scenario.presentation_tip"));
    });
    language(ui, state);
    if state.session.folder.is_some()
        && ui
            .button(t.tr("scenario.reset"))
            .on_hover_text(t.tr("scenario.reset_tip"))
            .clicked()
    {
        state.reset_to_defaults();
        ui.ctx().memory_mut(|m| *m = egui::Memory::default());
    }
    if let Some(note) = &state.session.note {
        ui.label(egui::RichText::new(note).color(widgets::WARNING).small());
    }
}

/// The heading with *Undo* and *Redo*.
fn heading(ui: &mut egui::Ui, state: &mut ViewerState) {
    let t = state.look.lang;
    ui.horizontal(|ui| {
        ui.heading(t.tr("scenario.heading"));
        let undo = ui
            .add_enabled(
                state.doc.undo.can_undo(),
                egui::Button::new(t.tr("scenario.undo")),
            )
            .on_hover_text(t.tr("scenario.undo_tip"));
        if undo.clicked() {
            state.undo_edit();
        }
        let redo = ui
            .add_enabled(
                state.doc.undo.can_redo(),
                egui::Button::new(t.tr("scenario.redo")),
            )
            .on_hover_text(t.tr("scenario.redo_tip"));
        if redo.clicked() {
            state.redo_edit();
        }
    });
}

/// The presets, each with its description as a tooltip (read only when hovered).
fn preset_choice(ui: &mut egui::Ui, state: &mut ViewerState) {
    let t = state.look.lang;
    let current = state.scenario().name.clone();
    egui::ComboBox::from_label(t.tr("scenario.preset"))
        .selected_text(&current)
        .show_ui(ui, |ui| {
            for name in presets::names() {
                let chosen = ui
                    .selectable_label(current == name, name)
                    .on_hover_ui(|ui| {
                        let words = presets::text(name)
                            .and_then(|text| Scenario::from_toml_str(text, name, None).ok())
                            .map(|s| crate::i18n::words::description(t, name, &s.description))
                            .unwrap_or_default();
                        ui.label(words);
                    })
                    .clicked();
                if chosen {
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
}

/// The path typed, and *Open*, *Save*, *Open…*, *Save as…*.
fn file_rows(ui: &mut egui::Ui, state: &mut ViewerState) {
    let t = state.look.lang;
    ui.horizontal(|ui| {
        let label = ui.label(t.tr("scenario.file"));
        ui.add(
            egui::TextEdit::singleline(&mut state.files.path)
                .hint_text("scenario.toml")
                .desired_width(ui.available_width()),
        )
        .labelled_by(label.id);
    });
    ui.horizontal(|ui| {
        let path = PathBuf::from(state.files.path.trim());
        let has_path = !state.files.path.trim().is_empty();
        if ui
            .add_enabled(has_path, egui::Button::new(t.tr("scenario.open")))
            .on_hover_text(t.tr("scenario.open_tip"))
            .clicked()
        {
            state.open_path(&path);
        }
        if ui
            .add_enabled(has_path, egui::Button::new(t.tr("scenario.save")))
            .on_hover_text(t.tr("scenario.save_tip"))
            .clicked()
        {
            state.save_file_asking(&path);
        }
        if ui
            .button(t.tr("scenario.open_dialog"))
            .on_hover_text(t.tr("scenario.open_dialog_tip"))
            .clicked()
        {
            state.choose_file(Purpose::Open);
        }
        if ui
            .button(t.tr("scenario.save_as"))
            .on_hover_text(t.tr("scenario.save_as_tip"))
            .clicked()
        {
            state.choose_file(Purpose::SaveScenario);
        }
    });
}

/// The scenario files of the current folder (read while the list is open, at most once a
/// second), each with its full path as a tooltip.
fn folder_choice(ui: &mut egui::Ui, state: &mut ViewerState) {
    let t = state.look.lang;
    egui::ComboBox::from_label(t.tr("scenario.in_folder"))
        .selected_text(t.tr("scenario.choose"))
        .show_ui(ui, |ui| {
            let here = state.files.scenario_files().to_vec();
            if here.is_empty() {
                ui.label(t.tr("scenario.none_here"));
            }
            for file in here {
                let name = file.display().to_string();
                let full = crate::viewer::state::files::absolute(&file)
                    .display()
                    .to_string();
                if ui
                    .selectable_label(false, &name)
                    .on_hover_text(full)
                    .clicked()
                {
                    state.open_file(&file);
                }
            }
        });
}

/// The files opened or saved last (kept between runs), newest first; one that is gone is
/// shown but cannot be chosen.
fn recent_choice(ui: &mut egui::Ui, state: &mut ViewerState) {
    let t = state.look.lang;
    if state.files.recent.is_empty() {
        return;
    }
    let mut chosen = None;
    egui::ComboBox::from_label(t.tr("scenario.recent"))
        .selected_text(t.tr("scenario.choose"))
        .show_ui(ui, |ui| {
            for file in &state.files.recent {
                let name = file.file_name().map_or_else(
                    || file.display().to_string(),
                    |n| n.to_string_lossy().into_owned(),
                );
                let there = file.is_file();
                let tip = if there {
                    file.display().to_string()
                } else {
                    t.fmt("scenario.recent_gone", &[("path", &file.display())])
                };
                if ui
                    .add_enabled(there, egui::Button::selectable(false, name))
                    .on_hover_text(&tip)
                    .on_disabled_hover_text(&tip)
                    .clicked()
                {
                    chosen = Some(file.clone());
                }
            }
        });
    if let Some(file) = chosen {
        state.open_path(&file);
    }
}

/// The interface's language: English or Chinese (Chinese only with a font that has it).
fn language(ui: &mut egui::Ui, state: &mut ViewerState) {
    let t = state.look.lang;
    let has_font = crate::i18n::fonts::cjk().is_some();
    ui.horizontal(|ui| {
        ui.label(t.tr("scenario.language"));
        for lang in Lang::ALL {
            let usable = lang == Lang::En || has_font;
            let button = ui
                .add_enabled(
                    usable,
                    egui::Button::selectable(state.look.lang == lang, lang.own_name()),
                )
                .on_disabled_hover_text(t.tr("scenario.no_cjk_font"));
            if button.clicked() && state.look.lang != lang {
                state.set_language(lang);
            }
        }
    });
}
