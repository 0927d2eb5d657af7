//! Actuator forces for a payload: statics through the Jacobian transpose, and dynamics
//! by Newton–Euler on the moving platform.
//!
//! Leg `i` pushes the platform with force `f_i u_i` (`u_i` the unit leg vector from base
//! to platform joint), so **positive forces are compression** (the leg pushes the
//! platform away from the base), negative tension. With `J` the inverse Jacobian
//! (rows `[u_iᵀ, (r_i × u_i)ᵀ]`, `r_i` from the pivot point to joint `i`), the legs
//! exert the wrench `Jᵀ f` about the pivot point. Newton–Euler for the platform and
//! payload (mass `m`, centre of mass `c`, inertia `I` about `c`; `r_c` from the pivot
//! point to `c`; `a_c` its acceleration; `ω`, `α` the angular velocity and acceleration):
//!
//! ```text
//! Jᵀ f = [ m (a_c − g) ;  I_w α + ω × (I_w ω) + r_c × m (a_c − g) ],   I_w = R I Rᵀ
//! ```
//!
//! Statics is the special case `a_c = 0`, `ω = α = 0`. Velocities and accelerations come
//! from central differences of the sampled motion (times are arguments, never a clock).
//!
//! **Rotary servos** take the servo Jacobian `J_s` (twist → servo rates, see
//! [`Geometry::servo_jacobian`]) in place of `J`: by virtual work `τᵀ θ̇ = wᵀ t` for every
//! twist `t`, so the servo torques that exert the wrench `w` are `J_sᵀ τ = w`, in N·m,
//! positive in the direction of positive θ (lifting the horn).

use nalgebra::{Matrix3, Vector3, Vector6};
use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::analysis::differences::{first_difference, second_difference};
use crate::model::geometry::Geometry;
use crate::model::trajectory::Samples;

/// Standard gravity, m/s², along −z of the base frame.
pub const STANDARD_GRAVITY: f64 = 9.806_65;

/// The moving mass: platform plus payload.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Payload {
    /// Mass, kg.
    pub mass: f64,
    /// Centre of mass in the platform frame, m.
    pub centre_of_mass: Vector3<f64>,
    /// Inertia tensor about the centre of mass, in platform axes, kg·m².
    pub inertia: Matrix3<f64>,
}

/// Why forces could not be computed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ForceError {
    /// The Jacobian cannot be inverted at this sample.
    #[error(
        "the platform is at a singular pose at t = {time} s: the actuator forces are not determined there"
    )]
    Singular {
        /// Time of the sample, seconds.
        time: f64,
    },
    /// A servo cannot reach its platform joint at this sample.
    #[error("at t = {time} s servo {servo} cannot reach its platform joint: no torque holds it")]
    Unreachable {
        /// Time of the sample, seconds.
        time: f64,
        /// Servo number, from 1.
        servo: usize,
    },
    /// A payload value that is not usable.
    #[error("payload {field} must be {requirement}, got {value}")]
    BadPayload {
        /// The field.
        field: &'static str,
        /// What it must be.
        requirement: &'static str,
        /// Its value.
        value: f64,
    },
}

impl Payload {
    /// A payload, validated: positive finite mass, finite centre, symmetric positive
    /// semi-definite finite inertia.
    pub fn new(
        mass: f64,
        centre_of_mass: Vector3<f64>,
        inertia: Matrix3<f64>,
    ) -> Result<Self, ForceError> {
        use crate::ground::bounds::{INERTIA_KG_M2, LENGTH_M, MASS_KG};
        if !(mass.is_finite() && mass > 0.0 && mass <= MASS_KG) {
            return Err(ForceError::BadPayload {
                field: "mass",
                requirement: "a positive number of kilograms, at most 1e6",
                value: mass,
            });
        }
        if let Some(&v) = centre_of_mass
            .iter()
            .find(|v| !(v.is_finite() && v.abs() <= LENGTH_M))
        {
            return Err(ForceError::BadPayload {
                field: "centre of mass",
                requirement: "finite and within ±1000 m",
                value: v,
            });
        }
        if let Some(&v) = inertia
            .iter()
            .find(|v| !(v.is_finite() && v.abs() <= INERTIA_KG_M2))
        {
            return Err(ForceError::BadPayload {
                field: "inertia",
                requirement: "finite and within ±1e6 kg·m²",
                value: v,
            });
        }
        // Bounded iterations: finite, bounded input converges in a few sweeps.
        let moments =
            nalgebra::SymmetricEigen::try_new(inertia, f64::EPSILON, 200).map(|e| e.eigenvalues);
        let smallest = moments.as_ref().map_or(f64::NEG_INFINITY, |m| m.min());
        if smallest < -1e-12 * inertia.amax() {
            return Err(ForceError::BadPayload {
                field: "inertia",
                requirement: "positive semi-definite",
                value: smallest,
            });
        }
        // A rigid body's principal moments obey the triangle inequality: each is at most the
        // sum of the other two (equal for a flat plate).
        if let Some(m) = &moments {
            let (largest, sum) = (m.max(), m.sum());
            if largest > (sum - largest) * (1.0 + 1e-9) + 1e-12 * inertia.amax() {
                return Err(ForceError::BadPayload {
                    field: "inertia",
                    requirement: "a rigid body's: each principal moment at most the sum of the other two (kg·m²)",
                    value: largest,
                });
            }
        }
        Ok(Self {
            mass,
            centre_of_mass,
            inertia,
        })
    }
}

