//! The size the window opens at: as asked on the command line, else the last session's
//! or a share of the screen, never larger than the screen.

/// Where the window's size comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum WindowSize {
    /// `--size`: exactly this (screenshots need it), logical pixels.
    Exact(u32, u32),
    /// The last session's, logical pixels: kept unless it does not fit this screen.
    Remembered(u32, u32),
    /// No size known: a share of the screen.
    FitScreen,
}

/// The share of the screen a window without a known size takes.
const SCREEN_SHARE: f64 = 0.85;
/// The share of the screen a remembered size may take at most (room for the title bar
/// and a task bar).
const SCREEN_MAX: f64 = 0.95;
/// The size when the screen's is unknown, logical pixels.
pub(crate) const FALLBACK: (u32, u32) = (1280, 720);

impl WindowSize {
    /// The logical size to open at on a screen of `screen` logical pixels (`None`:
    /// unknown, as on some Wayland compositors).
    pub(crate) fn on_screen(self, screen: Option<(f64, f64)>) -> (u32, u32) {
        let screen =
            screen.filter(|(w, h)| w.is_finite() && h.is_finite() && *w >= 1.0 && *h >= 1.0);
        match (self, screen) {
            (WindowSize::Exact(w, h), _) => (w, h),
            (WindowSize::Remembered(w, h), None) => (w, h),
            (WindowSize::Remembered(w, h), Some((sw, sh))) => {
                let fit = |v: u32, side: f64| {
                    (f64::from(v).min(side * SCREEN_MAX)).floor().max(1.0) as u32
                };
                (fit(w, sw), fit(h, sh))
            }
            (WindowSize::FitScreen, None) => FALLBACK,
            (WindowSize::FitScreen, Some((sw, sh))) => (
                (sw * SCREEN_SHARE).floor().max(1.0) as u32,
                (sh * SCREEN_SHARE).floor().max(1.0) as u32,
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_window_fits_the_screen_unless_its_size_was_asked_for() {
        let laptop = Some((1366.0, 768.0));
        // Asked on the command line: exactly that, even larger than the screen.
        assert_eq!(
            WindowSize::Exact(1920, 1080).on_screen(laptop),
            (1920, 1080)
        );
        // A session saved on a large monitor, opened on a laptop: within 95 % of it.
        assert_eq!(
            WindowSize::Remembered(2500, 1400).on_screen(laptop),
            (1297, 729)
        );
        // One that fits is kept.
        assert_eq!(
            WindowSize::Remembered(1000, 700).on_screen(laptop),
            (1000, 700)
        );
        // Nothing known: 85 % of the screen (1632×918 on a full-HD one).
        assert_eq!(
            WindowSize::FitScreen.on_screen(Some((1920.0, 1080.0))),
            (1632, 918)
        );
        assert_eq!(WindowSize::FitScreen.on_screen(None), FALLBACK);
        assert_eq!(
            WindowSize::FitScreen.on_screen(Some((f64::NAN, 0.0))),
            FALLBACK
        );
    }
}
