//! Platform geometry: radii, home height, joint angles, stroke limits, pivot.

use nalgebra::Vector3;
use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::angle::Angle;
use crate::layout::Layout;
use crate::pose::Pose;
use crate::rotary::{Actuator, RotaryActuators, Unreachable};

/// Which of the two plates a joint belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Plate {
    /// The fixed base.
    Base,
    /// The moving platform.
    Platform,
}

impl std::fmt::Display for Plate {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Plate::Base => "base",
            Plate::Platform => "platform",
        })
    }
}

/// Minimum and maximum leg length (the actuators' stroke), metres. Either may be absent.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct StrokeLimits {
    /// Shortest length a leg can take.
    pub min: Option<f64>,
    /// Longest length a leg can take.
    pub max: Option<f64>,
}

impl StrokeLimits {
    /// Limits from a minimum and a maximum length.
    pub fn new(min: f64, max: f64) -> Self {
        Self {
            min: Some(min),
            max: Some(max),
        }
    }

    /// Fraction of the stroke used by a leg of `length` (0 at `min`, 1 at `max`), when both limits exist.
    pub fn usage(&self, length: f64) -> Option<f64> {
        match (self.min, self.max) {
            (Some(lo), Some(hi)) => Some((length - lo) / (hi - lo)),
            _ => None,
        }
    }

    /// How far `length` lies outside the limits (positive = too long, negative = too short), or `None` inside.
    pub fn violation(&self, length: f64) -> Option<f64> {
        if let Some(hi) = self.max
            && length > hi
        {
            return Some(length - hi);
        }
        if let Some(lo) = self.min
            && length < lo
        {
            return Some(length - lo);
        }
        None
    }
}

/// Everything that describes a platform, as a user writes it down. Validate it with [`Geometry::new`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct GeometryParams {
    /// Radius of the circle through the base joints, metres.
    pub base_radius: f64,
    /// Radius of the circle through the platform joints, metres.
    pub platform_radius: f64,
    /// Height of the platform centre above the base centre at the home pose, metres.
    pub home_height: f64,
    /// Angle of base joint `i` (leg `i` starts there).
    pub base_angles: [Angle; 6],
    /// Angle of platform joint `i` in the platform frame (leg `i` ends there).
    pub platform_angles: [Angle; 6],
    /// Leg stroke limits.
    pub stroke: StrokeLimits,
    /// The point the platform rotates about, in the platform frame, metres. Zero (the
    /// platform centre) reproduces the seed.
    pub pivot: Vector3<f64>,
    /// What drives the joints: linear legs (default) or rotary servos.
    #[serde(default)]
    pub actuator: Actuator,
}

impl GeometryParams {
    /// The seed's platform: `r_b = 1.0 m`, `r_p = 0.6 m`, `h0 = 0.8 m`, staggered hexagons, no stroke limits.
    pub fn seed() -> Self {
        Self::from_layout(1.0, 0.6, 0.8, Layout::seed())
    }

    /// A platform with the given radii, home height and layout, no stroke limits, no pivot offset.
    pub fn from_layout(
        base_radius: f64,
        platform_radius: f64,
        home_height: f64,
        layout: Layout,
    ) -> Self {
        let (base_angles, platform_angles) = layout.angles();
        Self {
            base_radius,
            platform_radius,
            home_height,
            base_angles,
            platform_angles,
            stroke: StrokeLimits::default(),
            pivot: Vector3::zeros(),
            actuator: Actuator::Linear,
        }
    }
}

/// Why a geometry was refused. Each variant names the field (as spelled in scenario files) and the value.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum GeometryError {
    /// A number that must be finite is NaN or infinite.
    #[error("`{field}` must be a finite number, got {value}")]
    NotFinite {
        /// The field at fault.
        field: String,
        /// Its value.
        value: f64,
    },
    /// A length that must be positive is zero or negative.
    #[error("`{field}` must be positive, got {value}")]
    NotPositive {
        /// The field at fault.
        field: String,
        /// Its value.
        value: f64,
    },
    /// Two joints of one plate are at the same place.
    #[error(
        "{plate} joints {first} and {second} coincide (both at {angle_deg}°): the six joints of a plate must be distinct"
    )]
    DuplicateJoint {
        /// The plate.
        plate: Plate,
        /// Joint number, from 1.
        first: usize,
        /// Joint number, from 1.
        second: usize,
        /// Their angle in degrees.
        angle_deg: f64,
    },
    /// A stroke limit on a rotary platform (servos have a range instead).
    #[error(
        "`{key}` belongs to linear legs: a rotary platform's rods have a fixed length (give `actuator.servo_min_deg` and `servo_max_deg` for the servo range)"
    )]
    StrokeOnRotary {
        /// `leg_min` or `leg_max`.
        key: &'static str,
    },
    /// The stroke limits are empty.
    #[error("`leg_min` ({min} m) must be less than `leg_max` ({max} m)")]
    StrokeOrder {
        /// Minimum leg length.
        min: f64,
        /// Maximum leg length.
        max: f64,
    },
}

