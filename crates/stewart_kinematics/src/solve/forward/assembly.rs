//! Assembly modes: the different poses a platform can take with the same leg lengths.
//!
//! The forward problem has up to 40 complex solutions; the real ones are the ways the
//! platform can be assembled. All of them are found by polynomial homotopy continuation
//! ([`super::homotopy`]), a method that finds every isolated solution with probability
//! one; each real one is then polished by the damped Newton solver to the leg-length
//! tolerance. Tests compare the count with a dense multi-start search.

use nalgebra::{Matrix3, Vector3};

use super::homotopy;
use super::study::{LegParams, placement_of};
use super::{ForwardError, ForwardOptions, ForwardSolution};
use crate::model::geometry::Geometry;
use crate::model::pose::Pose;

/// Two solutions closer than this (metres, and rotation-matrix entries) are the same.
const SAME_POSE: f64 = 1e-7;

/// A solution whose coordinates have imaginary parts below this (relative) is real.
const REAL: f64 = 1e-8;

/// Whether two poses are the same placement (compares rotation matrices, so Euler angle
/// representations that differ by full turns count as equal).
pub fn same_placement(a: &Pose, b: &Pose) -> bool {
    (a.position - b.position).amax() < SAME_POSE && (a.rotation() - b.rotation()).amax() < SAME_POSE
}

/// Every assembly mode of one set of legs: the real poses, and how many complex
/// solutions the forward problem has in all.
#[derive(Clone, Debug, PartialEq)]
pub struct AssemblyModes {
    /// The real poses, highest first.
    pub modes: Vec<ForwardSolution>,
    /// Isolated complex solutions found, real ones included (40 for a general platform).
    pub complex_solutions: usize,
}

/// See [`Geometry::assembly_modes`].
pub(crate) fn assembly_modes(
    geometry: &Geometry,
    lengths: &[f64; 6],
) -> Result<Vec<ForwardSolution>, ForwardError> {
    Ok(geometry.all_assembly_modes(lengths)?.modes)
}

/// See [`Geometry::all_assembly_modes`].
pub(crate) fn all_assembly_modes(
    geometry: &Geometry,
    lengths: &[f64; 6],
) -> Result<AssemblyModes, ForwardError> {
    geometry.check_lengths(lengths)?;
    solve_modes(geometry, geometry.base_joints(), lengths)
}

/// See [`Geometry::servo_assembly_modes`].
pub(crate) fn servo_assembly_modes(
    geometry: &Geometry,
    angles: &[crate::model::angle::Angle; 6],
) -> Result<Vec<ForwardSolution>, ForwardError> {
    let (tips, rod) = geometry.servo_anchors(angles)?;
    Ok(solve_modes(geometry, &tips, &[rod; 6])?.modes)
}

/// All solutions for legs of `lengths` from fixed `anchors`, by homotopy.
fn solve_modes(
    geometry: &Geometry,
    anchors: &[Vector3<f64>; 6],
    lengths: &[f64; 6],
) -> Result<AssemblyModes, ForwardError> {
    let legs = std::array::from_fn(|i| {
        LegParams::real(&geometry.platform_joints()[i], &anchors[i], lengths[i])
    });
    let solutions = homotopy::all_solutions(&legs).ok_or(ForwardError::NoRealPose {
        complex_solutions: 0,
    })?;
    let options = ForwardOptions {
        max_iterations: 50,
        ..ForwardOptions::default()
    };
    let c = geometry.pivot();
    let mut modes: Vec<ForwardSolution> = Vec::new();
    for z in homotopy::real_solutions(&solutions, REAL) {
        let (r, t) = placement_of(&z);
        // q = R a + t = p + c + R (a − c), so p = t − c + R c.
        let start = from_rotation(t - c + r * c, &r);
        let Ok(polished) = geometry.forward_from(anchors, lengths, &start, &options) else {
            continue;
        };
        let pose = canonical(&polished.pose);
        if !modes.iter().any(|m| same_placement(&m.pose, &pose)) {
            modes.push(ForwardSolution { pose, ..polished });
        }
    }
    if modes.is_empty() {
        return Err(ForwardError::NoRealPose {
            complex_solutions: solutions.len(),
        });
    }
    modes.sort_by(|a, b| b.pose.position.z.total_cmp(&a.pose.position.z));
    Ok(AssemblyModes {
        modes,
        complex_solutions: solutions.len(),
    })
}

