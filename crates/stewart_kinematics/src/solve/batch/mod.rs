//! Batch inverse kinematics: leg lengths for many poses at once, on all cores.
//!
//! The geometry is laid out once as structure-of-arrays constants; each pose then costs
//! one shared sine/cosine reduction per angle ([`crate::solve::fast_trig`]) and straight-line
//! arithmetic, with no allocation. Work is split over the cores with rayon in chunks
//! large enough to amortise scheduling; within a chunk the poses are copied 64 at a time
//! onto the stack before their arithmetic (and a table's rows checked there), so that
//! their cache misses are in flight together.

mod lanes;

use std::convert::Infallible;

use rayon::prelude::*;
use wide::f64x4;

use crate::model::geometry::Geometry;
use crate::model::pose::Pose;
use crate::solve::fast_trig::{atan2, sin_cos};
use lanes::LANES;

/// Poses per rayon task: big enough that scheduling is noise, small enough to balance.
pub const CHUNK: usize = 4096;
/// Poses copied together into a buffer on the stack before their arithmetic
/// ([`by_blocks`]).
const BLOCK: usize = 64;

/// What the batch reads a pose from: a [`Pose`], or a row `[x, y, z, roll, pitch, yaw]`
/// of a table (metres, degrees; its angles turned to radians as [`Pose`] turns them, so
/// the same bits).
pub(crate) trait AsPose: Copy + Sync {
    /// Coordinate `k` of the position (0: x, 1: y, 2: z), metres.
    fn coordinate(&self, k: usize) -> f64;
    /// Angle `k` (0: roll, 1: pitch, 2: yaw), radians.
    fn angle(&self, k: usize) -> f64;
    /// The pose itself.
    fn pose(&self) -> Pose;
    /// Why a block is refused before its arithmetic ([`Infallible`] for poses).
    type Refusal;
    /// A block's check before its arithmetic: rows must lie in the accepted range of a
    /// pose table, all of them; poses are not checked.
    fn check(block: &[Self]) -> Result<(), Self::Refusal>;
}

impl AsPose for Pose {
    #[inline(always)]
    fn coordinate(&self, k: usize) -> f64 {
        self.position[k]
    }
    #[inline(always)]
    fn angle(&self, k: usize) -> f64 {
        [self.roll, self.pitch, self.yaw][k].radians()
    }
    #[inline(always)]
    fn pose(&self) -> Pose {
        *self
    }
    type Refusal = Infallible;
    #[inline(always)]
    fn check(_: &[Self]) -> Result<(), Infallible> {
        Ok(())
    }
}

