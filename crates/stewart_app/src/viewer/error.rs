//! The viewer's one error: what went wrong, kept typed from where it happens to the edge
//! that shows it. A status line, a refused edit, a tool's note words it in the viewer's
//! language ([`ViewerError::words`]); the terminal gets English (`Display`). Errors of the
//! crates below keep their own type inside a variant, and their own words.

use std::path::PathBuf;
use std::sync::Arc;

use stewart_kinematics::analysis::cueing::CueError;
use stewart_kinematics::analysis::forces::ForceError;
use stewart_kinematics::analysis::workspace::WorkspaceError;
use stewart_kinematics::io::settings::{SettingError, SwitchError};
use stewart_kinematics::io::table::TableError;
use stewart_kinematics::model::trajectory::keyframes::KeyframeError;
use stewart_kinematics::{GeometryError, ScenarioError};

use crate::i18n::Lang;

/// What was being done with a file when the system refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Doing {
    /// Reading it.
    Read,
    /// Writing it.
    Write,
    /// Creating the folder.
    CreateFolder,
    /// Removing it.
    Remove,
}

/// Everything that can go wrong in the viewer.
#[derive(Clone, Debug)]
pub(crate) enum ViewerError {
    /// The system refused a file or folder.
    Io {
        /// The file or folder.
        path: PathBuf,
        /// What was being done.
        doing: Doing,
        /// The system's reason.
        source: Arc<std::io::Error>,
    },
    /// Not a regular file (a folder, a FIFO, a device): the viewer neither reads nor
    /// writes it.
    NotRegularFile(PathBuf),
    /// A file larger than its kind's cap (MiB).
    FileTooLarge {
        /// The file.
        path: PathBuf,
        /// The cap, MiB.
        cap_mib: u64,
    },
    /// A file of a kind the viewer does not open.
    UnknownKind(PathBuf),
    /// What went wrong, in the file named (a pose table, a vehicle recording).
    InFile {
        /// The file.
        file: String,
        /// What went wrong there.
        error: Box<ViewerError>,
    },
    /// A scenario that does not read (its error names the file, line and key).
    Scenario(ScenarioError),
    /// A pose table that does not read.
    Table(TableError),
    /// A vehicle recording that does not read (the reader's chain of reasons).
    VehicleTable(Arc<anyhow::Error>),
    /// A value a setting does not accept (out of its range, or one that cannot work with
    /// the others).
    OutOfRange {
        /// The key, as `--set` and the scenario file name it.
        key: String,
        /// Why, as the setting's check says.
        reason: String,
    },
    /// A setting refused its value.
    Setting(SettingError),
    /// A CAD part's mesh could not be read or placed (`[appearance]`).
    Part(Arc<stewart_render::appearance::parts::PartError>),
    /// The numbers do not make a platform.
    Geometry(GeometryError),
    /// Keyframes that do not make a motion.
    Keyframes(KeyframeError),
    /// The actuators cannot be switched to the kind asked for.
    Actuator(SwitchError),
    /// A payload that is not a body (mass, centre or inertia).
    Payload(ForceError),
    /// A vehicle recording the scenario's cueing cannot cue.
    Cue(CueError),
    /// An envelope coordinate whose range is inverted or not a number.
    InvertedRange {
        /// The coordinate, as `stewart design --envelope` names it.
        coordinate: &'static str,
        /// Its lower end.
        lo: f64,
        /// Its upper end.
        hi: f64,
    },
    /// An envelope in which no coordinate has a range.
    EmptyEnvelope,
    /// The workspace could not be computed.
    Workspace(WorkspaceError),
    /// Work off the UI thread did not finish.
    Job(JobFailed),
    /// The off-screen renderer failed.
    Render(Arc<stewart_render::offscreen::OffscreenError>),
    /// A picture larger than the GPU draws.
    TooLarge {
        /// Its width and height, pixels.
        size: [u32; 2],
        /// The largest side the GPU draws, pixels.
        max: u32,
    },
    /// A picture drawn could not be read back from the GPU.
    Readback(String),
    /// A picture could not be encoded as PNG.
    Encode(Arc<image::ImageError>),
    /// A shot of the window asked for after the window closed.
    WindowGone,
    /// The window has no GPU device to draw a shot with.
    NoGpuDevice,
    /// An export or a written file failed (the export pipeline's and the output rules'
    /// chain of reasons).
    Export(Arc<anyhow::Error>),
    /// The file manager could not be started.
    FileManager {
        /// The folder it was to show.
        folder: PathBuf,
        /// The program started.
        program: String,
        /// The system's reason.
        source: Arc<std::io::Error>,
    },
    /// A link that could not start (its plan, device or cue input).
    Link(Arc<anyhow::Error>),
    /// The link's sending thread could not start.
    LinkSpawn(Arc<stewart_link::sender::SpawnError>),
    /// A stream that stopped on a failure.
    LinkStopped {
        /// Where it streamed to, in the reader's words.
        to: String,
        /// The failure, as the sender reported it.
        why: String,
    },
    /// A stream stopped by a second stop on the way home: disarmed where it was.
    LinkEmergency {
        /// Where it streamed to, in the reader's words.
        to: String,
        /// The pose it was left at, in words.
        pose: String,
        /// The actuator values it was left at, in words.
        values: String,
    },
    /// The saved session could not be read.
    SessionUnreadable {
        /// The session file.
        path: PathBuf,
        /// Why.
        why: String,
    },
    /// The saved session is damaged.
    SessionDamaged {
        /// The session file.
        path: PathBuf,
        /// Why, as the reader says.
        why: String,
    },
    /// The saved session is of another version.
    SessionVersion {
        /// The session file.
        path: PathBuf,
        /// The version found.
        found: u32,
        /// The version this viewer writes.
        version: u32,
    },
    /// The session could not be encoded.
    SessionEncode(Arc<serde_json::Error>),
}

