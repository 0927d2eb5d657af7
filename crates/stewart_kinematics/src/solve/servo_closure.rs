//! The closed form of a rotary servo (6-RSS): the horn angle that closes its rod on a
//! platform joint, how far a joint is from the edge of a servo's reach, and the angle
//! nearest a joint out of reach. A horn of length `a` at angle θ and a rod of length `s`
//! close on a joint at `l` from the shaft centre when `N cos θ + M sin θ = L`.
//!
//! In closed form, with `l = q_i − B_i`: expanding the closure,
//! `N cos θ + M sin θ = L` where `L = |l|² − (s² − a²)`, `M = 2a·l_z` and
//! `N = 2a (cos β_i·l_x + sin β_i·l_y)`; so `θ_i = asin(L / √(M² + N²)) − atan2(N, M)`,
//! wrapped to (−180°, 180°] (the branch with the horn on the near side of the rod; the
//! other root, `π − asin(…) − atan2(N, M)`, is the mirrored assembly). When
//! `|L| > √(M² + N²)` no horn angle reaches the joint: the pose is *unreachable*.

use nalgebra::Vector3;

use crate::model::angle::Angle;
use crate::model::rotary::{RotaryActuators, Unreachable, wrap_half_turn};

/// The closure terms `(L, M, N)` of servo `i` for platform joint `joint`: the horn
/// angle θ closes the rod when `N cos θ + M sin θ = L`.
pub(crate) fn closure_terms(
    servos: &RotaryActuators,
    i: usize,
    base: &Vector3<f64>,
    joint: &Vector3<f64>,
) -> [f64; 3] {
    terms_along(servos, &servos.horn_direction(i), &(joint - base))
}

/// The closure terms for a joint at `l` from the shaft centre, the horn pointing along
/// `h` at angle 0.
pub(crate) fn terms_along(
    servos: &RotaryActuators,
    h: &Vector3<f64>,
    l: &Vector3<f64>,
) -> [f64; 3] {
    let a = servos.horn_length();
    let s = servos.rod_length();
    [
        l.norm_squared() - (s * s - a * a),
        2.0 * a * l.z,
        2.0 * a * (h.x * l.x + h.y * l.y),
    ]
}

/// How far servo `i`'s joint is from the edge of its reach: `|L| / √(M² + N²)`, at
/// most 1 when some horn angle closes the rod (1: the horn and rod are in line), and
/// infinite for a joint on the shaft's axis.
pub fn reach_ratio(
    servos: &RotaryActuators,
    i: usize,
    base: &Vector3<f64>,
    joint: &Vector3<f64>,
) -> f64 {
    let [big_l, m, n] = closure_terms(servos, i, base, joint);
    let ratio = big_l.abs() / m.hypot(n);
    if ratio.is_nan() { f64::INFINITY } else { ratio }
}

/// The angle of servo `i` whose horn tip comes closest to platform joint `joint` when
/// no angle reaches it: the horn pointing towards the joint (`L > 0`, joint too far)
/// or away from it (`L < 0`, too near). Where the joint can be reached this is where
/// the rod would be in line with the horn.
pub fn closest_angle(
    servos: &RotaryActuators,
    i: usize,
    base: &Vector3<f64>,
    joint: &Vector3<f64>,
) -> Angle {
    let [big_l, m, n] = closure_terms(servos, i, base, joint);
    // N cos θ + M sin θ is largest at θ = atan2(M, N), smallest half a turn away.
    let towards = m.atan2(n);
    let theta = if big_l >= 0.0 {
        towards
    } else {
        towards + std::f64::consts::PI
    };
    Angle::from_radians(wrap_half_turn(theta))
}

/// Servo `i`'s angle (from 0) that puts its rod's end on platform joint `joint` (base
/// frame), for shaft centre `base`; or why none does.
pub fn servo_angle(
    servos: &RotaryActuators,
    i: usize,
    base: &Vector3<f64>,
    joint: &Vector3<f64>,
) -> Result<Angle, Unreachable> {
    angle_from_terms(i, closure_terms(servos, i, base, joint))
}

/// Servo `i`'s angle from its closure terms (see [`servo_angle`]).
pub(crate) fn angle_from_terms(i: usize, terms: [f64; 3]) -> Result<Angle, Unreachable> {
    let [big_l, m, n] = terms;
    let r = m.hypot(n);
    let ratio = big_l.abs() / r;
    if ratio.is_nan() || ratio > 1.0 {
        // Also a joint on the shaft's axis (r = 0): no horn angle moves the rod end.
        return Err(Unreachable {
            servo: i + 1,
            ratio,
            excess: ratio - 1.0,
        });
    }
    let theta = (big_l / r).asin() - n.atan2(m);
    Ok(Angle::from_radians(wrap_half_turn(theta)))
}

