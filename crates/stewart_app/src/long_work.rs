//! Long work on the command line: say what it will cost before it starts, and show the
//! time spent against that estimate while it runs (on a terminal), as the workspace and
//! the export show their progress.

use std::io::Write as _;
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressStyle};
use stewart_kinematics::model::trajectory::Samples;

/// Work estimated shorter than this runs without a word.
pub(crate) const QUIET_BELOW_S: f64 = 2.0;

/// How many samples a probe takes (its time, scaled, is the estimate); a motion no longer
/// than this runs at once, without a probe.
pub(crate) const PROBE_SAMPLES: usize = 20_000;

/// Seconds for `items` from a probe of `probe_items` that took `probe_seconds` (the cost
/// of each item about the same).
pub(crate) fn scaled(probe_seconds: f64, probe_items: usize, items: usize) -> f64 {
    if probe_items == 0 {
        return 0.0;
    }
    probe_seconds * items as f64 / probe_items as f64
}

/// `work` over `samples`. A motion longer than `probe` samples is first timed on its first
/// `probe` samples; when the estimate scaled from that is long, `what` and the estimate are
/// said first, and a spinner with the time spent runs on a terminal until it ends. Ctrl-C
/// ends the process (nothing is written before the work ends).
pub(crate) fn over_samples<T: Send>(
    what: &str,
    samples: &Samples,
    probe: usize,
    work: impl Fn(&Samples) -> T + Sync,
) -> T {
    if samples.len() <= probe {
        return work(samples);
    }
    let first = Samples {
        times: samples.times[..probe].to_vec(),
        poses: samples.poses[..probe].to_vec(),
    };
    let started = Instant::now();
    drop(work(&first));
    let seconds = scaled(started.elapsed().as_secs_f64(), probe, samples.len());
    if seconds < QUIET_BELOW_S {
        return work(samples);
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
        let worker = scope.spawn(|| work(samples));
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
pub(crate) fn duration_words(seconds: f64) -> String {
    if seconds < 90.0 {
        format!("{seconds:.0} s")
    } else if seconds < 5400.0 {
        format!("{:.0} min", seconds / 60.0)
    } else {
        format!("{:.1} h", seconds / 3600.0)
    }
}

/// Run `work` on a thread of its own while a spinner (on a terminal) shows the time spent
/// and `message()`, asked anew ten times a second; its result, its panic passed on.
pub(crate) fn with_spinner<T: Send>(
    message: impl Fn() -> String,
    work: impl FnOnce() -> T + Send,
) -> T {
    let spinner = ProgressBar::new_spinner();
    spinner.set_style(
        ProgressStyle::with_template("{spinner} {elapsed} {msg}")
            .unwrap_or_else(|_| ProgressStyle::default_spinner()),
    );
    let result = std::thread::scope(|scope| {
        let worker = scope.spawn(work);
        while !worker.is_finished() {
            spinner.set_message(message());
            spinner.tick();
            std::thread::sleep(Duration::from_millis(100));
        }
        worker.join()
    });
    spinner.finish_and_clear();
    result.unwrap_or_else(|panic| std::panic::resume_unwind(panic))
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
        // A short motion runs once, without a probe, and its result comes back.
        let samples = Samples {
            times: vec![0.0, 1.0],
            poses: vec![stewart_kinematics::Pose::default(); 2],
        };
        let runs = std::sync::atomic::AtomicUsize::new(0);
        let n = over_samples("nothing", &samples, 10, |s| {
            runs.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            s.len()
        });
        assert_eq!((n, runs.into_inner()), (2, 1));
    }
}
