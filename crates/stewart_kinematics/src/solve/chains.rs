//! The rig as open chains from the base, for robot descriptions that cannot close a loop
//! (URDF's tree) or that close it with constraints (MJCF's bodies and equalities): at a
//! pose, the value of every joint along each leg's chain, so that the chain's far end lies
//! on the leg's platform joint.
//!
//! Every chain starts in a frame at the leg's base joint with the base's axes:
//!
//! - a linear leg: a universal joint ([`Universal`]: a revolute about the base's x, then
//!   one about the turned y), then a slide along the turned z by the leg's length;
//! - a servo: a revolute about the servo's shaft ([`servo_axis`]) by the model angle θ,
//!   the horn along `β_i` to its tip, then the rod's universal joint in the horn's frame
//!   and the rod's fixed length along its turned z.

use nalgebra::{Rotation3, Unit, Vector3};

use crate::model::geometry::Geometry;
use crate::model::pose::Pose;
use crate::model::rotary::Unreachable;

/// A universal joint's two angles (radians) turning the base's z onto a direction: first
/// about x, then about the turned y, so that its rotation is `Rx(about_x) · Ry(about_y)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Universal {
    /// The first revolute's angle, about x.
    pub about_x: f64,
    /// The second revolute's angle, about the turned y.
    pub about_y: f64,
}

impl Universal {
    /// The angles that turn z onto the unit vector `u`: `Rx(α)·Ry(β)·z = (sin β, −sin α
    /// cos β, cos α cos β)`. Along ±x (β = ±90°) the first angle is free and taken as 0.
    pub fn towards(u: &Vector3<f64>) -> Self {
        Self {
            about_x: (-u.y).atan2(u.z),
            about_y: u.x.clamp(-1.0, 1.0).asin(),
        }
    }

    /// The joint's rotation, `Rx(about_x) · Ry(about_y)`.
    pub fn rotation(&self) -> Rotation3<f64> {
        Rotation3::from_axis_angle(&Vector3::x_axis(), self.about_x)
            * Rotation3::from_axis_angle(&Vector3::y_axis(), self.about_y)
    }
}

/// One leg's chain at a pose.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LegChain {
    /// A linear leg: the universal joint at its base joint, then the slide.
    Linear {
        /// The universal joint at the base joint.
        universal: Universal,
        /// The leg's length, base joint to platform joint, metres.
        length: f64,
    },
    /// A servo: the horn turned about the shaft, then the rod's universal joint at the
    /// horn's tip, in the horn's frame.
    Rotary {
        /// The model angle θ, radians (positive lifts the horn's tip; the commanded
        /// angle adds the servo's trim and reversal).
        servo: f64,
        /// The rod's universal joint at the horn's tip, in the horn's frame.
        rod: Universal,
    },
}

/// A servo's shaft axis for a horn pointing along `beta` (radians) in the base plane:
/// horizontal, perpendicular to the horn, oriented so that a positive turn lifts the tip.
pub fn servo_axis(beta: f64) -> Unit<Vector3<f64>> {
    Unit::new_normalize(Vector3::new(beta.sin(), -beta.cos(), 0.0))
}

/// See [`Geometry::leg_chains`].
pub(crate) fn leg_chains(geometry: &Geometry, pose: &Pose) -> Result<[LegChain; 6], Unreachable> {
    let joints = geometry.inverse(pose).platform_joints;
    let base = geometry.base_joints();
    let Some(servos) = geometry.rotary() else {
        return Ok(std::array::from_fn(|k| {
            let leg = joints[k] - base[k];
            let length = leg.norm();
            LegChain::Linear {
                universal: Universal::towards(&(leg / length)),
                length,
            }
        }));
    };
    // The servos' angles closed on the joints just solved (not solved a second time).
    let angles = crate::solve::servo_closure::servo_angles(servos, base, &joints)?;
    Ok(std::array::from_fn(|k| {
        let servo = angles[k].radians();
        let horn = horn_rotation(servos.horn_angles()[k].radians(), servo);
        let tip = servos.horn_tip(k, &base[k], angles[k]);
        let rod = (joints[k] - tip) / servos.rod_length();
        LegChain::Rotary {
            servo,
            rod: Universal::towards(&(horn.inverse() * rod)),
        }
    }))
}

/// See [`Geometry::chain_tip`].
pub(crate) fn chain_tip(geometry: &Geometry, k: usize, chain: &LegChain) -> Option<Vector3<f64>> {
    let base = geometry.base_joints().get(k)?;
    match (chain, geometry.rotary()) {
        (LegChain::Linear { universal, length }, None) => {
            Some(base + universal.rotation() * Vector3::z() * *length)
        }
        (LegChain::Rotary { servo, rod }, Some(servos)) => {
            let beta = servos.horn_angles()[k].radians();
            let horn = horn_rotation(beta, *servo);
            let along = Vector3::new(beta.cos(), beta.sin(), 0.0) * servos.horn_length();
            let rod = horn * rod.rotation() * Vector3::z() * servos.rod_length();
            Some(base + horn * along + rod)
        }
        // A chain of the other kind of actuator.
        _ => None,
    }
}

