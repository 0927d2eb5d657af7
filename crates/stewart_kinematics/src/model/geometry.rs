//! Platform geometry: where the joints are (on circles, or at any 3-D points), home
//! height, stroke limits, pivot.

use nalgebra::Vector3;
use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::model::actuator::Actuator;
use crate::model::angle::Angle;
use crate::model::layout::Layout;
use crate::model::rotary::RotaryActuators;

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

/// Where the six joints of one plate are, in the plate's own frame.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PlateJoints {
    /// On a circle about the plate's origin in its plane `z = 0`.
    Circle {
        /// Radius of the circle, metres.
        radius: f64,
        /// Angle of joint `i` about the plate's z axis, from its x axis.
        angles: [Angle; 6],
    },
    /// At six points `(x, y, z)`, metres: any as-built layout.
    Points([Vector3<f64>; 6]),
}

impl PlateJoints {
    /// The six joint positions in the plate's frame, metres.
    pub fn points(&self) -> [Vector3<f64>; 6] {
        match self {
            PlateJoints::Circle { radius, angles } => joints_on_circle(*radius, angles),
            PlateJoints::Points(p) => *p,
        }
    }

    /// Radius and angles, for joints on a circle.
    pub fn circle(&self) -> Option<(f64, &[Angle; 6])> {
        match self {
            PlateJoints::Circle { radius, angles } => Some((*radius, angles)),
            PlateJoints::Points(_) => None,
        }
    }

    /// The same joints as points (a circle's joints computed).
    pub fn as_points(&self) -> Self {
        PlateJoints::Points(self.points())
    }
}

/// Everything that describes a platform, as a user writes it down. Validate it with [`Geometry::new`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct GeometryParams {
    /// The base joints (leg `i` starts at base joint `i`), base frame.
    pub base: PlateJoints,
    /// The platform joints (leg `i` ends at platform joint `i`), platform frame.
    pub platform: PlateJoints,
    /// Height of the platform centre above the base centre at the home pose, metres.
    pub home_height: f64,
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

    /// The joints of `plate`.
    pub fn plate(&self, plate: Plate) -> &PlateJoints {
        match plate {
            Plate::Base => &self.base,
            Plate::Platform => &self.platform,
        }
    }

    /// The joints of `plate`, to change them.
    pub fn plate_mut(&mut self, plate: Plate) -> &mut PlateJoints {
        match plate {
            Plate::Base => &mut self.base,
            Plate::Platform => &mut self.platform,
        }
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
            base: PlateJoints::Circle {
                radius: base_radius,
                angles: base_angles,
            },
            platform: PlateJoints::Circle {
                radius: platform_radius,
                angles: platform_angles,
            },
            home_height,
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
    /// Two joints of one plate given as coordinates are at the same point.
    #[error(
        "{plate} joints {first} and {second} coincide (both at ({x}, {y}, {z}) m): the six joints of a plate must be distinct"
    )]
    CoincidentJoints {
        /// The plate.
        plate: Plate,
        /// Joint number, from 1.
        first: usize,
        /// Joint number, from 1.
        second: usize,
        /// Where, metres.
        x: f64,
        /// Where, metres.
        y: f64,
        /// Where, metres.
        z: f64,
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
        check_plate(Plate::Base, &params.base)?;
        check_plate(Plate::Platform, &params.platform)?;
        check_positive("home_height", params.home_height)?;
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
        let base_joints = params.base.points();
        let platform_joints = params.platform.points();
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

    /// The joints of `plate` in its own frame.
    pub fn joints(&self, plate: Plate) -> &[Vector3<f64>; 6] {
        match plate {
            Plate::Base => &self.base_joints,
            Plate::Platform => &self.platform_joints,
        }
    }

    /// The size of `plate`: the largest distance of one of its joints from the plate's
    /// origin, metres (the radius, for joints on a circle).
    pub fn plate_radius(&self, plate: Plate) -> f64 {
        self.joints(plate)
            .iter()
            .map(|j| j.norm())
            .fold(0.0, f64::max)
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
        self.params.actuator.rotary()
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

/// Two joints closer than this (metres) count as the same joint.
const SAME_JOINT_DISTANCE: f64 = 1e-9;

/// Check one plate's joints: a positive radius and distinct angles, or six finite and
/// distinct points. Fields are named as in scenario files.
fn check_plate(plate: Plate, joints: &PlateJoints) -> Result<(), GeometryError> {
    match joints {
        PlateJoints::Circle { radius, angles } => {
            check_positive(&format!("{plate}_radius"), *radius)?;
            check_angles(plate, &format!("{plate}_angles_deg"), angles)
        }
        PlateJoints::Points(points) => {
            for (i, p) in points.iter().enumerate() {
                for (k, v) in p.iter().enumerate() {
                    check_finite(&format!("{plate}_joints_m[{i}][{k}]"), *v)?;
                }
            }
            for i in 0..6 {
                for j in i + 1..6 {
                    if (points[i] - points[j]).norm() < SAME_JOINT_DISTANCE {
                        return Err(GeometryError::CoincidentJoints {
                            plate,
                            first: i + 1,
                            second: j + 1,
                            x: points[i].x,
                            y: points[i].y,
                            z: points[i].z,
                        });
                    }
                }
            }
            Ok(())
        }
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
        p.base = PlateJoints::Circle {
            radius: -1.0,
            angles: Layout::seed().angles().0,
        };
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
        let (_, mut angles) = Layout::seed().angles();
        angles[4] = Angle::from_degrees(30.0 + 360.0);
        p.platform = PlateJoints::Circle {
            radius: 0.6,
            angles,
        };
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
        let (mut angles, _) = Layout::seed().angles();
        angles[2] = Angle::from_degrees(f64::NAN);
        p.base = PlateJoints::Circle {
            radius: 1.0,
            angles,
        };
        assert!(
            Geometry::new(p)
                .unwrap_err()
                .to_string()
                .contains("base_angles_deg[2]")
        );

        let mut p = GeometryParams::seed();
        let mut points = p.platform.points();
        points[3].y = f64::INFINITY;
        p.platform = PlateJoints::Points(points);
        assert_eq!(
            Geometry::new(p).unwrap_err().to_string(),
            "`platform_joints_m[3][1]` must be a finite number, got inf"
        );

        let mut p = GeometryParams::seed();
        let mut points = p.base.points();
        points[5] = points[1];
        p.base = PlateJoints::Points(points);
        assert!(matches!(
            Geometry::new(p),
            Err(GeometryError::CoincidentJoints {
                plate: Plate::Base,
                first: 2,
                second: 6,
                ..
            })
        ));
    }

    #[test]
    fn a_circle_given_as_points_is_the_same_platform() {
        let circle = Geometry::seed();
        let mut p = GeometryParams::seed();
        p.base = p.base.as_points();
        p.platform = p.platform.as_points();
        let points = Geometry::new(p).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(circle.base_joints(), points.base_joints());
        assert_eq!(circle.platform_joints(), points.platform_joints());
        assert!((points.plate_radius(Plate::Base) - 1.0).abs() < 1e-15);
        assert!((points.plate_radius(Plate::Platform) - 0.6).abs() < 1e-15);
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
