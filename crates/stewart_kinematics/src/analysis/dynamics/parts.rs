//! The moving parts of each actuator at a pose: where their velocities come from, what
//! accelerates them beyond that, and the actuator's own row of the Jacobian — for linear
//! legs (cylinder and rod) and for servos (horn and rod), about any reference point of
//! the platform. Inverse dynamics and the mass matrix both read them, so the two agree by
//! construction; the tests check both against energy computed independently.
//!
//! Notation (leg `i`, all in base-frame axes): `r` from the reference point `O` to the
//! platform joint `p`, the joint's velocity `v_p = v_O + ω × r`, the actuator rate `q̇`.
//! A part's centre-of-mass velocity is `lin_joint · v_p + lin_rate q̇` and its angular
//! velocity `ang_joint · v_p + ang_rate q̇`; its accelerations are the same maps applied
//! to `a_p` and `q̈`, plus the velocity-product terms `acc_bias`, `alpha_bias`.

use nalgebra::{Matrix3, Vector3, Vector6};

use crate::model::dynamics_settings::{DynamicsSettings, LegPart};
use crate::model::geometry::Geometry;
use crate::model::pose::Pose;
use crate::solve::servo_closure;

/// One moving part of a leg at a pose (and, for accelerations, a twist).
#[derive(Clone, Copy, Debug)]
pub(crate) struct MovingPart {
    /// Mass, kg.
    pub mass: f64,
    /// Inertia about the centre of mass, base-frame axes, kg·m².
    pub inertia: Matrix3<f64>,
    /// Centre-of-mass velocity per joint velocity.
    pub lin_joint: Matrix3<f64>,
    /// Centre-of-mass velocity per actuator rate.
    pub lin_rate: Vector3<f64>,
    /// Angular velocity per joint velocity.
    pub ang_joint: Matrix3<f64>,
    /// Angular velocity per actuator rate.
    pub ang_rate: Vector3<f64>,
    /// Angular velocity, rad/s (zero without a twist).
    pub omega: Vector3<f64>,
    /// Centre-of-mass acceleration from the velocities alone, m/s².
    pub acc_bias: Vector3<f64>,
    /// Angular acceleration from the velocities alone, rad/s².
    pub alpha_bias: Vector3<f64>,
}

impl MovingPart {
    fn still(part: &LegPart) -> Self {
        Self {
            mass: part.mass,
            inertia: Matrix3::zeros(),
            lin_joint: Matrix3::zeros(),
            lin_rate: Vector3::zeros(),
            ang_joint: Matrix3::zeros(),
            ang_rate: Vector3::zeros(),
            omega: Vector3::zeros(),
            acc_bias: Vector3::zeros(),
            alpha_bias: Vector3::zeros(),
        }
    }
}

/// Leg `i` at a pose: its joint arm, its actuator's Jacobian row, its rate and its parts.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Leg {
    /// From the reference point to the platform joint, m.
    pub arm: Vector3<f64>,
    /// The actuator's row of the Jacobian: `q̇ = row · (v_O, ω)`.
    pub row: Vector6<f64>,
    /// Actuator rate (m/s or rad/s; zero without a twist).
    pub rate: f64,
    /// For servos: `θ̈ = rate_per_joint_acc · a_p + rate_bias` (zero for linear legs).
    pub rate_per_joint_acc: Vector3<f64>,
    /// For servos, the part of `θ̈` from velocities alone.
    pub rate_bias: f64,
    /// Cylinder and rod, or horn and rod.
    pub parts: [MovingPart; 2],
}

/// Why a leg has no parts at a pose.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum LegTrouble {
    /// Servo `servo` (from 1) cannot reach its joint.
    Unreachable(usize),
}

/// The joint's velocity `v_O + ω × r` for twist `(v_O, ω)`.
pub(crate) fn joint_velocity(twist: &Vector6<f64>, arm: &Vector3<f64>) -> Vector3<f64> {
    let v = twist.fixed_rows::<3>(0).into_owned();
    let w = twist.fixed_rows::<3>(3).into_owned();
    v + w.cross(arm)
}

/// The joint's acceleration for twist `(v_O, ω)` and its rate `(a_O, α)`.
pub(crate) fn joint_acceleration(
    twist: &Vector6<f64>,
    rate: &Vector6<f64>,
    arm: &Vector3<f64>,
) -> Vector3<f64> {
    let w = twist.fixed_rows::<3>(3).into_owned();
    joint_velocity(rate, arm) + w.cross(&w.cross(arm))
}

/// `J_tᵀ x` for the joint at `arm`: the wrench `(x, arm × x)` of a force `x` there.
pub(crate) fn wrench_at(arm: &Vector3<f64>, x: &Vector3<f64>) -> Vector6<f64> {
    let m = arm.cross(x);
    Vector6::new(x.x, x.y, x.z, m.x, m.y, m.z)
}