/// Leg forces along a motion, newtons, positive in compression (servo torques, N·m, for
/// a rotary platform).
#[derive(Clone, Debug, PartialEq)]
pub struct ForceSeries {
    /// Sample times, seconds.
    pub times: Vec<f64>,
    /// Static forces (payload weight only) per sample.
    pub statics: Vec<[f64; 6]>,
    /// Dynamic forces (weight and inertia) per sample.
    pub dynamics: Vec<[f64; 6]>,
}

/// The vector of the skew-symmetric part of `m`: `vee((m − mᵀ)/2)`.
pub(crate) fn skew_vector(m: &Matrix3<f64>) -> Vector3<f64> {
    Vector3::new(
        m[(2, 1)] - m[(1, 2)],
        m[(0, 2)] - m[(2, 0)],
        m[(1, 0)] - m[(0, 1)],
    ) * 0.5
}

/// The inertia tensor from its values (`[payload] inertia_kg_m2`, `forces --inertia`):
/// none (zero), three principal
/// moments, or the six entries Ixx, Iyy, Izz, Ixy, Ixz, Iyz of the symmetric tensor
/// (products of inertia as the tensor holds them, with their minus sign, as URDF and
/// Simscape take them). `None` for any other count.
pub fn inertia_tensor(values: &[f64]) -> Option<Matrix3<f64>> {
    let v = |i: usize| values[i];
    match values.len() {
        0 => Some(Matrix3::zeros()),
        3 => Some(Matrix3::from_diagonal(&Vector3::new(v(0), v(1), v(2)))),
        6 => Some(Matrix3::new(
            v(0),
            v(3),
            v(4),
            v(3),
            v(1),
            v(5),
            v(4),
            v(5),
            v(2),
        )),
        _ => None,
    }
}

/// Leg forces that hold the payload still at `pose` (weight only).
pub fn static_forces(
    geometry: &Geometry,
    pose: &crate::model::pose::Pose,
    payload: &Payload,
) -> Option<[f64; 6]> {
    leg_forces(
        geometry,
        pose,
        payload,
        &Vector3::zeros(),
        &Vector3::zeros(),
        &Vector3::zeros(),
    )
}

/// Leg forces (N; servo torques in N·m for a rotary platform) at `pose` for a
/// centre-of-mass acceleration `a_c` and angular velocity `omega` and acceleration
/// `alpha` (base frame). `None` at a singular pose or one a servo cannot reach.
pub fn leg_forces(
    geometry: &Geometry,
    pose: &crate::model::pose::Pose,
    payload: &Payload,
    a_c: &Vector3<f64>,
    omega: &Vector3<f64>,
    alpha: &Vector3<f64>,
) -> Option<[f64; 6]> {
    let r = pose.rotation();
    let r_c = r * (payload.centre_of_mass - geometry.pivot());
    let inertia = r * payload.inertia * r.transpose();
    let g = Vector3::new(0.0, 0.0, -STANDARD_GRAVITY);
    let force = payload.mass * (a_c - g);
    let moment = inertia * alpha + omega.cross(&(inertia * omega)) + r_c.cross(&force);
    let wrench = Vector6::new(force.x, force.y, force.z, moment.x, moment.y, moment.z);
    let (j, cond) = geometry.actuator_jacobian_and_conditioning(pose)?;
    if cond.is_singular() {
        return None;
    }
    let f = j.transpose().lu().solve(&wrench)?;
    Some(std::array::from_fn(|i| f[i]))
}

/// Static and dynamic leg forces at every sample of a motion.
pub fn forces_along(
    geometry: &Geometry,
    samples: &Samples,
    payload: &Payload,
) -> Result<ForceSeries, ForceError> {
    let times = &samples.times;
    let rotations: Vec<Matrix3<f64>> = samples.poses.iter().map(|p| p.rotation()).collect();
    let c = geometry.pivot();
    let centres: Vec<Vector3<f64>> = samples
        .poses
        .iter()
        .zip(&rotations)
        .map(|(p, r)| p.position + c + r * (payload.centre_of_mass - c))
        .collect();
    // Ṙ = [ω]× R, so ω = vee(skew(Ṙ Rᵀ)); R̈ = ([α]× + [ω]×²) R and [ω]×² is
    // symmetric, so α = vee(skew(R̈ Rᵀ)).
    let zero_v = Vector3::zeros();
    let zero_m = Matrix3::zeros();
    let omegas: Vec<Vector3<f64>> = (0..rotations.len())
        .map(|k| {
            skew_vector(
                &(first_difference(times, &rotations, k).unwrap_or(zero_m)
                    * rotations[k].transpose()),
            )
        })
        .collect();
    let mut statics = Vec::with_capacity(times.len());
    let mut dynamics = Vec::with_capacity(times.len());
    for (k, pose) in samples.poses.iter().enumerate() {
        let singular = || match geometry.servo_angles(pose) {
            Some(Err(e)) => ForceError::Unreachable {
                time: times[k],
                servo: e.servo,
            },
            _ => ForceError::Singular { time: times[k] },
        };
        let a_c = second_difference(times, &centres, k).unwrap_or(zero_v);
        let alpha = skew_vector(
            &(second_difference(times, &rotations, k).unwrap_or(zero_m) * rotations[k].transpose()),
        );
        statics.push(static_forces(geometry, pose, payload).ok_or_else(singular)?);
        dynamics.push(
            leg_forces(geometry, pose, payload, &a_c, &omegas[k], &alpha).ok_or_else(singular)?,
        );
    }
    Ok(ForceSeries {
        times: times.clone(),
        statics,
        dynamics,
    })
}

#[cfg(test)]
mod tests;
