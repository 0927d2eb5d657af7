//! End-to-end tests of the `stewart` binary: run it as a user would and check what it
//! prints, writes and returns.

mod analysis;
mod boards;
mod cad;
mod calibrate;
mod capture;
mod certified;
mod check;
mod chinese;
mod cue;
mod design;
mod docs;
mod dynamics;
mod export;
mod firmware;
mod fk;
mod framing;
mod gates;
mod link;
mod omct;
mod robot;
mod rotary;
mod serial;
mod settings;
mod solve;
mod telemetry;
mod video_timing;
mod view;
mod watched;

use std::path::Path;
use std::process::{Command, Output};

/// Run `stewart` with `args` (standard input empty unless given).
pub fn stewart(args: &[&str]) -> Output {
    stewart_with_input(args, b"")
}

/// Run `stewart` with `args`, feeding `input` on standard input.
pub fn stewart_with_input(args: &[&str], input: &[u8]) -> Output {
    stewart_in(&[], args, input)
}

/// Run `stewart` with `args` and the environment variables `env`, feeding `input`. The
/// locale is English unless `env` says otherwise (the words drawn follow LANG).
pub fn stewart_in(env: &[(&str, &str)], args: &[&str], input: &[u8]) -> Output {
    use std::io::Write;
    let mut command = Command::new(env!("CARGO_BIN_EXE_stewart-e2e"));
    command
        .env_remove("LC_ALL")
        .env_remove("LC_MESSAGES")
        .env("LANG", "C.UTF-8");
    for (name, value) in env {
        command.env(name, value);
    }
    let mut child = command
        .args(args)
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("cannot start stewart: {e}"));
    if let Some(mut stdin) = child.stdin.take() {
        stdin
            .write_all(input)
            .unwrap_or_else(|e| panic!("stdin: {e}"));
    }
    child
        .wait_with_output()
        .unwrap_or_else(|e| panic!("stewart did not finish: {e}"))
}

/// Standard output as text.
pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// Standard error as text.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Write `text` to `dir/name` and return the path as a string.
pub fn write(dir: &Path, name: &str, text: &str) -> String {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap_or_else(|e| panic!("{e}"));
    path.display().to_string()
}

/// What `ffprobe` says of a video's first stream (`stream` entries, such as
/// `nb_read_frames,width`) and its container's duration, as `key=value` lines, with the
/// duration in seconds.
pub fn probe(video: &Path, stream: &str, count_frames: bool) -> (String, f64) {
    let mut command = Command::new("ffprobe");
    command.args(["-v", "error", "-select_streams", "v:0"]);
    if count_frames {
        command.arg("-count_frames");
    }
    let output = command
        .args(["-show_entries", &format!("stream={stream}")])
        .args(["-show_entries", "format=duration"])
        .args(["-of", "default=noprint_wrappers=1"])
        .arg(video)
        .output()
        .unwrap_or_else(|e| panic!("ffprobe: {e}"));
    let text = String::from_utf8_lossy(&output.stdout).into_owned();
    let duration = text
        .lines()
        .find_map(|l| l.strip_prefix("duration="))
        .and_then(|d| d.parse().ok())
        .unwrap_or(f64::NAN);
    (text, duration)
}

/// A fresh temporary folder.
pub fn tempdir() -> tempfile::TempDir {
    tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"))
}

/// Parse a CSV text into its header and numeric rows.
pub fn parse_csv(text: &str) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut lines = text.lines();
    let header = lines
        .next()
        .unwrap_or("")
        .split(',')
        .map(str::to_owned)
        .collect();
    let rows = lines
        .map(|l| {
            l.split(',')
                .map(|c| c.parse().unwrap_or_else(|e| panic!("{c}: {e}")))
                .collect()
        })
        .collect();
    (header, rows)
}

#[test]
fn help_lists_every_command() {
    let o = stewart(&["--help"]);
    assert!(o.status.success());
    let text = stdout(&o);
    // The command names: the first word of each line of the "Commands:" section.
    let commands: Vec<&str> = text
        .lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .filter_map(|l| l.split_whitespace().next())
        .collect();
    assert_eq!(
        commands,
        [
            "solve",
            "check",
            "fk",
            "cue",
            "calibrate",
            "workspace",
            "forces",
            "modes",
            "singularity",
            "design",
            "render",
            "plot",
            "robot",
            "view",
            "settings",
            "firmware",
            "link",
            "device-sim",
            "telemetry",
            "help"
        ]
    );
    assert!(!text.contains("later"), "{text}");
}

#[test]
fn an_argument_error_is_one_line_with_its_choices() {
    // clap's list of choices joins the line (it used to show a literal `\n`).
    let o = stewart(&["check", "--format", "bogus"]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(
        stderr(&o),
        "error: invalid value 'bogus' for '--format <FORMAT>' [possible values: text, json]\n"
    );
    // A value's own line break still shows as `\n`, on the one line.
    let o = stewart(&["check", "--format", "a\nb"]);
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("a\\nb"), "{err}");
}
