//! Forward kinematics: leg lengths → pose, by a damped Newton method with a line search.
//!
//! Unknowns are the pose coordinates `x = (x, y, z, roll, pitch, yaw)` (metres,
//! radians); the residual is `f(x) = L(x) − L*`. Each iteration solves `F δ = −f`
//! with `F = ∂L/∂x` (leg unit vectors for the position; for the angles the moment
//! `w_k · (R(a_i − c) × u_i)` about the axis `w_k` each angle turns the platform about), then halves the step until `|f|²` decreases enough (Armijo). When the
//! Newton step fails (singular `F` or no decrease), a Levenberg–Marquardt step
//! `(FᵀF + λI) δ = −Fᵀ f` with growing `λ` is taken instead. Converged when every leg
//! is within [`ForwardOptions::tolerance`] of its target (default 1e-12 m).

pub mod assembly;
pub(crate) mod homotopy;
pub mod sequence;
pub(crate) mod study;

use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};
use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::model::angle::Angle;
use crate::model::geometry::Geometry;
use crate::model::pose::{Pose, rotation_zyx_from_sin_cos};

/// The most Newton steps a polish takes (from within the tolerance, quadratic
/// convergence reaches rounding in one or two).
const POLISH_STEPS: usize = 4;

/// Settings of the forward solver.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct ForwardOptions {
    /// Largest leg-length error accepted, metres.
    pub tolerance: f64,
    /// Most iterations before giving up.
    pub max_iterations: usize,
    /// Once within the tolerance, go on with plain Newton steps while each lowers the
    /// residual, down to rounding (for callers that difference poses found microseconds
    /// apart).
    #[serde(default)]
    pub polish: bool,
}

impl Default for ForwardOptions {
    fn default() -> Self {
        Self {
            tolerance: 1e-12,
            max_iterations: 100,
            polish: false,
        }
    }
}

/// A pose found by the forward solver, with how it was found.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct ForwardSolution {
    /// The pose.
    pub pose: Pose,
    /// Newton iterations taken.
    pub iterations: usize,
    /// Largest leg-length error at the pose, metres.
    pub residual: f64,
}

/// Why no pose was returned.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum ForwardError {
    /// A length that is not a positive finite number.
    #[error("leg L{leg} length {value} is not a positive finite number")]
    InvalidLength {
        /// Leg number from 1.
        leg: usize,
        /// The value given.
        value: f64,
    },
    /// A length outside the actuator's stroke.
    #[error("leg L{leg} length {length} m is outside the stroke [{min} m, {max} m]")]
    OutsideStroke {
        /// Leg number from 1.
        leg: usize,
        /// The value given.
        length: f64,
        /// Stroke minimum (or 0).
        min: f64,
        /// Stroke maximum (or infinity).
        max: f64,
    },
    /// The iteration stopped without reaching the tolerance.
    #[error(
        "forward kinematics did not converge: {iterations} iterations, leg-length residual {residual:.3e} m (these lengths may not be reachable)"
    )]
    NotConverged {
        /// Iterations taken.
        iterations: usize,
        /// Largest leg-length error reached, metres.
        residual: f64,
    },
    /// Servo angles given for a platform with linear legs.
    #[error("servo angles were given, but the platform has linear legs (give leg lengths)")]
    NotRotary,
    /// A servo angle that is not a finite number.
    #[error("servo {servo} angle {value} is not a finite number of degrees")]
    InvalidAngle {
        /// Servo number from 1.
        servo: usize,
        /// The value given, degrees.
        value: f64,
    },
    /// No real pose has these leg lengths (every solution of the forward problem is complex).
    #[error(
        "no real pose has these leg lengths: the forward problem's {complex_solutions} solutions are all complex"
    )]
    NoRealPose {
        /// Isolated complex solutions found.
        complex_solutions: usize,
    },
    /// Neither a Newton nor a damped step could reduce the residual.
    #[error(
        "forward kinematics stalled at a singular pose: {iterations} iterations, leg-length residual {residual:.3e} m"
    )]
    Singular {
        /// Iterations taken.
        iterations: usize,
        /// Largest leg-length error reached, metres.
        residual: f64,
    },
}

fn coordinates(p: &Pose) -> Vector6<f64> {
    Vector6::from(p.to_coordinates())
}

fn pose_of(x: &Vector6<f64>) -> Pose {
    Pose::from_coordinates(std::array::from_fn(|i| x[i]))
}

