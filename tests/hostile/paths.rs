//! What stands at an output path is never destroyed: devices and FIFOs are written, not
//! replaced; links are followed; an input is never overwritten. Standard output and
//! error that cannot be written end the run cleanly.

use std::io::Read;
use std::path::Path;
use std::process::Stdio;
use std::time::Instant;

use crate::run::{collect, command, finish, names, path, run, tempdir, write};

fn is_char_device(p: &Path) -> bool {
    use std::os::unix::fs::FileTypeExt;
    std::fs::metadata(p).is_ok_and(|m| m.file_type().is_char_device())
}

#[test]
fn devices_stay_devices() {
    let dir = tempdir();
    let legs = dir.path().join("legs.csv");
    let o = run(&["solve", "--out", &legs.display().to_string()]);
    o.assert_promises();
    let legs = legs.display().to_string();
    for args in [
        vec!["solve", "--out", "/dev/null"],
        vec![
            "fk",
            "--preset",
            "paired",
            "--legs",
            &legs,
            "--out",
            "/dev/null",
        ],
        vec!["forces", "--preset", "paired", "--out", "/dev/null"],
        vec!["forces", "--preset", "crank-rig", "--out", "/dev/null"],
        vec!["firmware", "--preset", "servo-desk", "--out", "/dev/null"],
        vec!["plot", "--out", "/dev/null"],
        vec![
            "workspace",
            "--preset",
            "paired",
            "--resolution",
            "32",
            "--out",
            "/dev/null",
        ],
    ] {
        let o = run(&args);
        // A plot or points file needs a known extension; either way the device survives.
        o.assert_promises();
        assert!(
            is_char_device(Path::new("/dev/null")),
            "{} replaced /dev/null",
            o.shown()
        );
    }
    for args in [
        vec!["solve", "--out", "/dev/full"],
        vec!["firmware", "--preset", "servo-desk", "--out", "/dev/full"],
    ] {
        let o = run(&args);
        o.assert_refused();
        assert!(o.stderr.contains("No space left"), "{}", o.stderr);
        assert!(is_char_device(Path::new("/dev/full")));
    }
}

#[test]
fn a_fifo_is_written_into_and_stays_a_fifo() {
    let dir = tempdir();
    let fifo = dir.path().join("pipe");
    let made = std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .is_ok_and(|s| s.success());
    assert!(made, "mkfifo failed");
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || {
            let mut text = String::new();
            let _ = std::fs::File::open(&fifo).and_then(|mut f| f.read_to_string(&mut text));
            text
        })
    };
    let o = run(&["solve", "--out", &fifo.display().to_string()]);
    o.assert_promises();
    assert_eq!(o.code, Some(0));
    let text = reader.join().unwrap_or_default();
    assert!(
        text.starts_with("t,x,y,z,"),
        "the reader got {} bytes",
        text.len()
    );
    assert_eq!(text.lines().count(), 1002);
    use std::os::unix::fs::FileTypeExt;
    assert!(std::fs::metadata(&fifo).is_ok_and(|m| m.file_type().is_fifo()));
}

