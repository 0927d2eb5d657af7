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

use super::encode::{self, FrameSink};
use super::frames::{FrameJob, FrameSource};

/// What to export.
#[derive(Clone, Debug)]
pub(crate) struct VideoRequest {
    /// A folder (numbered PNG files), a `.gif` or an `.mp4`.
    pub(crate) out: PathBuf,
    /// Frame width and height, pixels.
    pub(crate) size: (u32, u32),
    /// Frames per second; `None`: the format's default ([`GIF_FPS`], [`MP4_FPS`], one
    /// frame per trajectory sample for a folder of frames).
    pub(crate) fps: Option<f64>,
    /// Only frames `A..B` (`None` ends: from the first, to the last).
    pub(crate) frames: (Option<usize>, Option<usize>),
    /// Colours.
    pub(crate) theme: Theme,
    /// The camera; `None`: the seed's angles, framing the whole motion of the exported
    /// frames with a margin, centred in the 3D view.
    pub(crate) camera: Option<OrbitCamera>,
    /// Put the leg-length plot beside the 3D view.
    pub(crate) composite: bool,
    /// What to draw beyond the platform.
    pub(crate) overlays: Overlays,
    /// Burn the readout (time, pose, the six values) into the frames under this title.
    pub(crate) readout: Option<String>,
    /// The language of the readout and the composite's plot.
    pub(crate) lang: crate::i18n::Lang,
    /// How fast the motion plays in the video against real time (below 1: slow motion;
    /// each second of motion lasts `1 / speed` seconds of video).
    pub(crate) speed: f64,
    /// The CAD parts drawn in place of the usual plates and legs.
    pub(crate) parts: stewart_render::appearance::parts::PartSet,
}

/// The slowest and fastest playback a video may have against real time.
pub(crate) const SPEEDS: std::ops::RangeInclusive<f64> = 0.01..=100.0;

/// What an export did.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct VideoReport {
    /// Frames written.
    pub(crate) frames: usize,
    /// Frames per second of the output.
    pub(crate) fps: f64,
    /// How long the written frames play, seconds.
    pub(crate) duration: f64,
    /// Bytes written (the file, or every frame in the folder).
    pub(crate) bytes: u64,
    /// Why the frame rate differs from the one asked for, if it does.
    pub(crate) note: Option<RateNote>,
    /// Wall time, seconds.
    pub(crate) seconds: f64,
    /// The GPU adapter in words.
    pub(crate) adapter: String,
}

/// Frames per second of a GIF unless asked otherwise: 4 centiseconds a frame, which every
/// browser and slide program plays as written, smooth enough for a platform's motion, and
/// a quarter of the frames (and bytes) of one frame per 100 Hz sample.
pub(crate) const GIF_FPS: f64 = 25.0;

/// Frames per second of an MP4 unless asked otherwise: every other sample of a 100 Hz
/// trajectory, within what 60 Hz displays, browsers and slide software play frame for
/// frame, and within H.264 level 4.2 at 1920×1080.
pub(crate) const MP4_FPS: f64 = 50.0;

/// Why an export's frame rate is not the one asked for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum RateNote {
    /// A GIF's frame delay is a whole number of centiseconds, at least
    /// [`encode::GIF_MIN_DELAY_CS`] (shorter delays play as 10 cs in browsers): the rate
    /// asked for became the nearest such rate.
    GifRounded {
        /// The rate asked for.
        asked: f64,
        /// The rate written.
        fps: f64,
        /// Each frame's delay, centiseconds.
        delay_cs: u16,
    },
}

impl std::fmt::Display for RateNote {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RateNote::GifRounded {
                asked,
                fps,
                delay_cs,
            } => write!(
                f,
                "a GIF frame lasts a whole number of hundredths of a second, at least {} (browsers play shorter delays as 10): {asked} frames/s became {} frames/s ({delay_cs} cs a frame)",
                encode::GIF_MIN_DELAY_CS,
                rate_in_words(*fps)
            ),
        }
    }
}