/// The rotation of pose angles `[roll, pitch, yaw]` and the three axes about which a
/// change of each angle turns the platform, in base-frame axes: `∂R/∂θ_k · v = w_k × (R v)`
/// with `w_roll = R_z R_y e_x`, `w_pitch = R_z e_y`, `w_yaw = e_z`. One sine and cosine per
/// angle.
fn rotation_and_axes(angles: [f64; 3]) -> (Matrix3<f64>, [Vector3<f64>; 3]) {
    let [(sr, cr), (sp, cp), (sy, cy)] = angles.map(f64::sin_cos);
    let r = rotation_zyx_from_sin_cos([sr, cr], [sp, cp], [sy, cy]);
    let axes = [
        Vector3::new(cy * cp, sy * cp, -sp),
        Vector3::new(-sy, cy, 0.0),
        Vector3::z(),
    ];
    (r, axes)
}

/// Residual `L(x) − target` and its derivative `∂L/∂x` at pose coordinates `x`, for
/// legs from the fixed points `anchors` (the base joints, or a rotary platform's horn
/// tips) to the platform joints.
fn residual_and_derivative(
    geometry: &Geometry,
    anchors: &[Vector3<f64>; 6],
    x: &Vector6<f64>,
    target: &[f64; 6],
) -> (Vector6<f64>, Matrix6<f64>) {
    let (r, axes) = rotation_and_axes([x[3], x[4], x[5]]);
    let position = Vector3::new(x[0], x[1], x[2]);
    let c = geometry.pivot();
    let mut f = Vector6::zeros();
    let mut d = Matrix6::zeros();
    for i in 0..6 {
        let arm = r * (geometry.platform_joints()[i] - c);
        let leg = position + c + arm - anchors[i];
        let length = leg.norm();
        let u = leg / length;
        f[i] = length - target[i];
        // ∂L/∂θ_k = u · (w_k × arm) = w_k · (arm × u).
        let moment = arm.cross(&u);
        for k in 0..3 {
            d[(i, k)] = u[k];
            d[(i, 3 + k)] = axes[k].dot(&moment);
        }
    }
    (f, d)
}

/// See [`Geometry::check_lengths`].
pub(crate) fn check_lengths(geometry: &Geometry, lengths: &[f64; 6]) -> Result<(), ForwardError> {
    let stroke = geometry.stroke();
    for (i, &l) in lengths.iter().enumerate() {
        if !(l.is_finite() && l > 0.0) {
            return Err(ForwardError::InvalidLength {
                leg: i + 1,
                value: l,
            });
        }
        if stroke.violation(l).is_some() {
            return Err(ForwardError::OutsideStroke {
                leg: i + 1,
                length: l,
                min: stroke.min.unwrap_or(0.0),
                max: stroke.max.unwrap_or(f64::INFINITY),
            });
        }
    }
    Ok(())
}

/// See [`Geometry::forward`].
pub(crate) fn forward(
    geometry: &Geometry,
    lengths: &[f64; 6],
    start: &Pose,
    options: &ForwardOptions,
) -> Result<ForwardSolution, ForwardError> {
    geometry.check_lengths(lengths)?;
    geometry.forward_unchecked(lengths, start, options)
}

/// See [`Geometry::forward_unchecked`].
pub(crate) fn forward_unchecked(
    geometry: &Geometry,
    lengths: &[f64; 6],
    start: &Pose,
    options: &ForwardOptions,
) -> Result<ForwardSolution, ForwardError> {
    geometry.forward_from(geometry.base_joints(), lengths, start, options)
}

/// See [`Geometry::forward_servos`].
pub(crate) fn forward_servos(
    geometry: &Geometry,
    angles: &[Angle; 6],
    start: &Pose,
    options: &ForwardOptions,
) -> Result<ForwardSolution, ForwardError> {
    let (tips, rod) = geometry.servo_anchors(angles)?;
    geometry.forward_from(&tips, &[rod; 6], start, options)
}

/// See [`Geometry::servo_anchors`].
pub(crate) fn servo_anchors(
    geometry: &Geometry,
    angles: &[Angle; 6],
) -> Result<([Vector3<f64>; 6], f64), ForwardError> {
    let Some(servos) = geometry.rotary() else {
        return Err(ForwardError::NotRotary);
    };
    for (i, a) in angles.iter().enumerate() {
        if !a.radians().is_finite() {
            return Err(ForwardError::InvalidAngle {
                servo: i + 1,
                value: a.radians().to_degrees(),
            });
        }
    }
    let tips = std::array::from_fn(|i| servos.horn_tip(i, &geometry.base_joints()[i], angles[i]));
    Ok((tips, servos.rod_length()))
}

