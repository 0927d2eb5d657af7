//! The one gate every file the studio reads goes through: scenarios, pose tables,
//! vehicle recordings, packet captures, sessions, CAD parts, their glTF buffers and OBJ
//! material files. Only a regular file is read (a folder, FIFO, socket or device is
//! refused at once, by name, before it is opened: opening a FIFO would wait for a writer
//! for ever, and `/dev/zero` never ends), and never more than its kind's size cap, so a
//! wrong file costs a sentence, not the memory or a hang.

use std::io::Read;
use std::path::{Path, PathBuf};

use thiserror::Error;

/// What a file is read as: each kind has its size cap.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FileKind {
    /// A scenario (TOML): a few kilobytes.
    Scenario,
    /// A table of numbers (poses, leg lengths, vehicle motion, measurements).
    Table,
    /// A packet capture (pcap, pcapng).
    Capture,
    /// The viewer's saved session.
    Session,
    /// A CAD part (STL, OBJ, glTF, GLB).
    Mesh,
    /// A glTF buffer (`.bin`) or an OBJ's material library (`.mtl`).
    MeshSidecar,
}

impl FileKind {
    /// The most bytes read of such a file.
    pub const fn cap(self) -> u64 {
        match self {
            FileKind::Scenario => crate::ground::text::MAX_SCENARIO_BYTES,
            FileKind::Table | FileKind::Capture => crate::ground::text::MAX_TABLE_BYTES,
            FileKind::Session => 4 << 20,
            FileKind::Mesh | FileKind::MeshSidecar => 512 << 20,
        }
    }

    /// The kind in words, for messages.
    pub const fn words(self) -> &'static str {
        match self {
            FileKind::Scenario => "a scenario",
            FileKind::Table => "a table",
            FileKind::Capture => "a packet capture",
            FileKind::Session => "a session",
            FileKind::Mesh => "a CAD part",
            FileKind::MeshSidecar => "a CAD part's buffer or material file",
        }
    }
}

/// Why a file was not read.
#[derive(Debug, Error)]
pub enum FileError {
    /// Not a regular file: what it is instead.
    #[error("`{path}` is {what}, not a file: {kind} is read from a regular file")]
    NotRegular {
        /// The path.
        path: PathBuf,
        /// What stands there ("a folder", "a FIFO", …).
        what: &'static str,
        /// What it was to be read as.
        kind: &'static str,
    },
    /// Larger than its kind's cap.
    #[error("`{path}` is larger than {cap_mib} MiB, the most read of {kind}")]
    TooLarge {
        /// The path.
        path: PathBuf,
        /// The cap, MiB.
        cap_mib: u64,
        /// What it was to be read as.
        kind: &'static str,
    },
    /// It could not be opened or read.
    #[error("`{path}` cannot be read ({cause})")]
    Io {
        /// The path.
        path: PathBuf,
        /// Why (said in the message, not again as a source).
        cause: std::io::Error,
    },
}

/// What stands at a path that is not a regular file, in words.
fn not_regular(meta: &std::fs::Metadata) -> Option<&'static str> {
    let t = meta.file_type();
    if t.is_file() {
        return None;
    }
    if t.is_dir() {
        return Some("a folder");
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt as _;
        if t.is_fifo() {
            return Some("a FIFO (named pipe)");
        }
        if t.is_socket() {
            return Some("a socket");
        }
        if t.is_char_device() || t.is_block_device() {
            return Some("a device");
        }
    }
    Some("not a regular file")
}

/// All of the regular file at `path`, read as `kind` (within its cap).
pub fn read_file(path: &Path, kind: FileKind) -> Result<Vec<u8>, FileError> {
    let io = |cause| FileError::Io {
        path: path.to_path_buf(),
        cause,
    };
    let meta = std::fs::metadata(path).map_err(io)?;
    if let Some(what) = not_regular(&meta) {
        return Err(FileError::NotRegular {
            path: path.to_path_buf(),
            what,
            kind: kind.words(),
        });
    }
    let too_large = || FileError::TooLarge {
        path: path.to_path_buf(),
        cap_mib: kind.cap() >> 20,
        kind: kind.words(),
    };
    if meta.len() > kind.cap() {
        return Err(too_large());
    }
    let file = std::fs::File::open(path).map_err(io)?;
    if let Some(bytes) = read_in_parallel(&file, meta.len()) {
        return Ok(bytes);
    }
    let mut bytes = Vec::with_capacity(usize::try_from(meta.len()).unwrap_or(0));
    file.take(kind.cap() + 1)
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > kind.cap() {
        return Err(too_large());
    }
    Ok(bytes)
}

/// Files from this size on are read on all cores.
const PARALLEL_FROM: u64 = 16 << 20;
/// Bytes each task reads.
const PIECE: usize = 4 << 20;

/// A large file's `len` bytes read piece by piece on all cores, at their offsets: the
/// fresh pages they land in are mapped and zeroed by the kernel as the copy first touches
/// them, which costs more than the copy, and is spread this way. `None` — read it as a
/// stream instead — for a small file, off Unix, on any error, or when the file's length
/// is no longer `len` (it is being written: the stream reads what is there, within the
/// cap, and says what went wrong).
fn read_in_parallel(file: &std::fs::File, len: u64) -> Option<Vec<u8>> {
    #[cfg(unix)]
    {
        use rayon::prelude::*;
        use std::os::unix::fs::FileExt;
        if len < PARALLEL_FROM {
            return None;
        }
        let mut bytes = vec![0; usize::try_from(len).ok()?];
        let whole = bytes
            .par_chunks_mut(PIECE)
            .enumerate()
            .all(|(k, piece)| file.read_exact_at(piece, (k * PIECE) as u64).is_ok());
        // Nothing past the end: the file did not grow while it was read.
        let ended = file.read_at(&mut [0], len).ok() == Some(0);
        (whole && ended).then_some(bytes)
    }
    #[cfg(not(unix))]
    {
        let _ = (file, len);
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_regular_files_are_read_within_their_cap() {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let file = dir.path().join("a.csv");
        std::fs::write(&file, b"t\n0\n").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(
            read_file(&file, FileKind::Table).ok(),
            Some(b"t\n0\n".to_vec())
        );
        let folder = read_file(dir.path(), FileKind::Mesh)
            .err()
            .map(|e| e.to_string());
        assert!(folder.is_some_and(|e| e.contains("is a folder") && e.contains("a CAD part")));
        #[cfg(unix)]
        {
            // A device is refused before it is opened (`/dev/zero` never ends).
            let zero = read_file(Path::new("/dev/zero"), FileKind::MeshSidecar).err();
            assert!(matches!(
                zero,
                Some(FileError::NotRegular {
                    what: "a device",
                    ..
                })
            ));
            // A FIFO no one writes to: refused at once, not waited on.
            let fifo = dir.path().join("pipe");
            let made = std::process::Command::new("mkfifo").arg(&fifo).status();
            if made.is_ok_and(|s| s.success()) {
                let e = read_file(&fifo, FileKind::Table)
                    .err()
                    .map(|e| e.to_string());
                assert!(e.is_some_and(|e| e.contains("FIFO")));
            }
        }
        let missing = read_file(&dir.path().join("none"), FileKind::Scenario).err();
        assert!(matches!(missing, Some(FileError::Io { .. })));
    }
}
