//! The rig's limits as linear constraints on the plan: every actuator's value (leg length
//! or servo angle) inside its stroke (range), and each joint's cone angle under its limit
//! where one is set (a rotary rig's rods measured from their horn tips, as `check` does), at the end of every step; the actuators' speeds at the end of every
//! step and accelerations over every step under their limits. Each is linearised about
//! the pose now, `c(s) ≈ c(s₀) + M (s − s₀)`, with `M` by central differences of the exact
//! inverse kinematics, and kept a margin inside its limit; the pose that comes out is then
//! checked exactly.

use nalgebra::Vector3;

use super::horizon::{Horizon, StepValue};
use super::qp::Constraints;
use crate::analysis::checks::servos::rod_cone_angles;
use crate::analysis::cueing::{Cue, pose_at};
use crate::model::angle::Angle;
use crate::model::geometry::Geometry;
use crate::model::limits::{Limits, joint_angles};
use crate::model::pose::Pose;

/// The most constrained values: six actuators, six base cones, six platform cones.
pub const MAX_VALUES: usize = 18;

/// The pose of a platform whose reference point (at `arm` from the rotation centre) is
/// moved by `s[0..3]` from home and turned by the angles `s[3..6]` (radians) about it.
pub fn pose_of(geometry: &Geometry, arm: Vector3<f64>, s: &[f64; 6]) -> Pose {
    let cue = Cue {
        position: [s[0], s[1], s[2]],
        angles: [s[3], s[4], s[5]],
        ..Cue::default()
    };
    pose_at(geometry, arm, &cue, 1.0)
}

/// The limited values of one rig and their bounds.
#[derive(Clone, Debug)]
pub struct Rig {
    geometry: Geometry,
    arm: Vector3<f64>,
    /// Lower and upper bound of each value, the margin taken off.
    bounds: [(f64, f64); MAX_VALUES],
    count: usize,
    base_cone: bool,
    platform_cone: bool,
    /// The actuators' speed and acceleration limits, the margin taken off.
    speed: Option<f64>,
    accel: Option<f64>,
}

/// The values and their linearisation at one state.
#[derive(Clone, Copy, Debug)]
pub struct Linearised {
    /// The values now.
    pub values: [f64; MAX_VALUES],
    /// `∂value/∂s`, one row per value.
    pub slopes: [[f64; 6]; MAX_VALUES],
    /// `ṡᵀ (∂²value/∂s²) ṡ` at the velocity now: the share of each value's acceleration
    /// that comes from moving at all (a leg turning as it slides), held over the horizon.
    pub curvature: [f64; MAX_VALUES],
}

/// The step of the central differences, metres or radians.
const DELTA: f64 = 1e-6;

impl Rig {
    /// The limits of `geometry` within `limits`, each kept `margin` (a share of the
    /// stroke, range or limit) inside, for the reference point at `arm`.
    pub fn new(geometry: &Geometry, limits: &Limits, arm: Vector3<f64>, margin: f64) -> Self {
        let mut bounds = [(f64::NEG_INFINITY, f64::INFINITY); MAX_VALUES];
        let [lo, hi] = geometry.quantity_limits();
        let width = match (lo, hi) {
            (Some(l), Some(h)) => h - l,
            _ => lo.or(hi).map_or(0.0, f64::abs),
        };
        let keep = margin * width;
        for b in bounds.iter_mut().take(6) {
            *b = (
                lo.map_or(f64::NEG_INFINITY, |l| l + keep),
                hi.map_or(f64::INFINITY, |h| h - keep),
            );
        }
        let mut count = 6;
        for cone in [limits.base_cone, limits.platform_cone]
            .into_iter()
            .flatten()
        {
            let max = cone.radians() * (1.0 - margin);
            for b in bounds.iter_mut().skip(count).take(6) {
                *b = (f64::NEG_INFINITY, max);
            }
            count += 6;
        }
        let [speed, accel, _] = geometry.actuator_rate_limits(limits);
        Self {
            geometry: geometry.clone(),
            arm,
            bounds,
            count,
            base_cone: limits.base_cone.is_some(),
            platform_cone: limits.platform_cone.is_some(),
            speed: speed.map(|v| v * (1.0 - margin)),
            accel: accel.map(|v| v * (1.0 - margin)),
        }
    }

    /// The number of limited values.
    pub fn count(&self) -> usize {
        self.count
    }

    /// The rows [`Rig::push_rows`] adds for a horizon of `steps`, at most.
    pub fn rows(&self, steps: usize) -> usize {
        steps
            * (self.count
                + 6 * (usize::from(self.speed.is_some()) + usize::from(self.accel.is_some())))
    }

