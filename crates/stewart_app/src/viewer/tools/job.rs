//! One background job at a time, the viewer's single way to work off the UI thread (the
//! pre-flight report, the design search, the workspace, screenshots, exports).
//!
//! The newest request wins: asking for new work cancels the work in flight (its flag is
//! set; work that looks at it stops early) and waits for it to end before starting, so at
//! most one thread runs and a fast slider does not pile up threads. Results of replaced
//! work are never shown. The work may send several results (a coarse then a refined
//! workspace); the UI polls for the newest, never blocking. A job dropped with work in
//! flight cancels it and waits for it (an export then removes what it staged).

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, Receiver, Sender};
use std::thread::JoinHandle;

use crate::viewer::error::JobFailed;

/// The work's side: its cancel flag and where its results go.
pub(crate) struct Worker<T> {
    cancel: Arc<AtomicBool>,
    results: Sender<T>,
}

impl<T> Worker<T> {
    /// Whether newer work (or the user) asked this work to stop.
    pub(crate) fn cancelled(&self) -> bool {
        self.cancel.load(Ordering::Relaxed)
    }

    /// The cancel flag itself, for code that watches a flag of its own (the workspace's
    /// columns, an export's frames).
    pub(crate) fn cancel_flag(&self) -> Arc<AtomicBool> {
        Arc::clone(&self.cancel)
    }

    /// Hand a result to the UI; `false` once nobody will read it.
    pub(crate) fn send(&self, result: T) -> bool {
        self.results.send(result).is_ok()
    }
}

type Work<T> = Box<dyn FnOnce(&Worker<T>) + Send>;

struct Running<T> {
    cancel: Arc<AtomicBool>,
    results: Receiver<T>,
    handle: JoinHandle<()>,
    /// Replaced by newer work: its results are dropped.
    stale: bool,
}

/// One background job (see the module docs).
pub(crate) struct Job<T> {
    name: &'static str,
    running: Option<Running<T>>,
    pending: Option<Work<T>>,
    replaced: usize,
    failed: Option<JobFailed>,
}

impl<T: Send + 'static> Job<T> {
    /// An idle job whose threads are called `name`.
    pub(crate) fn new(name: &'static str) -> Self {
        Self {
            name,
            running: None,
            pending: None,
            replaced: 0,
            failed: None,
        }
    }

    /// Ask for `work`: work in flight is cancelled and its results dropped; `work` starts
    /// at once when nothing runs, else once the cancelled work has ended (at a later
    /// [`Job::poll`] or [`Job::wait`]). Work asked for meanwhile replaces it.
    pub(crate) fn start(&mut self, work: impl FnOnce(&Worker<T>) + Send + 'static) {
        if let Some(running) = &mut self.running
            && !running.stale
        {
            running.stale = true;
            running.cancel.store(true, Ordering::Relaxed);
            self.replaced += 1;
        }
        self.pending = Some(Box::new(work));
        self.failed = None;
        self.advance();
    }

    /// The newest result of the current work since the last poll (older ones that
    /// arrived meanwhile are skipped), or why it gave none; never blocks.
    pub(crate) fn poll(&mut self) -> Option<Result<T, JobFailed>> {
        let newest = self.collect(false);
        self.advance();
        newest
    }

    /// Wait until no work is in flight or asked for, and return the newest result of the
    /// last work (tests, screenshots, shutdown).
    pub(crate) fn wait(&mut self) -> Option<Result<T, JobFailed>> {
        let mut newest = None;
        loop {
            if let Some(r) = self.collect(true) {
                newest = Some(r);
            }
            self.advance();
            if self.running.is_none() && self.pending.is_none() {
                return newest;
            }
        }
    }

    /// Whether work is in flight or waiting to start.
    pub(crate) fn busy(&self) -> bool {
        self.running.as_ref().is_some_and(|r| !r.stale) || self.pending.is_some()
    }

    /// Ask the work in flight to stop (it keeps its results: an export says it was
    /// cancelled), and drop work waiting to start.
    pub(crate) fn cancel(&mut self) {
        self.pending = None;
        if let Some(running) = &self.running {
            running.cancel.store(true, Ordering::Relaxed);
        }
    }

    /// Whether the work in flight was asked to stop.
    #[cfg(test)]
    pub(crate) fn cancelling(&self) -> bool {
        self.running
            .as_ref()
            .is_some_and(|r| r.cancel.load(Ordering::Relaxed))
    }

    /// Work replaced by newer work before it ended.
    #[cfg(test)]
    pub(crate) fn replaced(&self) -> usize {
        self.replaced
    }

    /// Take the results that arrived and, once the thread has ended (or, `block`ing, after
    /// waiting for it), let it go.
    fn collect(&mut self, block: bool) -> Option<Result<T, JobFailed>> {
        if let Some(failed) = self.failed.take() {
            return Some(Err(failed));
        }
        let running = self.running.as_mut()?;
        let ended = block || running.handle.is_finished();
        let mut newest = None;
        while let Ok(result) = running.results.try_recv() {
            newest = Some(result);
        }
        let stale = running.stale;
        let mut panicked = false;
        if ended && let Some(running) = self.running.take() {
            panicked = running.handle.join().is_err();
            // Results sent just before the end.
            while let Ok(result) = running.results.try_recv() {
                newest = Some(result);
            }
        }
        if stale {
            return None;
        }
        match newest {
            Some(result) => Some(Ok(result)),
            None if panicked => Some(Err(JobFailed::Panicked)),
            None => None,
        }
    }

    /// Start the waiting work once nothing runs.
    fn advance(&mut self) {
        if self.running.is_some() {
            return;
        }
        let Some(work) = self.pending.take() else {
            return;
        };
        let cancel = Arc::new(AtomicBool::new(false));
        let (send, results) = mpsc::channel();
        let worker = Worker {
            cancel: Arc::clone(&cancel),
            results: send,
        };
        match std::thread::Builder::new()
            .name(self.name.to_owned())
            .spawn(move || work(&worker))
        {
            Ok(handle) => {
                self.running = Some(Running {
                    cancel,
                    results,
                    handle,
                    stale: false,
                });
            }
            Err(e) => self.failed = Some(JobFailed::NotStarted(e.to_string())),
        }
    }
}

