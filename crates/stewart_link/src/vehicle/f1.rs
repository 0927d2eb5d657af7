//! EA SPORTS F1 24's and F1 25's UDP telemetry (port 20777), from Codemasters' *F1 24 UDP
//! Specification* (<https://answers.ea.com/t5/General-Discussion/F1-24-UDP-Specification/td-p/13745220>)
//! and EA's *F1 25 UDP Specification*: little-endian, packed. The 2025 format keeps the
//! 2024 one's header, `Motion` and the start of `Motion Ex`, which only grows at its end
//! (`chassisPitch`, wheel camber and camber gain: 273 bytes); packets logged from both
//! games (`tests/real_telemetry.rs`) read the same fields at the same offsets.
//!
//! Every packet starts with a 29-byte header: `packetFormat` (`u16`, 2024 or 2025) at 0,
//! `packetId` (`u8`) at 6, `sessionUID` (`u64`) at 7, `sessionTime` (`f32`, s) at 15,
//! `frameIdentifier` (`u32`) at 19 and `playerCarIndex` (`u8`) at 27. Two packets are read:
//!
//! - `Motion` (id 0, 1349 bytes): 22 cars of 60 bytes from byte 29; the player's car's
//!   `gForceLateral`, `gForceLongitudinal`, `gForceVertical` (`f32`, g) at 36, 40, 44 of
//!   its block;
//! - `Motion Ex` (id 13, 237 bytes in 2024, 273 in 2025; the player's car):
//!   `angularVelocityX, Y, Z` (`f32`, rad/s) at 173.
//!
//! The two of one frame (same session and `frameIdentifier`) make one sample, at
//! `sessionTime`; the first to arrive reads as [`Reading::Ignored`], as do packets of the
//! other ids. A pair of the frame already made into a sample (the game paused sends its
//! last frame again and again) reads as [`Reading::Idle`]: the cue fades to neutral, as in
//! Forza's menus, as does a `Motion` whose player car is 255 (no car of the player's: a
//! spectator). Packets of another year's format (the games can send the two years before
//! theirs) are refused, naming the year and the game's *UDP Format* setting.
//!
//! The specification draws the axes (pitch about X, yaw about Y, roll about Z; the world
//! right-handed with Y up); with Z the car's forward, X is its left. So
//! `(wx, wy, wz) = (ωZ, ωX, ωY)` in °/s, and the g-forces are taken along those axes,
//! gravity excluded: `ax = g·longitudinal`, `ay = g·lateral`, `az = g·vertical`. The
//! specification gives their signs in no words: check them with `stewart telemetry`
//! (braking reads `ax < 0`, a left turn `ay > 0`).

use super::fields::{f32_at, u16_at, u32_at, vector_at};
use super::{GRAVITY, Reading, VehicleError, VehicleFormat, VehicleSample};

/// The formats read: F1 24's and F1 25's.
pub const PACKET_FORMATS: [u16; 2] = [2024, 2025];
/// The header's length.
pub const HEADER_BYTES: usize = 29;
/// `Motion`'s id and length.
pub const MOTION: (u8, usize) = (0, 1349);
/// `Motion Ex`'s id and length in the 2024 format.
pub const MOTION_EX: (u8, usize) = (13, 237);
/// `Motion Ex`'s length in the 2025 format.
pub const MOTION_EX_2025_BYTES: usize = 273;
/// The player car index of a spectator (no car of the player's).
const SPECTATOR: u8 = 255;
/// Cars in a `Motion` packet, and the bytes of each.
pub const CARS: (u8, usize) = (22, 60);

/// Byte offsets of the fields read.
const PACKET_ID: usize = 6;
const SESSION_UID: usize = 7;
const SESSION_TIME: usize = 15;
const FRAME: usize = 19;
const PLAYER_CAR: usize = 27;
const G_FORCES: usize = 36;
const ANGULAR_VELOCITY: usize = 173;

