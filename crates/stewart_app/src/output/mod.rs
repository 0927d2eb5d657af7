//! Output that never destroys what stands at its path: written whole or not at all onto
//! regular files, straight into devices and pipes, through symbolic links, and never
//! onto one of the command's own inputs.
//!
//! A regular file (or a new path) is written into a temporary file beside it and then
//! renamed over it, so an interruption leaves the old file as it was. A device or FIFO
//! (`/dev/null`, `/dev/stdout`, a named pipe) cannot be replaced by a rename without
//! destroying it, so it is opened and written directly, waiting for a FIFO's reader
//! only until Ctrl-C, SIGTERM or SIGHUP. A symbolic link is followed and
//! its target written, as the shell's `>` does.

use std::fs::Metadata;
use std::io::{BufWriter, ErrorKind, Write};
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};

mod special;
use special::SpecialFile;

/// What stands at an output path once symbolic links are followed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kind {
    /// Nothing yet, or a regular file: staged and renamed into place.
    File,
    /// A folder.
    Folder,
    /// A device, FIFO or socket: written directly, never replaced.
    Special,
}

/// No inputs: for an output that no file the command reads could be.
pub(crate) const NO_INPUTS: &[(&str, &Path)] = &[];

/// An output path, checked before any work is done.
#[derive(Clone, Debug)]
pub(crate) struct Destination {
    /// The path as the user gave it (for messages).
    shown: PathBuf,
    /// The path with symbolic links followed: where bytes really go.
    real: PathBuf,
    /// What stands there now.
    kind: Kind,
    /// A FIFO opened before the work (see [`Destination::open_early`]), taken by the write.
    held: std::sync::Arc<std::sync::Mutex<Option<SpecialFile>>>,
}

/// Follow symbolic links (also dangling ones, whose target will be created).
fn resolve_links(path: &Path) -> Result<PathBuf> {
    let mut p = path.to_path_buf();
    for _ in 0..40 {
        match std::fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => {
                let target = std::fs::read_link(&p)
                    .with_context(|| format!("cannot read the link `{}`", path.display()))?;
                p = match p.parent() {
                    Some(dir) if target.is_relative() => dir.join(target),
                    _ => target,
                };
            }
            _ => return Ok(p),
        }
    }
    bail!(
        "cannot write `{}`: too many levels of symbolic links",
        path.display()
    )
}

fn kind_of(meta: &Metadata) -> Kind {
    if meta.is_dir() {
        Kind::Folder
    } else if meta.is_file() {
        Kind::File
    } else {
        Kind::Special
    }
}

/// Whether two existing paths are the same file (same device and inode on Unix).
fn same_file(a: &Metadata, b: &Path) -> bool {
    let Ok(b) = std::fs::metadata(b) else {
        return false;
    };
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        a.dev() == b.dev() && a.ino() == b.ino()
    }
    #[cfg(not(unix))]
    {
        let _ = (a, b);
        false
    }
}

