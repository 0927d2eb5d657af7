//! What the controller says back: telemetry frames (kind 02) matched to the set-points they
//! answer. A telemetry frame carries the sequence number of the last set-point the
//! controller received, its measured actuator values and its own state (see
//! docs/PROTOCOL.md); matched to that set-point it gives the commanded and measured values
//! side by side and the round trip's latency.
//!
//! Counted along the way: set-points no telemetry answered (*unanswered*: lost on the way
//! there or back, or a controller that answers fewer), and *stale* telemetry (an answer to
//! a set-point older than one already answered — reordered or delayed — or to one no longer
//! remembered, or later than [`STALE_AFTER_S`]).

use std::time::Instant;

use crate::channels::ChannelMap;
use crate::frame::Frame;

/// How many set-points are remembered for matching (4 s at 1 kHz).
const REMEMBERED: usize = 4096;

/// An answer later than this after its set-point is stale, seconds.
pub const STALE_AFTER_S: f64 = 0.1;

/// One set-point with the telemetry that answered it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Row {
    /// The set-point's stream time, seconds.
    pub time: f64,
    /// Its sequence number.
    pub sequence: u16,
    /// The values commanded, natural units (m or °).
    pub commanded: [f64; 6],
    /// The values the controller measured, natural units (read back through the channel
    /// map).
    pub measured: [f64; 6],
    /// From sending the set-point to receiving its answer, seconds.
    pub latency_s: f64,
}

/// What the telemetry so far amounts to.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TelemetryStats {
    /// Telemetry frames received.
    pub frames: u64,
    /// Set-points answered (matched).
    pub answered: u64,
    /// Set-points that no answer matched, between the first and the last answered.
    pub unanswered: u64,
    /// Answers that came out of order, too late, or for a set-point no longer remembered.
    pub stale: u64,
    /// Mean round-trip latency of the answered set-points, seconds.
    pub latency_mean_s: f64,
    /// Largest round-trip latency, seconds.
    pub latency_max_s: f64,
}

/// A set-point as sent.
#[derive(Clone, Copy)]
struct Sent {
    sequence: u16,
    time: f64,
    at: Instant,
    values: [f64; 6],
}

/// Matches telemetry to the set-points sent (allocation-free after it is built).
pub struct Matcher {
    sent: Vec<Option<Sent>>,
    newest_answered: Option<u16>,
    stats: TelemetryStats,
    latency_sum: f64,
}

impl Default for Matcher {
    fn default() -> Self {
        Self {
            sent: vec![None; REMEMBERED],
            newest_answered: None,
            stats: TelemetryStats::default(),
            latency_sum: 0.0,
        }
    }
}

impl Matcher {
    /// Remember a set-point sent at stream time `time` (instant `at`) with `values`.
    pub fn sent(&mut self, sequence: u16, time: f64, at: Instant, values: [f64; 6]) {
        self.sent[usize::from(sequence) % REMEMBERED] = Some(Sent {
            sequence,
            time,
            at,
            values,
        });
    }

    /// A telemetry frame that arrived at `at`: the row it makes with its set-point, or
    /// `None` (counted stale) when it answers none that can be matched.
    pub fn answer(&mut self, frame: &Frame, at: Instant, map: &ChannelMap) -> Option<Row> {
        self.stats.frames += 1;
        let Some(sent) = self.sent[usize::from(frame.sequence) % REMEMBERED]
            .filter(|s| s.sequence == frame.sequence)
        else {
            self.stats.stale += 1;
            return None;
        };
        let latency = at.saturating_duration_since(sent.at).as_secs_f64();
        // Sequence numbers wrap: "after" is within half the circle ahead.
        let ahead = self
            .newest_answered
            .map(|n| frame.sequence.wrapping_sub(n))
            .map_or(1, u32::from);
        if ahead == 0 || ahead >= 0x8000 || latency > STALE_AFTER_S {
            self.stats.stale += 1;
            return None;
        }
        if self.newest_answered.is_some() {
            self.stats.unanswered += u64::from(ahead - 1);
        }
        self.newest_answered = Some(frame.sequence);
        self.stats.answered += 1;
        self.latency_sum += latency;
        self.stats.latency_mean_s = self.latency_sum / self.stats.answered as f64;
        self.stats.latency_max_s = self.stats.latency_max_s.max(latency);
        Some(Row {
            time: sent.time,
            sequence: frame.sequence,
            commanded: sent.values,
            measured: map.natural(&frame.values),
            latency_s: latency,
        })
    }

    /// The counts so far.
    pub fn stats(&self) -> TelemetryStats {
        self.stats
    }
}

#[cfg(test)]
mod tests;
