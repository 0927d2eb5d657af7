//! The reachable workspace: positions reachable at a fixed orientation, and the range of
//! orientations reachable at a position, under the stroke and the pose limits.
//!
//! **Method (constant orientation).** With the rotation fixed, leg `i`'s length is the
//! distance from the platform position `p` to the fixed point `−d_i` (where
//! `d_i = c + R(a_i − c) − b_i`), so the stroke confines `p` to a spherical shell.
//! The `xy` plane is divided into `N × N` columns; in each column the shells' `z`
//! intervals are found in closed form and intersected (above the base plane), so each
//! column's reachable height is exact and only the `xy` discretisation errs. The volume
//! is the sum of column heights times the column area. Its error is estimated from the
//! spread of the 16 interleaved grids four times coarser that make up the grid (shifted
//! samples of the same volume; see `volume_error`).
//!
//! Rotary platforms are computed from the roots of each servo's boundary polynomials along
//! the column instead (see `rotary.rs`).
//!
//! When cone-angle or collision limits are set, each column's intervals are narrowed
//! further (see `limited.rs`): a cone can only be entered or left at the roots of a
//! quadratic in `z`, so the column stays exact; the leg clearance is resolved by a scan
//! that the Lipschitz bound of the legs' distance certifies, with edges bisected to
//! 1e-12 m (only a violation thinner than the column spacing can slip through it). The
//! error is estimated in the same way.

use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};

use nalgebra::Vector3;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::model::angle::Angle;
use crate::model::geometry::Geometry;
use crate::model::limits::Limits;
use crate::model::pose::Pose;

/// Why a workspace cannot be computed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum WorkspaceError {
    /// Without both stroke limits the workspace is unbounded or meaningless.
    #[error("the workspace needs both stroke limits (`leg_min` and `leg_max` in [geometry])")]
    NoStroke,
    /// Stopped through [`WorkspaceControl::cancel`].
    #[error("the workspace computation was stopped before it finished")]
    Cancelled,
    /// Resolution out of range.
    #[error("the resolution must be between 2 and {max} columns per side, got {got}")]
    Resolution {
        /// The value asked for.
        got: usize,
        /// The largest allowed.
        max: usize,
    },
}

/// Largest resolution (columns per side): 16 million columns.
pub const MAX_RESOLUTION: usize = 4096;

/// Resolution of the probe [`workspace_cost`] runs to estimate a request's cost.
pub const PROBE_RESOLUTION: usize = 64;

/// Progress and cancellation of a long workspace computation, shared with the thread
/// that shows progress (or takes Ctrl-C).
#[derive(Debug, Default)]
pub struct WorkspaceControl {
    /// Rows of the grid finished so far (of `resolution`).
    pub rows_done: AtomicUsize,
    /// Limit evaluations made so far (pieces decided, samples and bisection steps).
    pub evaluations: AtomicU64,
    /// Set to stop the computation early ([`WorkspaceError::Cancelled`]); shared, so that
    /// a flag owned elsewhere (a background job's) can stop it.
    pub cancel: std::sync::Arc<AtomicBool>,
}

impl WorkspaceControl {
    /// A control stopped by `cancel`.
    pub fn stopped_by(cancel: std::sync::Arc<AtomicBool>) -> Self {
        Self {
            cancel,
            ..Self::default()
        }
    }
}

/// What a workspace request will cost, estimated from a coarse probe.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WorkspaceCost {
    /// Columns of the grid.
    pub columns: f64,
    /// Limit evaluations (pieces decided, samples and bisection steps).
    pub evaluations: f64,
    /// Memory the reachable spans take, bytes.
    pub bytes: f64,
}

/// The most time a workspace request may be estimated to take unless its caller asks to
/// run it anyway (`stewart workspace --no-budget`, `Platform.workspace(budget=False)`).
pub const BUDGET_SECONDS: f64 = 120.0;

/// The most memory its reachable spans may be estimated to take, bytes.
pub const BUDGET_BYTES: f64 = 2.0 * 1024.0 * 1024.0 * 1024.0;

