//! A whole video export (frames, GIF or MP4) as the `render` command and the viewer's
//! export panel both ask for it: which times, which camera, which colours.

use std::ops::Range;
use std::path::PathBuf;
use std::sync::atomic::AtomicBool;
use std::time::Instant;

use anyhow::{Result, bail};
use indicatif::ProgressBar;
use stewart_kinematics::Scenario;
use stewart_render::{OrbitCamera, Overlays, Theme};

use super::encode::{self, Target};
use super::frames::{FrameJob, FrameSource, default_camera};

/// What to export.
#[derive(Clone, Debug)]
pub struct VideoRequest {
    /// A folder (numbered PNG files), a `.gif` or an `.mp4`.
    pub out: PathBuf,
    /// Frame width and height, pixels.
    pub size: (u32, u32),
    /// Frames per second; `None`: one frame per trajectory sample.
    pub fps: Option<f64>,
    /// Only frames `A..B` (`None` ends: from the first, to the last).
    pub frames: (Option<usize>, Option<usize>),
    /// Colours.
    pub theme: Theme,
    /// The camera; `None`: the seed's view framing the platform.
    pub camera: Option<OrbitCamera>,
    /// Put the leg-length plot beside the 3D view.
    pub composite: bool,
    /// What to draw beyond the platform.
    pub overlays: Overlays,
    /// Burn the readout (time, pose, the six values) into the frames under this title.
    pub readout: Option<String>,
    /// The language of the readout and the composite's plot.
    pub lang: crate::i18n::Lang,
}

/// What an export did.
#[derive(Clone, Debug, PartialEq)]
pub struct VideoReport {
    /// Frames written.
    pub frames: usize,
    /// Wall time, seconds.
    pub seconds: f64,
    /// The GPU adapter in words.
    pub adapter: String,
}

/// Most frames one export may write (as many as a trajectory may have samples).
pub const MAX_FRAMES: usize = stewart_kinematics::trajectory::MAX_SAMPLES;

/// The frames of an export: how many the motion gives at the rate, and when each is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FramePlan {
    /// Frames over the whole motion.
    pub count: usize,
    /// Frames per second.
    pub fps: f64,
    /// Time of frame 0, seconds.
    start: f64,
    /// The trajectory's own sampling, when frames are its samples.
    native: Option<stewart_kinematics::Sampling>,
}

impl FramePlan {
    /// Time of frame `k`, seconds.
    pub fn time(&self, k: usize) -> f64 {
        match &self.native {
            Some(sampling) => sampling.time(k),
            None => self.start + k as f64 / self.fps,
        }
    }
}

impl VideoRequest {
    /// How many frames at which rate: the trajectory's samples, or a new rate over its
    /// duration. Nothing is allocated, whatever the duration.
    pub fn plan(&self, scenario: &Scenario) -> Result<FramePlan> {
        let sampling = scenario.motion.sampling;
        let native_fps = (sampling.len() - 1) as f64 / sampling.duration();
        let fps = self.fps.unwrap_or(native_fps);
        if !(fps.is_finite() && fps > 0.0 && fps <= 1000.0) {
            bail!(
                "the frame rate must be more than 0 and at most 1000 frames per second, got {fps}"
            );
        }
        let count = match self.fps {
            None => sampling.len(),
            // In-range durations and rates give at most about 1e9 frames: a count, not a list.
            Some(_) => ((sampling.duration() * fps).floor() + 1.0) as usize,
        };
        Ok(FramePlan {
            count,
            fps,
            start: sampling.start(),
            native: self.fps.is_none().then_some(sampling),
        })
    }

    /// The frame indices to write, checked against the number of frames.
    pub fn range(&self, count: usize) -> Result<Range<usize>> {
        let (a, b) = (self.frames.0.unwrap_or(0), self.frames.1.unwrap_or(count));
        if a >= b || b > count {
            bail!(
                "frames {a}..{b} is not a non-empty range within the {count} frames (0..{count})"
            );
        }
        if b - a > MAX_FRAMES {
            bail!(
                "frames {a}..{b} are {} frames; one export writes at most {MAX_FRAMES} (choose a range with --frames, a lower --fps or a shorter motion)",
                b - a
            );
        }
        Ok(a..b)
    }

    /// How many frames the export writes.
    pub fn frame_count(&self, scenario: &Scenario) -> Result<usize> {
        let plan = self.plan(scenario)?;
        Ok(self.range(plan.count)?.len())
    }
}

/// Render and encode `request`, counting frames on `progress`; `stop` cancels (then
/// nothing is written).
pub fn export_video(
    scenario: &Scenario,
    request: &VideoRequest,
    progress: &ProgressBar,
    stop: &AtomicBool,
) -> Result<VideoReport> {
    let plan = request.plan(scenario)?;
    let fps = plan.fps;
    let range = request.range(plan.count)?;
    // Only the exported frames' times are kept.
    let times: Vec<f64> = range.clone().map(|k| plan.time(k)).collect();
    let target = Target::from_path(&request.out);
    target.destination()?;
    if matches!(target, Target::Mp4(_)) {
        encode::check_ffmpeg()?;
    }
    if let Some(c) = &request.camera
        && !(c.distance.is_finite() && c.distance > 0.0)
    {
        bail!("the camera distance must be positive, got {}", c.distance);
    }
    let (width, height) = request.size;
    let job = FrameJob {
        first_index: range.start,
        times,
        width,
        height,
        theme: request.theme,
        camera: request.camera.unwrap_or_else(|| default_camera(scenario)),
        composite: request.composite,
        overlays: request.overlays,
        readout: request.readout.clone(),
        lang: request.lang,
    };
    let mut source = FrameSource::new(scenario, &job)?;
    progress.set_length(range.len() as u64);
    let started = Instant::now();
    encode::export(&mut source, range.clone(), fps, &target, progress, stop)?;
    Ok(VideoReport {
        frames: range.len(),
        seconds: started.elapsed().as_secs_f64(),
        adapter: source.adapter(),
    })
}
