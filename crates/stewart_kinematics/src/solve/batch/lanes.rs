//! The batch leg lengths eight poses at a time: every step of [`BatchSolver::lengths`]
//! done lane by lane over eight poses in plain arrays, with no branch, so that the
//! compiler turns each step into vector instructions — as wide as the CPU has when
//! [`BatchSolver::solve_serial`] runs it compiled for AVX2 and FMA or AVX-512 (chosen at
//! run time by `pulp`). The operations are the scalar path's, lane for lane, so the
//! results are the same bits (a test checks it).
//!
//! Layout, measured: the eight rotations and positions go into a [`PosesLanes`] the caller
//! owns (returned by value it was copied each time), each leg's vector is then made and
//! used at once (kept in registers, not stored for all six legs) — together 70 → 114 M
//! poses/s for legs and 42 → 54 M/s for servos on a 2-core AVX-512 machine. On AVX2 (AMD
//! Zen 3, issue #60) three things kept it far slower: the quadrant converted `as i64`
//! (no AVX2 instruction: scalar code), lengths stored row by row (masked stores, slow on
//! AMD) and each transcendental's chain of dependent steps taken one lane group after
//! another; now the quadrant is read from a float's bits, lengths are stored leg by leg
//! and then turned into rows, and the three angles of a pose go through their polynomials
//! side by side ([`Wide`]`<3>`). The servos' `atan2` is taken servo by servo, eight poses
//! wide (`fast_trig::atan2_finite`, the scalar path's too), each after the next two
//! servos' closures, and a lane's soundness is a mask of non-short-circuit `&`, not
//! branches (docs/guide/performance.md has the figures).

use std::f64::consts::FRAC_2_PI;

use super::{AsPose, BatchSolver, ServoBatch};
use crate::solve::fast_trig::{self, REDUCTION_LIMIT, atan2_finite};
use crate::solve::wide::{Real, Wide, all_within};

/// Below this `M² + N²` a lane is left to the scalar path, which says whether the
/// closure is degenerate: above it `atan2`'s arguments, of magnitude `M² + N²` (as
/// `L² + c² = M² + N²`), are far from zero.
const TINY_REACH: f64 = 1e-150;
/// Above this `M² + N²` a lane is left to the scalar path: below it `atan2`'s arguments,
/// of magnitude `M² + N²`, are finite.
const HUGE_REACH: f64 = 1e299;

/// How many servos' closures come between a servo's closure and its `atan2` in the
/// servo-angle lanes (measured on Zen 3, one core, the median of eight runs: 37 ns a pose
/// with none between, 35 ns with one, 32 ns with two, 33 ns with three or four).
const ANGLE_LAG: usize = 2;

/// Poses computed together.
pub const LANES: usize = 8;

/// Eight numbers, one per pose.
type Lanes = [f64; LANES];

/// `(sin x, cos x)` of the three angles of eight poses within [`REDUCTION_LIMIT`]:
/// [`fast_trig::sin_cos`]'s reduction, polynomials and quadrant swap, lane by lane, each
/// step taken for the three angles of a lane side by side ([`Wide`]`<3>`: three
/// independent chains interleaved, where one angle after the other would wait on each
/// step's latency); the negations are the sign bit flipped (as `-` does), by bit
/// operations that stay in vector registers.
#[inline(always)]
fn sin_cos(angles: &[Lanes; 3]) -> ([Lanes; 3], [Lanes; 3]) {
    let (mut sin, mut cos) = ([[0.0; LANES]; 3], [[0.0; LANES]; 3]);
    for l in 0..LANES {
        let x = Wide::<3>::from_fn(|k| angles[k][l]);
        let (s, c, j) = fast_trig::kernel(x * Wide::splat(FRAC_2_PI), x);
        for k in 0..3 {
            let quadrant = fast_trig::quadrant(j.0[k]);
            let (a, b) = if quadrant & 1 != 0 {
                (c.0[k], s.0[k])
            } else {
                (s.0[k], c.0[k])
            };
            sin[k][l] = f64::from_bits(a.to_bits() ^ ((quadrant & 2) << 62));
            cos[k][l] = f64::from_bits(b.to_bits() ^ (((quadrant + 1) & 2) << 62));
        }
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
        let mut lengths = [[0.0; LANES]; 6];
        for (i, lengths) in lengths.iter_mut().enumerate() {
            let [x, y, z] = self.leg_lanes(&frames, i);
            for l in 0..LANES {
                lengths[l] = (x[l] * x[l] + y[l] * y[l] + z[l] * z[l]).sqrt();
            }
        }
        for (l, row) in out[..LANES].iter_mut().enumerate() {
            *row = std::array::from_fn(|i| lengths[i][l]);
        }
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
    let mut angles = [[0.0; LANES]; 3];
    for (k, angle) in angles.iter_mut().enumerate() {
        for (l, lane) in angle.iter_mut().enumerate() {
            *lane = poses[l].angle(k);
        }
    }
    if !all_within(angles.as_flattened(), REDUCTION_LIMIT) {
        return false;
    }
    let ([sr, sp, sy], [cr, cp, cy]) = sin_cos(&angles);
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
    /// the fast reduction, or a servo of some pose cannot reach its joint or has a
    /// degenerate or absurdly large closure ([`TINY_REACH`], [`HUGE_REACH`]) — the caller
    /// then takes the poses one by one, which says which.
    #[inline(always)]
    pub(super) fn angles_lanes<P: AsPose>(&self, poses: &[P], out: &mut [[f64; 6]]) -> bool {
        let mut frames = PosesLanes::ZERO;
        if !poses_lanes(poses, &mut frames) {
            return false;
        }
        let (two_a, rod_minus_horn, ncos, nsin) = self.constants();
        // The two arguments of each servo's atan2, then its angle, servo by servo, eight
        // poses wide; the angle of servo `i` is taken after the closure of servo `i + 2`
        // (its square root's wait filled with independent work). Lanes out of reach,
        // degenerate or absurdly large get some angle and are found by `sound` (one mask
        // per lane, non-short-circuit `&`: no branch) before anything is written.
        let (mut ty, mut tx) = ([[0.0; LANES]; 6], [[0.0; LANES]; 6]);
        let mut theta = [[0.0; LANES]; 6];
        let mut sound = [true; LANES];
        for step in 0..6 + ANGLE_LAG {
            if step < 6 {
                let i = step;
                let [lx, ly, lz] = self.legs().leg_lanes(&frames, i);
                for l in 0..LANES {
                    let (x, y, z) = (lx[l], ly[l], lz[l]);
                    let big_l = x * x + y * y + z * z - rod_minus_horn;
                    let m = two_a * z;
                    let n = ncos[i] * x + nsin[i] * y;
                    let reach = m * m + n * n;
                    let c2 = reach - big_l * big_l;
                    let c = c2.sqrt();
                    (ty[i][l], tx[i][l]) = (big_l * m - c * n, c * m + big_l * n);
                    sound[l] &= (c2 >= 0.0) & (reach > TINY_REACH) & (reach < HUGE_REACH);
                }
            }
            if step >= ANGLE_LAG {
                let i = step - ANGLE_LAG;
                theta[i] = atan2_finite(Wide(ty[i]), Wide(tx[i])).0;
            }
        }
        if !sound.iter().fold(true, |all, &lane| all & lane) {
            return false;
        }
        for (l, row) in out.iter_mut().enumerate().take(LANES) {
            for (i, value) in row.iter_mut().enumerate() {
                *value = theta[i][l];
            }
        }
        true
    }
}
