//! The constant-orientation workspace of a rotary platform.
//!
//! **Method.** With the orientation fixed, platform joint `i` sits at `p + d_i` (`d_i`
//! constant). Servo `i` holds it when some horn angle in its range closes the rod, and
//! along a column of the `xy` grid this can change only at a few points, all in closed
//! form: the edge of reach, where the joint is exactly a rod's length from the nearest or
//! the farthest point of the horn tip's circle (up to four heights, from the joint's
//! distances to the circle's plane and centre); an end of the range, where the joint is
//! one rod length from the horn tip at that end (a sphere: a quadratic); and the one
//! height where the angle's formula can jump (the closure term `M` changes sign). Rod
//! cones add the roots of a quartic each (see `Columns::rod_cone_boundary`). Between
//! consecutive such points each piece is decided at its
//! midpoint by the servo's own closed form, so the column's held intervals are exact (to
//! the roots' precision, about 1e-15 m) from the base plane to the highest a joint can be
//! (horn + rod above its shaft). The rods' clearance, when limited, is settled by branch
//! and bound (`rotary/clearance.rs`); only a collision thinner than one column spacing
//! can be missed there. The `xy` discretisation errs as for legs; the reported error
//! estimate is the difference from every other column (the grid twice as coarse), which
//! overstates the error of the finer grid as the grid converges; tests compare the volume
//! with a brute-force grid of positions.

use std::sync::atomic::Ordering;

use nalgebra::Vector3;

use super::column::{Spans, keep_between_cuts};
use super::roots::{Poly, mul, roots_in, sub};
use super::{
    ConstantOrientationWorkspace, WorkspaceControl, WorkspaceError, extent_of, grid_spans, shifted,
    volume_error, volume_of,
};
use crate::analysis::checks::servos::rods_allowed;
use crate::model::angle::Angle;
use crate::model::geometry::Geometry;
use crate::model::limits::Limits;
use crate::model::pose::Pose;
use crate::model::rotary::RotaryActuators;
use crate::solve::servo_closure;
use clearance::{Clearance, Column};
use std::f64::consts::FRAC_PI_2;

mod clearance;

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
        let Ok(theta) = servo_closure::servo_angle(servos, i, &bases[i], &joints[i]) else {
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
    /// `d_i`: platform joint `i` minus the platform position, base frame.
    offsets: [Vector3<f64>; 6],
    /// Highest platform position a joint allows, metres.
    z_top: f64,
    /// Each horn's direction at angle 0.
    horns: [Vector3<f64>; 6],
    /// The platform's normal, base frame.
    platform_normal: Vector3<f64>,
}

