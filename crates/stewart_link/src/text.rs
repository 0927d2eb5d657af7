//! The text line form, for the simplest sketches (`Serial.parseInt()` reads it):
//!
//! - `S,seq,v1,v2,v3,v4,v5,v6\n` — set-points, armed (values in the link's unit, whole
//!   numbers: µm, 0.01° or µs);
//! - `E,seq\n` — emergency stop: stop at once;
//! - `H,seq,v1,…,v6\n` — returning home after a stop: follow the values home.
//!
//! A disarmed link sends nothing in this form (the text form has no disarmed frame).

use thiserror::Error;

use crate::frame::{Flags, Frame, FrameKind, ValueUnit};

/// The longest line a [`LineDecoder`] accepts, newline included: `S`, a sequence number and
/// six `i32` values with their commas take at most 86 bytes.
pub const MAX_LINE: usize = 96;

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

/// Why a text line was refused.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
pub enum LineError {
    /// More than [`MAX_LINE`] bytes without a newline.
    #[error("a line longer than {MAX_LINE} bytes")]
    TooLong,
    /// Bytes that are not ASCII text.
    #[error("bytes that are not ASCII text")]
    NotText,
    /// A first field other than `S`, `E` or `H`.
    #[error("unknown line kind `{0}` (expected S, E or H)")]
    Kind(String),
    /// The sequence number is missing or not a whole number 0–65535.
    #[error("sequence number `{0}` is not a whole number 0–65535")]
    Sequence(String),
    /// Not the number of values the line's kind carries.
    #[error("{got} values where `{kind}` carries {expected}")]
    Count {
        /// The line's kind letter.
        kind: char,
        /// Values the kind carries.
        expected: usize,
        /// Values found.
        got: usize,
    },
    /// A value that is not a whole number fitting an `i32`.
    #[error("value {index} `{text}` is not a whole number")]
    Value {
        /// 1-based position among the six values.
        index: usize,
        /// What was there.
        text: String,
    },
}

/// The frame a line stands for (without its newline), the inverse of [`line`]: `S` is an
/// armed set-point, `E` an e-stop with all values 0, `H` the way home (armed and home, as the
/// link sends it). The text form carries no unit: the controller knows its own, `unit`.
pub fn parse(text: &str, unit: ValueUnit) -> Result<Frame, LineError> {
    let mut fields = text.trim_end_matches('\r').split(',');
    let kind = fields.next().unwrap_or_default();
    let (flags, count) = match kind {
        "S" => (
            Flags {
                armed: true,
                ..Flags::default()
            },
            6,
        ),
        "E" => (
            Flags {
                estop: true,
                ..Flags::default()
            },
            0,
        ),
        "H" => (
            Flags {
                armed: true,
                home: true,
                ..Flags::default()
            },
            6,
        ),
        other => return Err(LineError::Kind(other.to_owned())),
    };
    let sequence_text = fields.next().unwrap_or_default();
    let sequence = sequence_text
        .trim()
        .parse::<u16>()
        .map_err(|_| LineError::Sequence(sequence_text.to_owned()))?;
    let rest: Vec<&str> = fields.collect();
    if rest.len() != count {
        return Err(LineError::Count {
            kind: kind.chars().next().unwrap_or('?'),
            expected: count,
            got: rest.len(),
        });
    }
    let mut values = [0i32; 6];
    for (index, (slot, field)) in values.iter_mut().zip(&rest).enumerate() {
        *slot = field.trim().parse().map_err(|_| LineError::Value {
            index: index + 1,
            text: (*field).to_owned(),
        })?;
    }
    Ok(Frame {
        kind: FrameKind::SetPoint,
        sequence,
        flags,
        unit,
        values,
    })
}

/// Splits a byte stream into lines and parses each, as a controller reading the text form
/// would; a line that runs past [`MAX_LINE`] is refused once and skipped to its newline.
#[derive(Clone, Debug)]
pub struct LineDecoder {
    unit: ValueUnit,
    line: Vec<u8>,
    overflowed: bool,
}

impl LineDecoder {
    /// A decoder for a controller whose values are in `unit`.
    pub fn new(unit: ValueUnit) -> Self {
        Self {
            unit,
            line: Vec::with_capacity(MAX_LINE),
            overflowed: false,
        }
    }

