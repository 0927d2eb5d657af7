//! The binary frame: 34 bytes, little-endian.
//!
//! | offset | size | field |
//! |---|---|---|
//! | 0 | 2 | sync `0xA5 0x5A` |
//! | 2 | 1 | protocol version, 1 |
//! | 3 | 1 | kind: `0x01` set-point (host → controller), `0x02` telemetry (controller → host) |
//! | 4 | 2 | sequence number, `u16`, +1 per frame of a kind, wrapping |
//! | 6 | 1 | flags: bit 0 armed, bit 1 e-stop, bit 2 home; bits 3–7 zero |
//! | 7 | 1 | unit of the values: `0x00` leg length µm, `0x01` servo angle 0.01°, `0x02` pulse width µs |
//! | 8 | 24 | six values, `i32` each, actuator 1 first |
//! | 32 | 2 | CRC-16/CCITT-FALSE ([`crate::crc`]) of bytes 2–31 |

use thiserror::Error;

use crate::crc::crc16;

/// The two bytes every frame starts with.
pub const SYNC: [u8; 2] = [0xA5, 0x5A];
/// The protocol version this crate speaks.
pub const VERSION: u8 = 1;
/// Bytes in a frame.
pub const FRAME_LEN: usize = 34;

/// What a frame carries.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrameKind {
    /// Set-points, host to controller.
    SetPoint,
    /// Measured values, controller to host.
    Telemetry,
}

impl FrameKind {
    fn code(self) -> u8 {
        match self {
            FrameKind::SetPoint => 0x01,
            FrameKind::Telemetry => 0x02,
        }
    }

    fn from_code(code: u8) -> Option<Self> {
        match code {
            0x01 => Some(FrameKind::SetPoint),
            0x02 => Some(FrameKind::Telemetry),
            _ => None,
        }
    }
}

/// The unit of a frame's six values.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ValueUnit {
    /// Leg lengths, micrometres.
    Micrometre,
    /// Servo angles, hundredths of a degree.
    Centidegree,
    /// Servo pulse widths, microseconds.
    PulseMicrosecond,
}

impl ValueUnit {
    fn code(self) -> u8 {
        match self {
            ValueUnit::Micrometre => 0x00,
            ValueUnit::Centidegree => 0x01,
            ValueUnit::PulseMicrosecond => 0x02,
        }
    }

    fn from_code(code: u8) -> Option<Self> {
        match code {
            0x00 => Some(ValueUnit::Micrometre),
            0x01 => Some(ValueUnit::Centidegree),
            0x02 => Some(ValueUnit::PulseMicrosecond),
            _ => None,
        }
    }

    /// How many of this unit make one of the value's natural unit (metres, degrees,
    /// microseconds).
    pub fn per_natural_unit(self) -> f64 {
        match self {
            ValueUnit::Micrometre => 1e6,
            ValueUnit::Centidegree => 100.0,
            ValueUnit::PulseMicrosecond => 1.0,
        }
    }

    /// `value` (metres, degrees or microseconds) as the nearest whole number of this unit,
    /// or `None` when it is not finite or does not fit an `i32`.
    pub fn to_fixed(self, value: f64) -> Option<i32> {
        let v = (value * self.per_natural_unit()).round();
        (v.is_finite() && v >= f64::from(i32::MIN) && v <= f64::from(i32::MAX)).then_some(v as i32)
    }

    /// A fixed-point value back in metres, degrees or microseconds.
    pub fn to_natural(self, fixed: i32) -> f64 {
        f64::from(fixed) / self.per_natural_unit()
    }
}

/// The flags byte.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Flags {
    /// The host is armed: the controller may move to the set-points.
    pub armed: bool,
    /// Emergency stop: stop at once, whatever the values say.
    pub estop: bool,
    /// Returning home after a stop: the values lead home at a safe speed; follow them.
    pub home: bool,
}

impl Flags {
    fn byte(self) -> u8 {
        u8::from(self.armed) | u8::from(self.estop) << 1 | u8::from(self.home) << 2
    }

    fn from_byte(b: u8) -> Option<Self> {
        (b & !0b111 == 0).then_some(Self {
            armed: b & 1 != 0,
            estop: b & 2 != 0,
            home: b & 4 != 0,
        })
    }
}

/// One frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Frame {
    /// Set-point or telemetry.
    pub kind: FrameKind,
    /// Sequence number.
    pub sequence: u16,
    /// Armed, e-stop, home.
    pub flags: Flags,
    /// Unit of `values`.
    pub unit: ValueUnit,
    /// Six fixed-point values, actuator 1 first.
    pub values: [i32; 6],
}

