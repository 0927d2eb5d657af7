//! Datagrams in, samples out: the one loop that decodes a datagram ([`VehicleDecoder`]), places
//! its sample on the time line ([`Timeline`]) and counts what it was ([`Tally`], by
//! [`VehicleFormat`]). The live link, a replayed capture and `stewart telemetry` all read through
//! it, so they agree datagram for datagram.
//!
//! A sender's clock may start again (a new F1 session, a restarted game): after the game
//! said it is in its menus, or after nothing came for the stall time, the time line starts
//! a new stretch, so the samples that follow are not dropped as older than the last. The
//! rule is the intake's, by arrival times, so a capture replayed gives what the live link
//! took.

use super::timeline::{Placed, PushOutcome, Step, Timeline};
use super::{MAX_TIME_S, Reading, VehicleDecoder, VehicleError, VehicleFormat};

/// What one datagram was.
#[derive(Clone, Debug, PartialEq)]
pub enum Intaken {
    /// A sample, and what became of it on the time line.
    Sample(PushOutcome),
    /// The game in its menus or paused.
    Idle,
    /// Nothing to use (another packet of the game's, the first half of a pair).
    Ignored,
    /// Not readable: why.
    Refused(VehicleError),
}

/// Counts of what arrived, all along.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Tally {
    /// Datagrams taken.
    pub datagrams: u64,
    /// Datagrams per format recognised, in the order of [`VehicleFormat::ALL`].
    per_format: [u64; VehicleFormat::ALL.len()],
    /// Samples placed on the time line as samples of their own (a clockless sample that
    /// replaced the last, arriving with it, is not counted again).
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
    /// Times the sender's clock was started again (after its menus or a stall).
    pub restarts: u64,
    /// Why the first datagram refused was refused (the advice a game's setting needs).
    pub first_refusal: Option<VehicleError>,
}

impl Tally {
    /// Datagrams of `format` so far.
    pub fn of(&self, format: VehicleFormat) -> u64 {
        self.per_format.get(format.index()).copied().unwrap_or(0)
    }

    /// The formats that arrived, with their datagrams, in the order of [`VehicleFormat::ALL`].
    pub fn formats(&self) -> impl Iterator<Item = (VehicleFormat, u64)> + '_ {
        VehicleFormat::ALL
            .iter()
            .zip(self.per_format)
            .filter(|(_, n)| *n > 0)
            .map(|(f, n)| (*f, n))
    }
}

/// Reads datagrams into placed samples, counting them.
#[derive(Debug)]
pub struct Intake {
    decoder: VehicleDecoder,
    timeline: Timeline,
    tally: Tally,
    /// Silent this long (seconds of arrival), the input has stalled: a new stretch.
    stall_s: f64,
    /// The last datagram's arrival.
    last_arrival: Option<f64>,
}

impl Default for Intake {
    fn default() -> Self {
        Self::new(Self::STALL_S)
    }
}

impl Intake {
    /// The stall time of [`Intake::default`], seconds (the `[cueing] stall_s` default).
    pub const STALL_S: f64 = 0.5;

    /// An intake that has seen nothing, taking a silence of `stall_s` seconds as a stall.
    pub fn new(stall_s: f64) -> Self {
        Self {
            decoder: VehicleDecoder::new(),
            timeline: Timeline::new(),
            tally: Tally::default(),
            stall_s,
            last_arrival: None,
        }
    }

