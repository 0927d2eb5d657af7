//! `stewart render`: frames, GIF and MP4 of a trajectory, with no display.

use std::process::ExitCode;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use anyhow::{Result, bail};
use indicatif::{ProgressBar, ProgressStyle};
use stewart_render::{OrbitCamera, Overlays, Theme};

use crate::cli::{RenderArgs, ThemeName};
use crate::export::encode::{self, Target};
use crate::export::frames::{FrameJob, FrameSource, default_camera};
use crate::source;

/// Run the command.
pub fn run(args: &RenderArgs) -> Result<ExitCode> {
    let scenario = source::load(&args.scenario)?;
    let sampling = scenario.motion.sampling;
    let native_fps = (sampling.len() - 1) as f64 / sampling.duration();
    let fps = args.fps.unwrap_or(native_fps);
    if !(fps.is_finite() && fps > 0.0 && fps <= 1000.0) {
        bail!("--fps must be a number of frames per second between 0 and 1000, got {fps}");
    }
    let times: Vec<f64> = match args.fps {
        None => sampling.times().collect(),
        Some(_) => {
            let n = (sampling.duration() * fps).floor() as usize + 1;
            (0..n).map(|k| sampling.start() + k as f64 / fps).collect()
        }
    };
    let (a, b) = args.frames.unwrap_or((None, None));
    let (a, b) = (a.unwrap_or(0), b.unwrap_or(times.len()));
    if a >= b || b > times.len() {
        bail!(
            "--frames {a}..{b} is not a non-empty range within the {} frames (0..{})",
            times.len(),
            times.len()
        );
    }
    let target = Target::from_path(&args.out);
    if matches!(target, Target::Mp4(_)) {
        encode::check_ffmpeg()?;
    }
    let camera = match args.camera {
        Some([az, el, dist]) => {
            if dist <= 0.0 {
                bail!("--camera distance must be positive, got {dist}");
            }
            OrbitCamera {
                azimuth_deg: az as f32,
                elevation_deg: el as f32,
                distance: dist as f32,
                ..default_camera(&scenario)
            }
        }
        None => default_camera(&scenario),
    };
    let theme = match args.theme {
        ThemeName::Dark => Theme::DARK,
        ThemeName::Light => Theme::LIGHT,
    };
    let (width, height) = args.size;
    let job = FrameJob {
        times,
        width,
        height,
        theme,
        camera,
        composite: args.composite,
        overlays: Overlays {
            platform_axes: args.platform_axes,
            ..Overlays::default()
        },
    };
    let mut source = FrameSource::new(&scenario, &job)?;
    let progress = ProgressBar::new((b - a) as u64);
    progress.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} frames  {per_sec}  {eta} left")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    // Ctrl-C stops the export cleanly: staged files are removed, nothing is half-written.
    let stop = Arc::new(AtomicBool::new(false));
    let flag = Arc::clone(&stop);
    // A handler may already be installed (a second export in one process): then Ctrl-C
    // keeps its default meaning, which also leaves no output behind.
    let _ = ctrlc::set_handler(move || flag.store(true, Ordering::Relaxed));
    let started = Instant::now();
    let result = encode::export(&mut source, a..b, fps, &target, &progress, &stop);
    if result.is_err() {
        progress.abandon();
    }
    result?;
    progress.finish_and_clear();
    let seconds = started.elapsed().as_secs_f64();
    eprintln!(
        "Wrote {} frames of {width}×{height} to {} in {seconds:.1} s ({:.1} frames/s) on {}.",
        b - a,
        args.out.display(),
        (b - a) as f64 / seconds,
        source.adapter()
    );
    Ok(ExitCode::SUCCESS)
}