impl AsPose for [f64; 6] {
    #[inline(always)]
    fn coordinate(&self, k: usize) -> f64 {
        self[k]
    }
    #[inline(always)]
    fn angle(&self, k: usize) -> f64 {
        self[3 + k].to_radians()
    }
    #[inline(always)]
    fn pose(&self) -> Pose {
        Pose::from_row(self)
    }
    /// A row outside the accepted range, or not finite ([`all_accepted`]).
    type Refusal = ();
    #[inline(always)]
    fn check(block: &[Self]) -> Result<(), ()> {
        if all_accepted(block) { Ok(()) } else { Err(()) }
    }
}

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

    /// The constants by coordinate: `a_i − c` (x, y, z), then `c − b_i` (x, y, z).
    #[inline(always)]
    #[allow(clippy::type_complexity)]
    pub(super) fn constants(
        &self,
    ) -> (
        &[f64; 6],
        &[f64; 6],
        &[f64; 6],
        &[f64; 6],
        &[f64; 6],
        &[f64; 6],
    ) {
        (&self.ax, &self.ay, &self.az, &self.dx, &self.dy, &self.dz)
    }

    /// The six leg vectors `q_i − b_i` of one pose, by coordinate.
    #[inline]
    fn legs(&self, pose: &Pose) -> [[f64; 6]; 3] {
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
        let (ax, ay, az) = (&self.ax, &self.ay, &self.az);
        [
            std::array::from_fn(|i| p.x + self.dx[i] + (r00 * ax[i] + r01 * ay[i] + r02 * az[i])),
            std::array::from_fn(|i| p.y + self.dy[i] + (r10 * ax[i] + r11 * ay[i] + r12 * az[i])),
            std::array::from_fn(|i| p.z + self.dz[i] + (r20 * ax[i] + r21 * ay[i] + r22 * az[i])),
        ]
    }

    /// The six leg lengths of one pose.
    #[inline]
    pub fn lengths(&self, pose: &Pose) -> [f64; 6] {
        let [lx, ly, lz] = self.legs(pose);
        std::array::from_fn(|i| (lx[i] * lx[i] + ly[i] * ly[i] + lz[i] * lz[i]).sqrt())
    }

    /// Leg lengths of every pose into `out` on the calling thread.
    ///
    /// # Panics
    /// If `out` is shorter than `poses` (a programming error, not a user error).
    pub fn solve_serial(&self, poses: &[Pose], out: &mut [[f64; 6]]) {
        // The same loop compiled for the widest vector instructions this CPU has (AVX2 and
        // FMA, or AVX-512), chosen at run time; without them, the baseline build.
        let Ok(()) = pulp::Arch::new().dispatch(Lengths {
            solver: self,
            poses,
            out,
        });
    }

    /// [`BatchSolver::solve_serial`] as the baseline build runs it, whatever the CPU: the
    /// reference the dispatched code is tested against.
    ///
    /// # Panics
    /// If `out` is shorter than `poses` (a programming error, not a user error).
    #[inline(always)]
    pub fn solve_reference(&self, poses: &[Pose], out: &mut [[f64; 6]]) {
        let Ok(()) = self.solve_reference_of(poses, out);
    }

    /// [`BatchSolver::solve_reference`] of poses or rows, block by block ([`staged`]),
    /// each checked first ([`AsPose::check`]): the first refusal stops it (`out` is then
    /// partly written).
    #[inline(always)]
    fn solve_reference_of<P: AsPose>(
        &self,
        poses: &[P],
        out: &mut [[f64; 6]],
    ) -> Result<(), P::Refusal> {
        assert!(out.len() >= poses.len(), "output shorter than input");
        let whole = poses.len() / BLOCK * BLOCK;
        for (block, out) in poses[..whole]
            .chunks_exact(BLOCK)
            .zip(out.chunks_exact_mut(BLOCK))
        {
            let block = staged(block);
            P::check(&block)?;
            self.solve_block(&block, out);
        }
        P::check(&poses[whole..])?;
        self.solve_block(&poses[whole..], &mut out[whole..]);
        Ok(())
    }

    /// The leg lengths of a block of poses into `out`: eight at a time, and the poses of
    /// a group the lanes leave (or the rest) one by one.
    #[inline(always)]
    fn solve_block<P: AsPose>(&self, poses: &[P], out: &mut [[f64; 6]]) {
        let whole = poses.len() / LANES * LANES;
        for (p, o) in poses[..whole]
            .chunks_exact(LANES)
            .zip(out[..whole].chunks_exact_mut(LANES))
        {
            if !self.lengths_lanes(p, o) {
                self.solve_one_by_one_of(p, o);
            }
        }
        self.solve_one_by_one_of(&poses[whole..], &mut out[whole..]);
    }

    /// Leg lengths pose by pose (the scalar path).
    pub fn solve_one_by_one(&self, poses: &[Pose], out: &mut [[f64; 6]]) {
        self.solve_one_by_one_of(poses, out);
    }

    /// [`BatchSolver::solve_one_by_one`] of poses or rows.
    #[inline(always)]
    fn solve_one_by_one_of<P: AsPose>(&self, poses: &[P], out: &mut [[f64; 6]]) {
        for (pose, o) in poses.iter().zip(out.iter_mut()) {
            *o = self.lengths(&pose.pose());
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

/// A block of [`BLOCK`] poses copied into a buffer on the stack.
///
/// The copy's loads do not wait on one another, so the processor has the block's cache
/// misses in flight at once; read where they lie, a group of eight poses (over a thousand
/// instructions, beyond the reorder window) waited for its own misses, one group after
/// another: the batch read from main memory at a third of its speed on cached poses (30
/// against 11 ns a pose on Zen 3, whose prefetchers did not hide it).
#[inline(always)]
fn staged<P: AsPose>(block: &[P]) -> [P; BLOCK] {
    std::array::from_fn(|k| block[k])
}

/// [`BatchSolver::solve_reference`] as one piece of work for `pulp` to compile per
/// instruction set: inlined whole into each, so every step gets the wide instructions.
struct Lengths<'a, P> {
    solver: &'a BatchSolver,
    poses: &'a [P],
    out: &'a mut [[f64; 6]],
}

impl<P: AsPose> pulp::WithSimd for Lengths<'_, P> {
    type Output = Result<(), P::Refusal>;

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _simd: S) -> Self::Output {
        self.solver.solve_reference_of(self.poses, self.out)
    }
}