    /// Take one byte; a frame (or why the line was refused) when a line ends.
    pub fn push(&mut self, byte: u8) -> Option<Result<Frame, LineError>> {
        if byte != b'\n' {
            if self.line.len() < MAX_LINE {
                self.line.push(byte);
            } else if !self.overflowed {
                self.overflowed = true;
                return Some(Err(LineError::TooLong));
            }
            return None;
        }
        let line = std::mem::take(&mut self.line);
        if std::mem::take(&mut self.overflowed) {
            return None;
        }
        if line.is_empty() || line == b"\r" {
            return None;
        }
        Some(
            std::str::from_utf8(&line)
                .ok()
                .filter(|s| s.is_ascii())
                .ok_or(LineError::NotText)
                .and_then(|s| parse(s, self.unit)),
        )
    }

    /// Forget any part of a line (a datagram that ended stands alone).
    pub fn reset(&mut self) {
        self.line.clear();
        self.overflowed = false;
    }

    /// Whether part of a line is waiting for its newline.
    pub fn pending(&self) -> bool {
        !self.line.is_empty() || self.overflowed
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::frame::{FrameKind, ValueUnit};

    #[test]
    fn lines_for_set_points_stop_and_home() {
        let mut f = Frame {
            kind: FrameKind::SetPoint,
            sequence: 7,
            flags: Flags {
                armed: true,
                ..Flags::default()
            },
            unit: ValueUnit::Centidegree,
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

    #[test]
    fn parsing_a_line_gives_back_the_frame_it_came_from() {
        for flags in [
            Flags {
                armed: true,
                ..Flags::default()
            },
            Flags {
                armed: true,
                home: true,
                ..Flags::default()
            },
        ] {
            let f = Frame {
                kind: FrameKind::SetPoint,
                sequence: 65535,
                flags,
                unit: ValueUnit::Micrometre,
                values: [i32::MIN, i32::MAX, 0, 1, -1, 250_000],
            };
            let text = line(&f).unwrap_or_default();
            assert!(text.len() <= MAX_LINE, "{}", text.len());
            assert_eq!(parse(text.trim_end(), ValueUnit::Micrometre), Ok(f));
        }
        let e = parse("E,12", ValueUnit::Centidegree).unwrap_or_else(|e| panic!("{e}"));
        assert!(e.flags.estop && !e.flags.armed);
        assert_eq!(
            (e.sequence, e.values, e.unit),
            (12, [0; 6], ValueUnit::Centidegree)
        );
    }

    #[test]
    fn bad_lines_say_what_is_wrong() {
        let u = ValueUnit::Micrometre;
        assert_eq!(parse("X,1", u), Err(LineError::Kind("X".into())));
        assert_eq!(
            parse("S,70000,1,2,3,4,5,6", u),
            Err(LineError::Sequence("70000".into()))
        );
        assert_eq!(
            parse("S,1,1,2,3", u),
            Err(LineError::Count {
                kind: 'S',
                expected: 6,
                got: 3
            })
        );
        assert_eq!(
            parse("H,1,1,2,x,4,5,6", u),
            Err(LineError::Value {
                index: 3,
                text: "x".into()
            })
        );
        assert!(parse("E,1,5", u).is_err());
    }

    #[test]
    fn the_decoder_splits_a_stream_into_lines_and_skips_an_overlong_one_once() {
        let mut d = LineDecoder::new(ValueUnit::Micrometre);
        let mut out = Vec::new();
        let long = "9".repeat(300);
        let stream = format!("S,1,1,2,3,4,5,6\r\n\nS,2,{long}\nE,3\nS,4,1");
        for b in stream.bytes() {
            out.extend(d.push(b));
        }
        assert_eq!(out.len(), 3, "{out:?}");
        assert_eq!(out[0].as_ref().map(|f| f.sequence), Ok(1));
        assert_eq!(out[1], Err(LineError::TooLong));
        assert_eq!(out[2].as_ref().map(|f| f.flags.estop), Ok(true));
        assert!(d.pending());
        let mut binary = LineDecoder::new(ValueUnit::Micrometre);
        let got: Vec<_> = [0xA5, 0x5A, 0xFF, b'\n']
            .iter()
            .filter_map(|&b| binary.push(b))
            .collect();
        assert_eq!(got, vec![Err(LineError::NotText)]);
    }
}
