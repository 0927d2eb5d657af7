//! The workspace limiter: the cue scaled toward neutral, by one factor for its translation
//! and angles, just enough that the pose stays within the stroke and limits.
//!
//! Each sample the scale may grow back by at most `h / recovery_s` (to 1); if the pose at
//! that scale leaves the limits, the largest scale below it that keeps the pose within
//! them is found by bisection (to 2⁻⁴⁰), always taking the end that was checked to fit. So
//! every pose is within the limits, the platform is held on their edge while the cue asks
//! for more, and the full cue comes back gradually once it fits again. Neutral (scale 0)
//! must fit.

/// The limiter's scale and how fast it recovers.
#[derive(Clone, Debug)]
pub struct Limiter {
    scale: f64,
    recovery_s: f64,
}

/// Bisection steps: the scale to 2⁻⁴⁰ of its range.
const STEPS: usize = 40;

impl Limiter {
    /// A limiter at full scale that recovers from 0 to 1 in `recovery_s` seconds.
    pub fn new(recovery_s: f64) -> Self {
        Self {
            scale: 1.0,
            recovery_s,
        }
    }

    /// The scale now.
    pub fn scale(&self) -> f64 {
        self.scale
    }

    /// Back to full scale.
    pub fn reset(&mut self) {
        self.scale = 1.0;
    }

    /// The scale after `h` seconds, given whether the pose at a scale fits the limits
    /// (`fits(0.0)` must hold).
    pub fn scale_for(&mut self, h: f64, fits: impl Fn(f64) -> bool) -> f64 {
        let wanted = (self.scale + h / self.recovery_s).min(1.0);
        self.scale = if fits(wanted) {
            wanted
        } else {
            let (mut lo, mut hi) = (0.0, wanted);
            for _ in 0..STEPS {
                let mid = 0.5 * (lo + hi);
                if fits(mid) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            lo
        };
        self.scale
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_scale_drops_to_what_fits_and_recovers_at_its_rate() {
        let mut l = Limiter::new(2.0);
        // Only scales up to 0.3 fit: the scale falls to just below it.
        let s = l.scale_for(0.01, |s| s <= 0.3);
        assert!(s <= 0.3 && s > 0.3 - 1e-11, "{s}");
        // Everything fits again: back by h / recovery_s per step, never above 1.
        let s2 = l.scale_for(0.5, |_| true);
        assert!((s2 - (s + 0.25)).abs() < 1e-15);
        assert_eq!(l.scale_for(10.0, |_| true), 1.0);
    }
}