impl Frame {
    /// The frame in words: its flags, then the six values in their unit
    /// (`armed, home [1, 2, …] µm`; `disarmed` without flags).
    pub fn in_words(&self) -> String {
        let f = self.flags;
        let flags: Vec<&str> = [(f.armed, "armed"), (f.estop, "e-stop"), (f.home, "home")]
            .into_iter()
            .filter_map(|(on, word)| on.then_some(word))
            .collect();
        let unit = match self.unit {
            ValueUnit::Micrometre => "µm",
            ValueUnit::Centidegree => "0.01°",
            ValueUnit::PulseMicrosecond => "µs",
        };
        let values: Vec<String> = self.values.iter().map(i32::to_string).collect();
        format!(
            "{} [{}] {unit}",
            if flags.is_empty() {
                "disarmed".to_owned()
            } else {
                flags.join(", ")
            },
            values.join(", ")
        )
    }

    /// The 34 bytes on the wire.
    pub fn encode(&self) -> [u8; FRAME_LEN] {
        let mut out = [0u8; FRAME_LEN];
        out[..2].copy_from_slice(&SYNC);
        out[2] = VERSION;
        out[3] = self.kind.code();
        out[4..6].copy_from_slice(&self.sequence.to_le_bytes());
        out[6] = self.flags.byte();
        out[7] = self.unit.code();
        for (k, v) in self.values.iter().enumerate() {
            out[8 + 4 * k..12 + 4 * k].copy_from_slice(&v.to_le_bytes());
        }
        let crc = crc16(&out[2..32]);
        out[32..].copy_from_slice(&crc.to_le_bytes());
        out
    }

    /// Read one frame from exactly [`FRAME_LEN`] bytes.
    pub fn decode(bytes: &[u8; FRAME_LEN]) -> Result<Frame, DecodeError> {
        if bytes[..2] != SYNC {
            return Err(DecodeError::Sync);
        }
        let expected = crc16(&bytes[2..32]);
        let got = u16::from_le_bytes([bytes[32], bytes[33]]);
        if expected != got {
            return Err(DecodeError::Crc { expected, got });
        }
        if bytes[2] != VERSION {
            return Err(DecodeError::Version(bytes[2]));
        }
        let kind = FrameKind::from_code(bytes[3]).ok_or(DecodeError::Kind(bytes[3]))?;
        let flags = Flags::from_byte(bytes[6]).ok_or(DecodeError::Flags(bytes[6]))?;
        let unit = ValueUnit::from_code(bytes[7]).ok_or(DecodeError::Unit(bytes[7]))?;
        let values = std::array::from_fn(|k| {
            let at = 8 + 4 * k;
            i32::from_le_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]])
        });
        Ok(Frame {
            kind,
            sequence: u16::from_le_bytes([bytes[4], bytes[5]]),
            flags,
            unit,
            values,
        })
    }
}

/// Why bytes were not a frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Error)]
pub enum DecodeError {
    /// The frame does not start with the sync bytes.
    #[error("the frame does not start with the sync bytes A5 5A")]
    Sync,
    /// The checksum does not match: the bytes were damaged.
    #[error("CRC mismatch: the frame says {got:#06x}, its bytes give {expected:#06x}")]
    Crc {
        /// The CRC of the bytes received.
        expected: u16,
        /// The CRC the frame carries.
        got: u16,
    },
    /// A protocol version this decoder does not speak.
    #[error("protocol version {0}, expected 1")]
    Version(u8),
    /// An unknown frame kind.
    #[error("unknown frame kind {0:#04x}")]
    Kind(u8),
    /// Reserved flag bits set.
    #[error("reserved flag bits set in {0:#04x}")]
    Flags(u8),
    /// An unknown unit code.
    #[error("unknown unit code {0:#04x}")]
    Unit(u8),
}

/// A stream decoder: bytes in, frames out, resynchronising on the sync bytes after noise
/// or a damaged frame. Fixed memory (one frame's bytes).
#[derive(Clone, Debug)]
pub struct FrameDecoder {
    buffer: [u8; FRAME_LEN],
    filled: usize,
}

impl Default for FrameDecoder {
    fn default() -> Self {
        Self::new()
    }
}

impl FrameDecoder {
    /// A decoder waiting for a frame.
    pub fn new() -> Self {
        Self {
            buffer: [0; FRAME_LEN],
            filled: 0,
        }
    }

    /// Take one byte; a frame (or why the candidate frame was refused) when one is complete.
    pub fn push(&mut self, byte: u8) -> Option<Result<Frame, DecodeError>> {
        // Hunt for the sync bytes.
        match self.filled {
            0 if byte != SYNC[0] => return None,
            1 if byte != SYNC[1] => {
                self.filled = usize::from(byte == SYNC[0]);
                return None;
            }
            _ => {}
        }
        self.buffer[self.filled] = byte;
        self.filled += 1;
        if self.filled < FRAME_LEN {
            return None;
        }
        let result = Frame::decode(&self.buffer);
        self.filled = 0;
        if result.is_err() {
            // A damaged frame: keep what follows the next sync candidate inside it.
            let next = (1..FRAME_LEN).find(|&j| {
                self.buffer[j] == SYNC[0] && (j + 1 == FRAME_LEN || self.buffer[j + 1] == SYNC[1])
            });
            if let Some(j) = next {
                self.buffer.copy_within(j.., 0);
                self.filled = FRAME_LEN - j;
            }
        }
        Some(result)
    }
}

#[cfg(test)]
mod tests;