/// A frame rate with the decimals it needs (25, 33.33).
pub(crate) fn rate_in_words(fps: f64) -> String {
    // Two decimals, or four significant digits below 1 (0.3003, 0.01).
    let decimals = (3.0 - fps.abs().log10().floor()).clamp(2.0, 12.0) as usize;
    let text = format!("{fps:.decimals$}");
    text.trim_end_matches('0').trim_end_matches('.').to_owned()
}

/// Slowest frame rate an export may ask for: one frame per 100 s of motion.
pub(crate) const MIN_FPS: f64 = 0.01;

/// Fastest frame rate an export may ask for.
pub(crate) const MAX_FPS: f64 = 1000.0;

/// A frame rate asked for, checked: finite, from [`MIN_FPS`] to [`MAX_FPS`].
pub(crate) fn check_rate(fps: f64) -> Result<(), String> {
    if fps.is_finite() && (MIN_FPS..=MAX_FPS).contains(&fps) {
        Ok(())
    } else {
        Err(format!(
            "the frame rate must be from {MIN_FPS} to {MAX_FPS} frames per second, got {fps}"
        ))
    }
}

/// Most frames one export may write (as many as a trajectory may have samples).
pub(crate) const MAX_FRAMES: usize = stewart_kinematics::model::trajectory::MAX_SAMPLES;

/// The frames of an export: how many the motion gives at the rate, and when each is.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct FramePlan {
    /// Frames over the whole motion.
    pub(crate) count: usize,
    /// Frames per second.
    pub(crate) fps: f64,
    /// Why `fps` is not the rate asked for, if it is not.
    pub(crate) note: Option<RateNote>,
    /// Time of frame 0, seconds.
    start: f64,
    /// The motion's own sample times, when frames are its samples.
    native: Option<NativeTimes>,
    /// Seconds of motion per second of video.
    speed: f64,
}

/// A motion's own sample times: even ones (computed, nothing stored), or a table's rows.
#[derive(Clone, Debug, PartialEq)]
enum NativeTimes {
    Even(stewart_kinematics::Sampling),
    Rows(Vec<f64>),
}

impl FramePlan {
    /// Time of frame `k` in the motion, seconds.
    pub(crate) fn time(&self, k: usize) -> f64 {
        match &self.native {
            Some(NativeTimes::Even(sampling)) => sampling.time(k),
            Some(NativeTimes::Rows(times)) => {
                times.get(k).or(times.last()).copied().unwrap_or(self.start)
            }
            None => self.start + k as f64 * self.speed / self.fps,
        }
    }
}

impl VideoRequest {
    /// How many frames at which rate: the trajectory's samples, or a new rate over its
    /// duration. Nothing is allocated, whatever the duration.
    ///
    /// A GIF plays exactly the motion's duration: its frames start at the motion's start,
    /// one delay apart, and the last one is shown until the loop begins again. Other
    /// outputs end on the motion's last pose.
    pub(crate) fn plan(&self, scenario: &Scenario) -> Result<FramePlan> {
        let sampling = scenario.motion.sampling;
        let native_fps = (sampling.len() - 1) as f64 / sampling.duration();
        let target = FrameSink::from_path(&self.out);
        let speed = self.speed;
        if !SPEEDS.contains(&speed) {
            bail!(
                "a playback speed of {speed} is outside {} … {} times real time",
                SPEEDS.start(),
                SPEEDS.end()
            );
        }
        let slowed = speed != 1.0;
        let asked = self.fps.or(match target {
            FrameSink::Gif(_) => Some(GIF_FPS),
            FrameSink::Mp4(_) => Some(MP4_FPS),
            // Frames are the samples, unless the motion is slowed: then at their rate.
            FrameSink::Folder(_) => slowed.then_some(native_fps),
        });
        match (asked, self.fps) {
            // The motion's own rate, slowed into a folder of frames: say it is the motion's.
            (Some(fps), None) => check_rate(fps).map_err(|_| {
                anyhow::anyhow!(
                    "slowed to {speed}× its speed, the motion's frames would come at its own \
                     sample rate, {fps} a second, beyond what a video or folder of frames \
                     takes: give --fps"
                )
            })?,
            (Some(fps), Some(_)) => check_rate(fps).map_err(anyhow::Error::msg)?,
            (None, _) => {}
        }
        let fps = asked.unwrap_or(native_fps);
        let (fps, note) = match target {
            FrameSink::Gif(_) => {
                let delay_cs = encode::gif_delay_cs(fps);
                let played = 100.0 / f64::from(delay_cs);
                let note = ((played - fps).abs() > 1e-9 * fps).then_some(RateNote::GifRounded {
                    asked: fps,
                    fps: played,
                    delay_cs,
                });
                (played, note)
            }
            _ => (fps, None),
        };
        // In-range durations and rates give at most about 1e9 frames: a count, not a list.
        // The video's length: the motion's, stretched by the speed.
        let played = sampling.duration() / speed;
        let count = match (&target, asked) {
            (_, None) => sampling.len(),
            (FrameSink::Gif(_), Some(_)) => ((played * fps).round() as usize).max(1),
            (_, Some(_)) => ((played * fps).floor() + 1.0) as usize,
        };
        Ok(FramePlan {
            count,
            fps,
            note,
            start: sampling.start(),
            native: asked.is_none().then(|| match sampling.is_at_keys() {
                true => NativeTimes::Rows(scenario.motion.times().collect()),
                false => NativeTimes::Even(sampling),
            }),
            speed,
        })
    }

