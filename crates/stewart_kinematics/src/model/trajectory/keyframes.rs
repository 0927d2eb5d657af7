//! Keyframed motion: poses at given times, interpolated per coordinate.

use serde::{Deserialize, Serialize};

use crate::model::pose::Pose;

/// How to move between keyframes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Interpolation {
    /// Straight lines between keys (velocity jumps at each key).
    Linear,
    /// Stop at every key: each segment follows the minimum-jerk profile
    /// `10s³ − 15s⁴ + 6s⁵`, with zero velocity and acceleration at both ends.
    Smoothstep,
    /// A natural cubic spline through every key: continuous velocity and acceleration.
    #[default]
    Cubic,
}

/// A pose at a time.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Keyframe {
    /// Time, seconds.
    pub t: f64,
    /// Pose at that time.
    pub pose: Pose,
}

/// Poses at strictly increasing times, interpolated. Before the first key the motion
/// holds the first pose, after the last key the last pose.
#[derive(Clone, Debug, PartialEq)]
pub struct Keyframes {
    keys: Vec<Keyframe>,
    interpolation: Interpolation,
    /// Per coordinate (x, y, z, roll, pitch, yaw; angles in radians), the spline's
    /// second derivative at each key. Empty unless the interpolation is cubic.
    second_derivatives: [Vec<f64>; 6],
}

/// Why a list of keyframes was refused.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum KeyframeError {
    /// No keys.
    #[error("a keyframed motion needs at least one key")]
    Empty,
    /// Times out of order.
    #[error(
        "key {index} is at t = {t} s, not after the previous key's {previous} s: times must increase"
    )]
    NotIncreasing {
        /// Key number, from 1.
        index: usize,
        /// Its time.
        t: f64,
        /// The previous key's time.
        previous: f64,
    },
    /// A NaN or infinite value.
    #[error("key {index} holds a value that is not a finite number")]
    NotFinite {
        /// Key number, from 1.
        index: usize,
    },
    /// A value outside the accepted range of its kind (see [`crate::ground::bounds`]).
    #[error("key {index}: {what}")]
    OutOfRange {
        /// Key number, from 1.
        index: usize,
        /// Which value and why.
        what: String,
    },
    /// Two keys closer in time than [`MIN_KEY_GAP_S`].
    #[error(
        "key {index} is only {gap:.3e} s after the previous key; keys must be at least 1e-6 s apart"
    )]
    TooClose {
        /// Key number, from 1.
        index: usize,
        /// The gap, seconds.
        gap: f64,
    },
}

/// The smallest time between two keys, seconds (closer keys make splines overflow).
pub const MIN_KEY_GAP_S: f64 = 1e-6;

/// Whether two keys `gap` seconds apart are far enough: [`MIN_KEY_GAP_S`] at least, to a
/// millionth of it (times written to the microsecond, `0.000004` then `0.000005`, differ
/// by a hair less than 1e-6 once read).
pub fn far_enough_apart(gap: f64) -> bool {
    gap >= MIN_KEY_GAP_S * (1.0 - 1e-6)
}

impl KeyframeError {
    /// The key the error names, from 1 (none for an empty list).
    pub fn index(&self) -> Option<usize> {
        match self {
            Self::NotIncreasing { index, .. }
            | Self::NotFinite { index }
            | Self::OutOfRange { index, .. }
            | Self::TooClose { index, .. } => Some(*index),
            Self::Empty => None,
        }
    }
}

/// Check a key's values against [`crate::ground::bounds`]: time, position, angles.
fn check_key_ranges(index: usize, k: &Keyframe) -> Result<(), KeyframeError> {
    use crate::ground::bounds::{ANGLE_DEG, LENGTH_M, TIME_S, check, symmetric};
    let out = |name: &str, reason: crate::ground::bounds::OutOfBounds| KeyframeError::OutOfRange {
        index,
        what: format!("{name} {reason}"),
    };
    check(k.t, &symmetric(TIME_S), "s").map_err(|r| out("t_s", r))?;
    let c = k.pose.to_coordinates();
    for (name, v) in ["x_m", "y_m", "z_m"].iter().zip(&c[..3]) {
        check(*v, &symmetric(LENGTH_M), "m").map_err(|r| out(name, r))?;
    }
    for (name, v) in ["roll_deg", "pitch_deg", "yaw_deg"].iter().zip(&c[3..]) {
        check(v.to_degrees(), &symmetric(ANGLE_DEG), "°").map_err(|r| out(name, r))?;
    }
    Ok(())
}

