//! What the actuators do, whatever their kind: the quantity that drives each joint (a
//! leg's length, or a servo's angle), its name and unit, its limits, and its value along
//! a motion. The plots, leg bars and readouts read it from here.

use crate::model::actuator::{Actuator, ActuatorKind, Quantity};
use crate::model::geometry::Geometry;
use crate::model::pose::Pose;
use crate::model::rotary::Unreachable;
use crate::solve::forward::ForwardError;
use crate::solve::servo_closure;

/// See [`Geometry::quantity`].
pub(crate) fn quantity(geometry: &Geometry) -> Quantity {
    geometry.actuator().kind().quantity()
}

/// Whether the actuators are rotary servos: the solvers below dispatch on it.
fn servos(geometry: &Geometry) -> bool {
    geometry.actuator().kind() == ActuatorKind::Rotary
}

/// See [`Geometry::actuator_rate_limits`].
pub(crate) fn actuator_rate_limits(
    geometry: &Geometry,
    limits: &crate::model::limits::Limits,
) -> [Option<f64>; 3] {
    geometry.actuator().kind().rate_limits(limits)
}

/// See [`Geometry::actuator_assembly_modes`].
pub(crate) fn actuator_assembly_modes(
    geometry: &Geometry,
    values: &[f64; 6],
) -> Result<Vec<crate::solve::forward::ForwardSolution>, ForwardError> {
    if servos(geometry) {
        geometry.servo_assembly_modes(&values.map(crate::model::angle::Angle::from_degrees))
    } else {
        geometry.assembly_modes(values)
    }
}

/// See [`Geometry::actuator_jacobian`].
pub(crate) fn actuator_jacobian(
    geometry: &Geometry,
    pose: &Pose,
) -> Result<nalgebra::Matrix6<f64>, Unreachable> {
    match geometry.servo_jacobian(pose) {
        None => Ok(geometry.jacobian(pose)),
        Some(j) => j,
    }
}

/// See [`Geometry::actuator_jacobian_and_conditioning`].
pub(crate) fn actuator_jacobian_and_conditioning(
    geometry: &Geometry,
    pose: &Pose,
) -> Option<(nalgebra::Matrix6<f64>, crate::solve::jacobian::Conditioning)> {
    let j = geometry.actuator_jacobian(pose).ok()?;
    let conditioning = if servos(geometry) {
        geometry.servo_conditioning_of(&j)?
    } else {
        crate::solve::jacobian::conditioning_of(&j, geometry.characteristic_length())
    };
    Some((j, conditioning))
}

/// See [`Geometry::actuated_conditioning`].
pub(crate) fn actuated_conditioning(
    geometry: &Geometry,
    pose: &Pose,
) -> Option<crate::solve::jacobian::Conditioning> {
    if servos(geometry) {
        geometry.servo_conditioning(pose)
    } else {
        Some(geometry.conditioning(pose))
    }
}

/// See [`Geometry::quantity_limits`].
pub(crate) fn quantity_limits(geometry: &Geometry) -> [Option<f64>; 2] {
    match geometry.actuator() {
        Actuator::Rotary(servos) => match servos.range() {
            Some((min, max)) => [Some(min.degrees()), Some(max.degrees())],
            None => [None, None],
        },
        Actuator::Linear => [geometry.stroke().min, geometry.stroke().max],
    }
}

/// See [`Geometry::actuator_values_at`].
pub(crate) fn actuator_values_at(
    geometry: &Geometry,
    pose: &Pose,
) -> Result<[f64; 6], Unreachable> {
    match geometry.servo_angles(pose) {
        None => Ok(geometry.leg_lengths(pose)),
        Some(Ok(angles)) => Ok(angles.map(|a| a.degrees())),
        Some(Err(e)) => Err(e),
    }
}

/// See [`Geometry::pose_from_actuator_values`].
pub(crate) fn pose_from_actuator_values(
    geometry: &Geometry,
    values: &[f64; 6],
    near: &Pose,
) -> Result<Pose, ForwardError> {
    geometry.pose_from_actuator_values_with(values, near, &Default::default())
}