    /// The frame indices to write, checked against the number of frames.
    pub(crate) fn range(&self, count: usize) -> Result<Range<usize>> {
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
    pub(crate) fn frame_count(&self, scenario: &Scenario) -> Result<usize> {
        let plan = self.plan(scenario)?;
        Ok(self.range(plan.count)?.len())
    }
}

/// Render and encode `request`, counting frames on `progress`; `stop` cancels (then
/// nothing is written).
pub(crate) fn export_video(
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
    let target = FrameSink::from_path(&request.out);
    target.destination()?;
    if matches!(target, FrameSink::Mp4(_)) {
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
        camera: request.camera,
        composite: request.composite,
        overlays: request.overlays,
        readout: request.readout.clone(),
        lang: request.lang,
        parts: request.parts.clone(),
    };
    let mut source = FrameSource::new(scenario, &job)?;
    progress.set_length(range.len() as u64);
    let started = Instant::now();
    encode::export(&mut source, range.clone(), fps, &target, progress, stop)?;
    Ok(VideoReport {
        frames: range.len(),
        fps,
        duration: range.len() as f64 / fps,
        bytes: written_bytes(&request.out),
        note: plan.note,
        seconds: started.elapsed().as_secs_f64(),
        adapter: source.adapter(),
    })
}

/// The size of a written file, or of the files in a written folder, bytes.
fn written_bytes(out: &std::path::Path) -> u64 {
    match std::fs::metadata(out) {
        Ok(m) if m.is_dir() => std::fs::read_dir(out)
            .map(|entries| {
                entries
                    .filter_map(|e| e.ok()?.metadata().ok())
                    .map(|m| m.len())
                    .sum()
            })
            .unwrap_or(0),
        Ok(m) => m.len(),
        Err(_) => 0,
    }
}

/// A size in bytes for people: 3.4 MB, 812 kB.
pub(crate) fn bytes_in_words(bytes: u64) -> String {
    match bytes {
        b if b >= 1_000_000 => format!("{:.1} MB", b as f64 / 1e6),
        b if b >= 1_000 => format!("{} kB", b / 1_000),
        b => format!("{b} bytes"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn request(out: &str, fps: Option<f64>) -> VideoRequest {
        VideoRequest {
            out: PathBuf::from(out),
            size: (64, 48),
            fps,
            frames: (None, None),
            theme: Theme::DARK,
            camera: None,
            composite: false,
            overlays: Overlays::default(),
            readout: None,
            lang: crate::i18n::Lang::En,
            speed: 1.0,
            parts: stewart_render::appearance::parts::PartSet::none(),
        }
    }

    #[test]
    fn each_format_has_its_rate_and_a_gif_lasts_the_motion() {
        let seed = Scenario::preset("seed").unwrap_or_else(|e| panic!("{e}"));
        let samples = seed.motion.sampling.len();
        let plan = |out: &str, fps| {
            request(out, fps)
                .plan(&seed)
                .unwrap_or_else(|e| panic!("{e}"))
        };
        // The seed: 10 s sampled at 100 Hz.
        let gif = plan("a.gif", None);
        assert_eq!((gif.count, gif.fps, gif.note), (250, 25.0, None));
        assert!((gif.time(1) - gif.time(0) - 0.04).abs() < 1e-12);
        let mp4 = plan("a.mp4", None);
        assert_eq!((mp4.count, mp4.fps), (501, 50.0));
        let pngs = plan("frames", None);
        assert_eq!((pngs.count, pngs.fps), (samples, 100.0));
        // 30 frames/s is 3.33 cs: 3 cs, 33.33 frames/s, 333 frames of 3 cs (9.99 s).
        let odd = plan("a.gif", Some(30.0));
        assert_eq!(odd.count, 333);
        assert_eq!(
            odd.note,
            Some(RateNote::GifRounded {
                asked: 30.0,
                fps: 100.0 / 3.0,
                delay_cs: 3
            })
        );
        // Faster than 2 cs is rounded to 2 cs; MP4 takes any rate as asked.
        assert_eq!(plan("a.gif", Some(1000.0)).fps, 50.0);
        assert_eq!(plan("a.mp4", Some(1000.0)).note, None);
        for bad in [0.0, 0.005, 1000.5, f64::NAN, f64::INFINITY] {
            let e = request("a.gif", Some(bad)).plan(&seed);
            assert!(e.is_err(), "{bad}");
        }
    }

    #[test]
    fn slow_motion_stretches_the_video_and_keeps_the_motion_whole() {
        let seed = Scenario::preset("seed").unwrap_or_else(|e| panic!("{e}"));
        let slowed = |out: &str, fps, speed| {
            VideoRequest {
                speed,
                ..request(out, fps)
            }
            .plan(&seed)
            .unwrap_or_else(|e| panic!("{e}"))
        };
        // A quarter speed: the 10 s motion plays 40 s, 25 frames a second of video, each
        // frame 0.01 s of motion apart; the last frame is the motion's end.
        let gif = slowed("a.gif", None, 0.25);
        assert_eq!((gif.count, gif.fps), (1000, 25.0));
        assert!((gif.time(1) - gif.time(0) - 0.01).abs() < 1e-12);
        let mp4 = slowed("a.mp4", None, 0.25);
        assert_eq!(mp4.count, 2001);
        assert!((mp4.time(2000) - 10.0).abs() < 1e-9, "{}", mp4.time(2000));
        // Frames of a folder at the samples' rate, slowed: four frames a sample.
        let pngs = slowed("frames", None, 0.25);
        assert_eq!((pngs.count, pngs.fps), (4001, 100.0));
        // Twice as fast: half the frames.
        assert_eq!(slowed("a.mp4", None, 2.0).count, 251);
        // Real time is the plan without speed, frame for frame.
        assert_eq!(
            slowed("frames", None, 1.0),
            request("frames", None)
                .plan(&seed)
                .unwrap_or_else(|e| panic!("{e}"))
        );
        for bad in [0.0, 0.001, 101.0, f64::NAN, -1.0] {
            let e = VideoRequest {
                speed: bad,
                ..request("a.gif", None)
            }
            .plan(&seed);
            assert!(e.is_err(), "{bad}");
        }
    }

    #[test]
    fn rates_and_sizes_read_as_people_write_them() {
        for (fps, words) in [
            (25.0, "25"),
            (100.0 / 3.0, "33.33"),
            (0.5, "0.5"),
            (100.0 / 333.0, "0.3003"),
            (0.01, "0.01"),
        ] {
            assert_eq!(rate_in_words(fps), words);
        }
        assert_eq!(bytes_in_words(999), "999 bytes");
        assert_eq!(bytes_in_words(812_400), "812 kB");
        assert_eq!(bytes_in_words(8_812_400), "8.8 MB");
    }
}
