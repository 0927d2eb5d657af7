//! The protocols of hobby motion-rig controller boards that take several actuators on
//! several serial ports: what each port gets at each tick, and when the platform is armed
//! and disarmed.
//!
//! - [`Board::Smc3`]: the SMC3 Arduino sketch for DC motors (by RufusDufus, xsimulator.net;
//!   `SMC3.ino` v0.7.0): three motors a board, five-byte frames `[A hi lo]`, `[B hi lo]`,
//!   `[C hi lo]` (the target, 0–1023, high byte first) — actuators 1–3 on the first port,
//!   4–6 on the second; `[ena]` (enable all motors) at arming. The sketch has no command
//!   that disables the motors: at disarming nothing is sent (the stop has already brought
//!   the platform to rest), and the board holds its last target.
//! - [`Board::ODrive`]: ODrive's ASCII protocol (firmware 0.5 and later,
//!   <https://docs.odriverobotics.com/v/latest/manual/ascii-protocol.html>): `p <axis>
//!   <position> <velocity_ff> <torque_ff>\n` in turns, turns/s and N·m — actuators 1–2 on
//!   the first two-axis board, 3–4 on the second, 5–6 on the third; each axis put in closed
//!   loop control (`w axisN.requested_state 8\n`) at arming and idle
//!   (`w axisN.requested_state 1\n`) at disarming. Positions are `turns_per_unit · value +
//!   turns_offset` per actuator (metres or degrees to turns), the velocity feed-forward the
//!   supervisor's velocity scaled alike, the torque feed-forward 0.

use crate::template::{FieldType, scaled};

mod read;

pub use read::{BoardReader, BoardRecord};

/// A board protocol.
#[derive(Clone, Debug, PartialEq)]
pub enum Board {
    /// SMC3: two boards of three motors.
    Smc3,
    /// ODrive: three boards of two axes, each actuator's value turned into turns.
    ODrive(Turns),
}

/// Per actuator: turns per metre (or per degree), and turns at zero.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Turns {
    /// Turns per unit of the actuator's value.
    pub per_unit: [f64; 6],
    /// Turns where the value is zero.
    pub offset: [f64; 6],
}

/// The SMC3 command that enables every motor.
pub const SMC3_ENABLE: &[u8; 5] = b"[ena]";

/// The largest number an SMC3 target takes.
pub const SMC3_LARGEST: u32 = 1023;

/// ODrive's axis states: closed loop control, and idle.
pub const ODRIVE_CLOSED_LOOP: u8 = 8;
/// ODrive's idle axis state.
pub const ODRIVE_IDLE: u8 = 1;

impl Board {
    /// The serial ports (boards) it takes.
    pub fn ports(&self) -> usize {
        match self {
            Board::Smc3 => 2,
            Board::ODrive(_) => 3,
        }
    }

    /// The board and its channel (0-based) actuator `k` (0–5) goes to.
    pub fn place(&self, k: usize) -> (usize, usize) {
        match self {
            Board::Smc3 => (k / 3, k % 3),
            Board::ODrive(_) => (k / 2, k % 2),
        }
    }

    /// The most bytes one set-point puts on one port (the line rate's budget).
    pub fn max_frame_bytes(&self) -> usize {
        match self {
            Board::Smc3 => 3 * 5,
            // Two lines `p 1 -123456.789012 -123456.789012 0\n`.
            Board::ODrive(_) => 2 * 40,
        }
    }

    /// Append each port's bytes for the values `values` (moving at `velocities`, units a
    /// second) within `ranges` to `out[port]` (as many buffers as [`Board::ports`]).
    pub fn set_point(
        &self,
        values: &[f64; 6],
        velocities: &[f64; 6],
        ranges: &[(f64, f64); 6],
        out: &mut [Vec<u8>],
    ) {
        for k in 0..6 {
            let (port, channel) = self.place(k);
            let Some(buffer) = out.get_mut(port) else {
                continue;
            };
            match self {
                Board::Smc3 => {
                    let n = scaled(values[k], ranges[k], FieldType::U10Be);
                    let [_, _, hi, lo] = n.to_be_bytes();
                    buffer.extend([b'[', b'A' + channel as u8, hi, lo, b']']);
                }
                Board::ODrive(turns) => {
                    let position = turns.per_unit[k] * values[k] + turns.offset[k];
                    let velocity = turns.per_unit[k] * velocities[k];
                    // Six decimals: a micro-turn (0.36 millidegree of the motor).
                    use std::io::Write as _;
                    let _ = writeln!(buffer, "p {channel} {position:.6} {velocity:.6} 0");
                }
            }
        }
    }

    /// Append each port's bytes for arming (`true`) or disarming.
    pub fn arming(&self, armed: bool, out: &mut [Vec<u8>]) {
        for buffer in out.iter_mut().take(self.ports()) {
            match self {
                Board::Smc3 if armed => buffer.extend(SMC3_ENABLE),
                Board::Smc3 => {}
                Board::ODrive(_) => {
                    let state = if armed {
                        ODRIVE_CLOSED_LOOP
                    } else {
                        ODRIVE_IDLE
                    };
                    for axis in 0..2 {
                        use std::io::Write as _;
                        let _ = writeln!(buffer, "w axis{axis}.requested_state {state}");
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests;