    /// The limited values at `s`: actuator values (m or °), then the cone angles (rad)
    /// set; `None` where a servo cannot reach its joint.
    pub fn values(&self, s: &[f64; 6]) -> Option<[f64; MAX_VALUES]> {
        let pose = pose_of(&self.geometry, self.arm, s);
        let actuators = self.geometry.actuator_values_at(&pose).ok()?;
        let mut out = [0.0; MAX_VALUES];
        out[..6].copy_from_slice(&actuators);
        if self.base_cone || self.platform_cone {
            let angles = self.cone_angles(&pose, &actuators);
            let mut at = 6;
            for (on, k) in [(self.base_cone, 0), (self.platform_cone, 1)] {
                if on {
                    out[at..at + 6].copy_from_slice(&angles[k]);
                    at += 6;
                }
            }
        }
        Some(out)
    }

    /// The joints' cone angles (radians) at `pose`, whose actuator values are `actuators`:
    /// at the base (`[0]`) and platform (`[1]`) joints of each leg, or on a rotary rig of
    /// each rod, from its horn tip — where `check` measures them.
    fn cone_angles(&self, pose: &Pose, actuators: &[f64; 6]) -> [[f64; 6]; 2] {
        let solution = self.geometry.inverse(pose);
        let Some(servos) = self.geometry.rotary() else {
            let angles = joint_angles(pose, &solution);
            return [angles.map(|a| a[0]), angles.map(|a| a[1])];
        };
        let bases = self.geometry.base_joints();
        let tips = std::array::from_fn(|i| {
            servos.horn_tip(i, &bases[i], Angle::from_degrees(actuators[i]))
        });
        rod_cone_angles(pose, &solution.platform_joints, &tips).map(|k| k.map(f64::to_radians))
    }

    /// The values at `s`, their slopes, and their curvature along the velocity `v`.
    pub fn linearise(&self, s: &[f64; 6], v: &[f64; 6]) -> Option<Linearised> {
        let values = self.values(s)?;
        // The second difference along v, over a step that moves the pose by 1 mm.
        let speed = v.iter().map(|x| x * x).sum::<f64>().sqrt();
        let mut curvature = [0.0; MAX_VALUES];
        if speed > 0.0 {
            let e = 1e-3 / speed;
            let along = |sign: f64| -> [f64; 6] { std::array::from_fn(|i| s[i] + sign * e * v[i]) };
            let (a, b) = (self.values(&along(1.0))?, self.values(&along(-1.0))?);
            for (c, ((x, y), m)) in curvature.iter_mut().zip(a.iter().zip(&b).zip(&values)) {
                *c = (x + y - 2.0 * m) / (e * e);
            }
        }
        let mut slopes = [[0.0; 6]; MAX_VALUES];
        for axis in 0..6 {
            let (mut up, mut down) = (*s, *s);
            up[axis] += DELTA;
            down[axis] -= DELTA;
            let (a, b) = (self.values(&up)?, self.values(&down)?);
            for (row, (x, y)) in slopes.iter_mut().zip(a.iter().zip(&b)) {
                row[axis] = (x - y) / (2.0 * DELTA);
            }
        }
        Some(Linearised {
            values,
            slopes,
            curvature,
        })
    }

    /// Add the rows that keep the plan within the limits, from state `(s, v)` with the
    /// linearisation `lin` at `s`.
    pub fn push_rows(
        &self,
        c: &mut Constraints,
        layout: &Horizon,
        lin: &Linearised,
        s: &[f64; 6],
        v: &[f64; 6],
    ) {
        for k in 0..layout.steps {
            for i in 0..self.count {
                let slope = &lin.slopes[i];
                // c(s_k) ≈ c₀ + M (s_k − s₀), s_k − s₀ = free part + plan part.
                let free: f64 = (0..6)
                    .map(|a| slope[a] * (layout.free(StepValue::EndPosition, k, s[a], v[a]) - s[a]))
                    .sum();
                let here = lin.values[i] + free;
                let (lo, hi) = self.bounds[i];
                if lo == f64::NEG_INFINITY && hi == f64::INFINITY {
                    continue;
                }
                // A value already inside the margin (the exact motion left the
                // linearisation, or the platform was stopped there) may stay where it is
                // or come back, never go further: the programme stays feasible and the
                // planner recovers instead of holding the platform for ever.
                let (lo, hi) = (lo.min(lin.values[i]), hi.max(lin.values[i]));
                let row = c.push(lo - here, hi - here);
                for (axis, m) in slope.iter().enumerate() {
                    layout.add_quantity(row, StepValue::EndPosition, k, axis, *m);
                }
            }
            for (limit, quantity) in [
                (self.speed, StepValue::EndVelocity),
                (self.accel, StepValue::Acceleration),
            ] {
                let Some(limit) = limit else { continue };
                for (slope, bend) in lin.slopes.iter().zip(&lin.curvature).take(6) {
                    let mut free: f64 = (0..6)
                        .map(|a| slope[a] * layout.free(quantity, k, s[a], v[a]))
                        .sum();
                    if quantity == StepValue::Acceleration {
                        free += bend;
                    }
                    let row = c.push(-limit - free, limit - free);
                    for (axis, m) in slope.iter().enumerate() {
                        layout.add_quantity(row, quantity, k, axis, *m);
                    }
                }
            }
        }
    }
}