/// [`ServoBatch::solve_reference`] as one piece of work for `pulp`, as [`Lengths`].
struct ServoChunk<'a, P> {
    solver: &'a ServoBatch,
    poses: &'a [P],
    out: &'a mut [[f64; 6]],
}

impl<P: AsPose> pulp::WithSimd for ServoChunk<'_, P> {
    type Output = Result<(), Stop<P::Refusal>>;

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _simd: S) -> Self::Output {
        self.solver.solve_reference_of(self.poses, self.out)
    }
}

/// The first pose out of reach in a batch: its index and its servo (both from 0).
pub type OutOfReach = (usize, usize);

/// Why a servo batch stopped: a block refused by its check ([`AsPose::check`]), or a
/// pose out of reach.
enum Stop<R> {
    Refused(R),
    OutOfReach(OutOfReach),
}

impl Stop<Infallible> {
    /// The pose out of reach (poses are never refused).
    fn out_of_reach(self) -> OutOfReach {
        match self {
            Stop::OutOfReach(first) => first,
            Stop::Refused(never) => match never {},
        }
    }
}

/// Batch servo angles of a rotary platform: the batch leg vectors, then the closed form
/// of [`crate::model::rotary`] with one square root and one `atan2` per servo:
/// `θ = atan2(L·M − c·N, c·M + L·N)` with `c = √(M² + N² − L²)`, which is
/// `asin(L/√(M²+N²)) − atan2(N, M)` wrapped to (−π, π].
#[derive(Clone, Copy, Debug)]
pub struct ServoBatch {
    legs: BatchSolver,
    /// `2a cos β_i`, `2a sin β_i`.
    ncos: [f64; 6],
    nsin: [f64; 6],
    /// `2a`.
    two_a: f64,
    /// `s² − a²`.
    rod_minus_horn: f64,
}

impl ServoBatch {
    /// Prepare the constants of a rotary `geometry` (`None` for linear legs).
    pub fn new(geometry: &Geometry) -> Option<Self> {
        let servos = geometry.rotary()?;
        let (a, s) = (servos.horn_length(), servos.rod_length());
        let beta = servos.horn_angles();
        Some(Self {
            legs: BatchSolver::new(geometry),
            ncos: std::array::from_fn(|i| 2.0 * a * beta[i].radians().cos()),
            nsin: std::array::from_fn(|i| 2.0 * a * beta[i].radians().sin()),
            two_a: 2.0 * a,
            rod_minus_horn: s * s - a * a,
        })
    }

    /// The leg solver inside.
    #[inline(always)]
    pub(super) fn legs(&self) -> &BatchSolver {
        &self.legs
    }

    /// `2a`, `s² − a²`, `2a cos β_i`, `2a sin β_i`.
    #[inline(always)]
    pub(super) fn constants(&self) -> (f64, f64, &[f64; 6], &[f64; 6]) {
        (self.two_a, self.rod_minus_horn, &self.ncos, &self.nsin)
    }

