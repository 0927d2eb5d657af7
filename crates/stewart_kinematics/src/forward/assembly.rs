//! Assembly modes: the different poses a platform can take with the same leg lengths.
//!
//! The forward problem has up to 40 complex solutions; the real ones are the ways the
//! platform can be assembled. They are found here by starting the solver from many
//! initial poses (heights above and below the base, tilts and turns) and keeping the
//! distinct converged poses. A search cannot prove that it found all of them; it finds
//! every one whose basin of attraction contains a start.

use rayon::prelude::*;

use super::{ForwardError, ForwardOptions, ForwardSolution};
use crate::geometry::Geometry;
use crate::pose::Pose;

/// Two solutions closer than this (metres, and rotation-matrix entries) are the same.
const SAME_POSE: f64 = 1e-7;

/// Whether two poses are the same placement (compares rotation matrices, so Euler angle
/// representations that differ by full turns count as equal).
pub fn same_placement(a: &Pose, b: &Pose) -> bool {
    (a.position - b.position).amax() < SAME_POSE && (a.rotation() - b.rotation()).amax() < SAME_POSE
}

/// Initial poses of the search: heights from ±0.25 to ±2 home heights (above and below
/// the base plane), level and tilted by ±45° about x and y, turned by 0, ±60°, 180°.
fn starts(geometry: &Geometry) -> Vec<Pose> {
    let h = geometry.home_height();
    let mut v = Vec::new();
    for z in [0.25, 0.6, 1.0, 1.5, 2.0] {
        for sign in [1.0, -1.0] {
            for (r, p) in [
                (0.0, 0.0),
                (45.0, 0.0),
                (-45.0, 0.0),
                (0.0, 45.0),
                (0.0, -45.0),
            ] {
                for yaw in [0.0, 60.0, -60.0, 180.0] {
                    v.push(Pose::from_xyz_rpy_deg(
                        [0.0, 0.0, sign * z * h],
                        [r, p, yaw],
                    ));
                }
            }
        }
    }
    v
}

impl Geometry {
    /// Every distinct real assembly the search finds for `lengths`, sorted by height
    /// (highest first). Fails like [`Geometry::forward`] for invalid lengths, and with
    /// [`ForwardError::NotConverged`] when no start converges.
    pub fn assembly_modes(&self, lengths: &[f64; 6]) -> Result<Vec<ForwardSolution>, ForwardError> {
        self.check_lengths(lengths)?;
        self.search_modes(self.base_joints(), lengths)
    }

    /// Every distinct real assembly the search finds for a rotary platform whose servos
    /// stand at `angles` (the horn tips are then fixed and the rods legs of one length),
    /// sorted by height. Fails like [`Geometry::forward_servos`].
    pub fn servo_assembly_modes(
        &self,
        angles: &[crate::Angle; 6],
    ) -> Result<Vec<ForwardSolution>, ForwardError> {
        let (tips, rod) = self.servo_anchors(angles)?;
        self.search_modes(&tips, &[rod; 6])
    }

    /// The search for legs of `lengths` from fixed `anchors`.
    fn search_modes(
        &self,
        anchors: &[nalgebra::Vector3<f64>; 6],
        lengths: &[f64; 6],
    ) -> Result<Vec<ForwardSolution>, ForwardError> {
        let options = ForwardOptions {
            max_iterations: 200,
            ..ForwardOptions::default()
        };
        let found: Vec<ForwardSolution> = starts(self)
            .par_iter()
            .filter_map(|s| self.forward_from(anchors, lengths, s, &options).ok())
            .collect();
        let mut distinct: Vec<ForwardSolution> = Vec::new();
        for s in found {
            let pose = canonical(&s.pose);
            if !distinct.iter().any(|d| same_placement(&d.pose, &pose)) {
                distinct.push(ForwardSolution { pose, ..s });
            }
        }
        if distinct.is_empty() {
            return Err(ForwardError::NotConverged {
                iterations: options.max_iterations,
                residual: f64::NAN,
            });
        }
        distinct.sort_by(|a, b| b.pose.position.z.total_cmp(&a.pose.position.z));
        Ok(distinct)
    }
}

/// The same placement with its Euler angles in the principal ranges (roll and yaw in
/// (−180°, 180°], pitch in [−90°, 90°]).
pub fn canonical(pose: &Pose) -> Pose {
    let r = pose.rotation();
    let rot = nalgebra::Rotation3::from_matrix_unchecked(r);
    let (roll, pitch, yaw) = rot.euler_angles();
    let out = Pose::new(
        pose.position,
        crate::Angle::from_radians(roll),
        crate::Angle::from_radians(pitch),
        crate::Angle::from_radians(yaw),
    );
    // nalgebra's euler_angles are the roll-pitch-yaw of R = Rz(yaw)·Ry(pitch)·Rx(roll).
    debug_assert!((out.rotation() - r).amax() < 1e-9);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_the_pose_and_its_mirror_image_below_the_base() {
        let g = crate::test_support::paired_geometry();
        let truth = Pose::from_xyz_rpy_deg([0.05, -0.03, 0.85], [4.0, -3.0, 10.0]);
        let lengths = g.leg_lengths(&truth);
        let modes = g.assembly_modes(&lengths).unwrap_or_else(|e| panic!("{e}"));
        assert!(modes.len() >= 2, "{} modes", modes.len());
        assert!(modes.iter().all(|m| m.residual <= 1e-12));
        assert!(modes.iter().any(|m| same_placement(&m.pose, &truth)));
        // The mirror image through the base plane (z → −z; a reflection composed with
        // the platform's own, since its joints are planar) has the same leg lengths:
        // position (x, y, −z), rotation M·R·M with M = diag(1, 1, −1).
        let m = nalgebra::Matrix3::from_diagonal(&nalgebra::Vector3::new(1.0, 1.0, -1.0));
        let mirror_r = m * truth.rotation() * m;
        assert!(modes.iter().any(|s| {
            (s.pose.position - nalgebra::Vector3::new(0.05, -0.03, -0.85)).amax() < 1e-7
                && (s.pose.rotation() - mirror_r).amax() < 1e-7
        }));
        // Every mode really has the lengths asked for.
        for s in &modes {
            let l = g.leg_lengths(&s.pose);
            for i in 0..6 {
                assert!((l[i] - lengths[i]).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn canonical_keeps_the_placement() {
        let p = Pose::from_xyz_rpy_deg([0.0, 0.0, 1.0], [190.0, 10.0, -400.0]);
        let c = canonical(&p);
        assert!(same_placement(&p, &c));
        assert!(c.yaw.degrees().abs() <= 180.0 && c.roll.degrees().abs() <= 180.0);
    }
}
