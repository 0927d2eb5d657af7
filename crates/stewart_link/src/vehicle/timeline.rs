//! Samples placed on the stream's time line: the one rule by which the live link, a
//! replayed capture and `stewart telemetry` time what they decode.
//!
//! A sample is placed at its sender's clock, or, when its format has none, at its arrival.
//! A game's clock may tick more slowly than it sends: Forza Horizon 5's `TimestampMS`
//! advances every 15–16 ms while it sends 80 datagrams a second, so one datagram in five
//! repeats the stamp before it with new motion. Such a sample is held until the next
//! stamp arrives, and the samples held are then spaced evenly between the two stamps
//! (between their neighbours, not by arrival: a capture's times and a live stream's give
//! the same places, and a sample keeps its order). A sample whose stamp and motion both
//! repeat the last is a true repeat, counted and dropped; one older than the last is
//! stale, counted and dropped. Clockless samples arriving together (X-Plane read in one
//! tick) replace one another.

use super::VehicleSample;

/// The most samples held on one repeated stamp; more are dropped as stale (no game sends
/// more than a few between two ticks of its clock).
pub const MAX_HELD: usize = 8;

/// How a placed sample steps what it feeds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Step {
    /// The first sample of a stretch: nothing to step.
    First,
    /// A sample this much later than the last, seconds.
    By(f64),
    /// A sample without a clock of its own at the same time as the last: it replaces the
    /// last, nothing to step.
    Same,
}

/// A sample placed on the time line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Timed {
    /// Its time on the line, seconds.
    pub t: f64,
    /// How it steps what it feeds.
    pub step: Step,
    /// The sample.
    pub sample: VehicleSample,
}

/// What became of a sample pushed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PushOutcome {
    /// Placed (with any held before it).
    Placed,
    /// Held until the next stamp (its stamp repeats the last, its motion is new).
    Held,
    /// Its stamp and motion repeat the last: dropped.
    Repeat,
    /// Older than the last, or one too many on a repeated stamp: dropped.
    Stale,
}

/// The samples one push placed, oldest first (at most the held ones and itself).
#[derive(Clone, Copy, Debug)]
pub struct Placed {
    items: [Option<Timed>; MAX_HELD + 1],
}

impl Default for Placed {
    fn default() -> Self {
        Self::NONE
    }
}

impl Placed {
    const NONE: Placed = Placed {
        items: [None; MAX_HELD + 1],
    };

    /// The samples placed, oldest first.
    pub fn iter(&self) -> impl Iterator<Item = &Timed> {
        self.items.iter().flatten()
    }

    /// How many.
    pub fn len(&self) -> usize {
        self.iter().count()
    }

    /// Whether none was.
    pub fn is_empty(&self) -> bool {
        self.items[0].is_none()
    }
}

/// The time line: the last sample placed and the samples held on its stamp.
#[derive(Clone, Debug, Default)]
pub struct Timeline {
    /// The last sample placed, and its time.
    last: Option<(f64, VehicleSample)>,
    held: [Option<VehicleSample>; MAX_HELD],
}

impl Timeline {
    /// A line on which nothing is placed.
    pub fn new() -> Self {
        Self::default()
    }

    /// Place `sample`, arriving at `arrival` (seconds on the receiver's clock): what became
    /// of it, and the samples placed.
    pub fn push(&mut self, sample: VehicleSample, arrival: f64) -> (PushOutcome, Placed) {
        let mut placed = Placed::NONE;
        let time = sample.t.unwrap_or(arrival);
        let own_clock = sample.t.is_some();
        let Some((last, last_sample)) = self.last else {
            placed.items[0] = Some(Timed {
                t: time,
                step: Step::First,
                sample,
            });
            self.last = Some((time, sample));
            return (PushOutcome::Placed, placed);
        };
        if time > last {
            let held = self.held.iter().take_while(|h| h.is_some()).count();
            let spacing = (time - last) / (held + 1) as f64;
            let mut previous = last;
            for (k, h) in self.held.iter_mut().take(held).enumerate() {
                let t = last + spacing * (k + 1) as f64;
                placed.items[k] = h.take().map(|sample| Timed {
                    t,
                    step: Step::By(t - previous),
                    sample,
                });
                previous = t;
            }
            placed.items[held] = Some(Timed {
                t: time,
                step: Step::By(time - previous),
                sample,
            });
            self.last = Some((time, sample));
            return (PushOutcome::Placed, placed);
        }
        if time < last {
            return (PushOutcome::Stale, placed);
        }
        // The same time as the last.
        if !own_clock {
            placed.items[0] = Some(Timed {
                t: time,
                step: Step::Same,
                sample,
            });
            self.last = Some((time, sample));
            return (PushOutcome::Placed, placed);
        }
        let newest = self.held.iter().flatten().last().unwrap_or(&last_sample);
        if same_motion(newest, &sample) {
            return (PushOutcome::Repeat, placed);
        }
        match self.held.iter_mut().find(|h| h.is_none()) {
            Some(slot) => {
                *slot = Some(sample);
                (PushOutcome::Held, placed)
            }
            None => (PushOutcome::Stale, placed),
        }
    }

