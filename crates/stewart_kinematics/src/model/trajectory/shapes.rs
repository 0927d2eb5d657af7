//! Parametric test motions: circle, figure-eight, rising helix, banked circle.
//!
//! Every shape is centred over the base centre at height `z` (usually the home height);
//! `ω = 2π · frequency_hz`.

use std::f64::consts::PI;

use nalgebra::Vector3;
use serde::{Deserialize, Serialize};

use crate::model::angle::Angle;
use crate::model::pose::Pose;

fn omega(frequency_hz: f64) -> f64 {
    2.0 * PI * frequency_hz
}

/// A level circle: `x = r cos ωt`, `y = r sin ωt`, counter-clockwise seen from above.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Circle {
    /// Radius, metres.
    pub radius: f64,
    /// Revolutions per second.
    pub frequency_hz: f64,
    /// Height, metres.
    pub z: f64,
}

impl Circle {
    /// Pose at time `t` (seconds).
    pub fn pose_at(&self, t: f64) -> Pose {
        let (s, c) = (omega(self.frequency_hz) * t).sin_cos();
        Pose::level_at(self.z).with_position(Vector3::new(self.radius * c, self.radius * s, self.z))
    }
}

/// A level figure-eight (a 1:2 Lissajous curve): `x = A_x sin ωt`, `y = A_y sin 2ωt`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct FigureEight {
    /// Half-width along x, metres.
    pub amplitude_x: f64,
    /// Half-width along y, metres.
    pub amplitude_y: f64,
    /// Figure-eights per second.
    pub frequency_hz: f64,
    /// Height, metres.
    pub z: f64,
}

impl FigureEight {
    /// Pose at time `t` (seconds).
    pub fn pose_at(&self, t: f64) -> Pose {
        let w = omega(self.frequency_hz) * t;
        Pose::level_at(self.z).with_position(Vector3::new(
            self.amplitude_x * w.sin(),
            self.amplitude_y * (2.0 * w).sin(),
            self.z,
        ))
    }
}

/// A level circle that climbs steadily from `z_start` at `t = 0` to `z_end` at `t = duration`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Helix {
    /// Radius, metres.
    pub radius: f64,
    /// Revolutions per second.
    pub frequency_hz: f64,
    /// Height at the start, metres.
    pub z_start: f64,
    /// Height at the end, metres.
    pub z_end: f64,
    /// Time of the climb, seconds.
    pub duration: f64,
}

impl Helix {
    /// Pose at time `t` (seconds).
    pub fn pose_at(&self, t: f64) -> Pose {
        let (s, c) = (omega(self.frequency_hz) * t).sin_cos();
        let z = self.z_start + (self.z_end - self.z_start) * (t / self.duration);
        Pose::level_at(z).with_position(Vector3::new(self.radius * c, self.radius * s, z))
    }
}

/// A circle on which the platform banks into the turn: its normal leans toward the
/// circle's centre by `tilt`. For position `(r cos ωt, r sin ωt)`:
/// `roll = tilt · sin ωt`, `pitch = −tilt · cos ωt`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Sway {
    /// Radius, metres.
    pub radius: f64,
    /// Revolutions per second.
    pub frequency_hz: f64,
    /// Lean toward the centre.
    pub tilt: Angle,
    /// Height, metres.
    pub z: f64,
}

impl Sway {
    /// Pose at time `t` (seconds).
    pub fn pose_at(&self, t: f64) -> Pose {
        let (s, c) = (omega(self.frequency_hz) * t).sin_cos();
        Pose::new(
            Vector3::new(self.radius * c, self.radius * s, self.z),
            self.tilt * s,
            -(self.tilt * c),
            Angle::ZERO,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn circle_and_helix_stay_on_their_radius() {
        let c = Circle {
            radius: 0.1,
            frequency_hz: 0.3,
            z: 0.8,
        };
        let h = Helix {
            radius: 0.1,
            frequency_hz: 0.3,
            z_start: 0.7,
            z_end: 0.9,
            duration: 10.0,
        };
        for k in 0..100 {
            let t = k as f64 * 0.1;
            for p in [c.pose_at(t), h.pose_at(t)] {
                assert!((p.position.xy().norm() - 0.1).abs() < 1e-15);
            }
        }
        assert_eq!(h.pose_at(0.0).position.z, 0.7);
        assert!((h.pose_at(5.0).position.z - 0.8).abs() < 1e-15);
        assert_eq!(h.pose_at(10.0).position.z, 0.9);
        // A quarter turn takes the circle from +x to +y.
        let q = c.pose_at(1.0 / (4.0 * 0.3));
        assert!((q.position - Vector3::new(0.0, 0.1, 0.8)).norm() < 1e-15);
    }

    #[test]
    fn figure_eight_crosses_itself_at_the_centre() {
        let f = FigureEight {
            amplitude_x: 0.2,
            amplitude_y: 0.1,
            frequency_hz: 0.1,
            z: 0.8,
        };
        // Half a period later x and y are both back at zero.
        let p = f.pose_at(5.0);
        assert!(p.position.xy().norm() < 1e-15);
        // At a quarter period x is at its extreme and y back at zero.
        let p = f.pose_at(2.5);
        assert!((p.position.x - 0.2).abs() < 1e-15 && p.position.y.abs() < 1e-15);
    }

    #[test]
    fn sway_banks_toward_the_centre() {
        let s = Sway {
            radius: 0.1,
            frequency_hz: 0.2,
            tilt: Angle::from_degrees(5.0),
            z: 0.8,
        };
        for k in 0..50 {
            let p = s.pose_at(k as f64 * 0.1);
            let normal = p.rotation() * Vector3::z();
            // The normal's horizontal part points from the platform toward the axis.
            let toward_centre = -p.position.xy().normalize();
            let lean = normal.xy();
            assert!(lean.normalize().dot(&toward_centre) > 0.999);
            assert!((lean.norm() - 5f64.to_radians().sin()).abs() < 1e-3);
        }
    }
}