/// A request's cost scaled from its probe, against the budget.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WorkspaceEstimate {
    /// Seconds the request will take, about.
    pub seconds: f64,
    /// Whether that time or the spans' memory is over [`BUDGET_SECONDS`] or
    /// [`BUDGET_BYTES`].
    pub over_budget: bool,
    /// The largest resolution within the budget (2 at least).
    pub within_budget: usize,
}

impl WorkspaceCost {
    /// The estimate for `resolution` from this cost, whose probe (at
    /// [`PROBE_RESOLUTION`]) took `probe_seconds` (measured by the caller: the core reads
    /// no clock). Time grows as N², each column costing about the same at any resolution.
    pub fn estimate(&self, probe_seconds: f64, resolution: usize) -> WorkspaceEstimate {
        let ratio = resolution as f64 / PROBE_RESOLUTION as f64;
        let seconds = probe_seconds * ratio * ratio;
        let fits = |n: f64| {
            let r = n / PROBE_RESOLUTION as f64;
            probe_seconds * r * r <= BUDGET_SECONDS
                && self.bytes / (ratio * ratio) * r * r <= BUDGET_BYTES
        };
        WorkspaceEstimate {
            seconds,
            over_budget: seconds > BUDGET_SECONDS || self.bytes > BUDGET_BYTES,
            within_budget: (2..=resolution)
                .rev()
                .find(|&n| fits(n as f64))
                .unwrap_or(2),
        }
    }
}

/// At most this many separate reachable `z` intervals per column (each shell contributes
/// at most two, and intervals only split where shells cut them).
const MAX_SPANS: usize = 8;

/// The reachable positions at one orientation.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ConstantOrientationWorkspace {
    /// Roll, pitch, yaw of the platform.
    pub orientation: [Angle; 3],
    /// Columns per side of the `xy` grid.
    pub resolution: usize,
    /// Column spacing, metres.
    pub cell: f64,
    /// Reachable volume, m³.
    pub volume: f64,
    /// Error bound of the volume, m³ (twice the standard error of 16 interleaved coarser
    /// grids; see `volume_error`).
    pub volume_error: f64,
    /// `[[x_min, x_max], [y_min, y_max], [z_min, z_max]]` of the reachable set, metres
    /// (column centres in `x`, `y`; exact interval ends in `z`), or `None` when empty.
    pub extent: Option<[[f64; 2]; 3]>,
    /// Reachable spans `(x, y, z_low, z_high)` of the platform centre, one per interval of
    /// each column.
    pub spans: Vec<[f64; 4]>,
}

impl ConstantOrientationWorkspace {
    /// No reachable position at `orientation`, on a grid of `resolution` columns a side.
    fn empty(orientation: [Angle; 3], resolution: usize) -> Self {
        Self {
            orientation,
            resolution,
            cell: 0.0,
            volume: 0.0,
            volume_error: 0.0,
            extent: None,
            spans: Vec::new(),
        }
    }
}

impl ConstantOrientationWorkspace {
    /// Every `stride`-th column in `x` and `y` (a lighter mesh of the same workspace, for
    /// drawing): the kept columns' spans on a grid `stride` times coarser, with the volume
    /// and extent they give and an error bound widened by their difference from this
    /// volume. `stride` 0 or 1 keeps everything.
    pub fn every(&self, stride: usize) -> Self {
        let Some([ex, ey, _]) = self.extent.filter(|_| stride > 1) else {
            return self.clone();
        };
        let index = |v: f64, lo: f64| ((v - lo) / self.cell).round() as usize;
        let spans: Vec<[f64; 4]> = self
            .spans
            .iter()
            .filter(|s| index(s[0], ex[0]) % stride == 0 && index(s[1], ey[0]) % stride == 0)
            .copied()
            .collect();
        let cell = self.cell * stride as f64;
        let volume = volume_of(&spans, cell);
        Self {
            orientation: self.orientation,
            resolution: self.resolution.div_ceil(stride),
            cell,
            volume,
            volume_error: self.volume_error + (volume - self.volume).abs(),
            extent: extent_of(&spans),
            spans,
        }
    }
}

/// Geometry constants of one orientation.
struct Shells {
    /// Shell centres `−d_i`.
    centres: [Vector3<f64>; 6],
    min_sq: f64,
    max_sq: f64,
    max: f64,
}