/// The folder a path lies in (`.` for a bare file name).
pub(crate) fn parent_of(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

impl Destination {
    /// Check `path` as an output of a command whose inputs are `inputs` (each with the
    /// words that name it, such as `("the scenario", path)`): the output may not be one
    /// of them. Standard input (`-`) is one when it is redirected from that file.
    pub(crate) fn new(path: &Path, inputs: &[(&str, impl AsRef<Path>)]) -> Result<Self> {
        let real = resolve_links(path)?;
        let meta = std::fs::metadata(&real).ok();
        if let Some(meta) = &meta {
            for (what, input) in inputs {
                let input = input.as_ref();
                // Standard input (`-`) redirected from a file is that file.
                let read = if input.as_os_str() == "-" {
                    Path::new("/dev/stdin")
                } else {
                    input
                };
                if kind_of(meta) == Kind::File && same_file(meta, read) {
                    let named = if read == input {
                        format!("`{}`", input.display())
                    } else {
                        "standard input, redirected from it".to_owned()
                    };
                    bail!(
                        "refusing to write `{}`: it is {what} this command reads ({named}); choose another output file",
                        path.display(),
                    );
                }
            }
        }
        Ok(Self {
            shown: path.to_path_buf(),
            real,
            kind: meta.as_ref().map_or(Kind::File, kind_of),
            held: std::sync::Arc::default(),
        })
    }

    /// A FIFO (a named pipe) is opened now, before long work (a session listened to),
    /// waiting for its reader (said on standard error) until Ctrl-C, as the shell's `>`
    /// does: a session recorded for minutes is never lost waiting for a reader at the end.
    /// Other kinds are left to the write.
    pub(crate) fn hold_open(&self) -> Result<()> {
        #[cfg(unix)]
        {
            use std::os::unix::fs::FileTypeExt;
            let fifo = std::fs::metadata(&self.real).is_ok_and(|m| m.file_type().is_fifo());
            if fifo {
                crate::interrupt::flag();
                let shown = self.shown.display();
                let file = SpecialFile::open_saying(
                    &self.real,
                    &format!(
                        "waiting for a reader of `{shown}` (a named pipe) before starting; Ctrl-C stops"
                    ),
                )
                .with_context(|| format!("cannot write `{shown}`"))?;
                *self
                    .held
                    .lock()
                    .unwrap_or_else(std::sync::PoisonError::into_inner) = Some(file);
            }
        }
        Ok(())
    }

    /// The device or FIFO to write: the one held open, else opened now.
    fn special_file(&self) -> std::io::Result<SpecialFile> {
        let held = self
            .held
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
            .take();
        match held {
            Some(file) => Ok(file),
            None => {
                crate::interrupt::flag();
                SpecialFile::open_saying(
                    &self.real,
                    &format!(
                        "waiting for a reader of `{}` (a named pipe); Ctrl-C stops",
                        self.shown.display()
                    ),
                )
            }
        }
    }

    /// The path as the user gave it.
    pub(crate) fn shown(&self) -> &Path {
        &self.shown
    }

    /// The path written to, symbolic links followed.
    pub(crate) fn real(&self) -> &Path {
        &self.real
    }

    /// What stands at the path now.
    pub(crate) fn kind(&self) -> Kind {
        self.kind
    }

    /// The folder where staged files go: beside the output, so that the final rename
    /// stays on one file system; the system's temporary folder for a device or FIFO.
    pub(crate) fn staging_dir(&self) -> PathBuf {
        match self.kind {
            Kind::Special => std::env::temp_dir(),
            Kind::File | Kind::Folder => parent_of(&self.real).to_path_buf(),
        }
    }

    /// A new temporary file in [`Destination::staging_dir`] (removed when dropped), for
    /// output that is moved into place by [`Destination::deliver`] when complete.
    pub(crate) fn staged_file(&self, suffix: &str) -> Result<tempfile::NamedTempFile> {
        let dir = self.staging_dir();
        tempfile::Builder::new()
            .prefix(".stewart-")
            .suffix(suffix)
            .tempfile_in(&dir)
            .with_context(|| {
                format!(
                    "cannot write `{}`: cannot create a file in `{}`",
                    self.shown.display(),
                    dir.display()
                )
            })
    }

    /// Before long work: refuse a folder where a file is wanted, and a regular path whose
    /// folder is missing or cannot take a new file (tried with a staged file, removed at
    /// once), so that no result is computed only to be lost.
    pub(crate) fn check_writable(&self) -> Result<&Self> {
        self.require_file()?;
        if self.kind == Kind::File {
            let dir = self.staging_dir();
            if !dir.is_dir() {
                bail!(
                    "cannot write `{}`: the folder `{}` does not exist",
                    self.shown.display(),
                    dir.display()
                );
            }
            drop(self.staged_file(".probe")?);
        }
        Ok(self)
    }

    /// Refuse `other` where it is the same file as this output (`what` names the two):
    /// one would be lost under the other.
    pub(crate) fn refuse_same(&self, other: &Self, what: &str) -> Result<()> {
        // A path not there yet is named by its folder, links followed, and its name.
        let identity = |d: &Self| {
            let folder = parent_of(&d.real);
            match (std::fs::canonicalize(folder), d.real.file_name()) {
                (Ok(f), Some(name)) => f.join(name),
                _ => d.real.clone(),
            }
        };
        if self.kind != Kind::Special && identity(self) == identity(other) {
            bail!(
                "{what} both name `{}`; give them different files",
                other.shown.display()
            );
        }
        Ok(())
    }

    /// Refuse a folder where a file is wanted.
    pub(crate) fn require_file(&self) -> Result<&Self> {
        if self.kind == Kind::Folder {
            bail!(
                "cannot write `{}`: it is a folder; give a file name",
                self.shown.display()
            );
        }
        Ok(self)
    }

    /// Write what `fill` produces: staged and renamed for a regular file, directly for a
    /// device or FIFO. On any error nothing is left at a regular path.
    pub(crate) fn write_with(
        &self,
        fill: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
    ) -> Result<()> {
        self.require_file()?;
        let shown = self.shown.display();
        if self.kind == Kind::Special {
            let file = self
                .special_file()
                .with_context(|| format!("cannot write `{shown}`"))?;
            let mut w = BufWriter::new(file);
            return fill(&mut w)
                .and_then(|()| w.flush())
                .with_context(|| format!("cannot write `{shown}`"));
        }
        // From here Ctrl-C, SIGTERM and SIGHUP stop the writing (see `StopOnSignal`), so
        // the staged file is removed instead of being left behind by a killed process.
        crate::interrupt::flag();
        let (file, tmp_path) = self.staged_file(".partial")?.into_parts();
        let mut w = BufWriter::new(StopOnSignal(file));
        fill(&mut w)
            .and_then(|()| w.flush())
            .and_then(|()| w.get_ref().0.sync_all())
            .with_context(|| format!("cannot write `{shown}`"))?;
        drop(w);
        self.deliver(tmp_path)
    }

    /// Write `bytes` (see [`Destination::write_with`]).
    pub(crate) fn write_bytes(&self, bytes: &[u8]) -> Result<()> {
        self.write_with(|w| w.write_all(bytes))
    }

    /// Move a finished staged file into place: renamed over a regular path (keeping an
    /// existing file's permissions), copied into a device or FIFO. The staged file is
    /// gone afterwards, whatever happens.
    pub(crate) fn deliver(&self, staged: tempfile::TempPath) -> Result<()> {
        let shown = self.shown.display();
        match self.kind {
            Kind::Special => {
                let mut from = std::fs::File::open(&staged)
                    .with_context(|| format!("cannot write `{shown}`"))?;
                let mut to = self
                    .special_file()
                    .with_context(|| format!("cannot write `{shown}`"))?;
                std::io::copy(&mut from, &mut to)
                    .and_then(|_| to.flush())
                    .with_context(|| format!("cannot write `{shown}`"))?;
                Ok(())
            }
            Kind::Folder => bail!("cannot write `{shown}`: it is a folder; give a file name"),
            Kind::File => {
                let mode = std::fs::metadata(&self.real).ok().map(|m| m.permissions());
                match mode {
                    Some(p) => {
                        let _ = std::fs::set_permissions(&staged, p);
                    }
                    None => readable_by_all(&staged),
                }
                staged
                    .persist(&self.real)
                    .map_err(|e| e.error)
                    .with_context(|| format!("cannot write `{shown}`"))
            }
        }
    }
}

/// A writer that fails once a stop was asked for ([`crate::interrupt`]), ending a long
/// write early; the staged file is then dropped (removed) and the command exits 2.
struct StopOnSignal<W>(W);

impl<W: Write> Write for StopOnSignal<W> {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        if crate::interrupt::requested() {
            return Err(std::io::Error::other("interrupted: nothing was written"));
        }
        self.0.write(buf)
    }

    fn flush(&mut self) -> std::io::Result<()> {
        self.0.flush()
    }
}

