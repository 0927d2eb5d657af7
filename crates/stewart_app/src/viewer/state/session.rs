//! The viewer's saved session: the last scenario (where it came from, and as shown, unsaved
//! edits included), the camera, the look switches, the panels' open/closed states and the
//! window size, kept in the platform's config folder (`~/.config/stewart/session.json` on
//! Linux, `%APPDATA%\stewart` on Windows, `~/Library/Application Support/stewart` on
//! macOS; `STEWART_CONFIG_DIR` overrides it). A broken or older file is set aside with a
//! note, never a crash; *Reset to defaults* forgets it.

use std::path::PathBuf;
use std::sync::Arc;

use serde::{Deserialize, Serialize};
use stewart_kinematics::Scenario;
use stewart_render::OrbitCamera;

use crate::i18n::Lang;
use crate::viewer::error::{Doing, ViewerError};
use crate::viewer::state::look::Look;

/// The session file's format; a file of another version is ignored.
pub(crate) const VERSION: u32 = 1;

/// What the viewer remembers.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct Session {
    /// [`VERSION`] when written.
    pub(crate) version: u32,
    /// Where the scenario came from: a preset name or a file path, in words.
    pub(crate) origin: String,
    /// The scenario as shown (TOML, edits included).
    pub(crate) scenario: String,
    /// Camera azimuth, elevation (degrees), distance and target (metres).
    pub(crate) camera: [f32; 6],
    /// Light theme.
    pub(crate) light_theme: bool,
    /// The traced path.
    pub(crate) show_path: bool,
    /// The platform's axes.
    pub(crate) platform_axes: bool,
    /// Legs in their plot colours.
    pub(crate) coloured_legs: bool,
    /// Leg labels.
    pub(crate) labels: bool,
    /// The head-up readout.
    pub(crate) readouts: bool,
    /// Window size, logical pixels.
    pub(crate) window: [u32; 2],
    /// egui's memory (open panels, scroll positions), as egui writes it.
    pub(crate) panels: Option<String>,
    /// The interface's language (absent in sessions written before it was remembered).
    #[serde(default)]
    pub(crate) lang: Option<Lang>,
    /// The files opened or saved last, newest first (absent in older sessions).
    #[serde(default)]
    pub(crate) recent: Vec<String>,
    /// The export window's choices (absent in older sessions).
    #[serde(default)]
    pub(crate) export: Option<crate::viewer::state::exports::ExportForm>,
}

impl Session {
    /// The session of what the viewer shows now.
    pub(crate) fn capture(
        scenario: &Scenario,
        origin: &str,
        look: &Look,
        window: [u32; 2],
        panels: Option<String>,
    ) -> Self {
        let c = &look.camera;
        Self {
            version: VERSION,
            origin: origin.to_owned(),
            scenario: scenario.to_toml(),
            camera: [
                c.azimuth_deg,
                c.elevation_deg,
                c.distance,
                c.target.x,
                c.target.y,
                c.target.z,
            ],
            light_theme: look.light_theme,
            show_path: look.show_path,
            platform_axes: look.platform_axes,
            coloured_legs: look.coloured_legs,
            labels: look.labels,
            readouts: look.readouts,
            window,
            panels,
            lang: Some(look.lang),
            recent: Vec::new(),
            export: None,
        }
    }

    /// The saved scenario, or why it no longer reads.
    pub(crate) fn scenario(&self) -> Result<Scenario, ViewerError> {
        // Not held to the template grammar: the Link panel keeps a template being typed
        // (and shows why it is not one yet); a session restores it as it was left.
        Ok(Scenario::from_toml_str(
            &self.scenario,
            "the saved session",
            None,
        )?)
    }

    /// The saved window size, when it is one a screen can show (320×240 to 8192×8192; a
    /// damaged file's 4294967295² is not taken).
    pub(crate) fn window_size(&self) -> Option<(u32, u32)> {
        let [w, h] = self.window;
        ((320..=8192).contains(&w) && (240..=8192).contains(&h)).then_some((w, h))
    }