/// See [`Geometry::forward_from`].
pub(crate) fn forward_from(
    geometry: &Geometry,
    anchors: &[Vector3<f64>; 6],
    lengths: &[f64; 6],
    start: &Pose,
    options: &ForwardOptions,
) -> Result<ForwardSolution, ForwardError> {
    let mut x = coordinates(start);
    let mut lambda: f64 = 1e-3;
    let mut iterations = 0;
    let (mut f, mut d) = residual_and_derivative(geometry, anchors, &x, lengths);
    loop {
        let residual = f.amax();
        if !residual.is_finite() {
            return Err(ForwardError::NotConverged {
                iterations,
                residual,
            });
        }
        if residual <= options.tolerance {
            if options.polish {
                (x, f) = polished(geometry, anchors, x, f, d, lengths);
            }
            return Ok(ForwardSolution {
                pose: pose_of(&x),
                iterations,
                residual: f.amax(),
            });
        }
        if iterations == options.max_iterations {
            return Err(ForwardError::NotConverged {
                iterations,
                residual,
            });
        }
        iterations += 1;
        let cost = f.norm_squared();
        // Newton step with backtracking; the accepted point's residual and derivative
        // are those of the next iteration.
        if let Some(step) = d.lu().solve(&(-f))
            && step.iter().all(|v| v.is_finite())
            && let Some(next) = line_search(geometry, anchors, &x, &step, lengths, cost)
        {
            (x, f, d) = next;
            lambda = (lambda * 0.3).max(1e-12);
            continue;
        }
        // Levenberg–Marquardt: increase the damping until the cost decreases.
        let g = d.transpose() * f;
        let h = d.transpose() * d;
        let mut improved = false;
        for _ in 0..30 {
            let damped = h + Matrix6::identity() * (lambda * (1.0 + h.diagonal().amax()));
            if let Some(step) = damped.cholesky().map(|c| c.solve(&(-g))) {
                let candidate = x + step;
                let (fc, dc) = residual_and_derivative(geometry, anchors, &candidate, lengths);
                if fc.norm_squared() < cost {
                    (x, f, d) = (candidate, fc, dc);
                    improved = true;
                    break;
                }
            }
            lambda *= 10.0;
        }
        if !improved {
            return Err(ForwardError::Singular {
                iterations,
                residual,
            });
        }
    }
}

/// Plain Newton steps from `x` (residual `f`, derivative `d`) while each lowers the
/// largest residual: the point and its residual where rounding stops the descent.
fn polished(
    geometry: &Geometry,
    anchors: &[Vector3<f64>; 6],
    mut x: Vector6<f64>,
    mut f: Vector6<f64>,
    mut d: Matrix6<f64>,
    lengths: &[f64; 6],
) -> (Vector6<f64>, Vector6<f64>) {
    for _ in 0..POLISH_STEPS {
        let Some(step) = d.lu().solve(&(-f)) else {
            break;
        };
        let candidate = x + step;
        let (fc, dc) = residual_and_derivative(geometry, anchors, &candidate, lengths);
        // Stop at rounding (or a NaN).
        if fc.amax().partial_cmp(&f.amax()) != Some(std::cmp::Ordering::Less) {
            break;
        }
        (x, f, d) = (candidate, fc, dc);
    }
    (x, f)
}

/// Backtracking along `step` until the cost drops by the Armijo fraction; returns the
/// accepted point with its residual and derivative.
fn line_search(
    geometry: &Geometry,
    anchors: &[Vector3<f64>; 6],
    x: &Vector6<f64>,
    step: &Vector6<f64>,
    lengths: &[f64; 6],
    cost: f64,
) -> Option<(Vector6<f64>, Vector6<f64>, Matrix6<f64>)> {
    let mut alpha = 1.0;
    while alpha > 1e-4 {
        let candidate = x + step * alpha;
        let (f, d) = residual_and_derivative(geometry, anchors, &candidate, lengths);
        let c = f.norm_squared();
        // Full Newton steps reduce the cost by ~2α·cost; ask for 1e-4 of that.
        if c <= cost * (1.0 - 2e-4 * alpha) || c == 0.0 {
            return Some((candidate, f, d));
        }
        alpha *= 0.5;
    }
    None
}

#[cfg(test)]
mod tests;
