//! Exports whose sink fails (an ffmpeg that quits or hangs, a full disk, a folder that
//! vanishes) and exports stopped by signals: each ends promptly with its error, exit 2,
//! nothing left behind, no ffmpeg left running.

use std::path::Path;
use std::process::Child;
use std::time::{Duration, Instant};

use crate::run::{collect, command, names, path, tempdir, wait_or_kill};

/// A stand-in `ffmpeg` (a shell script) in `dir/bin`: `-version` works, encoding does
/// what `body` says. It writes its process id to `dir/ffmpeg.pid`.
fn fake_ffmpeg(dir: &Path, body: &str) -> String {
    let bin = dir.join("bin");
    std::fs::create_dir_all(&bin).unwrap_or_else(|e| panic!("{e}"));
    let script = format!(
        "#!/bin/sh\nfor a in \"$@\"; do [ \"$a\" = \"-version\" ] && exit 0; done\necho $$ > '{}'\n{body}\n",
        dir.join("ffmpeg.pid").display()
    );
    let file = bin.join("ffmpeg");
    std::fs::write(&file, script).unwrap_or_else(|e| panic!("{e}"));
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&file, std::fs::Permissions::from_mode(0o755))
            .unwrap_or_else(|e| panic!("{e}"));
    }
    format!(
        "{}:{}",
        bin.display(),
        std::env::var("PATH").unwrap_or_default()
    )
}

/// Whether the process whose id the fake ffmpeg wrote is still alive.
fn fake_ffmpeg_alive(dir: &Path) -> bool {
    std::fs::read_to_string(dir.join("ffmpeg.pid"))
        .ok()
        .is_some_and(|pid| Path::new(&format!("/proc/{}", pid.trim())).exists())
}

fn signal(child: &Child, name: &str) {
    let status = std::process::Command::new("kill")
        .args([format!("-{name}"), child.id().to_string()])
        .status()
        .unwrap_or_else(|e| panic!("kill: {e}"));
    assert!(status.success());
}

/// Entries of `dir` other than the fake ffmpeg's folder and pid file.
fn left(dir: &Path) -> Vec<String> {
    names(dir)
        .into_iter()
        .filter(|n| n != "bin" && n != "ffmpeg.pid" && n != "out-dir")
        .collect()
}

#[test]
fn an_ffmpeg_that_quits_early_ends_the_export_with_its_words() {
    let dir = tempdir();
    let path_var = fake_ffmpeg(
        dir.path(),
        "head -c 1000 > /dev/null\necho \"Unknown encoder 'libx264'\" >&2\nexit 1",
    );
    let out = path(dir.path(), "v.mp4");
    let args = ["render", "--out", &out, "--size", "64x48"];
    let mut c = command(&args);
    c.env("PATH", path_var);
    let o = crate::run::finish(c, &args);
    o.assert_refused();
    assert!(
        o.stderr
            .contains("ffmpeg failed: Unknown encoder 'libx264'"),
        "{}",
        o.stderr
    );
    assert!(o.elapsed < Duration::from_secs(20), "{:?}", o.elapsed);
    assert!(left(dir.path()).is_empty(), "{:?}", left(dir.path()));
}

#[test]
fn an_ffmpeg_that_hangs_yields_to_ctrl_c_and_is_killed() {
    let dir = tempdir();
    // Never reads its input and never exits: the export's writer blocks on the pipe.
    let path_var = fake_ffmpeg(dir.path(), "exec sleep 600");
    let out = path(dir.path(), "v.mp4");
    let args = ["render", "--out", &out, "--size", "320x240"];
    let mut c = command(&args);
    c.env("PATH", path_var);
    let started = Instant::now();
    let child = c.spawn().unwrap_or_else(|e| panic!("{e}"));
    std::thread::sleep(Duration::from_secs(4));
    signal(&child, "INT");
    let asked = Instant::now();
    let o = collect(child, &args, started);
    o.assert_refused();
    assert!(o.stderr.contains("interrupted"), "{}", o.stderr);
    assert!(
        asked.elapsed() < Duration::from_secs(3),
        "took {:?} after Ctrl-C",
        asked.elapsed()
    );
    assert!(!fake_ffmpeg_alive(dir.path()), "ffmpeg was left running");
    assert!(left(dir.path()).is_empty(), "{:?}", left(dir.path()));
}

#[test]
fn signals_stop_every_kind_of_export_and_leave_nothing() {
    for (out_name, signal_name) in [
        ("v.mp4", "INT"),
        ("v.mp4", "TERM"),
        ("v.gif", "HUP"),
        ("frames", "TERM"),
    ] {
        let dir = tempdir();
        let out = path(dir.path(), out_name);
        let args = ["render", "--out", &out, "--size", "320x240"];
        let started = Instant::now();
        let child = command(&args).spawn().unwrap_or_else(|e| panic!("{e}"));
        std::thread::sleep(Duration::from_secs(3));
        signal(&child, signal_name);
        let asked = Instant::now();
        let o = collect(child, &args, started);
        o.assert_refused();
        assert!(
            asked.elapsed() < Duration::from_secs(3),
            "{out_name} {signal_name}: took {:?}",
            asked.elapsed()
        );
        assert!(o.stderr.contains("interrupted"), "{}", o.stderr);
        assert!(
            names(dir.path()).is_empty(),
            "{out_name} {signal_name}: {:?}",
            names(dir.path())
        );
    }
}