/// All six servo angles for platform joints `joints` and shaft centres `bases`.
pub fn servo_angles(
    servos: &RotaryActuators,
    bases: &[Vector3<f64>; 6],
    joints: &[Vector3<f64>; 6],
) -> Result<[Angle; 6], Unreachable> {
    let mut out = [Angle::from_radians(0.0); 6];
    for i in 0..6 {
        out[i] = servo_angle(servos, i, &bases[i], &joints[i])?;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::rotary::wrap_half_turn;
    use proptest::prelude::*;

    fn hobby() -> RotaryActuators {
        RotaryActuators::new(0.025, 0.12, [255.0, 105.0, 15.0, 225.0, 135.0, 345.0], None)
            .unwrap_or_else(|e| panic!("{e}"))
    }

    #[test]
    fn a_horn_level_under_a_vertical_rod_is_angle_zero() {
        // β = 0, shaft at the origin: the tip is at (a, 0, 0); a joint straight above it
        // at the rod's length needs θ = 0 (asin(a/√(s²+a²)) = atan(a/s) exactly).
        let act =
            RotaryActuators::new(0.025, 0.12, [0.0; 6], None).unwrap_or_else(|e| panic!("{e}"));
        let b = Vector3::zeros();
        let q = Vector3::new(0.025, 0.0, 0.12);
        let theta = servo_angle(&act, 0, &b, &q).unwrap_or_else(|e| panic!("{e}"));
        assert!(theta.radians().abs() < 1e-15, "{}", theta.degrees());
        // Lifted by 30°: the tip moves to a(cos 30°, 0, sin 30°); the joint above it too.
        let tip = act.horn_tip(0, &b, Angle::from_degrees(30.0));
        let q = tip + Vector3::new(0.0, 0.0, 0.12);
        let theta = servo_angle(&act, 0, &b, &q).unwrap_or_else(|e| panic!("{e}"));
        assert!(
            (theta.degrees() - 30.0).abs() < 1e-12,
            "{}",
            theta.degrees()
        );
    }

    #[test]
    fn too_far_or_too_near_is_unreachable_never_nan() {
        let act = hobby();
        let b = Vector3::new(0.1, 0.0, 0.0);
        for q in [
            Vector3::new(0.1, 0.0, 0.5),  // farther than a + s
            Vector3::new(0.1, 0.0, 0.05), // nearer than s − a
            Vector3::new(0.1, 0.0, 0.0),  // on the shaft centre
        ] {
            let e = servo_angle(&act, 0, &b, &q).unwrap_err();
            assert_eq!(e.servo, 1);
            assert!(e.ratio > 1.0, "{e:?}");
        }
    }

    proptest! {
        /// Any horn angle and any rod direction: the solver's angle closes the rod
        /// exactly, and is the very angle used where that lies on the solver's branch.
        #[test]
        fn the_closed_form_closes_the_rod(
            i in 0usize..6,
            theta_deg in -170.0f64..170.0,
            azimuth in 0.0f64..std::f64::consts::TAU,
            elevation in -1.4f64..1.4,
            bx in -0.2f64..0.2, by in -0.2f64..0.2,
        ) {
            let act = hobby();
            let b = Vector3::new(bx, by, 0.0);
            let tip = act.horn_tip(i, &b, Angle::from_degrees(theta_deg));
            let dir = Vector3::new(
                elevation.cos() * azimuth.cos(),
                elevation.cos() * azimuth.sin(),
                elevation.sin(),
            );
            let q = tip + act.rod_length() * dir;
            let found = servo_angle(&act, i, &b, &q);
            prop_assert!(found.is_ok(), "{found:?}");
            let theta = found.unwrap_or(Angle::from_radians(0.0));
            let closure = (q - act.horn_tip(i, &b, theta)).norm() - act.rod_length();
            prop_assert!(closure.abs() < 1e-12, "closure {closure}");
            // On the solver's branch (the rod's end on the near side), it is the same angle.
            let l = q - b;
            let (sb, cb) = act.horn_angles()[i].radians().sin_cos();
            let m = 2.0 * act.horn_length() * l.z;
            let n = 2.0 * act.horn_length() * (cb * l.x + sb * l.y);
            let phase = wrap_half_turn(theta_deg.to_radians() + n.atan2(m));
            if phase.abs() < std::f64::consts::FRAC_PI_2 - 1e-6 {
                let d = wrap_half_turn(theta.radians() - theta_deg.to_radians());
                prop_assert!(d.abs() < 1e-9, "{} vs {theta_deg}", theta.degrees());
            }
        }
    }
}
