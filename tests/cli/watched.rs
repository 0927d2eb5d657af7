//! A command whose standard error is read line by line as it comes, so that a test waits
//! for the line it needs (a port bound, a stream armed, a value held) instead of for a
//! time that a slow machine may not keep.

use std::io::{BufRead, BufReader, Read};
use std::process::{Child, Command, Output, Stdio};
use std::sync::{Arc, Condvar, Mutex};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// What the command said so far, and whether its standard error has closed.
#[derive(Default)]
struct Said {
    text: String,
    closed: bool,
}

/// A running command, its standard error watched (standard output gathered).
pub struct Watched {
    child: Child,
    said: Arc<(Mutex<Said>, Condvar)>,
    readers: Vec<JoinHandle<Vec<u8>>>,
}

impl Watched {
    /// Start `command` with its standard output and error piped.
    pub fn spawn(command: &mut Command) -> Self {
        let mut child = command
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap_or_else(|e| panic!("{e}"));
        let said = Arc::new((Mutex::new(Said::default()), Condvar::new()));
        let mut err = BufReader::new(child.stderr.take().unwrap_or_else(|| panic!("stderr")));
        let mut out = child.stdout.take().unwrap_or_else(|| panic!("stdout"));
        let shared = Arc::clone(&said);
        let error_reader = std::thread::spawn(move || {
            let mut line = String::new();
            loop {
                line.clear();
                let ended = !matches!(err.read_line(&mut line), Ok(n) if n > 0);
                let (lock, changed) = &*shared;
                let mut s = lock.lock().unwrap_or_else(|e| e.into_inner());
                s.text.push_str(&line);
                s.closed = ended;
                changed.notify_all();
                if ended {
                    return Vec::new();
                }
            }
        });
        let output_reader = std::thread::spawn(move || {
            let mut bytes = Vec::new();
            let _ = out.read_to_end(&mut bytes);
            bytes
        });
        Self {
            child,
            said,
            readers: vec![output_reader, error_reader],
        }
    }

    /// The process id (to signal it).
    pub fn id(&self) -> u32 {
        self.child.id()
    }

    /// Wait until a line of standard error contains `needle` (at most a minute: a hung
    /// command fails the test with what it said).
    pub fn wait_for(&self, needle: &str) {
        self.wait_for_line(needle, |line| line.contains(needle));
    }

    /// Wait until a whole line of standard error meets `wanted` (at most a minute), named
    /// `what` if it never comes.
    pub fn wait_for_line(&self, what: &str, wanted: impl Fn(&str) -> bool) {
        let (lock, changed) = &*self.said;
        let deadline = Instant::now() + Duration::from_secs(60);
        let mut s = lock.lock().unwrap_or_else(|e| e.into_inner());
        while !s.text.lines().any(&wanted) {
            let left = deadline.saturating_duration_since(Instant::now());
            assert!(
                !s.closed && !left.is_zero(),
                "never said `{what}`; said:\n{}",
                s.text
            );
            s = changed
                .wait_timeout(s, left)
                .unwrap_or_else(|e| e.into_inner())
                .0;
        }
    }

    /// Wait for the command to end (at most a minute): its status, standard output and
    /// standard error.
    pub fn finish(mut self) -> Output {
        let deadline = Instant::now() + Duration::from_secs(60);
        let status = loop {
            if let Some(status) = self.child.try_wait().unwrap_or_else(|e| panic!("{e}")) {
                break status;
            }
            assert!(Instant::now() < deadline, "the command did not end");
            std::thread::sleep(Duration::from_millis(20));
        };
        let mut readers = self.readers.drain(..);
        let stdout = (readers.next())
            .and_then(|r| r.join().ok())
            .unwrap_or_default();
        for r in readers {
            let _ = r.join();
        }
        let (lock, _) = &*self.said;
        let stderr = std::mem::take(&mut lock.lock().unwrap_or_else(|e| e.into_inner()).text);
        Output {
            status,
            stdout,
            stderr: stderr.into_bytes(),
        }
    }
}

impl Drop for Watched {
    /// A test that failed half-way leaves no command running.
    fn drop(&mut self) {
        let _ = self.child.kill();
    }
}