impl<T> Drop for Job<T> {
    /// Work in flight is cancelled and waited for, so it leaves nothing half done.
    fn drop(&mut self) {
        self.pending = None;
        if let Some(running) = self.running.take() {
            running.cancel.store(true, Ordering::Relaxed);
            let _ = running.handle.join();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::{Duration, Instant};

    /// Work that sends `value` after waiting until cancelled or `ms` passed.
    fn slow(value: u32, ms: u64) -> impl FnOnce(&Worker<u32>) + Send + 'static {
        move |w| {
            let start = Instant::now();
            while !w.cancelled() && start.elapsed() < Duration::from_millis(ms) {
                std::thread::sleep(Duration::from_millis(1));
            }
            if !w.cancelled() {
                w.send(value);
            }
        }
    }

    #[test]
    fn the_newest_request_wins_and_replaced_work_is_never_shown() {
        let mut job = Job::new("test");
        job.start(slow(1, 10_000));
        job.start(slow(2, 10_000));
        job.start(|w: &Worker<u32>| {
            w.send(3);
        });
        assert!(job.busy());
        assert_eq!(job.wait(), Some(Ok(3)));
        assert!(!job.busy());
        // The first was cancelled in flight; the second never started (replaced while
        // waiting), so one replacement of running work.
        assert_eq!(job.replaced(), 1);
    }

    #[test]
    fn polling_gives_the_newest_of_several_results_without_blocking() {
        let mut job = Job::new("test");
        job.start(|w: &Worker<u32>| {
            for k in 0..5 {
                w.send(k);
            }
        });
        let start = Instant::now();
        let mut last = None;
        while job.busy() && start.elapsed() < Duration::from_secs(10) {
            if let Some(r) = job.poll() {
                last = Some(r);
            }
        }
        assert_eq!(last, Some(Ok(4)));
        assert_eq!(job.poll(), None);
    }

    #[test]
    fn cancel_reaches_the_work_and_a_panic_is_a_failure_not_a_crash() {
        let mut job = Job::new("test");
        job.start(|w: &Worker<u32>| {
            while !w.cancelled() {
                std::thread::sleep(Duration::from_millis(1));
            }
            w.send(7);
        });
        job.cancel();
        assert!(job.cancelling());
        assert_eq!(job.wait(), Some(Ok(7)));
        job.start(|_: &Worker<u32>| panic!("boom"));
        assert_eq!(job.wait(), Some(Err(JobFailed::Panicked)));
    }

    #[test]
    fn dropping_a_job_stops_and_waits_for_its_work() {
        let ended = Arc::new(AtomicBool::new(false));
        let flag = Arc::clone(&ended);
        let mut job = Job::new("test");
        job.start(move |w: &Worker<u32>| {
            while !w.cancelled() {
                std::thread::sleep(Duration::from_millis(1));
            }
            flag.store(true, Ordering::Relaxed);
        });
        drop(job);
        assert!(ended.load(Ordering::Relaxed));
    }
}
