//! The seed's composite sinusoid, with every amplitude, frequency, phase and offset adjustable.

use std::f64::consts::PI;

use nalgebra::Vector3;
use serde::{Deserialize, Serialize};

use crate::model::angle::Angle;
use crate::model::pose::Pose;

/// Which periodic function a channel follows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Wave {
    /// `sin`.
    #[default]
    Sin,
    /// `cos` (the seed's `y`; kept apart from a 90° phase so the seed is reproduced bit for bit).
    Cos,
}

/// One coordinate over time: `offset + amplitude · wave(2π · frequency · t + phase)`.
///
/// The unit of `offset` and `amplitude` is the unit of the coordinate the channel
/// drives: metres for x, y, z and degrees for roll, pitch, yaw (see [`Sinusoid`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Channel {
    /// Peak deviation from `offset`.
    pub amplitude: f64,
    /// Frequency in hertz.
    pub frequency_hz: f64,
    /// Phase at `t = 0`.
    pub phase: Angle,
    /// Value about which the channel oscillates.
    pub offset: f64,
    /// The periodic function.
    pub wave: Wave,
}

impl Channel {
    /// A channel `amplitude · sin(2π f t)` with no phase and no offset.
    pub fn sine(amplitude: f64, frequency_hz: f64) -> Self {
        Self {
            amplitude,
            frequency_hz,
            ..Self::default()
        }
    }

    /// The same channel with its phase set.
    pub fn with_phase(self, phase: Angle) -> Self {
        Self { phase, ..self }
    }

    /// The same channel with its offset set.
    pub fn with_offset(self, offset: f64) -> Self {
        Self { offset, ..self }
    }

    /// The same channel with its wave set.
    pub fn with_wave(self, wave: Wave) -> Self {
        Self { wave, ..self }
    }

    /// Value at time `t` (seconds). Evaluated in the seed's order of operations,
    /// `2·π·f·t + φ`, so the seed preset matches the article to the last bit.
    #[inline]
    pub fn at(&self, t: f64) -> f64 {
        let arg = 2.0 * PI * self.frequency_hz * t + self.phase.radians();
        let w = match self.wave {
            Wave::Sin => arg.sin(),
            Wave::Cos => arg.cos(),
        };
        self.offset + self.amplitude * w
    }
}

/// The channels' names as written in scenario files: x, y, z in metres, then roll,
/// pitch, yaw in degrees.
pub const CHANNEL_NAMES: [&str; 6] = ["x", "y", "z", "roll", "pitch", "yaw"];

/// Six independent sinusoidal channels, one per degree of freedom.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Sinusoid {
    /// x in metres.
    pub x: Channel,
    /// y in metres.
    pub y: Channel,
    /// z in metres (its offset is the mean height, usually the home height).
    pub z: Channel,
    /// Roll in degrees.
    pub roll_deg: Channel,
    /// Pitch in degrees.
    pub pitch_deg: Channel,
    /// Yaw in degrees.
    pub yaw_deg: Channel,
}

impl Sinusoid {
    /// The article's trajectory about home height `h0`:
    /// `x = 0.15 sin(2π·0.2t)`, `y = 0.15 cos(2π·0.2t)`, `z = h0 + 0.08 sin(2π·0.1t)`,
    /// `roll = 6° sin(2π·0.1t)`, `pitch = 4° sin(2π·0.15t + π/4)`, `yaw = 8° sin(2π·0.05t)`.
    pub fn seed(h0: f64) -> Self {
        Self {
            x: Channel::sine(0.15, 0.2),
            y: Channel::sine(0.15, 0.2).with_wave(Wave::Cos),
            z: Channel::sine(0.08, 0.1).with_offset(h0),
            roll_deg: Channel::sine(6.0, 0.1),
            pitch_deg: Channel::sine(4.0, 0.15).with_phase(Angle::from_degrees(45.0)),
            yaw_deg: Channel::sine(8.0, 0.05),
        }
    }

    /// Pose at time `t` (seconds).
    pub fn pose_at(&self, t: f64) -> Pose {
        Pose::new(
            Vector3::new(self.x.at(t), self.y.at(t), self.z.at(t)),
            Angle::from_degrees(self.roll_deg.at(t)),
            Angle::from_degrees(self.pitch_deg.at(t)),
            Angle::from_degrees(self.yaw_deg.at(t)),
        )
    }

    /// The six channels with their names as written in scenario files.
    pub fn channels(&self) -> [(&'static str, &Channel); 6] {
        let c = [
            &self.x,
            &self.y,
            &self.z,
            &self.roll_deg,
            &self.pitch_deg,
            &self.yaw_deg,
        ];
        std::array::from_fn(|i| (CHANNEL_NAMES[i], c[i]))
    }

    /// The six channels, mutable, in the order of [`CHANNEL_NAMES`].
    pub fn channels_mut(&mut self) -> [&mut Channel; 6] {
        [
            &mut self.x,
            &mut self.y,
            &mut self.z,
            &mut self.roll_deg,
            &mut self.pitch_deg,
            &mut self.yaw_deg,
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seed_matches_the_article_formulas_bit_for_bit() {
        let s = Sinusoid::seed(0.8);
        for k in 0..1001 {
            let t = k as f64 * 10.0 / 1000.0;
            let pose = s.pose_at(t);
            // The article's lines, transcribed.
            let x = 0.15 * (2.0 * PI * 0.2 * t).sin();
            let y = 0.15 * (2.0 * PI * 0.2 * t).cos();
            let z = 0.8 + 0.08 * (2.0 * PI * 0.1 * t).sin();
            let roll = 6.0 * (2.0 * PI * 0.1 * t).sin();
            let pitch = 4.0 * (2.0 * PI * 0.15 * t + PI / 4.0).sin();
            let yaw = 8.0 * (2.0 * PI * 0.05 * t).sin();
            assert_eq!(pose.position, Vector3::new(x, y, z), "t = {t}");
            assert_eq!(pose.roll.radians(), roll * (PI / 180.0));
            assert_eq!(pose.pitch.radians(), pitch * (PI / 180.0));
            assert_eq!(pose.yaw.radians(), yaw * (PI / 180.0));
        }
    }

    #[test]
    fn channel_values_at_known_times() {
        let c = Channel::sine(2.0, 0.25).with_offset(1.0);
        assert_eq!(c.at(0.0), 1.0);
        assert!((c.at(1.0) - 3.0).abs() < 1e-15); // quarter period: sin = 1
        assert!((c.at(3.0) + 1.0).abs() < 1e-15); // three quarters: sin = −1
        let d = c.with_wave(Wave::Cos).with_phase(Angle::from_degrees(90.0));
        assert!((d.at(0.0) - 1.0).abs() < 1e-15); // cos(90°) = 0
    }
}
