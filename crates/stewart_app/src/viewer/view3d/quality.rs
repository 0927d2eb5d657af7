//! The 3D view's quality, adapted to the measured frame time.
//!
//! On a GPU nothing changes: the window's pass has 4× MSAA and the view is drawn straight
//! into it. On a software rasteriser (lavapipe on a PC without a usable GPU) every sample
//! and every covered pixel costs CPU time, so the window's pass has one sample and the
//! view is drawn at one of two qualities:
//!
//! - [`Drawn::Full`]: rendered off screen with 4× MSAA at full size and drawn in as one
//!   picture — always when still (so the picture at rest, and a window screenshot of it,
//!   is the full one), and while moving as long as frames keep within the budget;
//! - [`Drawn::Direct`]: straight into the window's single-sample pass (fewer samples: no
//!   off-screen pass, no copy) while moving, once the full picture's frames were over the
//!   budget;
//! - [`Drawn::Scaled`]: rendered off screen with one sample at [`SCALE`] of the view's
//!   size and filtered up, while moving, once direct frames were over the budget too.
//!
//! A level is left for the next lower one when the mean of its last [`LEVEL_FRAMES`]
//! moving frames is over [`BUDGET_MS`], and the next higher one is tried again after
//! [`RETRY_AFTER`] moving frames in a row under half the budget.
//!
//! View screenshots and exports render off screen at their own quality, untouched.

use std::collections::VecDeque;

/// How the 3D view is drawn this frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Drawn {
    /// Straight into the window's pass with the window's samples.
    Direct,
    /// Off screen with 4× MSAA at full size, drawn in as one picture (only where the
    /// window's pass has one sample; elsewhere the same as [`Drawn::Direct`]).
    Full,
    /// Off screen with one sample at [`SCALE`] of the view's size, filtered up (only
    /// where the window's pass has one sample).
    Scaled,
}

/// The moving levels, best first.
const LEVELS: [Drawn; 3] = [Drawn::Full, Drawn::Direct, Drawn::Scaled];

/// The size of the scaled picture against the view's (each side).
pub(crate) const SCALE: f32 = 0.5;

/// The frame time a moving view keeps within: 30 frames a second, milliseconds.
pub(crate) const BUDGET_MS: f64 = 1000.0 / 30.0;

/// Moving frames at one level averaged to decide that it is too slow.
const LEVEL_FRAMES: usize = 8;

/// Moving frames in a row, each under half the budget, before the next higher level is
/// tried again.
const RETRY_AFTER: usize = 120;

/// Frame times kept for the readout.
const KEPT: usize = 120;

/// What a `STEWART_VIEW_QUALITY` of `full` or `fast` fixes (for measuring), else adapts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Policy {
    /// Adapt to the measured frame time.
    Adaptive,
    /// Always the full picture.
    Full,
    /// Always drawn straight in while moving (still: the full picture).
    Fast,
    /// Always the scaled picture while moving (still: the full picture).
    Scaled,
}

impl Policy {
    /// From `STEWART_VIEW_QUALITY` (`adaptive`, `full`, `fast`, `scaled`; anything else:
    /// adaptive).
    pub(crate) fn from_env() -> Self {
        match std::env::var("STEWART_VIEW_QUALITY").as_deref() {
            Ok("full") => Policy::Full,
            Ok("fast") => Policy::Fast,
            Ok("scaled") => Policy::Scaled,
            _ => Policy::Adaptive,
        }
    }
}

/// The quality chooser and the frame-time record.
#[derive(Clone, Debug)]
pub(crate) struct Quality {
    /// The window's pass has one sample (a software rasteriser): the full picture is
    /// drawn off screen.
    pub(crate) software: bool,
    /// How the choice is made.
    pub(crate) policy: Policy,
    /// The window clears itself to the panels' colour: the panels draw no fill (on a
    /// software rasteriser each large fill costs milliseconds a frame). Off where nothing
    /// clears so (tests render on a transparent image).
    pub(crate) window_clears: bool,
    /// The level while moving now (an index into [`LEVELS`]).
    level: usize,
    /// This level's moving frames' times, newest last (at most [`LEVEL_FRAMES`]).
    level_times: VecDeque<f64>,
    /// Moving frames in a row under half the budget.
    fast_run: usize,
    /// The last frames' times, ms, newest last (for the readout).
    times: VecDeque<f64>,
    /// How the last frame was drawn, and whether it was moving.
    last: (Drawn, bool),
    /// The next frame is the full picture whatever moves (a window screenshot).
    full_next: bool,
}