    /// The six servo angles of one pose, radians, or the index (from 0) of the first servo
    /// that cannot reach its joint. The closed form runs on four lanes at a time (`wide`'s
    /// `f64x4`: servos 1–4, then 5–6 twice), with its polynomial `atan2`.
    #[inline]
    pub fn angles(&self, pose: &Pose) -> Result<[f64; 6], usize> {
        let [lx, ly, lz] = self.legs.legs(pose);
        let mut out = [0.0; 6];
        for (first, lanes) in [(0, [0, 1, 2, 3]), (4, [4, 5, 4, 5])] {
            let pick = |v: &[f64; 6]| f64x4::new(lanes.map(|i| v[i]));
            let (x, y, z) = (pick(&lx), pick(&ly), pick(&lz));
            let big_l = x * x + y * y + z * z - f64x4::splat(self.rod_minus_horn);
            let m = f64x4::splat(self.two_a) * z;
            let n = pick(&self.ncos) * x + pick(&self.nsin) * y;
            let c2 = m * m + n * n - big_l * big_l;
            let (c2a, ma, na) = (c2.to_array(), m.to_array(), n.to_array());
            if (0..4).any(|j| c2a[j].is_nan() || c2a[j] < 0.0 || (ma[j] == 0.0 && na[j] == 0.0)) {
                // Rare: say which servo, in the order of the scalar form.
                return self.angles_scalar(pose);
            }
            let c = c2.sqrt();
            let theta = (big_l * m - c * n).atan2(c * m + big_l * n).to_array();
            let count = if first == 0 { 4 } else { 2 };
            out[first..first + count].copy_from_slice(&theta[..count]);
        }
        Ok(out)
    }

    /// [`ServoBatch::angles`] one servo at a time (the scalar `atan2` of
    /// [`crate::solve::fast_trig`]).
    pub fn angles_scalar(&self, pose: &Pose) -> Result<[f64; 6], usize> {
        let [lx, ly, lz] = self.legs.legs(pose);
        let mut out = [0.0; 6];
        for i in 0..6 {
            let big_l = lx[i] * lx[i] + ly[i] * ly[i] + lz[i] * lz[i] - self.rod_minus_horn;
            let m = self.two_a * lz[i];
            let n = self.ncos[i] * lx[i] + self.nsin[i] * ly[i];
            let c2 = m * m + n * n - big_l * big_l;
            if c2.is_nan() || c2 < 0.0 || (m == 0.0 && n == 0.0) {
                return Err(i);
            }
            let c = c2.sqrt();
            out[i] = atan2(big_l * m - c * n, c * m + big_l * n);
        }
        Ok(out)
    }

    /// Servo angles (radians) of every pose into `out` on the calling thread, compiled for
    /// the CPU's widest vector instructions (as [`BatchSolver::solve_serial`]); the first
    /// unreachable pose, with its servo (from 0), is the error.
    ///
    /// # Panics
    /// If `out` is shorter than `poses` (a programming error, not a user error).
    pub fn solve_serial(&self, poses: &[Pose], out: &mut [[f64; 6]]) -> Result<(), OutOfReach> {
        pulp::Arch::new()
            .dispatch(ServoChunk {
                solver: self,
                poses,
                out,
            })
            .map_err(Stop::out_of_reach)
    }

    /// Servo angles (radians) of every pose into `out`, spread over all cores; the first
    /// unreachable pose found, with its servo (from 0), is the error.
    ///
    /// # Panics
    /// If `out` is shorter than `poses` (a programming error, not a user error).
    pub fn solve_parallel(
        &self,
        poses: &[Pose],
        out: &mut [[f64; 6]],
    ) -> Result<(), (usize, usize)> {
        assert!(out.len() >= poses.len(), "output shorter than input");
        poses
            .par_chunks(CHUNK)
            .zip(out[..poses.len()].par_chunks_mut(CHUNK))
            .enumerate()
            .try_for_each(|(chunk, (p, o))| {
                self.solve_serial(p, o)
                    .map_err(|(k, servo)| (chunk * CHUNK + k, servo))
            })
    }

