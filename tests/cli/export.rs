//! `stewart render` and `stewart plot`: files a person would open, checked as such.

use std::path::Path;
use std::process::Command;

use crate::{probe, stderr, stdout, stewart, tempdir};

fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .map(|d| {
            d.filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}

/// `stewart render --out OUT --frames 0..2` with extra environment variables.
fn render_two_frames_with_env(
    out: &Path,
    env: &[(&str, &std::ffi::OsStr)],
) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_stewart-e2e"))
        .args([
            "render",
            "--out",
            &out.display().to_string(),
            "--frames",
            "0..2",
        ])
        .envs(env.iter().copied())
        .output()
        .unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn a_png_sequence_has_the_right_count_names_and_size() {
    let dir = tempdir();
    let out = dir.path().join("frames");
    let o = stewart(&[
        "render",
        "--out",
        &out.display().to_string(),
        "--frames",
        "10..25",
        "--size",
        "200x120",
        "--theme",
        "light",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let files = names(&out);
    assert_eq!(files.len(), 15);
    assert_eq!(files[0], "frame_00010.png");
    assert_eq!(files[14], "frame_00024.png");
    for f in &files {
        let img = image::open(out.join(f)).unwrap_or_else(|e| panic!("{f}: {e}"));
        assert_eq!((img.width(), img.height()), (200, 120));
    }
    // Light theme: white corners; and consecutive frames differ (the platform moves).
    let a = image::open(out.join(&files[0]))
        .map(|i| i.to_rgba8())
        .unwrap_or_default();
    let b = image::open(out.join(&files[14]))
        .map(|i| i.to_rgba8())
        .unwrap_or_default();
    assert_eq!(a.get_pixel(0, 0).0, [255, 255, 255, 255]);
    assert_ne!(a.as_raw(), b.as_raw());
    // Only the folder was created: no staging leftovers.
    assert_eq!(names(dir.path()), ["frames"]);
    // Rendering again into the now non-empty folder is refused, and it is left as it was.
    let o = stewart(&[
        "render",
        "--out",
        &out.display().to_string(),
        "--frames",
        "0..2",
        "--size",
        "200x120",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("is not an empty folder"),
        "{}",
        stderr(&o)
    );
    assert_eq!(names(&out).len(), 15);
}

#[test]
fn a_gif_has_every_frame_at_the_frame_rate() {
    let dir = tempdir();
    let out = dir.path().join("motion.gif");
    let o = stewart(&[
        "render",
        "--out",
        &out.display().to_string(),
        "--fps",
        "20",
        "--frames",
        "0..12",
        "--size",
        "160x100",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let file = std::fs::File::open(&out).unwrap_or_else(|e| panic!("{e}"));
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::RGBA);
    let mut decoder = options.read_info(file).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!((decoder.width(), decoder.height()), (160, 100));
    let mut count = 0;
    while let Some(frame) = decoder.read_next_frame().unwrap_or_else(|e| panic!("{e}")) {
        assert_eq!(frame.delay, 5, "20 frames/s is 5 centiseconds a frame");
        count += 1;
    }
    assert_eq!(count, 12);
}

#[test]
fn an_mp4_has_its_frames_and_duration() {
    let dir = tempdir();
    let out = dir.path().join("motion.mp4");
    let o = stewart(&[
        "render",
        "--out",
        &out.display().to_string(),
        "--fps",
        "25",
        "--frames",
        "0..50",
        "--size",
        "320x180",
        "--composite",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (text, duration) = probe(&out, "nb_read_frames,width,height,codec_name", true);
    assert!(text.contains("codec_name=h264"), "{text}");
    assert!(
        text.contains("width=320") && text.contains("height=180"),
        "{text}"
    );
    assert!(text.contains("nb_read_frames=50"), "{text}");
    assert!((duration - 2.0).abs() < 0.05, "{text}");
}

#[test]
fn mp4_without_ffmpeg_says_how_to_install_it() {
    let dir = tempdir();
    let out = dir.path().join("motion.mp4");
    let o = render_two_frames_with_env(&out, &[("PATH", dir.path().as_os_str())]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("apt-get install ffmpeg"));
    assert!(!out.exists());
}

/// `--speed 0.25`: the motion in slow motion, four times the frames over the same motion.
#[test]
fn slow_motion_plays_the_motion_four_times_longer() {
    let dir = tempdir();
    let out = dir.path().join("slow.gif");
    let o = stewart(&[
        "render",
        "--out",
        &out.display().to_string(),
        "--fps",
        "20",
        "--speed",
        "0.25",
        "--frames",
        "0..8",
        "--size",
        "160x100",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    // 8 frames of 5 cs: 0.4 s of video, 0.1 s of motion.
    let said = format!("{}{}", stdout(&o), stderr(&o));
    assert!(said.contains("Wrote 8 frames"), "{said}");
    // The whole 10 s motion would be 40 s: 800 frames at 20 frames/s.
    let o = stewart(&[
        "render",
        "--out",
        &out.display().to_string(),
        "--fps",
        "20",
        "--speed",
        "0.25",
        "--frames",
        "799..801",
        "--size",
        "160x100",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("within the 800 frames"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn bad_render_options_are_refused() {
    let dir = tempdir();
    let long = "x".repeat(201);
    let out = dir.path().join("x.gif").display().to_string();
    for (args, expected) in [
        (vec!["--size", "10x10"], "outside 16..=4096"),
        (vec!["--size", "big"], "not a size"),
        (vec!["--frames", "5..3"], "not a non-empty range"),
        (vec!["--frames", "0..99999"], "not a non-empty range"),
        (
            vec!["--fps", "0"],
            "frame rate must be from 0.01 to 1000 frames per second, got 0",
        ),
        (
            vec!["--fps", "0.001"],
            "frame rate must be from 0.01 to 1000 frames per second, got 0.001",
        ),
        (
            vec!["--fps", "1e-300"],
            "frame rate must be from 0.01 to 1000 frames per second, got 1e-300",
        ),
        (
            vec!["--title", "two\nlines"],
            "without control characters (found U+000A)",
        ),
        (vec!["--title", &long], "at most 200 fit a line"),
        (
            vec!["--speed", "0"],
            "is not a playback speed from 0.01 to 100",
        ),
        (
            vec!["--speed", "-1"],
            "is not a playback speed from 0.01 to 100",
        ),
        (
            vec!["--speed", "NaN"],
            "is not a playback speed from 0.01 to 100",
        ),
    ] {
        let mut all = vec!["render", "--out", &out];
        all.extend(args);
        let o = stewart(&all);
        assert_eq!(o.status.code(), Some(2), "{all:?}");
        assert!(stderr(&o).contains(expected), "{}", stderr(&o));
    }
    assert!(names(dir.path()).is_empty(), "{:?}", names(dir.path()));
}

#[test]
fn the_plot_is_real_svg_pdf_and_png() {
    let dir = tempdir();
    let svg = dir.path().join("legs.svg");
    let o = stewart(&[
        "plot",
        "--preset",
        "paired",
        "--out",
        &svg.display().to_string(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&svg).unwrap_or_default();
    let tree = resvg::usvg::Tree::from_str(&text, &resvg::usvg::Options::default())
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(tree.size().width() > 500.0);
    for leg in 1..=6 {
        assert_eq!(text.matches(&format!(r#"class="leg L{leg}""#)).count(), 1);
    }
    assert!(
        text.contains("<text") && text.contains("Leg length L (m)") && text.contains("Time t (s)")
    );
    assert_eq!(
        text.matches("stroke-dasharray").count(),
        2,
        "both stroke limits"
    );
    assert!(
        !text.contains("<image"),
        "vector output must not embed a bitmap"
    );

    let pdf = dir.path().join("legs.pdf");
    let o = stewart(&[
        "plot",
        "--preset",
        "paired",
        "--out",
        &pdf.display().to_string(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let bytes = std::fs::read(&pdf).unwrap_or_default();
    assert!(bytes.starts_with(b"%PDF-"));
    let raster = dir.path().join("page");
    let r = Command::new("pdftoppm")
        .args(["-png", "-r", "50", "-singlefile"])
        .arg(&pdf)
        .arg(&raster)
        .output()
        .unwrap_or_else(|e| panic!("pdftoppm: {e}"));
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    let page = image::open(dir.path().join("page.png"))
        .map(|i| i.to_rgb8())
        .unwrap_or_else(|e| panic!("{e}"));
    let coloured = page
        .pixels()
        .filter(|p| p.0.iter().max().unwrap_or(&0) - p.0.iter().min().unwrap_or(&0) > 60)
        .count();
    assert!(
        coloured > 200,
        "the PDF page shows the coloured curves ({coloured} pixels)"
    );

    let png = dir.path().join("legs.png");
    let o = stewart(&["plot", "--out", &png.display().to_string()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let img = image::open(&png).unwrap_or_else(|e| panic!("{e}"));
    assert!(img.width() >= 1800, "about 300 dpi for a 16 cm figure");

    let o = stewart(&[
        "plot",
        "--out",
        &dir.path().join("legs.txt").display().to_string(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("must end in .svg, .pdf or .png"));
}

#[test]
fn an_interrupted_export_leaves_nothing_behind() {
    let dir = tempdir();
    let out = dir.path().join("long.gif");
    let child = Command::new(env!("CARGO_BIN_EXE_stewart-e2e"))
        .args([
            "render",
            "--out",
            &out.display().to_string(),
            "--size",
            "640x360",
        ])
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("{e}"));
    // Wait until the export has staged its file (the Ctrl-C handler is in place by then)
    // and written frames into it, then press Ctrl-C mid-encoding.
    let encoding = || {
        std::fs::read_dir(dir.path())
            .into_iter()
            .flatten()
            .flatten()
            .any(|e| e.metadata().is_ok_and(|m| m.len() > 0))
    };
    let started = std::time::Instant::now();
    while !encoding() && started.elapsed().as_secs() < 60 {
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    assert!(encoding(), "the export never started");
    let killed = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .map(|s| s.success());
    assert_eq!(killed.ok(), Some(true));
    let o = child.wait_with_output().unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        o.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(
        String::from_utf8_lossy(&o.stderr).contains("interrupted"),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(
        names(dir.path()).is_empty(),
        "left behind: {:?}",
        names(dir.path())
    );
}

#[test]
fn a_4k_frame_renders() {
    let dir = tempdir();
    let out = dir.path().join("uhd");
    let o = stewart(&[
        "render",
        "--out",
        &out.display().to_string(),
        "--frames",
        "0..1",
        "--size",
        "3840x2160",
        "--platform-axes",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let img = image::open(out.join("frame_00000.png")).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!((img.width(), img.height()), (3840, 2160));
    // The same picture, not just the same size: scaled down, the 4K frame matches the
    // 1280×720 frame of the same pose (edges are rasterised differently; the scene is not).
    let small = dir.path().join("hd");
    let o = stewart(&[
        "render",
        "--out",
        &small.display().to_string(),
        "--frames",
        "0..1",
        "--size",
        "1280x720",
        "--platform-axes",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let hd = image::open(small.join("frame_00000.png"))
        .unwrap_or_else(|e| panic!("{e}"))
        .to_rgba8();
    let down = image::imageops::resize(
        &img.to_rgba8(),
        1280,
        720,
        image::imageops::FilterType::Triangle,
    );
    let (mut total, mut far) = (0u64, 0usize);
    for (p, q) in hd.pixels().zip(down.pixels()) {
        let d = (0..3)
            .map(|k| (i32::from(p[k]) - i32::from(q[k])).unsigned_abs())
            .max()
            .unwrap_or(0);
        total += u64::from(d);
        far += usize::from(d > 64);
    }
    let n = (1280 * 720) as f64;
    let mean = total as f64 / n;
    assert!(mean < 4.0, "mean difference {mean:.2} of 255");
    assert!(
        (far as f64) < 0.01 * n,
        "{far} pixels differ by more than 64"
    );
    // And the 4K frame is not blank: the background does not fill it.
    let bg = hd.get_pixel(0, 0);
    let drawn = hd.pixels().filter(|p| *p != bg).count();
    assert!(drawn as f64 > 0.1 * n, "only {drawn} pixels drawn");
}

#[test]
fn no_adapter_is_one_clear_error() {
    let dir = tempdir();
    let out = dir.path().join("frames");
    let no_driver = dir.path().join("none.json");
    let o = render_two_frames_with_env(
        &out,
        &[
            ("VK_ICD_FILENAMES", no_driver.as_os_str()),
            ("WGPU_BACKEND", "vulkan".as_ref()),
        ],
    );
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("no graphics adapter found") && err.contains("mesa-vulkan-drivers"),
        "{err}"
    );
    assert!(!out.exists());
    let o = render_two_frames_with_env(&out, &[("WGPU_ADAPTER_NAME", "no-such-gpu".as_ref())]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("WGPU_ADAPTER_NAME is `no-such-gpu`"));
}

#[test]
fn the_overlay_burns_the_readout_into_the_top_left_corner_at_any_size() {
    let dir = tempdir();
    for size in ["1280x720", "3840x2160"] {
        let frame = |name: &str, extra: &[&str]| {
            let out = dir.path().join(format!("{name}-{size}"));
            let o = stewart(
                &[
                    &[
                        "render",
                        "--preset",
                        "servo-desk",
                        "--out",
                        &out.display().to_string(),
                        "--frames",
                        "40..41",
                        "--size",
                        size,
                        // One camera for both (by default a readout moves the framing
                        // down, out of its way).
                        "--camera",
                        "135,20,0.6",
                    ][..],
                    extra,
                ]
                .concat(),
            );
            assert!(o.status.success(), "{}", stderr(&o));
            image::open(out.join("frame_00040.png"))
                .unwrap_or_else(|e| panic!("{e}"))
                .to_rgba8()
        };
        let plain = frame("plain", &[]);
        // A Latin title at 720p, a Chinese one at 4K (drawn with the system's Chinese font).
        let title = if size == "1280x720" {
            "Defense demo"
        } else {
            "斯图尔特平台 答辩演示"
        };
        let with = frame("overlay", &["--title", title]);
        let (w, h) = plain.dimensions();
        // Changed pixels, as fractions of the corner (a third wide, a quarter high) and of
        // the rest: the readout is there, and only there.
        let (mut corner, mut rest) = (0usize, 0usize);
        for (x, y, p) in plain.enumerate_pixels() {
            if p != with.get_pixel(x, y) {
                if x < w / 3 && y < h / 4 {
                    corner += 1;
                } else {
                    rest += 1;
                }
            }
        }
        let corner_share = corner as f64 / f64::from(w / 3 * (h / 4));
        assert!(
            corner_share > 0.04,
            "{size}: only {corner_share:.3} of the corner changed"
        );
        assert!(
            rest == 0,
            "{size}: {rest} pixels changed outside the corner"
        );
    }
}

/// A refused `--size` is one line that starts `error:` like every other error (it once
/// read `Error:`), and nothing is written.
#[test]
fn a_refused_size_is_one_lowercase_error_line() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let out = dir.path().join("x.gif");
    let out_text = out.display().to_string();
    for size in ["5x5", "99999x10", "abc"] {
        let o = stewart(&[
            "render", "--preset", "seed", "--size", size, "--out", &out_text,
        ]);
        let text = String::from_utf8_lossy(&o.stderr).into_owned();
        let lines: Vec<&str> = text
            .lines()
            .filter(|l| !l.contains("XDG_RUNTIME_DIR"))
            .collect();
        assert_eq!(o.status.code(), Some(2), "{text}");
        assert_eq!(lines.len(), 1, "{text}");
        assert!(
            lines[0].starts_with("error: ") && lines[0].contains(size),
            "{text}"
        );
        assert!(!out.exists());
    }
}
