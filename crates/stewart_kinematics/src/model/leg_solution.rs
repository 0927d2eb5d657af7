//! What inverse kinematics gives for one pose (`Geometry::inverse`): the platform joints,
//! leg vectors and leg lengths, plain data that the model's limits and the analyses read.

use nalgebra::Vector3;

#[cfg(doc)]
use crate::model::geometry::Geometry;

/// The platform joints, leg vectors and leg lengths for one pose.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LegSolution {
    /// Platform joints `q_i` in the base frame, metres.
    pub platform_joints: [Vector3<f64>; 6],
    /// Leg vectors `l_i = q_i − b_i`, metres.
    pub legs: [Vector3<f64>; 6],
    /// Leg lengths `L_i = |l_i|`, metres.
    pub lengths: [f64; 6],
}

impl LegSolution {
    /// Unit vector along leg `i`, from base joint to platform joint (not finite for a
    /// leg of zero length: see [`Geometry::leg_without_direction`]).
    pub fn unit(&self, i: usize) -> Vector3<f64> {
        self.legs[i] / self.lengths[i]
    }
}