    /// Servo angles of every pose into `out` on the calling thread, eight poses at a time
    /// where all reach (as the baseline build runs it; the parallel solve runs it compiled
    /// for the CPU's widest instructions), else pose by pose with
    /// [`ServoBatch::angles_scalar`] — the same bits either way. The first pose out of reach
    /// (its index and servo) stops it.
    ///
    /// # Panics
    /// If `out` is shorter than `poses` (a programming error, not a user error).
    #[inline(always)]
    pub fn solve_reference(&self, poses: &[Pose], out: &mut [[f64; 6]]) -> Result<(), OutOfReach> {
        self.solve_reference_of(poses, out)
            .map_err(Stop::out_of_reach)
    }

    /// [`ServoBatch::solve_reference`] of poses or rows, block by block ([`staged`]), each
    /// checked first ([`AsPose::check`]).
    #[inline(always)]
    fn solve_reference_of<P: AsPose>(
        &self,
        poses: &[P],
        out: &mut [[f64; 6]],
    ) -> Result<(), Stop<P::Refusal>> {
        assert!(out.len() >= poses.len(), "output shorter than input");
        let whole = poses.len() / BLOCK * BLOCK;
        for (b, (block, out)) in poses[..whole]
            .chunks_exact(BLOCK)
            .zip(out.chunks_exact_mut(BLOCK))
            .enumerate()
        {
            let block = staged(block);
            P::check(&block).map_err(Stop::Refused)?;
            self.solve_block(&block, out, b * BLOCK)
                .map_err(Stop::OutOfReach)?;
        }
        P::check(&poses[whole..]).map_err(Stop::Refused)?;
        self.solve_block(&poses[whole..], &mut out[whole..], whole)
            .map_err(Stop::OutOfReach)
    }

    /// The servo angles of a block of poses, the first of which is pose `start` of the
    /// batch, into `out`: eight at a time, and the poses of a group the lanes leave (or
    /// the rest) one by one, the first out of reach stopping it.
    #[inline(always)]
    fn solve_block<P: AsPose>(
        &self,
        poses: &[P],
        out: &mut [[f64; 6]],
        start: usize,
    ) -> Result<(), OutOfReach> {
        for (group, (p, o)) in poses.chunks(LANES).zip(out.chunks_mut(LANES)).enumerate() {
            if p.len() == LANES && self.angles_lanes(p, o) {
                continue;
            }
            for (k, (pose, slot)) in p.iter().zip(o.iter_mut()).enumerate() {
                *slot = self
                    .angles_scalar(&pose.pose())
                    .map_err(|servo| (start + group * LANES + k, servo))?;
            }
        }
        Ok(())
    }
}

/// See [`Geometry::servo_angles_batch`].
pub(crate) fn servo_angles_batch(
    geometry: &Geometry,
    poses: &[Pose],
) -> Option<Result<Vec<[f64; 6]>, OutOfReach>> {
    let solver = ServoBatch::new(geometry)?;
    let mut out = vec![[0.0; 6]; poses.len()];
    Some(match solver.solve_parallel(poses, &mut out) {
        Ok(()) => Ok(out
            .into_iter()
            .map(|row| row.map(|r| crate::model::angle::Angle::from_radians(r).degrees()))
            .collect()),
        // Parallel chunks may stop at a later pose first: find the earliest.
        Err(_) => Err(poses
            .iter()
            .enumerate()
            .find_map(|(k, p)| solver.angles(p).err().map(|servo| (k, servo)))
            .unwrap_or((0, 0))),
    })
}

/// See [`Geometry::leg_lengths_batch`].
pub(crate) fn leg_lengths_batch(geometry: &Geometry, poses: &[Pose]) -> Vec<[f64; 6]> {
    let mut out = vec![[0.0; 6]; poses.len()];
    BatchSolver::new(geometry).solve_parallel(poses, &mut out);
    out
}