/// Write `bytes` to `path` whole or not at all (see [`Destination`]); the path may not
/// be an input (the caller checks that with [`Destination::new`] where there are inputs).
pub(crate) fn write_atomically(path: &Path, bytes: &[u8]) -> Result<()> {
    Destination::new(path, NO_INPUTS)?.write_bytes(bytes)
}

/// Give a staged file or folder the usual permissions (temporary files are private).
pub(crate) fn readable_by_all(path: &Path) {
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = if path.is_dir() { 0o755 } else { 0o644 };
        // Best effort: a file that stays private is still a correct file.
        let _ = std::fs::set_permissions(path, std::fs::Permissions::from_mode(mode));
    }
}

/// A path's extension in lower case (`None` without one): how outputs choose their format.
pub(crate) fn extension(path: &Path) -> Option<String> {
    path.extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
}

/// Write `bytes` to standard output. A closed pipe (`stewart solve | head`) is the
/// reader's choice and ends the writing quietly; any other failure (a full disk) is an error.
pub(crate) fn stdout(bytes: &[u8]) -> Result<()> {
    stdout_with(|w| w.write_all(bytes))
}

/// Write what `fill` produces to standard output (see [`stdout`]).
pub(crate) fn stdout_with(fill: impl FnOnce(&mut dyn Write) -> std::io::Result<()>) -> Result<()> {
    let out = std::io::stdout().lock();
    let mut w = BufWriter::with_capacity(1 << 16, out);
    match fill(&mut w).and_then(|()| w.flush()) {
        Err(e) if e.kind() == ErrorKind::BrokenPipe => Ok(()),
        other => other.context("cannot write to standard output"),
    }
}

/// Write to `out` when given (checked already), else to standard output.
pub(crate) fn emit_with(
    out: Option<&Destination>,
    fill: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
) -> Result<()> {
    match out {
        Some(d) => d.write_with(fill),
        None => stdout_with(fill),
    }
}

/// Check an optional `--out` path against the command's inputs.
pub(crate) fn destination(
    path: Option<&Path>,
    inputs: &[(&str, impl AsRef<Path>)],
) -> Result<Option<Destination>> {
    path.map(|p| Destination::new(p, inputs)).transpose()
}

#[cfg(test)]
mod tests;