    /// Put the saved look (and camera, when it is a usable one: finite, within the bounds a
    /// camera takes anywhere — angles ±3600°, distance up to 10 km, target within 1 km)
    /// on `look`.
    pub(crate) fn restore_look(&self, look: &mut Look) {
        use stewart_kinematics::ground::bounds::{ANGLE_DEG, LENGTH_M};
        let [azimuth_deg, elevation_deg, distance, x, y, z] = self.camera;
        let within = |v: f32, limit: f64| v.is_finite() && f64::from(v.abs()) <= limit;
        let usable = within(azimuth_deg, ANGLE_DEG)
            && within(elevation_deg, ANGLE_DEG)
            && within(distance, 10.0 * LENGTH_M)
            && distance > 0.0
            && [x, y, z].iter().all(|&c| within(c, LENGTH_M));
        if usable {
            look.camera = OrbitCamera {
                azimuth_deg,
                elevation_deg: elevation_deg.clamp(-89.5, 89.5),
                distance,
                target: glam::Vec3::new(x, y, z),
            };
        }
        look.light_theme = self.light_theme;
        look.show_path = self.show_path;
        look.platform_axes = self.platform_axes;
        look.coloured_legs = self.coloured_legs;
        look.labels = self.labels;
        look.readouts = self.readouts;
        if let Some(lang) = self.lang {
            look.lang = lang;
        }
    }
}

/// The folder the session lives in (`None`: the platform has none).
pub(crate) fn folder() -> Option<PathBuf> {
    match std::env::var_os("STEWART_CONFIG_DIR") {
        Some(dir) if !dir.is_empty() => Some(PathBuf::from(dir)),
        _ => dirs::config_dir().map(|d| d.join("stewart")),
    }
}

/// The session file in `folder`.
pub(crate) fn file_in(folder: &std::path::Path) -> PathBuf {
    folder.join("session.json")
}

/// The saved session in `folder`: `Ok(None)` when there is none; an error when the file is
/// broken, of another version or unreadable (it is then left alone and the viewer starts
/// fresh).
pub(crate) fn load(folder: &std::path::Path) -> Result<Option<Session>, ViewerError> {
    let path = file_in(folder);
    let unreadable = |why: &dyn std::fmt::Display| ViewerError::SessionUnreadable {
        path: path.clone(),
        why: why.to_string(),
    };
    let damaged = |why: &dyn std::fmt::Display| ViewerError::SessionDamaged {
        path: path.clone(),
        why: why.to_string(),
    };
    // The rules of every input: a regular file (not a device such as /dev/zero, not a FIFO
    // that would block the start for ever), of a bounded size, read with a limit.
    use stewart_kinematics::io::file::{FileError, FileKind, read_file};
    let bytes = match read_file(&path, FileKind::Session) {
        Ok(bytes) => bytes,
        Err(FileError::Io { cause: source, .. })
            if source.kind() == std::io::ErrorKind::NotFound =>
        {
            return Ok(None);
        }
        Err(FileError::Io { cause: source, .. }) => return Err(unreadable(&source)),
        Err(FileError::NotRegular { .. }) => return Err(unreadable(&"not a regular file")),
        Err(e @ FileError::TooLarge { .. }) => return Err(unreadable(&e)),
    };
    let text = String::from_utf8(bytes).map_err(|e| damaged(&e))?;
    let session: Session = serde_json::from_str(&text).map_err(|e| damaged(&e))?;
    if session.version != VERSION {
        return Err(ViewerError::SessionVersion {
            path,
            found: session.version,
            version: VERSION,
        });
    }
    Ok(Some(session))
}

/// The largest session file read, bytes (a session is a few kilobytes: its scenario and the
/// panels' memory): the gate's cap for sessions.
#[cfg(test)]
pub(crate) const MAX_SESSION_BYTES: u64 = stewart_kinematics::io::file::FileKind::Session.cap();

