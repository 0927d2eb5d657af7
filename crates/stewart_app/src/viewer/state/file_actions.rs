//! What the viewer does with files: open a scenario or a pose table (chosen, typed or
//! dropped on the window), save the scenario, and ask before replacing a file. Every
//! outcome is shown in the Scenario panel; a file that cannot be read leaves the scenario
//! as it was.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use stewart_kinematics::Scenario;
use stewart_kinematics::io::file::{FileKind, read_file};
use stewart_kinematics::io::settings::Group;
use stewart_kinematics::model::appearance::{MeshScale, Part, PartLook};
use stewart_kinematics::model::trajectory::PoseTable;
use stewart_render::appearance::parts::{likely_unit, platform_size};

use crate::viewer::error::{Doing, ViewerError};
use crate::viewer::state::ViewerState;
use crate::viewer::state::files::{
    OpenKind, Overwrite, Picker, Purpose, WriteAction, absolute, folder_of,
};

impl ViewerState {
    /// Open whatever `path` is: a scenario (`.toml`) replaces the scenario, a pose table
    /// (`.csv`) the motion; anything else is refused with a note.
    pub(crate) fn open_path(&mut self, path: &Path) {
        match OpenKind::of(path) {
            OpenKind::Scenario => self.open_file(path),
            OpenKind::PoseTable => self.open_pose_table(path),
            // Which part it is for is asked (see `panels::file_dialogs`).
            OpenKind::Mesh => self.files.mesh_dropped = Some(absolute(path)),
            OpenKind::Other => {
                self.files.status = Some(Err(ViewerError::UnknownKind(absolute(path))));
            }
        }
    }

    /// Open a scenario file. A file that cannot be read or is invalid leaves the current
    /// scenario untouched; either way the outcome is shown in the Scenario panel.
    pub(crate) fn open_file(&mut self, path: &Path) {
        let full = absolute(path);
        self.files.status = Some(
            match regular_file(&full).and_then(|()| Ok(crate::source::load_file(&full)?)) {
                Ok(s) => {
                    let name = s.name.clone();
                    self.session.origin = full.display().to_string();
                    self.load_scenario(s, folder_of(&full));
                    self.files.path = full.display().to_string();
                    self.files.current = Some(full.clone());
                    self.files.remember_recent(&full);
                    Ok(self.look.lang.fmt(
                        "scenario.opened",
                        &[("name", &name), ("path", &full.display())],
                    ))
                }
                Err(e) => Err(e),
            },
        );
    }

    /// Play the poses of a CSV table (`t,x,y,z,roll_deg,pitch_deg,yaw_deg`) as the motion,
    /// one edit (Ctrl+Z takes it back); the platform stays. A table of vehicle motion
    /// (`t,ax,ay,az,wx,wy,wz`) is cued first (see [`ViewerState::open_vehicle`]).
    pub(crate) fn open_pose_table(&mut self, path: &Path) {
        let full = absolute(path);
        let name = full.display().to_string();
        // Read once through the gate; the header line tells which reader parses it.
        let bytes = read_file(&full, FileKind::Table);
        let header = bytes.as_ref().ok().map(|b| {
            String::from_utf8_lossy(b.split(|c| *c == b'\n').next().unwrap_or(&[])).into_owned()
        });
        if header.is_some_and(|h| crate::vehicle_in::table::is_vehicle_header(&h)) {
            self.open_vehicle(&full);
            return;
        }
        let motion = bytes.map_err(ViewerError::from).and_then(|bytes| {
            let table = PoseTable::read(bytes.as_slice(), &name)?;
            Ok(table.to_motion(&name)?)
        });
        let lang = self.look.lang;
        let played = motion.and_then(|motion| {
            let (count, seconds) = (motion.sampling.len(), motion.sampling.duration());
            let set = |s: &mut Scenario| {
                s.motion = motion;
                Ok(())
            };
            (self.doc.try_edit(Group::Trajectory, set))
                .map_err(|why| why.in_file(&name))
                .map(|()| (count, seconds))
        });
        self.files.status = Some(played.map(|(count, seconds)| {
            // The motion starts again (and the time stays within the new one).
            self.playback.time = 0.0;
            self.files.remember_recent(&full);
            lang.fmt(
                "files.poses_opened",
                &[
                    ("count", &count),
                    ("seconds", &format!("{seconds:.2}")),
                    ("path", &name),
                ],
            )
        }));
    }

    /// Cue a CSV of vehicle motion (`t,ax,ay,az,wx,wy,wz`) with the scenario's `[cueing]`
    /// table and play the poses as the motion, one edit; the Cueing panel then plots it,
    /// and edits of the cueing cue it again.
    pub(crate) fn open_vehicle(&mut self, full: &Path) {
        let name = full.display().to_string();
        let lang = self.look.lang;
        let read = read_file(full, FileKind::Table)
            .map_err(ViewerError::from)
            .and_then(|bytes| {
                crate::vehicle_in::table::read(&mut bytes.as_slice(), &name)
                    .map_err(|e| ViewerError::VehicleTable(Arc::new(e)))
            });
        let outcome = read.and_then(|table| {
            let count = table.samples.len();
            let seconds = table.samples.last().map_or(0.0, |l| l.0)
                - table.samples.first().map_or(0.0, |f| f.0);
            self.doc
                .play_vehicle(&name, Arc::new(table.samples))
                .map(|()| (count, seconds))
        });
        if outcome.is_ok() {
            self.files.remember_recent(full);
        }
        self.files.status = Some(outcome.map(|(count, seconds)| {
            self.playback.time = 0.0;
            lang.fmt(
                "files.vehicle_opened",
                &[
                    ("count", &count),
                    ("seconds", &format!("{seconds:.2}")),
                    ("path", &name),
                ],
            )
        }));
    }

