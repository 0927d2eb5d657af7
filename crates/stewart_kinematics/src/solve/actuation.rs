//! What the actuators do, whatever their kind: the quantity that drives each joint (a
//! leg's length, or a servo's angle), its name and unit, its limits, and its value along
//! a motion. The plots, leg bars and readouts read it from here.

use crate::model::actuator::{Actuator, ActuatorKind, Quantity};
use crate::model::geometry::Geometry;
use crate::model::pose::Pose;
use crate::model::rotary::Unreachable;
use crate::solve::forward::ForwardError;
use crate::solve::servo_closure;

impl Geometry {
    /// The quantity that drives the joints: leg length or servo angle.
    pub fn quantity(&self) -> Quantity {
        self.actuator().kind().quantity()
    }

    /// Whether the actuators are rotary servos: the solvers below dispatch on it.
    fn servos(&self) -> bool {
        self.actuator().kind() == ActuatorKind::Rotary
    }

    /// The speed, acceleration and jerk limits of the actuator values (m/s… or °/s…),
    /// from `limits`' keys for this kind.
    pub fn actuator_rate_limits(&self, limits: &crate::model::limits::Limits) -> [Option<f64>; 3] {
        self.actuator().kind().rate_limits(limits)
    }

    /// Every assembly mode of actuator `values` (leg lengths in metres or servo angles in
    /// degrees): the poses that hold them.
    pub fn actuator_assembly_modes(
        &self,
        values: &[f64; 6],
    ) -> Result<Vec<crate::solve::forward::ForwardSolution>, ForwardError> {
        if self.servos() {
            self.servo_assembly_modes(&values.map(crate::model::angle::Angle::from_degrees))
        } else {
            self.assembly_modes(values)
        }
    }

    /// The map from a platform twist to the actuator rates: the legs' inverse Jacobian
    /// ([`Geometry::jacobian`]) or the servos' ([`Geometry::servo_jacobian`]), or the servo
    /// that cannot reach its joint.
    pub fn actuator_jacobian(&self, pose: &Pose) -> Result<nalgebra::Matrix6<f64>, Unreachable> {
        match self.servo_jacobian(pose) {
            None => Ok(self.jacobian(pose)),
            Some(j) => j,
        }
    }

    /// [`Geometry::actuator_jacobian`] and its conditioning, the Jacobian computed once
    /// (`None` when a servo cannot reach its joint).
    pub fn actuator_jacobian_and_conditioning(
        &self,
        pose: &Pose,
    ) -> Option<(nalgebra::Matrix6<f64>, crate::solve::jacobian::Conditioning)> {
        let j = self.actuator_jacobian(pose).ok()?;
        let conditioning = if self.servos() {
            self.servo_conditioning_of(&j)?
        } else {
            crate::solve::jacobian::conditioning_of(&j, self.characteristic_length())
        };
        Some((j, conditioning))
    }

    /// Conditioning of whatever drives the platform: the legs' ([`Geometry::conditioning`])
    /// or the servos' ([`Geometry::servo_conditioning`]; `None` when a servo cannot
    /// reach its joint).
    pub fn actuated_conditioning(
        &self,
        pose: &Pose,
    ) -> Option<crate::solve::jacobian::Conditioning> {
        if self.servos() {
            self.servo_conditioning(pose)
        } else {
            Some(self.conditioning(pose))
        }
    }

    /// The limits of that quantity: the stroke (m) or the servo range (°), each end
    /// optional.
    pub fn quantity_limits(&self) -> [Option<f64>; 2] {
        match self.actuator() {
            Actuator::Rotary(servos) => match servos.range() {
                Some((min, max)) => [Some(min.degrees()), Some(max.degrees())],
                None => [None, None],
            },
            Actuator::Linear => [self.stroke().min, self.stroke().max],
        }
    }

    /// The quantity at one pose: leg lengths (m) or servo angles (°), or why a servo cannot
    /// reach its joint.
    pub fn actuator_values_at(&self, pose: &Pose) -> Result<[f64; 6], Unreachable> {
        match self.servo_angles(pose) {
            None => Ok(self.leg_lengths(pose)),
            Some(Ok(angles)) => Ok(angles.map(|a| a.degrees())),
            Some(Err(e)) => Err(e),
        }
    }

    /// The pose whose actuator values are `values` (leg lengths in metres or servo angles
    /// in degrees): forward kinematics searched from `near` (the last pose known, or
    /// home), or why there is none.
    pub fn pose_from_actuator_values(
        &self,
        values: &[f64; 6],
        near: &Pose,
    ) -> Result<Pose, ForwardError> {
        self.pose_from_actuator_values_with(values, near, &Default::default())
    }

    /// [`Geometry::pose_from_actuator_values`] with the forward solver's `options`.
    pub fn pose_from_actuator_values_with(
        &self,
        values: &[f64; 6],
        near: &Pose,
        options: &crate::solve::forward::ForwardOptions,
    ) -> Result<Pose, ForwardError> {
        let solution = if self.servos() {
            let angles = values.map(crate::model::angle::Angle::from_degrees);
            self.forward_servos(&angles, near, options)
        } else {
            self.forward(values, near, options)
        };
        solution.map(|s| s.pose)
    }

    /// The quantity at every pose, on all cores (leg lengths in metres or servo angles in
    /// degrees), or the earliest pose (its index) a servo cannot reach, and why.
    pub fn actuator_values_batch(
        &self,
        poses: &[Pose],
    ) -> Result<Vec<[f64; 6]>, (usize, Unreachable)> {
        match self.servo_angles_batch(poses) {
            None => Ok(self.leg_lengths_batch(poses)),
            Some(Ok(values)) => Ok(values),
            Some(Err((k, servo))) => Err((
                k,
                // Say why in the closed form's words.
                match self.servo_angles(&poses[k]) {
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

    /// The quantity at every pose, on all cores for legs: lengths in metres, or servo
    /// angles in degrees with NaN where a servo cannot reach its joint (a gap in a plot).
    pub fn actuator_values(&self, poses: &[Pose]) -> Vec<[f64; 6]> {
        let Actuator::Rotary(servos) = self.actuator() else {
            return self.leg_lengths_batch(poses);
        };
        if let Some(Ok(all)) = self.servo_angles_batch(poses) {
            return all;
        }
        let bases = self.base_joints();
        poses
            .iter()
            .map(|p| {
                let joints = self.inverse(p).platform_joints;
                std::array::from_fn(|i| {
                    servo_closure::servo_angle(servos, i, &bases[i], &joints[i])
                        .map_or(f64::NAN, |a| a.degrees())
                })
            })
            .collect()
    }
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
