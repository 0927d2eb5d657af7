//! What a held vertical force or rotation rate is predicted to do over the horizon: fade.
//!
//! No platform can sustain a vertical specific force or a rotation (tilt gives surge and
//! sway their forces, nothing gives heave or a rate theirs). Held unchanged over the
//! horizon, they mislead the plan: a heave force that must be given back before the
//! horizon's end is reproduced no better by moving now than later (the best plan is
//! exactly none), a roll or pitch rate held for the whole horizon tilts the platform so
//! far that the force gravity then gives outweighs the rate (the best plan barely turns),
//! and a held yaw rate would turn the platform to its limit. So each is cued as what is
//! new in it: the vehicle's value less what of it has lasted, a first-order high-pass of
//! time constant `τ` (the horizon's length for heave and yaw, a quarter of it for roll
//! and pitch: [`super::FADE_SHARES`]), predicted over the horizon as the filter's own
//! decay while the input holds, `(u − ū) e^{−t/τ}`. A step is cued at its onset and
//! washed out; a held value, or the vertical force that tilt costs, leaves the platform
//! at neutral. A recording's look-ahead is used as it is.

use super::horizon::Horizon;

/// The axes that fade: heave and the three rates (of the six of a wish: forces, rates).
pub const FADING: [usize; 4] = [2, 3, 4, 5];

/// One axis's high-pass.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Fading {
    /// The value held now, scaled (m/s² or rad/s).
    held: f64,
    /// What of it has lasted: the low-pass of the held values.
    lasted: f64,
}

impl Fading {
    /// Hold `value` (scaled) from now on.
    pub fn hold(&mut self, value: f64) {
        self.held = value;
    }

    /// Let `dt` seconds pass with the force held, the filter's time constant `tau`: exact
    /// for a held input.
    pub fn advance(&mut self, dt: f64, tau: f64) {
        let kept = (-dt / tau).exp();
        let lasted = self.held + (self.lasted - self.held) * kept;
        // A force past any float (the planner then fails safe) must not leave a NaN here
        // for ever.
        self.lasted = if lasted.is_finite() { lasted } else { 0.0 };
    }

    /// The predicted value over step `k` of `layout` (its mean) and at its end,
    /// the time constant `tau`.
    pub fn predicted(&self, layout: &Horizon, k: usize, tau: f64) -> (f64, f64) {
        let new = self.held - self.lasted;
        let (start, end) = (layout.start(k), layout.start(k) + layout.length(k));
        let (a, b) = ((-start / tau).exp(), (-end / tau).exp());
        // The mean of e^{−t/τ} over [start, end].
        let mean = tau * (a - b) / (end - start);
        (new * mean, new * b)
    }

    /// Back to nothing held, none lasted.
    pub fn reset(&mut self) {
        *self = Self::default();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn layout() -> Horizon {
        Horizon {
            axes: vec![2],
            steps: 4,
            first: 0.01,
            step: 0.1,
            extra: 0,
        }
    }

    #[test]
    fn a_held_force_decays_as_the_filter_s_free_response() {
        let tau = 0.5;
        let mut h = Fading::default();
        h.hold(2.0);
        // At once: all of it new; the mean over the first 10 ms, ∫ 2e^{−t/τ} / 0.01.
        let (mean, end) = h.predicted(&layout(), 0, tau);
        let exact = 2.0 * tau * (1.0 - (-0.02_f64).exp()) / 0.01;
        assert!((mean - exact).abs() < 1e-12, "{mean} {exact}");
        assert!((end - 2.0 * (-0.02_f64).exp()).abs() < 1e-12);
        // After 0.3 s in steps of 1 ms, held: 2 e^{−0.6} left, whatever the steps.
        for _ in 0..300 {
            h.advance(0.001, tau);
        }
        let (_, end0) = h.predicted(&layout(), 0, tau);
        let left = 2.0 * (-0.6_f64).exp() * (-0.02_f64).exp();
        assert!((end0 - left).abs() < 1e-12, "{end0} {left}");
        // And the prediction then is what the filter would give: step 2 ends at 0.21 s.
        let (_, end2) = h.predicted(&layout(), 2, tau);
        assert!((end2 - 2.0 * (-(0.3 + 0.21) / tau).exp()).abs() < 1e-12);
    }

    #[test]
    fn a_force_past_any_float_leaves_no_nan_behind() {
        let mut h = Fading::default();
        h.hold(f64::INFINITY);
        h.advance(0.01, 1.0);
        h.hold(1.0);
        h.advance(0.01, 1.0);
        assert!(h.predicted(&layout(), 1, 1.0).0.is_finite());
    }
}