impl Shells {
    fn new(geometry: &Geometry, rotation: &nalgebra::Matrix3<f64>, min: f64, max: f64) -> Self {
        let c = geometry.pivot();
        let centres = std::array::from_fn(|i| {
            let d = c + rotation * (geometry.platform_joints()[i] - c) - geometry.base_joints()[i];
            -d
        });
        Self {
            centres,
            min_sq: min * min,
            max_sq: max * max,
            max,
        }
    }

    /// The `xy` box outside which no shell intersection can lie.
    fn xy_bounds(&self) -> Option<[[f64; 2]; 2]> {
        let mut b = [[f64::NEG_INFINITY, f64::INFINITY]; 2];
        for c in &self.centres {
            for k in 0..2 {
                b[k][0] = b[k][0].max(c[k] - self.max);
                b[k][1] = b[k][1].min(c[k] + self.max);
            }
        }
        (b[0][0] < b[0][1] && b[1][0] < b[1][1]).then_some(b)
    }

    /// Reachable `z` intervals (above the base plane) of the column at `(x, y)`.
    fn column(&self, x: f64, y: f64, out: &mut [(f64, f64); MAX_SPANS]) -> usize {
        let mut n = 1;
        out[0] = (0.0, f64::INFINITY);
        for c in &self.centres {
            let h2 = (x - c.x) * (x - c.x) + (y - c.y) * (y - c.y);
            let top = self.max_sq - h2;
            if top < 0.0 {
                return 0;
            }
            let hi = top.sqrt();
            let inner = self.min_sq - h2;
            // This shell allows z − c_z in [−hi, −lo] ∪ [lo, hi], one interval when the
            // column misses the inner sphere.
            let allowed = if inner > 0.0 {
                let lo = inner.sqrt();
                [(c.z - hi, c.z - lo), (c.z + lo, c.z + hi)]
            } else {
                [(c.z - hi, c.z + hi), (0.0, 0.0)]
            };
            let mut next = [(0.0, 0.0); MAX_SPANS];
            let mut m = 0;
            for &(a0, a1) in &out[..n] {
                for &(b0, b1) in &allowed {
                    let (s0, s1) = (a0.max(b0), a1.min(b1));
                    if s0 < s1 && m < MAX_SPANS {
                        next[m] = (s0, s1);
                        m += 1;
                    }
                }
            }
            *out = next;
            n = m;
            if n == 0 {
                return 0;
            }
        }
        n
    }
}

/// Column spacing and origin of an `n × n` grid over `bounds`.
fn grid(bounds: &[[f64; 2]; 2], n: usize) -> (f64, f64, f64) {
    let side = (bounds[0][1] - bounds[0][0]).max(bounds[1][1] - bounds[1][0]);
    let cell = side / n as f64;
    let x0 = 0.5 * (bounds[0][0] + bounds[0][1]) - 0.5 * side;
    let y0 = 0.5 * (bounds[1][0] + bounds[1][1]) - 0.5 * side;
    (cell, x0, y0)
}

/// Spans of platform positions as spans of platform-centre positions: with a pivot offset
/// `c` the centre sits at `p + c − R c`, a constant `shift` at a fixed orientation.
fn shifted(spans: impl Iterator<Item = [f64; 4]>, shift: Vector3<f64>) -> Vec<[f64; 4]> {
    spans
        .map(|[x, y, z0, z1]| [x + shift.x, y + shift.y, z0 + shift.z, z1 + shift.z])
        .collect()
}

/// The volume of `spans` in columns of side `cell`.
fn volume_of(spans: &[[f64; 4]], cell: f64) -> f64 {
    // Folded from +0 (an empty sum of floats is −0, which would print as "-0.000000").
    spans.iter().fold(0.0, |sum, s| sum + (s[3] - s[2])) * cell * cell
}

