//! Live for Speed's OutSim, from the `docs/InSim.txt` and `docs/OutSimPack.txt` that come
//! with the game (mirrored at <https://en.lfsmanual.net/wiki/InSim.txt>) and the developer's
//! *Live telemetry data* post (<https://www.lfs.net/forum/thread/93185>). Little-endian.
//!
//! - The **classic** packet (`OutSim Opts 0`): 64 bytes, 68 with an ID — `Time` (`u32`, ms)
//!   at 0, `AngVel` (3 `f32`, rad/s) at 4, `Heading`, `Pitch`, `Roll` (`f32`, rad) at 16,
//!   `Accel` (3 `f32`, m/s²) at 28.
//! - The **pack** with the `LFST` header (`OutSim Opts ff` or `1ff`, all blocks: 272 or 280
//!   bytes): `LFST`, the ID, `Time` at 8, then the same fields from 12 (`AngVel` 12,
//!   angles 24, `Accel` 36). Other `Opts` leave blocks out and move the fields; they are
//!   refused, naming the two accepted.
//!
//! LFS's axes are X right, Y forward, Z up, and OutSim's vectors are in the world's: at a
//! heading of 0 the car faces world Y. Heading turns about Z (anticlockwise from above),
//! pitch about the car's X (anticlockwise seen from the right), roll about its Y
//! (anticlockwise seen from the front), taken in that order (the order the documents
//! list them in; they name none). The vectors are turned into the car's frame with the
//! transpose of that rotation, then into ours:
//! `(x, y, z) = (Y, −X, Z)`. `Time` is the clock (unwrapped across datagrams);
//! accelerations are taken without gravity.

use super::fields::{u32_at, vector_at};
use super::{Reading, VehicleError, VehicleFormat, VehicleSample, WrappingClock};

/// The classic packet's length.
pub const CLASSIC_BYTES: usize = 64;
/// The classic packet's length with an ID.
pub const CLASSIC_WITH_ID_BYTES: usize = 68;
/// The `LFST` pack's lengths with every block (`OutSim Opts ff`, `1ff`).
pub const PACK_BYTES: [usize; 2] = [272, 280];

/// Where a packet's fields are.
struct FieldOffsets {
    time: usize,
    angular_velocity: usize,
    angles: usize,
    acceleration: usize,
}

const CLASSIC: FieldOffsets = FieldOffsets {
    time: 0,
    angular_velocity: 4,
    angles: 16,
    acceleration: 28,
};

const PACK: FieldOffsets = FieldOffsets {
    time: 8,
    angular_velocity: 12,
    angles: 24,
    acceleration: 36,
};

/// A classic packet.
pub(crate) fn classic(bytes: &[u8], clock: &mut WrappingClock) -> Reading {
    read(bytes, &CLASSIC, clock)
}

/// An `LFST` pack.
pub(crate) fn pack(bytes: &[u8], clock: &mut WrappingClock) -> Result<Reading, VehicleError> {
    if !PACK_BYTES.contains(&bytes.len()) {
        return Err(VehicleError::Length {
            format: VehicleFormat::OutSimPack,
            got: bytes.len(),
            expected: "272 or 280 (OutSim Opts ff or 1ff)",
        });
    }
    Ok(read(bytes, &PACK, clock))
}

fn read(bytes: &[u8], at: &FieldOffsets, clock: &mut WrappingClock) -> Reading {
    let t = u32_at(bytes, at.time).map(|ms| clock.seconds(ms));
    let [heading, pitch, roll] = vector_at(bytes, at.angles);
    let to_car = |v: [f64; 3]| {
        let [right, forward, up] = car_frame(v, heading, pitch, roll);
        [forward, -right, up]
    };
    let omega = to_car(vector_at(bytes, at.angular_velocity));
    Reading::Sample(VehicleSample {
        t,
        accel: to_car(vector_at(bytes, at.acceleration)),
        rates_deg_s: omega.map(f64::to_degrees),
    })
}

/// World vector `v` in the car's frame (X right, Y forward, Z up): `Rᵀ v` with the car's
/// rotation `R = Rz(heading) Rx(pitch) Ry(roll)`.
pub(crate) fn car_frame(v: [f64; 3], heading: f64, pitch: f64, roll: f64) -> [f64; 3] {
    // Undo the heading, then the pitch, then the roll: Ry(−roll) Rx(−pitch) Rz(−heading) v.
    let [x, y, z] = v;
    let (s, c) = (-heading).sin_cos();
    let [x, y] = [c * x - s * y, s * x + c * y];
    let (s, c) = (-pitch).sin_cos();
    let [y, z] = [c * y - s * z, s * y + c * z];
    let (s, c) = (-roll).sin_cos();
    let [x, z] = [c * x + s * z, -s * x + c * z];
    [x, y, z]
}