impl Default for Quality {
    fn default() -> Self {
        Self::new(false, Policy::Adaptive)
    }
}

impl Quality {
    /// The chooser for a window whose pass has one sample (`software`) or MSAA.
    pub(crate) fn new(software: bool, policy: Policy) -> Self {
        Self {
            software,
            policy,
            window_clears: false,
            level: 0,
            level_times: VecDeque::new(),
            fast_run: 0,
            times: VecDeque::new(),
            last: (Drawn::Full, false),
            full_next: false,
        }
    }

    /// Draw the next frame as the full picture whatever moves (a window screenshot is
    /// taken of it).
    pub(crate) fn ask_full(&mut self) {
        self.full_next = true;
    }

    /// Whether the next frame is to be the full picture whatever moves (a window shot).
    pub(crate) fn full_asked(&self) -> bool {
        self.full_next
    }

    /// Whether the last frame was the full picture (or drawn on a GPU, where every frame
    /// is).
    pub(crate) fn last_was_full(&self) -> bool {
        !self.software || self.last.0 == Drawn::Full
    }

    /// How to draw this frame: `moving` when the view changes from frame to frame
    /// (playback, a drag, a stream).
    pub(crate) fn choose(&mut self, moving: bool) -> Drawn {
        let drawn = if !self.software {
            Drawn::Direct
        } else if !moving || std::mem::take(&mut self.full_next) {
            Drawn::Full
        } else {
            match self.policy {
                Policy::Adaptive => LEVELS[self.level],
                Policy::Full => Drawn::Full,
                Policy::Fast => Drawn::Direct,
                Policy::Scaled => Drawn::Scaled,
            }
        };
        self.last = (drawn, moving);
        drawn
    }

    /// The whole frame just drawn took `ms` milliseconds: adapt the quality while moving.
    pub(crate) fn record(&mut self, ms: f64) {
        if !ms.is_finite() {
            return;
        }
        if self.times.len() == KEPT {
            self.times.pop_front();
        }
        self.times.push_back(ms);
        let (drawn, moving) = self.last;
        if !(self.software && moving) {
            return;
        }
        if drawn != LEVELS[self.level] {
            return;
        }
        if self.level_times.len() == LEVEL_FRAMES {
            self.level_times.pop_front();
        }
        self.level_times.push_back(ms);
        let mean = self.level_times.iter().sum::<f64>() / self.level_times.len() as f64;
        self.fast_run = if ms < BUDGET_MS / 2.0 {
            self.fast_run + 1
        } else {
            0
        };
        let lower = self.level_times.len() == LEVEL_FRAMES && mean > BUDGET_MS;
        if lower && self.level + 1 < LEVELS.len() {
            self.level += 1;
        } else if self.fast_run >= RETRY_AFTER && self.level > 0 {
            self.level -= 1;
        } else {
            return;
        }
        self.level_times.clear();
        self.fast_run = 0;
    }

    /// Whether one more frame must be drawn: the last was not the full picture and the
    /// view is still (so the picture left on screen is the full one).
    pub(crate) fn wants_full_frame(&self) -> bool {
        self.software && self.last.0 != Drawn::Full
    }

    /// Mean and 95th percentile of the last frames' times, ms (`None` before any).
    pub(crate) fn frame_times(&self) -> Option<(f64, f64)> {
        if self.times.is_empty() {
            return None;
        }
        let mut sorted: Vec<f64> = self.times.iter().copied().collect();
        sorted.sort_by(f64::total_cmp);
        let mean = sorted.iter().sum::<f64>() / sorted.len() as f64;
        let p95 = sorted[((sorted.len() as f64 * 0.95) as usize).min(sorted.len() - 1)];
        Some((mean, p95))
    }

