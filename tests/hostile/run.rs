//! Running the real binary under hostile conditions, and the promises every run keeps.

use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::time::{Duration, Instant};

/// The longest any one command may run before it counts as a hang.
pub const HANG: Duration = Duration::from_secs(90);

/// What one run did.
#[derive(Debug)]
pub struct Outcome {
    /// The command line, for messages.
    pub args: Vec<String>,
    /// Exit code (`None`: killed by a signal).
    pub code: Option<i32>,
    /// Standard output.
    pub stdout: String,
    /// Standard error.
    pub stderr: String,
    /// Wall time.
    pub elapsed: Duration,
}

/// A `stewart` command with a private runtime folder (Mesa warns without one).
pub fn command(args: &[&str]) -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_stewart-e2e"));
    c.args(args)
        .env("XDG_RUNTIME_DIR", std::env::temp_dir())
        .env_remove("WGPU_BACKEND")
        .env_remove("WINIT_X11_SCALE_FACTOR")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    c
}

/// Run `c` to the end (killing it after [`HANG`], which fails the test).
pub fn finish(mut c: Command, args: &[&str]) -> Outcome {
    let started = Instant::now();
    let child = c
        .spawn()
        .unwrap_or_else(|e| panic!("cannot start stewart: {e}"));
    collect(child, args, started)
}

/// Wait for a started child, reading its output, failing on a hang.
pub fn collect(mut child: Child, args: &[&str], started: Instant) -> Outcome {
    let out = child.stdout.take();
    let err = child.stderr.take();
    let read = |pipe: Option<std::process::ChildStdout>| {
        std::thread::spawn(move || {
            let mut s = Vec::new();
            if let Some(mut p) = pipe {
                let _ = std::io::Read::read_to_end(&mut p, &mut s);
            }
            String::from_utf8_lossy(&s).into_owned()
        })
    };
    let out = read(out);
    let err = std::thread::spawn(move || {
        let mut s = Vec::new();
        if let Some(mut p) = err {
            let _ = std::io::Read::read_to_end(&mut p, &mut s);
        }
        String::from_utf8_lossy(&s).into_owned()
    });
    let status = wait_or_kill(&mut child, HANG);
    let outcome = Outcome {
        args: args.iter().map(|s| (*s).to_owned()).collect(),
        code: status.and_then(|s| s.code()),
        stdout: out.join().unwrap_or_default(),
        stderr: err.join().unwrap_or_default(),
        elapsed: started.elapsed(),
    };
    assert!(
        status.is_some(),
        "HANG: `stewart {}` ran past {HANG:?}",
        outcome.args.join(" ")
    );
    outcome
}

/// Wait up to `limit`; kill and return `None` past it.
pub fn wait_or_kill(child: &mut Child, limit: Duration) -> Option<ExitStatus> {
    let started = Instant::now();
    loop {
        if let Ok(Some(s)) = child.try_wait() {
            return Some(s);
        }
        if started.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            return None;
        }
        std::thread::sleep(Duration::from_millis(10));
    }
}

/// Run `stewart args` in the current folder.
pub fn run(args: &[&str]) -> Outcome {
    finish(command(args), args)
}

impl Outcome {
    /// The command line, for messages.
    pub fn shown(&self) -> String {
        format!("`stewart {}`", self.args.join(" "))
    }

    /// The promises of every run: an exit status of 0, 1 or 2 (never a panic's 101 or a
    /// signal), no panic message; a refusal (2) is exactly one line starting `error: `;
    /// a success prints no NaN or infinity.
    pub fn assert_promises(&self) {
        let who = self.shown();
        assert!(
            !self.stderr.contains("panicked") && !self.stderr.contains("RUST_BACKTRACE"),
            "PANIC in {who}:\n{}",
            self.stderr
        );
        assert!(
            matches!(self.code, Some(0..=2)),
            "{who} exited with {:?}:\n{}",
            self.code,
            self.stderr
        );
        if self.code == Some(2) {
            let lines: Vec<&str> = self.stderr.lines().filter(|l| !l.is_empty()).collect();
            assert!(
                lines.len() == 1 && lines[0].starts_with("error: "),
                "{who}: a refusal must be one `error: ` line, got:\n{}",
                self.stderr
            );
            assert!(
                !self.stderr.contains(".stewart-"),
                "{who}: the error shows an internal temporary path:\n{}",
                self.stderr
            );
        } else {
            assert_no_nonfinite(&self.stdout, &who);
        }
    }

    /// [`Outcome::assert_promises`], and a refusal (exit 2).
    pub fn assert_refused(&self) {
        self.assert_promises();
        assert_eq!(self.code, Some(2), "{} was not refused", self.shown());
    }
}

/// No `NaN` or `inf` token in `text` (a number that is not one).
pub fn assert_no_nonfinite(text: &str, who: &str) {
    for token in text.split([',', ' ', '\n', '\t', '[', ']', ':', '(', ')']) {
        let t = token
            .trim()
            .trim_start_matches(['-', '+'])
            .to_ascii_lowercase();
        assert!(
            t != "nan" && t != "inf" && t != "infinity",
            "{who} printed a non-finite number `{token}`"
        );
    }
}

/// Files and folders in `dir` (names only, sorted).
pub fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .map(|d| {
            d.flatten()
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}

/// A fresh temporary folder.
pub fn tempdir() -> tempfile::TempDir {
    tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"))
}

/// `dir/name` as a string.
pub fn path(dir: &Path, name: &str) -> String {
    dir.join(name).display().to_string()
}

/// Write `bytes` to `dir/name`; its path as a string.
pub fn write(dir: &Path, name: &str, bytes: &[u8]) -> String {
    let p: PathBuf = dir.join(name);
    std::fs::write(&p, bytes).unwrap_or_else(|e| panic!("{e}"));
    p.display().to_string()
}

/// How many random cases each property runs: `HOSTILE_CASES` (the longer run of
/// `scripts/hostile.sh` sets it), else a number that keeps CI quick.
pub fn cases(default: u32) -> u32 {
    std::env::var("HOSTILE_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// The random-case settings of every property: [`cases`] cases (24 by default), no
/// failure files written into the source tree.
pub fn config() -> proptest::test_runner::Config {
    proptest::test_runner::Config {
        cases: cases(24),
        failure_persistence: None,
        ..proptest::test_runner::Config::default()
    }
}

/// Shipped presets with linear legs (`dietmaier` with its joints as coordinates).
pub const PRESETS: [&str; 8] = [
    "seed",
    "paired",
    "circle",
    "figure8",
    "helix",
    "sway",
    "keyframes",
    "dietmaier",
];
