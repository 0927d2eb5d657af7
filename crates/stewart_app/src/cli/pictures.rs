//! The picture commands' arguments (`render`, `plot`, `view`) and the values they take:
//! sizes, frame rates and ranges, playback speeds, titles, languages.

use std::path::PathBuf;

use clap::{Args, ValueEnum};

use super::values::parse_camera;
use super::{ArgError, ScenarioArgs};
use crate::i18n::Lang;
use crate::shot_scale::ShotScale;

/// A frame rate: from 0.01 to 1000 frames per second.
pub(crate) fn parse_fps(text: &str) -> Result<f64, ArgError> {
    let v: f64 = text
        .trim()
        .parse()
        .map_err(|_| ArgError::not_a(text, "a number of frames per second"))?;
    crate::export::video::check_rate(v)
        .map(|()| v)
        .map_err(|_| {
            ArgError::out_of_range(
                Some("the frame rate"),
                "from 0.01 to 1000 frames per second",
                text,
            )
        })
}

/// The smallest frame or window side, pixels.
pub(crate) const MIN_SIDE: u32 = 16;

/// The longest title a readout takes, characters.
pub(crate) const MAX_TITLE_CHARS: usize = 200;

/// A title for the readout: one line of at most [`MAX_TITLE_CHARS`] characters.
pub(crate) fn parse_title(text: &str) -> Result<String, ArgError> {
    let n = text.chars().count();
    if n > MAX_TITLE_CHARS {
        return Err(ArgError::LongTitle {
            chars: n,
            max: MAX_TITLE_CHARS,
        });
    }
    if let Some(c) = text.chars().find(|c| c.is_control()) {
        return Err(ArgError::TitleControl { found: c });
    }
    Ok(text.to_owned())
}

/// A language code: `zh` or `en` (`zh-CN`, `zh_CN` and any case accepted).
pub(crate) fn parse_lang(text: &str) -> Result<Lang, ArgError> {
    let code = text.trim().to_ascii_lowercase();
    match code.split(['-', '_', '.']).next() {
        Some("zh") => Ok(Lang::Zh),
        Some("en") => Ok(Lang::En),
        _ => Err(ArgError::not_a(
            text,
            "a language this program speaks: zh (Simplified Chinese) or en (English)",
        )),
    }
}

/// `WxH`, such as `1280x720`.
pub(crate) fn parse_size(text: &str) -> Result<(u32, u32), ArgError> {
    let (w, h) = text
        .split_once(['x', 'X', '×'])
        .ok_or_else(|| ArgError::not_a(text, "a size like 1280x720"))?;
    let side = |s: &str| -> Result<u32, ArgError> {
        let v: u32 = s
            .trim()
            .parse()
            .map_err(|_| ArgError::not_a(s, "a whole number of pixels"))?;
        let max = stewart_render::offscreen::MAX_SIDE;
        if (MIN_SIDE..=max).contains(&v) {
            Ok(v)
        } else {
            Err(ArgError::Pixels {
                got: v,
                min: MIN_SIDE,
                max,
            })
        }
    };
    Ok((side(w)?, side(h)?))
}

/// A playback speed against real time, within [`crate::export::video::SPEEDS`].
pub(crate) fn parse_speed(text: &str) -> Result<f64, ArgError> {
    let speeds = crate::export::video::SPEEDS;
    match text.trim().parse::<f64>() {
        Ok(x) if speeds.contains(&x) => Ok(x),
        _ => Err(ArgError::not_a(
            text,
            format!(
                "a playback speed from {} to {} (times real time)",
                speeds.start(),
                speeds.end()
            ),
        )),
    }
}

/// `A..B`, `A..` or `..B`: frame indices from A (default 0) up to, not including, B.
pub(crate) fn parse_frames(text: &str) -> Result<(Option<usize>, Option<usize>), ArgError> {
    let (a, b) = text
        .split_once("..")
        .ok_or_else(|| ArgError::not_a(text, "a range like 0..100"))?;
    let index = |s: &str| -> Result<Option<usize>, ArgError> {
        if s.trim().is_empty() {
            Ok(None)
        } else {
            s.trim()
                .parse()
                .map(Some)
                .map_err(|_| ArgError::not_a(s, "a frame number"))
        }
    };
    Ok((index(a)?, index(b)?))
}