/// The box around `spans` (column centres in x and y, span ends in z), `None` when empty.
fn extent_of(spans: &[[f64; 4]]) -> Option<[[f64; 2]; 3]> {
    (!spans.is_empty()).then(|| {
        let mut e = [[f64::INFINITY, f64::NEG_INFINITY]; 3];
        for s in spans {
            e[0] = [e[0][0].min(s[0]), e[0][1].max(s[0])];
            e[1] = [e[1][0].min(s[1]), e[1][1].max(s[1])];
            e[2] = [e[2][0].min(s[2]), e[2][1].max(s[3])];
        }
        e
    })
}

/// Scratch space of a column under cone and clearance limits.
#[derive(Default)]
struct LimitedScratch {
    spans: column::Spans,
    limits: limited::Scratch,
}

/// Every column of an `n × n` grid over `bounds`, rows in parallel: `column(x, y, dz, scratch,
/// row)` appends the spans `(x, y, z0, z1)` of the column at `(x, y)` to `row` (`dz` is the
/// grid's spacing) and returns the limit evaluations it made. Stops early when `control`
/// is cancelled; counts rows and evaluations on it when `count` is set. Returns the column
/// spacing and the spans.
fn grid_spans<S: Default>(
    bounds: &[[f64; 2]; 2],
    n: usize,
    control: &WorkspaceControl,
    count: bool,
    column: impl Fn(f64, f64, f64, &mut S, &mut Vec<[f64; 4]>) -> usize + Sync,
) -> (f64, Vec<[f64; 4]>) {
    let (cell, x0, y0) = grid(bounds, n);
    let rows: Vec<Vec<[f64; 4]>> = (0..n)
        .into_par_iter()
        .map(|i| {
            let x = x0 + (i as f64 + 0.5) * cell;
            let mut row = Vec::new();
            let mut scratch = S::default();
            let mut evaluations = 0;
            for j in 0..n {
                if control.cancel.load(Ordering::Relaxed) {
                    break;
                }
                let y = y0 + (j as f64 + 0.5) * cell;
                evaluations += column(x, y, cell, &mut scratch, &mut row);
            }
            if count {
                control
                    .evaluations
                    .fetch_add(evaluations as u64, Ordering::Relaxed);
                control.rows_done.fetch_add(1, Ordering::Relaxed);
            }
            row
        })
        .collect();
    (cell, rows.into_iter().flatten().collect())
}

/// The error bound of the volume of `spans`, on an `n × n` grid over `bounds` whose columns
/// are never taller than `tallest`: a shifted-lattice estimate. The grid is the union of
/// 16 interleaved grids four times coarser (every fourth column from each of the 4 × 4
/// starting columns), each a shifted sample of the same volume, and its sum is their mean;
/// the bound is twice the standard error of that mean (their standard deviation over √16,
/// doubled). A Richardson difference from one coarser grid understated the real error up
/// to 11× where a boundary happened to fall between columns; this bound covers the error
/// at every resolution from 2 to 256 for the presets (test). When no column centre is
/// reachable, a region thinner than the spacing can still lie between them: up to one
/// column's width across the grid at the tallest height.
fn volume_error(spans: &[[f64; 4]], bounds: &[[f64; 2]; 2], n: usize, tallest: f64) -> f64 {
    let (cell, x0, y0) = grid(bounds, n);
    if spans.is_empty() {
        return n as f64 * cell * cell * tallest;
    }
    const STRIDE: usize = 4;
    let mut samples = [0.0; STRIDE * STRIDE];
    let phase = |v: f64, origin: f64| ((v - origin) / cell - 0.5).round() as usize % STRIDE;
    for s in spans {
        samples[phase(s[0], x0) * STRIDE + phase(s[1], y0)] += s[3] - s[2];
    }
    let scale = (STRIDE * STRIDE) as f64 * cell * cell;
    let count = samples.len() as f64;
    let mean = samples.iter().sum::<f64>() / count;
    let variance = samples.iter().map(|h| (h - mean).powi(2)).sum::<f64>() / (count - 1.0);
    2.0 * scale * (variance / count).sqrt()
}