impl Columns<'_> {
    /// Servo `i`'s angle holding platform joint `joint` (shaft centre `base`), if any.
    fn angle(&self, i: usize, base: &Vector3<f64>, joint: &Vector3<f64>) -> Option<Angle> {
        let terms = servo_closure::terms_along(self.servos, &self.horns[i], &(joint - base));
        servo_closure::angle_from_terms(i, terms).ok()
    }

    /// Polynomials in `z` whose roots include every height at which servo `i`'s rod meets
    /// the cone of half-angle `alpha` about the unit axis `n`, for the column whose joint
    /// is at `joint0` at `z = 0`. The rod from the horn tip `T(θ)` to the joint `J` is on
    /// the cone where `(J − T)·n = s cos α`, i.e. `A cos θ + C sin θ = D(z)`; with the
    /// closure `N cos θ + M sin θ = L(z)` this fixes `cos θ` and `sin θ` by Cramer's rule,
    /// and `cos² + sin² = 1` is a quartic in `z`. Where the two equations are dependent
    /// (their determinant, linear in `z`, vanishes) Cramer's rule fails: those roots too.
    fn rod_cone_boundary(
        &self,
        i: usize,
        base: &Vector3<f64>,
        joint0: &Vector3<f64>,
        n: &Vector3<f64>,
        alpha: f64,
    ) -> [Poly; 2] {
        let (a, s) = (self.servos.horn_length(), self.servos.rod_length());
        let q = joint0 - base;
        let [l0, m0, big_n] = servo_closure::closure_terms(self.servos, i, base, joint0);
        let l: Poly = [l0, 2.0 * q.z, 1.0, 0.0, 0.0];
        let m: Poly = [m0, 2.0 * a, 0.0, 0.0, 0.0];
        // The horn at θ = 0 points along (cos β, sin β, 0): T(θ) − B = a (cos θ h + sin θ ẑ).
        let coef_a = a * self.horns[i].dot(n);
        let coef_c = a * n.z;
        let d: Poly = [q.dot(n) - s * alpha.cos(), n.z, 0.0, 0.0, 0.0];
        let scale = |p: &Poly, k: f64| p.map(|c| c * k);
        let det = sub(&scale(&m, coef_a), &[coef_c * big_n, 0.0, 0.0, 0.0, 0.0]);
        let cos_num = sub(&mul(&d, &m), &scale(&l, coef_c));
        let sin_num = sub(&scale(&l, coef_a), &scale(&d, big_n));
        let circle = sub(
            &sub(&mul(&det, &det), &mul(&cos_num, &cos_num)),
            &mul(&sin_num, &sin_num),
        );
        [circle, det]
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

    /// Append the held `z` intervals of the column at `(x, y)` to `row` (see the module
    /// docs; `dz` is the sampling of the rod limits); returns the evaluations made.
    fn column(
        &self,
        x: f64,
        y: f64,
        dz: f64,
        scratch: &mut Scratch,
        row: &mut Vec<[f64; 4]>,
    ) -> usize {
        let Scratch {
            spans,
            spare,
            cuts,
            turning,
        } = scratch;
        spans.clear();
        spans.push((0.0, self.z_top));
        let mut evaluations = 0;
        let (a, s) = (self.servos.horn_length(), self.servos.rod_length());
        for (i, base) in self.geometry.base_joints().iter().enumerate() {
            let Some(&(lo, _)) = spans.first() else {
                return evaluations;
            };
            let hi = spans.last().map_or(lo, |span| span.1);
            let joint0 = Vector3::new(x, y, 0.0) + self.offsets[i];
            let q = joint0 - base;
            // The horn tip runs on a circle of radius a about the shaft centre, in the
            // vertical plane along the horn's zero direction h. A joint at in-plane distance
            // r from the centre and w off the plane is between √((r − a)² + w²) and
            // √((r + a)² + w²) from the circle's points, so the rod closes while
            // |√(s² − w²) − a| ≤ r ≤ √(s² − w²) + a; with r² = u² + v², u = q·h and
            // v = q_z + z, the edges of reach are where v² = (those bounds)² − u².
            let h = self.horns[i];
            let (u, w) = (q.dot(&h), q.x * -h.y + q.y * h.x);
            let in_plane = s * s - w * w;
            if in_plane < 0.0 {
                spans.clear();
                return evaluations;
            }
            cuts.clear();
            let root = in_plane.sqrt();
            for bound in [(root - a).abs(), root + a] {
                let v2 = bound * bound - u * u;
                if v2 >= 0.0 {
                    let v = v2.sqrt();
                    cuts.extend([-v - q.z, v - q.z]);
                }
            }
            // The angle leaves its range where the joint is a rod's length from the horn tip
            // at the range's end; where M changes sign with N = 0 it jumps.
            if let Some((min, max)) = self.servos.range() {
                for end in [min, max] {
                    let v = joint0 - self.servos.horn_tip(i, base, end);
                    let sphere: Poly = [v.norm_squared() - s * s, 2.0 * v.z, 1.0, 0.0, 0.0];
                    roots_in(&sphere, lo, hi, cuts);
                }
            }
            // Where v = 0 too (M = 0).
            cuts.push(-q.z);
            let held = |z: f64| {
                let joint = joint0 + Vector3::new(0.0, 0.0, z);
                self.angle(i, base, &joint).is_some_and(|theta| {
                    self.servos.range().is_none_or(|(min, max)| {
                        (min.radians()..=max.radians()).contains(&theta.radians())
                    })
                })
            };
            evaluations += keep_between_cuts(spans, cuts, held, spare);
            std::mem::swap(spans, spare);
        }
        let cones = [
            (self.limits.base_cone, Vector3::z()),
            (self.limits.platform_cone, self.platform_normal),
        ];
        if cones.iter().any(|(limit, _)| limit.is_some()) {
            for (i, base) in self.geometry.base_joints().iter().enumerate() {
                let Some(&(lo, _)) = spans.first() else {
                    return evaluations;
                };
                let hi = spans.last().map_or(lo, |span| span.1);
                let joint0 = Vector3::new(x, y, 0.0) + self.offsets[i];
                cuts.clear();
                for (limit, n) in &cones {
                    if let Some(alpha) = limit {
                        for p in self.rod_cone_boundary(i, base, &joint0, n, alpha.radians()) {
                            roots_in(&p, lo, hi, cuts);
                        }
                    }
                }
                let within = |z: f64| {
                    let joint = joint0 + Vector3::new(0.0, 0.0, z);
                    self.angle(i, base, &joint).is_some_and(|theta| {
                        let tip = self.servos.tip_along(&self.horns[i], base, theta);
                        let rod = (joint - tip).normalize();
                        cones.iter().all(|(limit, n)| {
                            limit.is_none_or(|a| rod.dot(n).clamp(-1.0, 1.0).acos() <= a.radians())
                        })
                    })
                };
                evaluations += keep_between_cuts(spans, cuts, within, spare);
                std::mem::swap(spans, spare);
            }
        }
        if let Some(radius) = self.limits.leg_radius {
            let clearance = Clearance {
                columns: self,
                least: 2.0 * radius,
            };
            let Some(&(lo, _)) = spans.first() else {
                return evaluations;
            };
            let hi = spans.last().map_or(lo, |span| span.1);
            for (i, base) in self.geometry.base_joints().iter().enumerate() {
                let joint0 = Vector3::new(x, y, 0.0) + self.offsets[i];
                turning[i].clear();
                // The angle turns where a sin θ = q_z + z: a rod "cone" about ẑ at 90°.
                let [quartic, _] =
                    self.rod_cone_boundary(i, base, &joint0, &Vector3::z(), FRAC_PI_2);
                roots_in(&quartic, lo, hi, &mut turning[i]);
            }
            let column = Column { x, y, dz, turning };
            evaluations += clearance.narrow(&column, spans, spare);
        }
        row.extend(spans.iter().map(|&(z0, z1)| [x, y, z0, z1]));
        evaluations
    }
}