#[test]
fn a_fifo_nobody_reads_gives_way_to_sigterm() {
    let dir = tempdir();
    let fifo = dir.path().join("pipe");
    let made = std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .is_ok_and(|s| s.success());
    assert!(made, "mkfifo failed");
    // The table and a GIF both wait for a reader that never comes, until SIGTERM.
    let gif = dir.path().join("pipe.gif");
    std::os::unix::fs::symlink(&fifo, &gif).unwrap_or_else(|e| panic!("{e}"));
    for args in [
        vec!["solve", "--out", &fifo.to_str().unwrap_or_default()],
        vec![
            "render",
            "--frames",
            "0..2",
            "--size",
            "64x48",
            "--out",
            gif.to_str().unwrap_or_default(),
        ],
    ] {
        let started = Instant::now();
        let child = command(&args)
            .spawn()
            .unwrap_or_else(|e| panic!("cannot start stewart: {e}"));
        std::thread::sleep(std::time::Duration::from_millis(1500));
        let sent = std::process::Command::new("kill")
            .args(["-TERM", &child.id().to_string()])
            .status()
            .is_ok_and(|s| s.success());
        assert!(sent);
        let mut o = collect(child, &args, started);
        // The note said while waiting for the reader is not part of the refusal.
        let note = "waiting for a reader of";
        o.stderr = (o.stderr.lines())
            .filter(|l| !l.starts_with(note))
            .map(|l| format!("{l}\n"))
            .collect();
        o.assert_refused();
        assert!(
            o.stderr.contains("interrupted"),
            "{}: {}",
            o.shown(),
            o.stderr
        );
        assert!(
            o.elapsed.as_secs_f64() < 10.0,
            "{}: {:?}",
            o.shown(),
            o.elapsed
        );
    }
    assert_eq!(names(dir.path()), vec!["pipe", "pipe.gif"]);
}

#[test]
fn links_are_followed_and_kept() {
    let dir = tempdir();
    let target = write(dir.path(), "target.csv", b"old");
    let link = dir.path().join("link.csv");
    std::os::unix::fs::symlink(&target, &link).unwrap_or_else(|e| panic!("{e}"));
    let o = run(&["solve", "--out", &link.display().to_string()]);
    o.assert_promises();
    assert!(std::fs::symlink_metadata(&link).is_ok_and(|m| m.file_type().is_symlink()));
    let text = std::fs::read_to_string(&target).unwrap_or_default();
    assert!(text.starts_with("t,x,y,z,"), "{text:.40}");
    assert_eq!(names(dir.path()), vec!["link.csv", "target.csv"]);
}