/// Whether `pose` keeps every leg within its stroke and respects `limits` — for a
/// rotary platform: every servo reaches its joint within its range, and the rods
/// respect the cone and clearance limits.
pub fn pose_within_limits(geometry: &Geometry, limits: &Limits, pose: &Pose) -> bool {
    let solution = geometry.inverse(pose);
    if let Some(servos) = geometry.rotary() {
        return rotary::servos_allowed(geometry, servos, limits, pose, &solution.platform_joints);
    }
    let stroke = geometry.stroke();
    solution
        .lengths
        .iter()
        .all(|&l| stroke.violation(l).is_none())
        && limits.pose_allowed(pose, &solution)
}

/// [`pose_within_limits`] both of the pose and of the pose its table row gives back
/// (`Pose::from_row(&pose.to_row())`, degrees rounded to radians): what a command that
/// writes poses for `check` to read must keep, so that the pose judged is the pose read,
/// bit for bit.
pub fn pose_within_limits_as_written(geometry: &Geometry, limits: &Limits, pose: &Pose) -> bool {
    pose_within_limits(geometry, limits, pose)
        && pose_within_limits(geometry, limits, &Pose::from_row(&pose.to_row()))
}

/// The platform-centre positions reachable at orientation `[roll, pitch, yaw]`, on an
/// `resolution × resolution` grid of columns (see the module docs).
pub fn constant_orientation_workspace(
    geometry: &Geometry,
    limits: &Limits,
    orientation: [Angle; 3],
    resolution: usize,
) -> Result<ConstantOrientationWorkspace, WorkspaceError> {
    constant_orientation_workspace_with(
        geometry,
        limits,
        orientation,
        resolution,
        &WorkspaceControl::default(),
    )
}

/// The cost of [`constant_orientation_workspace`] at `resolution`, from a
/// probe at [`PROBE_RESOLUTION`]: columns, spans and evaluations scale as N² (each
/// column is solved from its boundary polynomials or by a certified scan whose cost
/// barely grows with the resolution).
pub fn workspace_cost(
    geometry: &Geometry,
    limits: &Limits,
    orientation: [Angle; 3],
    resolution: usize,
) -> Result<WorkspaceCost, WorkspaceError> {
    let control = WorkspaceControl::default();
    let probe = constant_orientation_workspace_with(
        geometry,
        limits,
        orientation,
        PROBE_RESOLUTION,
        &control,
    )?;
    let ratio = resolution as f64 / PROBE_RESOLUTION as f64;
    let evaluations = control.evaluations.load(Ordering::Relaxed) as f64;
    Ok(WorkspaceCost {
        columns: (resolution * resolution) as f64,
        evaluations: evaluations * ratio * ratio,
        bytes: (probe.spans.len() * size_of::<[f64; 4]>()) as f64 * ratio.powi(2),
    })
}