/// Write the session into `folder` (whole or not at all).
pub(crate) fn save(folder: &std::path::Path, session: &Session) -> Result<(), ViewerError> {
    std::fs::create_dir_all(folder).map_err(|e| ViewerError::io(folder, Doing::CreateFolder, e))?;
    let text = serde_json::to_string_pretty(session)
        .map_err(|e| ViewerError::SessionEncode(Arc::new(e)))?;
    // The output rules' path (a symbolic link is followed and stays a link), staged beside
    // the real file and renamed over it. Not their writing: a session is saved also when a
    // signal asked the viewer to close. A character device (a link to `/dev/null` keeps the
    // viewer from remembering) is written as it is; a FIFO is not: at exit it would wait
    // for a reader for ever.
    let path = file_in(folder);
    let destination = crate::output::Destination::new(&path, crate::output::NO_INPUTS)
        .map_err(|e| ViewerError::Export(Arc::new(e)))?;
    let real = destination.real();
    if destination.kind() != crate::output::Kind::File {
        let device = std::fs::metadata(real).is_ok_and(|m| is_character_device(&m));
        if device {
            return std::fs::OpenOptions::new()
                .write(true)
                .open(real)
                .and_then(|mut f| std::io::Write::write_all(&mut f, text.as_bytes()))
                .map_err(|e| ViewerError::io(&path, Doing::Write, e));
        }
        return Err(ViewerError::NotRegularFile(path));
    }
    let fail = |e: std::io::Error| ViewerError::io(&path, Doing::Write, e);
    let mut staged =
        tempfile::NamedTempFile::new_in(crate::output::parent_of(real)).map_err(fail)?;
    std::io::Write::write_all(&mut staged, text.as_bytes()).map_err(fail)?;
    // Renamed over the old file keeping its permissions (a new one readable by all), as
    // every output is.
    destination
        .deliver(staged.into_temp_path())
        .map_err(|e| ViewerError::Export(Arc::new(e)))
}

/// Whether `meta` is a character device (`/dev/null`).
fn is_character_device(meta: &std::fs::Metadata) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        meta.file_type().is_char_device()
    }
    #[cfg(not(unix))]
    {
        let _ = meta;
        false
    }
}

