//! Batch inverse kinematics: leg lengths for many poses at once, on all cores.
//!
//! The geometry is laid out once as structure-of-arrays constants; each pose then costs
//! one shared sine/cosine reduction per angle ([`crate::fast_trig`]) and straight-line
//! arithmetic, with no allocation. Work is split over the cores with rayon in chunks
//! large enough to amortise scheduling.

use rayon::prelude::*;

use crate::fast_trig::sin_cos;
use crate::geometry::Geometry;
use crate::pose::Pose;

/// Poses per rayon task: big enough that scheduling is noise, small enough to balance.
const CHUNK: usize = 4096;

/// Geometry constants arranged for the batch loop.
#[derive(Clone, Copy, Debug)]
pub struct BatchSolver {
    /// Platform joints relative to the pivot, `a_i − c`, by coordinate.
    ax: [f64; 6],
    ay: [f64; 6],
    az: [f64; 6],
    /// `c − b_i`, by coordinate.
    dx: [f64; 6],
    dy: [f64; 6],
    dz: [f64; 6],
}

impl BatchSolver {
    /// Prepare the constants of `geometry`.
    pub fn new(geometry: &Geometry) -> Self {
        let c = geometry.pivot();
        let a = geometry.platform_joints().map(|a| a - c);
        let d = geometry.base_joints().map(|b| c - b);
        Self {
            ax: a.map(|v| v.x),
            ay: a.map(|v| v.y),
            az: a.map(|v| v.z),
            dx: d.map(|v| v.x),
            dy: d.map(|v| v.y),
            dz: d.map(|v| v.z),
        }
    }

    /// The six leg lengths of one pose.
    #[inline]
    pub fn lengths(&self, pose: &Pose) -> [f64; 6] {
        let (sr, cr) = sin_cos(pose.roll.radians());
        let (sp, cp) = sin_cos(pose.pitch.radians());
        let (sy, cy) = sin_cos(pose.yaw.radians());
        // Rows of R = Rz(yaw)·Ry(pitch)·Rx(roll), as in `pose::rotation_zyx`.
        let r00 = cy * cp;
        let r01 = cy * sp * sr - sy * cr;
        let r02 = cy * sp * cr + sy * sr;
        let r10 = sy * cp;
        let r11 = sy * sp * sr + cy * cr;
        let r12 = sy * sp * cr - cy * sr;
        let r20 = -sp;
        let r21 = cp * sr;
        let r22 = cp * cr;
        let p = &pose.position;
        std::array::from_fn(|i| {
            let (ax, ay, az) = (self.ax[i], self.ay[i], self.az[i]);
            let lx = p.x + self.dx[i] + (r00 * ax + r01 * ay + r02 * az);
            let ly = p.y + self.dy[i] + (r10 * ax + r11 * ay + r12 * az);
            let lz = p.z + self.dz[i] + (r20 * ax + r21 * ay + r22 * az);
            (lx * lx + ly * ly + lz * lz).sqrt()
        })
    }

    /// Leg lengths of every pose into `out` on the calling thread.
    ///
    /// # Panics
    /// If `out` is shorter than `poses` (a programming error, not a user error).
    pub fn solve_serial(&self, poses: &[Pose], out: &mut [[f64; 6]]) {
        assert!(out.len() >= poses.len(), "output shorter than input");
        for (pose, o) in poses.iter().zip(out.iter_mut()) {
            *o = self.lengths(pose);
        }
    }

    /// Leg lengths of every pose into `out`, spread over all cores.
    ///
    /// # Panics
    /// If `out` is shorter than `poses` (a programming error, not a user error).
    pub fn solve_parallel(&self, poses: &[Pose], out: &mut [[f64; 6]]) {
        assert!(out.len() >= poses.len(), "output shorter than input");
        poses
            .par_chunks(CHUNK)
            .zip(out[..poses.len()].par_chunks_mut(CHUNK))
            .for_each(|(p, o)| self.solve_serial(p, o));
    }
}

impl Geometry {
    /// Leg lengths of many poses, on all cores; allocates only the result.
    pub fn leg_lengths_batch(&self, poses: &[Pose]) -> Vec<[f64; 6]> {
        let mut out = vec![[0.0; 6]; poses.len()];
        BatchSolver::new(self).solve_parallel(poses, &mut out);
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::GeometryParams;
    use crate::layout::Layout;
    use nalgebra::Vector3;

    #[test]
    fn batch_agrees_with_single_pose_solution_for_every_pose() {
        let mut params = GeometryParams::from_layout(0.9, 0.5, 0.7, Layout::paired(24.0));
        params.pivot = Vector3::new(0.05, -0.02, 0.3);
        let g = Geometry::new(params).unwrap_or_else(|e| panic!("{e}"));
        // A deterministic spread of poses, including large angles in every quadrant.
        let poses: Vec<Pose> = (0..10_000)
            .map(|k| {
                let t = k as f64;
                Pose::from_xyz_rpy_deg(
                    [
                        0.3 * (0.37 * t).sin(),
                        0.3 * (0.23 * t).cos(),
                        0.7 + 0.2 * (0.11 * t).sin(),
                    ],
                    [
                        170.0 * (0.05 * t).sin(),
                        80.0 * (0.07 * t).cos(),
                        359.0 * (0.013 * t).sin(),
                    ],
                )
            })
            .collect();
        let batch = g.leg_lengths_batch(&poses);
        for (pose, lengths) in poses.iter().zip(&batch) {
            let single = g.leg_lengths(pose);
            for i in 0..6 {
                assert!((single[i] - lengths[i]).abs() < 1e-14, "{pose:?}");
            }
        }
    }
}
