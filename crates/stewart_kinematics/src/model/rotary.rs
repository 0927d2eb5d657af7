//! Rotary-servo (6-RSS) actuators: a horn on each servo shaft and a rod of fixed length
//! from the horn's tip to the platform joint.
//!
//! Servo `i`'s shaft is horizontal, through the base joint `B_i` (z = 0), perpendicular to
//! the direction `β_i` in the base plane. Its horn tip is
//! `H_i = B_i + a (cos θ_i cos β_i, cos θ_i sin β_i, sin θ_i)`: `θ_i = 0` is the horn
//! horizontal along `β_i`, a positive `θ_i` lifts the tip. The rod closes
//! `|q_i − H_i| = s` with `q_i` the platform joint in the base frame.
//!
//! Its inverse kinematics in closed form (the horn angle that closes the rod) is
//! `crate::solve::servo_closure`'s.

use nalgebra::Vector3;
use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::model::angle::Angle;

/// Why rotary actuators were refused. Each names the scenario key at fault.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum RotaryError {
    /// A length that is not a positive finite number.
    #[error("`actuator.{key}` must be a positive finite number of metres, got {value}")]
    Length {
        /// `horn_length_m` or `rod_length_m`.
        key: &'static str,
        /// The value given.
        value: f64,
    },
    /// The horn is at least as long as the rod: the rod could fold onto the shaft.
    #[error(
        "`actuator.horn_length_m` ({horn} m) must be shorter than `actuator.rod_length_m` ({rod} m)"
    )]
    HornNotShorter {
        /// Horn length, metres.
        horn: f64,
        /// Rod length, metres.
        rod: f64,
    },
    /// A horn angle that is not finite.
    #[error("`actuator.horn_angles_deg[{index}]` must be a finite number of degrees, got {value}")]
    HornAngle {
        /// Index from 0, as in the file.
        index: usize,
        /// The value given.
        value: f64,
    },
    /// A trim that is not a finite number within ±180°.
    #[error(
        "`actuator.servo_trim_deg[{index}]` must be a finite number of degrees within ±180, got {value}"
    )]
    Trim {
        /// Index from 0, as in the file.
        index: usize,
        /// The value given.
        value: f64,
    },
    /// A servo range end outside (−180°, 180°], or a minimum not below the maximum.
    #[error("the servo range must lie in (-180, 180] degrees with min < max, got {min} … {max}")]
    Range {
        /// `servo_min_deg`.
        min: f64,
        /// `servo_max_deg`.
        max: f64,
    },
}

/// A percentage in words: one decimal (a reason shown live, `250.8`, does not flicker
/// through four changing decimals), and in scientific form from 10 000 on (`1.0e302`).
pub fn percent(x: f64) -> String {
    if x.is_finite() && x.abs() < 1e4 {
        format!("{x:.1}")
    } else {
        format!("{x:.1e}")
    }
}

/// No horn angle of servo `servo` reaches its platform joint.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error(
    "servo {servo} cannot reach its platform joint: no horn angle closes its rod ({} % beyond its reach)",
    percent(100.0 * *.excess)
)]
pub struct Unreachable {
    /// Servo number, from 1.
    pub servo: usize,
    /// `|L| / √(M² + N²)`, above 1 when unreachable.
    pub ratio: f64,
    /// `ratio − 1`: how far from reachable.
    pub excess: f64,
}

/// The servo side of a rotary platform: horn and rod lengths, horn directions, range.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RotaryActuators {
    horn_length: f64,
    rod_length: f64,
    horn_angles: [Angle; 6],
    range: Option<(Angle, Angle)>,
    /// Servos mounted mirrored: their commanded angle runs the other way.
    #[serde(default)]
    reversed: [bool; 6],
    /// Mounting offsets added to the commanded angle.
    #[serde(default)]
    trims: [Angle; 6],
}

