//! Forza *Data Out* (Forza Motorsport 7 and 2023, Forza Horizon 4 and 5), from Turn 10's
//! published layout: the *Forza Motorsport 7 'Data Out' feature details* post
//! (<https://forums.forza.net/t/forza-motorsport-7-data-out-feature-details/74013>) and
//! *Forza Motorsport Data Out Documentation*
//! (<https://support.forzamotorsport.net/hc/en-us/articles/21742934024211>).
//!
//! Every form begins with the same 232-byte *Sled* block (little-endian): `IsRaceOn`
//! (`s32`, 0 in menus and pause) at 0, `TimestampMS` (`u32`, wraps) at 4, then
//! `AccelerationX, Y, Z` at 20, `VelocityX, Y, Z` at 32 and `AngularVelocityX, Y, Z` at
//! 44 (`f32`). The forms differ only in what follows, and so in length: *Sled* 232 bytes,
//! Motorsport 7's *Dash* 311, Horizon 324 (12 bytes inserted after byte 232), Motorsport
//! (2023) 331.
//!
//! The car's local frame is X right, Y up, Z forward — a left-handed triple — with the
//! angular velocity's X about the right axis (pitch), Y about up (yaw), Z about forward
//! (roll), in rad/s; accelerations in m/s² without gravity. Ours is x forward, y left,
//! z up. A vector maps as `(x, y, z) = (Z, −X, Y)`: that map reverses handedness, so an
//! angular velocity (a cross product's kind of vector) also changes sign:
//! `(wx, wy, wz) = (−ωZ, ωX, −ωY)`. The check is the game's own numbers: a car turning at
//! a steady rate has `a = ω × v` in its frame, so in a left turn (acceleration to the left,
//! `AccelerationX < 0`, at forward speed `VelocityZ > 0`) `AngularVelocityY` is negative;
//! ours must read `ay > 0` and `wz > 0` (the tests build such a packet).
//!
//! `TimestampMS` is the clock (unwrapped across datagrams). `IsRaceOn = 0` reads as
//! [`Reading::Idle`]: the cue fades to neutral as when the input stalls.

use super::fields::{i32_at, u32_at, vector_at};
use super::{Reading, VehicleSample, WrappingClock};

/// The *Sled* form's length.
pub const SLED_BYTES: usize = 232;
/// Forza Motorsport 7's *Dash* form's length.
pub const DASH_BYTES: usize = 311;
/// Forza Horizon 4 and 5's length.
pub const HORIZON_BYTES: usize = 324;
/// Forza Motorsport (2023)'s length.
pub const MOTORSPORT_2023_BYTES: usize = 331;

/// Byte offsets of the fields read.
const IS_RACE_ON: usize = 0;
const TIMESTAMP_MS: usize = 4;
const ACCELERATION: usize = 20;
const ANGULAR_VELOCITY: usize = 44;

/// The motion of the *Sled* block at the start of every form.
pub(crate) fn sled(bytes: &[u8], clock: &mut WrappingClock) -> Reading {
    if i32_at(bytes, IS_RACE_ON) == Some(0) {
        return Reading::Idle;
    }
    let t = u32_at(bytes, TIMESTAMP_MS).map(|ms| clock.seconds(ms));
    let [ax_right, ay_up, az_forward] = vector_at(bytes, ACCELERATION);
    let [w_pitch, w_yaw, w_roll] = vector_at(bytes, ANGULAR_VELOCITY);
    Reading::Sample(VehicleSample {
        t,
        accel: [az_forward, -ax_right, ay_up],
        rates_deg_s: [-w_roll, w_pitch, -w_yaw].map(f64::to_degrees),
    })
}
