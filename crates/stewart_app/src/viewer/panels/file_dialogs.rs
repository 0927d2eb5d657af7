//! The file dialog, the question asked before a file is replaced, and files dropped on the
//! window (a scenario `.toml` or a pose table `.csv`; a note says what a hovering file
//! would do).

use crate::viewer::state::ViewerState;
use crate::viewer::state::files::{Purpose, WriteAction};

/// Everything about files that floats over the window.
pub fn show(ctx: &egui::Context, state: &mut ViewerState) {
    picker(ctx, state);
    confirm(ctx, state);
    dropped(ctx, state);
}

/// The open/save dialog, while one is shown; its choice is acted on once.
fn picker(ctx: &egui::Context, state: &mut ViewerState) {
    let Some(picker) = &mut state.files.picker else {
        return;
    };
    let chosen = picker.dialog.show(ctx).selected();
    let path = picker.dialog.path().map(std::path::Path::to_path_buf);
    let purpose = picker.purpose;
    if !picker.dialog.visible() || chosen {
        state.files.picker = None;
    }
    let (true, Some(path)) = (chosen, path) else {
        return;
    };
    match purpose {
        Purpose::Open => state.open_path(&path),
        Purpose::SaveScenario => state.save_file_asking(&path),
        Purpose::ExportTo => state.exports.form.path = path.display().to_string(),
    }
}

/// "`path` exists. Replace it?" before a save or an export overwrites a file.
fn confirm(ctx: &egui::Context, state: &mut ViewerState) {
    let Some(question) = state.files.confirm.clone() else {
        return;
    };
    let t = state.look.lang;
    let mut answer = None;
    egui::Modal::new(egui::Id::unique("replace-file")).show(ctx, |ui| {
        ui.label(t.fmt(
            "files.replace_question",
            &[("path", &question.path.display())],
        ));
        ui.horizontal(|ui| {
            if ui
                .button(t.tr("files.replace"))
                .on_hover_text(t.tr("files.replace_tip"))
                .clicked()
            {
                answer = Some(true);
            }
            if ui
                .button(t.tr("files.cancel"))
                .on_hover_text(t.tr("files.keep_tip"))
                .clicked()
                || ui.input(|i| i.key_pressed(egui::Key::Escape))
            {
                answer = Some(false);
            }
        });
    });
    match answer {
        Some(true) => {
            state.files.confirm = None;
            match question.action {
                WriteAction::SaveScenario => state.save_file(&question.path),
                WriteAction::Export => super::export::start(state, question.path),
            }
        }
        Some(false) => state.files.confirm = None,
        None => {}
    }
}

/// Files dropped on the window are opened (the last scenario wins; a pose table replaces
/// the motion); while files hover, a note says what dropping them does.
fn dropped(ctx: &egui::Context, state: &mut ViewerState) {
    let (dropped, hovering) = ctx.input(|i| {
        (
            i.raw
                .dropped_files
                .iter()
                .map(|f| f.path().to_path_buf())
                .collect::<Vec<_>>(),
            !i.raw.hovered_files.is_empty(),
        )
    });
    for path in dropped {
        state.open_path(&path);
    }
    if hovering {
        let t = state.look.lang;
        let painter = ctx.layer_painter(egui::LayerId::new(
            egui::Order::Foreground,
            egui::Id::unique("drop-note"),
        ));
        let rect = ctx.content_rect();
        painter.rect_filled(rect, 0.0, egui::Color32::from_black_alpha(160));
        painter.text(
            rect.center(),
            egui::Align2::CENTER_CENTER,
            t.tr("files.drop_here"),
            egui::FontId::proportional(24.0),
            egui::Color32::WHITE,
        );
    }
}