/// Arguments of `stewart render`.
#[derive(Debug, Args)]
pub(crate) struct RenderArgs {
    /// The scenario: a preset or a file.
    #[command(flatten)]
    pub(crate) scenario: ScenarioArgs,
    /// A folder (numbered PNG files), a `.gif` or an `.mp4`; or a `.glb` (or `.gltf`, its
    /// buffer in a `.bin` beside it): the whole trajectory as an animated glTF 2.0 scene
    /// for slides, Blender and web pages (only `--theme` and `--single-colour` apply).
    #[arg(long, value_name = "OUT")]
    pub(crate) out: PathBuf,
    /// Frame size WxH in pixels (up to 3840x2160 and beyond, 4096 a side at most).
    #[arg(long, allow_hyphen_values = true, value_name = "WxH", value_parser = parse_size, default_value = "1280x720")]
    pub(crate) size: (u32, u32),
    /// Frames per second of the output, the motion resampled (default: 25 for a GIF, 50
    /// for an MP4, one frame per trajectory sample for a folder of frames). A GIF's
    /// frame lasts whole hundredths of a second, at least 2: other rates are rounded
    /// to the nearest such one, with a note.
    #[arg(long, value_name = "N", value_parser = parse_fps, allow_hyphen_values = true)]
    pub(crate) fps: Option<f64>,
    /// Only frames A..B (indices, B excluded).
    #[arg(long, value_name = "A..B", value_parser = parse_frames, allow_hyphen_values = true)]
    pub(crate) frames: Option<(Option<usize>, Option<usize>)>,
    /// How fast the motion plays against real time: 0.25 is slow motion (each second of
    /// motion lasts four seconds of video), 2 twice as fast (0.01 to 100; default 1).
    #[arg(long, value_name = "X", value_parser = parse_speed, allow_hyphen_values = true, default_value = "1")]
    pub(crate) speed: f64,
    /// Colours: `dark` for the screen, `light` for slides and papers.
    #[arg(long, value_enum, default_value_t = ThemeName::Dark)]
    pub(crate) theme: ThemeName,
    /// Camera AZ,EL,DIST (degrees, degrees, metres); default: the seed's view framing the platform.
    #[arg(long, value_name = "AZ,EL,DIST", value_parser = parse_camera, allow_hyphen_values = true)]
    pub(crate) camera: Option<[f64; 3]>,
    /// Put the leg-length plot beside the 3D view, with a marker at the frame's time.
    #[arg(long)]
    pub(crate) composite: bool,
    /// Draw the platform's own axes at its centre.
    #[arg(long)]
    pub(crate) platform_axes: bool,
    /// Draw every leg in one colour (by default each leg takes the colour of its curve
    /// in the plot).
    #[arg(long)]
    pub(crate) single_colour: bool,
    /// Leave out the numbered labels (L1…L6, S1…S6) beside the legs.
    #[arg(long)]
    pub(crate) no_labels: bool,
    /// Burn a readout into the frames: a title, the time, the pose and the six leg
    /// lengths or servo angles, top left.
    #[arg(long)]
    pub(crate) overlay: bool,
    /// The readout's title line (default: the scenario's name); implies --overlay.
    #[arg(long, value_name = "TEXT", value_parser = parse_title)]
    pub(crate) title: Option<String>,
    /// The language of the words drawn: `zh` (Simplified Chinese) or `en` (default: the
    /// environment's, Chinese for LANG=zh_CN.UTF-8).
    #[arg(long, value_name = "zh|en", value_parser = parse_lang)]
    pub(crate) lang: Option<Lang>,
}

/// The colour themes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum ThemeName {
    /// Dark background.
    Dark,
    /// White background (presentation).
    Light,
}

