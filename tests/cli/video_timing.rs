//! Videos that play in their motion's own time wherever they are shown: the GIF's and
//! the MP4's default rates, read back from the written files.

use std::path::Path;

use crate::{probe, stderr, stdout, stewart, tempdir};

/// A GIF's frames as written, (delay in centiseconds, width × height) each, and the
/// picture's size.
fn gif_frames(path: &Path) -> (Vec<(u16, u32)>, (u16, u16)) {
    let file = std::fs::File::open(path).unwrap_or_else(|e| panic!("{e}"));
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::Indexed);
    let mut decoder = options.read_info(file).unwrap_or_else(|e| panic!("{e}"));
    let size = (decoder.width(), decoder.height());
    let mut frames = Vec::new();
    while let Some(f) = decoder.read_next_frame().unwrap_or_else(|e| panic!("{e}")) {
        frames.push((f.delay, u32::from(f.width) * u32::from(f.height)));
    }
    (frames, size)
}

/// The seed's motion: its duration in seconds, from the solved table's first and last
/// times (an independent reading of the trajectory, not the export's own arithmetic).
fn seed_duration() -> f64 {
    let o = stewart(&["solve", "--preset", "seed"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    let times: Vec<f64> = text
        .lines()
        .skip(1)
        .filter_map(|l| l.split(',').next()?.trim().parse().ok())
        .collect();
    assert!(times.len() > 100, "{text}");
    times[times.len() - 1] - times[0]
}

#[test]
fn the_default_gif_plays_the_whole_motion_in_its_own_time() {
    let dir = tempdir();
    let out = dir.path().join("seed.gif");
    let o = stewart(&[
        "render",
        "--preset",
        "seed",
        "--out",
        &out.display().to_string(),
        "--size",
        "200x120",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (frames, size) = gif_frames(&out);
    assert_eq!(size, (200, 120));
    let duration = seed_duration();
    // 25 frames a second, 4 cs each, which browsers play as written.
    assert!(frames.iter().all(|f| f.0 == 4), "delays: {frames:?}");
    assert_eq!(frames.len() as f64, (duration * 25.0).round());
    let played: f64 = frames.iter().map(|f| f64::from(f.0) / 100.0).sum();
    assert!(
        (played - duration).abs() < 1e-9,
        "{played} s for {duration} s"
    );
    // The first frame is whole; later ones carry only what changed.
    assert_eq!(frames[0].1, 200 * 120);
    let partial = frames[1..].iter().filter(|f| f.1 < 200 * 120).count();
    assert!(partial * 10 >= 9 * (frames.len() - 1), "{frames:?}");
    // The closing line says what was written and how long it plays.
    let bytes = std::fs::metadata(&out).map(|m| m.len()).unwrap_or(0);
    let said = stderr(&o);
    assert!(
        said.contains(&format!("Wrote {} frames", frames.len())),
        "{said}"
    );
    assert!(said.contains("25 frames/s, plays 10.00 s"), "{said}");
    let size = if bytes >= 1_000_000 {
        format!("{:.1} MB", bytes as f64 / 1e6)
    } else {
        format!("{} kB", bytes / 1000)
    };
    assert!(said.contains(&size), "{said} ({bytes} bytes)");
    assert!(!said.contains("Note:"), "{said}");
}

#[test]
fn a_gif_rate_too_fast_for_browsers_is_rounded_with_a_note() {
    let dir = tempdir();
    let out = dir.path().join("fast.gif");
    let o = stewart(&[
        "render",
        "--out",
        &out.display().to_string(),
        "--fps",
        "100",
        "--frames",
        "0..10",
        "--size",
        "64x48",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = stderr(&o);
    assert!(
        said.contains("Note: a GIF frame lasts a whole number of hundredths of a second, at least 2 (browsers play shorter delays as 10): 100 frames/s became 50 frames/s (2 cs a frame)"),
        "{said}"
    );
    let (frames, _) = gif_frames(&out);
    assert_eq!(frames.len(), 10);
    assert!(frames.iter().all(|f| f.0 == 2), "{frames:?}");
    // 30 frames/s is 3.33 cs: 3 cs, that is 33.33 frames/s.
    let out = dir.path().join("thirty.gif");
    let o = stewart(&[
        "render",
        "--out",
        &out.display().to_string(),
        "--fps",
        "30",
        "--frames",
        "0..4",
        "--size",
        "64x48",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("30 frames/s became 33.33 frames/s (3 cs a frame)"),
        "{}",
        stderr(&o)
    );
    assert!(gif_frames(&out).0.iter().all(|f| f.0 == 3));
}

#[test]
fn the_default_mp4_is_fifty_frames_a_second() {
    let dir = tempdir();
    let out = dir.path().join("motion.mp4");
    let o = stewart(&[
        "render",
        "--out",
        &out.display().to_string(),
        "--frames",
        "0..25",
        "--size",
        "160x96",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (text, duration) = probe(&out, "r_frame_rate", false);
    assert!(text.contains("r_frame_rate=50/1"), "{text}");
    assert!((duration - 0.5).abs() < 0.03, "{text}");
    assert!(
        stderr(&o).contains("50 frames/s, plays 0.50 s"),
        "{}",
        stderr(&o)
    );
}