impl Keyframes {
    /// Validate and prepare keyframes.
    pub fn new(keys: Vec<Keyframe>, interpolation: Interpolation) -> Result<Self, KeyframeError> {
        if keys.is_empty() {
            return Err(KeyframeError::Empty);
        }
        for (i, k) in keys.iter().enumerate() {
            if !k.t.is_finite() || !k.pose.is_finite() {
                return Err(KeyframeError::NotFinite { index: i + 1 });
            }
            check_key_ranges(i + 1, k)?;
            if i > 0 && k.t <= keys[i - 1].t {
                return Err(KeyframeError::NotIncreasing {
                    index: i + 1,
                    t: k.t,
                    previous: keys[i - 1].t,
                });
            }
            if i > 0 && !far_enough_apart(k.t - keys[i - 1].t) {
                return Err(KeyframeError::TooClose {
                    index: i + 1,
                    gap: k.t - keys[i - 1].t,
                });
            }
        }
        let second_derivatives = if interpolation == Interpolation::Cubic {
            let times: Vec<f64> = keys.iter().map(|k| k.t).collect();
            std::array::from_fn(|c| {
                let values: Vec<f64> = keys.iter().map(|k| k.pose.to_coordinates()[c]).collect();
                natural_spline_second_derivatives(&times, &values)
            })
        } else {
            Default::default()
        };
        Ok(Self {
            keys,
            interpolation,
            second_derivatives,
        })
    }

    /// The keys.
    pub fn keys(&self) -> &[Keyframe] {
        &self.keys
    }

    /// The interpolation.
    pub fn interpolation(&self) -> Interpolation {
        self.interpolation
    }

    /// Time of the first and last key, seconds.
    pub fn time_span(&self) -> (f64, f64) {
        let first = self.keys.first().map_or(0.0, |k| k.t);
        let last = self.keys.last().map_or(0.0, |k| k.t);
        (first, last)
    }

    /// Pose at time `t` (seconds).
    pub fn pose_at(&self, t: f64) -> Pose {
        let (first, last) = self.time_span();
        if self.keys.len() == 1 || t <= first {
            return self.keys[0].pose;
        }
        if t >= last {
            return self.keys[self.keys.len() - 1].pose;
        }
        // Segment k: keys[k].t <= t < keys[k + 1].t.
        let k = self.keys.partition_point(|key| key.t <= t) - 1;
        let (k0, k1) = (&self.keys[k], &self.keys[k + 1]);
        let h = k1.t - k0.t;
        let s = (t - k0.t) / h;
        let (c0, c1) = (k0.pose.to_coordinates(), k1.pose.to_coordinates());
        let value = |c: usize| match self.interpolation {
            Interpolation::Linear => c0[c] + (c1[c] - c0[c]) * s,
            Interpolation::Smoothstep => {
                let w = s * s * s * (10.0 + s * (-15.0 + 6.0 * s));
                c0[c] + (c1[c] - c0[c]) * w
            }
            Interpolation::Cubic => {
                let m = &self.second_derivatives[c];
                let a = 1.0 - s;
                // Cubic on [t_k, t_k+1] with values y_k, y_k+1 and second derivatives m_k, m_k+1.
                a * c0[c]
                    + s * c1[c]
                    + ((a * a * a - a) * m[k] + (s * s * s - s) * m[k + 1]) * h * h / 6.0
            }
        };
        Pose::from_coordinates(std::array::from_fn(value))
    }
}