/// See [`Geometry::actuator_values_rows`].
pub(crate) fn actuator_values_rows(
    geometry: &Geometry,
    rows: &[[f64; 6]],
    out: &mut [[f64; 6]],
) -> Result<(), RowError> {
    assert!(out.len() >= rows.len(), "output shorter than input");
    let out = &mut out[..rows.len()];
    let servos = ServoBatch::new(geometry);
    // Parallel chunks may stop at a later row first: the earliest is found afterwards.
    let earliest_refused = || {
        rows.iter()
            .enumerate()
            .find_map(|(k, row)| {
                if let Err((column, why)) = crate::ground::bounds::check_pose_row(row) {
                    return Some(match why {
                        crate::ground::bounds::OutOfBounds::NotFinite(_) => {
                            RowError::NotFinite { row: k, column }
                        }
                        crate::ground::bounds::OutOfBounds::Outside { .. } => {
                            RowError::Outside { row: k, column }
                        }
                    });
                }
                let solver = servos.as_ref()?;
                solver
                    .angles(&Pose::from_row(row))
                    .err()
                    .map(|servo| RowError::Unreachable { row: k, servo })
            })
            .unwrap_or(RowError::NotFinite { row: 0, column: 0 })
    };
    let solved = match &servos {
        None => {
            let solver = BatchSolver::new(geometry);
            rows.par_chunks(CHUNK)
                .zip(out.par_chunks_mut(CHUNK))
                .try_for_each(|(r, o)| {
                    // Each block's rows checked as it is staged (accepted poses of an
                    // accepted geometry give finite lengths).
                    pulp::Arch::new().dispatch(Lengths {
                        solver: &solver,
                        poses: r,
                        out: o,
                    })
                })
        }
        Some(solver) => rows
            .par_chunks(CHUNK)
            .zip(out.par_chunks_mut(CHUNK))
            .try_for_each(|(r, o)| {
                pulp::Arch::new()
                    .dispatch(ServoChunk {
                        solver,
                        poses: r,
                        out: &mut *o,
                    })
                    .map_err(drop)?;
                for row in o.iter_mut() {
                    *row = row.map(|r| crate::model::angle::Angle::from_radians(r).degrees());
                }
                Ok(())
            }),
    };
    solved.map_err(|()| earliest_refused())
}

/// Whether every value of `rows` is within its accepted range ([`crate::ground::bounds::POSE_ROW`];
/// NaN is not), with no early exit so that the loop vectorises.
#[inline(always)]
fn all_accepted(rows: &[[f64; 6]]) -> bool {
    // Four rows are 24 values: three blocks of eight lanes, each lane always the same
    // column, so each lane keeps one running verdict against one limit.
    const LIMITS: [f64; 24] = {
        let mut l = [0.0; 24];
        let mut k = 0;
        while k < 24 {
            l[k] = crate::ground::bounds::POSE_ROW[k % 6];
            k += 1;
        }
        l
    };
    let values = rows.as_flattened();
    let mut lanes = [true; 24];
    let mut pieces = values.chunks_exact(24);
    for piece in &mut pieces {
        for ((ok, v), limit) in lanes.iter_mut().zip(piece).zip(LIMITS) {
            *ok &= v.abs() <= limit;
        }
    }
    let rest = pieces.remainder();
    lanes.iter().all(|&ok| ok) && rest.iter().zip(LIMITS).all(|(v, limit)| v.abs() <= limit)
}

/// Why pose rows have no actuator values.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RowError {
    /// Value `column` (0 to 5: x, y, z, roll, pitch, yaw) of `row` is NaN or infinite.
    NotFinite {
        /// The row, from 0.
        row: usize,
        /// The column, from 0.
        column: usize,
    },
    /// Value `column` of `row` is finite but outside its accepted range
    /// ([`crate::ground::bounds::POSE_ROW`]).
    Outside {
        /// The row, from 0.
        row: usize,
        /// The column, from 0.
        column: usize,
    },
    /// A servo cannot reach its platform joint at `row`.
    Unreachable {
        /// The row, from 0.
        row: usize,
        /// The servo, from 0.
        servo: usize,
    },
}

#[cfg(test)]
mod tests;
