//! The batch leg lengths eight poses at a time: every step of [`BatchSolver::lengths`]
//! done lane by lane over eight poses in plain arrays, with no branch, so that the
//! compiler turns each step into vector instructions — as wide as the CPU has when
//! [`BatchSolver::solve_serial`] runs it compiled for AVX2 and FMA or AVX-512 (chosen at
//! run time by `pulp`). The operations are the scalar path's, lane for lane, so the
//! results are the same bits (a test checks it).

use std::f64::consts::FRAC_2_PI;

use super::batch::BatchSolver;
use super::fast_trig::{self, REDUCTION_LIMIT};
use crate::pose::Pose;

/// Poses computed together.
pub const LANES: usize = 8;

/// Eight numbers, one per pose.
type Lanes = [f64; LANES];

/// `(sin x, cos x)` of eight angles within [`REDUCTION_LIMIT`]: [`fast_trig::sin_cos`]'s
/// reduction, polynomials and quadrant swap, lane by lane.
#[inline(always)]
fn sin_cos(x: &Lanes) -> (Lanes, Lanes) {
    let (mut sin, mut cos) = ([0.0; LANES], [0.0; LANES]);
    for l in 0..LANES {
        let (s, c, quadrant) = fast_trig::kernel(x[l] * FRAC_2_PI, x[l]);
        let swap = quadrant & 1 != 0;
        let (a, b) = if swap { (c, s) } else { (s, c) };
        sin[l] = if quadrant & 2 != 0 { -a } else { a };
        cos[l] = if (quadrant + 1) & 2 != 0 { -b } else { b };
    }
    (sin, cos)
}

impl BatchSolver {
    /// The leg lengths of eight poses into `out`, or `false` (nothing written) when an
    /// angle lies beyond the fast reduction (or is not a number): the caller then takes
    /// the poses one by one.
    #[inline(always)]
    pub(super) fn lengths_lanes(&self, poses: &[Pose], out: &mut [[f64; 6]]) -> bool {
        let angle = |f: fn(&Pose) -> f64| -> Lanes { std::array::from_fn(|l| f(&poses[l])) };
        let roll = angle(|p| p.roll.radians());
        let pitch = angle(|p| p.pitch.radians());
        let yaw = angle(|p| p.yaw.radians());
        let fast = |a: &Lanes| a.iter().all(|x| x.abs() <= REDUCTION_LIMIT);
        if !(fast(&roll) && fast(&pitch) && fast(&yaw)) {
            return false;
        }
        let (sr, cr) = sin_cos(&roll);
        let (sp, cp) = sin_cos(&pitch);
        let (sy, cy) = sin_cos(&yaw);
        let position = |f: fn(&Pose) -> f64| -> Lanes { std::array::from_fn(|l| f(&poses[l])) };
        let (px, py, pz) = (
            position(|p| p.position.x),
            position(|p| p.position.y),
            position(|p| p.position.z),
        );
        let mut r = [[0.0; LANES]; 9];
        for l in 0..LANES {
            // Rows of R = Rz(yaw)·Ry(pitch)·Rx(roll), as in `BatchSolver::legs`.
            r[0][l] = cy[l] * cp[l];
            r[1][l] = cy[l] * sp[l] * sr[l] - sy[l] * cr[l];
            r[2][l] = cy[l] * sp[l] * cr[l] + sy[l] * sr[l];
            r[3][l] = sy[l] * cp[l];
            r[4][l] = sy[l] * sp[l] * sr[l] + cy[l] * cr[l];
            r[5][l] = sy[l] * sp[l] * cr[l] - cy[l] * sr[l];
            r[6][l] = -sp[l];
            r[7][l] = cp[l] * sr[l];
            r[8][l] = cp[l] * cr[l];
        }
        let (ax, ay, az, dx, dy, dz) = self.constants();
        for i in 0..6 {
            for l in 0..LANES {
                let x = px[l] + dx[i] + (r[0][l] * ax[i] + r[1][l] * ay[i] + r[2][l] * az[i]);
                let y = py[l] + dy[i] + (r[3][l] * ax[i] + r[4][l] * ay[i] + r[5][l] * az[i]);
                let z = pz[l] + dz[i] + (r[6][l] * ax[i] + r[7][l] * ay[i] + r[8][l] * az[i]);
                out[l][i] = (x * x + y * y + z * z).sqrt();
            }
        }
        true
    }
}