#[test]
fn a_folder_that_vanishes_mid_export_ends_it_at_once() {
    let dir = tempdir();
    let sub = dir.path().join("sub");
    std::fs::create_dir(&sub).unwrap_or_else(|e| panic!("{e}"));
    let out = sub.join("frames").display().to_string();
    let args = ["render", "--out", &out, "--size", "160x120"];
    let started = Instant::now();
    let mut child = command(&args).spawn().unwrap_or_else(|e| panic!("{e}"));
    std::thread::sleep(Duration::from_secs(3));
    // Frames keep arriving while it is removed: repeat until it is gone.
    let removed = Instant::now();
    while sub.exists() && removed.elapsed() < Duration::from_secs(5) {
        let _ = std::fs::remove_dir_all(&sub);
    }
    let gone = Instant::now();
    let status = wait_or_kill(&mut child, Duration::from_secs(30));
    let after = gone.elapsed();
    let o = collect(child, &args, started);
    assert!(status.is_some());
    o.assert_refused();
    assert!(o.stderr.contains("cannot write"), "{}", o.stderr);
    assert!(
        after < Duration::from_secs(2),
        "took {after:?} after the folder went"
    );
}

/// A 64 KiB file system (tmpfs), when this process may mount one (root on Linux).
struct TinyDisk {
    dir: tempfile::TempDir,
}

impl TinyDisk {
    fn mount() -> Option<Self> {
        let dir = tempdir();
        let ok = std::process::Command::new("mount")
            .args(["-t", "tmpfs", "-o", "size=64k", "tmpfs"])
            .arg(dir.path())
            .stderr(std::process::Stdio::null())
            .status()
            .is_ok_and(|s| s.success());
        ok.then_some(Self { dir })
    }
}

impl Drop for TinyDisk {
    fn drop(&mut self) {
        let _ = std::process::Command::new("umount")
            .arg(self.dir.path())
            .status();
    }
}

#[test]
fn a_full_disk_is_an_error_and_leaves_nothing() {
    // Always: a GIF written through a link to /dev/full (every write fails: disk full).
    let dir = tempdir();
    let link = dir.path().join("full.gif");
    #[cfg(unix)]
    std::os::unix::fs::symlink("/dev/full", &link).unwrap_or_else(|e| panic!("{e}"));
    let out = link.display().to_string();
    let args = [
        "render", "--out", &out, "--size", "64x48", "--frames", "0..5",
    ];
    let o = crate::run::run(&args);
    o.assert_refused();
    assert!(o.stderr.contains("No space left"), "{}", o.stderr);
    assert_eq!(names(dir.path()), vec!["full.gif".to_owned()]);
    // Where mounting is allowed: a really full file system, for each kind of export.
    match TinyDisk::mount() {
        Some(disk) => {
            for name in ["v.gif", "frames", "v.mp4", "legs.csv"] {
                let out = path(disk.dir.path(), name);
                let args: Vec<&str> = if name == "legs.csv" {
                    vec!["solve", "--set", "trajectory.samples=100000", "--out", &out]
                } else {
                    vec!["render", "--out", &out, "--size", "320x240"]
                };
                let o = crate::run::run(&args);
                o.assert_refused();
                assert!(o.stderr.contains("No space left"), "{name}: {}", o.stderr);
                assert!(
                    names(disk.dir.path()).is_empty(),
                    "{name}: {:?}",
                    names(disk.dir.path())
                );
            }
        }
        None => {
            eprintln!("note: cannot mount a tmpfs here; the full-disk case ran on /dev/full only")
        }
    }
}

#[test]
fn a_signal_during_a_long_table_write_leaves_nothing_half_written() {
    // A million poses: the CSV takes a while to write. Whenever SIGTERM lands — while
    // sampling, while writing, or after — there is never a staged file left, and an
    // output that exists is whole.
    for delay_ms in [800, 1600, 2400, 3200] {
        let dir = tempdir();
        let out = path(dir.path(), "legs.csv");
        let args = [
            "solve",
            "--preset",
            "paired",
            "--set",
            "trajectory.samples=1000000",
            "--out",
            &out,
        ];
        let started = Instant::now();
        let child = command(&args).spawn().unwrap_or_else(|e| panic!("{e}"));
        std::thread::sleep(Duration::from_millis(delay_ms));
        let _ = std::process::Command::new("kill")
            .args(["-TERM", &child.id().to_string()])
            .status();
        let o = collect(child, &args, started);
        assert!(
            matches!(o.code, None | Some(0) | Some(2)),
            "{delay_ms} ms: {:?} {}",
            o.code,
            o.stderr
        );
        let left = names(dir.path());
        assert!(
            left.iter().all(|n| !n.starts_with(".stewart-")),
            "{delay_ms} ms: {left:?}"
        );
        if let Ok(text) = std::fs::read_to_string(&out) {
            assert_eq!(
                text.lines().count(),
                1_000_001,
                "{delay_ms} ms: a partial file"
            );
        }
    }
}