impl ViewerError {
    /// The error in `lang`'s words, as a status line shows it.
    pub(crate) fn words(&self, lang: Lang) -> String {
        use ViewerError as E;
        match self {
            E::Io { .. }
            | E::NotRegularFile(..)
            | E::FileTooLarge { .. }
            | E::UnknownKind(..)
            | E::InFile { .. }
            | E::Scenario(..)
            | E::Table(..)
            | E::VehicleTable(..)
            | E::Export(..)
            | E::Link(..)
            | E::SessionUnreadable { .. }
            | E::SessionDamaged { .. }
            | E::SessionVersion { .. }
            | E::SessionEncode(..) => self.file_words(lang),
            E::OutOfRange { .. }
            | E::Setting(..)
            | E::Part(..)
            | E::Geometry(..)
            | E::Keyframes(..)
            | E::Actuator(..)
            | E::Payload(..)
            | E::Cue(..)
            | E::InvertedRange { .. }
            | E::EmptyEnvelope
            | E::Workspace(..)
            | E::Job(..) => self.edit_words(lang),
            E::Render(..)
            | E::TooLarge { .. }
            | E::Readback(..)
            | E::Encode(..)
            | E::WindowGone
            | E::NoGpuDevice
            | E::FileManager { .. }
            | E::LinkSpawn(..)
            | E::LinkStopped { .. }
            | E::LinkEmergency { .. } => self.output_words(lang),
        }
    }