/// The horn's frame: the base's axes turned by `servo` about the shaft of a horn along
/// `beta`.
fn horn_rotation(beta: f64, servo: f64) -> Rotation3<f64> {
    Rotation3::from_axis_angle(&servo_axis(beta), servo)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::scenario::Scenario;
    use crate::model::angle::Angle;

    /// Poses about home, moved by up to a tenth of the platform's size and 8° a turn.
    fn poses(g: &Geometry) -> Vec<Pose> {
        let home = g.home_pose();
        let size = g.characteristic_length();
        let mut out = vec![home];
        let mut seed = 0x9e37_79b9_u32;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            f64::from(seed) / f64::from(u32::MAX) * 2.0 - 1.0
        };
        for _ in 0..40 {
            let position = home.position + Vector3::new(next(), next(), next()) * 0.1 * size;
            let [r, p, y] = [next(), next(), next()].map(|v| Angle::from_degrees(8.0 * v));
            out.push(Pose::new(position, r, p, y));
        }
        out
    }

    #[test]
    fn a_universal_joint_turns_z_onto_its_direction() {
        for u in [
            Vector3::new(0.3, -0.2, 0.9),
            Vector3::new(-0.7, 0.1, 0.2),
            Vector3::new(0.0, 0.0, 1.0),
            Vector3::new(0.0, 1.0, 0.0),
            Vector3::new(1.0, 0.0, 0.0),
            Vector3::new(0.2, 0.3, -0.9),
        ] {
            let u = u.normalize();
            let turned = Universal::towards(&u).rotation() * Vector3::z();
            assert!((turned - u).norm() < 1e-15, "{u} → {turned}");
        }
        // By hand: a quarter turn about x takes z to −y.
        let q = Universal::towards(&Vector3::new(0.0, -1.0, 0.0));
        assert!((q.about_x - std::f64::consts::FRAC_PI_2).abs() < 1e-15 && q.about_y == 0.0);
    }

    #[test]
    fn a_servo_turn_lifts_the_horn_as_the_model_says() {
        // θ = 30° about the shaft of a horn along β = 120°: the tip at
        // (cos θ cos β, cos θ sin β, sin θ), the rotary model's own formula.
        let (beta, theta) = (120f64.to_radians(), 30f64.to_radians());
        let tip = horn_rotation(beta, theta) * Vector3::new(beta.cos(), beta.sin(), 0.0);
        let model = Vector3::new(
            theta.cos() * beta.cos(),
            theta.cos() * beta.sin(),
            theta.sin(),
        );
        assert!((tip - model).norm() < 1e-15, "{tip} vs {model}");
    }

    #[test]
    fn every_chain_ends_on_its_platform_joint_on_every_kind_of_rig() {
        for preset in ["seed", "paired", "servo-desk", "crank-rig"] {
            let g = Scenario::preset(preset)
                .unwrap_or_else(|e| panic!("{e}"))
                .geometry;
            let size = g.characteristic_length();
            let mut closed = 0;
            for pose in poses(&g) {
                let Ok(chains) = g.leg_chains(&pose) else {
                    continue; // out of a servo's reach: no chain closes
                };
                let joints = g.inverse(&pose).platform_joints;
                for (k, chain) in chains.iter().enumerate() {
                    let tip = g.chain_tip(k, chain).unwrap_or_else(|| panic!("{preset}"));
                    let miss = (tip - joints[k]).norm();
                    assert!(miss < 1e-12 * size, "{preset} leg {k}: {miss:e} m");
                    match (chain, g.servo_angles(&pose)) {
                        (LegChain::Linear { length, .. }, None) => {
                            let l = g.leg_lengths(&pose)[k];
                            assert!((length - l).abs() < 1e-15 * l);
                        }
                        (LegChain::Rotary { servo, .. }, Some(Ok(angles))) => {
                            assert_eq!(*servo, angles[k].radians());
                        }
                        other => panic!("{preset}: {other:?}"),
                    }
                }
                closed += 1;
            }
            assert!(closed > 20, "{preset}: only {closed} of 41 poses closed");
        }
    }

    #[test]
    fn a_pose_beyond_a_servo_has_no_chain() {
        let g = Scenario::preset("servo-desk")
            .unwrap_or_else(|e| panic!("{e}"))
            .geometry;
        let mut far = g.home_pose();
        far.position.z += 1.0;
        assert!(g.leg_chains(&far).is_err());
    }
}
