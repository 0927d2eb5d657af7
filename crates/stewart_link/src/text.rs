//! The text line form, for the simplest sketches (`Serial.parseInt()` reads it):
//!
//! - `S,seq,v1,v2,v3,v4,v5,v6\n` — set-points, armed (values in the link's unit, whole
//!   numbers: µm, 0.01° or µs);
//! - `E,seq\n` — emergency stop: stop at once;
//! - `H,seq,v1,…,v6\n` — returning home after a stop: follow the values home.
//!
//! A disarmed link sends nothing in this form (the text form has no disarmed frame).

use crate::frame::{Flags, Frame};

/// The line for `frame`, or `None` for a frame the text form does not carry (disarmed).
pub fn line(frame: &Frame) -> Option<String> {
    let values = || {
        frame
            .values
            .iter()
            .map(i32::to_string)
            .collect::<Vec<_>>()
            .join(",")
    };
    let Flags { armed, estop, home } = frame.flags;
    if estop {
        Some(format!("E,{}\n", frame.sequence))
    } else if home {
        Some(format!("H,{},{}\n", frame.sequence, values()))
    } else if armed {
        Some(format!("S,{},{}\n", frame.sequence, values()))
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::frame::{FrameKind, Unit};

    #[test]
    fn lines_for_set_points_stop_and_home() {
        let mut f = Frame {
            kind: FrameKind::SetPoint,
            sequence: 7,
            flags: Flags {
                armed: true,
                ..Flags::default()
            },
            unit: Unit::Centidegree,
            values: [1250, -300, 0, 4500, -9000, 17],
        };
        assert_eq!(line(&f).as_deref(), Some("S,7,1250,-300,0,4500,-9000,17\n"));
        f.flags.estop = true;
        assert_eq!(line(&f).as_deref(), Some("E,7\n"));
        f.flags = Flags {
            home: true,
            ..Flags::default()
        };
        assert_eq!(line(&f).as_deref(), Some("H,7,1250,-300,0,4500,-9000,17\n"));
        f.flags = Flags::default();
        assert_eq!(line(&f), None);
    }
}