/// Scratch space a row of columns reuses.
#[derive(Default)]
struct Scratch {
    spans: Spans,
    spare: Spans,
    cuts: Vec<f64>,
    turning: [Vec<f64>; 6],
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
    let rotation = crate::model::pose::rotation_zyx(roll, pitch, yaw);
    let c = geometry.pivot();
    let offsets = geometry.platform_joints().map(|a| c + rotation * (a - c));
    let lowest_offset = offsets.iter().map(|d| d.z).fold(f64::INFINITY, f64::min);
    let columns = Columns {
        geometry,
        servos,
        limits,
        offsets,
        z_top: (servos.horn_length() + servos.rod_length() - lowest_offset).max(0.0),
        platform_normal: rotation * Vector3::z(),
        horns: std::array::from_fn(|i| servos.horn_direction(i)),
    };
    let empty = ConstantOrientationWorkspace::empty(orientation, resolution);
    let Some(bounds) = columns.xy_bounds() else {
        return Ok(empty);
    };
    let column = |x, y, dz, scratch: &mut Scratch, row: &mut Vec<[f64; 4]>| {
        columns.column(x, y, dz, scratch, row)
    };
    let (cell, spans) = grid_spans(&bounds, resolution, control, true, column);
    if control.cancel.load(Ordering::Relaxed) {
        return Err(WorkspaceError::Cancelled);
    }
    let volume = volume_of(&spans, cell);
    let volume_error = volume_error(&spans, &bounds, resolution, columns.z_top);
    let spans = shifted(spans.into_iter(), c - rotation * c);
    let extent = extent_of(&spans);
    Ok(ConstantOrientationWorkspace {
        cell,
        volume,
        volume_error,
        extent,
        spans,
        ..empty
    })
}