/// See [`Geometry::pose_from_actuator_values_with`].
pub(crate) fn pose_from_actuator_values_with(
    geometry: &Geometry,
    values: &[f64; 6],
    near: &Pose,
    options: &crate::solve::forward::ForwardOptions,
) -> Result<Pose, ForwardError> {
    let solution = if servos(geometry) {
        let angles = values.map(crate::model::angle::Angle::from_degrees);
        geometry.forward_servos(&angles, near, options)
    } else {
        geometry.forward(values, near, options)
    };
    solution.map(|s| s.pose)
}

/// See [`Geometry::actuator_values_batch`].
pub(crate) fn actuator_values_batch(
    geometry: &Geometry,
    poses: &[Pose],
) -> Result<Vec<[f64; 6]>, (usize, Unreachable)> {
    match geometry.servo_angles_batch(poses) {
        None => Ok(geometry.leg_lengths_batch(poses)),
        Some(Ok(values)) => Ok(values),
        Some(Err((k, servo))) => Err((
            k,
            // Say why in the closed form's words.
            match geometry.servo_angles(&poses[k]) {
                Some(Err(e)) => e,
                _ => Unreachable {
                    servo: servo + 1,
                    ratio: f64::INFINITY,
                    excess: f64::INFINITY,
                },
            },
        )),
    }
}

/// See [`Geometry::actuator_values`].
pub(crate) fn actuator_values(geometry: &Geometry, poses: &[Pose]) -> Vec<[f64; 6]> {
    let Actuator::Rotary(servos) = geometry.actuator() else {
        return geometry.leg_lengths_batch(poses);
    };
    if let Some(Ok(all)) = geometry.servo_angles_batch(poses) {
        return all;
    }
    let bases = geometry.base_joints();
    poses
        .iter()
        .map(|p| {
            let joints = geometry.inverse(p).platform_joints;
            std::array::from_fn(|i| {
                servo_closure::servo_angle(servos, i, &bases[i], &joints[i])
                    .map_or(f64::NAN, |a| a.degrees())
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::actuator::LEG_LENGTH;
    use crate::test_support::servo_geometry;

    #[test]
    fn values_are_lengths_or_angles_with_gaps_where_out_of_reach() {
        let seed = Geometry::seed();
        let home = seed.home_pose();
        assert_eq!(seed.actuator_values(&[home]), vec![seed.leg_lengths(&home)]);
        assert_eq!(seed.actuator_values_at(&home), Ok(seed.leg_lengths(&home)));
        assert_eq!(seed.quantity(), LEG_LENGTH);
        assert_eq!(seed.quantity_limits(), [None, None]);
        let g = servo_geometry();
        assert_eq!(g.quantity().symbol, "θ");
        let high = Pose::from_xyz_rpy_deg([0.0, 0.0, 0.3], [0.0; 3]);
        let values = g.actuator_values(&[g.home_pose(), high]);
        let angles = g
            .servo_angles(&g.home_pose())
            .and_then(Result::ok)
            .unwrap_or_else(|| panic!("home reachable"));
        for i in 0..6 {
            assert!((values[0][i] - angles[i].degrees()).abs() < 1e-9);
            assert!(values[1][i].is_nan());
        }
    }

    #[test]
    fn the_pose_from_the_values_at_a_pose_is_that_pose() {
        let lifted = |g: &Geometry| {
            let h = g.home_pose().to_coordinates();
            Pose::from_coordinates([h[0] + 0.004, h[1] - 0.003, h[2] + 0.005, 0.03, -0.02, 0.05])
        };
        // The paired preset (the seed's layout is singular at home) and a rotary platform.
        let paired =
            crate::io::scenario::Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
        for g in [paired.geometry, servo_geometry()] {
            let pose = lifted(&g);
            let values = g
                .actuator_values_at(&pose)
                .unwrap_or_else(|e| panic!("{e}"));
            let back = g
                .pose_from_actuator_values(&values, &g.home_pose())
                .unwrap_or_else(|e| panic!("{e}"));
            for (a, b) in back.to_coordinates().iter().zip(pose.to_coordinates()) {
                assert!((a - b).abs() < 1e-9, "{a} vs {b}");
            }
        }
        assert!(
            Geometry::seed()
                .pose_from_actuator_values(&[f64::NAN; 6], &Geometry::seed().home_pose())
                .is_err()
        );
    }
}
