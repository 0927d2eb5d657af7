//! Classical washout (Reid & Nahon): three channels from the vehicle's specific force `f`
//! (its acceleration in its own frame, gravity excluded) and rotation rates `ω`.
//!
//! - **Translational**, per axis: `k_t f` through the second-order high-pass
//!   `s²/(s²+2ζω s+ω²)`, the first-order high-pass `s/(s+ω_b)` (it brings the platform
//!   back to neutral; left out when `ω_b = 0`) and a double integration. The chain is one
//!   linear system, `x/f = k_t s/((s²+2ζω s+ω²)(s+ω_b))`, in companion form: three
//!   states, the position its second.
//! - **Tilt coordination**, surge and sway: `k_t f` through the low-pass
//!   `ω²/(s²+2ζω s+ω²)`; the platform tilts until gravity's component along it matches,
//!   `θ = asin(f/g)` (pitch nose-up for forward force, roll right-side-down for force to
//!   the left), turning no faster than the tilt rate limit.
//! - **Rotational**, per axis: `k_r ω` through the second-order high-pass, then integrated:
//!   `θ/ω = k_r s/(s²+2ζω s+ω²)`, two states, the angle its second. The vehicle's body
//!   rates are taken as the platform's roll, pitch and yaw rates (exact for a rotation
//!   about one axis; the difference is of the order of the tilt angle times the rate).
//!
//! Each linear part is stepped exactly for inputs held between samples ([`Lti`]): a step
//! of input from rest gives the continuous response at every sample time. The rate limit
//! works on the samples: each sample's tilt moves toward the low-pass's `asin(f/g)` by at
//! most the limit times the step.

use super::lti::Lti;
use crate::model::cueing_settings::{CueingSettings, GRAVITY};

/// One sample of vehicle motion.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct VehicleMotion {
    /// Specific force (acceleration, gravity excluded) along the vehicle's x, y, z, m/s².
    pub accel: [f64; 3],
    /// Rotation rates about the vehicle's x, y, z, degrees per second.
    pub rates_deg_s: [f64; 3],
}

/// What the washout asks of the platform at the reference point.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Cue {
    /// Translation from neutral, metres.
    pub position: [f64; 3],
    /// Translational acceleration, m/s².
    pub acceleration: [f64; 3],
    /// Roll, pitch, yaw, radians (rotational channel and tilt together).
    pub angles: [f64; 3],
    /// The tilt part of roll and pitch, radians.
    pub tilt: [f64; 2],
}

impl Cue {
    /// The specific force the occupant feels on the platform, in the platform's axes,
    /// m/s², less the 1 g of standing still: `Rᵀ (a + g ẑ) − g ẑ` with `a` the cue's
    /// translational acceleration and `R` its rotation. Sustained force rendered by tilt
    /// shows here as gravity's share along the tilted platform.
    pub fn specific_force(&self) -> [f64; 3] {
        let [roll, pitch, yaw] = self.angles.map(crate::model::angle::Angle::from_radians);
        let r = crate::model::pose::rotation_zyx(roll, pitch, yaw);
        let up = nalgebra::Vector3::new(0.0, 0.0, GRAVITY);
        let f = r.transpose() * (nalgebra::Vector3::from(self.acceleration) + up) - up;
        [f.x, f.y, f.z]
    }
}

/// The washout's filters and their state.
#[derive(Clone, Debug)]
pub struct Washout {
    settings: CueingSettings,
    translation: [Lti<3>; 3],
    tilt_filter: [Lti<2>; 2],
    rotation: [Lti<2>; 3],
    /// Tilt of roll and pitch now, radians.
    tilt: [f64; 2],
    /// The input held since the last sample (scaled, SI).
    force: [f64; 3],
    rates: [f64; 3],
}