/// Whether `bytes` begin with an F1 header: a `packetFormat` that is a year of the series
/// (2018 on).
pub(crate) fn is_f1(bytes: &[u8]) -> bool {
    bytes.len() >= HEADER_BYTES && u16_at(bytes, 0).is_some_and(|y| (2018..=2030).contains(&y))
}

/// The halves of the frame being paired.
#[derive(Debug, Default)]
pub(crate) struct Pairing {
    /// The last `Motion`'s frame and its g-forces `[lateral, longitudinal, vertical]`.
    motion: Option<(FrameStamp, [f64; 3])>,
    /// The last `Motion Ex`'s frame and its angular velocity `[X, Y, Z]`.
    motion_ex: Option<(FrameStamp, [f64; 3])>,
    /// The frame of the last pair made into a sample.
    last_pair: Option<FrameStamp>,
}

/// Which frame a packet belongs to: session, frame number, and its time.
#[derive(Clone, Copy, Debug, PartialEq)]
struct FrameStamp {
    session: [u8; 8],
    number: Option<u32>,
    time: f64,
}

/// One F1 packet.
pub(crate) fn packet(bytes: &[u8], pairing: &mut Pairing) -> Result<Reading, VehicleError> {
    let format = u16_at(bytes, 0).unwrap_or(0);
    if !PACKET_FORMATS.contains(&format) {
        return Err(VehicleError::F1Format(format));
    }
    let id = bytes.get(PACKET_ID).copied();
    let motion_ex_bytes = match format {
        2024 => MOTION_EX.1,
        _ => MOTION_EX_2025_BYTES,
    };
    let length = |expected: usize| match bytes.len() == expected {
        true => Ok(()),
        false => Err(VehicleError::Length {
            format: VehicleFormat::F1,
            got: bytes.len(),
            expected: match expected {
                e if e == MOTION.1 => "1349 for Motion",
                e if e == MOTION_EX.1 => "237 for Motion Ex (2024 format)",
                _ => "273 for Motion Ex (2025 format)",
            },
        }),
    };
    let session = (bytes.get(SESSION_UID..SESSION_UID + 8))
        .and_then(|s| <[u8; 8]>::try_from(s).ok())
        .unwrap_or_default();
    let frame = FrameStamp {
        session,
        number: u32_at(bytes, FRAME),
        time: f32_at(bytes, SESSION_TIME),
    };
    if id == Some(MOTION.0) {
        length(MOTION.1)?;
        let car = bytes.get(PLAYER_CAR).copied().unwrap_or(u8::MAX);
        if car == SPECTATOR {
            return Ok(Reading::Idle);
        }
        if car >= CARS.0 {
            return Err(VehicleError::F1Car(car));
        }
        let block = HEADER_BYTES + CARS.1 * usize::from(car);
        pairing.motion = Some((frame, vector_at(bytes, block + G_FORCES)));
    } else if id == Some(MOTION_EX.0) {
        length(motion_ex_bytes)?;
        pairing.motion_ex = Some((frame, vector_at(bytes, ANGULAR_VELOCITY)));
    } else {
        return Ok(Reading::Ignored);
    }
    match (pairing.motion, pairing.motion_ex) {
        (Some((a, [lateral, longitudinal, vertical])), Some((b, [wx_pitch, wy_yaw, wz_roll])))
            if same_frame(&a, &b) =>
        {
            pairing.motion = None;
            pairing.motion_ex = None;
            // The game paused sends its last frame again and again: not a new sample but
            // a game at rest, faded to neutral as its menus are.
            if pairing.last_pair.is_some_and(|last| same_frame(&last, &a)) {
                return Ok(Reading::Idle);
            }
            pairing.last_pair = Some(a);
            Ok(Reading::Sample(VehicleSample {
                t: Some(frame.time),
                accel: [longitudinal, lateral, vertical].map(|g| GRAVITY * g),
                rates_deg_s: [wz_roll, wx_pitch, wy_yaw].map(f64::to_degrees),
            }))
        }
        _ => Ok(Reading::Ignored),
    }
}

fn same_frame(a: &FrameStamp, b: &FrameStamp) -> bool {
    a.session == b.session && a.number == b.number
}
