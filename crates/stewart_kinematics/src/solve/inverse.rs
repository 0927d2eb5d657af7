//! Inverse kinematics: platform pose → joint positions, leg vectors and leg lengths.
//!
//! With `p` the pose position, `R` its rotation, `c` the pivot (platform frame),
//! `a_i` the platform joints (platform frame) and `b_i` the base joints:
//!
//! ```text
//! q_i = p + c + R (a_i − c)      platform joint i in the base frame
//! l_i = q_i − b_i                leg vector
//! L_i = |l_i|                    leg length
//! ```
//!
//! With `c = 0` these are the seed's formulas `q_i = p + R a_i` exactly.

use nalgebra::{Matrix3, Vector3};

use crate::model::geometry::Geometry;
use crate::model::leg_solution::LegSolution;
use crate::model::pose::Pose;

/// See [`Geometry::inverse`].
pub(crate) fn inverse(geometry: &Geometry, pose: &Pose) -> LegSolution {
    let r = pose.rotation();
    let platform_joints = geometry.platform_joints_for(&pose.position, &r);
    let legs = std::array::from_fn(|i| platform_joints[i] - geometry.base_joints()[i]);
    let lengths = legs.map(|l: Vector3<f64>| l.norm());
    LegSolution {
        platform_joints,
        legs,
        lengths,
    }
}

/// See [`Geometry::leg_lengths`].
pub(crate) fn leg_lengths(geometry: &Geometry, pose: &Pose) -> [f64; 6] {
    geometry.inverse(pose).lengths
}

/// See [`Geometry::platform_joints_for`].
pub(crate) fn platform_joints_for(
    geometry: &Geometry,
    position: &Vector3<f64>,
    rotation: &Matrix3<f64>,
) -> [Vector3<f64>; 6] {
    let c = geometry.pivot();
    geometry
        .platform_joints()
        .map(|a| position + c + rotation * (a - c))
}

/// See [`Geometry::platform_centre`].
pub(crate) fn platform_centre(geometry: &Geometry, pose: &Pose) -> Vector3<f64> {
    let c = geometry.pivot();
    pose.position + c - pose.rotation() * c
}