#[test]
fn an_input_is_never_an_output() {
    let dir = tempdir();
    let scenario = dir.path().join("s.toml");
    std::fs::write(
        &scenario,
        stewart_kinematics::io::scenario::presets::text("paired")
            .unwrap_or_else(|| panic!("no preset paired")),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let original = std::fs::read(&scenario).unwrap_or_default();
    let s = scenario.display().to_string();
    let legs = path(dir.path(), "legs.csv");
    assert_eq!(
        run(&["solve", "--scenario", &s, "--out", &legs]).code,
        Some(0)
    );
    let legs_before = std::fs::read(&legs).unwrap_or_default();
    let alias = dir.path().join(".").join("s.toml").display().to_string();
    // A scenario file named like a video: rendering must not write over it.
    let as_gif = dir.path().join("s.gif");
    std::fs::copy(&scenario, &as_gif).unwrap_or_else(|e| panic!("{e}"));
    let g = as_gif.display().to_string();
    for args in [
        vec!["render", "--scenario", &g, "--out", &g, "--frames", "0..2"],
        vec!["render", "--scenario", &s, "--out", &s, "--frames", "0..2"],
        vec!["solve", "--scenario", &s, "--out", &s],
        vec!["solve", "--scenario", &s, "--out", &alias],
        vec!["solve", "--poses", &legs, "--out", &legs],
        vec!["fk", "--scenario", &s, "--legs", &legs, "--out", &legs],
        vec![
            "calibrate",
            "--scenario",
            &s,
            "--measurements",
            &legs,
            "--out",
            &legs,
        ],
        vec![
            "calibrate",
            "--scenario",
            &s,
            "--measurements",
            &legs,
            "--out",
            &alias,
        ],
        vec!["forces", "--scenario", &s, "--out", &s],
        vec!["firmware", "--scenario", &s, "--out", &s],
        vec!["plot", "--scenario", &s, "--out", &s],
        vec![
            "workspace",
            "--scenario",
            &s,
            "--resolution",
            "16",
            "--out",
            &s,
        ],
    ] {
        let o = run(&args);
        o.assert_refused();
        assert!(
            o.stderr.contains("refusing to write") || o.stderr.contains("must end in"),
            "{}: {}",
            o.shown(),
            o.stderr
        );
    }
    assert_eq!(std::fs::read(&scenario).unwrap_or_default(), original);
    assert_eq!(std::fs::read(&as_gif).unwrap_or_default(), original);
    assert_eq!(std::fs::read(&legs).unwrap_or_default(), legs_before);
}

#[test]
fn a_full_standard_output_or_error_is_an_error_not_a_panic() {
    for args in [
        vec!["settings"],
        vec!["check", "--preset", "paired"],
        vec!["solve"],
        vec!["--help"],
    ] {
        let full = std::fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .unwrap_or_else(|e| panic!("{e}"));
        let mut c = command(&args);
        c.stdout(Stdio::from(full));
        let o = finish(c, &args);
        o.assert_refused();
        assert!(
            o.stderr.contains("No space left"),
            "{}: {}",
            o.shown(),
            o.stderr
        );
    }
    // Standard error itself full: nothing can be said, but the status still says it.
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .unwrap_or_else(|e| panic!("{e}"));
    let mut c = command(&["check", "--scenario", "nope.toml"]);
    c.stderr(Stdio::from(full));
    let status = c.status().unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(status.code(), Some(2));
}

#[test]
fn a_closed_pipe_ends_quietly() {
    let args = ["solve", "--set", "trajectory.samples=200000"];
    let started = Instant::now();
    let mut child = command(&args).spawn().unwrap_or_else(|e| panic!("{e}"));
    // Read the first line, then close the pipe (as `| head -1` does).
    if let Some(mut out) = child.stdout.take() {
        let mut first = [0u8; 64];
        let _ = out.read(&mut first);
    }
    let o = collect(child, &args, started);
    assert_eq!(o.code, Some(0), "{}", o.stderr);
    assert!(o.stderr.is_empty(), "{}", o.stderr);
}

#[test]
fn window_and_gpu_settings_are_checked_before_use() {
    for (var, value, command_args) in [
        ("WINIT_X11_SCALE_FACTOR", "abc", vec!["view"]),
        ("WINIT_X11_SCALE_FACTOR", "0", vec!["view"]),
        ("WINIT_X11_SCALE_FACTOR", "-2", vec!["view"]),
        ("WINIT_X11_SCALE_FACTOR", "1e9", vec!["view"]),
        ("WGPU_BACKEND", "bogus", vec!["view"]),
        ("WGPU_BACKEND", "vulcan", vec!["render", "--out", "x.gif"]),
        ("WGPU_POWER_PREF", "fast", vec!["render", "--out", "x.gif"]),
    ] {
        let mut c = command(&command_args);
        c.env(var, value).env("DISPLAY", ":999");
        let o = finish(c, &command_args);
        o.assert_refused();
        assert!(
            o.stderr.contains(var) && o.stderr.contains(value),
            "{var}={value}: {}",
            o.stderr
        );
    }
}

#[test]
fn a_window_larger_than_the_gpu_allows_is_shrunk_not_a_panic() {
    let dir = tempdir();
    let shot = dir.path().join("big.png");
    let o = std::process::Command::new("xvfb-run")
        .args([
            "-a",
            "-s",
            "-screen 0 1600x900x24",
            env!("CARGO_BIN_EXE_stewart-e2e"),
        ])
        .args([
            "view",
            "--size",
            "3000x720",
            "--frames",
            "2",
            "--screenshot",
        ])
        .arg(&shot)
        .env("WINIT_X11_SCALE_FACTOR", "3")
        .env("XDG_RUNTIME_DIR", std::env::temp_dir())
        .output()
        .unwrap_or_else(|e| panic!("xvfb-run is needed (apt-get install xvfb xauth): {e}"));
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    let (w, h) = image::image_dimensions(&shot).unwrap_or_else(|e| panic!("{e}"));
    assert!(w <= 8192 && h <= 8192 && w > 4000, "{w}×{h}");
}