    /// Files, tables, exports, the link's own words, the session.
    fn file_words(&self, lang: Lang) -> String {
        use ViewerError as E;
        match self {
            E::Io {
                path,
                doing,
                source,
            } => {
                let key = match doing {
                    Doing::Read => "errors.read",
                    Doing::Write => "errors.write",
                    Doing::CreateFolder => "errors.create_folder",
                    Doing::Remove => "errors.remove",
                };
                lang.fmt(key, &[("path", &path.display()), ("why", source)])
            }
            E::NotRegularFile(path) => {
                lang.fmt("errors.not_regular_file", &[("path", &path.display())])
            }
            E::FileTooLarge { path, cap_mib } => lang.fmt(
                "errors.file_too_large",
                &[("path", &path.display()), ("cap", cap_mib)],
            ),
            E::UnknownKind(path) => lang.fmt("files.unknown_kind", &[("path", &path.display())]),
            E::InFile { file, error } => lang.fmt(
                "errors.in_file",
                &[("file", file), ("why", &error.words(lang))],
            ),
            E::Scenario(e) => e.to_string(),
            E::Table(e) => e.to_string(),
            E::VehicleTable(e) | E::Export(e) | E::Link(e) => format!("{e:#}"),
            E::SessionUnreadable { path, why } => lang.fmt(
                "session.unreadable",
                &[("path", &path.display()), ("why", why)],
            ),
            E::SessionDamaged { path, why } => lang.fmt(
                "session.damaged",
                &[("path", &path.display()), ("why", why)],
            ),
            E::SessionVersion {
                path,
                found,
                version,
            } => lang.fmt(
                "session.other_version",
                &[
                    ("path", &path.display()),
                    ("found", found),
                    ("version", version),
                ],
            ),
            E::SessionEncode(e) => e.to_string(),
            _ => self.to_string(),
        }
    }

    /// Edits refused, analyses and background jobs.
    fn edit_words(&self, lang: Lang) -> String {
        use ViewerError as E;
        match self {
            E::OutOfRange { key, reason } => {
                lang.fmt("errors.setting", &[("key", key), ("why", reason)])
            }
            E::Setting(e) => e.to_string(),
            E::Part(e) => lang.fmt("errors.part", &[("why", e)]),
            E::Geometry(e) => e.to_string(),
            E::Keyframes(e) => e.to_string(),
            E::Actuator(e) => e.to_string(),
            E::Payload(e) => e.to_string(),
            E::Cue(e) => e.to_string(),
            E::InvertedRange { coordinate, lo, hi } => lang.fmt(
                "errors.inverted_range",
                &[("coordinate", coordinate), ("lo", lo), ("hi", hi)],
            ),
            E::EmptyEnvelope => lang.tr("errors.empty_envelope").to_owned(),
            E::Workspace(e) => e.to_string(),
            E::Job(JobFailed::NotStarted(why)) => {
                lang.fmt("errors.job_not_started", &[("why", why)])
            }
            E::Job(JobFailed::Panicked) => lang.tr("errors.job_panicked").to_owned(),
            _ => self.to_string(),
        }
    }

    /// Rendering, the window, the file manager and the link's outcome.
    fn output_words(&self, lang: Lang) -> String {
        use ViewerError as E;
        match self {
            E::Render(e) => e.to_string(),
            E::TooLarge { size, max } => lang.fmt(
                "errors.too_large",
                &[("w", &size[0]), ("h", &size[1]), ("max", max)],
            ),
            E::Readback(why) => lang.fmt("errors.readback", &[("why", why)]),
            E::Encode(e) => lang.fmt("errors.encode", &[("why", e)]),
            E::WindowGone => lang.tr("errors.window_gone").to_owned(),
            E::NoGpuDevice => lang.tr("errors.no_gpu_device").to_owned(),
            E::FileManager {
                folder,
                program,
                source,
            } => lang.fmt(
                "errors.file_manager",
                &[
                    ("path", &folder.display()),
                    ("program", program),
                    ("why", source),
                ],
            ),
            E::LinkSpawn(e) => e.to_string(),
            E::LinkStopped { to, why } => lang.fmt("link.stopped", &[("to", to), ("why", why)]),
            E::LinkEmergency { to, pose, values } => lang.fmt(
                "link.emergency",
                &[("to", to), ("pose", pose), ("values", values)],
            ),
            _ => self.to_string(),
        }
    }

