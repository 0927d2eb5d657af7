//! Scenario: presets, opening and saving TOML files, theme and presentation mode.

use std::path::PathBuf;

use stewart_kinematics::Scenario;
use stewart_kinematics::io::scenario::presets;

use super::widgets;
use crate::i18n::Lang;
use crate::viewer::state::SessionState;
use crate::viewer::state::document::Document;
use crate::viewer::state::files::{Files, Purpose};
use crate::viewer::state::look::Look;

/// What the Scenario panel asks of the viewer: each touches more than the panel holds
/// (loading a scenario resets playback, the workspace, the link's plan…), so the caller
/// does it.
#[derive(Clone, Debug)]
pub(crate) enum ScenarioAction {
    /// Undo the last edit.
    Undo,
    /// Redo the last undone edit.
    Redo,
    /// Show this preset (its name).
    Preset(String),
    /// Open what a path is: a scenario or a pose table.
    OpenPath(PathBuf),
    /// Open a scenario file.
    OpenFile(PathBuf),
    /// Save the scenario here, asking before replacing another file.
    Save(PathBuf),
    /// Open the file dialog for this purpose.
    Choose(Purpose),
    /// Speak this language.
    Language(Lang),
    /// Forget the session: defaults from now on, nothing saved at the end.
    Reset,
}

/// The parts the Scenario panel edits or shows.
pub(crate) struct ScenarioParts<'a> {
    /// The scenario and its undo history (read).
    pub(crate) doc: &'a Document,
    /// The path typed, the status, the folder's files, the recent files.
    pub(crate) files: &'a mut Files,
    /// Theme, presentation mode, language.
    pub(crate) look: &'a mut Look,
    /// Whether a session is kept, and its note.
    pub(crate) session: &'a SessionState,
}

/// The panel. Returns what it asks of the viewer, if anything.
pub(crate) fn show(ui: &mut egui::Ui, parts: ScenarioParts) -> Option<ScenarioAction> {
    let t = parts.look.lang;
    let mut action = heading(ui, parts.doc, t);
    let scenario = parts.doc.scenario();
    action = action.or(preset_choice(ui, &scenario.name, t));
    if !scenario.description.is_empty() {
        let words = crate::i18n::words::description(t, &scenario.name, &scenario.description);
        ui.label(egui::RichText::new(words).small());
    }
    action = action.or(file_rows(ui, parts.files, t));
    action = action.or(folder_choice(ui, parts.files, t));
    action = action.or(recent_choice(ui, parts.files, t));
    widgets::status(ui, &parts.files.status, t);
    ui.horizontal(|ui| {
        ui.checkbox(&mut parts.look.light_theme, t.tr("scenario.light_theme"));
        ui.checkbox(&mut parts.look.presentation, t.tr("scenario.presentation"))
            .on_hover_text(t.tr("scenario.presentation_tip"));
    });
    action = action.or(language(ui, t));
    if parts.session.folder.is_some()
        && ui
            .button(t.tr("scenario.reset"))
            .on_hover_text(t.tr("scenario.reset_tip"))
            .clicked()
    {
        action = Some(ScenarioAction::Reset);
    }
    if let Some(note) = &parts.session.note {
        ui.label(egui::RichText::new(note).color(widgets::WARNING).small());
    }
    action
}

/// The heading with *Undo* and *Redo*.
fn heading(ui: &mut egui::Ui, doc: &Document, t: Lang) -> Option<ScenarioAction> {
    let mut action = None;
    ui.horizontal(|ui| {
        ui.heading(t.tr("scenario.heading"));
        let undo = ui
            .add_enabled(
                doc.undo.can_undo(),
                egui::Button::new(t.tr("scenario.undo")),
            )
            .on_hover_text(t.tr("scenario.undo_tip"));
        if undo.clicked() {
            action = Some(ScenarioAction::Undo);
        }
        let redo = ui
            .add_enabled(
                doc.undo.can_redo(),
                egui::Button::new(t.tr("scenario.redo")),
            )
            .on_hover_text(t.tr("scenario.redo_tip"));
        if redo.clicked() {
            action = Some(ScenarioAction::Redo);
        }
    });
    action
}