/// The six legs at `pose` about the world point `reference` (a point moving with the
/// platform), with velocities for `twist` when given.
pub(crate) fn legs(
    geometry: &Geometry,
    pose: &Pose,
    reference: &Vector3<f64>,
    twist: Option<&Vector6<f64>>,
    dynamics: &DynamicsSettings,
) -> Result<[Leg; 6], LegTrouble> {
    let solution = geometry.inverse(pose);
    let zero = Vector6::zeros();
    let twist = twist.unwrap_or(&zero);
    let mut out = [None; 6];
    for (i, slot) in out.iter_mut().enumerate() {
        let joint = solution.platform_joints[i];
        let arm = joint - reference;
        let v_p = joint_velocity(twist, &arm);
        *slot = Some(match geometry.rotary() {
            None => linear_leg(&joint, &geometry.base_joints()[i], arm, v_p, dynamics),
            Some(servos) => {
                let theta =
                    servo_closure::servo_angle(servos, i, &geometry.base_joints()[i], &joint)
                        .map_err(|e| LegTrouble::Unreachable(e.servo))?;
                let horn_direction = servos.horn_direction(i);
                let servo = Servo {
                    shaft: geometry.base_joints()[i],
                    horn_direction,
                    horn_length: servos.horn_length(),
                    rod_length: servos.rod_length(),
                    theta: theta.radians(),
                };
                servo_leg(&servo, &joint, arm, v_p, dynamics)
            }
        });
    }
    Ok(out.map(|l| l.unwrap_or_else(|| unreachable!("every leg was filled"))))
}

/// A linear leg from base joint `base` to platform joint `joint` moving at `v_p`.
fn linear_leg(
    joint: &Vector3<f64>,
    base: &Vector3<f64>,
    arm: Vector3<f64>,
    v_p: Vector3<f64>,
    dynamics: &DynamicsSettings,
) -> Leg {
    let leg = joint - base;
    let l = leg.norm();
    let u = leg / l;
    // P x = (x − u (u·x)) / l: the rate of the leg's direction per joint velocity.
    let p = (Matrix3::identity() - u * u.transpose()) / l;
    let rate = u.dot(&v_p);
    let u_dot = p * v_p;
    let omega = u.cross(&u_dot);
    let across = Matrix3::identity() - u * u.transpose();
    // ü = P a_p − |u̇|² u − 2 l̇ u̇ / l, α = u × ü.
    let curve = -u_dot.norm_squared() * u - 2.0 * rate / l * u_dot;
    let alpha_bias = u.cross(&(-2.0 * rate / l * u_dot));
    let ang_joint = u.cross_matrix() / l;
    let (cylinder, rod) = (dynamics.cylinder(), dynamics.rod());
    let cylinder_part = MovingPart {
        inertia: cylinder.inertia * across,
        lin_joint: cylinder.com * p,
        ang_joint,
        omega,
        acc_bias: cylinder.com * curve,
        alpha_bias,
        ..MovingPart::still(&cylinder)
    };
    let rod_part = MovingPart {
        inertia: rod.inertia * across,
        lin_joint: Matrix3::identity() - rod.com * p,
        ang_joint,
        omega,
        acc_bias: -rod.com * curve,
        alpha_bias,
        ..MovingPart::still(&rod)
    };
    Leg {
        arm,
        row: wrench_at(&arm, &u),
        rate,
        rate_per_joint_acc: Vector3::zeros(),
        rate_bias: 0.0,
        parts: [cylinder_part, rod_part],
    }
}

/// A servo's shaft, horn and rod at angle `theta`.
struct Servo {
    shaft: Vector3<f64>,
    horn_direction: Vector3<f64>,
    horn_length: f64,
    rod_length: f64,
    theta: f64,
}

/// A servo leg whose rod ends on platform joint `joint`, moving at `v_p`.
fn servo_leg(
    servo: &Servo,
    joint: &Vector3<f64>,
    arm: Vector3<f64>,
    v_p: Vector3<f64>,
    dynamics: &DynamicsSettings,
) -> Leg {
    let (a, rho) = (servo.horn_length, servo.rod_length);
    let (st, ct) = servo.theta.sin_cos();
    let h = servo.horn_direction;
    let horn = a * Vector3::new(ct * h.x, ct * h.y, st);
    let tip = servo.shaft + horn;
    // dH/dθ and d²H/dθ² (the tip turns on a circle about the shaft's axis n).
    let h1 = a * Vector3::new(-st * h.x, -st * h.y, ct);
    let h2 = -horn;
    let axis = h.cross(&Vector3::z());
    let d = joint - tip;
    let e = d / rho;
    let scale = 1.0 / d.dot(&h1);
    let rate = d.dot(&v_p) * scale;
    let d_dot = v_p - h1 * rate;
    // θ̈ = (ḋ·ḋ + d·(a_p − H'' θ̇²)) / (d·H').
    let rate_per_joint_acc = d * scale;
    let rate_bias = (d_dot.norm_squared() - d.dot(&h2) * rate * rate) * scale;
    let (horn_part, rod) = (dynamics.horn(), dynamics.rod());
    let horn_share = horn_part.com / a;
    let horn_body = MovingPart {
        inertia: horn_part.inertia * axis * axis.transpose(),
        lin_rate: horn_share * h1,
        ang_rate: axis,
        omega: rate * axis,
        acc_bias: horn_share * rate * rate * h2,
        ..MovingPart::still(&horn_part)
    };
    let along = rod.com / rho;
    let rod_body = MovingPart {
        inertia: rod.inertia * (Matrix3::identity() - e * e.transpose()),
        lin_joint: along * Matrix3::identity(),
        lin_rate: (1.0 - along) * h1,
        ang_joint: e.cross_matrix() / rho,
        ang_rate: -e.cross(&h1) / rho,
        omega: e.cross(&d_dot) / rho,
        acc_bias: (1.0 - along) * rate * rate * h2,
        alpha_bias: -e.cross(&h2) * (rate * rate / rho),
        ..MovingPart::still(&rod)
    };
    Leg {
        arm,
        row: wrench_at(&arm, &d) * scale,
        rate,
        rate_per_joint_acc,
        rate_bias,
        parts: [horn_body, rod_body],
    }
}