/// Forget the session saved in `folder`.
pub(crate) fn forget(folder: &std::path::Path) -> Result<(), ViewerError> {
    let path = file_in(folder);
    match std::fs::remove_file(&path) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(()),
        Err(e) => Err(ViewerError::io(path, Doing::Remove, e)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    #[cfg(unix)]
    fn saving_keeps_the_files_permissions() {
        use std::os::unix::fs::PermissionsExt as _;
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let session = Session::capture(
            &Scenario::preset("seed").unwrap_or_else(|e| panic!("{e}")),
            "seed",
            &Look::new(OrbitCamera::seed_view(glam::Vec3::ZERO, 1.0)),
            [1280, 720],
            None,
        );
        let mode = |p: &std::path::Path| {
            std::fs::metadata(p).map_or(0, |m| m.permissions().mode() & 0o777)
        };
        // A new file: readable by all, as every output.
        save(dir.path(), &session).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(mode(&file_in(dir.path())), 0o644);
        // An existing file keeps its own.
        for kept in [0o640, 0o604] {
            std::fs::set_permissions(file_in(dir.path()), std::fs::Permissions::from_mode(kept))
                .unwrap_or_else(|e| panic!("{e}"));
            save(dir.path(), &session).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(mode(&file_in(dir.path())), kept);
        }
    }

    #[test]
    #[cfg(unix)]
    fn a_linked_session_stays_a_link_and_a_fifo_or_device_is_left_alone() {
        use std::os::unix::fs::FileTypeExt as _;
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let session = Session::capture(
            &Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}")),
            "paired",
            &Look::new(OrbitCamera::seed_view(glam::Vec3::ZERO, 1.0)),
            [1280, 720],
            None,
        );
        // A link to a file elsewhere: the file gets the session, the link stays.
        let elsewhere = dir.path().join("kept").join("my-session.json");
        std::fs::create_dir_all(elsewhere.parent().unwrap_or(dir.path()))
            .unwrap_or_else(|e| panic!("{e}"));
        std::fs::write(&elsewhere, b"{}").unwrap_or_else(|e| panic!("{e}"));
        let folder = dir.path().join("config");
        std::fs::create_dir_all(&folder).unwrap_or_else(|e| panic!("{e}"));
        std::os::unix::fs::symlink(&elsewhere, file_in(&folder)).unwrap_or_else(|e| panic!("{e}"));
        save(&folder, &session).unwrap_or_else(|e| panic!("{e}"));
        let link = std::fs::symlink_metadata(file_in(&folder)).unwrap_or_else(|e| panic!("{e}"));
        assert!(link.file_type().is_symlink());
        assert!(matches!(load(&folder), Ok(Some(_))));
        let kept = std::fs::read_to_string(&elsewhere).unwrap_or_default();
        assert!(kept.contains("\"version\""), "{kept}");
        // A link to /dev/null: written there (nothing kept), still a link. A FIFO: refused
        // with a note, left as it is.
        let null = dir.path().join("null");
        std::fs::create_dir_all(&null).unwrap_or_else(|e| panic!("{e}"));
        std::os::unix::fs::symlink("/dev/null", file_in(&null)).unwrap_or_else(|e| panic!("{e}"));
        save(&null, &session).unwrap_or_else(|e| panic!("{e}"));
        let meta = std::fs::symlink_metadata(file_in(&null)).unwrap_or_else(|e| panic!("{e}"));
        assert!(meta.file_type().is_symlink());
        let folder = dir.path().join("fifo");
        std::fs::create_dir_all(&folder).unwrap_or_else(|e| panic!("{e}"));
        let path = file_in(&folder);
        let made = std::process::Command::new("mkfifo").arg(&path).status();
        assert!(made.is_ok_and(|s| s.success()));
        let note = save(&folder, &session)
            .err()
            .map(|e| e.to_string())
            .unwrap_or_default();
        assert!(note.contains("not a regular file"), "{note}");
        let meta = std::fs::symlink_metadata(&path).unwrap_or_else(|e| panic!("{e}"));
        assert!(meta.file_type().is_fifo(), "the FIFO was replaced");
    }

    #[test]
    fn a_session_round_trips_and_restores_the_look() {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        assert!(matches!(load(dir.path()), Ok(None)));
        let mut scenario = Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
        stewart_kinematics::io::settings::apply_all(&mut scenario, ["geometry.base_radius=1.1"])
            .unwrap_or_else(|e| panic!("{e}"));
        let mut look = Look::new(OrbitCamera::seed_view(glam::Vec3::ZERO, 1.0));
        look.camera.azimuth_deg = 40.0;
        look.light_theme = true;
        look.labels = false;
        look.readouts = true;
        look.lang = Lang::Zh;
        let mut session = Session::capture(&scenario, "preset paired", &look, [1500, 900], None);
        session.recent = vec!["/tmp/a.toml".to_owned(), "/tmp/b.csv".to_owned()];
        session.export = Some(crate::viewer::state::exports::ExportForm {
            span_s: Some([1.0, 2.5]),
            title: "Defence, figure 3".to_owned(),
            size: (1024, 768),
            ..Default::default()
        });
        save(dir.path(), &session).unwrap_or_else(|e| panic!("{e}"));
        let back = load(dir.path())
            .unwrap_or_else(|e| panic!("{e}"))
            .unwrap_or_else(|| panic!("nothing saved"));
        assert_eq!(back, session);
        // The unsaved edit comes back with the scenario.
        let restored = back.scenario().unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(restored.geometry, scenario.geometry);
        let mut fresh = Look::new(OrbitCamera::seed_view(glam::Vec3::ZERO, 1.0));
        back.restore_look(&mut fresh);
        assert_eq!(fresh.camera.azimuth_deg, 40.0);
        assert!(fresh.light_theme && !fresh.labels && fresh.readouts);
        assert_eq!(fresh.lang, Lang::Zh, "the language is remembered");
        // A session written before the language was remembered keeps the current one.
        let mut json: serde_json::Value =
            serde_json::to_value(&session).unwrap_or_else(|e| panic!("{e}"));
        json.as_object_mut().map(|o| o.remove("lang"));
        json.as_object_mut().map(|o| o.remove("recent"));
        json.as_object_mut().map(|o| o.remove("export"));
        let older: Session = serde_json::from_value(json).unwrap_or_else(|e| panic!("{e}"));
        assert!(
            older.recent.is_empty(),
            "an older session has no recent files"
        );
        let mut english = Look::new(OrbitCamera::seed_view(glam::Vec3::ZERO, 1.0));
        older.restore_look(&mut english);
        assert_eq!(english.lang, Lang::En);
        forget(dir.path()).unwrap_or_else(|e| panic!("{e}"));
        assert!(matches!(load(dir.path()), Ok(None)));
    }

    #[test]
    fn a_broken_or_older_session_is_a_note_not_a_crash() {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let file = file_in(dir.path());
        for (text, words) in [
            ("{ not json", "is damaged"),
            ("{\"version\": 1}", "is damaged"),
            ("\u{0}\u{1}binary", "is damaged"),
        ] {
            std::fs::write(&file, text).unwrap_or_else(|e| panic!("{e}"));
            let note = load(dir.path())
                .err()
                .map(|e| e.to_string())
                .unwrap_or_default();
            assert!(
                note.contains(words) && note.ends_with("starting fresh"),
                "{note}"
            );
        }
        let scenario = Scenario::seed();
        let look = Look::new(OrbitCamera::seed_view(glam::Vec3::ZERO, 1.0));
        let mut old = Session::capture(&scenario, "preset seed", &look, [800, 600], None);
        old.version = 0;
        std::fs::write(&file, serde_json::to_string(&old).unwrap_or_default())
            .unwrap_or_else(|e| panic!("{e}"));
        let note = load(dir.path())
            .err()
            .map(|e| e.to_string())
            .unwrap_or_default();
        assert!(note.contains("another version (0"), "{note}");
        // A saved scenario that no longer reads, and a camera of NaNs, restore nothing.
        let mut bad = Session::capture(&scenario, "preset seed", &look, [800, 600], None);
        bad.scenario = "[geometry]\nbase_radius = -1".to_owned();
        bad.camera = [f32::NAN; 6];
        assert!(bad.scenario().is_err());
        let mut kept = Look::new(OrbitCamera::seed_view(glam::Vec3::ZERO, 1.0));
        let camera = kept.camera;
        bad.restore_look(&mut kept);
        assert_eq!(kept.camera, camera);
        // A camera 1e38 m away, or aimed 1e30 m off, and a window of 4294967295² are not
        // taken either.
        for wild in [
            [0.0, 20.0, 1e38, 0.0, 0.0, 0.0],
            [0.0, 20.0, 3.0, 1e30, 0.0, 0.0],
            [1e9, 20.0, 3.0, 0.0, 0.0, 0.0],
        ] {
            bad.camera = wild;
            bad.restore_look(&mut kept);
            assert_eq!(kept.camera, camera, "{wild:?}");
        }
        bad.window = [u32::MAX; 2];
        assert_eq!(bad.window_size(), None);
        bad.window = [1000, 600];
        assert_eq!(bad.window_size(), Some((1000, 600)));
        bad.camera = [30.0, 20.0, 3.0, 0.1, 0.0, 0.5];
        bad.restore_look(&mut kept);
        assert_eq!(kept.camera.distance, 3.0);
    }

    #[test]
    fn a_session_that_is_a_device_a_fifo_or_too_large_is_set_aside_at_once() {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let file = file_in(dir.path());
        // A link to /dev/zero (it used to grow memory without end).
        std::os::unix::fs::symlink("/dev/zero", &file).unwrap_or_else(|e| panic!("{e}"));
        let note = load(dir.path())
            .err()
            .map(|e| e.to_string())
            .unwrap_or_default();
        assert!(note.contains("not a regular file"), "{note}");
        std::fs::remove_file(&file).unwrap_or_else(|e| panic!("{e}"));
        // A FIFO with no writer (opening it used to block the start for ever).
        let made = std::process::Command::new("mkfifo")
            .arg(&file)
            .status()
            .map(|s| s.success());
        assert_eq!(made.ok(), Some(true));
        let started = std::time::Instant::now();
        let note = load(dir.path())
            .err()
            .map(|e| e.to_string())
            .unwrap_or_default();
        assert!(note.contains("not a regular file"), "{note}");
        assert!(started.elapsed().as_secs() < 2);
        std::fs::remove_file(&file).unwrap_or_else(|e| panic!("{e}"));
        // Larger than the cap.
        let big = vec![b' '; (MAX_SESSION_BYTES + 1) as usize];
        std::fs::write(&file, big).unwrap_or_else(|e| panic!("{e}"));
        let note = load(dir.path())
            .err()
            .map(|e| e.to_string())
            .unwrap_or_default();
        assert!(note.contains("larger than 4 MiB"), "{note}");
        assert!(note.ends_with("starting fresh"), "{note}");
    }
}