/// [`constant_orientation_workspace`], counting progress on `control` and
/// stopping early (with [`WorkspaceError::Cancelled`]) when its `cancel` flag is set.
pub fn constant_orientation_workspace_with(
    geometry: &Geometry,
    limits: &Limits,
    orientation: [Angle; 3],
    resolution: usize,
    control: &WorkspaceControl,
) -> Result<ConstantOrientationWorkspace, WorkspaceError> {
    if !(2..=MAX_RESOLUTION).contains(&resolution) {
        return Err(WorkspaceError::Resolution {
            got: resolution,
            max: MAX_RESOLUTION,
        });
    }
    if let Some(servos) = geometry.rotary() {
        return rotary::workspace(geometry, servos, limits, orientation, resolution, control);
    }
    let (Some(min), Some(max)) = (geometry.stroke().min, geometry.stroke().max) else {
        return Err(WorkspaceError::NoStroke);
    };
    let [roll, pitch, yaw] = orientation;
    let rotation = crate::model::pose::rotation_zyx(roll, pitch, yaw);
    let shells = Shells::new(geometry, &rotation, min, max);
    let empty = ConstantOrientationWorkspace::empty(orientation, resolution);
    let Some(bounds) = shells.xy_bounds() else {
        return Ok(empty);
    };
    let (spans, cell, volume_error) = if limits.has_pose_limits() {
        let limited = limited::LegLimits::new(geometry, limits, &rotation);
        let column =
            |x: f64, y: f64, dz: f64, scratch: &mut LimitedScratch, row: &mut Vec<[f64; 4]>| {
                let mut stroke = [(0.0, 0.0); MAX_SPANS];
                let k = shells.column(x, y, &mut stroke);
                scratch.spans.clear();
                scratch.spans.extend_from_slice(&stroke[..k]);
                let n = limited.narrow(x, y, dz, &mut scratch.spans, &mut scratch.limits);
                row.extend(scratch.spans.iter().map(|&(z0, z1)| [x, y, z0, z1]));
                n
            };
        let (cell, spans) = grid_spans(&bounds, resolution, control, true, column);
        if control.cancel.load(Ordering::Relaxed) {
            return Err(WorkspaceError::Cancelled);
        }
        let error = volume_error(&spans, &bounds, resolution, 2.0 * shells.max);
        (spans, cell, error)
    } else {
        let (cell, spans) = grid_spans(
            &bounds,
            resolution,
            control,
            true,
            |x, y, _, _: &mut (), row| {
                let mut stroke = [(0.0, 0.0); MAX_SPANS];
                let k = shells.column(x, y, &mut stroke);
                row.extend(stroke[..k].iter().map(|&(z0, z1)| [x, y, z0, z1]));
                0
            },
        );
        let error = volume_error(&spans, &bounds, resolution, 2.0 * shells.max);
        (spans, cell, error)
    };
    if control.cancel.load(Ordering::Relaxed) {
        return Err(WorkspaceError::Cancelled);
    }
    // Report platform-centre positions: with a pivot offset `c` the centre sits at
    // `p + c − R c`, a constant shift at a fixed orientation.
    let spans = shifted(
        spans.into_iter(),
        geometry.pivot() - rotation * geometry.pivot(),
    );
    Ok(ConstantOrientationWorkspace {
        cell,
        volume: volume_of(&spans, cell),
        volume_error,
        extent: extent_of(&spans),
        spans,
        ..empty
    })
}

/// The range of one angle (others held at the given values) reachable at `pose`'s
/// position, searched outward from the pose's own angle in steps of `step` and refined
/// by bisection; `None` when the pose itself is not reachable.
pub fn orientation_range(
    geometry: &Geometry,
    limits: &Limits,
    pose: &Pose,
    axis: Axis,
    span: Angle,
    step: Angle,
) -> Option<[Angle; 2]> {
    let with = |a: Angle| {
        let mut p = *pose;
        match axis {
            Axis::Roll => p.roll = a,
            Axis::Pitch => p.pitch = a,
            Axis::Yaw => p.yaw = a,
        }
        pose_within_limits(geometry, limits, &p)
    };
    let centre = match axis {
        Axis::Roll => pose.roll,
        Axis::Pitch => pose.pitch,
        Axis::Yaw => pose.yaw,
    };
    // A step that cannot advance, or angles that are not numbers, would never end the
    // search below: such a question has no answer.
    let finite = [span, step, centre].iter().all(|a| a.radians().is_finite());
    if !finite || step.radians() <= 0.0 || !with(centre) {
        return None;
    }
    let edge = |direction: f64| {
        let mut inside = centre;
        let mut k = 1.0;
        loop {
            let a = centre + step * (k * direction);
            if (a - centre).radians().abs() > span.radians() {
                return centre + span * direction;
            }
            if !with(a) {
                // Bisect between the last reachable and the first unreachable angle.
                let (mut lo, mut hi) = (inside, a);
                for _ in 0..40 {
                    let mid = Angle::from_radians(0.5 * (lo.radians() + hi.radians()));
                    if with(mid) { lo = mid } else { hi = mid }
                }
                return lo;
            }
            inside = a;
            k += 1.0;
        }
    };
    Some([edge(-1.0), edge(1.0)])
}

/// One of the three Euler angles.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Axis {
    /// Rotation about x.
    Roll,
    /// Rotation about y.
    Pitch,
    /// Rotation about z.
    Yaw,
}

mod column;
mod limited;
mod method;
pub mod reach;
mod roots;
mod rotary;
pub mod slice;
pub mod surface;
#[cfg(test)]
mod tests;

pub use reach::{ReachMap, coordinate_range, roll_pitch_map};
pub use slice::{Plane, Slice, stiffness_slice, workspace_slice};
pub use surface::WorkspaceSurface;
