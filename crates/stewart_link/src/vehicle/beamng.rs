//! BeamNG.drive's MotionSim protocol (port 4444), from BeamNG's *Protocols* page
//! (<https://documentation.beamng.com/modding/protocols/>) and the game's own
//! `lua/vehicle/protocols/motionSim.lua` that sends it: `BNG1`, then 21 little-endian
//! `f32` — 88 bytes. Read: `accX, accY, accZ` at 28 ("acceleration of the car, gravity not
//! included", m/s², in the car's frame) and `rollRate, pitchRate, yawRate` at 64 (rad/s).
//! It has no clock (the receiver's is used).
//!
//! The page gives the accelerations' frame but not their signs; the game's own packets
//! settle them (`tests/real_telemetry.rs` decodes five recorded from the game). Two cars
//! parked on 52° and 28° slopes read `acc ≈ 0` (gravity is not included); a car in free
//! fall reads `|acc| ≈ g`. `accX` is to the right, `accY` forward, `accZ` up. A car turning
//! right at 13.2 m/s reads `accX = +7.41` and `yawRate = +0.598 rad/s` (`ω·v ≈ 7.9 m/s²`):
//! the yaw rate is positive turning right, nose right, so opposite to ours; braking with the
//! nose going down reads a negative `pitchRate`, positive nose up. The roll rate is positive
//! rolling right side down, as ours. In our axes: `ax = accY`, `ay = −accX`, `az = accZ`,
//! `wx = rollRate`, `wy = −pitchRate`, `wz = −yawRate`, so that in a steady turn
//! `ay = wz·vx` as in any right-handed frame. Check with `stewart telemetry`
//! (accelerating reads `ax > 0`, a left turn `ay > 0` and `wz > 0`).
//!
//! OutGauge (the dashboard protocol BeamNG and Live for Speed share, 92 bytes or 96 with
//! an ID) may arrive at the same port: it carries no motion and reads as
//! [`Reading::Ignored`].

use super::fields::vector_at;
use super::{Reading, VehicleError, VehicleFormat, VehicleSample};

/// The MotionSim packet's length.
pub const MOTION_SIM_BYTES: usize = 88;
/// OutGauge's length, without and with its ID.
pub const OUTGAUGE_BYTES: usize = 92;
/// OutGauge's length with its ID.
pub const OUTGAUGE_WITH_ID_BYTES: usize = 96;

/// Byte offsets of the fields read.
const ACCELERATION: usize = 28;
const RATES: usize = 64;

/// A MotionSim packet (`BNG1`).
pub(crate) fn motion_sim(bytes: &[u8]) -> Result<Reading, VehicleError> {
    if bytes.len() != MOTION_SIM_BYTES {
        return Err(VehicleError::Length {
            format: VehicleFormat::BeamNg,
            got: bytes.len(),
            expected: "88",
        });
    }
    let [acc_right, acc_forward, acc_up] = vector_at(bytes, ACCELERATION);
    let [roll, pitch, yaw] = vector_at(bytes, RATES);
    Ok(Reading::Sample(VehicleSample {
        t: None,
        accel: [acc_forward, -acc_right, acc_up],
        rates_deg_s: [roll, -pitch, -yaw].map(f64::to_degrees),
    }))
}