impl RotaryActuators {
    /// Validated actuators: positive lengths with the horn shorter than the rod, finite
    /// horn directions `β_i`, and an optional servo range `(min, max)` within (−180°, 180°].
    pub fn new(
        horn_length: f64,
        rod_length: f64,
        horn_angles_deg: [f64; 6],
        range_deg: Option<(f64, f64)>,
    ) -> Result<Self, RotaryError> {
        for (key, value) in [("horn_length_m", horn_length), ("rod_length_m", rod_length)] {
            if !(value.is_finite() && value > 0.0) {
                return Err(RotaryError::Length { key, value });
            }
        }
        if horn_length >= rod_length {
            return Err(RotaryError::HornNotShorter {
                horn: horn_length,
                rod: rod_length,
            });
        }
        if let Some((index, &value)) = horn_angles_deg
            .iter()
            .enumerate()
            .find(|(_, v)| !v.is_finite())
        {
            return Err(RotaryError::HornAngle { index, value });
        }
        if let Some((min, max)) = range_deg {
            let inside = |v: f64| v > -180.0 && v <= 180.0;
            if !(inside(min) && inside(max) && min < max) {
                return Err(RotaryError::Range { min, max });
            }
        }
        Ok(Self {
            horn_length,
            rod_length,
            horn_angles: horn_angles_deg.map(Angle::from_degrees),
            range: range_deg.map(|(a, b)| (Angle::from_degrees(a), Angle::from_degrees(b))),
            reversed: [false; 6],
            trims: [Angle::ZERO; 6],
        })
    }

    /// The same servos with their mounting: which run mirrored, and the trim (degrees,
    /// within ±180°) added to each commanded angle.
    pub fn with_mounting(
        mut self,
        reversed: [bool; 6],
        trims_deg: [f64; 6],
    ) -> Result<Self, RotaryError> {
        if let Some((index, &value)) = trims_deg
            .iter()
            .enumerate()
            .find(|(_, v)| !(v.is_finite() && v.abs() <= 180.0))
        {
            return Err(RotaryError::Trim { index, value });
        }
        self.reversed = reversed;
        self.trims = trims_deg.map(Angle::from_degrees);
        Ok(self)
    }

    /// Which servos run mirrored.
    pub fn reversed(&self) -> &[bool; 6] {
        &self.reversed
    }

    /// The trims added to the commanded angles.
    pub fn trims(&self) -> &[Angle; 6] {
        &self.trims
    }

    /// The angle servo `i` (from 0) is commanded for model angle `theta`: mirrored when
    /// the servo is reversed, then trimmed, wrapped to (−180°, 180°].
    pub fn commanded(&self, i: usize, theta: Angle) -> Angle {
        let sign = if self.reversed[i] { -1.0 } else { 1.0 };
        Angle::from_radians(wrap_half_turn(
            sign * theta.radians() + self.trims[i].radians(),
        ))
    }

    /// The model angle of servo `i` commanded to `command` ([`RotaryActuators::commanded`]
    /// undone).
    pub fn model_angle(&self, i: usize, command: Angle) -> Angle {
        let sign = if self.reversed[i] { -1.0 } else { 1.0 };
        Angle::from_radians(wrap_half_turn(
            sign * (command.radians() - self.trims[i].radians()),
        ))
    }

    /// Horn length `a`, metres.
    pub fn horn_length(&self) -> f64 {
        self.horn_length
    }

    /// Rod length `s`, metres.
    pub fn rod_length(&self) -> f64 {
        self.rod_length
    }

    /// Horn directions `β_i` (where horn `i` points at servo angle 0).
    pub fn horn_angles(&self) -> &[Angle; 6] {
        &self.horn_angles
    }

    /// The servo range `(min, max)`, if one is set.
    pub fn range(&self) -> Option<(Angle, Angle)> {
        self.range
    }

    /// Horn tip `H_i` of servo `i` (from 0) at angle `theta`, for shaft centre `base`.
    pub fn horn_tip(&self, i: usize, base: &Vector3<f64>, theta: Angle) -> Vector3<f64> {
        self.tip_along(&self.horn_direction(i), base, theta)
    }

    /// Unit vector along which horn `i` points at servo angle 0: `(cos β_i, sin β_i, 0)`.
    pub(crate) fn horn_direction(&self, i: usize) -> Vector3<f64> {
        let (sb, cb) = self.horn_angles[i].radians().sin_cos();
        Vector3::new(cb, sb, 0.0)
    }

    /// The horn tip at angle `theta` of a servo whose horn points along `h` at angle 0
    /// (see [`RotaryActuators::horn_direction`]).
    pub(crate) fn tip_along(
        &self,
        h: &Vector3<f64>,
        base: &Vector3<f64>,
        theta: Angle,
    ) -> Vector3<f64> {
        let (st, ct) = theta.radians().sin_cos();
        base + self.horn_length * Vector3::new(ct * h.x, ct * h.y, st)
    }
}

