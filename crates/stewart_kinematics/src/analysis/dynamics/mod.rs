//! Rigid-body dynamics of the whole mechanism: inverse dynamics with the legs' own masses,
//! the Cartesian stiffness, the mass matrix and the natural modes.
//!
//! **Model.** The moving platform with its payload ([`Payload`]: mass, centre of mass,
//! full inertia tensor) and, per actuator, two slender parts (`[dynamics]`,
//! [`DynamicsSettings`]): a linear leg's cylinder (hanging from the base joint) and rod
//! (from the platform joint), or a servo's horn (turning with the shaft) and rod (from
//! the horn tip to the platform joint). Each part has a mass, a centre of mass along it
//! and a moment of inertia about that centre; a part's spin about its own axis is not
//! modelled. Gravity is `−9.80665 m/s²` along the base frame's z. Each actuator adds
//! viscous friction `c q̇` and, for the modes, an axial stiffness `k`.
//!
//! **Inverse dynamics** by the principle of virtual work (Tsai 2000, *Solving the inverse
//! dynamics of a Stewart–Gough manipulator by the principle of virtual work*), which gives
//! the same forces as the Newton–Euler recursion of Dasgupta & Mruthyunjaya (1998) with
//! fewer unknowns: every body's inertial and gravity wrench — `m (a − g)` at its centre of
//! mass and `I α + ω × I ω` — is carried to the platform twist through that body's own
//! velocity map, and the actuator efforts `τ` balance the sum, `J_aᵀ τ = Σ J_bᵀ w_b`, plus
//! the friction `c q̇`. `J_a` is the legs' Jacobian (rows `[u, r × u]`) or the servos'
//! (twist → servo rates). Positive efforts push the platform away from the base (legs in
//! compression) or turn the servo towards positive angles (lifting the horn).
//!
//! **Stiffness and modes.** `K = J_aᵀ diag(k) J_a`, and the mass matrix
//! `M = Σ J_bᵀ diag(m, I) J_b` (the kinetic energy is `½ tᵀ M t` for the platform twist
//! `t`), both about the platform frame's origin in base-frame axes; the modes solve
//! `K v = ω² M v`.
//!
//! The tests check the inverse dynamics against Lagrange's equations written from the
//! positions of every body alone (exact derivatives by automatic differentiation), the
//! mass matrix against the kinetic energy of every body, and the stiffness against the
//! closed form of a cubic configuration.

mod along;
mod modes;
mod parts;

use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};
use thiserror::Error;

use crate::analysis::forces::{Payload, STANDARD_GRAVITY};
pub use crate::model::dynamics_settings::DynamicsSettings;
use crate::model::geometry::Geometry;
use crate::model::pose::Pose;
pub use along::{LowestMode, efforts_along, lowest_mode_along, motion_states};
pub use modes::{AXES, Modes, dominant, joint_travel, modes, moved_along};
use parts::{Leg, LegTrouble, joint_acceleration, wrench_at};

/// The platform's pose and how it moves: the twist and its rate about the pivot point
/// (the point `pose.position` places), base-frame axes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MotionState {
    /// Where the platform is.
    pub pose: Pose,
    /// `(v, ω)`: the pivot point's velocity (m/s) and the angular velocity (rad/s).
    pub twist: Vector6<f64>,
    /// `(a, α)`: the pivot point's acceleration (m/s²) and the angular acceleration (rad/s²).
    pub twist_rate: Vector6<f64>,
}

impl MotionState {
    /// The platform held still at `pose`.
    pub fn still(pose: Pose) -> Self {
        Self {
            pose,
            twist: Vector6::zeros(),
            twist_rate: Vector6::zeros(),
        }
    }
}

/// Why dynamics could not be computed at a pose.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum DynamicsError {
    /// The actuators' Jacobian cannot be inverted.
    #[error("the platform is at a singular pose: the actuator efforts are not determined there")]
    Singular,
    /// A servo cannot reach its platform joint.
    #[error("servo {servo} cannot reach its platform joint")]
    Unreachable {
        /// Servo number, from 1.
        servo: usize,
    },
    /// `[dynamics] actuator_stiffness` is needed and absent.
    #[error(
        "the actuator stiffness is not given: add `actuator_stiffness` to the scenario's [dynamics] table (N/m for linear legs, N·m/rad for servos) or pass `--set dynamics.actuator_stiffness=VALUE`"
    )]
    NoStiffness,
    /// A leg's two joints meet at this pose: it has no direction, so its stiffness and
    /// force are undefined.
    #[error(
        "leg {leg} has zero length at this pose (its joints meet): it has no direction, so the stiffness and the modes are undefined there"
    )]
    LegWithoutDirection {
        /// Leg number, from 1.
        leg: usize,
    },
    /// The mass matrix is not positive definite: some motion has no inertia.
    #[error(
        "the mass matrix is not positive definite: some motion of the platform has no inertia, or next to none beside the others (give [payload] a mass and inertia_kg_m2 a positive moment about every axis, of comparable sizes)"
    )]
    MassMatrixNotPositive,
}

