//! The constant-orientation workspace of a rotary platform.
//!
//! **Method.** With the orientation fixed, platform joint `i` sits at `p + d_i` (`d_i`
//! constant). Servo `i` holds it when some horn angle in its range closes the rod: the
//! closed form says so directly (reach ratio at most 1, angle within the range). The
//! reachable set is no longer an intersection of spherical shells, so each column of the
//! `xy` grid is *sampled* in `z` at the column spacing, from the base plane to the highest
//! a joint can be (horn + rod above its shaft), and every change between reachable and
//! unreachable samples is refined by bisection to 1e-12 m. The ends found are exact up to
//! that; what can be missed is a reachable (or unreachable) piece thinner than one sample
//! spacing in `z` (the reachable set of a servo is a thick shell around its horn's arc, so
//! such pieces occur only at grazing edges), and the `xy` discretisation errs as for legs.
//! The reported error estimate is the difference from the same computation on the
//! half-resolution grid (whose sampling in `z` is twice as coarse too), which overstates
//! the error of the finer grid as the grid converges; a test compares it with a
//! brute-force grid of positions.

use std::sync::atomic::Ordering;

use nalgebra::Vector3;
use rayon::prelude::*;

use super::{
    ConstantOrientationWorkspace, WorkspaceControl, WorkspaceError, extent_of, grid, shifted,
    volume_of,
};
use crate::angle::Angle;
use crate::checks::servos::rods_allowed;
use crate::geometry::Geometry;
use crate::limits::Limits;
use crate::pose::Pose;
use crate::rotary::RotaryActuators;

/// Whether every servo of `servos` holds platform joints `joints` of `pose` within its
/// range, and the rods respect the pose limits.
pub(super) fn servos_allowed(
    geometry: &Geometry,
    servos: &RotaryActuators,
    limits: &Limits,
    pose: &Pose,
    joints: &[Vector3<f64>; 6],
) -> bool {
    let bases = geometry.base_joints();
    let pose_limits = limits.has_pose_limits();
    let mut tips = [Vector3::zeros(); 6];
    for i in 0..6 {
        let Ok(theta) = servos.servo_angle(i, &bases[i], &joints[i]) else {
            return false;
        };
        if let Some((min, max)) = servos.range()
            && !(min.radians()..=max.radians()).contains(&theta.radians())
        {
            return false;
        }
        if pose_limits {
            tips[i] = servos.horn_tip(i, &bases[i], theta);
        }
    }
    !pose_limits || rods_allowed(limits, pose, bases, joints, &tips)
}

/// One orientation of a rotary platform: what a column needs.
struct Columns<'a> {
    geometry: &'a Geometry,
    servos: &'a RotaryActuators,
    limits: &'a Limits,
    orientation: [Angle; 3],
    /// `d_i`: platform joint `i` minus the platform position, base frame.
    offsets: [Vector3<f64>; 6],
    /// Highest platform position a joint allows, metres.
    z_top: f64,
}