    /// Whether nothing is placed on it yet.
    pub fn is_empty(&self) -> bool {
        self.last.is_none()
    }

    /// Start a new stretch (after a stall: the sender's clock may have started again);
    /// returns how many held samples were dropped.
    pub fn restart(&mut self) -> usize {
        let dropped = self.held.iter().flatten().count();
        *self = Self::default();
        dropped
    }
}

/// Whether two samples carry the same motion (bit for bit).
fn same_motion(a: &VehicleSample, b: &VehicleSample) -> bool {
    let bits = |s: &VehicleSample| {
        let mut out = [0u64; 6];
        for (o, v) in out.iter_mut().zip(s.accel.iter().chain(&s.rates_deg_s)) {
            *o = v.to_bits();
        }
        out
    };
    bits(a) == bits(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(t: Option<f64>, ax: f64) -> VehicleSample {
        VehicleSample {
            t,
            accel: [ax, 0.0, 0.0],
            rates_deg_s: [0.0; 3],
        }
    }

    fn times(placed: &Placed) -> Vec<(f64, Step, f64)> {
        placed
            .iter()
            .map(|p| (p.t, p.step, p.sample.accel[0]))
            .collect()
    }

    #[test]
    fn repeated_stamps_with_new_motion_are_spaced_between_their_neighbours() {
        let mut line = Timeline::new();
        let (p, placed) = line.push(at(Some(0.0), 1.0), 0.0);
        assert_eq!(
            (p, times(&placed)),
            (PushOutcome::Placed, vec![(0.0, Step::First, 1.0)])
        );
        // Two more on the same stamp, each new: held.
        assert_eq!(line.push(at(Some(0.0), 2.0), 0.01).0, PushOutcome::Held);
        assert_eq!(line.push(at(Some(0.0), 3.0), 0.02).0, PushOutcome::Held);
        // The same motion again: a true repeat.
        assert_eq!(line.push(at(Some(0.0), 3.0), 0.025).0, PushOutcome::Repeat);
        // The next stamp places the two held at a third and two thirds of the way.
        let (p, placed) = line.push(at(Some(0.03), 4.0), 0.03);
        assert_eq!(p, PushOutcome::Placed);
        let got = times(&placed);
        assert_eq!(got.len(), 3);
        for ((t, step, ax), (want_t, want_ax)) in
            got.iter().zip([(0.01, 2.0), (0.02, 3.0), (0.03, 4.0)])
        {
            assert!((t - want_t).abs() < 1e-15, "{got:?}");
            assert_eq!(*ax, want_ax);
            let Step::By(h) = step else {
                panic!("{step:?}")
            };
            assert!((h - 0.01).abs() < 1e-15, "{got:?}");
        }
        // Older: stale.
        assert_eq!(line.push(at(Some(0.02), 5.0), 0.04).0, PushOutcome::Stale);
    }

    #[test]
    fn a_repeat_of_the_last_placed_is_dropped_and_held_ones_are_bounded() {
        let mut line = Timeline::new();
        line.push(at(Some(1.0), 1.0), 0.0);
        assert_eq!(line.push(at(Some(1.0), 1.0), 0.0).0, PushOutcome::Repeat);
        for k in 0..MAX_HELD {
            assert_eq!(
                line.push(at(Some(1.0), 10.0 + k as f64), 0.0).0,
                PushOutcome::Held
            );
        }
        assert_eq!(line.push(at(Some(1.0), 99.0), 0.0).0, PushOutcome::Stale);
        assert_eq!(line.restart(), MAX_HELD);
        let (p, placed) = line.push(at(Some(0.5), 1.0), 0.0);
        assert_eq!((p, placed.len()), (PushOutcome::Placed, 1));
    }

    #[test]
    fn clockless_samples_step_by_arrival_and_replace_at_the_same_time() {
        let mut line = Timeline::new();
        line.push(at(None, 1.0), 2.0);
        let (_, placed) = line.push(at(None, 2.0), 2.0);
        assert_eq!(times(&placed), vec![(2.0, Step::Same, 2.0)]);
        let (_, placed) = line.push(at(None, 3.0), 2.5);
        assert_eq!(times(&placed), vec![(2.5, Step::By(0.5), 3.0)]);
        assert_eq!(line.push(at(None, 4.0), 2.0).0, PushOutcome::Stale);
    }
}
