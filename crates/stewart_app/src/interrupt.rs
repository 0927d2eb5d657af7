//! Ctrl-C, SIGTERM and SIGHUP as a flag that long work polls: it then stops, removes
//! what it staged and exits with an error, leaving nothing half-written. The signals are
//! also counted (a second one can mean more than the first).

use std::sync::OnceLock;
use std::sync::atomic::{AtomicBool, AtomicU32, Ordering};

static FLAG: AtomicBool = AtomicBool::new(false);
static COUNT: AtomicU32 = AtomicU32::new(0);
static INSTALLED: OnceLock<bool> = OnceLock::new();

/// The process-wide stop flag, with the signal handler installed on first use. Where no
/// handler can be installed the signals keep their default meaning (the process ends,
/// which also leaves no finished-looking output behind).
pub(crate) fn flag() -> &'static AtomicBool {
    INSTALLED.get_or_init(|| {
        ctrlc::set_handler(|| {
            FLAG.store(true, Ordering::Relaxed);
            COUNT.fetch_add(1, Ordering::Relaxed);
        })
        .is_ok()
    });
    &FLAG
}

/// How many stops were asked for so far (the link takes a second Ctrl-C on the way home as
/// an emergency stop). Installs the handler as [`flag`] does.
pub(crate) fn count() -> u32 {
    let _ = flag();
    COUNT.load(Ordering::Relaxed)
}

/// Whether a stop was asked for.
pub(crate) fn requested() -> bool {
    FLAG.load(Ordering::Relaxed)
}