/// A validated platform geometry with its joint positions computed.
#[derive(Clone, Debug, PartialEq)]
pub struct Geometry {
    params: GeometryParams,
    base_joints: [Vector3<f64>; 6],
    platform_joints: [Vector3<f64>; 6],
}

/// Two joints closer in angle than this (radians, about 5.7e-8°) count as the same joint.
const SAME_JOINT_ANGLE: f64 = 1e-9;

impl Geometry {
    /// Validate `params` and compute the joint positions.
    pub fn new(params: GeometryParams) -> Result<Self, GeometryError> {
        check_positive("base_radius", params.base_radius)?;
        check_positive("platform_radius", params.platform_radius)?;
        check_positive("home_height", params.home_height)?;
        check_angles(Plate::Base, "base_angles_deg", &params.base_angles)?;
        check_angles(
            Plate::Platform,
            "platform_angles_deg",
            &params.platform_angles,
        )?;
        if matches!(params.actuator, Actuator::Rotary(_)) {
            for (key, value) in [
                ("leg_min", params.stroke.min),
                ("leg_max", params.stroke.max),
            ] {
                if value.is_some() {
                    return Err(GeometryError::StrokeOnRotary { key });
                }
            }
        }
        if let Some(min) = params.stroke.min {
            check_positive("leg_min", min)?;
        }
        if let Some(max) = params.stroke.max {
            check_positive("leg_max", max)?;
        }
        if let (Some(min), Some(max)) = (params.stroke.min, params.stroke.max)
            && min >= max
        {
            return Err(GeometryError::StrokeOrder { min, max });
        }
        for (axis, v) in ["x", "y", "z"].iter().zip(params.pivot.iter()) {
            check_finite(&format!("pivot.{axis}"), *v)?;
        }
        let base_joints = joints_on_circle(params.base_radius, &params.base_angles);
        let platform_joints = joints_on_circle(params.platform_radius, &params.platform_angles);
        Ok(Self {
            params,
            base_joints,
            platform_joints,
        })
    }

    /// The seed's geometry.
    pub fn seed() -> Self {
        // The seed parameters are constants that pass validation.
        Self::new(GeometryParams::seed()).unwrap_or_else(|e| unreachable!("seed geometry: {e}"))
    }

    /// The parameters this geometry was built from.
    pub fn params(&self) -> &GeometryParams {
        &self.params
    }

    /// Base joint positions `b_i` in the base frame, metres.
    pub fn base_joints(&self) -> &[Vector3<f64>; 6] {
        &self.base_joints
    }

    /// Platform joint positions `a_i` in the platform frame, metres.
    pub fn platform_joints(&self) -> &[Vector3<f64>; 6] {
        &self.platform_joints
    }

    /// Leg stroke limits.
    pub fn stroke(&self) -> StrokeLimits {
        self.params.stroke
    }

    /// Rotation centre in the platform frame, metres.
    pub fn pivot(&self) -> Vector3<f64> {
        self.params.pivot
    }

    /// What drives the joints.
    pub fn actuator(&self) -> &Actuator {
        &self.params.actuator
    }

    /// The servos, for a rotary platform.
    pub fn rotary(&self) -> Option<&RotaryActuators> {
        match &self.params.actuator {
            Actuator::Rotary(r) => Some(r),
            Actuator::Linear => None,
        }
    }

    /// The home height at which the servos stand level (mean servo angle zero) with the
    /// platform centred and level, for a rotary platform: where the horns have the most
    /// travel both ways. `None` for linear legs, or when no height between the base and
    /// `a + s` above it gets there. Found by a scan for the sign change of the mean
    /// angle, then bisection to the last bit.
    pub fn servo_home_height(&self) -> Option<f64> {
        let servos = self.rotary()?;
        let mean_angle = |h: f64| -> Option<f64> {
            let pose = Pose::new(
                Vector3::new(0.0, 0.0, h),
                Angle::ZERO,
                Angle::ZERO,
                Angle::ZERO,
            );
            let joints = self.inverse(&pose).platform_joints;
            let angles = servos.servo_angles(&self.base_joints, &joints).ok()?;
            Some(angles.iter().map(|a| a.radians()).sum::<f64>() / 6.0)
        };
        let top = servos.horn_length() + servos.rod_length() + self.pivot().z.abs();
        let steps = 400;
        let mut last: Option<(f64, f64)> = None;
        for k in 1..=steps {
            let h = top * f64::from(k) / f64::from(steps);
            let Some(m) = mean_angle(h) else {
                last = None;
                continue;
            };
            if let Some((h0, m0)) = last
                && m0 <= 0.0
                && m >= 0.0
            {
                let (mut lo, mut hi) = (h0, h);
                for _ in 0..80 {
                    let mid = 0.5 * (lo + hi);
                    match mean_angle(mid) {
                        Some(v) if v < 0.0 => lo = mid,
                        Some(_) => hi = mid,
                        None => break,
                    }
                }
                return Some(0.5 * (lo + hi));
            }
            last = Some((h, m));
        }
        None
    }