    /// Save the scenario as TOML (whole or not at all).
    pub(crate) fn save_file(&mut self, path: &Path) {
        let full = absolute(path);
        // Part files stay the same files: named from the folder saved to.
        let mut saved = self.scenario().clone();
        saved.appearance =
            crate::appearance::rebase(&saved.appearance, self.doc.folder(), &folder_of(&full));
        let text = saved.to_toml();
        let lang = self.look.lang;
        let written = crate::output::write_atomically(&full, text.as_bytes())
            .map(|()| lang.fmt("scenario.saved", &[("path", &full.display())]))
            .map_err(|e| ViewerError::Export(Arc::new(e)));
        if written.is_ok() {
            self.doc.moved_to(folder_of(&full));
            self.doc.mark_saved();
            // The saved session remembers the file now (Ctrl+S at the next start saves it).
            self.session.origin = full.display().to_string();
            self.files.path = full.display().to_string();
            self.files.remember_recent(&full);
            self.files.current = Some(full);
        }
        self.files.status = Some(written);
    }

    /// Save to `path`, first asking whether to replace it when it exists and is not the
    /// file open now.
    pub(crate) fn save_file_asking(&mut self, path: &Path) {
        let full = absolute(path);
        if full.exists() && self.files.current.as_deref() != Some(full.as_path()) {
            self.files.confirm = Some(Overwrite {
                path: full,
                action: WriteAction::SaveScenario,
            });
        } else {
            self.save_file(&full);
        }
    }

    /// Take `origin` (a saved session's, or `--scenario`'s) as the file open now when it
    /// names a regular file: Ctrl+S then saves it without asking where.
    pub(crate) fn remember_file(&mut self, origin: &str) {
        if origin.starts_with("preset ") {
            return;
        }
        let full = absolute(Path::new(origin));
        if regular_file(&full).is_ok() {
            self.files.path = full.display().to_string();
            self.files.current = Some(full);
        }
    }

    /// Ctrl+S: save to the file open now, or ask where (Save as…) when there is none.
    pub(crate) fn save(&mut self) {
        match self.files.current.clone() {
            Some(path) => self.save_file(&path),
            None => self.choose_file(Purpose::SaveScenario),
        }
    }

    /// Show the file dialog for `purpose`, starting where the relevant file is.
    pub(crate) fn choose_file(&mut self, purpose: Purpose) {
        let (start, name) = match purpose {
            Purpose::Open | Purpose::SaveScenario => (
                self.files.current.clone().unwrap_or_default(),
                format!("{}.toml", self.scenario().name),
            ),
            Purpose::Mesh(part) => (
                self.scenario()
                    .appearance
                    .part(part)
                    .map(|look| self.doc.folder().join(&look.file))
                    .unwrap_or_else(|| self.doc.folder().join("part.stl")),
                String::new(),
            ),
            Purpose::ExportTo => {
                let path = PathBuf::from(self.exports.form.path.trim());
                let name = path
                    .file_name()
                    .map(|n| n.to_string_lossy().into_owned())
                    .unwrap_or_default();
                (path, name)
            }
        };
        self.files.picker = Some(Picker::open(
            purpose,
            &folder_of(&start),
            &name,
            self.look.lang,
        ));
    }
}

impl ViewerState {
    /// Draw `part` from the mesh file at `path`: one edit of `[appearance]` (the file
    /// named by its absolute path; saving names it from the scenario's folder). A part
    /// that had no file takes the unit (mm, cm, m, in) that makes the mesh nearest the
    /// platform's size; a refused mesh leaves the picture and says why.
    pub(crate) fn attach_mesh(&mut self, part: Part, path: &Path) {
        let full = absolute(path);
        let kept = self.scenario().appearance.part(part).cloned();
        let scale = match &kept {
            Some(look) => look.scale,
            None => stewart_render::appearance::load(&full).map_or(MeshScale::Millimetre, |mesh| {
                likely_unit(&mesh, platform_size(&self.scenario().geometry))
            }),
        };
        let look = PartLook {
            file: full.to_string_lossy().into_owned(),
            scale,
            ..kept.unwrap_or_else(|| PartLook::new(""))
        };
        self.doc.edit(Group::Appearance, |s| {
            *s.appearance.slot_mut(part) = Some(look);
            Ok(())
        });
    }
}

/// Only regular files are read: a FIFO would block the window, a device never ends.
fn regular_file(path: &Path) -> Result<(), ViewerError> {
    match std::fs::metadata(path) {
        Ok(m) if m.is_file() => Ok(()),
        Ok(_) => Err(ViewerError::NotRegularFile(path.to_owned())),
        Err(e) => Err(ViewerError::io(path, Doing::Read, e)),
    }
}
