//! Screenshots from the viewer (the *Screenshot* menu and F12): the 3D view alone at 1×,
//! 2× or 4K, on the theme's background or transparent (for slides), rendered off screen
//! on a thread of its own so that playback goes on; or the whole window as it is on
//! screen.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use stewart_render::{DrawList, Offscreen, OrbitCamera, Theme};

use crate::i18n::Lang;
use crate::viewer::error::ActionStatus;
use crate::viewer::error::ViewerError;
use crate::viewer::tools::job::Job;

/// What to capture.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ShotKind {
    /// The 3D view alone, rendered again at the chosen size.
    View,
    /// The whole window, as on screen.
    Window,
}

pub(crate) use crate::shot_scale::ShotScale;

/// How long a saved shot's line stays in sight.
pub(crate) const SAID_FOR: std::time::Duration = std::time::Duration::from_secs(8);

/// The Screenshot menu's choices and the shot in progress.
pub(crate) struct Shots {
    /// 3D view or whole window.
    pub(crate) kind: ShotKind,
    /// The 3D view's size.
    pub(crate) scale: ShotScale,
    /// A transparent background (3D view only).
    pub(crate) transparent: bool,
    /// Where the last shot went or why it failed.
    pub(crate) status: ActionStatus,
    /// When that was said (a success is shown for [`SAID_FOR`], then goes).
    said_at: Option<std::time::Instant>,
    /// A whole-window shot the window is to take at its next frame.
    pub(crate) window_request: Option<(PathBuf, ShotScale)>,
    /// The folder shots are saved in (the current folder).
    pub(crate) folder: PathBuf,
    job: Job<ActionStatus>,
    /// The language of the outcome's words.
    lang: Lang,
}

impl Default for Shots {
    fn default() -> Self {
        Self {
            kind: ShotKind::View,
            scale: ShotScale::One,
            transparent: false,
            status: None,
            said_at: None,
            window_request: None,
            folder: PathBuf::from("."),
            job: Job::new("stewart-screenshot"),
            lang: Lang::En,
        }
    }
}

/// The first `NAME-shot-NN.png` in `folder` that does not exist yet, as an absolute path.
pub(crate) fn next_path(folder: &Path, name: &str) -> PathBuf {
    // Absolute, so that the message saying where the shot went needs no guessing.
    let folder = std::path::absolute(folder).unwrap_or_else(|_| folder.to_path_buf());
    let stem: String = name
        .chars()
        .map(|c| {
            if c.is_alphanumeric() || c == '-' {
                c
            } else {
                '_'
            }
        })
        .collect();
    (1..10_000)
        .map(|k| folder.join(format!("{stem}-shot-{k:02}.png")))
        .find(|p| !p.exists())
        .unwrap_or_else(|| folder.join(format!("{stem}-shot.png")))
}

impl Shots {
    /// Whether a shot is being rendered.
    pub(crate) fn busy(&self) -> bool {
        self.job.busy() || self.window_request.is_some()
    }

    /// Render `list` seen by `camera` in `theme` into a PNG at `path` on a thread of its
    /// own, `size` pixels; the outcome shows in `status` once [`Shots::poll`] collects it.
    pub(crate) fn start_view(
        &mut self,
        list: DrawList,
        camera: OrbitCamera,
        theme: Theme,
        size: (u32, u32),
        path: PathBuf,
        lang: Lang,
    ) {
        let transparent = self.transparent;
        self.lang = lang;
        self.job.start(move |worker| {
            worker.send(Some(render_view(
                &list,
                camera,
                theme,
                transparent,
                size,
                &path,
                lang,
            )));
        });
    }

    /// Collect a finished shot.
    pub(crate) fn poll(&mut self) {
        match self.job.poll() {
            Some(Ok(status)) => self.say(status),
            Some(Err(e)) => self.say(Some(Err(e.into()))),
            None => {}
        }
        // A success is said for a while, not for the rest of the session.
        if matches!(self.status, Some(Ok(_)))
            && self.said_at.is_some_and(|at| at.elapsed() >= SAID_FOR)
        {
            self.status = None;
        }
    }

    /// Say `status` (where a shot went, or why it failed), from now.
    pub(crate) fn say(&mut self, status: ActionStatus) {
        self.status = status;
        self.said_at = Some(std::time::Instant::now());
    }
}

/// Render and write one 3D-view shot.
pub(crate) fn render_view(
    list: &DrawList,
    camera: OrbitCamera,
    theme: Theme,
    transparent: bool,
    (w, h): (u32, u32),
    path: &Path,
    lang: Lang,
) -> Result<String, ViewerError> {
    let mut theme = theme;
    if transparent {
        theme.background[3] = 0.0;
    }
    let render_failed = |e| ViewerError::Render(Arc::new(e));
    let mut offscreen = Offscreen::new().map_err(render_failed)?;
    let camera = camera.fitted_to(w as f32 / h as f32);
    let frame = offscreen
        .render(list, &camera, &theme, w, h)
        .map_err(render_failed)?;
    let mut png = Vec::new();
    image::ImageEncoder::write_image(
        image::codecs::png::PngEncoder::new(&mut png),
        &frame.rgba,
        w,
        h,
        image::ExtendedColorType::Rgba8,
    )
    .map_err(|e| ViewerError::Encode(Arc::new(e)))?;
    crate::output::write_atomically(path, &png).map_err(|e| ViewerError::Export(Arc::new(e)))?;
    Ok(lang.fmt(
        "shots.saved_view",
        &[("w", &w), ("h", &h), ("path", &path.display())],
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scales_and_names() {
        assert_eq!(ShotScale::One.size([1000, 600]), (1000, 600));
        assert_eq!(ShotScale::Two.size([1000, 600]), (2000, 1200));
        assert_eq!(ShotScale::Uhd.size([1000, 600]), (3840, 2160));
        assert_eq!(ShotScale::Two.size([6000, 100]), (8192, 200));
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let p = next_path(dir.path(), "seed / test");
        assert_eq!(p, dir.path().join("seed___test-shot-01.png"));
        std::fs::write(&p, b"").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(
            next_path(dir.path(), "seed / test"),
            dir.path().join("seed___test-shot-02.png")
        );
        // The current folder ("."): said as an absolute path.
        let here = next_path(Path::new("."), "seed");
        assert!(here.is_absolute(), "{}", here.display());
    }
}
