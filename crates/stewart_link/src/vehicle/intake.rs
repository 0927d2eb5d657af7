//! Datagrams in, samples out: the one loop that decodes a datagram ([`Decoder`]), places
//! its sample on the time line ([`Timeline`]) and counts what it was ([`Tally`], by
//! [`Format`]). The live link, a replayed capture and `stewart telemetry` all read through
//! it, so they agree datagram for datagram.

use super::timeline::{Placed, Placement, Timeline};
use super::{Decoder, Format, Reading, VehicleError};

/// What one datagram was.
#[derive(Clone, Debug, PartialEq)]
pub enum Intaken {
    /// A sample, and what became of it on the time line.
    Sample(Placement),
    /// The game in its menus or paused.
    Idle,
    /// Nothing to use (another packet of the game's, the first half of a pair).
    Ignored,
    /// Not readable: why.
    Refused(VehicleError),
}

/// Counts of what arrived, all along.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Tally {
    /// Datagrams taken.
    pub datagrams: u64,
    /// Datagrams per format recognised, in the order of [`Format::ALL`].
    per_format: [u64; Format::ALL.len()],
    /// Samples placed on the time line.
    pub placed: u64,
    /// Datagrams that could not be read (of a format recognised or of none).
    pub refused: u64,
    /// Samples whose stamp and motion repeat the last (dropped).
    pub repeats: u64,
    /// Samples older than the last (dropped).
    pub stale: u64,
    /// Datagrams saying the game was in its menus or paused.
    pub idle: u64,
    /// Samples held on a repeated stamp when the stream stopped or stalled (dropped).
    pub unplaced: u64,
}

impl Tally {
    /// Datagrams of `format` so far.
    pub fn of(&self, format: Format) -> u64 {
        self.per_format[format.index()]
    }

    /// The formats that arrived, with their datagrams, in the order of [`Format::ALL`].
    pub fn formats(&self) -> impl Iterator<Item = (Format, u64)> + '_ {
        Format::ALL
            .iter()
            .zip(self.per_format)
            .filter(|(_, n)| *n > 0)
            .map(|(f, n)| (*f, n))
    }
}

/// Reads datagrams into placed samples, counting them.
#[derive(Debug, Default)]
pub struct Intake {
    decoder: Decoder,
    timeline: Timeline,
    tally: Tally,
}

impl Intake {
    /// An intake that has seen nothing.
    pub fn new() -> Self {
        Self::default()
    }

    /// Take one datagram arriving at `arrival` (seconds on the receiver's clock): its
    /// format, what it was, and the samples it placed (oldest first).
    pub fn take(&mut self, bytes: &[u8], arrival: f64) -> (Option<Format>, Intaken, Placed) {
        let decoded = self.decoder.decode(bytes);
        let tally = &mut self.tally;
        tally.datagrams += 1;
        if let Some(format) = decoded.format {
            tally.per_format[format.index()] += 1;
        }
        let mut placed = Placed::default();
        let what = match decoded.reading {
            Ok(Reading::Sample(sample)) => {
                let (placement, p) = self.timeline.push(sample, arrival);
                placed = p;
                tally.placed += placed.len() as u64;
                match placement {
                    Placement::Repeat => tally.repeats += 1,
                    Placement::Stale => tally.stale += 1,
                    Placement::Placed | Placement::Held => {}
                }
                Intaken::Sample(placement)
            }
            Ok(Reading::Idle) => {
                tally.idle += 1;
                Intaken::Idle
            }
            Ok(Reading::Ignored) => Intaken::Ignored,
            Err(e) => {
                tally.refused += 1;
                Intaken::Refused(e)
            }
        };
        (decoded.format, what, placed)
    }

    /// Start a new stretch of the senders' clocks (after a stall, or at the end): samples
    /// held on a repeated stamp are dropped and counted.
    pub fn restart(&mut self) {
        self.tally.unplaced += self.timeline.restart() as u64;
    }

    /// What arrived so far.
    pub fn tally(&self) -> &Tally {
        &self.tally
    }
}
