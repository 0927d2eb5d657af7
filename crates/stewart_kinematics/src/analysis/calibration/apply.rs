//! Putting a calibration into a scenario: the joints as coordinates, a servo's angle
//! offset folded into its trim, a linear leg's length offset into the link's channel
//! offset (so that what reaches the actuator makes the real leg as long as the model's).

use crate::io::scenario::Scenario;
use crate::model::actuator::{Actuator, ActuatorKind};
use crate::model::angle::Angle;
use crate::model::rotary::{RotaryActuators, RotaryError, wrap_half_turn};

use super::Calibration;

/// The servos with the identified angle offsets (radians: real horn angle − commanded
/// model angle) folded into their trims: commanding model angle `θ` then turns the horn
/// to `θ` itself.
///
/// A servo is commanded `±θ + trim` and really stands at model angle `θ + δ`; to stand
/// at `θ` it must be commanded as for `θ − δ`, which is `±θ + (trim ∓ δ)`.
pub(crate) fn retrimmed(
    servos: &RotaryActuators,
    offsets: &[f64; 6],
) -> Result<RotaryActuators, RotaryError> {
    let trims_deg: [f64; 6] = std::array::from_fn(|i| {
        let sign = if servos.reversed()[i] { -1.0 } else { 1.0 };
        Angle::from_radians(wrap_half_turn(
            servos.trims()[i].radians() - sign * offsets[i],
        ))
        .degrees()
    });
    servos.clone().with_mounting(*servos.reversed(), trims_deg)
}

/// Where [`calibrated_scenario`] puts the actuators' offsets, in words.
pub fn offsets_folded_into(kind: ActuatorKind) -> &'static str {
    match kind {
        ActuatorKind::Rotary => "angle offsets folded into actuator.servo_trim_deg",
        ActuatorKind::Linear => "length offsets folded into the link's channel offsets",
    }
}

/// `scenario` with `calibration` applied: its geometry (joints as coordinates, servo
/// trims adjusted) and, for linear legs, the link's channel offsets lowered by each leg's
/// length offset (scaled and mirrored as the channel is), so that a leg commanded the
/// model's length `L` receives what used to make it `L − d` long, and is `L` long.
pub fn calibrated_scenario(
    scenario: &Scenario,
    calibration: &Calibration,
    poses: usize,
) -> Scenario {
    let mut link = scenario.link.clone();
    match calibration.geometry.actuator() {
        // The trims were adjusted with the geometry.
        Actuator::Rotary(_) => {}
        Actuator::Linear => {
            for k in 0..6 {
                let leg = usize::from(link.actuator[k].clamp(1, 6)) - 1;
                let sign = if link.reversed[k] { -1.0 } else { 1.0 };
                link.offset[k] -= sign * link.scale[k] * calibration.offsets[leg];
            }
        }
    }
    let note = format!("calibrated from {poses} measured poses");
    Scenario {
        description: if scenario.description.is_empty() {
            note
        } else {
            format!("{} ({note})", scenario.description)
        },
        geometry: calibration.geometry.clone(),
        link,
        ..scenario.clone()
    }
}