    /// The six servo angles that hold `pose`, for a rotary platform (`None` for linear
    /// legs), or the first servo that cannot reach its joint.
    pub fn servo_angles(&self, pose: &Pose) -> Option<Result<[Angle; 6], Unreachable>> {
        let servos = self.rotary()?;
        let joints = self.inverse(pose).platform_joints;
        Some(servos.servo_angles(&self.base_joints, &joints))
    }

    /// Height of the platform centre at the home pose, metres.
    pub fn home_height(&self) -> f64 {
        self.params.home_height
    }
}

fn joints_on_circle(radius: f64, angles: &[Angle; 6]) -> [Vector3<f64>; 6] {
    angles.map(|a| {
        let (s, c) = a.sin_cos();
        Vector3::new(radius * c, radius * s, 0.0)
    })
}

fn check_finite(field: &str, value: f64) -> Result<(), GeometryError> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(GeometryError::NotFinite {
            field: field.to_owned(),
            value,
        })
    }
}

fn check_positive(field: &str, value: f64) -> Result<(), GeometryError> {
    check_finite(field, value)?;
    if value > 0.0 {
        Ok(())
    } else {
        Err(GeometryError::NotPositive {
            field: field.to_owned(),
            value,
        })
    }
}

fn check_angles(plate: Plate, field: &str, angles: &[Angle; 6]) -> Result<(), GeometryError> {
    for (i, a) in angles.iter().enumerate() {
        check_finite(&format!("{field}[{i}]"), a.degrees())?;
    }
    for i in 0..6 {
        for j in i + 1..6 {
            let d = (angles[i] - angles[j])
                .radians()
                .rem_euclid(std::f64::consts::TAU);
            if d < SAME_JOINT_ANGLE || std::f64::consts::TAU - d < SAME_JOINT_ANGLE {
                return Err(GeometryError::DuplicateJoint {
                    plate,
                    first: i + 1,
                    second: j + 1,
                    angle_deg: angles[i].degrees(),
                });
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seed_joints_are_where_the_article_puts_them() {
        let g = Geometry::seed();
        let b = g.base_joints();
        let a = g.platform_joints();
        assert!((b[0] - Vector3::new(1.0, 0.0, 0.0)).norm() < 1e-15);
        assert!((b[3] - Vector3::new(-1.0, 0.0, 0.0)).norm() < 1e-15);
        // Platform joint 1 at 30°: (0.6·√3/2, 0.6/2, 0).
        assert!((a[0] - Vector3::new(0.3 * 3f64.sqrt(), 0.3, 0.0)).norm() < 1e-15);
        assert!((a[4] - Vector3::new(0.0, -0.6, 0.0)).norm() < 1e-15);
    }

    #[test]
    fn validation_names_the_field_and_value() {
        let mut p = GeometryParams::seed();
        p.base_radius = -1.0;
        assert_eq!(
            Geometry::new(p).unwrap_err().to_string(),
            "`base_radius` must be positive, got -1"
        );

        let mut p = GeometryParams::seed();
        p.home_height = f64::NAN;
        assert!(matches!(
            Geometry::new(p),
            Err(GeometryError::NotFinite { ref field, .. }) if field == "home_height"
        ));

        let mut p = GeometryParams::seed();
        p.platform_angles[4] = Angle::from_degrees(30.0 + 360.0);
        assert!(matches!(
            Geometry::new(p),
            Err(GeometryError::DuplicateJoint {
                plate: Plate::Platform,
                first: 1,
                second: 5,
                ..
            })
        ));

        let mut p = GeometryParams::seed();
        p.stroke = StrokeLimits::new(1.2, 0.9);
        assert!(matches!(
            Geometry::new(p),
            Err(GeometryError::StrokeOrder { .. })
        ));

        let mut p = GeometryParams::seed();
        p.pivot.z = f64::INFINITY;
        assert!(
            Geometry::new(p)
                .unwrap_err()
                .to_string()
                .contains("pivot.z")
        );

        let mut p = GeometryParams::seed();
        p.base_angles[2] = Angle::from_degrees(f64::NAN);
        assert!(
            Geometry::new(p)
                .unwrap_err()
                .to_string()
                .contains("base_angles_deg[2]")
        );
    }

    #[test]
    fn stroke_usage_and_violation() {
        let s = StrokeLimits::new(0.5, 1.0);
        assert_eq!(s.usage(0.75), Some(0.5));
        assert_eq!(s.violation(0.75), None);
        assert!((s.violation(1.25).unwrap_or(0.0) - 0.25).abs() < 1e-15);
        assert!((s.violation(0.25).unwrap_or(0.0) + 0.25).abs() < 1e-15);
        assert_eq!(StrokeLimits::default().violation(100.0), None);
    }
}
