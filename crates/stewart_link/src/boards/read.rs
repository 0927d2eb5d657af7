//! One board's stream read back (the stand-in controller's side): SMC3's five-byte frames
//! or ODrive's ASCII lines, gathered into one record per tick — every channel of the board
//! set once, in order — and the arming commands.

use super::{Board, ODRIVE_CLOSED_LOOP, ODRIVE_IDLE, SMC3_ENABLE};

/// What a board's stream said.
#[derive(Clone, Debug, PartialEq)]
pub enum BoardRecord {
    /// One tick's targets, channel by channel: SMC3's numbers (0–1023), ODrive's positions
    /// in turns.
    SetPoint(Vec<f64>),
    /// The motors enabled (SMC3 `[ena]`, ODrive closed loop) or put idle (ODrive).
    Armed(bool),
    /// Bytes that are none of the protocol's commands (skipped, counted by the reader).
    Unknown,
}

/// Reads one board's stream.
#[derive(Clone, Debug)]
pub struct BoardReader {
    board: Board,
    buffer: Vec<u8>,
    pending: Vec<Option<f64>>,
}

/// The longest ODrive line read, bytes (a longer one is not the protocol's).
const MAX_LINE: usize = 256;

impl BoardReader {
    /// A reader of `board`'s protocol.
    pub fn new(board: Board) -> Self {
        let channels = match board {
            Board::Smc3 => 3,
            Board::ODrive(_) => 2,
        };
        Self {
            board,
            buffer: Vec::new(),
            pending: vec![None; channels],
        }
    }

    /// The board protocol read.
    pub fn board(&self) -> &Board {
        &self.board
    }

    /// Whether bytes wait that may begin a command.
    pub fn pending(&self) -> bool {
        !self.buffer.is_empty()
    }

    /// Take `bytes` in; [`BoardReader::next_record`] gives what they complete.
    pub fn push(&mut self, bytes: &[u8]) {
        self.buffer.extend_from_slice(bytes);
    }

    /// The next record, if the bytes in complete one.
    pub fn next_record(&mut self) -> Option<BoardRecord> {
        loop {
            let (record, used) = match self.board {
                Board::Smc3 => self.smc3()?,
                Board::ODrive(_) => self.odrive()?,
            };
            self.buffer.drain(..used);
            match record {
                Some(r) => return Some(r),
                None => continue,
            }
        }
    }

    /// An SMC3 frame at the buffer's start: `(record, bytes used)`; `None` to wait.
    fn smc3(&mut self) -> Option<(Option<BoardRecord>, usize)> {
        let b = &self.buffer;
        if b.is_empty() {
            return None;
        }
        if b[0] != b'[' {
            return Some((Some(BoardRecord::Unknown), 1));
        }
        let frame: [u8; 5] = b.get(..5)?.try_into().ok()?;
        if frame[4] != b']' {
            return Some((Some(BoardRecord::Unknown), 1));
        }
        if &frame == SMC3_ENABLE {
            return Some((Some(BoardRecord::Armed(true)), 5));
        }
        let channel = match frame[1] {
            c @ b'A'..=b'C' => usize::from(c - b'A'),
            // Other commands (PID settings, reads) are not set-points.
            _ => return Some((Some(BoardRecord::Unknown), 5)),
        };
        let n = u16::from_be_bytes([frame[2], frame[3]]);
        Some((self.channel(channel, f64::from(n)), 5))
    }

    /// An ODrive line at the buffer's start.
    fn odrive(&mut self) -> Option<(Option<BoardRecord>, usize)> {
        let Some(end) = self.buffer.iter().position(|&c| c == b'\n') else {
            if self.buffer.len() > MAX_LINE {
                return Some((Some(BoardRecord::Unknown), self.buffer.len()));
            }
            return None;
        };
        let line = String::from_utf8_lossy(&self.buffer[..end]).into_owned();
        let words: Vec<&str> = line.split_whitespace().collect();
        let record = match words[..] {
            ["p", axis, position, _velocity, _torque] => {
                match (axis.parse::<usize>(), position.parse::<f64>()) {
                    (Ok(a), Ok(p)) if a < 2 && p.is_finite() => self.channel(a, p),
                    _ => Some(BoardRecord::Unknown),
                }
            }
            ["w", path, state]
                if path.starts_with("axis") && path.ends_with(".requested_state") =>
            {
                match state.parse::<u8>() {
                    Ok(ODRIVE_CLOSED_LOOP) => Some(BoardRecord::Armed(true)),
                    Ok(ODRIVE_IDLE) => Some(BoardRecord::Armed(false)),
                    _ => Some(BoardRecord::Unknown),
                }
            }
            _ => Some(BoardRecord::Unknown),
        };
        Some((record, end + 1))
    }

    /// Channel `c` set to `value`; the tick's record once the last channel is set.
    fn channel(&mut self, c: usize, value: f64) -> Option<BoardRecord> {
        if c == 0 {
            self.pending.iter_mut().for_each(|p| *p = None);
        }
        self.pending[c] = Some(value);
        let last = self.pending.len() - 1;
        if c == last && self.pending.iter().all(Option::is_some) {
            let values = self.pending.iter().map(|p| p.unwrap_or(0.0)).collect();
            return Some(BoardRecord::SetPoint(values));
        }
        None
    }
}
