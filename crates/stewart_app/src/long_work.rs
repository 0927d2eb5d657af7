//! Long work on the command line: say what it will cost before it starts, and show the
//! time spent against that estimate while it runs (on a terminal), as the workspace and
//! the export show their progress.

use std::io::Write as _;
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressStyle};

/// Work estimated shorter than this runs without a word.
pub const QUIET_BELOW_S: f64 = 2.0;

/// How many items a probe takes at most (its time, scaled, is the estimate).
pub const PROBE_ITEMS: usize = 20_000;

/// Seconds for `items` from a probe of `probe_items` that took `probe_seconds` (the cost
/// of each item about the same).
pub fn scaled(probe_seconds: f64, probe_items: usize, items: usize) -> f64 {
    if probe_items == 0 {
        return 0.0;
    }
    probe_seconds * items as f64 / probe_items as f64
}

/// Time `probe`, then run `work`: when the estimate (`scale` of the probe's seconds) is
/// long, `what` and the estimate are said first, and a spinner with the time spent runs
/// on a terminal until it ends. Ctrl-C ends the process (nothing is written before the
/// work ends).
pub fn run<T: Send>(
    what: &str,
    probe: impl FnOnce(),
    scale: impl FnOnce(f64) -> f64,
    work: impl FnOnce() -> T + Send,
) -> T {
    let started = Instant::now();
    probe();
    let seconds = scale(started.elapsed().as_secs_f64());
    if seconds < QUIET_BELOW_S {
        return work();
    }
    let words = duration_words(seconds);
    let _ = writeln!(
        std::io::stderr(),
        "{what}: about {words} (Ctrl-C stops it)."
    );
    let spinner = ProgressBar::new_spinner();
    spinner.set_style(
        ProgressStyle::with_template("{spinner} {elapsed} of about {msg}")
            .unwrap_or_else(|_| ProgressStyle::default_spinner()),
    );
    spinner.set_message(words);
    let result = std::thread::scope(|scope| {
        let worker = scope.spawn(work);
        while !worker.is_finished() {
            spinner.tick();
            std::thread::sleep(Duration::from_millis(100));
        }
        worker.join()
    });
    spinner.finish_and_clear();
    result.unwrap_or_else(|panic| std::panic::resume_unwind(panic))
}

/// Seconds in words: `40 s`, `12 min`, `3.1 h`.
pub fn duration_words(seconds: f64) -> String {
    if seconds < 90.0 {
        format!("{seconds:.0} s")
    } else if seconds < 5400.0 {
        format!("{:.0} min", seconds / 60.0)
    } else {
        format!("{:.1} h", seconds / 3600.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn estimates_scale_with_the_items_and_read_in_sensible_units() {
        assert_eq!(scaled(0.02, 20_000, 10_000_000), 10.0);
        assert_eq!(scaled(1.0, 0, 5), 0.0);
        assert_eq!(duration_words(40.4), "40 s");
        assert_eq!(duration_words(720.0), "12 min");
        assert_eq!(duration_words(11_160.0), "3.1 h");
        // Short work runs without a word, and its result comes back.
        assert_eq!(run("nothing", || {}, |_| 0.5, || 7), 7);
    }
}