/// The pose at `position` with rotation matrix `r`, Euler angles in the principal ranges.
fn from_rotation(position: Vector3<f64>, r: &Matrix3<f64>) -> Pose {
    let rot = nalgebra::Rotation3::from_matrix_unchecked(*r);
    let (roll, pitch, yaw) = rot.euler_angles();
    Pose::new(
        position,
        crate::model::angle::Angle::from_radians(roll),
        crate::model::angle::Angle::from_radians(pitch),
        crate::model::angle::Angle::from_radians(yaw),
    )
}

/// The same placement with its Euler angles in the principal ranges (roll and yaw in
/// (−180°, 180°], pitch in [−90°, 90°]).
pub fn canonical(pose: &Pose) -> Pose {
    let r = pose.rotation();
    let out = from_rotation(pose.position, &r);
    // nalgebra's euler_angles are the roll-pitch-yaw of R = Rz(yaw)·Ry(pitch)·Rx(roll).
    debug_assert!((out.rotation() - r).amax() < 1e-9);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::geometry::{GeometryParams, PlateJoints};
    use crate::solve::forward::homotopy::SplitMix;

    /// A random general platform: joints anywhere in a 2 m box (the platform's within
    /// 1.5 m), and a random pose above the base whose legs are the ones to solve.
    fn random_platform(seed: u64) -> (Geometry, Pose) {
        let mut rng = SplitMix(seed);
        let mut point = |scale: f64| Vector3::new(rng.next(), rng.next(), 0.3 * rng.next()) * scale;
        let base = std::array::from_fn(|_| point(1.0));
        let platform = std::array::from_fn(|_| point(0.7));
        let mut p = GeometryParams::seed();
        p.base = PlateJoints::Points(base);
        p.platform = PlateJoints::Points(platform);
        let g = Geometry::new(p).unwrap_or_else(|e| panic!("{e}"));
        let truth = Pose::from_xyz_rpy_deg(
            [0.2 * rng.next(), 0.2 * rng.next(), 0.9 + 0.2 * rng.next()],
            [20.0 * rng.next(), 20.0 * rng.next(), 90.0 * rng.next()],
        );
        (g, truth)
    }

    /// An independent search: Newton from `n` random poses (positions in a 4 m box,
    /// uniformly random orientations), the distinct converged ones.
    fn multi_start(g: &Geometry, lengths: &[f64; 6], n: usize, seed: u64) -> Vec<Pose> {
        let mut rng = SplitMix(seed);
        let options = ForwardOptions {
            max_iterations: 200,
            ..ForwardOptions::default()
        };
        let mut found: Vec<Pose> = Vec::new();
        for _ in 0..n {
            let q = nalgebra::UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(
                rng.next(),
                rng.next(),
                rng.next(),
                rng.next(),
            ));
            let position = Vector3::new(rng.next(), rng.next(), rng.next()) * 2.0;
            let start = from_rotation(position, q.to_rotation_matrix().matrix());
            if let Ok(s) = g.forward_from(g.base_joints(), lengths, &start, &options)
                && !found.iter().any(|f| same_placement(f, &s.pose))
            {
                found.push(canonical(&s.pose));
            }
        }
        found
    }

    #[test]
    fn the_homotopy_finds_every_mode_a_dense_multi_start_search_finds() {
        for seed in 1..=4 {
            let (g, truth) = random_platform(seed);
            let lengths = g.leg_lengths(&truth);
            let all = g
                .all_assembly_modes(&lengths)
                .unwrap_or_else(|e| panic!("{e}"));
            // A general platform: 40 complex solutions, the non-real ones in conjugate
            // pairs, so an even number of real ones; the pose the legs came from is one.
            assert_eq!(all.complex_solutions, 40, "platform {seed}");
            assert_eq!(all.modes.len() % 2, 0, "platform {seed}");
            assert!(all.modes.iter().any(|m| same_placement(&m.pose, &truth)));
            assert!(all.modes.iter().all(|m| m.residual <= 1e-12));
            let searched = multi_start(&g, &lengths, 1500, 100 + seed);
            for s in &searched {
                assert!(
                    all.modes.iter().any(|m| same_placement(&m.pose, s)),
                    "platform {seed}: the search found a mode the homotopy missed: {s:?}"
                );
            }
            // The search is no proof, but on these platforms it finds most of them.
            assert!(
                2 * searched.len() >= all.modes.len(),
                "platform {seed}: {} searched, {} modes",
                searched.len(),
                all.modes.len()
            );
        }
    }

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
        let m = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, -1.0));
        let mirror_r = m * truth.rotation() * m;
        assert!(modes.iter().any(|s| {
            (s.pose.position - Vector3::new(0.05, -0.03, -0.85)).amax() < 1e-7
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