    /// Take one datagram arriving at `arrival` (seconds on the receiver's clock): its
    /// format, what it was, and the samples it placed (oldest first).
    pub fn take(&mut self, bytes: &[u8], arrival: f64) -> (Option<VehicleFormat>, Intaken, Placed) {
        if self
            .last_arrival
            .is_some_and(|last| arrival - last > self.stall_s)
        {
            self.restart();
        }
        self.last_arrival = Some(arrival);
        let decoded = self.decoder.decode(bytes);
        self.tally.datagrams += 1;
        // A format missing from `VehicleFormat::ALL` goes uncounted rather than panic.
        if let Some(count) = decoded
            .format
            .and_then(|f| self.tally.per_format.get_mut(f.index()))
        {
            *count += 1;
        }
        let mut placed = Placed::default();
        let reading = match decoded.reading {
            // A clockless sample is placed at its arrival: within the tables' times too.
            Ok(Reading::Sample(s))
                if s.t.is_none() && (arrival.is_nan() || arrival.abs() > MAX_TIME_S) =>
            {
                Err(VehicleError::Value {
                    name: "arrival time",
                    value: arrival,
                })
            }
            other => other,
        };
        let what = match reading {
            Ok(Reading::Sample(sample)) => {
                let (placement, p) = self.timeline.push(sample, arrival);
                placed = p;
                let tally = &mut self.tally;
                tally.placed += placed.iter().filter(|p| p.step != Step::Same).count() as u64;
                match placement {
                    PushOutcome::Repeat => tally.repeats += 1,
                    PushOutcome::Stale => tally.stale += 1,
                    PushOutcome::Placed | PushOutcome::Held => {}
                }
                Intaken::Sample(placement)
            }
            Ok(Reading::Idle) => {
                self.tally.idle += 1;
                // The game's menus or pause: its clock may start again after them.
                self.restart();
                Intaken::Idle
            }
            Ok(Reading::Ignored) => Intaken::Ignored,
            Err(e) => {
                self.tally.refused += 1;
                self.tally.first_refusal.get_or_insert_with(|| e.clone());
                Intaken::Refused(e)
            }
        };
        (decoded.format, what, placed)
    }

    /// Start a new stretch of the senders' clocks (after their menus or a stall, which
    /// [`Intake::take`] sees itself): samples held on a repeated stamp are dropped and
    /// counted.
    pub fn restart(&mut self) {
        if !self.timeline.is_empty() {
            self.tally.restarts += 1;
        }
        self.finish();
    }

    /// The stream has ended: samples held on a repeated stamp are dropped and counted.
    pub fn finish(&mut self) {
        self.tally.unplaced += self.timeline.restart() as u64;
    }

    /// What arrived so far.
    pub fn tally(&self) -> &Tally {
        &self.tally
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn text(t: f64, ax: f64) -> String {
        format!("{t},{ax},0,0,0,0,0")
    }

    #[test]
    fn a_clock_that_starts_again_after_a_stall_or_the_menus_is_a_new_stretch() {
        let mut intake = Intake::new(0.5);
        for (k, arrival) in [0.0, 0.1, 0.2].into_iter().enumerate() {
            let (_, what, _) = intake.take(text(10.0 + k as f64 * 0.1, 1.0).as_bytes(), arrival);
            assert_eq!(what, Intaken::Sample(PushOutcome::Placed));
        }
        // Back to 0 at once: older than the last, dropped.
        let (_, what, _) = intake.take(text(0.0, 2.0).as_bytes(), 0.3);
        assert_eq!(what, Intaken::Sample(PushOutcome::Stale));
        // Back to 0 after a second of silence: a new stretch, kept.
        let (_, what, placed) = intake.take(text(0.05, 2.0).as_bytes(), 1.3);
        assert_eq!(
            (what, placed.len()),
            (Intaken::Sample(PushOutcome::Placed), 1)
        );
        assert_eq!(intake.tally().restarts, 1);
        // A clockless sample beyond the tables' times is refused by name.
        let mut far = Intake::default();
        let beamng = {
            let mut p = vec![0u8; 88];
            p[..4].copy_from_slice(b"BNG1");
            p
        };
        let (_, what, _) = far.take(&beamng, 2e6);
        assert!(
            matches!(
                what,
                Intaken::Refused(VehicleError::Value {
                    name: "arrival time",
                    ..
                })
            ),
            "{what:?}"
        );
        assert!(far.tally().first_refusal.is_some());
    }
}
