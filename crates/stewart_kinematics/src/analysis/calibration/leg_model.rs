//! One leg's closure equation over the measured poses, and its derivative with respect to
//! the leg's seven parameters.
//!
//! Parameters, in this order: the base joint `b` (x, y, z, base frame), the platform joint
//! `a` (x, y, z, platform frame) and the actuator offset `o`. With a measured pose
//! (`p`, `R`) and pivot `c`, the platform joint stands at `q = p + c − R c + R a`.
//!
//! - **Linear leg**, commanded length `L`: the leg really is `L + o` long, so the residual
//!   is `|q − b| − (L + o)`.
//! - **Rotary servo**, commanded model angle `θ`: the horn really stands at `θ + o`, its tip
//!   at `H = b + h (cos(θ+o) d_x, cos(θ+o) d_y, sin(θ+o))` (`h` the horn length, `d` the
//!   horn direction); the residual is the rod's closure `|q − H| − s`.
//!
//! Both are `|q − A| − ℓ` for an anchor `A` and a length `ℓ`; with `n = (q − A)/|q − A|`
//! the derivatives are `∂/∂a = Rᵀn`, `∂/∂b = −n` and `∂/∂o = −1` (linear) or
//! `−n · ∂H/∂θ` (rotary).

use nalgebra::{Matrix3, Vector3};

use crate::model::geometry::Geometry;

use super::Measurement;

/// Number of parameters of one leg.
pub(crate) const PARAMETERS: usize = 7;

/// The actuator of one leg, as the closure equation needs it.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Drive {
    /// A linear leg.
    Linear,
    /// A rotary servo: horn length, horn direction at angle 0 (unit, horizontal), rod length.
    Servo {
        horn: f64,
        direction: Vector3<f64>,
        rod: f64,
    },
}

/// One measured pose, prepared once for every leg: `q = shift + rotation · a`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PreparedPose {
    rotation: Matrix3<f64>,
    shift: Vector3<f64>,
}

impl PreparedPose {
    /// The pose of `m` for a platform rotating about `pivot`.
    pub(crate) fn new(m: &Measurement, pivot: &Vector3<f64>) -> Self {
        let rotation = m.pose.rotation();
        Self {
            rotation,
            shift: m.pose.position + pivot - rotation * pivot,
        }
    }
}

/// Leg `leg`'s closure equations over all measured poses.
#[derive(Clone, Debug)]
pub(crate) struct LegModel<'a> {
    drive: Drive,
    poses: &'a [PreparedPose],
    /// Commanded length (m) or model servo angle (rad) per pose.
    commanded: Vec<f64>,
}

impl<'a> LegModel<'a> {
    /// Leg `leg` (from 0) of `geometry` over `poses`, commanded `measurements[k].commanded[leg]`.
    pub(crate) fn new(
        geometry: &Geometry,
        leg: usize,
        poses: &'a [PreparedPose],
        measurements: &[Measurement],
    ) -> Self {
        let drive = match geometry.rotary() {
            None => Drive::Linear,
            Some(servos) => Drive::Servo {
                horn: servos.horn_length(),
                direction: servos.horn_direction(leg),
                rod: servos.rod_length(),
            },
        };
        Self {
            drive,
            poses,
            commanded: measurements.iter().map(|m| m.commanded[leg]).collect(),
        }
    }

    /// Number of measured poses (equations).
    pub(crate) fn len(&self) -> usize {
        self.poses.len()
    }

    /// Residual of pose `k` for parameters `x`, and its gradient when `gradient` is given.
    pub(crate) fn residual(
        &self,
        x: &[f64; PARAMETERS],
        k: usize,
        gradient: Option<&mut [f64; PARAMETERS]>,
    ) -> f64 {
        let pose = &self.poses[k];
        let b = Vector3::new(x[0], x[1], x[2]);
        let a = Vector3::new(x[3], x[4], x[5]);
        let offset = x[6];
        let q = pose.shift + pose.rotation * a;
        let (anchor, length, tip_rate) = match self.drive {
            Drive::Linear => (b, self.commanded[k] + offset, None),
            Drive::Servo {
                horn,
                direction,
                rod,
            } => {
                let (s, c) = (self.commanded[k] + offset).sin_cos();
                let tip = b + horn * Vector3::new(c * direction.x, c * direction.y, s);
                let rate = horn * Vector3::new(-s * direction.x, -s * direction.y, c);
                (tip, rod, Some(rate))
            }
        };
        let e = q - anchor;
        let distance = e.norm();
        if let Some(g) = gradient {
            let n = e / distance;
            let along_a = pose.rotation.transpose() * n;
            g[..3].copy_from_slice((-n).as_slice());
            g[3..6].copy_from_slice(along_a.as_slice());
            g[6] = match tip_rate {
                None => -1.0,
                Some(rate) => -n.dot(&rate),
            };
        }
        distance - length
    }

    /// Sum of squared residuals for parameters `x`.
    pub(crate) fn cost(&self, x: &[f64; PARAMETERS]) -> f64 {
        (0..self.len())
            .map(|k| self.residual(x, k, None).powi(2))
            .sum()
    }
}