impl Columns<'_> {
    /// Whether the platform position `(x, y, z)` is held.
    fn allowed(&self, x: f64, y: f64, z: f64) -> bool {
        let p = Vector3::new(x, y, z);
        let joints = self.offsets.map(|d| p + d);
        let [roll, pitch, yaw] = self.orientation;
        let pose = Pose::new(p, roll, pitch, yaw);
        servos_allowed(self.geometry, self.servos, self.limits, &pose, &joints)
    }

    /// The `xy` box outside which some joint is beyond horn + rod of its shaft.
    fn xy_bounds(&self) -> Option<[[f64; 2]; 2]> {
        let reach = self.servos.horn_length() + self.servos.rod_length();
        let mut b = [[f64::NEG_INFINITY, f64::INFINITY]; 2];
        for (base, d) in self.geometry.base_joints().iter().zip(&self.offsets) {
            for k in 0..2 {
                let centre = base[k] - d[k];
                b[k][0] = b[k][0].max(centre - reach);
                b[k][1] = b[k][1].min(centre + reach);
            }
        }
        (b[0][0] < b[0][1] && b[1][0] < b[1][1]).then_some(b)
    }

    /// The held `z` intervals of the column at `(x, y)`, sampled every `dz` and refined
    /// by bisection, appended to `out`; returns the positions evaluated.
    fn column(&self, x: f64, y: f64, dz: f64, out: &mut Vec<[f64; 4]>) -> usize {
        let count = (self.z_top / dz).ceil().max(1.0) as usize;
        let step = self.z_top / count as f64;
        let mut evaluations = count + 1;
        let mut edge = |lo: f64, hi: f64, lo_inside: bool| {
            let (mut a, mut b) = (lo, hi);
            while b - a > 1e-12 {
                let mid = 0.5 * (a + b);
                evaluations += 1;
                if self.allowed(x, y, mid) == lo_inside {
                    a = mid;
                } else {
                    b = mid;
                }
            }
            0.5 * (a + b)
        };
        let mut start: Option<f64> = None;
        let mut previous = self.allowed(x, y, 0.0);
        if previous {
            start = Some(0.0);
        }
        for k in 1..=count {
            let z = k as f64 * step;
            let now = self.allowed(x, y, z);
            if now != previous {
                let at = edge(z - step, z, previous);
                if now {
                    start = Some(at);
                } else if let Some(s) = start.take() {
                    out.push([x, y, s, at]);
                }
            }
            previous = now;
        }
        if let Some(s) = start {
            out.push([x, y, s, self.z_top]);
        }
        evaluations
    }

    /// Every column of an `n × n` grid over `bounds`, with progress and cancellation.
    fn spans(
        &self,
        bounds: &[[f64; 2]; 2],
        n: usize,
        control: &WorkspaceControl,
    ) -> (f64, Vec<[f64; 4]>) {
        let (cell, x0, y0) = grid(bounds, n);
        let rows: Vec<Vec<[f64; 4]>> = (0..n)
            .into_par_iter()
            .map(|i| {
                let x = x0 + (i as f64 + 0.5) * cell;
                let mut row = Vec::new();
                for j in 0..n {
                    if control.cancel.load(Ordering::Relaxed) {
                        break;
                    }
                    let y = y0 + (j as f64 + 0.5) * cell;
                    let evaluated = self.column(x, y, cell, &mut row);
                    control
                        .evaluations
                        .fetch_add(evaluated as u64, Ordering::Relaxed);
                }
                control.rows_done.fetch_add(1, Ordering::Relaxed);
                row
            })
            .collect();
        (cell, rows.into_iter().flatten().collect())
    }
}

/// The workspace of a rotary platform at `orientation` (see the module docs).
pub(super) fn workspace(
    geometry: &Geometry,
    servos: &RotaryActuators,
    limits: &Limits,
    orientation: [Angle; 3],
    resolution: usize,
    control: &WorkspaceControl,
) -> Result<ConstantOrientationWorkspace, WorkspaceError> {
    let [roll, pitch, yaw] = orientation;
    let rotation = crate::pose::rotation_zyx(roll, pitch, yaw);
    let c = geometry.pivot();
    let offsets = geometry.platform_joints().map(|a| c + rotation * (a - c));
    let lowest_offset = offsets.iter().map(|d| d.z).fold(f64::INFINITY, f64::min);
    let columns = Columns {
        geometry,
        servos,
        limits,
        orientation,
        offsets,
        z_top: (servos.horn_length() + servos.rod_length() - lowest_offset).max(0.0),
    };
    let empty = ConstantOrientationWorkspace::empty(orientation, resolution);
    let Some(bounds) = columns.xy_bounds() else {
        return Ok(empty);
    };
    let (cell, spans) = columns.spans(&bounds, resolution, control);
    if control.cancel.load(Ordering::Relaxed) {
        return Err(WorkspaceError::Cancelled);
    }
    let volume = volume_of(&spans, cell);
    let (coarse_cell, coarse) = columns.spans(
        &bounds,
        (resolution / 2).max(2),
        &WorkspaceControl::default(),
    );
    let coarse_volume = volume_of(&coarse, coarse_cell);
    let spans = shifted(spans.into_iter(), c - rotation * c);
    let extent = extent_of(&spans);
    Ok(ConstantOrientationWorkspace {
        cell,
        volume,
        volume_error: (volume - coarse_volume).abs(),
        extent,
        spans,
        ..empty
    })
}
