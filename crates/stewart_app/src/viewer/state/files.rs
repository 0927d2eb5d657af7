//! The viewer's files: the scenario path typed and the file open now, the outcome of the
//! last open or save, the scenario files of the current folder (read at most once a
//! second, not every frame), the open/save dialog (`egui_file`, drawn by egui itself, so it
//! works the same on every system, under Xvfb and in kittest) and the question asked
//! before a file is replaced.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// How long a folder listing is trusted before the folder is read again.
const LISTING_LIFETIME: Duration = Duration::from_secs(1);

/// The viewer's files.
#[derive(Default)]
pub(crate) struct Files {
    /// The scenario file path typed in the panel.
    pub(crate) path: String,
    /// The scenario file opened or saved last (Ctrl+S writes there without asking).
    pub(crate) current: Option<PathBuf>,
    /// What the last open or save did.
    pub(crate) status: crate::viewer::error::ActionStatus,
    /// The open/save dialog, while one is shown.
    pub(crate) picker: Option<Picker>,
    /// A write waiting for the answer to "replace it?".
    pub(crate) confirm: Option<Overwrite>,
    /// A mesh file dropped on the window, waiting for the part it is for.
    pub(crate) mesh_dropped: Option<PathBuf>,
    /// The files opened or saved last, newest first (at most [`RECENT`]; kept in the
    /// session).
    pub(crate) recent: Vec<PathBuf>,
    listing: Option<(Instant, Vec<PathBuf>)>,
}

/// Files kept in the recent list.
pub(crate) const RECENT: usize = 8;

impl Files {
    /// Put `path` (absolute) first in the recent list, once.
    pub(crate) fn remember_recent(&mut self, path: &Path) {
        let path = absolute(path);
        self.recent.retain(|p| p != &path);
        self.recent.insert(0, path);
        self.recent.truncate(RECENT);
    }
}

/// What a file dialog's choice is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Purpose {
    /// Open a scenario (`.toml`) or a pose table (`.csv`).
    Open,
    /// Save the scenario as TOML.
    SaveScenario,
    /// Choose where the export writes.
    ExportTo,
    /// Choose a mesh file (STL, OBJ, glTF) for a CAD part.
    Mesh(stewart_kinematics::model::appearance::Part),
}

/// A file dialog on screen and what its choice is for.
pub(crate) struct Picker {
    /// What the chosen path is for.
    pub(crate) purpose: Purpose,
    /// The dialog.
    pub(crate) dialog: egui_file::FileDialog,
}

impl Picker {
    /// Open a dialog for `purpose` in `folder`, offering `name` for a file to write; its
    /// buttons and title in `lang`.
    pub(crate) fn open(
        purpose: Purpose,
        folder: &Path,
        name: &str,
        lang: crate::i18n::Lang,
    ) -> Self {
        let (dialog, title) = match purpose {
            Purpose::Open => (
                egui_file::FileDialog::open_file().show_files_filter(Box::new(|p: &Path| {
                    matches!(OpenKind::of(p), OpenKind::Scenario | OpenKind::PoseTable)
                })),
                "files.open_title",
            ),
            Purpose::SaveScenario => (
                egui_file::FileDialog::save_file()
                    .default_filename(name)
                    .show_files_filter(Box::new(|p: &Path| OpenKind::of(p) == OpenKind::Scenario)),
                "files.save_title",
            ),
            Purpose::ExportTo => (
                egui_file::FileDialog::save_file().default_filename(name),
                "files.export_title",
            ),
            Purpose::Mesh(_) => (
                egui_file::FileDialog::open_file()
                    .show_files_filter(Box::new(|p: &Path| OpenKind::of(p) == OpenKind::Mesh)),
                "appearance.choose_title",
            ),
        };
        let mut dialog = dialog
            .initial_path(folder)
            .title(lang.tr(title))
            .open_button_text(lang.tr("files.open_button").into())
            .save_button_text(lang.tr("files.save_button").into())
            .cancel_button_text(lang.tr("files.cancel").into())
            .file_label_text(lang.tr("files.file_label").into())
            .new_folder_button_text(lang.tr("files.new_folder").into())
            .new_folder_name_text(lang.tr("files.new_folder_name").into())
            .show_hidden_checkbox_text(lang.tr("files.show_hidden").into())
            .refresh_button_hover_text(lang.tr("files.refresh").into())
            .parent_folder_button_hover_text(lang.tr("files.parent_folder").into())
            .show_new_folder(true)
            .show_rename(false)
            .anchor(egui::Align2::CENTER_CENTER, [0.0, 0.0])
            // Wide enough for the longest title, in either language, at presentation size.
            .default_size([720.0, 480.0])
            .id(egui::Id::unique("stewart_file_dialog"));
        dialog.open();
        Self { purpose, dialog }
    }
}