impl From<LegTrouble> for DynamicsError {
    fn from(t: LegTrouble) -> Self {
        match t {
            LegTrouble::Unreachable(servo) => DynamicsError::Unreachable { servo },
        }
    }
}

/// The inertial and gravity wrench `(m (a − g), I α + ω × I ω)` of a body.
fn body_wrench(
    mass: f64,
    inertia: &Matrix3<f64>,
    acceleration: &Vector3<f64>,
    omega: &Vector3<f64>,
    alpha: &Vector3<f64>,
) -> (Vector3<f64>, Vector3<f64>) {
    let g = Vector3::new(0.0, 0.0, -STANDARD_GRAVITY);
    let force = mass * (acceleration - g);
    let moment = inertia * alpha + omega.cross(&(inertia * omega));
    (force, moment)
}

/// `Jᵀ x = b` for the 6×6 `j` when it is well enough conditioned.
fn solve_transposed(j: &Matrix6<f64>, b: &Vector6<f64>) -> Option<Vector6<f64>> {
    let lu = j.transpose().lu();
    let u = lu.u();
    let diagonal = u.diagonal().abs();
    let invertible = diagonal.min() > 1e-13 * diagonal.max();
    if !invertible {
        return None;
    }
    lu.solve(b).filter(|x| x.iter().all(|v| v.is_finite()))
}

/// The actuator efforts (N for legs, N·m for servos) that move the platform and
/// `payload` through `state`, with the legs' parts, friction and gravity of
/// `dynamics` (see the module's documentation for the model and signs).
pub fn inverse_dynamics(
    geometry: &Geometry,
    state: &MotionState,
    payload: &Payload,
    dynamics: &DynamicsSettings,
) -> Result<[f64; 6], DynamicsError> {
    let pose = &state.pose;
    let r = pose.rotation();
    let pivot = pose.position + geometry.pivot();
    let legs = parts::legs(geometry, pose, &pivot, Some(&state.twist), dynamics)?;
    let (t, dt) = (&state.twist, &state.twist_rate);
    let omega = t.fixed_rows::<3>(3).into_owned();
    let alpha = dt.fixed_rows::<3>(3).into_owned();
    // The platform and payload (the same wrench `leg_forces` balances).
    let r_c = r * (payload.centre_of_mass - geometry.pivot());
    let a_c = joint_acceleration(t, dt, &r_c);
    let inertia = r * payload.inertia * r.transpose();
    let (force, moment) = body_wrench(payload.mass, &inertia, &a_c, &omega, &alpha);
    let moment = moment + r_c.cross(&force);
    let mut load = Vector6::new(force.x, force.y, force.z, moment.x, moment.y, moment.z);
    // Each leg's parts: a force at its platform joint and a load on its actuator.
    let mut direct = [0.0; 6];
    let mut j = Matrix6::zeros();
    for (i, leg) in legs.iter().enumerate() {
        j.set_row(i, &leg.row.transpose());
        let a_p = joint_acceleration(t, dt, &leg.arm);
        let q_ddot = leg.rate_per_joint_acc.dot(&a_p) + leg.rate_bias;
        let mut at_joint = Vector3::zeros();
        for part in leg
            .parts
            .iter()
            .filter(|p| p.mass != 0.0 || p.inertia != Matrix3::zeros())
        {
            let acc = part.lin_joint * a_p + part.lin_rate * q_ddot + part.acc_bias;
            let alpha = part.ang_joint * a_p + part.ang_rate * q_ddot + part.alpha_bias;
            let (f, mu) = body_wrench(part.mass, &part.inertia, &acc, &part.omega, &alpha);
            at_joint += part.lin_joint.tr_mul(&f) + part.ang_joint.tr_mul(&mu);
            direct[i] += part.lin_rate.dot(&f) + part.ang_rate.dot(&mu);
        }
        if at_joint != Vector3::zeros() {
            load += wrench_at(&leg.arm, &at_joint);
        }
    }
    let balance = solve_transposed(&j, &load).ok_or(DynamicsError::Singular)?;
    let friction = dynamics.actuator_friction;
    Ok(std::array::from_fn(|i| {
        balance[i] + direct[i] + friction * legs[i].rate
    }))
}

