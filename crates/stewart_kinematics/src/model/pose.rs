//! Platform pose: position of the platform centre and ZYX Euler angles.

use nalgebra::{Matrix3, Vector3};
use serde::{Deserialize, Serialize};

use crate::model::angle::Angle;

/// Pose of the moving platform relative to the base frame.
///
/// `position` is where the platform centre is when the rotation is zero (with no pivot
/// offset it is simply the platform centre), in metres. The orientation is given by
/// ZYX Euler angles: `R = Rz(yaw) · Ry(pitch) · Rx(roll)`, so a vector is rolled first,
/// then pitched, then yawed (the seed's convention).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Pose {
    /// Position in the base frame, metres.
    pub position: Vector3<f64>,
    /// Rotation about the x axis (applied first).
    pub roll: Angle,
    /// Rotation about the y axis (applied second).
    pub pitch: Angle,
    /// Rotation about the z axis (applied last).
    pub yaw: Angle,
}

impl Pose {
    /// A pose from a position in metres and three angles.
    pub fn new(position: Vector3<f64>, roll: Angle, pitch: Angle, yaw: Angle) -> Self {
        Self {
            position,
            roll,
            pitch,
            yaw,
        }
    }

    /// A pose from `x, y, z` in metres and roll, pitch, yaw in degrees.
    pub fn from_xyz_rpy_deg(xyz: [f64; 3], rpy_deg: [f64; 3]) -> Self {
        Self::new(
            Vector3::new(xyz[0], xyz[1], xyz[2]),
            Angle::from_degrees(rpy_deg[0]),
            Angle::from_degrees(rpy_deg[1]),
            Angle::from_degrees(rpy_deg[2]),
        )
    }

    /// The level pose at height `z` above the base centre.
    pub fn level_at(z: f64) -> Self {
        Self::new(
            Vector3::new(0.0, 0.0, z),
            Angle::ZERO,
            Angle::ZERO,
            Angle::ZERO,
        )
    }

    /// The same orientation at another position.
    pub fn with_position(self, position: Vector3<f64>) -> Self {
        Self { position, ..self }
    }

    /// The pose as a table row `[x, y, z, roll, pitch, yaw]` (metres, degrees), as pose
    /// tables, `solve` and the Python package write it.
    pub fn to_row(&self) -> [f64; 6] {
        let [r, p, y] = self.rpy_degrees();
        [self.position.x, self.position.y, self.position.z, r, p, y]
    }

    /// The pose of a table row `[x, y, z, roll, pitch, yaw]` (metres, degrees).
    pub fn from_row(row: &[f64; 6]) -> Self {
        Self::from_xyz_rpy_deg([row[0], row[1], row[2]], [row[3], row[4], row[5]])
    }

    /// `[x, y, z, roll, pitch, yaw]` in metres and radians: the pose as six numbers
    /// (for solvers and interpolation).
    pub fn to_coordinates(&self) -> [f64; 6] {
        [
            self.position.x,
            self.position.y,
            self.position.z,
            self.roll.radians(),
            self.pitch.radians(),
            self.yaw.radians(),
        ]
    }

    /// The pose from `[x, y, z, roll, pitch, yaw]` in metres and radians.
    pub fn from_coordinates(c: [f64; 6]) -> Self {
        Self::new(
            Vector3::new(c[0], c[1], c[2]),
            Angle::from_radians(c[3]),
            Angle::from_radians(c[4]),
            Angle::from_radians(c[5]),
        )
    }

    /// Rotation matrix `Rz(yaw) · Ry(pitch) · Rx(roll)`.
    pub fn rotation(&self) -> Matrix3<f64> {
        rotation_zyx(self.roll, self.pitch, self.yaw)
    }

    /// `[roll, pitch, yaw]` in degrees.
    pub fn rpy_degrees(&self) -> [f64; 3] {
        [
            self.roll.degrees(),
            self.pitch.degrees(),
            self.yaw.degrees(),
        ]
    }

