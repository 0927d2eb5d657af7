//! *Show in folder*: the system's file manager opened on the folder of a file just written.

use std::path::Path;
use std::process::{Command, Stdio};
use std::sync::Arc;

use crate::viewer::error::ViewerError;

/// The command that opens `folder` in the system's file manager.
pub(crate) fn folder_command(folder: &Path) -> Command {
    let program = if cfg!(target_os = "windows") {
        "explorer"
    } else if cfg!(target_os = "macos") {
        "open"
    } else {
        "xdg-open"
    };
    let mut command = Command::new(program);
    command
        .arg(folder)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null());
    command
}

/// Open the folder holding `file` (or `file` itself, when it is a folder of frames) in the
/// file manager, without waiting for it; an error names what could not be started.
pub(crate) fn show_in_folder(file: &Path) -> Result<(), ViewerError> {
    let folder = if file.is_dir() {
        file
    } else {
        file.parent().unwrap_or(file)
    };
    let mut command = folder_command(folder);
    let program = command.get_program().to_string_lossy().into_owned();
    let mut child = command.spawn().map_err(|e| ViewerError::FileManager {
        folder: folder.to_owned(),
        program,
        source: Arc::new(e),
    })?;
    // Reap it in the background so it leaves no zombie behind.
    std::thread::spawn(move || child.wait());
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_file_manager_is_asked_for_the_files_folder() {
        let c = folder_command(Path::new("/tmp/exports"));
        let args: Vec<_> = c.get_args().collect();
        assert_eq!(args, [Path::new("/tmp/exports").as_os_str()]);
        assert!(!c.get_program().is_empty());
    }
}
