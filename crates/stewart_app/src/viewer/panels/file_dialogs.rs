//! The file dialog, the question asked before a file is replaced, and files dropped on the
//! window (a scenario `.toml` or a pose table `.csv`; a note says what a hovering file
//! would do).

use std::path::PathBuf;

use stewart_kinematics::model::actuator::ActuatorKind;
use stewart_kinematics::model::appearance::Part;

use crate::i18n::Lang;
use crate::viewer::state::files::{Files, Purpose, WriteAction};

/// What the file dialogs ask of the viewer, in order.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum FileAction {
    /// Open what this path is (a scenario or a pose table).
    Open(PathBuf),
    /// Save the scenario here, asking before replacing another file.
    SaveAsking(PathBuf),
    /// Save the scenario here (replacing it was agreed).
    Save(PathBuf),
    /// The export's output is this path.
    ExportTo(PathBuf),
    /// Start the export to this path (replacing it was agreed).
    Export(PathBuf),
    /// Draw this part from this mesh file.
    Mesh(Part, PathBuf),
}

/// Everything about files that floats over the window: the dialog, the question before a
/// file is replaced, files dropped. Returns what they ask of the viewer.
pub(crate) fn show(
    ctx: &egui::Context,
    files: &mut Files,
    kind: ActuatorKind,
    t: Lang,
) -> Vec<FileAction> {
    let mut asked = Vec::new();
    asked.extend(picker(ctx, files));
    asked.extend(which_part(ctx, files, kind, t));
    asked.extend(confirm(ctx, files, t));
    asked.extend(dropped(ctx, t));
    asked
}

/// The open/save dialog, while one is shown; its choice is acted on once.
fn picker(ctx: &egui::Context, files: &mut Files) -> Option<FileAction> {
    let picker = files.picker.as_mut()?;
    let chosen = picker.dialog.show(ctx).selected();
    let path = picker.dialog.path().map(std::path::Path::to_path_buf);
    let purpose = picker.purpose;
    if !picker.dialog.visible() || chosen {
        files.picker = None;
    }
    let (true, Some(path)) = (chosen, path) else {
        return None;
    };
    Some(match purpose {
        Purpose::Open => FileAction::Open(path),
        Purpose::SaveScenario => FileAction::SaveAsking(path),
        Purpose::ExportTo => FileAction::ExportTo(path),
        Purpose::Mesh(part) => FileAction::Mesh(part, path),
    })
}

/// "Which part is `file`?" after a mesh file was dropped: a button per part the
/// platform has.
fn which_part(
    ctx: &egui::Context,
    files: &mut Files,
    kind: ActuatorKind,
    t: Lang,
) -> Option<FileAction> {
    let path = files.mesh_dropped.clone()?;
    let mut answer = None;
    let mut cancel = false;
    egui::Modal::new(egui::Id::unique("which-part")).show(ctx, |ui| {
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        ui.label(t.fmt("appearance.which_part", &[("file", &name)]));
        ui.horizontal_wrapped(|ui| {
            for part in Part::ALL.into_iter().filter(|p| p.applies_to(kind)) {
                if ui.button(super::appearance::part_name(part, t)).clicked() {
                    answer = Some(part);
                }
            }
            cancel = ui.button(t.tr("files.cancel")).clicked()
                || ui.input(|i| i.key_pressed(egui::Key::Escape));
        });
    });
    if answer.is_some() || cancel {
        files.mesh_dropped = None;
    }
    answer.map(|part| FileAction::Mesh(part, path))
}

/// "`path` exists. Replace it?" before a save or an export overwrites a file.
fn confirm(ctx: &egui::Context, files: &mut Files, t: Lang) -> Option<FileAction> {
    let question = files.confirm.clone()?;
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
            files.confirm = None;
            Some(match question.action {
                WriteAction::SaveScenario => FileAction::Save(question.path),
                WriteAction::Export => FileAction::Export(question.path),
            })
        }
        Some(false) => {
            files.confirm = None;
            None
        }
        None => None,
    }
}

/// Files dropped on the window are opened (the last scenario wins; a pose table replaces
/// the motion); while files hover, a note says what dropping them does.
fn dropped(ctx: &egui::Context, t: Lang) -> Vec<FileAction> {
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
    if hovering {
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
    dropped.into_iter().map(FileAction::Open).collect()
}
