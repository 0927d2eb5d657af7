//! The rolling history of leg lengths in manual mode: what the legs did over the last
//! seconds of wall time while the sliders moved.

use std::collections::VecDeque;

/// Leg lengths at wall-clock times, the oldest dropped after [`History::WINDOW`] seconds.
#[derive(Clone, Debug, Default)]
pub(crate) struct History {
    entries: VecDeque<(f64, [f64; 6])>,
    last_change: Option<f64>,
}

impl History {
    /// Seconds of history kept and shown.
    pub(crate) const WINDOW: f64 = 10.0;

    /// Record the lengths at `clock` seconds.
    pub(crate) fn push(&mut self, clock: f64, lengths: [f64; 6]) {
        if self.entries.back().is_none_or(|(_, l)| *l != lengths) {
            self.last_change = Some(clock);
        }
        self.entries.push_back((clock, lengths));
        while self
            .entries
            .front()
            .is_some_and(|(t, _)| *t < clock - Self::WINDOW)
        {
            self.entries.pop_front();
        }
    }

    /// The entries, oldest first.
    pub(crate) fn entries(&self) -> impl Iterator<Item = &(f64, [f64; 6])> {
        self.entries.iter()
    }

    /// Whether the lengths changed within the window before `clock` (the plot still scrolls).
    pub(crate) fn recently_changed(&self, clock: f64) -> bool {
        self.last_change.is_some_and(|t| clock - t < Self::WINDOW)
    }

    /// Forget everything.
    pub(crate) fn clear(&mut self) {
        self.entries.clear();
        self.last_change = None;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keeps_a_window_and_knows_when_it_last_changed() {
        let mut h = History::default();
        for k in 0..=300 {
            let t = k as f64 * 0.1;
            let l = if k < 100 { [1.0 + t; 6] } else { [11.0; 6] };
            h.push(t, l);
        }
        let times: Vec<f64> = h.entries().map(|(t, _)| *t).collect();
        assert!((times[0] - 20.0).abs() < 1e-9, "{}", times[0]);
        assert_eq!(times.len(), 101);
        // Lengths stopped changing at 10 s; at 30 s the window has passed.
        assert!(h.recently_changed(15.0));
        assert!(!h.recently_changed(30.0));
        h.clear();
        assert_eq!(h.entries().count(), 0);
    }
}