/// See [`Geometry::home_pose`].
pub(crate) fn home_pose(geometry: &Geometry) -> Pose {
    Pose::level_at(geometry.home_height())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::angle::Angle;
    use crate::model::geometry::GeometryParams;
    use proptest::prelude::*;

    /// Seed home leg length by hand: base joint at radius 1, platform joint at radius
    /// 0.6 turned 30° further, 0.8 higher. Law of cosines in the plane plus the height:
    /// L² = 1 + 0.36 − 2·0.6·cos 30° + 0.64 = 2 − 0.6·√3.
    fn seed_home_length() -> f64 {
        (2.0 - 0.6 * 3f64.sqrt()).sqrt()
    }

    #[test]
    fn home_pose_gives_six_equal_hand_computed_lengths() {
        let g = Geometry::seed();
        let lengths = g.leg_lengths(&g.home_pose());
        for l in lengths {
            assert!((l - seed_home_length()).abs() < 1e-15, "{l}");
        }
        assert!((seed_home_length() - 0.980_188_510_164_587_5).abs() < 1e-12);
    }

    #[test]
    fn pure_heave_follows_pythagoras() {
        // Planar distance is fixed (1.36 − 0.6√3); height adds in quadrature.
        let g = Geometry::seed();
        for z in [0.3, 0.55, 1.2] {
            let expected = (1.36 - 0.6 * 3f64.sqrt() + z * z).sqrt();
            for l in g.leg_lengths(&Pose::level_at(z)) {
                assert!((l - expected).abs() < 1e-15);
            }
        }
    }

    #[test]
    fn pure_yaw_changes_the_angle_between_joints() {
        // Yaw ψ turns every platform joint by ψ: the angle between base joint and
        // platform joint becomes 30° + ψ for every leg, so L² = 2 − 1.2·cos(30° + ψ).
        let g = Geometry::seed();
        for psi in [-25.0f64, -8.0, 5.0, 40.0] {
            let pose = Pose::from_xyz_rpy_deg([0.0, 0.0, 0.8], [0.0, 0.0, psi]);
            let expected = (2.0 - 1.2 * (30.0 + psi).to_radians().cos()).sqrt();
            for l in g.leg_lengths(&pose) {
                assert!((l - expected).abs() < 1e-14, "{psi}: {l} vs {expected}");
            }
        }
    }

    #[test]
    fn pure_roll_hand_case_for_leg_on_the_axis() {
        // Roll 10° about x. Platform joint 5 sits at 270° = (0, −0.6, 0); the roll takes
        // it to (0, −0.6 cos10°, −0.6 sin10°). Base joint 5 is at 240° = (−0.5, −√3/2, 0).
        let g = Geometry::seed();
        let r = 10f64.to_radians();
        let pose = Pose::from_xyz_rpy_deg([0.0, 0.0, 0.8], [10.0, 0.0, 0.0]);
        let q = Vector3::new(0.0, -0.6 * r.cos(), 0.8 - 0.6 * r.sin());
        let b = Vector3::new(-0.5, -(3f64.sqrt()) / 2.0, 0.0);
        assert!((g.leg_lengths(&pose)[4] - (q - b).norm()).abs() < 1e-15);
    }

    #[test]
    fn pivot_offset_keeps_the_pivot_still_while_rotating() {
        let mut params = GeometryParams::seed();
        params.pivot = Vector3::new(0.1, -0.05, 0.4);
        let g = Geometry::new(params).unwrap_or_else(|e| panic!("{e}"));
        let pose = Pose::from_xyz_rpy_deg([0.02, 0.03, 0.8], [7.0, -4.0, 12.0]);
        let level = Pose {
            roll: Angle::ZERO,
            pitch: Angle::ZERO,
            yaw: Angle::ZERO,
            ..pose
        };
        // The pivot point, fixed to the platform, is at the same place rotated or not.
        let pivot_in_base = |p: &Pose| g.platform_centre(p) + p.rotation() * g.pivot();
        assert!((pivot_in_base(&pose) - pivot_in_base(&level)).norm() < 1e-15);
        // The rotation still moves the joints.
        let moved = g.inverse(&pose).platform_joints;
        let still = g.inverse(&level).platform_joints;
        assert!((moved[0] - still[0]).norm() > 0.01);
        // A pivot at the platform centre reproduces the seed formula q = p + R a.
        let seed = Geometry::seed();
        let sol = seed.inverse(&pose);
        for i in 0..6 {
            let q = pose.position + pose.rotation() * seed.platform_joints()[i];
            assert_eq!(sol.platform_joints[i], q);
        }
    }

    proptest! {
        #[test]
        fn platform_stays_rigid_and_legs_connect_the_joints(
            x in -2.0f64..2.0, y in -2.0f64..2.0, z in -2.0f64..2.0,
            r in -180.0f64..180.0, p in -90.0f64..90.0, w in -180.0f64..180.0,
            cx in -0.5f64..0.5, cz in -0.5f64..0.5,
        ) {
            let mut params = GeometryParams::seed();
            params.pivot = Vector3::new(cx, 0.0, cz);
            let g = Geometry::new(params).unwrap_or_else(|e| panic!("{e}"));
            let pose = Pose::from_xyz_rpy_deg([x, y, z], [r, p, w]);
            let sol = g.inverse(&pose);
            for i in 0..6 {
                for j in 0..6 {
                    let before = (g.platform_joints()[i] - g.platform_joints()[j]).norm();
                    let after = (sol.platform_joints[i] - sol.platform_joints[j]).norm();
                    prop_assert!((before - after).abs() < 1e-14);
                }
                prop_assert!((g.base_joints()[i] + sol.legs[i] - sol.platform_joints[i]).norm() < 1e-14);
                prop_assert!((sol.lengths[i] - sol.legs[i].norm()).abs() == 0.0);
                // Distance from the rotated joint to the platform centre stays the radius
                // (joints lie in the platform's plane through its centre).
                let centre = g.platform_centre(&pose);
                prop_assert!(((sol.platform_joints[i] - centre).norm() - 0.6).abs() < 1e-14);
            }
        }
    }
}