    /// Whether every component is a finite number.
    pub fn is_finite(&self) -> bool {
        self.position.iter().all(|v| v.is_finite())
            && self.roll.is_finite()
            && self.pitch.is_finite()
            && self.yaw.is_finite()
    }
}

/// Elementary rotation about x by `a` (right-handed).
pub fn rot_x(a: Angle) -> Matrix3<f64> {
    let (s, c) = a.sin_cos();
    Matrix3::new(1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c)
}

/// Elementary rotation about y by `a` (right-handed).
pub fn rot_y(a: Angle) -> Matrix3<f64> {
    let (s, c) = a.sin_cos();
    Matrix3::new(c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c)
}

/// Elementary rotation about z by `a` (right-handed).
pub fn rot_z(a: Angle) -> Matrix3<f64> {
    let (s, c) = a.sin_cos();
    Matrix3::new(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0)
}

/// `Rz(yaw) · Ry(pitch) · Rx(roll)`, written out in closed form.
///
/// The product of the three elementary matrices, expanded by hand; tests check it
/// against the explicit product.
pub fn rotation_zyx(roll: Angle, pitch: Angle, yaw: Angle) -> Matrix3<f64> {
    let (sr, cr) = roll.sin_cos();
    let (sp, cp) = pitch.sin_cos();
    let (sy, cy) = yaw.sin_cos();
    rotation_zyx_from_sin_cos([sr, cr], [sp, cp], [sy, cy])
}

/// The ZYX rotation from precomputed `[sin, cos]` of roll, pitch and yaw.
#[inline]
pub(crate) fn rotation_zyx_from_sin_cos(
    [sr, cr]: [f64; 2],
    [sp, cp]: [f64; 2],
    [sy, cy]: [f64; 2],
) -> Matrix3<f64> {
    Matrix3::new(
        cy * cp,
        cy * sp * sr - sy * cr,
        cy * sp * cr + sy * sr,
        sy * cp,
        sy * sp * sr + cy * cr,
        sy * sp * cr - cy * sr,
        -sp,
        cp * sr,
        cp * cr,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn deg(d: f64) -> Angle {
        Angle::from_degrees(d)
    }

    #[test]
    fn elementary_rotations_turn_axes_the_right_handed_way() {
        // +90° about z takes x to y; about x takes y to z; about y takes z to x.
        let x = Vector3::x();
        let y = Vector3::y();
        let z = Vector3::z();
        assert!((rot_z(deg(90.0)) * x - y).norm() < 1e-15);
        assert!((rot_x(deg(90.0)) * y - z).norm() < 1e-15);
        assert!((rot_y(deg(90.0)) * z - x).norm() < 1e-15);
    }

    #[test]
    fn zyx_order_rolls_first_then_pitches_then_yaws() {
        // Roll 90° takes y to z; pitch 90° then takes z to x; yaw 90° takes x to y.
        let r = rotation_zyx(deg(90.0), deg(90.0), deg(90.0));
        assert!((r * Vector3::y() - Vector3::y()).norm() < 1e-15);
        // The other order (XYZ) would give a different result for the same vector.
        let xyz = rot_x(deg(90.0)) * rot_y(deg(90.0)) * rot_z(deg(90.0));
        assert!((xyz * Vector3::y() - Vector3::y()).norm() > 0.5);
    }

    proptest! {
        #[test]
        fn closed_form_matches_product_and_is_a_rotation(
            r in -360.0f64..360.0, p in -360.0f64..360.0, y in -360.0f64..360.0
        ) {
            let closed = rotation_zyx(deg(r), deg(p), deg(y));
            let product = rot_z(deg(y)) * rot_y(deg(p)) * rot_x(deg(r));
            prop_assert!((closed - product).abs().max() < 1e-15);
            let should_be_identity = closed.transpose() * closed;
            prop_assert!((should_be_identity - Matrix3::identity()).abs().max() < 1e-14);
            prop_assert!((closed.determinant() - 1.0).abs() < 1e-14);
        }
    }
}
