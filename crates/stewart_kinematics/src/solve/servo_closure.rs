//! The closed form of a rotary servo (6-RSS): the horn angle that closes its rod on a
//! platform joint, how far a joint is from the edge of a servo's reach, and the angle
//! nearest a joint out of reach. A horn of length `a` at angle θ and a rod of length `s`
//! close on a joint at `l` from the shaft centre when `N cos θ + M sin θ = L`.

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
