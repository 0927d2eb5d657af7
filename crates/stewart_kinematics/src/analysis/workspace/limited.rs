//! Cone and clearance limits of a linear platform, one column at a time.
//!
//! At a fixed orientation leg `i` runs from its base joint `b_i` to `P_i(z) = P_i0 + z ẑ`
//! along a column, so:
//!
//! - **cones**: the angle between the leg `L(z) = q + z ẑ` and a joint's axis `n` reaches
//!   the limit α only where `(L·n)² = cos²α |L|²`, a quadratic in `z`: its (at most two)
//!   roots are the only places the cone can be entered or left, and each piece between
//!   them is decided at its midpoint, exactly as [`Limits::pose_allowed`] decides a pose;
//! - **clearance**: the distance between two leg segments changes by at most `|Δz|` when
//!   the platform moves by `Δz` (each point of a segment moves by a fraction of `Δz`), so
//!   it is resolved by the certified scan of `column::keep_where_margin` — a pair whose
//!   legs are far apart costs one distance per column.

use nalgebra::{Matrix3, Vector3};

use super::column::{Spans, keep_between_cuts, keep_where_margin};
use super::roots::{Poly, roots_in};
use crate::model::geometry::Geometry;
use crate::model::limits::{LEG_PAIRS, Limits, segment_distance};

/// One orientation's cone and clearance limits, as a column needs them.
pub(super) struct LegLimits {
    /// Base joints.
    bases: [Vector3<f64>; 6],
    /// `d_i`: platform joint `i` minus the platform position, base frame.
    offsets: [Vector3<f64>; 6],
    /// The platform's normal, base frame.
    platform_normal: Vector3<f64>,
    /// Largest angle at the base joints and at the platform joints, radians.
    cones: [Option<f64>; 2],
    /// The least distance between two leg axes (twice the leg radius), metres.
    clearance: Option<f64>,
}

/// Scratch space a row of columns reuses.
#[derive(Default)]
pub(super) struct Scratch {
    spare: Spans,
    cuts: Vec<f64>,
}

impl LegLimits {
    /// The limits of `geometry` at rotation `rotation` (about the pivot).
    pub(super) fn new(geometry: &Geometry, limits: &Limits, rotation: &Matrix3<f64>) -> Self {
        let c = geometry.pivot();
        Self {
            bases: *geometry.base_joints(),
            offsets: geometry.platform_joints().map(|a| c + rotation * (a - c)),
            platform_normal: rotation * Vector3::z(),
            cones: [limits.base_cone, limits.platform_cone].map(|a| a.map(|a| a.radians())),
            clearance: limits.leg_radius.map(|r| 2.0 * r),
        }
    }

    /// Narrow the column at `(x, y)`'s `spans` (platform heights) to where the limits
    /// hold; `dz` is the finest piece the clearance scan splits; returns the evaluations.
    pub(super) fn narrow(
        &self,
        x: f64,
        y: f64,
        dz: f64,
        spans: &mut Spans,
        scratch: &mut Scratch,
    ) -> usize {
        let mut evaluations = 0;
        let joint0 = |i: usize| Vector3::new(x, y, 0.0) + self.offsets[i];
        let normals = [Vector3::z(), self.platform_normal];
        if self.cones.iter().any(Option::is_some) {
            for i in 0..6 {
                let Some(&(lo, _)) = spans.first() else {
                    return evaluations;
                };
                let hi = spans.last().map_or(lo, |s| s.1);
                let q = joint0(i) - self.bases[i];
                scratch.cuts.clear();
                for (limit, n) in self.cones.iter().zip(&normals) {
                    if let Some(alpha) = limit {
                        roots_in(&cone_boundary(&q, n, *alpha), lo, hi, &mut scratch.cuts);
                    }
                }
                let within = |z: f64| {
                    let u = (q + Vector3::new(0.0, 0.0, z)).normalize();
                    self.cones.iter().zip(&normals).all(|(limit, n)| {
                        limit.is_none_or(|a| u.dot(n).clamp(-1.0, 1.0).acos() <= a)
                    })
                };
                evaluations +=
                    keep_between_cuts(spans, &mut scratch.cuts, within, &mut scratch.spare);
                std::mem::swap(spans, &mut scratch.spare);
            }
        }
        if let Some(least) = self.clearance {
            for (i, j) in LEG_PAIRS {
                if spans.is_empty() {
                    break;
                }
                let (pi, pj) = (joint0(i), joint0(j));
                let margin = |z: f64| {
                    let up = Vector3::new(0.0, 0.0, z);
                    segment_distance(self.bases[i], pi + up, self.bases[j], pj + up) - least
                };
                evaluations += keep_where_margin(spans, dz, margin, &mut scratch.spare);
                std::mem::swap(spans, &mut scratch.spare);
            }
        }
        evaluations
    }
}

/// `(L·n)² − cos²α |L|²` for `L(z) = q + z ẑ`: zero where the leg's angle to the unit axis
/// `n` is α (or π − α).
fn cone_boundary(q: &Vector3<f64>, n: &Vector3<f64>, alpha: f64) -> Poly {
    let c2 = alpha.cos().powi(2);
    let qn = q.dot(n);
    [
        qn * qn - c2 * q.norm_squared(),
        2.0 * qn * n.z - 2.0 * c2 * q.z,
        n.z * n.z - c2,
        0.0,
        0.0,
    ]
}
