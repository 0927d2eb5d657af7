//! A scenario's CAD parts (`[appearance]`) read for drawing: files relative to the
//! scenario file's folder, each part's scale judged against the platform's size.

use std::path::{Path, PathBuf};

use stewart_kinematics::Scenario;
use stewart_kinematics::model::appearance::{AppearanceSettings, Part};
use stewart_render::appearance::parts::{PartError, PartSet, platform_size};

use crate::cli::ScenarioArgs;

/// The folder a scenario's part files are named from: its file's folder, or the working
/// folder for a preset.
pub(crate) fn folder_of(args: &ScenarioArgs) -> PathBuf {
    args.scenario
        .as_deref()
        .and_then(Path::parent)
        .map_or_else(|| PathBuf::from("."), Path::to_path_buf)
}

/// `appearance` with its files, named from `from`, named from `to` instead (a scenario
/// saved to another folder keeps its parts): relative below `to`, else absolute.
pub(crate) fn rebase(
    appearance: &AppearanceSettings,
    from: &Path,
    to: &Path,
) -> AppearanceSettings {
    let mut out = appearance.clone();
    for part in Part::ALL {
        if let Some(look) = out.slot_mut(part) {
            let full = std::path::absolute(from.join(&look.file))
                .unwrap_or_else(|_| from.join(&look.file));
            let to = std::path::absolute(to).unwrap_or_else(|_| to.to_path_buf());
            look.file = full
                .strip_prefix(&to)
                .map_or_else(|_| full.clone(), Path::to_path_buf)
                .to_string_lossy()
                .into_owned();
        }
    }
    out
}

/// `appearance` with every file named by its absolute path from `folder` (the viewer's
/// document keeps them so: undo and a scenario from another folder name the same files).
pub(crate) fn anchored(appearance: &AppearanceSettings, folder: &Path) -> AppearanceSettings {
    let mut out = appearance.clone();
    for part in Part::ALL {
        if let Some(look) = out.slot_mut(part) {
            let full = folder.join(&look.file);
            look.file = std::path::absolute(&full)
                .unwrap_or(full)
                .to_string_lossy()
                .into_owned();
        }
    }
    out
}

/// Read the parts `scenario` names, files relative to `folder`, for a command (no
/// stand-ins); the first that fails is the error.
pub(crate) fn load(scenario: &Scenario, folder: &Path) -> Result<PartSet, PartError> {
    PartSet::load(
        &scenario.appearance,
        folder,
        scenario.geometry.actuator().kind(),
        platform_size(&scenario.geometry),
        None,
        false,
    )
}

/// Read the parts `scenario` names for the viewer, part by part (stand-ins for software
/// rasterisers made), meshes of `previous` read from the same file kept: those that
/// read, and why each other failed.
pub(crate) fn read(
    scenario: &Scenario,
    folder: &Path,
    previous: Option<&PartSet>,
) -> (PartSet, Vec<PartError>) {
    PartSet::read(
        &scenario.appearance,
        folder,
        scenario.geometry.actuator().kind(),
        platform_size(&scenario.geometry),
        previous,
        true,
    )
}
