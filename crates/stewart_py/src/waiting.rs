//! Long work that Ctrl-C can stop: the work runs on a thread of its own with the GIL
//! released, and the caller wakes every 50 ms to let Python handle its signals.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{RecvTimeoutError, channel};
use std::sync::{Arc, Mutex, PoisonError};
use std::time::Duration;

use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;

/// How often the caller looks at Python's signals while the work runs.
const POLL: Duration = Duration::from_millis(50);

/// The result of `work`, run on a thread of its own while the GIL is released (other
/// Python threads run). A signal handler that raises (Ctrl-C: `KeyboardInterrupt`) ends the
/// wait at once with its exception: `cancel`, when given, is then set so that work that
/// polls it stops; other work (a read from a FIFO no writer opens) is left to finish on
/// its own thread, its result dropped.
pub fn interruptible<T: Send + 'static>(
    py: Python<'_>,
    cancel: Option<Arc<AtomicBool>>,
    work: impl FnOnce() -> T + Send + 'static,
) -> PyResult<T> {
    let (sender, receiver) = channel();
    std::thread::Builder::new()
        .name("stewart-work".to_owned())
        .spawn(move || {
            let _ = sender.send(work());
        })
        .map_err(|e| PyRuntimeError::new_err(format!("cannot start the work: {e}")))?;
    // Shared with the detached closure (a receiver is Send but not Sync).
    let receiver = Mutex::new(receiver);
    loop {
        let waited = py.detach(|| {
            receiver
                .lock()
                .unwrap_or_else(PoisonError::into_inner)
                .recv_timeout(POLL)
        });
        match waited {
            Ok(value) => return Ok(value),
            Err(RecvTimeoutError::Timeout) => {
                if let Err(e) = py.check_signals() {
                    if let Some(flag) = &cancel {
                        flag.store(true, Ordering::Relaxed);
                    }
                    return Err(e);
                }
            }
            Err(RecvTimeoutError::Disconnected) => {
                return Err(PyRuntimeError::new_err(
                    "internal error: the computation failed (a panic in the core)",
                ));
            }
        }
    }
}