/// What the user is asked before a file is replaced.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Overwrite {
    /// The file that exists.
    pub(crate) path: PathBuf,
    /// What writes it once the user agrees.
    pub(crate) action: WriteAction,
}

/// A write that can wait for "replace it?".
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum WriteAction {
    /// Save the scenario.
    SaveScenario,
    /// Run the export.
    Export,
}

/// What a dropped or chosen file is, by its extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum OpenKind {
    /// A scenario, `.toml`.
    Scenario,
    /// Poses over time, `.csv`.
    PoseTable,
    /// A mesh for a CAD part: `.stl`, `.obj`, `.gltf`, `.glb`.
    Mesh,
    /// Anything else.
    Other,
}

impl OpenKind {
    /// The kind of `path`, from its extension (any case).
    pub(crate) fn of(path: &Path) -> Self {
        let ext = path
            .extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase());
        match ext.as_deref() {
            Some("toml") => OpenKind::Scenario,
            Some("csv") => OpenKind::PoseTable,
            Some("stl" | "obj" | "gltf" | "glb") => OpenKind::Mesh,
            _ => OpenKind::Other,
        }
    }
}

/// `path` as an absolute path (relative paths from the current folder), for messages that
/// say where a file went.
pub(crate) fn absolute(path: &Path) -> PathBuf {
    std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf())
}

/// The folder a file dialog for `path` starts in: the file's own folder, else the current
/// one.
pub(crate) fn folder_of(path: &Path) -> PathBuf {
    absolute(path)
        .parent()
        .map_or_else(|| absolute(Path::new(".")), Path::to_path_buf)
}

impl Files {
    /// The scenario files of the current folder, read again only when the last reading
    /// is older than a second.
    pub(crate) fn scenario_files(&mut self) -> &[PathBuf] {
        let fresh = self
            .listing
            .as_ref()
            .is_some_and(|(at, _)| at.elapsed() < LISTING_LIFETIME);
        if !fresh {
            self.listing = Some((Instant::now(), scenario_files(Path::new("."))));
        }
        self.listing.as_ref().map_or(&[], |(_, files)| files)
    }
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
        .filter(|p| {
            // Only the start of each file: a scenario names its geometry early.
            std::fs::File::open(p).is_ok_and(|f| {
                let mut head = String::new();
                std::io::Read::read_to_string(&mut std::io::Read::take(f, 64 * 1024), &mut head)
                    .is_ok()
                    && head.contains("[geometry]")
            })
        })
        .map(|p| p.strip_prefix(".").map(Path::to_path_buf).unwrap_or(p))
        .take(200)
        .collect();
    files.sort();
    files
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn files_are_told_apart_by_their_extension() {
        assert_eq!(OpenKind::of(Path::new("a/b.toml")), OpenKind::Scenario);
        assert_eq!(OpenKind::of(Path::new("POSES.CSV")), OpenKind::PoseTable);
        assert_eq!(OpenKind::of(Path::new("notes.txt")), OpenKind::Other);
        assert_eq!(OpenKind::of(Path::new("toml")), OpenKind::Other);
    }

    #[test]
    fn paths_in_messages_are_absolute() {
        let here = std::env::current_dir().unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(absolute(Path::new("seed.gif")), here.join("seed.gif"));
        assert_eq!(folder_of(Path::new("seed.gif")), here);
        assert_eq!(folder_of(Path::new("/tmp/x/seed.gif")), Path::new("/tmp/x"));
    }
}