/// Arguments of `stewart plot`.
#[derive(Debug, Args)]
pub(crate) struct PlotArgs {
    /// The scenario: a preset or a file.
    #[command(flatten)]
    pub(crate) scenario: ScenarioArgs,
    /// `.svg`, `.pdf` or `.png`.
    #[arg(long, value_name = "FILE")]
    pub(crate) out: PathBuf,
    /// The language of the words drawn: `zh` (Simplified Chinese) or `en` (default: the
    /// environment's, Chinese for LANG=zh_CN.UTF-8).
    #[arg(long, value_name = "zh|en", value_parser = parse_lang)]
    pub(crate) lang: Option<Lang>,
    /// Plot the actuator forces (servo torques) the scenario's `[payload]` needs along the
    /// motion — weight, inertia, and the legs' parts and friction of `[dynamics]` —
    /// instead of the lengths (angles).
    #[arg(long)]
    pub(crate) forces: bool,
}

/// Arguments of `stewart view`.
#[derive(Debug, Args)]
pub(crate) struct ViewArgs {
    /// The scenario: a preset or a file.
    #[command(flatten)]
    pub(crate) scenario: ScenarioArgs,
    /// Start in the light theme.
    #[arg(long)]
    pub(crate) light: bool,
    /// Start in presentation mode (light colours, large text, control panels hidden).
    #[arg(long)]
    pub(crate) presentation: bool,
    /// Start with every collapsible section of the panels open.
    #[arg(long)]
    pub(crate) expand_panels: bool,
    /// Show the reachable workspace (surface and conditioning slice) from the start.
    #[arg(long)]
    pub(crate) workspace: bool,
    /// Window size WxH in logical pixels (default: the last session's within the screen,
    /// else 85 % of the screen).
    #[arg(long, allow_hyphen_values = true, value_name = "WxH", value_parser = parse_size)]
    pub(crate) size: Option<(u32, u32)>,
    /// Start without the saved session (the last scenario, camera, panels, theme and
    /// window size); it is still saved at exit.
    #[arg(long)]
    pub(crate) fresh: bool,
    /// The interface's language: `zh` (Simplified Chinese) or `en` (default: the last
    /// session's, else the environment's, Chinese for LANG=zh_CN.UTF-8).
    #[arg(long, value_name = "zh|en", value_parser = parse_lang)]
    pub(crate) lang: Option<Lang>,
    /// Save the window's image here after `--frames` frames, then exit.
    #[arg(long, value_name = "FILE.png")]
    pub(crate) screenshot: Option<PathBuf>,
    /// Frames to draw before the screenshot.
    #[arg(long, default_value_t = 10, value_parser = clap::value_parser!(u32).range(1..=100_000), allow_hyphen_values = true)]
    pub(crate) frames: u32,
    /// The screenshot's size: `1` as on screen, `2` twice that (text drawn anew, not
    /// upscaled), `4k` 3840 pixels wide.
    #[arg(long, value_name = "1|2|4k", default_value = "1", value_parser = parse_shot_scale, requires = "screenshot")]
    pub(crate) screenshot_scale: ShotScale,
    /// With --screenshot: start from the saved session (a screenshot run otherwise neither
    /// reads nor writes it, so that it does not depend on leftover state).
    #[arg(long, requires = "screenshot", conflicts_with = "fresh")]
    pub(crate) from_session: bool,
    /// Print frame-time statistics (CPU part and total) when the window closes.
    #[arg(long)]
    pub(crate) frame_stats: bool,
}

/// A screenshot scale as the command line takes it: `1`, `2` or `4k`.
pub(crate) fn parse_shot_scale(text: &str) -> Result<ShotScale, ArgError> {
    match text.trim().to_ascii_lowercase().as_str() {
        "1" | "1x" => Ok(ShotScale::One),
        "2" | "2x" => Ok(ShotScale::Two),
        "4k" => Ok(ShotScale::Uhd),
        _ => Err(ArgError::not_a(text, "a screenshot scale: 1, 2 or 4k")),
    }
}