    /// The locale key of how the last frame's 3D view was drawn.
    pub(crate) fn words_key(&self) -> &'static str {
        match (self.software, self.last.0) {
            (false, _) => "quality.gpu",
            (true, Drawn::Full) => "quality.full",
            (true, Drawn::Direct) => "quality.direct",
            (true, Drawn::Scaled) => "quality.scaled",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Draw `n` frames, moving or not, each taking `ms`.
    fn frames(q: &mut Quality, n: usize, moving: bool, ms: f64) -> Drawn {
        let mut drawn = Drawn::Full;
        for _ in 0..n {
            drawn = q.choose(moving);
            q.record(ms);
        }
        drawn
    }

    #[test]
    fn a_gpu_draws_straight_in_whatever_the_frame_time() {
        let mut q = Quality::new(false, Policy::Adaptive);
        assert_eq!(frames(&mut q, 50, true, 200.0), Drawn::Direct);
        assert_eq!(q.choose(false), Drawn::Direct);
        assert!(!q.wants_full_frame());
    }

    #[test]
    fn software_steps_down_while_moving_only_when_over_budget() {
        let mut q = Quality::new(true, Policy::Adaptive);
        // Within the budget the full picture stays, moving or not.
        assert_eq!(frames(&mut q, 50, true, 25.0), Drawn::Full);
        // One slow frame among fast ones is not enough; two bring the mean of the last
        // eight over the budget: moving frames are then drawn straight in.
        assert_eq!(frames(&mut q, 1, true, 60.0), Drawn::Full);
        assert_eq!(q.choose(true), Drawn::Full);
        q.record(60.0);
        assert_eq!(q.choose(true), Drawn::Direct);
        q.record(30.0);
        // Still: the full picture, and one more frame is asked for when the last was not.
        assert!(q.wants_full_frame());
        assert_eq!(q.choose(false), Drawn::Full);
        q.record(70.0);
        assert!(!q.wants_full_frame());
        // Moving again: still direct (a still frame says nothing of moving ones).
        assert_eq!(q.choose(true), Drawn::Direct);
        q.record(30.0);
        // Direct frames over the budget too: the lower scale, and no lower than that.
        frames(&mut q, LEVEL_FRAMES, true, 45.0);
        assert_eq!(q.choose(true), Drawn::Scaled);
        assert_eq!(frames(&mut q, 5 * LEVEL_FRAMES, true, 45.0), Drawn::Scaled);
        assert_eq!(q.choose(true), Drawn::Scaled);
        assert!(!q.last_was_full());
        // A window screenshot: the next frame is the full picture, then back.
        q.ask_full();
        assert_eq!(q.choose(true), Drawn::Full);
        assert!(q.last_was_full());
        assert_eq!(q.choose(true), Drawn::Scaled);
    }

    #[test]
    fn a_long_run_of_fast_frames_tries_the_level_above_again() {
        let mut q = Quality::new(true, Policy::Adaptive);
        frames(&mut q, LEVEL_FRAMES, true, 50.0);
        assert_eq!(q.choose(true), Drawn::Direct);
        // Fast but not fast enough: no retry.
        assert_eq!(frames(&mut q, 3 * RETRY_AFTER, true, 20.0), Drawn::Direct);
        // Under half the budget for long enough: full again.
        frames(&mut q, RETRY_AFTER, true, 10.0);
        assert_eq!(q.choose(true), Drawn::Full);
        // At the top, fast frames change nothing.
        assert_eq!(frames(&mut q, 2 * RETRY_AFTER, true, 5.0), Drawn::Full);
    }

    #[test]
    fn a_fixed_policy_does_not_adapt_and_times_are_summarised() {
        let mut q = Quality::new(true, Policy::Full);
        assert_eq!(frames(&mut q, 40, true, 90.0), Drawn::Full);
        let mut q = Quality::new(true, Policy::Fast);
        assert_eq!(frames(&mut q, 1, true, 1.0), Drawn::Direct);
        assert_eq!(q.choose(false), Drawn::Full);
        let mut q = Quality::new(true, Policy::Scaled);
        assert_eq!(frames(&mut q, 300, true, 1.0), Drawn::Scaled);
        let mut q = Quality::new(true, Policy::Adaptive);
        assert_eq!(q.frame_times(), None);
        for ms in 1..=100 {
            q.choose(false);
            q.record(f64::from(ms));
        }
        q.record(f64::NAN);
        assert_eq!(q.frame_times(), Some((50.5, 96.0)));
    }
}
