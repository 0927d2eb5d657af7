//! Ctrl-C, SIGTERM and SIGHUP as a flag that long work polls: it then stops, removes
//! what it staged and exits with an error, leaving nothing half-written.

use std::sync::OnceLock;
use std::sync::atomic::{AtomicBool, Ordering};

static FLAG: AtomicBool = AtomicBool::new(false);
static INSTALLED: OnceLock<bool> = OnceLock::new();

/// The process-wide stop flag, with the signal handler installed on first use. Where no
/// handler can be installed the signals keep their default meaning (the process ends,
/// which also leaves no finished-looking output behind).
pub fn flag() -> &'static AtomicBool {
    INSTALLED.get_or_init(|| ctrlc::set_handler(|| FLAG.store(true, Ordering::Relaxed)).is_ok());
    &FLAG
}

/// Whether a stop was asked for.
pub fn requested() -> bool {
    FLAG.load(Ordering::Relaxed)
}