/// The presets, each with its description as a tooltip (read only when hovered).
fn preset_choice(ui: &mut egui::Ui, current: &str, t: Lang) -> Option<ScenarioAction> {
    let mut action = None;
    egui::ComboBox::from_label(t.tr("scenario.preset"))
        .selected_text(current)
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
                    action = Some(ScenarioAction::Preset(name.to_owned()));
                }
            }
        });
    action
}

/// The path typed, and *Open*, *Save*, *Open…*, *Save as…*.
fn file_rows(ui: &mut egui::Ui, files: &mut Files, t: Lang) -> Option<ScenarioAction> {
    ui.horizontal(|ui| {
        let label = ui.label(t.tr("scenario.file"));
        ui.add(
            egui::TextEdit::singleline(&mut files.path)
                .hint_text("scenario.toml")
                .desired_width(ui.available_width()),
        )
        .labelled_by(label.id);
    });
    let mut action = None;
    ui.horizontal(|ui| {
        let path = PathBuf::from(files.path.trim());
        let has_path = !files.path.trim().is_empty();
        if ui
            .add_enabled(has_path, egui::Button::new(t.tr("scenario.open")))
            .on_hover_text(t.tr("scenario.open_tip"))
            .clicked()
        {
            action = Some(ScenarioAction::OpenPath(path.clone()));
        }
        if ui
            .add_enabled(has_path, egui::Button::new(t.tr("scenario.save")))
            .on_hover_text(t.tr("scenario.save_tip"))
            .clicked()
        {
            action = Some(ScenarioAction::Save(path));
        }
        if ui
            .button(t.tr("scenario.open_dialog"))
            .on_hover_text(t.tr("scenario.open_dialog_tip"))
            .clicked()
        {
            action = Some(ScenarioAction::Choose(Purpose::Open));
        }
        if ui
            .button(t.tr("scenario.save_as"))
            .on_hover_text(t.tr("scenario.save_as_tip"))
            .clicked()
        {
            action = Some(ScenarioAction::Choose(Purpose::SaveScenario));
        }
    });
    action
}

/// The scenario files of the current folder (read while the list is open, at most once a
/// second), each with its full path as a tooltip.
fn folder_choice(ui: &mut egui::Ui, files: &mut Files, t: Lang) -> Option<ScenarioAction> {
    let mut action = None;
    egui::ComboBox::from_label(t.tr("scenario.in_folder"))
        .selected_text(t.tr("scenario.choose"))
        .show_ui(ui, |ui| {
            let here = files.scenario_files().to_vec();
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
                    action = Some(ScenarioAction::OpenFile(file));
                }
            }
        });
    action
}

/// The files opened or saved last (kept between runs), newest first; one that is gone is
/// shown but cannot be chosen.
fn recent_choice(ui: &mut egui::Ui, files: &Files, t: Lang) -> Option<ScenarioAction> {
    if files.recent.is_empty() {
        return None;
    }
    let mut chosen = None;
    egui::ComboBox::from_label(t.tr("scenario.recent"))
        .selected_text(t.tr("scenario.choose"))
        .show_ui(ui, |ui| {
            for file in &files.recent {
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
    chosen.map(ScenarioAction::OpenPath)
}

/// The interface's language: English or Chinese (Chinese only with a font that has it).
/// `t`: the language spoken now.
fn language(ui: &mut egui::Ui, t: Lang) -> Option<ScenarioAction> {
    let has_font = crate::i18n::fonts::cjk().is_some();
    let mut action = None;
    ui.horizontal(|ui| {
        ui.label(t.tr("scenario.language"));
        for lang in Lang::ALL {
            let usable = lang == Lang::En || has_font;
            let button = ui
                .add_enabled(usable, egui::Button::selectable(t == lang, lang.own_name()))
                .on_disabled_hover_text(t.tr("scenario.no_cjk_font"));
            if button.clicked() && t != lang {
                action = Some(ScenarioAction::Language(lang));
            }
        }
    });
    action
}