impl Washout {
    /// The washout of `settings` at rest (platform at neutral).
    pub fn new(settings: &CueingSettings) -> Self {
        let s = settings;
        let (w, z, wb) = (
            s.translation_hp_wn,
            s.translation_hp_zeta,
            s.translation_hp_wb,
        );
        // (s² + 2ζω s + ω²)(s + ω_b) = s³ + (2ζω + ω_b) s² + (ω² + 2ζω ω_b) s + ω² ω_b.
        let translation =
            || Lti::companion([w * w * wb, w * w + 2.0 * z * w * wb, 2.0 * z * w + wb]);
        let (wl, zl) = (s.tilt_lp_wn, s.tilt_lp_zeta);
        let tilt = || Lti::companion([wl * wl, 2.0 * zl * wl]);
        let (wr, zr) = (s.rotation_hp_wn, s.rotation_hp_zeta);
        let rotation = || Lti::companion([wr * wr, 2.0 * zr * wr]);
        Self {
            settings: s.clone(),
            translation: [translation(), translation(), translation()],
            tilt_filter: [tilt(), tilt()],
            rotation: [rotation(), rotation(), rotation()],
            tilt: [0.0; 2],
            force: [0.0; 3],
            rates: [0.0; 3],
        }
    }

    /// The settings it runs.
    pub fn settings(&self) -> &CueingSettings {
        &self.settings
    }

    /// Hold `motion` as the input from now until the next sample.
    pub fn hold(&mut self, motion: &VehicleMotion) {
        let s = &self.settings;
        self.force = motion.accel.map(|a| s.translation_scale * a);
        self.rates = motion
            .rates_deg_s
            .map(|r| s.rotation_scale * r.to_radians());
    }

    /// Advance every channel by `h` seconds with the input held.
    pub fn advance(&mut self, h: f64) {
        for (f, u) in self.translation.iter_mut().zip(self.force) {
            f.advance(h, u);
        }
        for (f, u) in self.tilt_filter.iter_mut().zip(self.force) {
            f.advance(h, u);
        }
        for (f, u) in self.rotation.iter_mut().zip(self.rates) {
            f.advance(h, u);
        }
        let step = self.settings.tilt_rate_max_deg_s.to_radians() * h;
        let targets = self.tilt_targets();
        for (tilt, target) in self.tilt.iter_mut().zip(targets) {
            *tilt += (target - *tilt).clamp(-step, step);
        }
    }

    /// The tilt of roll and pitch the low-passed force asks for: `asin(f/g)` (pitch
    /// negative, nose up, for a forward force), nothing with tilt off.
    fn tilt_targets(&self) -> [f64; 2] {
        if !self.settings.tilt {
            return [0.0; 2];
        }
        // The companion form's first state is the force over the denominator: times ω²
        // it is the low-passed force.
        let gain = self.settings.tilt_lp_wn.powi(2);
        let angle = |f: &Lti<2>| (gain * f.state()[0] / GRAVITY).clamp(-1.0, 1.0).asin();
        [angle(&self.tilt_filter[1]), -angle(&self.tilt_filter[0])]
    }

    /// The cue now, each axis the settings switch off left at neutral.
    pub fn cue(&self) -> Cue {
        let [x, y, z, roll, pitch, yaw] = self.settings.axes();
        let on = [x, y, z];
        let position = std::array::from_fn(|i| {
            if on[i] {
                self.translation[i].state()[1]
            } else {
                0.0
            }
        });
        let acceleration = std::array::from_fn(|i| {
            if on[i] {
                self.translation[i].derivative(self.force[i])[2]
            } else {
                0.0
            }
        });
        let tilt = [
            if roll { self.tilt[0] } else { 0.0 },
            if pitch { self.tilt[1] } else { 0.0 },
        ];
        let rotation = |i: usize, on: bool| {
            if on { self.rotation[i].state()[1] } else { 0.0 }
        };
        Cue {
            position,
            acceleration,
            angles: [
                rotation(0, roll) + tilt[0],
                rotation(1, pitch) + tilt[1],
                rotation(2, yaw),
            ],
            tilt,
        }
    }

    /// Back to neutral and rest.
    pub fn reset(&mut self) {
        for f in &mut self.translation {
            f.reset();
        }
        for f in self.tilt_filter.iter_mut().chain(&mut self.rotation) {
            f.reset();
        }
        self.tilt = [0.0; 2];
        self.force = [0.0; 3];
        self.rates = [0.0; 3];
    }
}