/// The legs at `pose` about the platform frame's origin, standing still.
fn legs_about_origin(
    geometry: &Geometry,
    pose: &Pose,
    dynamics: &DynamicsSettings,
) -> Result<[Leg; 6], DynamicsError> {
    let origin = geometry.platform_centre(pose);
    Ok(parts::legs(geometry, pose, &origin, None, dynamics)?)
}

/// The Cartesian stiffness `K = J_aᵀ diag(k) J_a` at `pose` for actuators of axial
/// stiffness `k` (N/m, or N·m/rad for servos): N/m, N, N·m/rad blocks, about the
/// platform frame's origin in base-frame axes.
pub fn stiffness(geometry: &Geometry, pose: &Pose, k: f64) -> Result<Matrix6<f64>, DynamicsError> {
    let legs = legs_about_origin(geometry, pose, &DynamicsSettings::default())?;
    Ok(legs.iter().fold(Matrix6::zeros(), |sum, leg| {
        sum + k * leg.row * leg.row.transpose()
    }))
}

/// The lowest stiffness of the platform at `pose` for actuators of stiffness `k`, N/m:
/// the smallest eigenvalue of `D K D` with `D = diag(1, 1, 1, 1/ℓ, 1/ℓ, 1/ℓ)` and `ℓ`
/// the characteristic length (a rotation counted as the motion it gives at that
/// distance, as the conditioning does). `None` when a servo cannot reach its joint.
pub fn lowest_stiffness(geometry: &Geometry, pose: &Pose, k: f64) -> Option<f64> {
    let stiffness = stiffness(geometry, pose, k).ok()?;
    let l = geometry.characteristic_length();
    let d = Matrix6::from_diagonal(&Vector6::new(1.0, 1.0, 1.0, 1.0 / l, 1.0 / l, 1.0 / l));
    let scaled = d * stiffness * d;
    Some(scaled.symmetric_eigenvalues().min().max(0.0))
}

/// The 6×6 mass matrix at `pose`: the kinetic energy of platform, payload and legs is
/// `½ tᵀ M t` for the twist `t` about the platform frame's origin (base-frame axes).
pub fn mass_matrix(
    geometry: &Geometry,
    pose: &Pose,
    payload: &Payload,
    dynamics: &DynamicsSettings,
) -> Result<Matrix6<f64>, DynamicsError> {
    let legs = legs_about_origin(geometry, pose, dynamics)?;
    let r = pose.rotation();
    let r_c = r * payload.centre_of_mass;
    let mut m = body_matrix(
        payload.mass,
        &(r * payload.inertia * r.transpose()),
        &joint_map(&r_c),
        &angular_map(),
    );
    for leg in &legs {
        let joint = joint_map(&leg.arm);
        let row = leg.row.transpose();
        for part in &leg.parts {
            let lin = part.lin_joint * joint + part.lin_rate * row;
            let ang = part.ang_joint * joint + part.ang_rate * row;
            m += body_matrix(part.mass, &part.inertia, &lin, &ang);
        }
    }
    Ok(m)
}

/// `J_t = [I | −[r]×]`: a platform point's velocity per twist, for the point at `arm`.
fn joint_map(arm: &Vector3<f64>) -> nalgebra::Matrix3x6<f64> {
    let mut j = nalgebra::Matrix3x6::zeros();
    j.fixed_view_mut::<3, 3>(0, 0).fill_with_identity();
    j.fixed_view_mut::<3, 3>(0, 3)
        .copy_from(&(-arm.cross_matrix()));
    j
}

/// The platform's angular velocity per twist: `[0 | I]`.
fn angular_map() -> nalgebra::Matrix3x6<f64> {
    let mut j = nalgebra::Matrix3x6::zeros();
    j.fixed_view_mut::<3, 3>(0, 3).fill_with_identity();
    j
}

/// A body's share of the mass matrix: `m J_vᵀ J_v + J_ωᵀ I J_ω`.
fn body_matrix(
    mass: f64,
    inertia: &Matrix3<f64>,
    lin: &nalgebra::Matrix3x6<f64>,
    ang: &nalgebra::Matrix3x6<f64>,
) -> Matrix6<f64> {
    mass * lin.transpose() * lin + ang.transpose() * inertia * ang
}

#[cfg(test)]
mod tests;