    /// A refusal of the system's for `path` while `doing` it.
    pub(crate) fn io(path: impl Into<PathBuf>, doing: Doing, source: std::io::Error) -> Self {
        Self::Io {
            path: path.into(),
            doing,
            source: Arc::new(source),
        }
    }

    /// `self`, said to have happened in `file`.
    pub(crate) fn in_file(self, file: &str) -> Self {
        Self::InFile {
            file: file.to_owned(),
            error: Box::new(self),
        }
    }
}

impl std::fmt::Display for ViewerError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.words(Lang::En))
    }
}

/// The words already say the reason below (the system's, the core's), so `source()` is
/// none: a chain printed with `{:#}` would say it twice.
impl std::error::Error for ViewerError {}

/// A file the gate refused (`stewart_kinematics::io::file`), in the viewer's words.
impl From<stewart_kinematics::io::file::FileError> for ViewerError {
    fn from(e: stewart_kinematics::io::file::FileError) -> Self {
        use stewart_kinematics::io::file::FileError;
        match e {
            FileError::NotRegular { path, .. } => Self::NotRegularFile(path),
            FileError::Io { path, cause } => Self::io(path, Doing::Read, cause),
            FileError::TooLarge { path, cap_mib, .. } => Self::FileTooLarge { path, cap_mib },
        }
    }
}

/// `From` for the errors of the crates below that an edit or a tool passes on with `?`.
macro_rules! from_below {
    ($($source:ty => $variant:ident),* $(,)?) => {
        $(impl From<$source> for ViewerError {
            fn from(e: $source) -> Self {
                Self::$variant(e)
            }
        })*
    };
}

from_below! {
    ScenarioError => Scenario,
    TableError => Table,
    SettingError => Setting,
    GeometryError => Geometry,
    KeyframeError => Keyframes,
    SwitchError => Actuator,
    ForceError => Payload,
    CueError => Cue,
    WorkspaceError => Workspace,
    JobFailed => Job,
}

/// The outcome of the last file or export action, shown until the next one.
pub(crate) type ActionStatus = Option<Result<String, ViewerError>>;

/// Why a job gave no result.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum JobFailed {
    /// The thread could not be started.
    NotStarted(String),
    /// The work panicked.
    Panicked,
}

impl std::fmt::Display for JobFailed {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            JobFailed::NotStarted(why) => write!(f, "the background thread could not start: {why}"),
            JobFailed::Panicked => write!(f, "the background work failed unexpectedly"),
        }
    }
}

impl std::error::Error for JobFailed {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_language_words_a_file_error_with_the_path_and_the_reason() {
        let e = ViewerError::io(
            "/tmp/x.csv",
            Doing::Read,
            std::io::Error::from(std::io::ErrorKind::PermissionDenied),
        );
        for lang in Lang::ALL {
            let words = e.words(lang);
            assert!(words.contains("/tmp/x.csv"), "{words}");
            assert!(words.contains("ermission denied"), "{words}");
        }
        assert_ne!(e.words(Lang::En), e.words(Lang::Zh));
        assert_eq!(e.to_string(), e.words(Lang::En));
        // Said once, even in anyhow's chain.
        let chained = format!("{:#}", anyhow::Error::from(e));
        assert_eq!(chained.matches("ermission denied").count(), 1, "{chained}");
    }

    #[test]
    fn an_error_in_a_file_names_the_file_then_says_what() {
        let inner = ViewerError::EmptyEnvelope;
        let e = inner.clone().in_file("poses.csv");
        assert_eq!(e.to_string(), format!("poses.csv: {inner}"));
        assert!(e.words(Lang::Zh).starts_with("poses.csv："));
    }

    #[test]
    fn errors_from_below_keep_their_type_and_their_words() {
        let e: ViewerError = JobFailed::Panicked.into();
        assert!(matches!(e, ViewerError::Job(JobFailed::Panicked)));
        let refused = KeyframeError::Empty;
        let e: ViewerError = refused.clone().into();
        assert_eq!(e.to_string(), refused.to_string());
    }
}
