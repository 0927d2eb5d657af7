//! The batch leg lengths eight poses at a time: every step of [`BatchSolver::lengths`]
//! done lane by lane over eight poses in plain arrays, with no branch, so that the
//! compiler turns each step into vector instructions — as wide as the CPU has when
//! [`BatchSolver::solve_serial`] runs it compiled for AVX2 and FMA or AVX-512 (chosen at
//! run time by `pulp`). The operations are the scalar path's, lane for lane, so the
//! results are the same bits (a test checks it).
//!
//! Layout, measured: the eight rotations and positions go into a [`PosesLanes`] the caller
//! owns (returned by value it was copied each time), each leg's vector is then made and
//! used at once (kept in registers, not stored for all six legs), and the lengths are
//! gathered in a local block of eight rows copied out whole — together 70 → 114 M poses/s
//! for legs and 42 → 54 M/s for servos on a 2-core AVX-512 machine.

use std::f64::consts::FRAC_2_PI;

use super::{AsPose, BatchSolver, ServoBatch};
use crate::solve::fast_trig::{self, REDUCTION_LIMIT, atan2_finite};

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

/// The rotation (rows of `R`, by element) and position of eight poses, lane by lane.
pub(super) struct PosesLanes {
    r: [Lanes; 9],
    p: [Lanes; 3],
}

impl PosesLanes {
    const ZERO: Self = Self {
        r: [[0.0; LANES]; 9],
        p: [[0.0; LANES]; 3],
    };
}

impl BatchSolver {
    /// The leg lengths of eight poses into `out`, or `false` (nothing written) when an
    /// angle lies beyond the fast reduction (or is not a number): the caller then takes
    /// the poses one by one.
    #[inline(always)]
    #[allow(clippy::needless_range_loop)] // lane loops index several arrays alike
    pub(super) fn lengths_lanes<P: AsPose>(&self, poses: &[P], out: &mut [[f64; 6]]) -> bool {
        let mut frames = PosesLanes::ZERO;
        if !poses_lanes(poses, &mut frames) {
            return false;
        }
        // Rows gathered here and copied out whole: the eight output rows are contiguous.
        let mut rows = [[0.0; 6]; LANES];
        for i in 0..6 {
            let [x, y, z] = self.leg_lanes(&frames, i);
            for l in 0..LANES {
                rows[l][i] = (x[l] * x[l] + y[l] * y[l] + z[l] * z[l]).sqrt();
            }
        }
        out[..LANES].copy_from_slice(&rows);
        true
    }

    /// Leg `i`'s vector `q_i − b_i` in eight poses ([`BatchSolver::legs`] lane by lane).
    #[inline(always)]
    pub(super) fn leg_lanes(&self, poses: &PosesLanes, i: usize) -> [Lanes; 3] {
        let (ax, ay, az, dx, dy, dz) = self.constants();
        let (r, [px, py, pz]) = (&poses.r, &poses.p);
        let (mut x, mut y, mut z) = ([0.0; LANES], [0.0; LANES], [0.0; LANES]);
        for l in 0..LANES {
            x[l] = px[l] + dx[i] + (r[0][l] * ax[i] + r[1][l] * ay[i] + r[2][l] * az[i]);
            y[l] = py[l] + dy[i] + (r[3][l] * ax[i] + r[4][l] * ay[i] + r[5][l] * az[i]);
            z[l] = pz[l] + dz[i] + (r[6][l] * ax[i] + r[7][l] * ay[i] + r[8][l] * az[i]);
        }
        [x, y, z]
    }
}

/// The rotations and positions of eight poses into `frames`, or `false` when an angle lies
/// beyond the fast reduction (or is not a number).
#[inline(always)]
pub(super) fn poses_lanes<P: AsPose>(poses: &[P], frames: &mut PosesLanes) -> bool {
    let angle = |k: usize| -> Lanes { std::array::from_fn(|l| poses[l].angle(k)) };
    let roll = angle(0);
    let pitch = angle(1);
    let yaw = angle(2);
    let fast = |a: &Lanes| a.iter().all(|x| x.abs() <= REDUCTION_LIMIT);
    if !(fast(&roll) && fast(&pitch) && fast(&yaw)) {
        return false;
    }
    let (sr, cr) = sin_cos(&roll);
    let (sp, cp) = sin_cos(&pitch);
    let (sy, cy) = sin_cos(&yaw);
    let r = &mut frames.r;
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
    frames.p = std::array::from_fn(|k| std::array::from_fn(|l| poses[l].coordinate(k)));
    true
}

impl ServoBatch {
    /// The servo angles (radians) of eight poses into `out`: [`ServoBatch::angles_scalar`]
    /// lane by lane, so the same bits; `false` (nothing written) when an angle lies beyond
    /// the fast reduction or a servo of some pose cannot reach its joint — the caller then
    /// takes the poses one by one, which says which.
    #[inline(always)]
    pub(super) fn angles_lanes<P: AsPose>(&self, poses: &[P], out: &mut [[f64; 6]]) -> bool {
        let mut frames = PosesLanes::ZERO;
        if !poses_lanes(poses, &mut frames) {
            return false;
        }
        let (two_a, rod_minus_horn, ncos, nsin) = self.constants();
        let mut theta = [[0.0; LANES]; 6];
        let mut sound = true;
        for i in 0..6 {
            let [lx, ly, lz] = self.legs().leg_lanes(&frames, i);
            for l in 0..LANES {
                let (x, y, z) = (lx[l], ly[l], lz[l]);
                let big_l = x * x + y * y + z * z - rod_minus_horn;
                let m = two_a * z;
                let n = ncos[i] * x + nsin[i] * y;
                let c2 = m * m + n * n - big_l * big_l;
                // Out of reach, or a degenerate closure: the scalar path says which.
                sound &= c2 >= 0.0 && !(m == 0.0 && n == 0.0);
                let c = c2.max(0.0).sqrt();
                let (ty, tx) = (big_l * m - c * n, c * m + big_l * n);
                sound &= ty.is_finite() && tx.is_finite() && !(ty == 0.0 && tx == 0.0);
                theta[i][l] = atan2_finite(ty, tx);
            }
        }
        if !sound {
            return false;
        }
        for (l, row) in out.iter_mut().enumerate().take(LANES) {
            *row = std::array::from_fn(|i| theta[i][l]);
        }
        true
    }
}
