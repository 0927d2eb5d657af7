//! The set-point link to a real platform: what goes on the wire.
//!
//! - [`boards`]: hobby controller boards on several serial ports (SMC3, ODrive): their
//!   set-points and arming commands, written and read back;
//! - [`channels`]: which actuator goes out on which channel, scaled, mirrored, as µm,
//!   0.01° or servo pulse µs;
//! - [`crc`]: CRC-16/CCITT-FALSE, the frame checksum;
//! - [`frame`]: the binary frame (sync, version, kind, sequence, flags, unit, six
//!   fixed-point values, CRC) with its encoder and a resynchronising stream decoder;
//! - [`generator`]: online trajectory generation (Ruckig's algorithm): each actuator
//!   follows its target exactly when the target moves within the limits, else as fast as
//!   the speed, acceleration and jerk limits allow, never leaving its range;
//! - [`safety`]: the DISARMED → ARMING → ARMED → STOPPING state machine that decides,
//!   tick by tick, what may be sent;
//! - [`sender`]: the real-time thread: absolute deadlines, the supervisor, the wire;
//! - [`target`]: what a stream follows — the target of stream time, its samples (values,
//!   with velocity and acceleration when known), and why a tick has none;
//! - [`telemetry`]: the controller's answers matched to the set-points (commanded and
//!   measured side by side, latency, unanswered and stale counts);
//! - [`template`]: output templates (`<255><255>{a1:u16be}…`), the byte strings hobby
//!   boards read, written and read back;
//! - [`text`]: the plain text line form `S,seq,v1,…,v6` for the simplest sketches;
//! - [`transport`]: UDP, or a dry-run record of what would be sent.
//! - [`vehicle`]: vehicle motion coming in for motion cueing — the studio's generic text
//!   or `f32` datagram, or a game's telemetry (X-Plane `DATA` and `RREF`, Forza Data Out,
//!   F1 24 and 25, BeamNG.drive MotionSim, Live for Speed OutSim), told apart per datagram.
//!
//! `docs/PROTOCOL.md` documents the format with byte-exact examples, which the tests of
//! this crate reproduce.

pub mod boards;
pub mod channels;
pub mod crc;
pub mod frame;
pub mod generator;
pub mod safety;
pub mod sender;
pub mod target;
pub mod telemetry;
pub mod template;
pub mod text;
pub mod transport;
pub mod vehicle;

pub use frame::{DecodeError, Flags, Frame, FrameDecoder, FrameKind, ValueUnit};