/// Second derivatives of the natural cubic spline through `(x_i, y_i)` (zero at both
/// ends), by the tridiagonal system of the continuity conditions (Thomas algorithm).
fn natural_spline_second_derivatives(x: &[f64], y: &[f64]) -> Vec<f64> {
    let n = x.len();
    let mut m = vec![0.0; n];
    if n < 3 {
        return m;
    }
    // Unknowns m_1 … m_{n−2}; row i: h_{i−1} m_{i−1} + 2(h_{i−1} + h_i) m_i + h_i m_{i+1} = r_i.
    let mut diag = vec![0.0; n];
    let mut rhs = vec![0.0; n];
    for i in 1..n - 1 {
        let h0 = x[i] - x[i - 1];
        let h1 = x[i + 1] - x[i];
        diag[i] = 2.0 * (h0 + h1);
        rhs[i] = 6.0 * ((y[i + 1] - y[i]) / h1 - (y[i] - y[i - 1]) / h0);
    }
    // Forward elimination.
    for i in 2..n - 1 {
        let h0 = x[i] - x[i - 1];
        let factor = h0 / diag[i - 1];
        diag[i] -= factor * h0;
        rhs[i] -= factor * rhs[i - 1];
    }
    // Back substitution.
    for i in (1..n - 1).rev() {
        let h1 = x[i + 1] - x[i];
        m[i] = (rhs[i] - h1 * m[i + 1]) / diag[i];
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    fn key(t: f64, x: f64, yaw_deg: f64) -> Keyframe {
        Keyframe {
            t,
            pose: Pose::from_xyz_rpy_deg([x, 0.0, 0.8], [0.0, 0.0, yaw_deg]),
        }
    }

    #[test]
    fn every_interpolation_passes_through_the_keys() {
        let keys = vec![
            key(0.0, 0.0, 0.0),
            key(1.0, 0.1, 10.0),
            key(3.0, -0.1, 5.0),
            key(4.0, 0.0, 0.0),
        ];
        for interp in [
            Interpolation::Linear,
            Interpolation::Smoothstep,
            Interpolation::Cubic,
        ] {
            let k = Keyframes::new(keys.clone(), interp).unwrap_or_else(|e| panic!("{e}"));
            for key in &keys {
                let p = k.pose_at(key.t);
                assert!(
                    (p.position - key.pose.position).norm() < 1e-15,
                    "{interp:?}"
                );
                assert!((p.yaw - key.pose.yaw).radians().abs() < 1e-15);
            }
            // Held before the first and after the last key.
            assert_eq!(k.pose_at(-1.0), keys[0].pose);
            assert_eq!(k.pose_at(9.0), keys[3].pose);
        }
    }

    #[test]
    fn cubic_spline_reproduces_a_straight_line_and_is_smooth() {
        // A natural spline through points on a line is that line.
        let keys: Vec<_> = [0.0, 0.5, 2.0, 2.5, 4.0]
            .iter()
            .map(|&t| key(t, 0.1 * t, 0.0))
            .collect();
        let k = Keyframes::new(keys, Interpolation::Cubic).unwrap_or_else(|e| panic!("{e}"));
        for i in 0..=40 {
            let t = i as f64 * 0.1;
            assert!((k.pose_at(t).position.x - 0.1 * t).abs() < 1e-15);
        }
        // Through a bump, the slope is continuous across a key (no corner).
        let keys = vec![key(0.0, 0.0, 0.0), key(1.0, 1.0, 0.0), key(2.0, 0.0, 0.0)];
        let k = Keyframes::new(keys, Interpolation::Cubic).unwrap_or_else(|e| panic!("{e}"));
        let e = 1e-6;
        let left = (k.pose_at(1.0).position.x - k.pose_at(1.0 - e).position.x) / e;
        let right = (k.pose_at(1.0 + e).position.x - k.pose_at(1.0).position.x) / e;
        assert!((left - right).abs() < 1e-4, "{left} vs {right}");
        // Hand value: natural spline through (0,0),(1,1),(2,0) has m1 = −3, so at
        // t = 0.5: 0.5·1 + (0.125 − 0.5)·(−3)/6 = 0.6875.
        assert!((k.pose_at(0.5).position.x - 0.6875).abs() < 1e-15);
    }

    #[test]
    fn smoothstep_stops_at_each_key() {
        let keys = vec![key(0.0, 0.0, 0.0), key(2.0, 1.0, 0.0)];
        let k = Keyframes::new(keys, Interpolation::Smoothstep).unwrap_or_else(|e| panic!("{e}"));
        let v = (k.pose_at(1e-4).position.x - k.pose_at(0.0).position.x) / 1e-4;
        assert!(v.abs() < 1e-6);
        assert!((k.pose_at(1.0).position.x - 0.5).abs() < 1e-15);
    }

    #[test]
    fn bad_keys_are_refused_with_their_number() {
        assert_eq!(
            Keyframes::new(vec![], Interpolation::Linear),
            Err(KeyframeError::Empty)
        );
        let keys = vec![key(0.0, 0.0, 0.0), key(1.0, 0.0, 0.0), key(1.0, 0.0, 0.0)];
        assert_eq!(
            Keyframes::new(keys, Interpolation::Linear)
                .unwrap_err()
                .to_string(),
            "key 3 is at t = 1 s, not after the previous key's 1 s: times must increase"
        );
        let keys = vec![key(0.0, f64::NAN, 0.0)];
        assert_eq!(
            Keyframes::new(keys, Interpolation::Linear),
            Err(KeyframeError::NotFinite { index: 1 })
        );
    }
}
