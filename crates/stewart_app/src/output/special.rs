//! Writing into a device or FIFO without ever blocking past a stop request.
//!
//! Opening a FIFO for writing waits until a reader opens it, and writing into a full
//! pipe waits until the reader drains it; a signal handler that only sets the stop flag
//! cannot end either wait. So the file is opened and written non-blocking, waiting in
//! short sleeps that look at the stop flag (Ctrl-C, SIGTERM, SIGHUP) in between.

use std::fs::File;
use std::io::{ErrorKind, Write};
use std::os::unix::fs::OpenOptionsExt;
use std::path::Path;
use std::time::Duration;

/// How long to sleep between attempts while the other end is not ready.
const WAIT: Duration = Duration::from_millis(20);

/// The error for a stop requested while waiting.
fn stopped() -> std::io::Error {
    std::io::Error::new(
        ErrorKind::Interrupted,
        "interrupted: nothing more was written",
    )
}

/// A device or FIFO opened for writing.
#[derive(Debug)]
pub(crate) struct SpecialFile(File);

impl SpecialFile {
    /// Open `path` for writing, waiting for a FIFO's reader until one comes or a stop is
    /// requested; `waiting` is said on standard error (when not empty) once the reader has
    /// kept it waiting half a second.
    pub(crate) fn open_saying(path: &Path, waiting: &str) -> std::io::Result<Self> {
        let started = std::time::Instant::now();
        let mut said = waiting.is_empty();
        loop {
            match std::fs::OpenOptions::new()
                .write(true)
                .custom_flags(libc::O_NONBLOCK)
                .open(path)
            {
                Ok(file) => return Ok(Self(file)),
                // A FIFO with no reader yet.
                Err(e) if e.raw_os_error() == Some(libc::ENXIO) => {
                    if crate::interrupt::requested() {
                        return Err(std::io::Error::new(
                            ErrorKind::Interrupted,
                            "interrupted while waiting for a reader: nothing was written",
                        ));
                    }
                    if !said && started.elapsed() >= Duration::from_millis(500) {
                        said = true;
                        let _ = writeln!(std::io::stderr(), "{waiting}");
                    }
                    std::thread::sleep(WAIT);
                }
                Err(e) => return Err(e),
            }
        }
    }
}

impl Write for SpecialFile {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        loop {
            match self.0.write(buf) {
                Err(e) if e.kind() == ErrorKind::WouldBlock => {
                    if crate::interrupt::requested() {
                        return Err(stopped());
                    }
                    std::thread::sleep(WAIT);
                }
                other => return other,
            }
        }
    }

    fn flush(&mut self) -> std::io::Result<()> {
        self.0.flush()
    }
}