/// `x` (radians) wrapped to (−π, π].
pub(crate) fn wrap_half_turn(x: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    let w = x - tau * (x / tau).round();
    if w <= -std::f64::consts::PI {
        w + tau
    } else {
        w
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_joint_far_out_of_reach_is_said_without_hundreds_of_digits() {
        let e = Unreachable {
            servo: 3,
            ratio: 1e300,
            excess: 1e300,
        };
        let text = e.to_string();
        assert!(text.contains("(1.0e302 % beyond its reach)"), "{text}");
        assert!(!text.contains('√'), "no formula in the words: {text}");
        let near = Unreachable {
            servo: 1,
            ratio: 1.125,
            excess: 0.125,
        };
        assert!(
            near.to_string().contains("(12.5 % beyond its reach)"),
            "{near}"
        );
        assert!(text.len() < 140, "{text}");
        assert_eq!(percent(250.831_7), "250.8");
        assert_eq!(percent(f64::INFINITY), "inf");
    }

    fn hobby() -> RotaryActuators {
        RotaryActuators::new(0.025, 0.12, [255.0, 105.0, 15.0, 225.0, 135.0, 345.0], None)
            .unwrap_or_else(|e| panic!("{e}"))
    }

    #[test]
    fn bad_actuators_name_their_key() {
        let e = |a, s, r| {
            RotaryActuators::new(a, s, [0.0; 6], r)
                .unwrap_err()
                .to_string()
        };
        assert_eq!(
            e(0.0, 0.1, None),
            "`actuator.horn_length_m` must be a positive finite number of metres, got 0"
        );
        assert_eq!(
            e(0.2, 0.1, None),
            "`actuator.horn_length_m` (0.2 m) must be shorter than `actuator.rod_length_m` (0.1 m)"
        );
        assert!(e(0.02, 0.1, Some((10.0, -10.0))).contains("min < max"));
        assert!(e(0.02, 0.1, Some((-180.0, 0.0))).contains("(-180, 180]"));
        let bad_angle = RotaryActuators::new(0.02, 0.1, [0.0, f64::NAN, 0.0, 0.0, 0.0, 0.0], None);
        assert_eq!(
            bad_angle.unwrap_err().to_string(),
            "`actuator.horn_angles_deg[1]` must be a finite number of degrees, got NaN"
        );
    }

    #[test]
    fn the_automatic_home_height_levels_the_horns() {
        // With every horn level (θ = 0) the tip is at B + a(cos β, sin β, 0), and the rod
        // reaches the platform joint straight from there: h = √(s² − d²), d the horizontal
        // distance from tip to joint (the test layout is three-fold symmetric, so one
        // servo's h is every servo's).
        let g = crate::test_support::servo_geometry();
        let servos = g.rotary().unwrap_or_else(|| panic!("not rotary"));
        let tip = servos.horn_tip(0, &g.base_joints()[0], Angle::ZERO);
        let joint = g.platform_joints()[0];
        let d2 = (joint.x - tip.x).powi(2) + (joint.y - tip.y).powi(2);
        let expected = (servos.rod_length().powi(2) - d2).sqrt();
        let h = g
            .servo_home_height()
            .unwrap_or_else(|| panic!("no level height"));
        assert!((h - expected).abs() < 1e-12, "{h} vs {expected}");
        assert!((0.115..0.12).contains(&h), "{h}");
        assert!(
            crate::model::geometry::Geometry::seed()
                .servo_home_height()
                .is_none()
        );
    }

    #[test]
    fn mounting_maps_model_angles_to_commands_and_back() {
        let act = hobby()
            .with_mounting(
                [false, true, false, false, false, false],
                [5.0, -3.0, 0.0, 0.0, 0.0, 0.0],
            )
            .unwrap_or_else(|e| panic!("{e}"));
        let theta = Angle::from_degrees(20.0);
        assert!((act.commanded(0, theta).degrees() - 25.0).abs() < 1e-12);
        assert!((act.commanded(1, theta).degrees() - (-23.0)).abs() < 1e-12);
        for i in 0..6 {
            for d in [-170.0, -20.0, 0.0, 33.0, 179.0] {
                let t = Angle::from_degrees(d);
                let back = act.model_angle(i, act.commanded(i, t));
                assert!(wrap_half_turn(back.radians() - t.radians()).abs() < 1e-12);
            }
        }
        let e = hobby().with_mounting([false; 6], [0.0, 0.0, 200.0, 0.0, 0.0, 0.0]);
        assert_eq!(
            e.unwrap_err().to_string(),
            "`actuator.servo_trim_deg[2]` must be a finite number of degrees within ±180, got 200"
        );
    }
}
